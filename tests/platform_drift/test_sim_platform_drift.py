"""Simulation side of the platform-drift paper: floors, eqs. 32/36, Schuler period, bad input,
reproducibility.

The scenario files are run once per module (all five runs take a few seconds).
"""

from __future__ import annotations

import copy
import math
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import yaml

from pipeline.config import ConfigError
from pipeline.platform_drift import analytic
from pipeline.platform_drift import platform as pf
from pipeline.platform_drift.run import (
    DIAGNOSTIC_SCHEME,
    ERRORS_COLUMNS,
    SCHEMES,
    SUMMARY_COLUMNS,
    crossover,
    run_scenario,
    simulate_errors,
)
from pipeline.platform_drift.scenario import build_scenario, load_scenario
from pipeline.platform_drift.trajectory import haversine

REPO = Path(__file__).resolve().parents[2]
SCEN = REPO / "config" / "scenarios" / "platform_drift"
NAMES = ("stationary", "latitude_change", "longitude_change", "lat_lon_change")

FLOOR_M = 0.01  # no-drift error bound over 2 h (measured: < 0.04 mm for both schemes)
FLOOR_LONG_M = 0.01  # over 24 h, stationary


def curve(df: pd.DataFrame, case: str, scheme: str) -> tuple[np.ndarray, np.ndarray]:
    sub = df[(df["case"] == case) & (df["scheme"] == scheme)].sort_values("t_s")
    return sub["t_s"].to_numpy(), sub["error_m"].to_numpy()


@pytest.fixture(scope="module")
def results(tmp_path_factory) -> dict[str, dict[str, pd.DataFrame]]:
    out = {}
    for name in NAMES:
        d = tmp_path_factory.mktemp(name)
        files = run_scenario(SCEN / f"{name}.yaml", d, log=lambda m: None)
        out[name] = {k: pd.read_csv(v) for k, v in files.items() if str(v).endswith(".csv")}
        out[name]["dir"] = d
    return out


# --------------------------------------------------------------------------------------------
# results contract
# --------------------------------------------------------------------------------------------
def test_files_and_columns(results):
    for name in NAMES:
        r = results[name]
        assert list(r["errors"].columns) == ERRORS_COLUMNS
        assert list(r["summary"].columns) == SUMMARY_COLUMNS
        assert set(r["errors"]["scheme"]) == set(SCHEMES)
        assert set(r["errors_diagnostic"]["scheme"]) == {DIAGNOSTIC_SCHEME}
        t, _ = curve(r["errors"], "ch1", "strapdown")
        np.testing.assert_array_equal(t, np.arange(0, 7201, 10.0))
        assert (Path(r["dir"]) / "provenance.json").is_file()
    assert "errors_long" in results["stationary"]
    t, _ = curve(results["stationary"]["errors_long"], "ch3", "strapdown")
    assert t[-1] == 86400.0 and np.all(np.diff(t) == 10.0)


# --------------------------------------------------------------------------------------------
# no-drift error floors
# --------------------------------------------------------------------------------------------
@pytest.mark.parametrize("name", NAMES)
def test_no_drift_floor(results, name):
    errors = results[name]["errors"]
    for scheme in ("proposed_simulated", "strapdown"):
        _, e = curve(errors, "none", scheme)
        assert e.max() < FLOOR_M, (name, scheme, e.max())
    _, e = curve(errors, "none", "proposed_analytic")
    assert np.all(e == 0.0)


def test_no_drift_floor_long(results):
    for scheme in ("proposed_simulated", "strapdown"):
        _, e = curve(results["stationary"]["errors_long"], "none", scheme)
        assert e.max() < FLOOR_LONG_M, (scheme, e.max())


def test_zero_error_at_start(results):
    for name in NAMES:
        errors = results[name]["errors"]
        assert np.all(errors.loc[errors["t_s"] == 0.0, "error_m"].abs() < 1e-6)


# --------------------------------------------------------------------------------------------
# channel 1, stationary: eq. 32, and the paper's "equal for both schemes"
# --------------------------------------------------------------------------------------------
def test_ch1_stationary_matches_eq32(results):
    errors = results["stationary"]["errors"]
    t, sim = curve(errors, "ch1", "proposed_simulated")
    _, ana = curve(errors, "ch1", "proposed_analytic")
    late = t >= 3600.0
    rel = np.abs(sim[late] - ana[late]) / ana[late]
    assert rel.max() < 0.03, rel.max()


