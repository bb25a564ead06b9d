"""Batched UKF (pipeline.altimeter_attitude.ukf) against filterpy's UnscentedKalmanFilter.

The attitude/altitude model below is written here independently of the pipeline: state
x = [roll phi, pitch theta, V_d (velocity down), h (altitude up)], gyro omega and accelerometer
f held constant over a step, one RK4 step per filter step, altimeter z = h + noise. filterpy
is a test-only dependency (``pytest.importorskip``); the weight, sigma-point and error tests
run without it.
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np
import pytest

from pipeline.altimeter_attitude.ukf import (
    MerweWeights,
    NotPositiveDefiniteError,
    assert_positive_definite,
    predict,
    sigma_points,
    unscented_transform,
    update,
)

G = 9.80665  # m/s^2
DT = 0.02  # s
N_STEPS = 400
SIGMA_GYRO = np.deg2rad(0.5)  # rad/s
SIGMA_ACCEL = 0.1  # m/s^2
R_ALT = np.array([[2.0**2]])  # m^2
Q_FLOOR = 1e-12
X0_ERROR = np.array([np.deg2rad(1.0), np.deg2rad(-1.0), 0.3, 3.0])
P0 = np.diag([np.deg2rad(2.0) ** 2, np.deg2rad(2.0) ** 2, 0.5**2, 5.0**2])
# (alpha, beta, kappa) for which a whole run agrees with filterpy to 1e-9
SETTINGS = [(0.5, 2.0, 0.0), (1.0, 2.0, 1.0)]
# alpha = 1e-3 gives Wm[0] = 1 - 1e6: the weighted means cancel terms ~1e8 m, so round-off
# differences of ~1e-16 per step (summation order of the cross-covariance, K y) grow to ~1e-7
# in x over the run. filterpy is equally sensitive to its own round-off (perturbing z by
# 1e-13 m moves its x by ~1e-7), so this setting is checked to a looser tolerance.
SENSITIVE = (1e-3, 2.0, 0.0)


# --- model (any leading dimensions: (4,) for filterpy, (N, S, 4) for the batched filter) ---


def rates(x: np.ndarray, omega: np.ndarray, f: np.ndarray) -> np.ndarray:
    """d/dt [phi, theta, V_d, h] for body rates omega and specific force f."""
    phi, theta, v_d = x[..., 0], x[..., 1], x[..., 2]
    sphi, cphi = np.sin(phi), np.cos(phi)
    sth, cth = np.sin(theta), np.cos(theta)
    wx, wy, wz = omega[..., 0], omega[..., 1], omega[..., 2]
    fx, fy, fz = f[..., 0], f[..., 1], f[..., 2]
    return np.stack(
        [
            wx + np.tan(theta) * (sphi * wy + cphi * wz),
            cphi * wy - sphi * wz,
            -sth * fx + sphi * cth * fy + cphi * cth * fz + G,
            -v_d,
        ],
        axis=-1,
    )


def rk4_step(x: np.ndarray, dt: float, omega: np.ndarray, f: np.ndarray) -> np.ndarray:
    k1 = rates(x, omega, f)
    k2 = rates(x + 0.5 * dt * k1, omega, f)
    k3 = rates(x + 0.5 * dt * k2, omega, f)
    k4 = rates(x + dt * k3, omega, f)
    return x + dt / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4)


def noise_jacobian(x: np.ndarray) -> np.ndarray:
    """d(rates)/d[gyro noise, accel noise], shape (..., 4, 6): the noise enters like omega, f."""
    phi, theta = x[..., 0], x[..., 1]
    sphi, cphi = np.sin(phi), np.cos(phi)
    sth, cth, tth = np.sin(theta), np.cos(theta), np.tan(theta)
    J = np.zeros(x.shape[:-1] + (4, 6))
    J[..., 0, 0] = 1.0
    J[..., 0, 1] = tth * sphi
    J[..., 0, 2] = tth * cphi
    J[..., 1, 1] = cphi
    J[..., 1, 2] = -sphi
    J[..., 2, 3] = -sth
    J[..., 2, 4] = sphi * cth
    J[..., 2, 5] = cphi * cth
    return J


SIGMA_NOISE = np.diag([SIGMA_GYRO**2] * 3 + [SIGMA_ACCEL**2] * 3)


def process_noise(x: np.ndarray, dt: float, q_alt: float = 0.0) -> np.ndarray:
    """State-dependent Q = dt^2 J Sigma J^T + 1e-12 I (+ q_alt on h), shape (..., 4, 4)."""
    J = noise_jacobian(x)
    Q = dt**2 * (J @ SIGMA_NOISE @ np.swapaxes(J, -1, -2)) + Q_FLOOR * np.eye(4)
    Q[..., 3, 3] += q_alt
    return Q


def fx_single(x: np.ndarray, dt: float, omega: np.ndarray, f: np.ndarray) -> np.ndarray:
    return rk4_step(x, dt, omega, f)


def hx_single(x: np.ndarray) -> np.ndarray:
    return x[3:4]


def fx_batched(sigmas: np.ndarray, dt: float, omega: np.ndarray, f: np.ndarray) -> np.ndarray:
    # per-trial inputs (N, 3) are broadcast over the sigma-point axis here, as ukf.py documents
    return rk4_step(sigmas, dt, omega[:, None, :], f[:, None, :])


def hx_batched(sigmas: np.ndarray) -> np.ndarray:
    return sigmas[..., 3:4]


# --- truth and sensor data ---


def bump(t: float, t0: float, t1: float) -> float:
    """Smooth sin^2 pulse on [t0, t1] (integral (t1 - t0) / 2)."""
    if not t0 <= t <= t1:
        return 0.0
    return float(np.sin(np.pi * (t - t0) / (t1 - t0)) ** 2)


def true_omega(t: float) -> np.ndarray:
    """Gentle pull-up (pitch rate pulse) and roll in and partly out."""
    return np.array(
        [
            0.3 * bump(t, 1.0, 3.0) - 0.15 * bump(t, 5.0, 7.0),
            0.15 * bump(t, 0.5, 2.5) - 0.05 * bump(t, 4.0, 6.0),
            0.02,
        ]
    )


def true_specific_force(x: np.ndarray, t: float) -> np.ndarray:
    """Gravity-cancelling specific force plus a vertical pull-up pulse and a small wobble."""
    phi, theta = x[0], x[1]
    down = np.array([-np.sin(theta), np.sin(phi) * np.cos(theta), np.cos(phi) * np.cos(theta)])
    delta = np.array([0.2 * np.sin(1.3 * t), 0.1 * np.cos(0.7 * t), -1.5 * bump(t, 0.5, 3.0)])
    return -G * down + delta


@dataclass(frozen=True)
class Data:
    truth: np.ndarray  # (N_STEPS + 1, 4)
    gyro: np.ndarray  # (N, N_STEPS, 3), held over [t_k, t_k+1]
    accel: np.ndarray  # (N, N_STEPS, 3)
    z: np.ndarray  # (N, N_STEPS + 1) altimeter; z[:, k] at t_k
    x0: np.ndarray  # (N, 4)

    def trial(self, i: int) -> Data:
        s = slice(i, i + 1)
        return Data(self.truth, self.gyro[s], self.accel[s], self.z[s], self.x0[s])


def simulate_truth(substeps: int = 5) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Fine RK4 of the model with time-varying true inputs; omega, f sampled at each t_k."""
    x = np.array([0.0, np.deg2rad(2.0), 0.0, 100.0])
    truth, omegas, forces = [x], [], []
    h = DT / substeps
    for k in range(N_STEPS):
        t_k = k * DT
        omegas.append(true_omega(t_k))
        forces.append(true_specific_force(x, t_k))
        for j in range(substeps):
            t = t_k + j * h

            def rhs(xx: np.ndarray, tt: float) -> np.ndarray:
                return rates(xx, true_omega(tt), true_specific_force(xx, tt))

            k1 = rhs(x, t)
            k2 = rhs(x + 0.5 * h * k1, t + 0.5 * h)
            k3 = rhs(x + 0.5 * h * k2, t + 0.5 * h)
            k4 = rhs(x + h * k3, t + h)
            x = x + h / 6.0 * (k1 + 2.0 * k2 + 2.0 * k3 + k4)
        truth.append(x)
    return np.array(truth), np.array(omegas), np.array(forces)


