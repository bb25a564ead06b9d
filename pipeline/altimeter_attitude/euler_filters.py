"""The comparison filters on the Euler-angle model: UKF (Sec. 6) and EKF, vectorised.

State [phi, theta, V_d, h]; model eqs. 4, 6, 24, 25 (generated ``euler_model_rhs``) driven
by the IMU outputs held over the step, integrated by one classical RK4 step. The sensor noise
enters the model through the outputs; it is handled as additive process noise
``Q_k = dt^2 J Sigma J^T`` with J = d(rhs)/d[n_w, n_a] at the current estimate (generated
``euler_noise_jacobian``) and Sigma = diag(sigma_g^2 I3, sigma_a^2 I3), plus Q_FLOOR I: the
same first-order noise model as the linear filter's G Q G^T with G = dt C(x). The altimeter
is z = h + v (eq. 27). The UKF is :mod:`pipeline.altimeter_attitude.ukf` (filterpy's
algorithm, Merwe scaled sigma points); the EKF linearises the RK4 step to first order
(F = I + dt d(rhs)/dx).
"""

from __future__ import annotations

import numpy as np

from pipeline.altimeter_attitude import ukf
from pipeline.altimeter_attitude.estimates import Estimates, by_runs
from pipeline.altimeter_attitude.sensors import Inputs
from pipeline.generated import altimeter_attitude as gen

__all__ = ["rk4_step", "process_noise", "run_ukf", "run_ekf", "Q_FLOOR"]

Q_FLOOR = 1e-12  # added to the process noise diagonal (keeps Q positive definite)


def _rhs(x: np.ndarray, gyro: tuple, accel: tuple, g: float) -> np.ndarray:
    out = gen.euler_model_rhs(x[..., 0], x[..., 1], x[..., 2], x[..., 3], *gyro, *accel, g)
    return np.stack(out, -1)


def rk4_step(x: np.ndarray, dt: float, gyro: np.ndarray, accel: np.ndarray, g: float) -> np.ndarray:
    """One RK4 step of the Euler model for states x (..., 4) and inputs broadcast to them."""
    gyro_c = tuple(np.moveaxis(np.asarray(gyro), -1, 0))
    accel_c = tuple(np.moveaxis(np.asarray(accel), -1, 0))
    k1 = _rhs(x, gyro_c, accel_c, g)
    k2 = _rhs(x + 0.5 * dt * k1, gyro_c, accel_c, g)
    k3 = _rhs(x + 0.5 * dt * k2, gyro_c, accel_c, g)
    k4 = _rhs(x + dt * k3, gyro_c, accel_c, g)
    return x + dt / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4)


def process_noise(x: np.ndarray, dt: float, gyro_sigma: float, accel_sigma: float) -> np.ndarray:
    """Q_k (N, 4, 4) = dt^2 J Sigma J^T + Q_FLOOR I at the estimates x (N, 4) (generated)."""
    q = gen.euler_process_noise(x[:, 0], x[:, 1], dt, gyro_sigma**2, accel_sigma**2)
    return np.stack(q, -1).reshape(-1, 4, 4) + Q_FLOOR * np.eye(4)


def _initial(inputs: Inputs) -> tuple[np.ndarray, np.ndarray]:
    x0 = inputs.x0_euler.copy()
    P0 = np.zeros((inputs.n_runs, 4, 4))
    P0[:, np.arange(4), np.arange(4)] = inputs.sigma0**2
    return x0, P0


def _estimates(name: str, xs: np.ndarray, Ps: np.ndarray) -> Estimates:
    c = np.stack(gen.third_row_from_euler(xs[..., 0], xs[..., 1]), -1)
    return Estimates(
        filter=name,
        roll=xs[..., 0],
        pitch=xs[..., 1],
        roll_sigma=np.sqrt(Ps[..., 0, 0]),
        pitch_sigma=np.sqrt(Ps[..., 1, 1]),
        c=c,
        norm_error=np.zeros(xs.shape[:2]),
    )


def _kernel_inputs(inputs: Inputs) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """gyro, accel, altimeter as C-contiguous float arrays (what the kernels take)."""
    return tuple(
        np.ascontiguousarray(a, dtype=float) for a in (inputs.gyro, inputs.accel, inputs.altimeter)
    )


def _third_row(phi: np.ndarray, theta: np.ndarray) -> np.ndarray:
    """c (..., 3) of eq. 6 from roll and pitch (the generated formula)."""
    return np.stack(gen.third_row_from_euler(phi, theta), -1)


def _estimates_var(name: str, xs: np.ndarray, var: np.ndarray, third_row: bool = True) -> Estimates:
    """Estimates from a kernel's states (N, T+1, 4) and roll/pitch variances (N, T+1, 2);
    ``third_row=False``: c is NaN (a read-only view, not computed)."""
    if third_row:
        c = by_runs(_third_row, xs[..., 0], xs[..., 1])
    else:
        c = np.broadcast_to(np.nan, (*xs.shape[:2], 3))
    return Estimates(
        filter=name,
        roll=xs[..., 0],
        pitch=xs[..., 1],
        roll_sigma=np.sqrt(var[..., 0]),
        pitch_sigma=np.sqrt(var[..., 1]),
        c=c,
        norm_error=np.zeros(xs.shape[:2]),
    )


