"""The UKF tuning grid (ukf_tuning.csv): the chosen setting follows the stated rule, and the
grid's row of the scenario's own setting is the scenario's UKF result."""

from __future__ import annotations

import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest

from pipeline.altimeter_attitude import run
from pipeline.altimeter_attitude.columns import UKF_TUNING_COLUMNS
from pipeline.altimeter_attitude.scenario import build_scenario, load_scenario
from pipeline.altimeter_attitude.ukf import MerweWeights
from pipeline.altimeter_attitude.ukf_tuning import N_STATE, nonnegative_weights, run_tuning
from pipeline.config import load_yaml

SCENARIOS = sorted(Path("config/scenarios/altimeter_attitude").glob("*.yaml"))
PAPER = Path("config/scenarios/altimeter_attitude/paper.yaml")


@pytest.mark.parametrize("path", SCENARIOS, ids=lambda p: p.stem)
def test_every_scenario_uses_nonnegative_sigma_point_weights(path):
    """The decision's rule: all mean and covariance weights >= 0 (alpha 0.5, kappa 0, the
    earlier setting with W0 = -3, fails it)."""
    sc = load_scenario(path)
    assert nonnegative_weights(sc.ukf_alpha, sc.ukf_beta, sc.ukf_kappa)
    assert not nonnegative_weights(0.5, sc.ukf_beta, 0.0)
    assert MerweWeights(N_STATE, 0.5, sc.ukf_beta, 0.0).Wm[0] == pytest.approx(-3.0)


def test_the_rule_picks_one_setting_of_the_configured_grid():
    """Of the grid in config/config.yaml, exactly one setting has every weight >= 0, and it is
    the published scenario's (so the rule, not a preference, decides)."""
    grid = load_yaml("config/config.yaml")["altimeter_attitude"]["ukf_tuning"]
    sc = load_scenario(PAPER)
    ok = [(a, k) for a in grid["alpha"] for k in grid["kappa"] if nonnegative_weights(a, 2.0, k)]
    assert ok == [(sc.ukf_alpha, sc.ukf_kappa)]
    assert 3.0 - N_STATE in grid["kappa"] and 0.0 in grid["kappa"]


@pytest.fixture(scope="module")
def short_paper():
    """The paper scenario cut to its first 30 s, with the transient at 5 s."""
    base = load_scenario(PAPER)
    raw = {**base.raw, "trajectory": {**base.raw["trajectory"], "duration_s": 30.0}}
    raw["trajectory"]["maneuvers"] = [
        m for m in base.raw["trajectory"]["maneuvers"] if m["start_s"] + m["duration_s"] <= 30.0
    ]
    raw["metrics"] = {**raw["metrics"], "transient_s": 5.0}
    return build_scenario(raw, base.path)


def test_chosen_row_is_the_scenarios_own_ukf_result(short_paper):
    """The grid's row of the scenario's setting equals rms_summary.csv's and noise_free.csv's
    UKF rows of the same scenario and runs, to the bit; another alpha differs."""
    frame = run_tuning(short_paper, [0.5, 1.0], [0.0], n_runs=3, log=lambda m: None)
    assert list(frame.columns) == UKF_TUNING_COLUMNS and len(frame) == 2
    assert frame["chosen"].tolist() == [False, True]
    assert frame["status"].tolist() == ["ok", "ok"]
    assert frame["wm0"].tolist() == [pytest.approx(-3.0), 0.0]
    inputs, mc, nf = run.simulate(short_paper, 3, filters=("ukf",), log=lambda m: None)
    mine = run.summary_frame(short_paper, inputs, mc).set_index("filter").loc["ukf"]
    clean = run.summary_frame(short_paper, inputs, nf).set_index("filter").loc["ukf"]
    chosen = frame[frame["chosen"]].iloc[0]
    for q in ("roll_rms_deg", "pitch_rms_deg", "nees_roll", "nees_pitch"):
        assert chosen[q] == mine[q]
    assert chosen["noise_free_pitch_rms_deg"] == clean["pitch_rms_deg"]
    other = frame[~frame["chosen"]].iloc[0]
    assert other["pitch_rms_deg"] != chosen["pitch_rms_deg"]
    assert all(math.isfinite(x) for x in frame["noise_free_roll_rms_deg"])


def test_tuning_frame_is_deterministic(short_paper):
    a = run_tuning(short_paper, [1.0], [0.0, -1.0], n_runs=2, log=lambda m: None)
    b = run_tuning(short_paper, [1.0], [0.0, -1.0], n_runs=2, log=lambda m: None)
    pd.testing.assert_frame_equal(a, b, check_exact=True)
    assert np.all(a["kappa"].to_numpy() == [0.0, -1.0])
