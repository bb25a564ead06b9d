"""The paper's estimators, vectorised over Monte Carlo trials.

Every formula comes from ``pipeline.generated.north_finding`` (generated from
the SymPy derivations); this module only adds the algorithms around them:
least squares (methods L2, L4), root finding of the quartic (A3) and root
selection by the compass prior. Where noise pushes an argument out of a formula's domain the
estimator clips it and, given a :class:`pipeline.north_finding.trouble.Trouble`, counts it
(clipped arcsines, unreachable roots, complex quartic roots).

Results are a mapping ``(method, quantity) -> array of shape (n_trials,)`` in
the units of the quantity name (deg, micro-g, rad/s, dimensionless).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from pipeline.generated import north_finding as gen
from pipeline.north_finding.readings import Readings
from pipeline.north_finding.trouble import Trouble, mark

__all__ = ["Site", "a2_psi", "estimate_all", "select_nearest", "wrap_pi", "solve_quartic_psi"]

Estimates = dict[tuple[str, str], np.ndarray]


@dataclass(frozen=True)
class Site:
    """Known quantities: latitude (rad), gravity (m/s^2), Earth rate (rad/s)."""

    lat: float
    g: float
    omega_ie: float


def wrap_pi(angle: np.ndarray) -> np.ndarray:
    """Wrap to (-pi, pi]."""
    return -((-np.asarray(angle) + np.pi) % (2 * np.pi) - np.pi)


def select_nearest(
    candidates: np.ndarray, prior: np.ndarray, valid: np.ndarray | None = None
) -> np.ndarray:
    """Pick, per trial, the candidate angle nearest to the compass prior.

    ``candidates`` (T, K) in rad; NaN or ``valid == False`` entries are never picked.
    Returns (T,); NaN where no candidate is valid.
    """
    cand = np.asarray(candidates, dtype=float)
    ok = np.isfinite(cand) if valid is None else valid & np.isfinite(cand)
    dist = np.where(ok, np.abs(wrap_pi(cand - np.asarray(prior)[:, None])), np.inf)
    k = np.argmin(dist, axis=1)
    out = np.take_along_axis(cand, k[:, None], axis=1)[:, 0]
    return np.where(np.isfinite(dist.min(axis=1)), out, np.nan)


def _least_squares(h1: np.ndarray, h2: np.ndarray, y: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Solve H X = Y in the least-squares sense for every trial; H is (P, 2), Y is (T, P)."""
    design = np.stack([h1, h2], axis=1)
    sol, *_ = np.linalg.lstsq(design, y.T, rcond=None)  # (2, T)
    return sol[0], sol[1]


def _asin(x: np.ndarray, trouble: Trouble | None = None, method: str = "") -> np.ndarray:
    mark(trouble, method, "clipped_arcsine", np.abs(x) > 1.0)
    return np.arcsin(np.clip(x, -1.0, 1.0))


def _acos(x: np.ndarray, trouble: Trouble | None = None, method: str = "") -> np.ndarray:
    mark(trouble, method, "clipped_arcsine", np.abs(x) > 1.0)
    return np.arccos(np.clip(x, -1.0, 1.0))


