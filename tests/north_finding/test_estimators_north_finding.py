"""Estimators of north_finding: exact recovery, root selection, reproducibility, CSV round trip.

The ideal-sensor property test draws random attitudes and latitudes (hypothesis,
derandomised) and asks every method for the truth to 1e-9 deg. A method is only asked
where its problem is well posed; that is decided from the sensor model, independently of
the estimator code (:func:`well_posed`):

* every azimuth method solves "model(psi') = measured" for psi' and lets the compass
  (truth + 5 deg) pick among the solutions. Where another solution lies as close to the
  compass as the truth, the compass legitimately picks it: that is the method's ambiguity,
  not an error. So all solutions psi' within 5 + 1 deg of the compass are counted on a
  fine grid, and the method is asked only if the truth is the only one;
* the truth must be a simple root: |d model / d psi| / Omega >= 1e-3 (for A3, the quartic
  of eq. 50 squares eq. 47, so the stricter |d w_max / d psi| / Omega >= 0.05).

A second seeded test checks that these filters keep most of the sample space, so the
property test cannot pass vacuously.
"""

from __future__ import annotations

import dataclasses
import os
import subprocess
import sys
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import yaml
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from pipeline.generated import north_finding as gen
from pipeline.north_finding import columns as col
from pipeline.north_finding import estimators as est
from pipeline.north_finding import readings as rd
from pipeline.north_finding.run import OUTPUTS, run_scenario
from pipeline.north_finding.scenario import ROOT, Scenario, load_scenario
from tests.hang_guard import HANG_GUARD_S

PAPER = ROOT / "config" / "scenarios" / "north_finding" / "paper.yaml"
ALL_SOURCES = ("scale_factor", "misalignment", "bias", "noise")
AZIMUTH = ("A1c1", "A1c2", "A2", "A3", "A4", "A5")
COMPASS_OFFSET_DEG = 5.0
DEG = np.pi / 180


@pytest.fixture(scope="module")
def paper() -> Scenario:
    return load_scenario(PAPER)


def _at(sc: Scenario, phi: float, theta: float, psi: float, lat: float) -> Scenario:
    """The paper scenario at another attitude and latitude (degrees in, radians stored)."""
    truth = {"phi": phi * DEG, "theta": theta * DEG, "psi": psi * DEG}
    return dataclasses.replace(sc, truth=truth, lat=lat * DEG)


def _estimate(
    sc: Scenario, off: tuple[str, ...], methods: tuple[str, ...] | None = None
) -> est.Estimates:
    r = rd.simulate(sc, sc.accel.without(*off), sc.gyro.without(*off), None, 1)
    prior = np.array([sc.truth["psi"] + COMPASS_OFFSET_DEG * DEG])
    return est.estimate_all(
        r,
        est.Site(sc.lat, sc.g, sc.omega_ie),
        methods or sc.methods,
        "truth",
        (sc.truth["theta"], sc.truth["phi"]),
        prior,
        sc.table["a2_tau_deg"],
    )


# --------------------------------------------------------------------------------------------
# well-posedness of each azimuth method, from the sensor model only
# --------------------------------------------------------------------------------------------
def _gyro_x(omega: float, lat: float, psi, theta: float, phi: float, tau_deg: float):
    """Ideal x gyro at table angle tau (still table), over Omega."""
    return gen.angular_rate_b(omega, lat, psi, theta, phi, tau_deg * DEG, 0.0)[0] / omega


def _level_set(method: str, omega: float, lat: float, theta: float, phi: float, psi_true: float):
    """h(psi') whose zeros are the candidate azimuths of ``method`` for the true ``psi_true``."""

    def w(p, tau):
        return _gyro_x(omega, lat, p, theta, phi, tau)

    signatures = {
        "A1c1": lambda p: w(p, 0) - w(p, 180),  # eq. 40
        "A1c2": lambda p: w(p, 90) - w(p, 270),  # eqs. 40-41
        "A2": lambda p: w(p, 45),  # eq. 42, tau = 45 deg (paper.yaml)
        "A3": lambda p: np.hypot(w(p, 0), w(p, 90)),  # eq. 45: largest reading over tau
        "A5": lambda p: np.cos(p),  # eq. 67: arccos, the sign of psi left to the compass
    }
    if method == "A4":  # eq. 57: the direction of (omega_1, omega_2), up to its sign
        return lambda p: w(p, 0) * w(psi_true, 90) - w(p, 90) * w(psi_true, 0)
    sig = signatures[method]
    return lambda p: sig(p) - sig(psi_true)


