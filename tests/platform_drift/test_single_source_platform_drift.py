"""The formulas platform_drift's numeric code calls, against the paper's forms and independent paths.

* the exact end-of-alignment rates (``alignment_rates``, which ``platform.initial_state``
  calls) are the inertial rate of m_N rotated into s, and to first order they are eq. 19
  solved (p, q) and eq. 24 (r) with the tilts of eq. 21: proved symbolically;
* the initial state built from them equals the rotation of the local frame's inertial rate
  into the platform axes (the numeric path it replaces) to round-off, and differs from the
  generated eq. 24 by no more than its second-order remainder;
* ``oscillation_period`` (eq. 30) gives ``schuler_period`` at k_sh = g/R, symbolically;
* the strapdown velocity equation (eq. 10 in NED) is the textbook vector form, symbolically
  and numerically (numpy cross products); the ground velocity is v - omega x r;
* ``trajectory.eq2_angles`` inverts eq. 2 (the generated ``frames.mat_tn``);
* the generated course rate and the body rate are the derivatives of the truth path (central
  differences); the known-altitude z and z_dot keep |r| = R_G (symbolically).
"""

from __future__ import annotations

from pathlib import Path

import numpy as np
import pytest
import sympy as sp

from derivations import frames as sym_frames
from derivations.platform_drift import alignment as al
from derivations.platform_drift import drift as dr
from derivations.platform_drift import kinematics as kin
from derivations.platform_drift import schuler as sch
from derivations.platform_drift import strapdown as sdn
from derivations.platform_drift import symbols as s
from derivations.platform_drift.approx import taylor
from derivations.platform_drift.drift import IDEAL_IMU
from pipeline.generated import frames
from pipeline.generated import platform_drift as gen
from pipeline.platform_drift import platform as pf
from pipeline.platform_drift.scenario import load_scenario
from pipeline.platform_drift.trajectory import Trajectory, eq2_angles

SCEN = Path(__file__).resolve().parents[2] / "config" / "scenarios" / "platform_drift"
TILTS = [s.phi_x, s.phi_y]


def test_alignment_rates_are_the_earth_rate_in_the_platform_axes():
    """Exact p, q, r(0-) = ^s_{mN}C ^{mN}omega_ie: the platform at rest turns with m_N."""
    r = al.rates_0m_exact()
    want = kin.mat_s_mN() * kin.earth_rate_mN()
    for k, key in enumerate(("p", "q", "r")):
        assert sp.simplify(r[key] - want[k]) == 0, key


def test_alignment_rates_to_first_order_are_eq19_and_eq24():
    """r(0-) to first order in the tilts, with eq. 21's tilts and to first order in alpha and
    theta_F, is the derived eq. 24 (al.r_0m); p, q to first order solve eq. 19 at rest."""
    exact = al.rates_0m_exact()
    r1 = taylor(exact["r"], TILTS, 1)
    t21 = al.tilts_0m()
    r24 = taylor(
        sp.expand(r1.subs({s.phi_x: t21["phi_x"], s.phi_y: t21["phi_y"]})),
        [s.alpha, s.theta_F1, s.theta_F2],
        1,
    )
    assert sp.simplify(r24 - al.r_0m()) == 0
    # eq. 19 with phi_dot = 0: p = omega_e cos cos psi - phi_y r, q = q(0-) = r phi_x + ...
    q19 = al.q_0m().subs(s.r, exact["r"])
    assert sp.simplify(taylor(exact["q"] - q19, TILTS, 1)) == 0
    k19 = al.alg.tilt_kinematics_stationary()
    p19 = sp.solve(k19["phi_x_dot"], s.p)[0].subs(s.r, exact["r"])
    assert sp.simplify(taylor(exact["p"] - p19, TILTS, 1)) == 0
    # and the paper's eq. 24 (without alpha omega_e cos) is not the first-order form
    paper = al.r_0m().subs(s.alpha, 0)
    assert sp.simplify(r24.subs(IDEAL_IMU) - paper.subs(IDEAL_IMU)) != 0


@pytest.mark.parametrize("psi0", [0.0, 0.7])
@pytest.mark.parametrize("level", ["mass", "plumb"])
def test_initial_state_rates_match_the_rotated_frame_rate(level, psi0):
    """Independent path: C_s^i^T (NWU's inertial rate) at t = 0, as a matrix product."""
    sc = load_scenario(SCEN / "stationary.yaml")
    traj = Trajectory(sc.earth, sc.route, psi0)
    init = pf.initial_state(traj, level)
    tr = traj.at(0.0)
    p0, q0, r0 = init.c_si.T @ (tr.nwu_i @ tr.w_nwu)
    scale = sc.earth.omega_e
    assert abs(init.p - p0) <= 1e-15 * scale
    assert abs(init.q - q0) <= 1e-15 * scale
    assert abs(init.r_0m - r0) <= 1e-15 * scale


def test_initial_r_0m_against_eq24():
    """Mass level (no tilt): eq. 24 is exact. Plumb level (tilt alpha about axis 2 for
    psi0 = 0): eq. 24 with that alpha is within its second-order remainder omega_e alpha^2."""
    sc = load_scenario(SCEN / "stationary.yaml")
    traj = sc.trajectory()
    we, lat = sc.earth.omega_e, sc.route.lat0
    mass = pf.initial_state(traj, "mass")
    r24 = float(gen.r_alignment(we, lat, sc.psi0, 0.0, 0.0, 0.0))
    assert mass.r_0m == pytest.approx(r24, rel=1e-14)
    plumb = pf.initial_state(traj, "plumb")
    alpha = plumb.phi_y
    r24 = float(gen.r_alignment(we, lat, sc.psi0, alpha, 0.0, 0.0))
    assert abs(plumb.r_0m - r24) <= we * alpha**2
    # the alpha term of eq. 24 (which the paper drops) is resolved: it is far above the remainder
    assert abs(plumb.r_0m - we * np.sin(lat)) > 100 * we * alpha**2