def test_ch1_stationary_strapdown_equals_proposed(results):
    errors = results["stationary"]["errors"]
    t, sim = curve(errors, "ch1", "proposed_simulated")
    _, strap = curve(errors, "ch1", "strapdown")
    late = t >= 1800.0
    rel = np.abs(strap[late] - sim[late]) / sim[late]
    assert rel.max() < 0.10, rel.max()


def test_ch1_schuler_period(results):
    """Fit a t + b + c sin(w t) + d cos(w t) to the simulated ch1 error; 2 pi / w ~ 84.4 min."""
    t, e = curve(results["stationary"]["errors"], "ch1", "proposed_simulated")
    periods = np.arange(60.0, 110.0, 0.01) * 60.0
    best, best_res = None, np.inf
    for period in periods:
        w = 2 * np.pi / period
        design = np.column_stack((t, np.ones_like(t), np.sin(w * t), np.cos(w * t)))
        _, res, *_ = np.linalg.lstsq(design, e, rcond=None)
        if res.size and res[0] < best_res:
            best, best_res = period, res[0]
    sc = load_scenario(SCEN / "stationary.yaml")
    expected = analytic.constants(sc)["schuler_period_s"]
    assert abs(expected / 60.0 - 84.4) < 0.1
    assert abs(best - expected) / expected < 0.01, (best / 60.0, expected / 60.0)


# --------------------------------------------------------------------------------------------
# channel 3, stationary: eq. 36 and boundedness over 24 h
# --------------------------------------------------------------------------------------------
def test_ch3_tilt_only_error_matches_eq36(results):
    """With the true azimuth in eq. 16, the simulated error is the one eqs. 33-36 model."""
    t, diag = curve(results["stationary"]["errors_diagnostic"], "ch3", DIAGNOSTIC_SCHEME)
    _, ana = curve(results["stationary"]["errors"], "ch3", "proposed_analytic")
    assert np.max(np.abs(diag - ana)) < 0.02 * ana.max()


def test_ch3_stationary_24h_bounded_vs_growing(results):
    long = results["stationary"]
    t, strap = curve(long["errors_long"], "ch3", "strapdown")
    _, ana = curve(long["errors_long"], "ch3", "proposed_analytic")
    _, diag = curve(long["errors_long_diagnostic"], "ch3", DIAGNOSTIC_SCHEME)
    _, sim = curve(long["errors_long"], "ch3", "proposed_simulated")
    first, last = t <= 43200.0, t > 43200.0
    # the paper's analysis (eq. 36) and the tilt-only simulation: bounded
    for e in (ana, diag):
        assert e[last].max() <= 1.5 * e[first].max()
        assert e.max() < 1000.0
    # strapdown grows
    assert strap[last].max() > 1.2 * strap[first].max()
    assert strap[t == 7200.0][0] > 10 * diag.max()
    # FINDING: the full algorithm (free azimuth psi of eq. 16, r_m = 0) does not see the
    # azimuth drift; its error is the strapdown's, not eq. 36's
    late = t >= 3600.0
    rel = np.abs(sim[late] - strap[late]) / strap[late]
    assert rel.max() < 0.01, rel.max()


def test_ch1_ch3_analytic_is_vector_sum(results):
    sc = load_scenario(SCEN / "stationary.yaml")
    t = np.arange(0.0, 7201.0, 10.0)
    e1 = analytic.error_m(sc, "ch1", t)
    e3 = analytic.error_m(sc, "ch3", t)
    e13 = analytic.error_m(sc, "ch1_ch3", t)
    assert np.all(e13 <= e1 + e3 + 1e-9)
    assert np.all(e13 >= np.abs(e1 - e3) - 1e-9)
    # the vector sum of the signed integrals of eq. 32 and eq. 36 follows the tilt-only simulation
    _, diag = curve(results["stationary"]["errors_diagnostic"], "ch1_ch3", DIAGNOSTIC_SCHEME)
    assert np.max(np.abs(diag - e13)) < 0.01 * e13.max()


