"""The flight-log command line: a log written from a simulated run gives that run's estimates;
malformed logs and arguments fail with messages naming the column, row or option."""

from __future__ import annotations

import numpy as np
import pandas as pd
import pytest

from pipeline.altimeter_attitude import euler_filters, flightlog, linear_kf, metrics
from pipeline.altimeter_attitude.columns import FLIGHTLOG_OUTPUT_COLUMNS
from pipeline.altimeter_attitude.estimates import Estimates
from pipeline.altimeter_attitude.scenario import build_scenario, load_scenario
from pipeline.altimeter_attitude.sensors import simulate_inputs
from pipeline.altimeter_attitude.ukf import NotPositiveDefiniteError


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
    args = [str(path), "--out", str(out), "--filters", "linear_kf,gyro_only"]
    # the reference below is the scenario's 2-deg initial sigma (the CLI's default is levelling's)
    assert flightlog.main([*args, "--init-sigma-deg", "2"]) == 0
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
        (lambda f: f.drop(columns="accel_y_m_s2"), r"missing columns for accel_y \(accel_y_m_s2\)"),
        (lambda f: f.drop(columns="gyro_z_deg_s"), r"missing columns for gyro_z \(gyro_z_rad_s\)"),
        (
            lambda f: f.assign(t_s=f["t_s"].where(f.index != 10, f["t_s"][10] + 0.005)),
            r"column t_s: the IMU step is inferred as 0.02 s \(50 Hz\) and every step must be "
            r"within 0.01 of it \(--max-jitter\); gaps or jitter before data rows 11 \(0.025 s\), "
            r"12 \(0.015 s\)",
        ),
        (
            lambda f: f.drop(index=range(100, 103)),
            r"gaps or jitter before data rows 101 \(0.08 s\)$",
        ),
        (
            lambda f: f.assign(t_s=f["t_s"].where(f.index != 10, f["t_s"][9])),
            r"column t_s must be strictly increasing; data rows 11 \(0.18 s\) are not",
        ),
        (
            lambda f: f.assign(
                accel_x_m_s2=f["accel_x_m_s2"].astype(object).where(f.index != 5, "abc")
            ),
            r"column accel_x_m_s2 \(accel_x\), data row 6: 'abc' is not a finite number",
        ),
        (
            lambda f: f.assign(
                accel_z_m_s2=f["accel_z_m_s2"].astype(object).where(f.index != 8, "inf")
            ),
            r"column accel_z_m_s2 \(accel_z\), data row 9: 'inf' is not a finite number",
        ),
        (
            lambda f: f.assign(altimeter_m=f["altimeter_m"].where(f.index != 7, 1000.0)),
            r"altimeter_m must sample every n-th IMU row; inferred n = 1 \(smallest spacing\)",
        ),
        (
            lambda f: f.assign(altimeter_m=f["altimeter_m"].where(f.index != 40, np.nan)),
            r"altimeter_m must sample every n-th IMU row; inferred n = 2 \(smallest spacing\), "
            r"but data rows 43 break it",
        ),
        (lambda f: f.assign(altimeter_m=np.nan), "altimeter_m has 0 samples"),
        (
            lambda f: f.assign(gyro_x_deg_s=f["gyro_x_deg_s"].where(f.index != 4, np.nan)),
            r"column gyro_x_deg_s \(gyro_x\), data row 5: an empty cell is not a finite number",
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
    err = capsys.readouterr().err
    assert err.startswith("error: ") and err.count("\n") == 1 and str(path) in err, err
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
        (["--filters", "kalman"], "error: --filters = 'kalman': allowed values are"),
        (
            ["--gyro-sigma-deg-s", "-1"],
            "error: --gyro-sigma-deg-s = '-1': must be a number in (0, 100]",
        ),
        (["--roll0-deg", "95"], "error: --roll0-deg = '95': must be a number in [-89, 89]"),
        (["--gravity", "nan"], "error: --gravity = 'nan': must be a number in (9.7, 9.9]"),
        (["--gravity", "inf"], "error: --gravity = 'inf': must be a number in (9.7, 9.9]"),
        (["--gravity", "10.5"], "error: --gravity = '10.5'"),
        (["--latitude-deg", "91"], "error: --latitude-deg = '91': must be a number in [-90, 90]"),
        (["--gravity", "9.81", "--latitude-deg", "45"], "not allowed with argument"),
        (["--height-m", "100"], "error: --height-m = 100: only with --latitude-deg"),
        (["--ukf-alpha", "0"], "error: --ukf-alpha = '0': must be a number in (0, 1]"),
        (["--ukf-kappa", "-4"], "error: --ukf-kappa = '-4': must be a number in (-4, 100]"),
        (["--max-jitter", "0"], "error: --max-jitter = '0': must be a number in (0, 0.5]"),
        (["--level-s", "1e9"], "error: --level-s = '1e9': must be a number in (0, 600]"),
        (["--stamp", "middle"], "error: --stamp: invalid choice: 'middle'"),
        (
            ["--k-per-s", "30"],
            "error: --k-per-s = 30: k dt = 0.6 at the log's 50 Hz must be <= 0.5",
        ),
        (["--level-s", "500"], "error: --level-s = 500: longer than the log (30 s)"),
        (
            ["--columns", "gyro=gx:deg/s"],
            "error: --columns: 'gyro=gx:deg/s': quantity 'gyro' unknown",
        ),
        (
            ["--columns", "gyro_x=gx:rpm"],
            "error: --columns: gyro_x=gx:rpm: unit 'rpm' unknown for gyro_x; allowed: rad/s, deg/s",
        ),
        (
            ["--columns", "gyro_x=gx"],
            "error: --columns: gyro_x=gx: no unit given and none in the column name",
        ),
        (["--columns", "gyro_x"], "error: --columns: 'gyro_x': write QUANTITY=COLUMN[:UNIT]"),
        (["--columns", "gyro_x=gx:deg/s"], "missing columns for gyro_x (gx)"),
        (
            [
                "--columns",
                "accel_x=accel_x_m_s2:g0,accel_y=accel_y_m_s2:g0,accel_z=accel_z_m_s2:g0",
            ],
            "columns accel_x_m_s2[g0], accel_y_m_s2[g0], accel_z_m_s2[g0]: mean |f| over the first 50 rows (--level-s) is 9.8",
        ),
    ],
)
def test_bad_arguments_are_named(simulated, tmp_path, capsys, args, match):
    """Each bad option: status 2, one 'error:' line naming option and value, no output file."""
    _, _, _, path = simulated
    out = tmp_path / "o.csv"
    assert flightlog.main([str(path), "--out", str(out), *args]) == 2
    err = capsys.readouterr().err
    assert match in err and err.count("error:") == 1 and "Traceback" not in err, err
    assert err.splitlines()[-1].startswith("error: ") and not out.exists()