def test_oscillation_period_gives_the_schuler_period():
    assert sp.simplify(dr.oscillation_period().subs(s.k_sh, s.g / s.R) - sch.schuler_period()) == 0
    k = 9.81 / 6371e3
    assert float(gen.oscillation_period(k)) == pytest.approx(2 * np.pi / np.sqrt(k), rel=1e-15)


def _textbook_velocity_rate() -> sp.Matrix:
    """f + g - (2 w_ie + w_en) x v - w_ie x (w_ie x r), typed here from the textbook."""
    w_ie = sym_frames.earth_rate_n(s.omega_e, s.lat)
    w_en = sym_frames.transport_rate_n_velocity(sdn.v_n, sdn.v_e, s.lat, sdn.rho)
    v = sp.Matrix([sdn.v_n, sdn.v_e, 0])
    r = sp.Matrix([0, 0, -sdn.rho])
    f = sp.Matrix([sdn.f_n, sdn.f_e, sdn.f_d]) + sp.Matrix([0, 0, s.g])
    return f - (2 * w_ie + w_en).cross(v) - w_ie.cross(w_ie.cross(r))


def test_strapdown_velocity_equation_is_the_textbook_form():
    got = sdn.velocity_rates_n()
    want = _textbook_velocity_rate()
    for k, key in enumerate(("v_N_dot", "v_E_dot", "v_D_dot")):
        assert sp.simplify(got[key] - want[k]) == 0, key


def test_generated_strapdown_velocity_rates_match_numpy_cross_products():
    rng = np.random.default_rng(3)
    n, rho, we = 50, 6.4e6, 7.292115e-5
    lat = rng.uniform(-1.4, 1.4, n)
    vn, ve = rng.uniform(-300, 300, (2, n))
    f = rng.normal(0.0, 1.0, (n, 3))
    w_ie = frames.earth_rate_n(we, lat)
    w_en = frames.transport_rate_n_velocity(vn, ve, lat, rho)
    v = np.column_stack((vn, ve, np.zeros(n)))
    r = np.broadcast_to([0.0, 0.0, -rho], (n, 3))
    a = f - np.cross(2 * w_ie + w_en, v) - np.cross(w_ie, np.cross(w_ie, r))
    got = np.column_stack(gen.strapdown_velocity_rates(f[:, 0], f[:, 1], vn, ve, lat, rho, we))
    np.testing.assert_allclose(got, a[:, :2], rtol=1e-12, atol=1e-15)
    # ground velocity (eq. 8): v_i - omega_ie x r
    vi, ri = rng.normal(0, 500, (n, 3)), rng.normal(0, 6e6, (n, 3))
    w = frames.earth_rate_e(we)
    want = vi - np.cross(w, ri)
    got = gen.ground_velocity(*vi.T, *ri.T, *w)
    np.testing.assert_allclose(got, want, rtol=1e-15, atol=1e-12)


def test_eq2_angles_invert_eq2():
    rng = np.random.default_rng(5)
    psi = rng.uniform(-3.0, 3.0, 40)
    phi_y = rng.uniform(-1.5, 1.5, 40)
    phi_x = rng.uniform(-3.0, 3.0, 40)
    c = np.swapaxes(frames.mat_tn(psi, phi_y, phi_x), -1, -2)  # C3(psi) C2(phi_y) C1(phi_x)
    got = eq2_angles(c)
    for g_, w_ in zip(got, (psi, phi_y, phi_x), strict=True):
        np.testing.assert_allclose(g_, w_, atol=1e-12)


def test_course_rate_and_body_rate_are_derivatives_of_the_path():
    """Independent path: central differences of the course and of the body attitude C_b^i."""
    sc = load_scenario(SCEN / "lat_lon_change.yaml")
    traj = sc.trajectory()
    h = 1e-2
    for t in (300.0, 2000.0, 6900.0):
        lat_p, lat_m = traj.at(t + h).lat, traj.at(t - h).lat
        chi_dot = (traj.course(lat_p) - traj.course(lat_m)) / (2 * h)
        assert -traj.at(t).psi_b_dot == pytest.approx(chi_dot, rel=1e-6, abs=1e-15)
        c_dot = (traj.body_i(traj.at(t + h)) - traj.body_i(traj.at(t - h))) / (2 * h)
        w_skew = traj.body_i(traj.at(t)).T @ c_dot  # [omega_ib^b x]
        w_fd = np.array([w_skew[2, 1], w_skew[0, 2], w_skew[1, 0]])
        np.testing.assert_allclose(traj.body_rate(traj.at(t)), w_fd, rtol=0, atol=1e-10)


def test_known_altitude_keeps_the_radius():
    """z of the vertical channel puts r on the sphere |r| = R_G; z_dot is d z / dt along x(t),
    y(t) (an independent differentiation of the explicit root)."""
    ka = al.alg.known_altitude()
    assert sp.simplify(s.x**2 + s.y**2 + ka["z"] ** 2 - s.R_G**2) == 0
    xf, yf = sp.Function("X")(s.t), sp.Function("Y")(s.t)
    direct = ka["z"].subs({s.x: xf, s.y: yf}).diff(s.t)
    direct = direct.subs({xf.diff(s.t): s.x_dot, yf.diff(s.t): s.y_dot, xf: s.x, yf: s.y})
    assert sp.simplify(direct - ka["z_dot"].subs(s.z, ka["z"])) == 0
