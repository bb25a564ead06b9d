"""Derivations of altimeter_attitude checked by numbers, independently of the SymPy path.

* the quaternion DCM of the 3-2-1 quaternion is the 3-2-1 DCM (eqs. 5-6);
* the Euler-rate equation (eq. 4), integrated along a random smooth body-rate profile,
  gives the roll and pitch of the DCM integrated with d/dt C = C [omega x] (eq. 1);
* the normalised third-row equation (eq. 14) drives |c| from 1.1 to 1 at rate 2k;
* Appendix A by Monte Carlo: the covariance of y = F x + G(x) w is F P F^T +
  G(x_hat) Q G^T(x_hat) + Gamma (Q kron P) Gamma^T, and is underestimated without the Gamma
  term; the symbolic identities hold for the generic instance and the paper's G(x) = dt C(x);
* the PI loop of Fig. 1 simulated in time has the step responses of eq. 18;
* A x + B g + C(x) w of eq. 26 is eqs. 14, 24, 25 with omega = omega_tilde - n_w,
  f = f_tilde - n_a;
* the series discretisation of eqs. 29-30 agrees with the matrix-exponential ZOH model to
  O(dt^4).
"""

from __future__ import annotations

import functools

import numpy as np
import pytest
import sympy as sp
from scipy import signal
from scipy.integrate import solve_ivp
from scipy.linalg import expm

from derivations.altimeter_attitude import complementary as cf
from derivations.altimeter_attitude import kinematics as kin
from derivations.altimeter_attitude import model as md
from derivations.altimeter_attitude import multiplicative_noise as mn
from derivations.altimeter_attitude import printed as pr
from derivations.altimeter_attitude import symbols as s


def _skew(v: np.ndarray) -> np.ndarray:
    return np.array([[0.0, -v[2], v[1]], [v[2], 0.0, -v[0]], [-v[1], v[0], 0.0]])


# ---------------------------------------------------------------- attitude kinematics


def test_quaternion_dcm_of_the_euler_quaternion_is_the_euler_dcm():
    angles = [s.phi, s.theta, s.psi]
    f_q = sp.lambdify(angles, kin.quaternion_dcm(kin.quaternion_from_euler()), "numpy")
    f_c = sp.lambdify(angles, kin.mat_nb(), "numpy")
    rng = np.random.default_rng(1)
    for _ in range(20):
        ang = rng.uniform([-np.pi, -1.5, -np.pi], [np.pi, 1.5, np.pi])
        c = np.asarray(f_c(*ang), dtype=float)
        np.testing.assert_allclose(np.asarray(f_q(*ang), dtype=float), c, atol=1e-13)
        np.testing.assert_allclose(c.T @ c, np.eye(3), atol=1e-13)


def test_euler_rates_integrate_to_the_attitude_of_the_dcm_equation():
    rng = np.random.default_rng(2)
    amp = rng.uniform(-0.3, 0.3, (3, 3))
    freq = rng.uniform(0.2, 1.5, (3, 3))
    phase = rng.uniform(0, 2 * np.pi, (3, 3))

    def omega(t):  # smooth body rate relative to NED, rad/s
        return (amp * np.sin(freq * t + phase)).sum(axis=1)

    rates = sp.lambdify([s.phi, s.theta, s.psi, *s.omega], kin.euler_rates(), "numpy")
    dcm = sp.lambdify([s.phi, s.theta, s.psi], kin.mat_nb(), "numpy")
    ang0 = np.array([0.2, -0.1, 0.7])
    t_end = 10.0
    t_eval = np.linspace(0, t_end, 101)
    sol_e = solve_ivp(
        lambda t, y: np.asarray(rates(*y, *omega(t)), dtype=float).ravel(),
        (0, t_end),
        ang0,
        t_eval=t_eval,
        rtol=1e-11,
        atol=1e-12,
    )
    sol_c = solve_ivp(
        lambda t, y: (y.reshape(3, 3) @ _skew(omega(t))).ravel(),
        (0, t_end),
        np.asarray(dcm(*ang0), dtype=float).ravel(),
        t_eval=t_eval,
        rtol=1e-11,
        atol=1e-12,
    )
    assert sol_e.success and sol_c.success
    assert np.abs(sol_e.y[1]).max() < 1.3  # pitch stays away from the singularity
    c = sol_c.y.reshape(3, 3, -1)
    roll = np.arctan2(c[2, 1], c[2, 2])
    pitch = -np.arcsin(c[2, 0])
    np.testing.assert_allclose(np.angle(np.exp(1j * (sol_e.y[0] - roll))), 0, atol=1e-8)
    np.testing.assert_allclose(sol_e.y[1], pitch, atol=1e-8)
    assert np.ptp(roll) > 0.3 and np.ptp(pitch) > 0.3  # the profile really moves


