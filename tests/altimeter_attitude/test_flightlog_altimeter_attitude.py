"""The flight-log command line: a log written from a simulated run gives that run's estimates;
malformed logs and arguments fail with messages naming the column, row or option."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from pipeline.altimeter_attitude import flightlog, linear_kf, metrics
from pipeline.altimeter_attitude.columns import FLIGHTLOG_OUTPUT_COLUMNS
from pipeline.altimeter_attitude.scenario import build_scenario, load_scenario
from pipeline.altimeter_attitude.sensors import simulate_inputs


@pytest.fixture(scope="module")
def simulated(tmp_path_factory):
    """A 30 s gentle flight with the altimeter every 2nd IMU row, written as a flight log."""
    base = load_scenario("config/scenarios/altimeter_attitude/gentle_cruise.yaml")
    raw = {**base.raw, "trajectory": {**base.raw["trajectory"], "duration_s": 30.0}}
    raw["trajectory"]["maneuvers"] = []
    raw["sensors"] = {**raw["sensors"], "altimeter_every": 2}
    sc = build_scenario(raw, base.path)
    inp = simulate_inputs(sc.profiles, sc.sensors, sc.initial, 1, sc.seed, sc.name)
    n = inp.n_steps
    frame = pd.DataFrame({"t_s": inp.truth.t})
    for i, a in enumerate("xyz"):
        frame[f"gyro_{a}_deg_s"] = np.degrees(np.r_[inp.gyro[0, :, i], inp.gyro[0, -1, i]])
        frame[f"accel_{a}_m_s2"] = np.r_[inp.accel[0, :, i], inp.accel[0, -1, i]]
    alt = inp.altimeter[0].copy()
    alt[0] = inp.truth.h[0]
    frame["altimeter_m"] = alt
    path = tmp_path_factory.mktemp("log") / "log.csv"
    frame.to_csv(path, index=False)
    assert np.isnan(alt[1]) and np.isfinite(alt[2]) and len(frame) == n + 1
    return sc, inp, frame, path


def test_log_round_trip_matches_the_pipeline_filter(simulated, tmp_path):
    sc, inp, frame, path = simulated
    out = tmp_path / "att.csv"
    assert flightlog.main([str(path), "--out", str(out), "--filters", "linear_kf,gyro_only"]) == 0
    result = pd.read_csv(out)
    assert list(result.columns) == FLIGHTLOG_OUTPUT_COLUMNS
    assert set(result["filter"]) == {"linear_kf", "gyro_only"}
    lkf = result[result["filter"] == "linear_kf"]
    assert len(lkf) == len(frame)
    # the CLI starts from accelerometer levelling; run the pipeline filter from the same start
    first = lkf.iloc[0]
    start = inp.__class__(
        **{
            **inp.__dict__,
            "x0_euler": np.array(
                [[np.radians(first.roll_deg), np.radians(first.pitch_deg), 0.0, inp.truth.h[0]]]
            ),
            "sigma0": np.array([[np.radians(2.0), np.radians(2.0), 1.0, 2.0]]),
        }
    )
    ref = linear_kf.run_linear_kf(start, 1.0, "exact", ("linear_kf",))[0]
    np.testing.assert_allclose(lkf["roll_deg"].to_numpy(), np.degrees(ref.roll[0]), atol=1e-9)
    np.testing.assert_allclose(
        lkf["pitch_sigma_deg"].to_numpy(), np.degrees(ref.pitch_sigma[0]), atol=1e-9
    )
    # and the estimate is good: within a degree of the truth after 10 s
    err = lkf["roll_deg"].to_numpy() - np.degrees(inp.truth.roll)
    assert np.sqrt(np.mean(err[500:] ** 2)) < 1.0


def _write(tmp_path, frame, name="bad.csv"):
    path = tmp_path / name
    frame.to_csv(path, index=False)
    return path


@pytest.mark.parametrize(
    ("mutate", "match"),
    [
        (lambda f: f.drop(columns="accel_y_m_s2"), r"missing columns \['accel_y_m_s2'\]"),
        (lambda f: f.drop(columns="gyro_z_deg_s"), "gyro columns missing"),
        (
            lambda f: f.assign(t_s=f["t_s"].where(f.index != 10, f["t_s"][10] + 0.005)),
            r"t_s step before data row 11",
        ),
        (
            lambda f: f.assign(t_s=f["t_s"].where(f.index != 10, f["t_s"][9])),
            r"t_s must increase strictly; data row 11",
        ),
        (
            lambda f: f.assign(
                accel_x_m_s2=f["accel_x_m_s2"].astype(object).where(f.index != 5, "abc")
            ),
            r"column accel_x_m_s2, data row 6: 'abc'",
        ),
        (
            lambda f: f.assign(altimeter_m=f["altimeter_m"].where(f.index != 7, 1000.0)),
            r"altimeter_m must sample every n-th IMU row; inferred n = 2",
        ),
        (lambda f: f.assign(altimeter_m=np.nan), "altimeter_m has 0 samples"),
        (
            lambda f: f.assign(gyro_x_deg_s=f["gyro_x_deg_s"].where(f.index != 4, np.nan)),
            r"column gyro_x_deg_s, data row 5: an empty cell is not a finite number",
        ),
    ],
)
def test_malformed_logs_are_named(simulated, tmp_path, capsys, mutate, match):
    _, _, frame, _ = simulated
    path = _write(tmp_path, mutate(frame.copy()))
    with pytest.raises(flightlog.FlightLogError, match=match):
        flightlog.read_log(path)
    out = tmp_path / "att.csv"
    assert flightlog.main([str(path), "--out", str(out)]) == 2
    assert "error:" in capsys.readouterr().err
    assert not out.exists()


def test_empty_log_is_named(tmp_path, capsys):
    path = tmp_path / "empty.csv"
    path.write_text("", encoding="utf-8")
    with pytest.raises(flightlog.FlightLogError, match="the file is empty"):
        flightlog.read_log(path)
    assert flightlog.main([str(path), "--out", str(tmp_path / "att.csv")]) == 2
    assert "the file is empty" in capsys.readouterr().err


@pytest.mark.parametrize(
    ("args", "match"),
    [
        (["--filters", "kalman"], "--filters = 'kalman'"),
        (["--gyro-sigma-deg-s", "-1"], "--gyro-sigma-deg-s = '-1'"),
        (["--roll0-deg", "95"], "--roll0-deg = 95"),
    ],
)
def test_bad_arguments_are_named(simulated, tmp_path, capsys, args, match):
    _, _, _, path = simulated
    with pytest.raises(SystemExit):
        flightlog.main([str(path), "--out", str(tmp_path / "o.csv"), *args])
    assert match in capsys.readouterr().err


def test_metrics_helpers_agree():
    """summary_row and run_rms_frame are two reductions of the same errors."""
    sc = load_scenario("config/scenarios/altimeter_attitude/gentle_cruise.yaml")
    raw = {**sc.raw, "trajectory": {**sc.raw["trajectory"], "duration_s": 30.0, "maneuvers": []}}
    sc = build_scenario(raw, sc.path)
    inp = simulate_inputs(sc.profiles, sc.sensors, sc.initial, 4, sc.seed, sc.name)
    est = linear_kf.run_linear_kf(inp, 1.0)[0]
    row = metrics.summary_row(est, inp.truth, 100)
    per_run = metrics.run_rms_frame(est, inp.truth, 100)
    assert row["roll_rms_deg"] == pytest.approx(np.sqrt(np.mean(per_run["roll_rms_deg"] ** 2)))