_TRUTH = None


def make_data(n_trials: int, seed: int) -> Data:
    global _TRUTH
    if _TRUTH is None:
        _TRUTH = simulate_truth()
    truth, omegas, forces = _TRUTH
    rng = np.random.default_rng(seed)
    gyro = omegas + SIGMA_GYRO * rng.standard_normal((n_trials, N_STEPS, 3))
    accel = forces + SIGMA_ACCEL * rng.standard_normal((n_trials, N_STEPS, 3))
    z = truth[:, 3] + np.sqrt(R_ALT[0, 0]) * rng.standard_normal((n_trials, N_STEPS + 1))
    x0 = truth[0] + X0_ERROR * (1.0 + 0.2 * rng.standard_normal((n_trials, 4)))
    return Data(truth, gyro, accel, z, x0)


# --- filters ---


def run_batched(
    data: Data, weights: MerweWeights, redraw_sigmas: bool = True, q_alt: float = 0.0
) -> dict:
    """Our UKF over all steps; histories shaped (N_STEPS, N, ...)."""
    N = data.x0.shape[0]
    x, P = data.x0.copy(), np.broadcast_to(P0, (N, 4, 4)).copy()
    out = {k: [] for k in ("x_prior", "P_prior", "x", "P", "y", "S", "min_eig")}
    for k in range(N_STEPS):
        Q = process_noise(x, DT, q_alt)
        x_prior, P_prior, sigmas_f = predict(
            x,
            P,
            fx_batched,
            Q,
            DT,
            weights,
            redraw_sigmas=redraw_sigmas,
            omega=data.gyro[:, k],
            f=data.accel[:, k],
        )
        x, P, y, S = update(
            x_prior, P_prior, sigmas_f, data.z[:, k + 1, None], hx_batched, R_ALT, weights
        )
        eig_prior = assert_positive_definite(P_prior, f"prior, step {k}")
        eig_post = assert_positive_definite(P, f"posterior, step {k}")
        for key, value in zip(
            out,
            (x_prior, P_prior, x, P, y, S, np.minimum(eig_prior, eig_post)),
            strict=True,
        ):
            out[key].append(value)
    return {key: np.array(value) for key, value in out.items()}