def _sign_changes(values: np.ndarray) -> int:
    """Number of sign changes along a grid (an exact zero counts as positive)."""
    return int(np.count_nonzero(np.diff(np.signbit(values))))


def _a5_scale_well_posed(omega: float, lat: float, theta: float, phi: float, psi: float) -> bool:
    """Eq. 65 has two roots S; the estimator keeps the one nearest 1. Require the true S = 1 to
    be a simple root with no other root within 1e-3 (written from omega_1 = S X, omega_2 = S Y)."""
    om1 = _gyro_x(omega, lat, psi, theta, phi, 0.0)
    om2 = _gyro_x(omega, lat, psi, theta, phi, 90.0)
    sl, cl, sth, cth, sph, cph = (
        np.sin(lat),
        np.cos(lat),
        np.sin(theta),
        np.cos(theta),
        np.sin(phi),
        np.cos(phi),
    )

    def q(s):
        c = (om1 / s - sth * sl) / (cth * cl)
        sn = (c * sth * sph * cl - cth * sph * sl - om2 / s) / (cph * cl)
        return c**2 + sn**2 - 1

    grid = 1.0 + np.linspace(-1e-3, 1e-3, 2001)
    slope = (q(1 + 1e-7) - q(1 - 1e-7)) / 2e-7
    return abs(slope) > 1e-3 and _sign_changes(q(grid)) == 1


def well_posed(method: str, sc: Scenario) -> bool:
    """True if the compass (truth + 5 deg) singles out the truth and the truth is a simple root."""
    t, lat, om = sc.truth, sc.lat, sc.omega_ie
    h = _level_set(method, om, lat, t["theta"], t["phi"], t["psi"])
    psi = t["psi"]
    d = 1e-6
    slope = (h(psi + d) - h(psi - d)) / (2 * d)
    if abs(slope) < (0.05 if method == "A3" else 1e-3):
        return False
    half_width = (COMPASS_OFFSET_DEG + 1.0) * DEG
    arc = psi + COMPASS_OFFSET_DEG * DEG + np.linspace(-half_width, half_width, 4001)
    if _sign_changes(h(arc)) != 1:
        return False
    if method == "A5":
        return _a5_scale_well_posed(om, lat, t["theta"], t["phi"], psi)
    return True


def _psi_error_deg(estimate: float, truth_deg: float) -> float:
    return abs((estimate - truth_deg + 180.0) % 360.0 - 180.0)


# --------------------------------------------------------------------------------------------
# ideal sensors: every method recovers the truth
# --------------------------------------------------------------------------------------------
signed_angle = st.builds(
    lambda mag, sign: mag * sign, st.floats(1.0, 75.0), st.sampled_from([-1.0, 1.0])
)


