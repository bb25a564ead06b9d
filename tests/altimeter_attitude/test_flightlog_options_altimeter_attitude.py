"""The flight-log options on 120 s, 100 Hz logs simulated with a known truth (tests/flightlog_sim.py).

Bounds come from the filter's own sigma: a noisy run's RMS error (after the transient) must
stay below 2 x its RMS sigma (about the 99.9 % point of a chi-square with the ~5 independent
samples a 100 s error series with ~20 s correlation holds), and a noise-free run, where the
error is only what the filter's model and a wrong option add, must stay below 1 % of it when
the option matches the log.
"""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from pipeline.altimeter_attitude import flightlog
from pipeline.altimeter_attitude.gravity import normal_gravity
from pipeline.altimeter_attitude.scenario import load_scenario
from tests import flightlog_sim as sim

NEGLIGIBLE = 0.01  # noise-free error / sigma when the log and the options agree
CONSISTENT = 2.0  # noisy-run RMS error / RMS sigma


def _worst(e: dict[str, float]) -> float:
    """The larger of roll and pitch RMS error in units of the filter's RMS sigma."""
    return max(e["roll"] / e["roll_sigma"], e["pitch"] / e["pitch_sigma"])


@pytest.fixture(scope="module")
def noisy(tmp_path_factory):
    inp = sim.simulate()
    return inp, sim.write(sim.log_frame(inp), tmp_path_factory.mktemp("n") / "log.csv")


def test_inferred_values_are_printed_and_estimates_are_consistent(noisy, tmp_path, capsys):
    inp, log = noisy
    out = tmp_path / "att.csv"
    assert sim.run(log, out, "--filters", "linear_kf,ukf") == 0
    err = capsys.readouterr().err
    for text in (
        "12001 rows, 120 s",
        "IMU 100 Hz",
        "altimeter 20 Hz (every 5 rows",
        "no gaps",
        "gravity 9.80665",
        "stamp start",
        "gyro_x=gyro_x_rad_s[rad/s]",
    ):
        assert text in err, text
    for name in ("linear_kf", "ukf"):
        e = sim.errors(out, inp, name)
        assert _worst(e) < CONSISTENT, (name, e)


def _engineer_frame(frame: pd.DataFrame) -> pd.DataFrame:
    """The independent simulator's layout: time in ms, gyro in deg/s, accel in g0, altitude in ft."""
    out = pd.DataFrame({"time": frame["t_s"] * 1000.0})
    for a in "xyz":
        out[f"gyro_{a}"] = np.degrees(frame[f"gyro_{a}_rad_s"])
        out[f"accel_{a}"] = frame[f"accel_{a}_m_s2"] / 9.80665
    out["alt_ft"] = frame["altimeter_m"] / 0.3048
    return out


def test_column_map_and_units_give_the_project_layout_estimates(noisy, tmp_path):
    """--columns and --format with converted units reproduce the estimates of the same data in
    the project's own layout (to 1e-6 deg), and those are consistent with the truth."""
    inp, log = noisy
    ref = tmp_path / "ref.csv"
    assert sim.run(log, ref, "--filters", "linear_kf") == 0
    other = sim.write(_engineer_frame(sim.log_frame(inp)), tmp_path / "eng.csv")
    cols = ",".join(
        ["t=time:ms", "altimeter=alt_ft"]
        + [f"gyro_{a}=gyro_{a}:deg/s" for a in "xyz"]
        + [f"accel_{a}=accel_{a}:g0" for a in "xyz"]
    )
    fmt = tmp_path / "fmt.yaml"
    fmt.write_text(
        "columns:\n  t: {column: time, unit: ms}\n  altimeter: alt_ft\n"
        + "".join(f"  gyro_{a}: {{column: gyro_{a}, unit: deg/s}}\n" for a in "xyz")
        + "".join(f"  accel_{a}: {{column: accel_{a}, unit: g0}}\n" for a in "xyz"),
        encoding="utf-8",
    )
    expected = pd.read_csv(ref)
    for args in (["--columns", cols], ["--format", str(fmt)]):
        out = tmp_path / "att.csv"
        assert sim.run(other, out, "--filters", "linear_kf", *args) == 0
        got = pd.read_csv(out)
        for c in ("t_s", "roll_deg", "pitch_deg", "roll_sigma_deg", "pitch_sigma_deg"):
            np.testing.assert_allclose(got[c], expected[c], rtol=0, atol=1e-6, err_msg=c)
    assert _worst(sim.errors(ref, inp, "linear_kf")) < CONSISTENT


