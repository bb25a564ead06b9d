"""The altimeter-attitude filters: discretisation, noise terms, exactness without noise,
consistency with noise, determinism, and the Monte Carlo bookkeeping."""

from __future__ import annotations

import numpy as np
import pytest
import scipy.linalg as sla

from pipeline.altimeter_attitude import (
    complementary,
    euler_filters,
    linear_kf,
    metrics,
    model,
    run,
)
from pipeline.altimeter_attitude.scenario import load_scenario
from pipeline.altimeter_attitude.sensors import simulate_inputs
from pipeline.altimeter_attitude.sweep import variant
from pipeline.generated import altimeter_attitude as gen

PAPER = "config/scenarios/altimeter_attitude/paper.yaml"
D_GAMMA = np.diag([1.0, 1.0, 1.0, 0.0, 0.0])


@pytest.fixture(scope="module")
def short_scenario():
    """The paper scenario cut to its first 45 s (pull-up and push-over included)."""
    base = load_scenario(PAPER)
    raw = {**base.raw, "trajectory": {**base.raw["trajectory"], "duration_s": 45.0}}
    raw["trajectory"]["maneuvers"] = [
        m for m in base.raw["trajectory"]["maneuvers"] if m["start_s"] + m["duration_s"] <= 45.0
    ]
    raw["metrics"] = {**raw["metrics"], "transient_s": 5.0}
    from pipeline.altimeter_attitude.scenario import build_scenario

    return build_scenario(raw, base.path)


def _random_a(rng, shape, k=1.0, gamma_scale=1e-3):
    gyro = rng.normal(scale=0.5, size=(*shape, 3))
    accel = rng.normal(scale=10.0, size=(*shape, 3))
    return model.matrix_a(gyro, accel, k, np.zeros(shape)), rng.normal(
        scale=gamma_scale, size=shape[0]
    )


def test_matrix_a_is_affine_in_gamma():
    rng = np.random.default_rng(0)
    gyro, accel = rng.normal(size=(4, 3)), rng.normal(size=(4, 3))
    g = rng.normal(size=4)
    a = model.matrix_a(gyro, accel, 2.5, g)
    a0 = model.matrix_a(gyro, accel, 2.5, np.zeros(4))
    np.testing.assert_allclose(a, a0 + 2.5 * g[:, None, None] * D_GAMMA, atol=1e-15)


def test_discretisations_match_scipy_expm():
    rng = np.random.default_rng(1)
    a0, gamma = _random_a(rng, (5, 6))
    dt = 0.02
    chunk = model.ChunkDiscretisation(a0[..., :3, :3], a0[..., 3, :3], dt)
    for j in range(6):
        a = a0[:, j] + gamma[:, None, None] * D_GAMMA
        ref = np.stack([sla.expm(m * dt) for m in a])
        np.testing.assert_allclose(chunk.transition(j, gamma), ref, atol=1e-14, rtol=0)
        F, L = model.discretise_structured(a, dt)
        np.testing.assert_allclose(F, ref, atol=1e-14, rtol=0)
        # exact ZOH input: int_0^dt exp(A s) ds B, from the augmented exponential
        aug = np.zeros((5, 6, 6))
        aug[:, :5, :5], aug[:, 3, 5] = a * dt, dt
        ref_l = np.stack([sla.expm(m)[:5, 5] for m in aug])
        np.testing.assert_allclose(L, ref_l, atol=1e-16)
        np.testing.assert_allclose(model.discretise(a, dt)[0], ref, atol=1e-13)


def test_chunk_falls_back_for_large_k_gamma():
    rng = np.random.default_rng(2)
    a0, _ = _random_a(rng, (3, 2))
    gamma = np.array([0.5, -0.3, 0.1])  # k gamma dt far beyond A_DT_MAX
    F = model.ChunkDiscretisation(a0[..., :3, :3], a0[..., 3, :3], 0.02).transition(1, gamma)
    ref = np.stack([sla.expm((a0[i, 1] + gamma[i] * D_GAMMA) * 0.02) for i in range(3)])
    np.testing.assert_allclose(F, ref, atol=1e-13)


def test_first_order_input_is_the_papers():
    np.testing.assert_array_equal(model.input_vector(0.02, "first_order"), [0, 0, 0, 0.02, 0])
    with pytest.raises(ValueError, match="input_matrix is 'zoh'"):
        model.input_vector(0.02, "zoh")


def test_gamma_term_closed_form_equals_kronecker_product():
    rng = np.random.default_rng(3)
    m = rng.normal(size=(6, 5, 5))
    P = m @ np.swapaxes(m, -1, -2)
    q = np.array([2.0, 2.0, 2.0, 0.3, 0.3, 0.3])
    gam = np.concatenate(list(model.GAMMA_COLUMNS * 0.02), axis=1)  # eq. 32, with G = dt C
    literal = np.stack([gam @ np.kron(np.diag(q), p) @ gam.T for p in P])
    np.testing.assert_allclose(model.gamma_kron_term(P, q, 0.02), literal, atol=1e-15)
    np.testing.assert_allclose(model.gamma_term_closed(P, 2.0, 0.3, 0.02), literal, atol=1e-15)