@settings(
    max_examples=60,
    deadline=None,
    derandomize=True,
    database=None,
    suppress_health_check=[HealthCheck.too_slow],
)
@given(
    phi=signed_angle,
    theta=signed_angle,
    psi=st.floats(0.0, 360.0, exclude_max=True),
    lat=st.floats(-80.0, 80.0),
)
def test_ideal_sensors_recover_truth(paper, phi, theta, psi, lat):
    sc = _at(paper, phi, theta, psi, lat)

    # attitude and azimuth with a perfect sensor
    out = _estimate(sc, ALL_SOURCES)
    for m in ("L1", "L2", "L3", "L4"):
        assert out[m, "phi_deg"][0] == pytest.approx(phi, abs=1e-9), m
        assert out[m, "theta_deg"][0] == pytest.approx(theta, abs=1e-9), m
    posed = {m: well_posed(m, sc) for m in AZIMUTH}
    for m in AZIMUTH:
        if posed[m]:
            assert _psi_error_deg(out[m, "psi_deg"][0], psi) < 1e-9, m

    # calibration methods with the nominal S and b kept (no misalignment, no noise)
    cal = _estimate(sc, ("misalignment", "noise"), ("L5", "A4", "A5", "A6"))
    acc, gyr = sc.accel, sc.gyro
    assert cal["L5", "acc_scale"][0] == pytest.approx(acc.scale, rel=1e-12)
    # The bias is (a(0) + a(180)) / 2 of two readings of size ~g: their rounding (~1e-16 g)
    # does not cancel, so the absolute error is ~1e-16 g, not 1e-16 b. Test to 1e-12 g.
    bias_ug = acc.bias / sc.g * 1e6
    assert cal["L5", "acc_bias_ug"][0] == pytest.approx(bias_ug, rel=1e-12 * sc.g / acc.bias)
    assert cal["A6", "gyro_scale"][0] == pytest.approx(gyr.scale, rel=1e-12)
    # the gyro readings (~Omega) are only ~1e3 times the bias: 1e-12 relative holds
    assert cal["A4", "gyro_bias_rad_s"][0] == pytest.approx(gyr.bias, rel=1e-12)
    if posed["A4"]:
        assert _psi_error_deg(cal["A4", "psi_deg"][0], psi) < 1e-9
        x = _gyro_x(sc.omega_ie, sc.lat, sc.truth["psi"], sc.truth["theta"], sc.truth["phi"], 0.0)
        if abs(x) > 1e-2:  # eq. 60: S = omega_1 / X is ill-conditioned where X ~ 0
            assert cal["A4", "gyro_scale"][0] == pytest.approx(gyr.scale, rel=1e-12)
    if posed["A5"]:
        assert cal["A5", "gyro_scale"][0] == pytest.approx(gyr.scale, rel=1e-12)
        assert _psi_error_deg(cal["A5", "psi_deg"][0], psi) < 1e-9


def test_wellposedness_filter_keeps_most_cases(paper):
    """The property test is not vacuous: each method is asked at most random points."""
    rng = np.random.default_rng(11)
    n, kept = 200, dict.fromkeys(AZIMUTH, 0)
    for _ in range(n):
        phi, theta = rng.uniform(1, 75, 2) * rng.choice([-1, 1], 2)
        sc = _at(paper, phi, theta, rng.uniform(0, 360), rng.uniform(-80, 80))
        for m in AZIMUTH:
            kept[m] += well_posed(m, sc)
    assert all(k >= 0.6 * n for k in kept.values()), kept


def test_wellposedness_filter_detects_compass_ambiguity(paper):
    """psi = 357 deg: A1c1 candidates are +-3 deg and the compass (2 deg) is nearer 3 deg, so
    A1c1 is ambiguous (not merely 'psi 3 deg away from 0'); the estimator indeed returns 3."""
    sc = _at(paper, 50.0, 30.0, 357.0, 35.0)
    assert not well_posed("A1c1", sc)
    out = _estimate(sc, ALL_SOURCES, ("A1c1",))
    assert out["A1c1", "psi_deg"][0] == pytest.approx(3.0, abs=1e-9)


def test_paper_case_every_method_and_calibration(paper):
    """The paper's own case (phi 50, theta 30, psi 88, lat 35) is well posed for every method."""
    assert all(well_posed(m, paper) for m in AZIMUTH)
    out = _estimate(paper, ALL_SOURCES)
    for m in AZIMUTH:
        assert _psi_error_deg(out[m, "psi_deg"][0], 88.0) < 1e-9, m
    for m in ("L1", "L2", "L3", "L4"):
        assert out[m, "phi_deg"][0] == pytest.approx(50.0, abs=1e-9)
        assert out[m, "theta_deg"][0] == pytest.approx(30.0, abs=1e-9)