@pytest.mark.parametrize(
    ("g", "args"),
    [
        (9.81, ["--gravity", "9.81"]),
        (normal_gravity(60.0, 1000.0), ["--latitude-deg", "60", "--height-m", "1000"]),
        (None, ["--latitude-deg", "0"]),  # height: the mean altimeter reading
    ],
)
def test_gravity_option_removes_the_gravity_error(tmp_path, g, args):
    """Noise-free log made with g != 9.80665: with the option the error is negligible against
    the filter's sigma; with the default g it is at least 10 times larger and >= 2 % of sigma."""
    if g is None:  # the altitude does not depend on g: its mean sets the log's g
        alt = sim.log_frame(sim.simulate(noise_scale=0.0))["altimeter_m"]
        g = normal_gravity(0.0, float(alt.mean()))
    inp = sim.simulate(g=g, noise_scale=0.0)
    log = sim.write(sim.log_frame(inp), tmp_path / "log.csv")
    right, wrong = tmp_path / "right.csv", tmp_path / "wrong.csv"
    assert sim.run(log, right, "--filters", "linear_kf", *args) == 0
    assert sim.run(log, wrong, "--filters", "linear_kf") == 0
    e_right, e_wrong = (_worst(sim.errors(p, inp, "linear_kf")) for p in (right, wrong))
    assert e_right < NEGLIGIBLE
    assert e_wrong > max(10 * e_right, 0.02)


def test_gravity_option_on_a_noisy_log_matches_the_standard_gravity_case(noisy, tmp_path):
    """The same noise on a g = 9.81 flight with --gravity 9.81 gives the RMS of the 9.80665
    flight with the default (within 2 %); both consistent with the sigma."""
    inp0, log0 = noisy
    inp1 = sim.simulate(g=9.81)
    log1 = sim.write(sim.log_frame(inp1), tmp_path / "g981.csv")
    a, b = tmp_path / "a.csv", tmp_path / "b.csv"
    assert sim.run(log0, a, "--filters", "linear_kf") == 0
    assert sim.run(log1, b, "--filters", "linear_kf", "--gravity", "9.81") == 0
    e0, e1 = sim.errors(a, inp0, "linear_kf"), sim.errors(b, inp1, "linear_kf")
    for angle in ("roll", "pitch"):
        assert e1[angle] == pytest.approx(e0[angle], rel=0.02)
    assert _worst(e1) < CONSISTENT


def test_end_stamped_samples_with_stamp_end(tmp_path):
    """Noise-free end-stamped log: --stamp end (or stamp: end in --format) is exact to 1 % of
    sigma; read as start-stamped (a one-sample lag) the error is >= 10 times larger."""
    inp = sim.simulate(noise_scale=0.0)
    log = sim.write(sim.log_frame(inp, "end"), tmp_path / "log.csv")
    fmt = tmp_path / "fmt.yaml"
    fmt.write_text("stamp: end\n", encoding="utf-8")
    outs = {k: tmp_path / f"{k}.csv" for k in ("cli", "fmt", "lag")}
    assert sim.run(log, outs["cli"], "--filters", "linear_kf", "--stamp", "end") == 0
    assert sim.run(log, outs["fmt"], "--filters", "linear_kf", "--format", str(fmt)) == 0
    assert sim.run(log, outs["lag"], "--filters", "linear_kf") == 0
    e = {k: _worst(sim.errors(p, inp, "linear_kf")) for k, p in outs.items()}
    assert e["cli"] < NEGLIGIBLE and e["fmt"] == pytest.approx(e["cli"], abs=1e-12)
    assert e["lag"] > max(10 * e["cli"], 0.02)


