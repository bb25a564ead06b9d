"""Derivations of platform_drift: closed forms against their ODEs, numerics and generated code.

* the analytic solutions of eqs. 30-36 and of Table 2 satisfy their ODEs and initial
  conditions symbolically (and the printed eq. 36 int q_merror does not: its first term has
  the wrong sign);
* scipy's solve_ivp of the tilt-error ODEs agrees with the closed forms (rtol 1e-6); the
  terms eq. 33 neglects (b_g3 phi_dot, the b_g3 t in psi) stay within their first-order
  bound (a slow resonant growth, < 10 % of the error after 2 h);
* the generated navigation equations (eqs. 9, 11, 12 with spherical gravity) integrated as a
  nonlinear closed loop oscillate at the Schuler period;
* every generated function equals the lambdified derivation at random points (that the
  committed module is fresh, tests/shared/test_generated_fresh.py checks for every paper).
"""

from __future__ import annotations

import inspect

import numpy as np
import pytest
import sympy as sp
from scipy.integrate import solve_ivp

from derivations.platform_drift import alignment as al
from derivations.platform_drift import drift as dr
from derivations.platform_drift import generate
from derivations.platform_drift import printed as P
from derivations.platform_drift import schuler as sch
from derivations.platform_drift import symbols as s
from pipeline.generated import platform_drift as gen

DEG = np.pi / 180
HOUR = 3600.0
OMEGA_E = 7.292115e-5
R_EARTH = 6371e3
G = 9.81
LAT = 35.7 * DEG  # Tehran (the authors' city; the paper does not state the latitude)
PSI0 = 30 * DEG
B_G1 = 0.01 * DEG / HOUR
B_G3 = 0.1 * DEG / HOUR


def _ode_residual(sol: sp.Expr, forcing: sp.Expr) -> sp.Expr:
    return sp.simplify(sol.diff(s.t, 2) + s.k_sh * sol - forcing)


# ---------------------------------------------------------------- symbolic checks


def test_channel1_solutions_satisfy_eq29_and_eq31():
    c1 = dr.channel1()
    ic = dr.initial_conditions_ideal()
    for key in ("phi_x", "phi_x_nodrift"):
        assert _ode_residual(c1[key], 0) == 0
    phi = c1["phi_x"]
    assert sp.simplify(phi.subs(s.t, 0) - s.alpha * sp.sin(s.psi0)) == 0
    rate0 = ic["phi_x_dot"].subs({s.b_g3: 0})
    assert sp.simplify(phi.diff(s.t).subs(s.t, 0) - rate0) == 0
    # the integral of eq. 32: derivative is p_merror and it starts at zero
    assert sp.simplify(c1["int_p"].diff(s.t) - c1["p_merror"]) == 0
    assert c1["int_p"].subs(s.t, 0) == 0
    assert c1["q_merror"] == 0


def test_channel3_solution_satisfies_eq35_and_eq34():
    c3 = dr.channel3_aw()
    ic = {k: v.subs({s.b_g1: 0, s.b_g2: 0}) for k, v in dr.initial_conditions_ideal().items()}
    forcing = {
        "x": s.Amp * sp.sin(s.psi0 - s.W * s.t),
        "y": s.Amp * sp.cos(s.psi0 - s.W * s.t),
    }
    for ax, key in (("x", "int_p"), ("y", "int_q")):
        phi = c3[f"phi_{ax}"]
        assert _ode_residual(phi, forcing[ax]) == 0
        assert sp.simplify(phi.subs(s.t, 0) - ic[f"phi_{ax}"]) == 0
        rate0 = ic[f"phi_{ax}_dot"].subs(dr.TO_AW)
        assert sp.simplify(phi.diff(s.t).subs(s.t, 0) - rate0) == 0
        # the position error (difference of two solutions) solves the forced ODE from rest
        # in tilt, with the jump of eq. 27 as its initial rate
        integral = c3[key]
        assert _ode_residual(integral, forcing[ax]) == 0
        assert integral.subs(s.t, 0) == 0
    jump_y = sp.expand(c3["int_q"].diff(s.t).subs(s.t, 0))
    assert sp.simplify(jump_y + s.alpha * s.b_g3 * sp.sin(s.psi0)) == 0