# --------------------------------------------------------------------------------------------
# method 3: the quartic of eq. 50 and root selection
# --------------------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def paper_quartic(paper):
    t = paper.truth
    om, lat = paper.omega_ie, paper.lat
    _, w_peak = gen.a3_peak(om, lat, t["psi"], t["theta"], t["phi"])
    coeffs = tuple(
        np.atleast_1d(c)
        for c in gen.a3_eq47_coeffs(np.array([w_peak]), om, lat, t["theta"], t["phi"])
    )
    quartic = [float(q[0]) for q in gen.a3_quartic_coeffs(*coeffs)]
    return coeffs, quartic, float(w_peak)


def test_quartic_has_four_real_roots_each_solving_eq47(paper, paper_quartic):
    coeffs, quartic, w_peak = paper_quartic
    roots = np.roots(quartic)
    assert np.all(np.abs(roots.imag) < 1e-12)
    c = np.sort(roots.real)
    assert np.all(np.abs(c) < 1)
    a_e = [float(x[0]) for x in coeffs]
    t = paper.truth
    psis = []
    for ci in c:
        s = np.sqrt(1 - ci**2)
        res = [abs(gen.a3_eq47_residual(ci, sg * s, *a_e)) for sg in (1, -1)]
        # exactly one sign of sin(psi) satisfies the unsquared eq. 47 (the other is spurious)
        assert min(res) < 1e-12 and max(res) > 1e-3
        psi = np.arctan2(s if res[0] < res[1] else -s, ci)
        psis.append(psi)
        # independent of eq. 47: psi reproduces the largest gyro reading over tau
        peak = np.hypot(
            *(_gyro_x(paper.omega_ie, paper.lat, psi, t["theta"], t["phi"], d) for d in (0, 90))
        )
        assert peak * paper.omega_ie == pytest.approx(w_peak, rel=1e-10)
    psis_deg = sorted(np.rad2deg(psis) % 360)
    assert len(psis_deg) == 4 and min(np.diff(psis_deg)) > 10
    assert any(abs(p - 88.0) < 1e-9 for p in psis_deg)
    # the compass picks each of them when it reads near it
    for p in psis_deg:
        got = est.solve_quartic_psi(coeffs, np.array([(p + 2.0) * DEG]))
        assert _psi_error_deg(np.rad2deg(got[0]), p) < 1e-9
    got = est.solve_quartic_psi(coeffs, np.array([93.0 * DEG]))
    assert _psi_error_deg(np.rad2deg(got[0]), 88.0) < 1e-9


def test_quartic_vectorised_over_trials(paper_quartic):
    coeffs, _, _ = paper_quartic
    many = tuple(np.repeat(c, 3) for c in coeffs)
    got = np.rad2deg(est.solve_quartic_psi(many, np.deg2rad([93.0, 50.0, 150.0]))) % 360
    np.testing.assert_allclose(got[0], 88.0, atol=1e-9)
    assert abs(got[1] - 46.479) < 1e-2 and abs(got[2] - 157.048) < 1e-2


# --------------------------------------------------------------------------------------------
# select_nearest
# --------------------------------------------------------------------------------------------
def test_select_nearest_wraps_angles():
    cand = np.deg2rad([[300.0, 1.0], [1.0, 300.0]])
    got = est.select_nearest(cand, np.deg2rad([359.0, 359.0]))
    np.testing.assert_allclose(np.rad2deg(got), [1.0, 1.0])
    # and the other way round: a prior just above 0 picks 359 over 60
    got = est.select_nearest(np.deg2rad([[60.0, 359.0]]), np.deg2rad([1.0]))
    np.testing.assert_allclose(np.rad2deg(got), [359.0])


def test_select_nearest_skips_invalid_and_nan():
    cand = np.deg2rad([[10.0, np.nan, 200.0], [10.0, 12.0, 200.0], [np.nan, np.nan, np.nan]])
    valid = np.array([[False, True, True], [True, True, True], [True, True, True]])
    got = est.select_nearest(cand, np.deg2rad([11.0, 11.9, 0.0]), valid)
    assert np.rad2deg(got[0]) == pytest.approx(200.0)
    assert np.rad2deg(got[1]) == pytest.approx(12.0)
    assert np.isnan(got[2])