def run_filterpy(
    data: Data, settings: tuple[float, float, float], classic: bool = False, q_alt=0.0
) -> dict:
    """filterpy's UKF step by step on trial 0 of ``data``; histories shaped (N_STEPS, 1, ...).

    ``classic=True`` replays filterpy 1.4.5's predict (no redraw of the sigma points).
    """
    kalman = pytest.importorskip("filterpy.kalman")
    ut = kalman.unscented_transform

    class Classic145(kalman.UnscentedKalmanFilter):
        def predict(self, dt=None, UT=None, fx=None, **fx_args):  # filterpy 1.4.5 verbatim
            if dt is None:
                dt = self._dt
            if UT is None:
                UT = ut
            self.compute_process_sigmas(dt, fx, **fx_args)
            self.x, self.P = UT(
                self.sigmas_f, self.Wm, self.Wc, self.Q, self.x_mean, self.residual_x
            )
            self.x_prior = np.copy(self.x)
            self.P_prior = np.copy(self.P)

    alpha, beta, kappa = settings
    points = kalman.MerweScaledSigmaPoints(4, alpha=alpha, beta=beta, kappa=kappa)
    cls = Classic145 if classic else kalman.UnscentedKalmanFilter
    ukf = cls(dim_x=4, dim_z=1, dt=DT, hx=hx_single, fx=fx_single, points=points)
    ukf.x = data.x0[0].copy()
    ukf.P = P0.copy()
    ukf.R = R_ALT.copy()
    out = {k: [] for k in ("x_prior", "P_prior", "x", "P", "y", "S")}
    for k in range(N_STEPS):
        ukf.Q = process_noise(ukf.x, DT, q_alt)
        ukf.predict(omega=data.gyro[0, k], f=data.accel[0, k])
        ukf.update(data.z[0, k + 1 : k + 2])
        for key, value in zip(
            out, (ukf.x_prior, ukf.P_prior, ukf.x, ukf.P, ukf.y, ukf.S), strict=True
        ):
            out[key].append(np.array(value, dtype=float)[None])
    return {key: np.array(value) for key, value in out.items()}


def max_abs_diff(a: dict, b: dict) -> dict:
    return {key: float(np.max(np.abs(a[key] - b[key]))) for key in b}


@pytest.fixture(scope="module")
def single_data() -> Data:
    return make_data(1, seed=20240611)


@pytest.fixture(scope="module")
def batch_data() -> Data:
    return make_data(5, seed=7)


# --- 1, 2: single run agrees with filterpy 2.0.0 ---


