"""Numerical trouble of the north-finding estimators is counted, never silent: each clip site
counts exactly the trials it clipped, a readings run writes the counts, and the page says so."""

from __future__ import annotations

import dataclasses

import numpy as np
import pandas as pd
import pytest

from pipeline.generated import north_finding as gen
from pipeline.north_finding import estimators as est
from pipeline.north_finding import readings as rd
from pipeline.north_finding.report_trouble import trouble_blocks
from pipeline.north_finding.run import run_scenario
from pipeline.north_finding.scenario import ROOT, load_scenario
from pipeline.north_finding.trouble import TROUBLE_COLUMNS, TROUBLE_KINDS, Trouble

READINGS = ROOT / "config" / "scenarios" / "north_finding" / "example_readings.yaml"


def _count(t: Trouble, method: str, kind: str, n: int) -> int:
    est_ = {(method, "x"): np.zeros(n)}
    frame = t.frame(est_, "r")
    return int(frame.loc[frame["kind"] == kind, "n_affected"].iloc[0])


def test_arcsine_clips_are_counted_per_trial():
    t = Trouble()
    out = est._asin(np.array([0.5, 1.2, -1.0001, 1.0]), t, "L1")
    assert np.allclose(np.degrees(out), [30.0, 90.0, -90.0, 90.0])
    assert _count(t, "L1", "clipped_arcsine", 4) == 2  # exactly +-1 is in the domain


def test_unreachable_sinusoid_roots_are_counted():
    t = Trouble()
    est._two_roots(np.ones(3), np.zeros(3), np.array([0.5, 2.0, -1.5]), t, "A4")
    assert _count(t, "A4", "unreachable_root", 3) == 2


def test_quartic_without_real_root_is_counted():
    """Method A3 with the measured maximum beyond the reachable one (no real root of eq. 50)
    falls back to the real parts, and says so; at the true maximum it has a real root."""
    lat, theta, phi, om = np.radians(35.0), np.radians(30.0), np.radians(50.0), 7.292115e-5
    reachable = om  # the x gyro can read at most the whole Earth rate
    w = np.array([0.9 * reachable, 5.0 * reachable])
    coeffs = gen.a3_eq47_coeffs(w, om, lat, np.full(2, theta), np.full(2, phi))
    t = Trouble()
    est.solve_quartic_psi(coeffs, np.radians(np.full(2, 88.0)), t)
    assert _count(t, "A3", "complex_roots", 2) == 1


def test_readings_run_writes_the_counts_and_a_bad_reading_is_caught(tmp_path):
    sc = load_scenario(READINGS)
    run_scenario(sc, tmp_path, log=lambda m: None)
    frame = pd.read_csv(tmp_path / "numerical_trouble.csv")
    assert list(frame.columns) == TROUBLE_COLUMNS
    assert set(frame["kind"]) == set(TROUBLE_KINDS) and set(frame["run"]) == {"readings"}
    assert frame["n_affected"].sum() == 0  # the shipped (simulated) readings are clean
    assert "No numerical trouble" in trouble_blocks(tmp_path / "numerical_trouble.csv")[0].text

    # the same readings with the accelerometer scaled past g: levelling's arcsines clip
    readings = rd.load_readings_csv(sc.readings_csv)
    loud = dataclasses.replace(readings, accel=readings.accel * 3.0)
    t = Trouble()
    out = est.estimate_all(
        loud,
        est.Site(sc.lat, sc.g, sc.omega_ie),
        sc.methods,
        sc.level_source,
        None,
        np.array([sc.compass_heading]),
        sc.raw.get("a2_tau_deg"),
        t,
    )
    counts = t.frame(out, "readings").set_index(["method", "kind"])["n_affected"]
    assert counts["L1", "clipped_arcsine"] == 1


def test_page_lists_every_method_and_kind_with_trouble(tmp_path):
    path = tmp_path / "numerical_trouble.csv"
    pd.DataFrame(
        [
            ("monte_carlo", "", "A3", "complex_roots", 1000, 7),
            ("monte_carlo", "", "L1", "non_finite", 1000, 0),
        ],
        columns=TROUBLE_COLUMNS,
    ).to_csv(path, index=False)
    blocks = trouble_blocks(path)
    assert "Numerical trouble in Monte Carlo (1000 trials)" in blocks[0].text
    shown = blocks[1].frame if hasattr(blocks[1], "frame") else None
    text = repr(blocks[1])
    assert "7 of 1000" in text and "A3" in text and "L1" not in text, (shown, text)


def test_unknown_kind_refused():
    with pytest.raises(ValueError, match="allowed: clipped_arcsine"):
        Trouble().mark("L1", "clipped", np.array([True]))


# --------------------------------------------------------------------------- whole runs
def _trouble(path) -> pd.DataFrame:
    return pd.read_csv(path, keep_default_na=False)