def test_noise_matrix_from_eq33_equals_generated_c():
    rng = np.random.default_rng(4)
    x = rng.normal(size=(7, 5))
    np.testing.assert_array_equal(model.noise_matrix_eq33(x), model.noise_matrix(x[:, :3]))


def test_noise_free_filters_follow_the_truth(short_scenario):
    inp = simulate_inputs(
        short_scenario.profiles,
        short_scenario.sensors,
        short_scenario.initial,
        1,
        short_scenario.seed,
        "t",
        noise_scale=0.0,
    )
    ests = linear_kf.run_linear_kf(inp, short_scenario.k, "exact", ("linear_kf", "gyro_only"))
    ests.append(euler_filters.run_ekf(inp))
    # the UKF's mean includes the sigma points' second-order terms (see the next test): with
    # its covariances shrunk it must follow the truth too, i.e. its model is exact
    tiny = inp.__class__(
        **{
            **inp.__dict__,
            "sigma0": inp.sigma0 * 1e-6,
            "sensors": inp.sensors.__class__(1e-9, 1e-9, 2.0, inp.sensors.rate_hz, 1),
        }
    )
    ests.append(euler_filters.run_ukf(tiny, 0.5, 2.0, 0.0))
    for est in ests:
        er, ep = metrics.angle_errors(est, inp.truth)
        # midpoint IMU samples held over 20 ms: second-order attitude error only
        assert np.abs(er).max() < 2e-4 and np.abs(ep).max() < 2e-4, est.filter
    lkf = ests[0]
    assert np.abs(lkf.norm_error).max() < 1e-6


def test_ukf_second_order_terms_bias_the_attitude_on_perfect_data(short_scenario):
    """With noise-free sensors and an exact start, the UKF (P0 = 2 deg) drifts in pitch: its
    sigma points spread the attitude, and E[c^T f] < c^T f moves the predicted altitude, which
    the linear update then attributes partly to pitch. The linear KF does not (test above)."""
    inp = simulate_inputs(
        short_scenario.profiles,
        short_scenario.sensors,
        short_scenario.initial,
        1,
        short_scenario.seed,
        "t",
        noise_scale=0.0,
    )
    est = euler_filters.run_ukf(inp, 0.5, 2.0, 0.0)
    _, ep = metrics.angle_errors(est, inp.truth)
    assert np.degrees(np.abs(ep).max()) > 0.5


def test_first_order_input_matrix_biases_the_vertical_channel(short_scenario):
    inp = simulate_inputs(
        short_scenario.profiles,
        short_scenario.sensors,
        short_scenario.initial,
        1,
        short_scenario.seed,
        "t",
        noise_scale=0.0,
    )
    exact = linear_kf.run_linear_kf(inp, 1.0, "exact", ("gyro_only",))[0]
    paper = linear_kf.run_linear_kf(inp, 1.0, "first_order", ("gyro_only",))[0]
    # attitude is unaffected: L only feeds V_d and h
    np.testing.assert_allclose(paper.roll, exact.roll, atol=1e-12)


def test_monte_carlo_is_reproducible_and_independent_of_run_count(short_scenario):
    sc = short_scenario
    a = simulate_inputs(sc.profiles, sc.sensors, sc.initial, 3, sc.seed, sc.name)
    b = simulate_inputs(sc.profiles, sc.sensors, sc.initial, 1, sc.seed, sc.name)
    np.testing.assert_array_equal(a.gyro[:1], b.gyro)
    np.testing.assert_array_equal(a.altimeter[:1], b.altimeter)
    other = simulate_inputs(sc.profiles, sc.sensors, sc.initial, 1, sc.seed, "another")
    assert not np.array_equal(other.gyro, b.gyro)
    e1 = run.run_filters(sc, a, ("linear_kf", "ukf"), log=lambda m: None)
    e2 = run.run_filters(sc, a, ("linear_kf", "ukf"), log=lambda m: None)
    for name in e1:
        np.testing.assert_array_equal(e1[name].roll, e2[name].roll)


def test_stacked_variants_equal_separate_runs(short_scenario):
    sc = short_scenario
    inp = simulate_inputs(sc.profiles, sc.sensors, sc.initial, 2, sc.seed, sc.name)
    stacked = linear_kf.run_linear_kf(inp, sc.k, "exact", tuple(linear_kf.VARIANTS))
    for est in stacked:
        alone = linear_kf.run_linear_kf(inp, sc.k, "exact", (est.filter,))[0]
        np.testing.assert_allclose(est.roll, alone.roll, atol=1e-13)
        np.testing.assert_allclose(est.roll_sigma, alone.roll_sigma, atol=1e-13)