@pytest.mark.parametrize("settings", SETTINGS, ids=lambda s: "alpha={},beta={},kappa={}".format(*s))
def test_single_run_matches_filterpy(single_data: Data, settings: tuple) -> None:
    ours = run_batched(single_data, MerweWeights(4, *settings))
    ref = run_filterpy(single_data, settings)
    diffs = max_abs_diff(ours, ref)
    print(f"max |ours - filterpy| for {settings}: {diffs}")
    for key in ref:
        np.testing.assert_allclose(ours[key], ref[key], atol=1e-9, rtol=0, err_msg=key)
    # the run is not trivial: the filter moved away from its start and tracked the altitude
    assert np.max(np.abs(ours["x"][:, 0, 3] - single_data.x0[0, 3])) > 5.0
    assert np.max(np.abs(ours["x"][-1, 0, 3] - single_data.truth[-1, 3])) < 5.0


def test_sensitive_alpha_agrees_to_filterpy_round_off(single_data: Data) -> None:
    ours = run_batched(single_data, MerweWeights(4, *SENSITIVE))
    ref = run_filterpy(single_data, SENSITIVE)
    print(f"max |ours - filterpy| for {SENSITIVE}: {max_abs_diff(ours, ref)}")
    for key in ("x_prior", "x", "y"):
        np.testing.assert_allclose(ours[key], ref[key], atol=1e-6, rtol=0, err_msg=key)
    for key in ("P_prior", "P", "S"):
        np.testing.assert_allclose(ours[key], ref[key], atol=1e-9, rtol=0, err_msg=key)


def test_no_redraw_matches_filterpy_145_predict(single_data: Data) -> None:
    # With the model's Q the 1.4.5/2.0.0 difference is only ~1e-12 (Q has a 1e-12 altitude
    # entry and no altitude coupling, and hx is linear), so give the altitude process noise.
    settings, q_alt = (0.5, 2.0, 0.0), 1e-2
    weights = MerweWeights(4, *settings)
    ours = run_batched(single_data, weights, redraw_sigmas=False, q_alt=q_alt)
    ref = run_filterpy(single_data, settings, classic=True, q_alt=q_alt)
    for key in ref:
        np.testing.assert_allclose(ours[key], ref[key], atol=1e-9, rtol=0, err_msg=key)
    # the 2.0.0 redraw is a real difference: it puts Q into S and the cross-covariance
    redrawn = run_batched(single_data, weights, q_alt=q_alt)
    assert np.max(np.abs(redrawn["S"] - ours["S"])) > 1e-3


# --- 3: batched run equals single runs ---


def test_batched_trials_equal_single_runs(batch_data: Data) -> None:
    weights = MerweWeights(4, 0.5, 2.0, 0.0)
    batched = run_batched(batch_data, weights)
    for i in range(batch_data.x0.shape[0]):
        single = run_batched(batch_data.trial(i), weights)
        for key in ("x", "P", "x_prior", "P_prior", "y", "S"):
            np.testing.assert_allclose(
                batched[key][:, i], single[key][:, 0], atol=1e-12, rtol=0, err_msg=f"{key} {i}"
            )
    # different noise, different estimates
    assert np.ptp(batched["x"][-1, :, 3]) > 1e-3


def test_per_trial_noise_covariances_broadcast(batch_data: Data) -> None:
    weights = MerweWeights(4, 1.0, 2.0, 1.0)
    x = batch_data.x0
    P = np.broadcast_to(P0, (5, 4, 4))
    Q = process_noise(x, DT)
    args = {"omega": batch_data.gyro[:, 0], "f": batch_data.accel[:, 0]}
    shared = predict(x, P, fx_batched, Q[0], DT, weights, **args)
    per_trial = predict(x, P, fx_batched, np.broadcast_to(Q[0], Q.shape), DT, weights, **args)
    for a, b in zip(shared, per_trial, strict=True):
        np.testing.assert_array_equal(a, b)
    R = np.broadcast_to(R_ALT, (5, 1, 1))
    z = batch_data.z[:, 1, None]
    post_shared = update(*shared, z, hx_batched, R_ALT, weights)
    post_trial = update(*shared, z, hx_batched, R, weights)
    for a, b in zip(post_shared, post_trial, strict=True):
        np.testing.assert_array_equal(a, b)


# --- 4: positive definiteness and input errors ---


def test_covariance_stays_positive_definite(batch_data: Data) -> None:
    for settings in SETTINGS[:2]:
        result = run_batched(batch_data, MerweWeights(4, *settings))
        assert np.all(result["min_eig"] > 0.0)
        assert np.all(np.isfinite(result["x"]))