# --------------------------------------------------------------------------------------------
# Monte Carlo reproducibility
# --------------------------------------------------------------------------------------------
def _small_paper(directory: Path, n_trials: int, **changes) -> Path:
    raw = yaml.safe_load(PAPER.read_text(encoding="utf-8"))
    raw["monte_carlo"]["n_trials"] = n_trials
    raw["sensitivity"] = {"n_avg": [10_000, 1_000_000], "n_trials": 20}
    raw["ranking"] = {"n_avg": [100, raw["averaging"]["n_samples"]], "n_trials": n_trials}
    raw.update(changes)
    directory.mkdir(parents=True, exist_ok=True)
    path = directory / "paper.yaml"  # same name: same scenario key, same seeds
    path.write_text(yaml.safe_dump(raw, sort_keys=False), encoding="utf-8")
    return path


def _quiet(_msg: str) -> None:
    pass


@pytest.fixture(scope="module")
def mc_runs(tmp_path_factory):
    base = tmp_path_factory.mktemp("mc")
    s50 = _small_paper(base / "cfg50", 50)
    s20 = _small_paper(base / "cfg20", 20)
    run_scenario(s50, base / "run_a", log=_quiet)
    run_scenario(s50, base / "run_b", log=_quiet)
    run_scenario(s20, base / "run_20", log=_quiet)
    return base


def test_two_runs_are_byte_identical(mc_runs):
    names = sorted(p.name for p in (mc_runs / "run_a").iterdir())
    assert names == sorted([name for name, _ in OUTPUTS.values()] + ["provenance.json"])
    for name in names:
        assert (mc_runs / "run_a" / name).read_bytes() == (mc_runs / "run_b" / name).read_bytes(), (
            name
        )


def test_trials_do_not_depend_on_number_of_trials(mc_runs):
    t50 = pd.read_csv(mc_runs / "run_a" / "mc_trials.csv")
    t20 = pd.read_csv(mc_runs / "run_20" / "mc_trials.csv")
    assert t50["trial"].max() == 49 and t20["trial"].max() == 19
    head = t50[t50["trial"] < 20].reset_index(drop=True)
    pd.testing.assert_frame_equal(head, t20, check_exact=False, rtol=1e-14, atol=0)
    # the noise is real: trials differ from each other
    psi = t50[(t50["method"] == "A1c1") & (t50["quantity"] == "psi_deg")]["estimate"]
    assert psi.nunique() == 50
    # the sensitivity study (its own 20 trials) is the same in both runs
    s50 = pd.read_csv(mc_runs / "run_a" / "sensitivity.csv")
    s20 = pd.read_csv(mc_runs / "run_20" / "sensitivity.csv")
    pd.testing.assert_frame_equal(s50, s20, check_exact=False, rtol=1e-14, atol=0)


def test_provenance_records_seed_and_config_hash(mc_runs, paper):
    import json

    prov = json.loads((mc_runs / "run_a" / "provenance.json").read_text())
    assert prov["seed"] == paper.seed and prov["n_trials"] == 50
    prov20 = json.loads((mc_runs / "run_20" / "provenance.json").read_text())
    assert prov20["config_sha256"] != prov["config_sha256"]
    assert prov20["scenario_key"] == prov["scenario_key"]


def test_ranking_at_the_scenario_n_reproduces_the_monte_carlo(mc_runs, paper):
    """ranking.csv runs on the main Monte Carlo's normals: at the scenario's N its RMS is the
    RMS of mc_trials.csv; at a smaller N the noise, and so the RMS, is larger."""
    ranking = pd.read_csv(mc_runs / "run_a" / "ranking.csv")
    trials = pd.read_csv(mc_runs / "run_a" / "mc_trials.csv")
    rms = trials.groupby(["method", "quantity"])["error_pct"].apply(
        lambda e: np.sqrt(np.mean(e**2))
    )
    at_n = ranking[ranking["n_avg"] == paper.n_samples].set_index(["method", "quantity"])
    assert len(at_n) == len(rms) and (at_n["n_trials"] == 50).all()
    np.testing.assert_allclose(at_n["rms_error_pct"].sort_index(), rms.sort_index(), rtol=1e-12)
    small = ranking[ranking["n_avg"] == 100].set_index(["method", "quantity"])["rms_error_pct"]
    assert (small.loc[at_n.index] > at_n["rms_error_pct"]).all()