def levelling(
    readings: Readings, site: Site, methods: tuple[str, ...], trouble: Trouble | None = None
) -> Estimates:
    """Levelling methods L1..L5 (eqs. 19-34)."""
    out: Estimates = {}
    acc = readings.accel
    g = site.g

    def ax(tau: float, method: str, axis: str = "x") -> np.ndarray:
        return acc[:, readings.index(axis, tau, method)]

    if "L1" in methods:
        theta = _asin(gen.l1_sin_theta(ax(0, "L1"), ax(180, "L1"), g), trouble, "L1")
        phi = _asin(gen.l1_sin_phi(ax(90, "L1"), ax(270, "L1"), g, theta), trouble, "L1")
        out["L1", "theta_deg"], out["L1", "phi_deg"] = np.rad2deg(theta), np.rad2deg(phi)
    if "L2" in methods:
        cols = readings.columns("x", "ls")
        h1, h2 = gen.l2_design_row(np.deg2rad(readings.tau_deg[cols]))
        s_th, cth_sphi = _least_squares(h1, h2, acc[:, cols] / g)
        theta = _asin(s_th, trouble, "L2")
        phi = _asin(gen.ls_sin_phi(cth_sphi, theta), trouble, "L2")
        out["L2", "theta_deg"], out["L2", "phi_deg"] = np.rad2deg(theta), np.rad2deg(phi)
    if "L3" in methods:
        theta = _asin(gen.l3_sin_theta(ax(90, "L3", "y"), ax(270, "L3", "y"), g), trouble, "L3")
        phi = _asin(gen.l3_sin_phi(ax(0, "L3", "y"), ax(180, "L3", "y"), g, theta), trouble, "L3")
        out["L3", "theta_deg"], out["L3", "phi_deg"] = np.rad2deg(theta), np.rad2deg(phi)
    if "L4" in methods:
        cols = readings.columns("y", "ls")
        h1, h2 = gen.l4_design_row(np.deg2rad(readings.tau_deg[cols]))
        cth_sphi, s_th = _least_squares(h1, h2, -acc[:, cols] / g)
        theta = _asin(s_th, trouble, "L4")
        phi = _asin(gen.ls_sin_phi(cth_sphi, theta), trouble, "L4")
        out["L4", "theta_deg"], out["L4", "phi_deg"] = np.rad2deg(theta), np.rad2deg(phi)
    if "L5" in methods:
        a0, a90, a180 = ax(0, "L5"), ax(90, "L5"), ax(180, "L5")
        az = acc[:, readings.columns("z")[0]]
        bias = gen.l5_bias(a0, a180)
        a1, a2, a3 = gen.l5_components(a0, a90, a180, az)
        out["L5", "acc_bias_ug"] = bias / g * 1e6
        out["L5", "acc_scale"] = gen.l5_scale(a1, a2, a3, g)
        out["L5", "acc_scale_approx"] = gen.l5_scale_approx(a1, a2, a3, g)
    return out


def solve_quartic_psi(
    coeffs47: tuple[np.ndarray, ...], prior: np.ndarray, trouble: Trouble | None = None
) -> np.ndarray:
    """Azimuth method 3: psi from eq. 47 via the quartic of eq. 50, vectorised over trials.

    1. F..J of eq. 50 from A..E of eq. 47; all four roots c = cos(psi) from the
       eigenvalues of the companion matrices (one 4x4 per trial).
    2. Keep real roots (|Im c| <= 1e-7) in [-1, 1]. Squaring (eq. 49) lost the sign of
       sin(psi): for each root take the sign of sin(psi) whose unsquared eq. 47 residual
       is smaller, which removes the spurious root of the pair.
    3. Polish each candidate with two Newton steps on the eq. 47 residual in psi.
    4. Keep the candidate nearest the compass prior. If noise pushed the measured
       maximum beyond the reachable one (no real root), the real parts of the
       complex roots are used instead (counted as ``complex_roots`` in ``trouble``).
    """
    A, B, C, D, E = (np.asarray(c, dtype=float) for c in coeffs47)
    F, G, H, I_, J = gen.a3_quartic_coeffs(A, B, C, D, E)
    n = F.shape[0]
    comp = np.zeros((n, 4, 4))
    comp[:, 0, :] = -np.stack([G, H, I_, J], axis=1) / F[:, None]
    comp[:, 1, 0] = comp[:, 2, 1] = comp[:, 3, 2] = 1.0
    roots = np.linalg.eigvals(comp)  # (T, 4)
    c = np.clip(roots.real, -1.0, 1.0)
    real = (np.abs(roots.imag) <= 1e-7) & (np.abs(roots.real) <= 1.0 + 1e-9)
    mark(trouble, "A3", "complex_roots", ~real.any(axis=1))
    real = np.where(real.any(axis=1, keepdims=True), real, True)
    s_abs = np.sqrt(1.0 - c**2)
    coef = [x[:, None] for x in (A, B, C, D, E)]
    r_plus = gen.a3_eq47_residual(c, s_abs, *coef)
    r_minus = gen.a3_eq47_residual(c, -s_abs, *coef)
    s = np.where(np.abs(r_plus) <= np.abs(r_minus), s_abs, -s_abs)
    psi = np.arctan2(s, c)
    for _ in range(2):
        cp, sp_ = np.cos(psi), np.sin(psi)
        r = gen.a3_eq47_residual(cp, sp_, *coef)
        dr = gen.a3_eq47_residual_dpsi(cp, sp_, *coef)  # d/dpsi of eq. 47's residual
        step = np.where(np.abs(dr) > 1e-12, r / np.where(dr == 0, 1.0, dr), 0.0)
        psi = psi - np.clip(step, -0.1, 0.1)
    return select_nearest(psi, prior, real)