def _check_summary_counts(d) -> None:
    """mc_summary's n_trials is the finite trials of mc_trials, method by method, and the
    Monte Carlo's non_finite count is the trials with any non-finite estimate of the method."""
    trials = pd.read_csv(d / "mc_trials.csv")
    summary = pd.read_csv(d / "mc_summary.csv").set_index(["method", "quantity"])
    finite = trials.groupby(["method", "quantity"])["estimate"].count()
    assert (summary["n_trials"] == finite.reindex(summary.index)).all()
    bad = trials.assign(bad=~np.isfinite(trials["estimate"]))
    per_method = bad.groupby(["method", "trial"])["bad"].any().groupby("method").sum()
    tr = _trouble(d / "numerical_trouble.csv")
    mc = tr[(tr["run"] == "monte_carlo") & (tr["kind"] == "non_finite")].set_index("method")
    assert (mc["n_affected"] == per_method.reindex(mc.index)).all()


def test_latitude_near_the_pole_forces_counted_trouble(tmp_path):
    """At latitude 89.99 deg the Earth rate has almost no horizontal part: the azimuth
    methods clip, lose their real roots and give NaN; every run of the scenario counts it,
    and the Monte Carlo summary's trial counts are the trials it used."""
    sc = load_scenario(ROOT / "config" / "scenarios" / "north_finding" / "high_latitude.yaml")
    polar = dataclasses.replace(sc, lat=float(np.deg2rad(89.99)))
    run_scenario(polar, tmp_path, log=lambda m: None)
    tr = _trouble(tmp_path / "numerical_trouble.csv")
    assert list(tr.columns) == TROUBLE_COLUMNS
    hit = tr[tr["n_affected"] > 0]
    assert {"monte_carlo", "sensitivity"} <= set(hit["run"])
    assert set(hit["kind"]) >= {"clipped_arcsine", "unreachable_root", "complex_roots"}
    assert (tr["n_affected"] <= tr["n_trials"]).all()
    sens = tr[tr["run"] == "sensitivity"]
    assert set(sens["case"]) == {f"N={n}" for n in sc.sensitivity["n_avg"]}
    assert set(sens["n_trials"]) == {sc.sensitivity["n_trials"]}
    _check_summary_counts(tmp_path)
    text = " ".join(
        getattr(b, "text", repr(b)) for b in trouble_blocks(tmp_path / "numerical_trouble.csv")
    )
    assert text.startswith("Numerical trouble in ") and "sensitivity Monte Carlo at" in text


@pytest.mark.parametrize("name", ["third_quadrant_south", "high_latitude"])
def test_shipped_scenarios_counts_are_the_computed_ones(tmp_path, name):
    """The shipped scenarios' counts (whatever they are) agree with their trials."""
    run_scenario(
        load_scenario(ROOT / f"config/scenarios/north_finding/{name}.yaml"),
        tmp_path,
        log=lambda m: None,
    )
    _check_summary_counts(tmp_path)
    tr = _trouble(tmp_path / "numerical_trouble.csv")
    assert set(tr["run"]) >= {"noise_free_real", "monte_carlo"}


def test_summary_skips_a_nan_trial_and_says_so():
    from pipeline.north_finding.run import summary_frame

    trials = pd.DataFrame(
        {
            "trial": [0, 1, 2, 3],
            "method": "L1",
            "quantity": "phi_deg",
            "truth": 1.0,
            "estimate": [1.0, np.nan, 3.0, 2.0],
            "error_pct": 0.0,
        }
    )
    row = summary_frame(trials).iloc[0]
    assert row["n_trials"] == 3 and row["mean"] == pytest.approx(2.0)


def test_n_inference_trial_count_is_the_trials_used():
    """A NaN trial injected at one grid N: that N's n_trials says one fewer."""
    from pipeline.north_finding.n_inference import infer_frames
    from pipeline.north_finding.run import trials_frame

    rng = np.random.default_rng(1)
    base = rng.standard_normal(200)

    def run(n: int):
        v = 10.0 + base / np.sqrt(n)
        if n == 100:
            v = v.copy()
            v[5] = np.nan
        return {("L1", "phi_deg"): v}

    items = [{"id": "T.x", "select": {"method": "L1"}, "quantity": "phi_deg", "value": "10.0"}]
    frames = infer_frames(run, lambda e: trials_frame(e, {"phi_deg": 10.0}), items, [10, 100], 0.05)
    assert frames["n_profile"]["n_trials"].tolist() == [200, 199]
    # the verdict's mixture leaves the NaN trial out and says so
    from pipeline.north_finding.judged_n import judged_at

    at = judged_at(
        {"n_rows": frames["n_rows"], "mc_trials_judged": frames["mc_trials_judged"]}, items[0]
    )
    assert at.weight_by_n.get(100, 0.0) > 0  # the N with the NaN trial carries weight
    assert np.isfinite(at.samples).all()
    said = [n for n in at.notes if "non-finite (numerical trouble)" in n]
    assert said == ["1 of 400 trials non-finite (numerical trouble), left out of the mixture"]