def test_ranking_pairs_are_paired_over_the_same_trials(mc_runs):
    """A4 and A5 are one estimator: equal on every trial; L1 and L3 are not."""
    pairs = pd.read_csv(mc_runs / "run_a" / "ranking_pairs.csv").set_index(["n_avg", "quantity", "method_a", "method_b"])  # fmt: skip
    same = pairs.loc[(100, "gyro_scale", "A4", "A5")]
    assert same["max_abs_diff_pct"] < 1e-10 and abs(same["mean_sq_diff_pct2"]) < 1e-12
    other = pairs.loc[(100, "phi_deg", "L1", "L3")]
    assert other["max_abs_diff_pct"] > 0.01 and other["se_sq_diff_pct2"] > 0


def test_a2_scan_contains_the_scenario_tau(mc_runs):
    """a2_scan.csv: the noise-free method-2 azimuth at every whole degree; at the scenario's
    tau it is the noise-free real estimate of estimates.csv."""
    scan = pd.read_csv(mc_runs / "run_a" / "a2_scan.csv").set_index("tau_deg")
    est_ = pd.read_csv(mc_runs / "run_a" / "estimates.csv")
    real = est_[(est_["sensor"] == "real") & (est_["method"] == "A2")]["estimate"].iloc[0]
    assert len(scan) == 360 and scan["psi_deg"].notna().all()
    assert scan.loc[45.0, "psi_deg"] == pytest.approx(real, abs=1e-12)


# --------------------------------------------------------------------------------------------
# readings CSV round trip through the command line
# --------------------------------------------------------------------------------------------
def _cli(*args: str, cwd: Path) -> subprocess.CompletedProcess:
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    return subprocess.run(
        [sys.executable, "-m", "pipeline.north_finding.cli", *args],
        cwd=cwd,
        env=env,
        capture_output=True,
        text=True,
        timeout=HANG_GUARD_S,
    )