def _two_roots(
    a: np.ndarray, b: np.ndarray, c: np.ndarray, trouble: Trouble | None = None, method: str = ""
) -> np.ndarray:
    """Both roots of a sin(psi) + b cos(psi) = c, (T, 2) in rad."""
    # |c| > r: unreachable (noise); the double root is used and counted
    r = np.hypot(a, b)
    mark(trouble, method, "unreachable_root", np.abs(c) > r)
    lo, hi = gen.sinusoid_roots(a, b, c)  # the generated roots clip c / r to [-1, 1]
    return np.stack([lo, hi], axis=1)


def a2_psi(
    w: np.ndarray,
    tau: np.ndarray | float,
    omega_ie: float,
    lat: float,
    theta: np.ndarray,
    phi: np.ndarray,
    prior: np.ndarray,
    trouble: Trouble | None = None,
) -> np.ndarray:
    """Azimuth method 2 (eqs. 42-43): psi (rad) from the x gyro ``w`` read at table angle
    ``tau`` (rad); every argument broadcasts, so one call covers many trials or many tau."""
    a, b, c = gen.a2_coeffs(w, tau, omega_ie, lat, theta, phi)
    return select_nearest(_two_roots(a, b, c, trouble, "A2"), prior)


def azimuth(
    readings: Readings,
    site: Site,
    methods: tuple[str, ...],
    theta: np.ndarray,
    phi: np.ndarray,
    prior: np.ndarray,
    a2_tau_deg: float | None,
    trouble: Trouble | None = None,
    bounds: dict[str, np.ndarray] | None = None,
) -> Estimates:
    """Azimuth methods A1c1..A6 (eqs. 40-71); theta, phi, prior are per-trial arrays (rad).

    Given ``bounds``, stores there under "A3" the per-trial bound (deg) on A3's error from the
    step of its peak scan (:func:`pipeline.north_finding.scan_bound.a3_scan_bound_deg`)."""
    out: Estimates = {}
    gyr = readings.gyro
    lat, om = site.lat, site.omega_ie

    def wx(tau: float, method: str) -> np.ndarray:
        return gyr[:, readings.index("x", tau, method)]

    def deg(x: np.ndarray) -> np.ndarray:
        return np.rad2deg(x) % 360.0

    if "A1c1" in methods:
        cos_psi = gen.a1c1_cos_psi(wx(0, "A1c1"), wx(180, "A1c1"), om, lat, theta)
        acos = _acos(cos_psi, trouble, "A1c1")
        out["A1c1", "psi_deg"] = deg(select_nearest(np.stack([acos, -acos], axis=1), prior))
    if "A1c2" in methods:
        a, b, c = gen.a1c2_coeffs(wx(90, "A1c2"), wx(270, "A1c2"), om, lat, theta, phi)
        out["A1c2", "psi_deg"] = deg(select_nearest(_two_roots(a, b, c, trouble, "A1c2"), prior))
    if "A2" in methods:
        if a2_tau_deg is None:
            col = readings.columns("x", "a2")[0]
        else:
            col = readings.index("x", a2_tau_deg, "A2", "a2")
        tau = np.deg2rad(readings.tau_deg[col])
        out["A2", "psi_deg"] = deg(a2_psi(gyr[:, col], tau, om, lat, theta, phi, prior, trouble))
    if "A3" in methods:
        cols = readings.columns("x", "peak")
        w_max = gyr[:, cols].max(axis=1)
        coeffs = gen.a3_eq47_coeffs(w_max, om, lat, theta, phi)
        out["A3", "psi_deg"] = deg(solve_quartic_psi(coeffs, prior, trouble))
        if bounds is not None:
            from pipeline.north_finding.scan_bound import a3_scan_bound_deg  # imports this module

            tau_scan = readings.tau_deg[cols]
            bounds["A3"] = a3_scan_bound_deg(tau_scan, gyr[:, cols], om, lat, theta, phi, prior)
    if {"A4", "A5", "A6"} & set(methods):
        w0, w90, w180 = wx(0, "A4"), wx(90, "A4"), wx(180, "A4")
        bias = gen.a4_bias(w0, w180)
        om1, om2 = gen.a4_omegas(w0, w90, w180, om)
    if "A4" in methods:
        a, b, c = gen.a4_coeffs(om1, om2, lat, theta, phi)
        psi = select_nearest(_two_roots(a, b, c, trouble, "A4"), prior)
        out["A4", "psi_deg"] = deg(psi)
        out["A4", "gyro_bias_rad_s"] = bias
        out["A4", "gyro_scale"] = gen.a4_scale(om1, psi, lat, theta)
    if "A5" in methods:
        A, B, C = gen.a5_coeffs(om1, om2, lat, theta, phi)
        with np.errstate(invalid="ignore"):  # negative discriminant: counted just below
            roots = np.stack(gen.a5_scale_roots(A, B, C, lat), axis=1)
        mark(trouble, "A5", "complex_roots", ~np.isfinite(roots).any(axis=1))
        # the sign and size of S are known from calibration: keep the root nearest 1
        k = np.nanargmin(np.abs(np.where(np.isfinite(roots), roots, np.inf) - 1.0), axis=1)
        scale = np.take_along_axis(roots, k[:, None], axis=1)[:, 0]
        acos = _acos(gen.a5_cos_psi(om1, scale, lat, theta), trouble, "A5")
        out["A5", "psi_deg"] = deg(select_nearest(np.stack([acos, -acos], axis=1), prior))
        out["A5", "gyro_scale"] = scale
        out["A5", "gyro_scale_approx"] = gen.a5_scale_approx(A, B, C, lat)
    if "A6" in methods:
        wz = gyr[:, readings.columns("z")[0]]
        om3 = gen.a6_omega3(wz, w0, w180, om)
        out["A6", "gyro_scale"] = gen.a6_scale(om1, om2, om3)
        out["A6", "gyro_scale_approx"] = gen.a6_scale_approx(om1, om2, om3)
    return out