def test_defaults_are_the_paper_scenario_settings():
    sc = load_scenario("config/scenarios/altimeter_attitude/paper.yaml")
    assert flightlog.DEFAULTS == {
        "k_per_s": sc.k,
        "ukf_alpha": sc.ukf_alpha,
        "ukf_beta": sc.ukf_beta,
        "ukf_kappa": sc.ukf_kappa,
        "omega_c": sc.omega_c,
    }
    args = flightlog._parser().parse_args(["x.csv", "--out", "o.csv"])
    assert (args.k_per_s, args.ukf_alpha, args.ukf_beta, args.ukf_kappa) == (
        sc.k,
        sc.ukf_alpha,
        sc.ukf_beta,
        sc.ukf_kappa,
    )


def test_gaps_and_jitter_are_refused_naming_the_rows(noisy, tmp_path, capsys):
    """A 50 ms dropout is refused naming the first row after it; 3 % jitter on one stamp is
    refused at the default --max-jitter 0.01, accepted with --max-jitter 0.05, and the
    estimates then stay consistent with the truth."""
    inp, log = noisy
    frame = pd.read_csv(log)
    out = tmp_path / "att.csv"
    gap = sim.write(frame.drop(index=range(6000, 6005)).reset_index(drop=True), tmp_path / "g.csv")
    assert sim.run(gap, out, "--filters", "linear_kf") == 2
    err = capsys.readouterr().err
    assert "IMU step is inferred as 0.01 s (100 Hz)" in err
    assert "gaps or jitter before data rows 6001 (0.06 s)" in err and not out.exists()
    jit = frame.copy()
    jit.loc[3000, "t_s"] += 0.0003
    jit_log = sim.write(jit, tmp_path / "j.csv")
    assert sim.run(jit_log, out, "--filters", "linear_kf") == 2
    assert "before data rows 3001 (0.0103 s), 3002 (0.0097 s)" in capsys.readouterr().err
    assert sim.run(jit_log, out, "--filters", "linear_kf", "--max-jitter", "0.05") == 0
    assert "largest step deviation 3.00%" in capsys.readouterr().err
    assert _worst(sim.errors(out, inp, "linear_kf")) < CONSISTENT


def test_a_held_altimeter_is_refused_or_unheld_to_the_sparse_log(noisy, tmp_path, capsys):
    """A logger writing the last altimeter value on every row (20 Hz held over 100 Hz rows):
    refused by default naming the repeats; with --altimeter-held yes the estimates are byte for
    byte those of the same log with the altimeter only on its sample rows; 'no' runs it as a
    100 Hz altimeter; a hold that breaks its period is refused naming the row."""
    inp, log = noisy
    frame = pd.read_csv(log)
    held = frame.assign(altimeter_m=frame["altimeter_m"].ffill())
    held_log = sim.write(held, tmp_path / "held.csv")
    out, ref = tmp_path / "att.csv", tmp_path / "ref.csv"
    assert sim.run(held_log, out, "--filters", "linear_kf,ukf") == 2
    err = capsys.readouterr().err
    repeats = int((held["altimeter_m"].diff() == 0).sum())  # 9600 held, 1 level-start repeat
    assert f"column altimeter_m repeats its value before on {repeats} of 12000 values" in err
    assert "changes only every 5 rows" in err
    assert "--altimeter-held yes" in err and not out.exists()
    assert sim.run(held_log, out, "--filters", "linear_kf,ukf", "--altimeter-held", "yes") == 0
    err = capsys.readouterr().err
    assert "altimeter 20 Hz (every 5 rows, 2401 samples; held values dropped" in err
    assert sim.run(log, ref, "--filters", "linear_kf,ukf") == 0
    assert out.read_bytes() == ref.read_bytes()
    assert sim.run(held_log, out, "--filters", "linear_kf", "--altimeter-held", "no") == 0
    assert "altimeter 100 Hz (every 1 rows" in capsys.readouterr().err
    broken = held.copy()
    broken.loc[6001:6004, "altimeter_m"] = broken.loc[6000, "altimeter_m"] + 0.25  # a 1-row hold
    broken_log = sim.write(broken, tmp_path / "broken.csv")
    assert sim.run(broken_log, out, "--filters", "linear_kf", "--altimeter-held", "yes") == 2
    assert "a change of value on consecutive rows (6002)" in capsys.readouterr().err