def test_normalised_third_row_converges_to_unit_norm_at_rate_2k():
    k = 2.0
    rhs = sp.lambdify([*s.c, *s.omega, s.k], kin.normalised_third_row_rates(), "numpy")
    w = np.array([0.3, -0.5, 0.2])
    c0 = np.array([0.3, -0.4, 0.8])
    c0 *= 1.1 / np.linalg.norm(c0)  # |c| = 1.1
    t = np.linspace(0, 4, 81)
    sol = solve_ivp(
        lambda _t, y: np.asarray(rhs(*y, *w, k), dtype=float).ravel(),
        (0, t[-1]),
        c0,
        t_eval=t,
        rtol=1e-11,
        atol=1e-13,
    )
    n = (sol.y**2).sum(axis=0)
    # n_dot = 2 k (1 - n) n: the logistic solution from n0 = 1.21
    n0 = n[0]
    np.testing.assert_allclose(n, 1 / (1 + (1 / n0 - 1) * np.exp(-2 * k * t)), rtol=1e-8)
    assert abs(np.sqrt(n[-1]) - 1) < 1e-3
    late = t > 1.0
    slope = np.polyfit(t[late], np.log(np.abs(n[late] - 1)), 1)[0]
    assert slope == pytest.approx(-2 * k, rel=1e-2)


# ---------------------------------------------------------------- Appendix A


def test_appendix_a_covariance_by_monte_carlo():
    rng = np.random.default_rng(3)
    n, m, N = 3, 2, 400_000
    F = rng.normal(size=(n, n))
    gc = [rng.normal(size=(n, n)) for _ in range(m)]
    xhat = rng.normal(size=n)
    a = rng.normal(size=(n, n))
    Pm = a @ a.T + 0.5 * np.eye(n)
    b = rng.normal(size=(m, m))
    Qm = b @ b.T + 0.2 * np.eye(m)
    x = rng.multivariate_normal(xhat, Pm, size=N)
    w = rng.multivariate_normal(np.zeros(m), Qm, size=N)
    gx = np.stack([x @ g.T for g in gc], axis=-1)  # G(x) for every sample: N x n x m
    y = x @ F.T + np.einsum("kij,kj->ki", gx, w)
    sample = np.cov(y, rowvar=False)
    ghat = np.stack([g @ xhat for g in gc], axis=-1)
    gamma = np.hstack(gc)
    gamma_term = gamma @ np.kron(Qm, Pm) @ gamma.T
    closed = F @ Pm @ F.T + ghat @ Qm @ ghat.T + gamma_term
    tol = 0.02 * np.abs(closed).max()
    assert np.abs(sample - closed).max() < tol
    assert np.abs(y.mean(axis=0) - F @ xhat).max() < 0.02 * np.sqrt(np.diag(closed)).max()
    # without the Gamma term the covariance is underestimated (the term is PSD and large here)
    assert np.linalg.eigvalsh(gamma_term).min() > -1e-9
    without = closed - gamma_term
    assert np.abs(sample - without).max() > 5 * tol
    assert np.trace(sample) > np.trace(without) + 5 * tol