def test_filters_are_consistent_with_noise(short_scenario):
    """Mean NEES over 40 runs after the transient inside a generous band around 1."""
    sc = short_scenario
    inp = simulate_inputs(sc.profiles, sc.sensors, sc.initial, 40, sc.seed, sc.name)
    ests = run.run_filters(sc, inp, ("linear_kf", "ukf", "gyro_only"), log=lambda m: None)
    for est in ests.values():
        row = metrics.summary_row(est, inp.truth, int(sc.transient * sc.sensors.rate_hz))
        # a conservative filter is acceptable (roll is poorly observable in cruise)
        assert 0.25 < row["nees_roll"] < 2.0 and 0.25 < row["nees_pitch"] < 2.0, row
    # the altimeter helps: both filters beat gyro-only propagation in pitch
    rms = {n: metrics.summary_row(e, inp.truth, 250)["pitch_rms_deg"] for n, e in ests.items()}
    assert rms["linear_kf"] < rms["gyro_only"] and rms["ukf"] < rms["gyro_only"]


def test_ukf_covariance_stays_positive_definite(short_scenario):
    sc = short_scenario
    inp = simulate_inputs(sc.profiles, sc.sensors, sc.initial, 5, sc.seed, sc.name)
    est = euler_filters.run_ukf(inp, sc.ukf_alpha, sc.ukf_beta, sc.ukf_kappa)
    assert np.all(est.roll_sigma > 0) and np.all(est.pitch_sigma > 0)


def test_complementary_converges_to_accelerometer_attitude_in_cruise():
    """Eq. 19: in unaccelerated flight the PI loop settles on c_a (here the truth)."""
    from pipeline.altimeter_attitude.scenario import build_scenario

    base = load_scenario("config/scenarios/altimeter_attitude/gentle_cruise.yaml")
    raw = {**base.raw, "trajectory": {**base.raw["trajectory"], "duration_s": 200.0}}
    raw["trajectory"]["maneuvers"] = []
    sc = build_scenario(raw, base.path)
    inp = simulate_inputs(sc.profiles, sc.sensors, sc.initial, 1, sc.seed, sc.name, noise_scale=0.0)
    inp = inp.__class__(**{**inp.__dict__, "x0_euler": inp.x0_euler + [0.1, -0.1, 0, 0]})
    est = complementary.run_complementary(inp, 0.1, 1 / np.sqrt(2))
    er, ep = metrics.angle_errors(est, inp.truth)
    assert abs(er[0, 0]) > 0.09 and np.abs(er[0, -500:]).max() < 1e-5
    assert np.abs(ep[0, -500:]).max() < 1e-5


def test_accelerometer_leveling_is_exact_at_rest_of_acceleration():
    base = load_scenario("config/scenarios/altimeter_attitude/gentle_cruise.yaml")
    sc = variant(base, "intensity", 0.0)
    inp = simulate_inputs(sc.profiles, sc.sensors, sc.initial, 1, sc.seed, sc.name, noise_scale=0.0)
    est = complementary.run_accel_leveling(inp)
    er, ep = metrics.angle_errors(est, inp.truth)
    assert np.abs(er).max() < 1e-12 and np.abs(ep).max() < 1e-12


def test_rotate_third_row_solves_the_kinematics():
    rng = np.random.default_rng(5)
    c = rng.normal(size=(4, 3))
    w = rng.normal(size=(4, 3))
    out = complementary.rotate_third_row(c, w, 0.05)
    # c_dot = -w x c  ->  c(dt) = exp(-[w x] dt) c
    ref = np.stack([sla.expm(-_skew(wi) * 0.05) @ ci for wi, ci in zip(w, c, strict=True)])
    np.testing.assert_allclose(out, ref, atol=1e-14)


def _skew(w):
    return np.array([[0, -w[2], w[1]], [w[2], 0, -w[0]], [-w[1], w[0], 0]])


def test_euler_maps_round_trip():
    rng = np.random.default_rng(6)
    phi, theta = rng.uniform(-1.5, 1.5, 50), rng.uniform(-1.4, 1.4, 50)
    c = np.stack(gen.third_row_from_euler(phi, theta), -1)
    back = gen.euler_from_third_row(*(1.3 * c).T)  # scale-invariant
    np.testing.assert_allclose(back[0], phi, atol=1e-14)
    np.testing.assert_allclose(back[1], theta, atol=1e-14)


def test_a_blocks_equal_the_generated_matrix():
    rng = np.random.default_rng(7)
    gyro, accel = rng.normal(size=(4, 5, 3)), rng.normal(size=(4, 5, 3))
    a = model.matrix_a(gyro, accel, 1.0, np.zeros((4, 5)))
    w, f = model.a_blocks(gyro, accel)
    np.testing.assert_allclose(w, a[..., :3, :3], atol=1e-15)
    np.testing.assert_allclose(f, a[..., 3, :3], atol=1e-15)