def test_assert_positive_definite_names_trial() -> None:
    P = np.broadcast_to(np.eye(3), (4, 3, 3)).copy()
    P[2] = np.diag([1.0, -0.5, 2.0])
    with pytest.raises(ValueError, match=r"^after update: .*trial indices \[2\]"):
        assert_positive_definite(P, "after update")
    P[0, 0, 0] = np.nan
    with pytest.raises(NotPositiveDefiniteError) as info:
        assert_positive_definite(P, "after update")
    assert info.value.trials == (0, 2)
    np.testing.assert_array_equal(assert_positive_definite(P[[1, 3]], "ok"), [1.0, 1.0])


def test_sigma_points_reports_failing_trials() -> None:
    weights = MerweWeights(3, 0.5, 2.0, 0.0)
    P = np.broadcast_to(np.eye(3), (5, 3, 3)).copy()
    P[1] = [[1.0, 2.0, 0.0], [2.0, 1.0, 0.0], [0.0, 0.0, 1.0]]  # eigenvalues 3, 1, -1
    P[4, 2, 2] = 0.0
    with pytest.raises(np.linalg.LinAlgError, match=r"trial indices \[1, 4\]") as info:
        sigma_points(np.zeros((5, 3)), P, weights)
    assert isinstance(info.value, ValueError)
    assert info.value.trials == (1, 4)


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        ({"n": 4, "alpha": 0.0}, r"alpha must be in \(0, 1\], got 0\.0"),
        ({"n": 4, "alpha": 1.5}, r"alpha must be in \(0, 1\]"),
        ({"n": 0, "alpha": 0.5}, r"n \(state dimension\) must be an integer >= 1, got 0"),
        ({"n": 2.0, "alpha": 0.5}, r"n \(state dimension\) must be an integer"),
        ({"n": 4, "alpha": 0.5, "kappa": -4.0}, r"lam \+ n .* must be > 0"),
        ({"n": 4, "alpha": 0.5, "beta": np.nan}, r"beta must be finite"),
    ],
)
def test_merwe_weights_validation(kwargs: dict, message: str) -> None:
    with pytest.raises(ValueError, match=message):
        MerweWeights(**kwargs)


# --- 5: weights and sigma-point math, independent of filterpy ---


@pytest.mark.parametrize("settings", [(0.5, 2.0, 0.0), (1.0, 2.0, 1.0), (0.3, 0.0, -1.0)])
def test_unscented_transform_of_identity_recovers_mean_and_cov(settings: tuple) -> None:
    n, N = 4, 6
    weights = MerweWeights(n, *settings)
    assert weights.Wm.shape == weights.Wc.shape == (2 * n + 1,)
    assert abs(weights.Wm.sum() - 1.0) < 1e-12
    assert abs(weights.Wc.sum() - (2.0 - settings[0] ** 2 + settings[1])) < 1e-12
    rng = np.random.default_rng(3)
    A = rng.standard_normal((N, n, n))
    P = A @ np.swapaxes(A, -1, -2) + 0.1 * np.eye(n)
    x = rng.standard_normal((N, n)) * 10.0
    sigmas = sigma_points(x, P, weights)
    assert sigmas.shape == (N, 2 * n + 1, n)
    np.testing.assert_array_equal(sigmas[:, 0], x)
    mean, cov = unscented_transform(sigmas, weights)
    np.testing.assert_allclose(mean, x, atol=1e-12, rtol=0)
    np.testing.assert_allclose(cov, P, atol=1e-12, rtol=0)
    noise = np.diag([1.0, 2.0, 3.0, 4.0])
    _, cov_noise = unscented_transform(sigmas, weights, noise)
    np.testing.assert_allclose(cov_noise, P + noise, atol=1e-12, rtol=0)


def test_weights_and_sigma_points_equal_filterpy() -> None:
    kalman = pytest.importorskip("filterpy.kalman")
    rng = np.random.default_rng(11)
    A = rng.standard_normal((4, 4))
    P = A @ A.T + np.eye(4)
    x = rng.standard_normal(4)
    for settings in [*SETTINGS, SENSITIVE]:
        ours = MerweWeights(4, *settings)
        ref = kalman.MerweScaledSigmaPoints(4, *settings)
        np.testing.assert_array_equal(ours.Wm, ref.Wm)
        np.testing.assert_array_equal(ours.Wc, ref.Wc)
        np.testing.assert_allclose(
            sigma_points(x[None], P[None], ours)[0], ref.sigma_points(x, P), atol=1e-13, rtol=0
        )