def test_printed_eq36q_violates_the_initial_rate_of_eq27():
    """The printed int q_merror starts at +alpha sin(psi0) b_g3; eq. 27 requires the opposite."""
    printed = P.PRINTED["36.q"].xreplace({**P.PRINTED["36.coef"], s.Amp: P.AMP_35})
    rate0 = sp.simplify(printed.diff(s.t).subs(s.t, 0))
    derived = al.tilt_rates_0p()["phi_y_dot"]  # (r_0m - b_g3) phi_x + b_g2
    jump = sp.expand(derived - derived.subs(s.b_g3, 0)).subs(s.phi_x, s.alpha * sp.sin(s.psi0))
    assert sp.simplify(rate0 - jump) != 0
    assert sp.simplify(rate0 + jump) == 0


def test_table2_entries_satisfy_the_schuler_loop():
    """Each derived Table 2 entry solves x''' + w0^2 x' = forcing with its initial conditions."""
    t2 = sch.table2()
    g = s.omega0**2 * s.R0
    cases = {
        # key: (solution, forcing of x''' + w0^2 x', x(0), x'(0), x''(0))
        "T2.1": (t2["T2.1"], 0, 0, 0, s.B_x),
        "T2.2": (t2["T2.2"], 0, 0, 0, -g * s.phi_y0),
        "T2.3": (t2["T2.3"], 0, 0, s.k_x * s.dV_x, 0),
        "T2.4": (t2["T2.4"], -g * s.eps_y, 0, 0, 0),
        "T2.6": (t2["T2.6"], 0, 0, s.dxdot0, 0),
        "T2.7": (t2["T2.7"], s.omega0**2 * s.phi_z0 * s.v_y, 0, 0, 0),
        "T2.5x": (t2["T2.5"][0], s.omega0**2 * s.v_y * s.eps_z * s.t, 0, 0, 0),
        "T2.5y": (t2["T2.5"][1], -(s.omega0**2) * s.v_x * s.eps_z * s.t, 0, 0, 0),
    }
    for key, (sol, forcing, x0, v0, a0) in cases.items():
        res = sol.diff(s.t, 3) + s.omega0**2 * sol.diff(s.t) - forcing
        assert sp.simplify(res) == 0, key
        assert sp.simplify(sol.subs(s.t, 0) - x0) == 0, key
        assert sp.simplify(sol.diff(s.t).subs(s.t, 0) - v0) == 0, key
        assert sp.simplify(sol.diff(s.t, 2).subs(s.t, 0) - a0) == 0, key


def test_scale_factor_impulse_limit():
    """Row 3: a velocity change over a short time tau tends to the impulse response."""
    tau = 1.0
    w0 = np.sqrt(G / R_EARTH)
    k, dv = 1e-4, 100.0

    def rhs(t, y):
        acc = dv / tau if t < tau else 0.0
        dx, dv_, phi = y
        return [dv_, k * acc - G * phi, dv_ / R_EARTH]

    t_end = 3000.0
    sol = solve_ivp(rhs, (0, t_end), [0, 0, 0], rtol=1e-10, atol=1e-12, max_step=0.05)
    exact = gen.table2_scale_factor(t_end - tau / 2, k, dv, w0)
    assert sol.y[0, -1] == pytest.approx(float(exact), rel=1e-3)


# ---------------------------------------------------------------- numerics


def _stationary_params():
    k = float(gen.k_sh_stationary(G, R_EARTH, OMEGA_E, LAT))
    alpha = float(gen.alpha_deflection(R_EARTH, OMEGA_E, LAT, G))
    return k, alpha