def run_ukf(
    inputs: Inputs,
    alpha: float,
    beta: float,
    kappa: float,
    name: str = "ukf",
    compiled: bool = True,
    third_row: bool = True,
) -> Estimates:
    """The UKF over all runs and steps (sigma points redrawn after predict, as filterpy 2).

    ``compiled``: :func:`kernels_euler.ukf_runs` (numba, run by run); if a covariance cannot
    be factored there, the batched numpy loop below (the reference) reruns and names it.
    ``third_row=False``: the estimates' c is left NaN (for callers that read the angles and
    sigmas only: computing it costs ~0.1 CPU-s per 100 runs x 10,000 steps)."""
    weights = ukf.MerweWeights(n=4, alpha=alpha, beta=beta, kappa=kappa)
    dt, g, sens = inputs.dt, inputs.g, inputs.sensors
    x, P = _initial(inputs)
    if compiled:
        from pipeline.altimeter_attitude import kernels_euler

        xs_c, var_c, failed = kernels_euler.ukf_runs(
            *_kernel_inputs(inputs), x, P, np.array(weights.Wm), np.array(weights.Wc),
            weights.scale, dt, g, sens.gyro_sigma**2, sens.accel_sigma**2,
            sens.altimeter_sigma**2, Q_FLOOR,
        )  # fmt: skip
        if not failed.any():
            return _estimates_var(name, xs_c, var_c, third_row)
    R = np.array([[sens.altimeter_sigma**2]])
    N, T = inputs.n_runs, inputs.n_steps
    xs = np.empty((T + 1, N, 4))  # time-major while filling (contiguous writes)
    Ps = np.empty((T + 1, N, 2, 2))
    xs[0], Ps[0] = x, P[:, :2, :2]

    def fx(sig, dt_, gyro, accel):
        return rk4_step(sig, dt_, gyro[:, None, :], accel[:, None, :], g)

    def hx(sig):
        return sig[..., 3:4]

    for step in range(T):
        Q = process_noise(x, dt, sens.gyro_sigma, sens.accel_sigma)
        gyro, accel = inputs.gyro[:, step], inputs.accel[:, step]
        x, P, sig_f = ukf.predict(x, P, fx, Q, dt, weights, gyro=gyro, accel=accel)
        z = inputs.altimeter[:, step + 1]
        if not np.isnan(z[0]):
            x, P, _, _ = ukf.update(x, P, sig_f, z[:, None], hx, R, weights)
        xs[step + 1] = x
        Ps[step + 1] = P[:, :2, :2]
    return _estimates(name, np.swapaxes(xs, 0, 1), np.swapaxes(Ps, 0, 1))


def run_ekf(inputs: Inputs, name: str = "ekf", compiled: bool = True) -> Estimates:
    """An EKF on the same model (the paper reports that it diverges; no details given).

    ``compiled``: :func:`kernels_euler.ekf_runs` (numba); else the batched numpy loop."""
    dt, g, sens = inputs.dt, inputs.g, inputs.sensors
    R = sens.altimeter_sigma**2
    x, P = _initial(inputs)
    if compiled:
        from pipeline.altimeter_attitude import kernels_euler

        xs_c, var_c = kernels_euler.ekf_runs(
            *_kernel_inputs(inputs), x, P, dt, g, sens.gyro_sigma**2, sens.accel_sigma**2, R,
            Q_FLOOR,
        )  # fmt: skip
        return _estimates_var(name, xs_c, var_c)
    N, T = inputs.n_runs, inputs.n_steps
    xs = np.empty((T + 1, N, 4))  # time-major while filling (contiguous writes)
    Ps = np.empty((T + 1, N, 2, 2))
    xs[0], Ps[0] = x, P[:, :2, :2]
    eye = np.eye(4)
    for step in range(T):
        gyro, accel = inputs.gyro[:, step], inputs.accel[:, step]
        Q = process_noise(x, dt, sens.gyro_sigma, sens.accel_sigma)
        J = np.stack(
            gen.euler_state_jacobian(
                x[:, 0], x[:, 1], *np.moveaxis(gyro, -1, 0), *np.moveaxis(accel, -1, 0)
            ),
            -1,
        ).reshape(N, 4, 4)
        F = eye + dt * J
        x = rk4_step(x, dt, gyro, accel, g)
        P = F @ P @ np.swapaxes(F, -1, -2) + Q
        z = inputs.altimeter[:, step + 1]
        if not np.isnan(z[0]):
            S = P[:, 3, 3] + R
            K = P[:, :, 3] / S[:, None]
            x = x + K * (z - x[:, 3])[:, None]
            ikh = eye - K[:, :, None] * eye[3][None, None, :]
            P = ikh @ P @ np.swapaxes(ikh, -1, -2) + R * K[:, :, None] * K[:, None, :]
        P = 0.5 * (P + np.swapaxes(P, -1, -2))
        xs[step + 1] = x
        Ps[step + 1] = P[:, :2, :2]
    return _estimates(name, np.swapaxes(xs, 0, 1), np.swapaxes(Ps, 0, 1))