@pytest.mark.parametrize(
    ("text", "match"),
    [
        ("columns: [1, 2]\n", "columns must be a mapping"),
        ("stamp: middle\n", "stamp = 'middle': allowed: start, end"),
        ("delimiter: ';'\n", "a format file is a mapping with keys columns and stamp"),
        ("columns: {gyro_x: {col: gx}}\n", "columns.gyro_x = {'col': 'gx'}: write a column name"),
        (
            "columns: {t: {column: time, unit: min}}\n",
            "unit 'min' unknown for t; allowed: s, ms, us",
        ),
        ("columns: {t: [\n", "not valid YAML"),
        ("columns: {gyro_x: {column: 5, unit: deg/s}}\n", "the column and unit must be non-empty"),
        (
            "columns: {altimeter: {column: h, unit: .nan}}\n",
            "columns.altimeter.unit = nan: not a finite number",
        ),
        ("columns: {gyro_x: gx}\n", "gyro_x=gx: no unit given and none in the column name"),
    ],
)
def test_bad_format_files_are_named(simulated, tmp_path, capsys, text, match):
    _, _, _, path = simulated
    fmt = tmp_path / "fmt.yaml"
    fmt.write_text(text, encoding="utf-8")
    assert flightlog.main([str(path), "--out", str(tmp_path / "o.csv"), "--format", str(fmt)]) == 2
    err = capsys.readouterr().err
    assert (
        err.startswith("error: ") and f"{fmt}: " in err and match in err and err.count("\n") == 1
    ), err


def test_unusable_out_is_refused_before_compute(simulated, tmp_path, capsys, monkeypatch):
    _, _, _, path = simulated

    def no_compute(*a, **k):
        raise AssertionError("the filters ran")

    monkeypatch.setattr(flightlog, "run_log", no_compute)
    blocker = tmp_path / "file"
    blocker.write_text("x", encoding="utf-8")
    for out, match in (
        (tmp_path, "is a directory; give the CSV file to write"),
        (blocker / "att.csv", f"{blocker} is not a directory"),
        (path, "is the input log"),
    ):
        assert flightlog.main([str(path), "--out", str(out)]) == 2
        err = capsys.readouterr().err
        assert err.startswith(f"error: --out = {out}: ") and match in err and err.count("\n") == 1


def test_filter_failures_are_one_line(simulated, tmp_path, capsys, monkeypatch):
    """NotPositiveDefiniteError, OSError and divergence (non-finite estimates) end with status 1
    and one line, no traceback, no output file."""
    _, _, _, path = simulated
    out = tmp_path / "o.csv"

    def not_pd(*a, **k):
        raise NotPositiveDefiniteError("ukf.predict", np.array([0]), np.array([-1.0]), 1)

    def diverge(inputs, *a, **k):
        est = real(inputs, *a, **k)[0]
        roll = est.roll.copy()
        roll[0, 700:] = np.nan
        return [Estimates(**{**est.__dict__, "roll": roll})]

    real = linear_kf.run_linear_kf
    cases = [
        (euler_filters, "run_ukf", not_pd, "ukf", "NotPositiveDefiniteError: ukf.predict"),
        (
            flightlog,
            "write_csv",
            lambda *a: open("/proc/nonexistent/x", "w"),
            "gyro_only",
            "FileNotFoundError: [Errno 2]",
        ),
        (linear_kf, "run_linear_kf", diverge, "linear_kf", "non-finite roll/pitch from t = 14 s"),
    ]
    for module, name, fake, filt, match in cases:
        with monkeypatch.context() as m:
            m.setattr(module, name, fake)
            assert flightlog.main([str(path), "--out", str(out), "--filters", filt]) == 1
        err = capsys.readouterr().err
        last = err.splitlines()[-1]
        assert last.startswith(f"error: {path}: ") and match in last and "Traceback" not in err
        assert not out.exists()


def test_help_documents_the_options(capsys):
    assert flightlog.main(["--help"]) == 0
    text = capsys.readouterr().out
    for option in (
        "--columns",
        "--format",
        "--stamp",
        "--gravity",
        "--latitude-deg",
        "--max-jitter",
        "--ukf-alpha",
        "--h0-m",
        "deg/s",
        "g0",
        "Somigliana",
    ):
        assert option in text, option


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