def test_channel1_closed_form_against_solve_ivp():
    k, alpha = _stationary_params()
    W = OMEGA_E * np.sin(LAT)
    phi0 = alpha * np.sin(PSI0)
    rate0 = -alpha * W * np.cos(PSI0)

    def rhs(t, y):
        # tilts with and without drift (eq. 29) and the integral of p_merror (eq. 32)
        a, ad, b, bd, _ = y
        return [ad, -k * a, bd, -k * b, ad - bd - B_G1]

    t = np.linspace(0, 2 * HOUR, 721)
    sol = solve_ivp(
        rhs, (0, t[-1]), [phi0, rate0 + B_G1, phi0, rate0, 0.0], t_eval=t, rtol=1e-12, atol=1e-18
    )
    int_p, int_q = gen.error_ch1(t, B_G1, k)
    # signed: int p_merror of eq. 32 is -b_g1 t + ..., the integral the ODE accumulates
    np.testing.assert_allclose(sol.y[4], int_p, rtol=1e-6, atol=1e-6 * np.abs(int_p).max())
    assert np.all(int_q == 0.0)
    closed = np.hypot(int_p, int_q)
    # linear growth b_g1 t with a Schuler ripple of amplitude b_g1 / sqrt(k_sh)
    assert np.all(np.abs(closed - B_G1 * t) <= B_G1 / np.sqrt(k) * (1 + 1e-9))


def test_channel3_closed_form_against_solve_ivp():
    k, alpha = _stationary_params()
    W = OMEGA_E * np.sin(LAT)
    amp = B_G3 * OMEGA_E * np.cos(LAT)

    def rhs(t, y):
        # eq. 35 with and without drift; their difference is int p_merror, int q_merror
        px, pxd, py, pyd, qx, qxd, qy, qyd = y
        return [
            pxd,
            -k * px + amp * np.sin(PSI0 - W * t),
            pyd,
            -k * py + amp * np.cos(PSI0 - W * t),
            qxd,
            -k * qx,
            qyd,
            -k * qy,
        ]

    ic = dr.initial_conditions_ideal()
    vals = {s.alpha: alpha, s.psi0: PSI0, s.omega_e: OMEGA_E, s.lat: LAT, s.b_g1: 0, s.b_g2: 0}
    y0 = []
    for drift in (B_G3, 0.0):
        for ax in ("x", "y"):
            y0 += [
                float(ic[f"phi_{ax}"].subs(vals)),
                float(ic[f"phi_{ax}_dot"].subs({**vals, s.b_g3: drift})),
            ]
    t = np.linspace(0, 2 * HOUR, 721)
    sol = solve_ivp(rhs, (0, t[-1]), y0, t_eval=t, rtol=1e-12, atol=1e-20)
    int_p, int_q = gen.error_ch3(t, B_G3, OMEGA_E, LAT, PSI0, k, alpha)
    scale = max(np.abs(int_p).max(), np.abs(int_q).max())
    np.testing.assert_allclose(sol.y[0] - sol.y[4], int_p, rtol=1e-6, atol=1e-6 * scale)
    np.testing.assert_allclose(sol.y[2] - sol.y[6], int_q, rtol=1e-6, atol=1e-6 * scale)
    # bounded: the error stays below A/(k - W^2) (1 + ...) ~ a few km, it does not grow
    err_km = np.hypot(int_p, int_q) * R_EARTH / 1e3
    assert err_km.max() < 3.0
    assert err_km[t > HOUR].max() < 1.5 * err_km[t <= HOUR].max()