def test_covariance_identity_is_exact_symbolically():
    assert mn.covariance_identity(n=2, m=2)["difference"] == sp.zeros(2, 2)
    assert mn.covariance_identity(setting=mn.paper_setting())["difference"] == sp.zeros(5, 5)
    assert mn.paper_gamma_term()["difference"] == sp.zeros(5, 5)


def _printed_setting() -> mn.Setting:
    st = mn.Setting(2, 2, [pr.Gc1, pr.Gc2])  # printed.py's n = m = 2 instance (the audit's)
    st.F, st.P, st.Q, st.xhat = pr.F_a, pr.P_a, pr.Q_a, pr.xhat_a
    return st


@pytest.mark.parametrize("which", ["generic", "printed", "paper"])
def test_expected_outer_is_the_expanded_expectation_of_each_product(which):
    """covariance_identity's E[u u^T] from the moments of products of monomials is the same
    expressions (srepr) as the expectation of each expanded product u_i u_j, entry by entry."""
    st = {"generic": mn.generic_setting, "printed": _printed_setting, "paper": mn.paper_setting}
    st = st[which]()
    y = st.F * st.x + st.G(st.x) * st.w
    for u in (y - st.F * st.xhat, st.G(st.x) * st.w, st.G(st.e) * st.w):
        by_product = (u * u.T).applyfunc(lambda v: sp.expand(mn.expect(v, st)))
        fast = mn._expected_outer(u, st)
        assert [sp.srepr(v) for v in fast] == [sp.srepr(v) for v in by_product]
    with pytest.raises(ValueError, match="needs more than the mean and covariance"):
        mn._expected_outer(sp.Matrix([st.e[0] ** 2, st.e[0]]), st)


# ---------------------------------------------------------------- the PI complementary filter


def test_pi_loop_in_time_has_the_step_responses_of_eq18():
    kp, ki = 2 * 0.707 * 0.5, 0.5**2
    t = np.linspace(0, 40, 801)

    def loop(_t, y, cg_dot, ca):  # s c_m = s c_g + (k_p + k_i/s)(c_a - c_m)
        cm, integ = y
        err = ca - cm
        return [cg_dot + kp * err + integ, ki * err]

    tf = cf.output_transfer().subs({s.k_p: kp, s.k_i: ki})

    def response(cg, ca):
        num, den = sp.fraction(sp.together(tf.subs({cf.c_g: cg, cf.c_a: ca})))
        num_c = [float(v) for v in sp.Poly(num, s.s).all_coeffs()]
        den_c = [float(v) for v in sp.Poly(den, s.s).all_coeffs()]
        return signal.step(signal.lti(num_c, den_c), T=t)[1]

    # unit step of c_a, c_g constant (zero)
    sim = solve_ivp(loop, (0, t[-1]), [0.0, 0.0], t_eval=t, args=(0.0, 1.0), rtol=1e-10, atol=1e-12)
    np.testing.assert_allclose(sim.y[0], response(0, 1), atol=1e-6)
    assert sim.y[0].max() > 1.15  # the zero of eq. 18 makes it overshoot (about 20.8 %)
    # unit step of c_g (its rate is an impulse: c_m jumps to 1 at 0+), c_a = 0
    sim = solve_ivp(loop, (0, t[-1]), [1.0, 0.0], t_eval=t, args=(0.0, 0.0), rtol=1e-10, atol=1e-12)
    np.testing.assert_allclose(sim.y[0], response(1, 0), atol=1e-6)
    assert abs(sim.y[0][-1]) < 1e-2  # eq. 19: the gyro solution is washed out


@pytest.mark.parametrize("xi", [1 / np.sqrt(2), 1.0, 0.3, 1.5])
def test_step_overshoot_closed_form_is_scipys_step_response(xi):
    """complementary.step_overshoot (the audit's note on eq. 21) takes the closed-form step
    responses; SciPy's signal.step of the same two systems gives the same peaks."""
    t = np.linspace(0.0, 30.0, 30001)
    kp = 2 * xi
    y_pi = signal.step(signal.lti([kp, 1.0], [1.0, kp, 1.0]), T=t)[1]
    y_2 = signal.step(signal.lti([1.0], [1.0, kp, 1.0]), T=t)[1]
    got = cf.step_overshoot(xi)
    assert got["pi_loop_overshoot_pct"] == pytest.approx(100 * (y_pi.max() - 1.0), abs=1e-9)
    assert got["second_order_overshoot_pct"] == pytest.approx(100 * (y_2.max() - 1.0), abs=1e-9)


