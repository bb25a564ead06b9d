"""Numerical trouble of the altimeter-attitude filters is counted per filter and run, never
silent: a non-finite estimate, a diverged error, a non-positive sigma; forced by an injected
zero specific force and by synthetic estimates; the page says so."""

from __future__ import annotations

import dataclasses

import numpy as np
import pandas as pd
import pytest

from pipeline.altimeter_attitude.estimates import Estimates
from pipeline.altimeter_attitude.metrics import summary_row
from pipeline.altimeter_attitude.report_trouble import filter_trouble_blocks
from pipeline.altimeter_attitude.run import run_filters
from pipeline.altimeter_attitude.scenario import ROOT, load_scenario
from pipeline.altimeter_attitude.sensors import simulate_inputs
from pipeline.altimeter_attitude.trouble import DIVERGED_DEG, estimates_trouble, trouble_frame
from pipeline.trouble import TROUBLE_COLUMNS

SCEN = ROOT / "config" / "scenarios" / "altimeter_attitude"


@pytest.fixture(scope="module")
def small():
    sc = load_scenario(SCEN / "gentle_cruise.yaml")
    inputs = simulate_inputs(sc.profiles, sc.sensors, sc.initial, 3, sc.seed, sc.name)
    return sc, inputs


def _counts(rows) -> dict:
    return {(r[2], r[3]): r[5] for r in rows}


def test_zero_specific_force_is_a_counted_non_finite_run(small):
    sc, inputs = small
    first = int(round(sc.transient * sc.sensors.rate_hz))
    accel = inputs.accel.copy()
    accel[1, first + 100] = 0.0  # run 1, after the transient: eq. 17-b divides by |f| = 0
    bad = dataclasses.replace(inputs, accel=accel)
    with np.errstate(invalid="ignore", divide="ignore"):
        est = run_filters(sc, bad, ("linear_kf", "accel_leveling"), log=lambda m: None)
    rows = [r for e in est.values() for r in estimates_trouble(e, inputs.truth, "monte_carlo")]
    counts = _counts(rows)
    assert counts["accel_leveling", "non_finite"] == 1
    assert counts["accel_leveling", "sigma_not_positive"] == 0  # no covariance: not counted
    # the summary keeps the run: its RMS is NaN, over the 3 runs it says
    with np.errstate(invalid="ignore"):
        row = summary_row(est["accel_leveling"], inputs.truth, first)
    assert row["n_runs"] == 3 and np.isnan(row["roll_rms_deg"])
    # the clean inputs: the same filters meet no trouble (computed)
    clean = run_filters(sc, inputs, ("linear_kf", "accel_leveling"), log=lambda m: None)
    clean_rows = [r for e in clean.values() for r in estimates_trouble(e, inputs.truth, "mc")]
    for (f, kind), n in _counts(clean_rows).items():
        e = clean[f]
        if kind == "non_finite":
            assert n == int((~np.isfinite(np.hstack([e.roll, e.pitch]))).any(axis=1).sum())


def test_diverged_and_sigma_counts(small):
    _, inputs = small
    tr = inputs.truth
    n, t1 = 4, tr.t.size
    roll = np.tile(tr.roll, (n, 1))
    pitch = np.tile(tr.pitch, (n, 1))
    roll[0, 10] += np.deg2rad(DIVERGED_DEG + 1.0)  # run 0 diverged
    pitch[2, 5] = np.nan  # run 2 non-finite
    sigma = np.full((n, t1), 0.01)
    sigma[3, 7] = -1e-9  # run 3: a negative variance's square root
    sigma[1, 0] = np.nan  # run 1
    est = Estimates("linear_kf", roll, pitch, sigma, sigma.copy(), np.zeros((n, t1, 3)), sigma * 0)
    frame = trouble_frame(estimates_trouble(est, tr, "monte_carlo"))
    assert list(frame.columns) == TROUBLE_COLUMNS
    got = frame.set_index("kind")["n_affected"].to_dict()
    assert got == {"non_finite": 1, "diverged": 1, "sigma_not_positive": 2}
    assert set(frame["n_trials"]) == {4}


def test_page_note(tmp_path):
    path = tmp_path / "numerical_trouble.csv"
    rows = [
        ("monte_carlo", "", "ukf", "non_finite", 100, 0),
        ("noise_free", "", "ukf", "diverged", 1, 0),
    ]
    pd.DataFrame(rows, columns=TROUBLE_COLUMNS).to_csv(path, index=False)
    text = filter_trouble_blocks(path)[0].text
    assert text.startswith("No numerical trouble in Monte Carlo (100 runs), noise-free run (1 run)")
    rows[0] = ("monte_carlo", "", "ukf", "non_finite", 100, 2)
    pd.DataFrame(rows, columns=TROUBLE_COLUMNS).to_csv(path, index=False)
    blocks = filter_trouble_blocks(path)
    assert blocks[0].text.startswith("Numerical trouble in Monte Carlo (100 runs)")
    assert "Accelerometer levelling" not in blocks[0].text  # said only where it applies
    assert blocks[1].rows == [
        ["Monte Carlo", "ukf", "NaN or infinite roll or pitch estimate", "2 of 100"]
    ]