# --------------------------------------------------------------------------------------------
# summary
# --------------------------------------------------------------------------------------------
def test_summary_consistent(results):
    for name in NAMES:
        r = results[name]
        for row in r["summary"].itertuples():
            src = r["errors_diagnostic"] if row.scheme == DIAGNOSTIC_SCHEME else r["errors"]
            t, e = curve(src, row.case, row.scheme)
            assert row.error_2h_m == e[-1]
            assert row.error_max_m == e.max()
        sub = r["summary"].set_index(["case", "scheme"])["crossover_s"]
        for case in dict.fromkeys(r["summary"]["case"]):
            a, b = sub[case, "proposed_simulated"], sub[case, "strapdown"]
            assert (math.isnan(a) and math.isnan(b)) or a == b


def test_crossover_rule():
    t = np.arange(0.0, 1000.0, 10.0)
    other = np.full_like(t, 100.0)
    strap = t / 5.0  # below until 500 s, exceeds 100 + 1 m at t = 505 s (interpolated)
    assert crossover(t, strap, other) == 505.0
    assert math.isnan(crossover(t, other, other))  # equal curves never cross
    # above from the start: never below, so no crossover (the summary and the verdicts agree)
    assert math.isnan(crossover(t, other + 5.0, other))
    # starting together and parting later is not a crossover either
    assert math.isnan(crossover(t, other + 0.01 * t, other))


# --------------------------------------------------------------------------------------------
# model checks
# --------------------------------------------------------------------------------------------
def test_initial_state_mass_level_is_level():
    sc = load_scenario(SCEN / "latitude_change.yaml")
    init = pf.initial_state(sc.trajectory(), "mass")
    assert abs(init.phi_x) < 1e-15 and abs(init.phi_y) < 1e-15
    assert init.omega_x == pytest.approx(init.p, rel=1e-12)
    assert abs(init.psi - sc.psi0) < 1e-15


def test_plumb_level_initial_tilt_is_alpha():
    sc = load_scenario(SCEN / "stationary.yaml")
    init = pf.initial_state(sc.trajectory(), "plumb")
    alpha = analytic.constants(sc)["plumb_deflection_rad"]
    # eq. 21 with psi0 = 0: phi_y0 ~ alpha cos(psi0), phi_x0 ~ alpha sin(psi0)
    assert init.phi_y == pytest.approx(alpha, rel=0.01)
    assert abs(init.phi_x) < 1e-12


def test_truth_path_endpoints():
    for name, (dlat, dlon) in {
        "latitude_change": (-75.0, 0.0),
        "longitude_change": (0.0, 75.0),
        "lat_lon_change": (-65.0, 55.0),
    }.items():
        sc = load_scenario(SCEN / f"{name}.yaml")
        lat, lon = sc.trajectory().latlon(np.array([0.0, 7200.0, 9000.0]))
        assert np.rad2deg(lat[1] - lat[0]) == pytest.approx(dlat, abs=1e-9)
        assert np.rad2deg(lon[1] - lon[0]) == pytest.approx(dlon, abs=1e-9)
        assert lat[2] == lat[1] and lon[2] == lon[1]  # at rest after the trip


def test_truth_acceleration_is_derivative_of_velocity():
    sc = load_scenario(SCEN / "lat_lon_change.yaml")
    traj = sc.trajectory()
    for t in (300.0, 2000.0, 6900.0):
        h = 1e-2
        num = (traj.at(t + h).v_i - traj.at(t - h).v_i) / (2 * h)
        np.testing.assert_allclose(traj.at(t).a_i, num, atol=1e-6)
        num_r = (traj.at(t + h).r_i - traj.at(t - h).r_i) / (2 * h)
        np.testing.assert_allclose(traj.at(t).v_i, num_r, atol=1e-5)


def test_generated_specific_force_matches_inertial_kinematics():
    """gen.specific_force_platform (eq. 17, exact) == C^T (a_i + GM r/r^3) from the path."""
    sc = load_scenario(SCEN / "lat_lon_change.yaml")
    traj = sc.trajectory()
    rng = np.random.default_rng(7)
    for t in (0.0, 300.0, 2000.0, 6900.0):
        tr = traj.at(t)
        # random attitudes: any azimuth, tilts up to a few mrad
        q, _ = np.linalg.qr(rng.normal(size=(3, 3)))
        frames = np.stack([traj.body_i(tr), tr.nwu_i @ q @ np.diag([1, 1, np.linalg.det(q)])])
        small = np.stack([tr.nwu_i @ np.eye(3)])
        for c in (*frames, *small):
            np.testing.assert_allclose(traj.specific_force_in(tr, c), c.T @ tr.f_i, atol=1e-12)