# ---------------------------------------------------------------- the linear model of eq. 26


def test_model_matrices_are_eqs_14_24_25_with_the_sensor_model():
    mm = md.model_matrices()
    syms = [*s.x, *s.omega_t, *s.f_t, *s.w, s.k, s.gamma, s.g]
    rhs = sp.lambdify(syms, mm["A"] * s.x + mm["B"] * s.g + mm["C"] * s.w, "numpy")
    rng = np.random.default_rng(4)
    for _ in range(20):
        c = rng.normal(size=3)
        vd, h = rng.normal(size=2)
        wt, ft, nw, na = (rng.normal(size=3) for _ in range(4))
        k, g = 3.0, 9.81
        gamma = 1 - c @ c
        om, f = wt - nw, ft - na  # omega_tilde = omega + n_w, f_tilde = f + n_a
        direct = np.concatenate([k * gamma * c - np.cross(om, c), [c @ f + g, -vd]])
        got = np.asarray(rhs(*c, vd, h, *wt, *ft, *nw, *na, k, gamma, g), dtype=float).ravel()
        np.testing.assert_allclose(got, direct, rtol=1e-12, atol=1e-12)


def test_series_discretisation_agrees_with_the_matrix_exponential():
    ds = md.discretisation_series(order=3)
    mm = md.model_matrices()
    syms = [*s.x, *s.omega_t, *s.f_t, s.k, s.gamma]
    rng = np.random.default_rng(5)
    vals = [*rng.normal(size=5), *rng.normal(size=3), *rng.normal(size=3), 1.0, 0.05]
    sub = dict(zip(syms, vals, strict=True))
    A = np.array(mm["A"].subs(sub), dtype=float)
    B = np.array(mm["B"], dtype=float)
    C = np.array(mm["C"].subs(sub), dtype=float)
    errs = {"F": [], "L": [], "G": []}
    for dt in (0.02, 0.01):
        # ZOH: expm([[A, I], [0, 0]] dt) has int_0^dt exp(A s) ds in its top-right block
        aug = np.zeros((10, 10))
        aug[:5, :5], aug[:5, 5:] = A, np.eye(5)
        big = expm(aug * dt)
        exact = {"F": big[:5, :5], "L": big[:5, 5:] @ B, "G": big[:5, 5:] @ C}
        for key in errs:
            series = np.array(ds[key].subs({**sub, s.dt: dt}), dtype=float)
            errs[key].append(np.abs(series - exact[key]).max())
    # L terminates (A^2 B = 0): exact; F, G are correct through dt^3, error O(dt^4)
    assert max(errs["L"]) < 1e-15
    for key in ("F", "G"):
        assert errs[key][0] < 1e-6
        assert errs[key][0] / errs[key][1] == pytest.approx(16, rel=0.15)
    # the paper's first-order L = dt B misses -g dt^2/2 in h (per unit g)
    assert ds["L"] - ds["L1"] == sp.Matrix([0, 0, 0, 0, -(s.dt**2) / 2])


# ------------------------------------------- the generated forms the filter calls (issue 12)


@functools.lru_cache(maxsize=1)
def _generated_functions():
    from derivations.altimeter_attitude import generate

    return {f.name: f for f in generate.functions()}


def _generated(name: str):
    return _generated_functions()[name]