def estimate_all(
    readings: Readings,
    site: Site,
    methods: tuple[str, ...],
    level_source: str,
    truth_level: tuple[float, float] | None,
    prior: np.ndarray,
    a2_tau_deg: float | None,
    trouble: Trouble | None = None,
    bounds: dict[str, np.ndarray] | None = None,
) -> Estimates:
    """Run every requested method, counting numerical trouble in ``trouble`` if given (and
    A3's scan bound in ``bounds``, see :func:`azimuth`).
    ``level_source`` is 'truth' (use ``truth_level`` =
    (theta, phi) in rad) or a levelling method id whose estimates feed the azimuth methods."""
    out = levelling(
        readings, site, methods + ((level_source,) if level_source != "truth" else ()), trouble
    )
    n = readings.n_trials
    if level_source == "truth":
        theta = np.full(n, truth_level[0])
        phi = np.full(n, truth_level[1])
    else:
        theta = np.deg2rad(out[level_source, "theta_deg"])
        phi = np.deg2rad(out[level_source, "phi_deg"])
    out = {k: v for k, v in out.items() if k[0] in methods}
    az_methods = tuple(m for m in methods if m.startswith("A"))
    if az_methods:
        prior = np.broadcast_to(np.asarray(prior, dtype=float), (n,))
        out.update(
            azimuth(readings, site, az_methods, theta, phi, prior, a2_tau_deg, trouble, bounds)
        )
    return out