def test_channel3_neglected_terms_are_small():
    """Eq. 33 drops b_g3 phi_dot and eq. 35 the b_g3 t of psi(t): keeping them stays in bound."""
    k, alpha = _stationary_params()
    W = OMEGA_E * np.sin(LAT)

    def full(t, y, drift):
        px, pxd, py, pyd = y
        psi = PSI0 + (drift - W) * t
        wy, wx = -OMEGA_E * np.cos(LAT) * np.sin(psi), OMEGA_E * np.cos(LAT) * np.cos(psi)
        return [
            pxd,
            -k * px - drift * wy + drift * pyd,
            pyd,
            -k * py + drift * wx - drift * pxd,
        ]

    ic = dr.initial_conditions_ideal()
    vals = {s.alpha: alpha, s.psi0: PSI0, s.omega_e: OMEGA_E, s.lat: LAT, s.b_g1: 0, s.b_g2: 0}
    t = np.linspace(0, 2 * HOUR, 361)
    runs = []
    for drift in (B_G3, 0.0):
        y0 = []
        for ax in ("x", "y"):
            y0 += [
                float(ic[f"phi_{ax}"].subs(vals)),
                float(ic[f"phi_{ax}_dot"].subs({**vals, s.b_g3: drift})),
            ]
        runs.append(
            solve_ivp(full, (0, t[-1]), y0, t_eval=t, args=(drift,), rtol=1e-12, atol=1e-20).y
        )
    int_p, int_q = gen.error_ch3(t, B_G3, OMEGA_E, LAT, PSI0, k, alpha)
    num = np.hypot(runs[0][0] - runs[1][0], runs[0][2] - runs[1][2])
    closed = np.hypot(int_p, int_q)
    # b_g3 phi_dot is resonant (phi oscillates at the Schuler frequency with amplitude ~ alpha):
    # it adds at most ~ b_g3 alpha t / 2 per axis, a slow secular growth (~6 % of the bounded
    # error after 2 h); the b_g3 t of psi adds ~ b_g3 t A / k_sh
    amp = B_G3 * OMEGA_E * np.cos(LAT)
    assert np.all(np.abs(num - closed) <= B_G3 * t * (alpha + amp / k) + 1e-12)
    assert np.abs(num - closed).max() < 0.1 * closed.max()


def test_schuler_period():
    period_min = float(gen.schuler_period(G, R_EARTH)) / 60
    assert abs(period_min - 84.4) < 0.1
    assert float(sch.schuler_period().subs({s.g: G, s.R: R_EARTH})) / 60 == pytest.approx(
        period_min
    )


def test_navigation_equations_oscillate_at_schuler_period():
    """Eqs. 9, 11 and 12 (generated) as a nonlinear closed loop: vehicle at rest in inertial space.

    Non-rotating Earth, r = 0; the accelerometers read f = -g (a = 0). A platform started
    with a 1 mrad tilt about axis 1 must oscillate at 2 pi / sqrt(GM / R^3).
    """
    GM = G * R_EARTH**2

    def rhs(t, y):
        x, y_, z, u, v, w, p, q = y
        g1, g2, g3 = gen.gravity_spherical(x, y_, z, GM)
        f1, f2, f3 = -g1, -g2, -g3
        rates = gen.motion_rates(x, y_, z, u, v, w, p, q, 0.0, f1, f2, f3, g1, g2, g3)
        p_dot, q_dot = gen.platform_commands_rates(f1, f2, z)
        return [*map(float, rates), float(p_dot), float(q_dot)]

    tilt = 1e-3
    y0 = [0.0, R_EARTH * np.sin(tilt), R_EARTH * np.cos(tilt), 0, 0, 0, 0, 0]
    period = float(gen.schuler_period(G, R_EARTH))
    sol = solve_ivp(rhs, (0, 2.2 * period), y0, rtol=1e-11, atol=1e-9, dense_output=True)
    t = np.linspace(0, 2.2 * period, 20001)
    phi_x = sol.sol(t)[1] / R_EARTH  # eq. 14
    up = np.where((phi_x[:-1] < 0) & (phi_x[1:] >= 0))[0]
    assert len(up) == 2
    measured = t[up[1]] - t[up[0]]
    assert measured == pytest.approx(period, rel=1e-3)
    assert np.abs(phi_x).max() == pytest.approx(tilt, rel=1e-3)


def test_position_rates_of_a_vehicle_at_rest():
    """Eq. 16 (derived): with p_m, q_m of the Earth rate, the position does not move."""
    rng = np.random.default_rng(11)
    lat, psi = rng.uniform(-1.4, 1.4, 50), rng.uniform(-np.pi, np.pi, 50)
    p_m = OMEGA_E * np.cos(lat) * np.cos(psi)
    q_m = -OMEGA_E * np.cos(lat) * np.sin(psi)
    lon_dot, lat_dot, psi_dot = gen.position_rates(p_m, q_m, 0.0, lat, psi, OMEGA_E)
    np.testing.assert_allclose(lon_dot, 0, atol=1e-18)
    np.testing.assert_allclose(lat_dot, 0, atol=1e-18)
    np.testing.assert_allclose(psi_dot, -OMEGA_E * np.sin(lat), rtol=1e-12)