def test_generated_gamma_term_closed_is_the_kronecker_form_symbolically():
    """The closed form the filter calls (generated ``gamma_term_closed``) equals eq. 31's
    literal Gamma (Q kron P) Gamma^T of eqs. 32-33 for a fully symbolic symmetric P:
    sympy simplifies the difference, entry by entry, to 0."""
    pg = mn.paper_gamma_term()
    *block, vv = _generated("gamma_term_closed").exprs
    closed = sp.zeros(5, 5)
    closed[:3, :3] = sp.Matrix(3, 3, block)
    closed[3, 3] = vv
    assert (pg["literal"] - closed).applyfunc(sp.simplify) == sp.zeros(5, 5)
    # the proof is not vacuous: dropping the sigma_a^2 entry leaves a nonzero difference
    closed[3, 3] = 0
    assert (pg["literal"] - closed).applyfunc(sp.simplify) != sp.zeros(5, 5)


def test_generated_normalisation_error_is_eq15():
    """The generated eq. 15 is 1 - c^T c (symbolically), and rounds like the einsum the
    filters used before it (bit for bit on x86-64, where the order was read off)."""
    import platform

    from pipeline.generated import altimeter_attitude as gen

    expr = _generated("normalisation_error").exprs
    assert sp.simplify(expr.doit() - (1 - (s.c.T * s.c)[0])) == 0
    rng = np.random.default_rng(15)
    c = rng.normal(size=(20000, 3))
    c /= np.linalg.norm(c, axis=-1, keepdims=True)
    c *= 1 + 1e-9 * rng.normal(size=(20000, 1))
    got = gen.normalisation_error(c[:, 0], c[:, 1], c[:, 2])
    np.testing.assert_allclose(got, 1 - np.sum(c**2, axis=-1), rtol=0, atol=1e-15)
    if platform.machine() in ("x86_64", "AMD64"):
        np.testing.assert_array_equal(got, 1.0 - np.einsum("ni,ni->n", c, c))


def test_generated_input_vectors_and_vertical_block_are_the_zoh_of_eq26():
    """L (exact and first order) and exp(V dt) as generated, against sympy's matrix exponential
    of the augmented [[A, B], [0, 0]] at random numeric IMU outputs (an independent path)."""
    from pipeline.generated import altimeter_attitude as gen

    mm = md.model_matrices()
    rng = np.random.default_rng(26)
    syms = [*s.omega_t, *s.f_t, s.k, s.gamma]
    vals = dict(zip(syms, [*rng.normal(size=6), 1.0, 0.01], strict=True))
    dt = 0.02
    aug = np.zeros((6, 6))
    aug[:5, :5] = np.array(mm["A"].subs(vals), dtype=float)
    aug[:5, 5] = np.array(mm["B"], dtype=float).ravel()
    big = expm(aug * dt)
    np.testing.assert_allclose(gen.input_vector_exact(dt), big[:5, 5], rtol=0, atol=1e-16)
    np.testing.assert_array_equal(gen.input_vector_first_order(dt), aug[:5, 5] * dt)
    np.testing.assert_allclose(
        np.reshape(gen.vertical_transition(dt), (2, 2)), big[3:5, 3:5], rtol=0, atol=1e-16
    )
    np.testing.assert_array_equal(gen.input_matrix_b(), aug[:5, 5])


def test_rodrigues_step_is_derived_and_grouping_keeps_the_value():
    """kinematics.third_row_rotation: R(a) = I + sin a [k x] + (1 - cos a)[k x]^2 solves
    dR/da = [k x] R on |k| = 1, and R c is the (grouped) Rodrigues vector; the check is
    not vacuous: off the unit sphere the same ODE residual is not 0."""
    r = kin.third_row_rotation(grouped=True)
    assert r["check"] is True
    k = sp.Matrix(r["args"][:3])
    a = sp.Symbol("a", real=True)
    kx = sp.Matrix([[0, -k[2], k[1]], [k[2], 0, -k[0]], [-k[1], k[0], 0]])
    rot = sp.eye(3) + sp.sin(a) * kx + (1 - sp.cos(a)) * kx * kx
    assert (rot.diff(a) - kx * rot).applyfunc(sp.expand) != sp.zeros(3, 3)