def test_haversine_small_and_large():
    assert haversine(0.5, 1.0, 0.5, 1.0) == 0.0
    assert haversine(0.0, 0.0, 0.0, np.pi / 2) == pytest.approx(np.pi / 2)
    assert haversine(0.3, 0.2, 0.3 + 1e-9, 0.2) == pytest.approx(1e-9, rel=1e-6)


def test_drift_compensation_kept_removes_ch1():
    raw = yaml.safe_load((SCEN / "stationary.yaml").read_text())
    raw["platform"]["drift_compensation_lost"] = False
    raw["duration_s"] = raw["long_duration_s"] = 1800.0
    raw["cases"] = ["ch1"]
    sc = build_scenario(raw, Path("kept.yaml"))
    errors, _, _ = simulate_errors(sc, sc.duration, log=lambda m: None)
    _, e = curve(errors, "ch1", "proposed_simulated")
    assert e.max() < FLOOR_M
    _, e = curve(errors, "ch1", "strapdown")  # the strapdown has no alignment compensation
    assert e.max() > 100.0


# --------------------------------------------------------------------------------------------
# bad input -> ConfigError naming file and field, before any compute
# --------------------------------------------------------------------------------------------
def _bad(tmp_path: Path, edit) -> Path:
    raw = yaml.safe_load((SCEN / "stationary.yaml").read_text())
    raw = copy.deepcopy(raw)
    edit(raw)
    path = tmp_path / "bad.yaml"
    path.write_text(yaml.safe_dump(raw))
    return path


@pytest.mark.parametrize(
    "edit, field, words",
    [
        (lambda r: r.__setitem__("cases", ["none", "ch2"]), "cases.1", "must be one of"),
        (lambda r: r.__setitem__("duration_s", -7200.0), "duration_s", "must be > 0"),
        (lambda r: r.__setitem__("long_duration_s", -1.0), "long_duration_s", "must be > 0"),
        (lambda r: r["start"].__setitem__("lat_deg", 95.0), "start.lat_deg", "must be < 90"),
        (lambda r: r.__setitem__("durration_s", 10.0), "(top level)", "unknown key"),
        (lambda r: r["drift"].__setitem__("ch2_deg_h", 0.1), "drift", "unknown key"),
        (
            lambda r: r["platform"].__setitem__("initial_level", "tilted"),
            "platform.initial_level",
            "must be one of",
        ),
        (
            lambda r: r["path"].__setitem__("delta_lat_deg", 60.0),
            "path.delta_lat_deg",
            "must lie in",
        ),
        (lambda r: r.__setitem__("output_step_s", 7.0), "duration_s", "whole number"),
        (
            lambda r: r.__setitem__("decisions", [{"field": "nowhere.at_all", "text": "x"}]),
            "nowhere.at_all",
            "not a field of this scenario",
        ),
    ],
)
def test_bad_input(tmp_path, edit, field, words):
    path = _bad(tmp_path, edit)
    with pytest.raises(ConfigError) as info:
        load_scenario(path)
    msg = str(info.value)
    assert str(path) in msg and field in msg and words in msg, msg


def test_cli_rejects_bad_file(tmp_path, capsys):
    from pipeline.platform_drift.run import main

    path = _bad(tmp_path, lambda r: r.__setitem__("cases", ["ch9"]))
    assert main(["--scenario", str(path), "--out-dir", str(tmp_path / "out")]) == 2
    assert "cases.0" in capsys.readouterr().err
    assert not (tmp_path / "out").exists()


# --------------------------------------------------------------------------------------------
# reproducibility
# --------------------------------------------------------------------------------------------
def test_two_runs_byte_identical(tmp_path):
    a = run_scenario(SCEN / "lat_lon_change.yaml", tmp_path / "a", log=lambda m: None)
    b = run_scenario(SCEN / "lat_lon_change.yaml", tmp_path / "b", log=lambda m: None)
    assert a.keys() == b.keys()
    for key in a:
        assert a[key].read_bytes() == b[key].read_bytes(), key


def test_provenance_has_no_wall_times(results):
    import json

    prov = json.loads((Path(results["stationary"]["dir"]) / "provenance.json").read_text())
    text = json.dumps(prov).lower()
    assert "wall" not in text and "elapsed" not in text and "seconds_taken" not in text
    assert prov["runs"]["main"]["no_drift_floor_m"]["proposed_simulated"] < FLOOR_M
    assert prov["scenario"] == "stationary"