def test_readings_csv_round_trip_equals_monte_carlo_trial_0(tmp_path, paper):
    # a scenario whose azimuth methods use levelling method 1, as the CLI must (no truth there)
    raw = yaml.safe_load(PAPER.read_text(encoding="utf-8"))
    raw["monte_carlo"]["n_trials"] = 3
    raw.pop("sensitivity")
    raw["level_source"] = "L1"
    scenario = tmp_path / "roundtrip.yaml"
    scenario.write_text(yaml.safe_dump(raw, sort_keys=False), encoding="utf-8")
    run_scenario(scenario, tmp_path / "mc", log=_quiet)
    trials = pd.read_csv(tmp_path / "mc" / "mc_trials.csv")
    trial0 = trials[trials["trial"] == 0].set_index(["method", "quantity"])["estimate"]

    csv = tmp_path / "readings.csv"
    r = _cli(
        "simulate-readings",
        "--scenario",
        str(scenario),
        "--trial",
        "0",
        "--out",
        str(csv),
        cwd=tmp_path,
    )
    assert r.returncode == 0, r.stderr
    out = tmp_path / "estimates.csv"
    site = raw["site"]
    r = _cli(
        "estimate",
        "--readings", str(csv),
        "--lat-deg", repr(site["lat_deg"]),
        "--g", repr(site["g_m_s2"]),
        "--omega-ie", repr(site["omega_ie_rad_s"]),
        "--compass-deg", repr(raw["truth"]["psi_deg"] + raw["compass"]["offset_deg"]),
        "--level-source", "L1",
        "--a2-tau-deg", repr(raw["table"]["a2_tau_deg"]),
        "--out", str(out),
        cwd=tmp_path,
    )  # fmt: skip
    assert r.returncode == 0, r.stderr
    cli = pd.read_csv(out)
    assert list(cli.columns) == col.ESTIMATE_COLUMNS
    cli = cli.set_index(["method", "quantity"])["estimate"]
    assert set(cli.index) == set(trial0.index)

    # The CSV carries each reading's role (fixed, ls, a2, peak, z) as the simulation lays them
    # out, so every method reads the same positions in both paths and must agree.
    for key, value in trial0.items():
        assert cli[key] == pytest.approx(value, rel=1e-12, abs=1e-15), key

    # L2, L4 on the CSV: least squares over the role-ls readings of the axis, written from eq. 17
    # and the a_y row of eq. 24 (still table) -- independent of the generated design rows.
    frame = pd.read_csv(csv, comment="#")
    assert set(frame["role"]) == {"fixed", "ls", "a2", "peak", "z"}
    frame = frame[frame["role"] == "ls"]
    g = site["g_m_s2"]
    x = frame[frame["axis"] == "x"]
    tx = np.deg2rad(x["tau_deg"].to_numpy())
    sol = np.linalg.lstsq(
        np.c_[np.cos(tx), -np.sin(tx)], x["accel_m_s2"].to_numpy() / g, rcond=None
    )[0]
    theta = np.arcsin(sol[0])
    assert cli["L2", "theta_deg"] == pytest.approx(np.rad2deg(theta), rel=1e-9)
    assert cli["L2", "phi_deg"] == pytest.approx(
        np.rad2deg(np.arcsin(sol[1] / np.cos(theta))), rel=1e-9
    )
    y = frame[frame["axis"] == "y"]
    ty = np.deg2rad(y["tau_deg"].to_numpy())
    sol = np.linalg.lstsq(
        np.c_[np.cos(ty), np.sin(ty)], -y["accel_m_s2"].to_numpy() / g, rcond=None
    )[0]
    theta = np.arcsin(sol[1])
    assert cli["L4", "theta_deg"] == pytest.approx(np.rad2deg(theta), rel=1e-9)
    assert cli["L4", "phi_deg"] == pytest.approx(
        np.rad2deg(np.arcsin(sol[0] / np.cos(theta))), rel=1e-9
    )
    # and both are close to the truth (noise-level errors only)
    assert cli["L2", "phi_deg"] == pytest.approx(50.0, abs=0.05)
    assert cli["L4", "theta_deg"] == pytest.approx(30.0, abs=0.05)


def test_newton_derivative_of_eq47_is_the_derivative_of_its_residual():
    """The generated d/dpsi of eq. 47's residual (Newton polish of A3) against a central
    difference of the generated residual along psi: an independent numeric path (a sign or
    factor error in the derivative moves it by O(1), far beyond the 1e-7 tolerance)."""
    rng = np.random.default_rng(47)
    coef = rng.normal(size=(5, 200))
    psi = rng.uniform(-np.pi, np.pi, 200)
    h = 1e-6
    res = [gen.a3_eq47_residual(np.cos(p), np.sin(p), *coef) for p in (psi + h, psi - h)]
    numeric = (res[0] - res[1]) / (2 * h)
    got = gen.a3_eq47_residual_dpsi(np.cos(psi), np.sin(psi), *coef)
    np.testing.assert_allclose(got, numeric, rtol=0, atol=1e-7 * np.abs(coef).sum(axis=0).max())


def test_least_squares_levelling_recovers_sin_phi_from_its_unknown():
    """L2/L4 solve for X2 = cos(theta) sin(phi); the generated ls_sin_phi inverts it (a wrong
    trig factor, e.g. sin(theta), fails at 1e-12)."""
    rng = np.random.default_rng(21)
    theta, phi = rng.uniform(-1.4, 1.4, 500), rng.uniform(-1.5, 1.5, 500)
    got = gen.ls_sin_phi(np.cos(theta) * np.sin(phi), theta)
    np.testing.assert_allclose(got, np.sin(phi), rtol=0, atol=1e-12)