def test_azimuth_drift_matches_fig5_value_at_tehran():
    """Table 2 row 5 (derived, eps_z/2) at rest: inertial east velocity omega_e R cos(lat)."""
    t = 2 * HOUR
    v_east = OMEGA_E * R_EARTH * np.cos(LAT)
    dx, dy = gen.table2_azimuth_drift(t, B_G3, v_east, 0.0, np.sqrt(G / R_EARTH))
    assert np.hypot(dx, dy) / 1e3 == pytest.approx(4.5, abs=0.2)


# ---------------------------------------------------------------- generated code


SAMPLE = {
    # keep the closed forms away from their singularities and in a physical range
    "k_sh": (0.6, 1.3),
    "omega_e": (0.05, 0.4),
    "lat": (-1.2, 1.2),
    "lat0": (0.2, 1.2),
    "R": (0.5, 2.0),
    "R_G": (0.5, 2.0),
    "z": (0.5, 2.0),
    "GM": (0.5, 2.0),
    # x, y small against R_G, so that the known-altitude z = sqrt(R_G^2 - x^2 - y^2) is real
    "x": (0.05, 0.3),
    "y": (0.05, 0.3),
}


@pytest.mark.parametrize("fn", generate.functions(), ids=lambda f: f.name)
def test_generated_equals_lambdified_derivation(fn):
    func = getattr(gen, fn.name)
    arg_names = list(inspect.signature(func).parameters)
    assert len(arg_names) == len(fn.args)
    exprs = [fn.exprs] if isinstance(fn.exprs, sp.Basic) else list(fn.exprs)
    lam = sp.lambdify(list(fn.args), exprs, "numpy")
    rng = np.random.default_rng(abs(hash(fn.name)) % 2**32)
    n = 25
    points = [rng.uniform(*SAMPLE.get(name, (0.1, 1.3)), n) for name in arg_names]
    got = func(*points)
    if fn.shape is not None:  # one array with trailing axes fn.shape
        got = list(np.asarray(got).reshape(n, -1).T)
    got = [got] if isinstance(fn.exprs, sp.Basic) else list(got)
    want = [np.broadcast_to(np.asarray(v, dtype=float), (n,)) for v in lam(*points)]
    for g_, w_ in zip(got, want, strict=True):
        assert np.all(np.isfinite(w_)), f"{fn.name}: sample outside the function's domain"
        np.testing.assert_allclose(g_, w_, rtol=1e-10, atol=1e-13)


def test_generated_signatures_are_the_agreed_ones():
    agreed = {
        "error_ch1": ["t", "b_g1", "k_sh"],
        "oscillation_period": ["k_sh"],
        "alignment_rates": ["omega_e", "lat", "psi", "phi_x", "phi_y"],
        "strapdown_velocity_rates": ["f_n", "f_e", "v_n", "v_e", "lat", "rho", "omega_e"],
        "error_ch3": ["t", "b_g3", "omega_e", "lat0", "psi0", "k_sh", "alpha"],
        "k_sh_stationary": ["g", "R", "omega_e", "lat"],
        "alpha_deflection": ["R", "omega_e", "lat", "g"],
        "table2_accel_bias": ["t", "B", "omega0"],
        "table2_initial_tilt": ["t", "phi0", "R0", "omega0"],
        "table2_scale_factor": ["t", "k", "dV", "omega0"],
        "table2_gyro_drift": ["t", "eps", "R0", "omega0"],
        "table2_azimuth_drift": ["t", "eps_z", "vx", "vy", "omega0"],
        "table2_initial_velocity": ["t", "dv0", "omega0"],
        "table2_initial_azimuth": ["t", "phi_z0", "v_cross", "omega0"],
        "position_rates": ["p_m", "q_m", "r_m", "lat", "psi", "omega_e"],
        "platform_commands_rates": ["f1", "f2", "z"],
        "motion_rates": [*"xyzuvwpqr", "f1", "f2", "f3", "g1", "g2", "g3"],
    }
    for name, args in agreed.items():
        assert list(inspect.signature(getattr(gen, name)).parameters) == args, name
