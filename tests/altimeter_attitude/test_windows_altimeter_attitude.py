"""Averaging windows: the window after the first bank starts where the first bank ends, on the trajectory, and
window_summary.csv / window_run_rms.csv hold the same statistics as rms_summary.csv / run_rms.csv
from each window's start."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pytest

from pipeline.altimeter_attitude import metrics, windows
from pipeline.altimeter_attitude.columns import (
    SWEEP_COLUMNS,
    WINDOW_RUN_RMS_COLUMNS,
    WINDOW_SUMMARY_COLUMNS,
    WINDOWS,
)
from pipeline.altimeter_attitude.run import run_filters
from pipeline.altimeter_attitude.scenario import build_scenario, load_scenario
from pipeline.altimeter_attitude.sensors import simulate_inputs

SCENARIOS = sorted(Path("config/scenarios/altimeter_attitude").glob("*.yaml"))
GENTLE = "config/scenarios/altimeter_attitude/gentle_cruise.yaml"


@pytest.mark.parametrize("path", SCENARIOS, ids=lambda p: p.stem)
def test_after_bank_window_starts_where_the_first_bank_ends(path):
    sc = load_scenario(path)
    flight, after = windows.scenario_windows(sc)
    assert (flight.name, after.name) == WINDOWS
    t = windows.state_times(sc)
    roll = np.degrees(np.abs(sc.profiles.roll(t)[0]))
    bank = math.degrees(sc.after_bank)
    assert flight.start == pytest.approx(sc.transient) and flight.end == t[-1]
    k = after.first
    assert k is not None and after.start == t[k] and after.end == t[-1]
    # level at the start, banked just before it, and banked once before it: the first bank
    assert roll[k] < bank <= roll[k - 1]
    first_bank = int(np.argmax(roll >= bank))
    assert first_bank < k and (roll[first_bank:k] >= bank).all()


def test_no_bank_no_after_bank_window(tmp_path):
    base = load_scenario(GENTLE)
    raw = {**base.raw, "trajectory": {**base.raw["trajectory"], "maneuvers": []}}
    sc = build_scenario(raw, base.path)
    _, after = windows.scenario_windows(sc)
    assert not after.defined and math.isnan(after.start)


@pytest.fixture(scope="module")
def simulated():
    """gentle_cruise (a bank up to 18 deg at 70-90 s), 3 runs, the linear filter and the UKF."""
    sc = load_scenario(GENTLE)
    inp = simulate_inputs(sc.profiles, sc.sensors, sc.initial, 3, sc.seed, sc.name)
    est = run_filters(sc, inp, ("linear_kf", "ukf"), log=lambda m: None)
    return sc, inp, est


def test_window_files_repeat_the_summaries_from_each_start(simulated):
    sc, inp, est = simulated
    wins = windows.scenario_windows(sc)
    summary = windows.summary_frame(wins, est, inp.truth)
    runs = windows.run_frame(wins, est, inp.truth)
    assert list(summary.columns) == WINDOW_SUMMARY_COLUMNS
    assert list(runs.columns) == WINDOW_RUN_RMS_COLUMNS
    first = int(round(sc.transient * sc.sensors.rate_hz))
    for w in wins:
        start = first if w.name == "flight" else w.first
        for name, e in est.items():
            row = summary[(summary["window"] == w.name) & (summary["filter"] == name)].iloc[0]
            expected = metrics.summary_row(e, inp.truth, start)
            for col, value in expected.items():
                assert row[col] == value, (w.name, name, col)
            per_run = runs[(runs["window"] == w.name) & (runs["filter"] == name)]
            ref = metrics.run_rms_frame(e, inp.truth, start)
            assert np.array_equal(per_run["roll_rms_deg"], ref["roll_rms_deg"])
            # the RMS over runs and times is the RMS of the per-run RMS (equal-length runs)
            assert math.sqrt(np.mean(per_run["pitch_rms_deg"] ** 2)) == pytest.approx(
                row["pitch_rms_deg"], rel=1e-12
            )
    after = summary[summary["window"] == "after_bank"]
    assert (after["t_start_s"] == wins[1].start).all() and wins[1].start > sc.transient


def test_undefined_window_rows_are_nan(simulated):
    sc, inp, est = simulated
    wins = (
        windows.Window("flight", 100, 2.0, 120.0),
        windows.Window("after_bank", None, math.nan, 1.0),
    )
    summary = windows.summary_frame(wins, est, inp.truth)
    after = summary[summary["window"] == "after_bank"]
    assert after["roll_rms_deg"].isna().all() and (after["n_runs"] == 3).all()
    runs = windows.run_frame(wins, est, inp.truth)
    assert runs.loc[runs["window"] == "after_bank", "pitch_rms_deg"].isna().all()
    assert len(runs) == 2 * 2 * 3


def test_sweep_reports_each_points_after_bank_window():
    from pipeline.altimeter_attitude.sweep import run_sweep

    sc = load_scenario(GENTLE)
    frame = run_sweep(sc, {"intensity": [1.0, 1.5]}, 2, ("linear_kf",), log=lambda m: None)
    assert list(frame.columns) == SWEEP_COLUMNS
    for v, row in frame.set_index("value").iterrows():
        variant = build_scenario(
            {**sc.raw, "trajectory": {**sc.raw["trajectory"], "intensity": v}}, sc.path
        )
        assert row["after_bank_start_s"] == windows.scenario_windows(variant)[1].start
        assert 0 < row["after_bank_roll_rms_deg"] and math.isfinite(row["after_bank_pitch_rms_deg"])
    # a harder turn banks more and ends its bank of >= 10 deg later
    starts = frame.set_index("value")["after_bank_start_s"]
    assert starts[1.5] > starts[1.0]
