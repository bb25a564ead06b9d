"""The conventional PI complementary filter of Fig. 1, and accelerometer levelling.

Continuous loop (the paper's eqs. 16, 22-23 are missing from the OCR; this is the loop whose
transfer function is eq. 18):

    c_m_dot = -omega_tilde x c_m + k_p e + k_i int e dt,   e = c_a - c_m,  c_a = -f/||f|| (17-b)

Discrete implementation per IMU step: rotate c_m by the gyro increment (exact for the held
rate: Rodrigues' formula of -omega dt), add dt (k_p e + k_i z), integrate z += dt e, and
renormalise c_m to unit length. Gains from eq. 20: k_i = omega_c^2, k_p = 2 xi omega_c.
The filter has no covariance, so its sigma is NaN.
"""

from __future__ import annotations

import numpy as np

from pipeline.altimeter_attitude import model
from pipeline.altimeter_attitude.estimates import Estimates, by_runs
from pipeline.altimeter_attitude.sensors import Inputs
from pipeline.generated import altimeter_attitude as gen

__all__ = ["rotate_third_row", "run_complementary", "run_accel_leveling"]


def rotate_third_row(c: np.ndarray, omega: np.ndarray, dt: float) -> np.ndarray:
    """Solution of c_dot = -omega x c over dt for omega held: rotation of c by -omega dt
    (the generated Rodrigues formula)."""
    angle_vec = -omega * dt
    angle = np.linalg.norm(angle_vec, axis=-1, keepdims=True)
    small = angle < 1e-12
    axis = np.where(small, 0.0, angle_vec / np.where(small, 1.0, angle))
    cos, sin = np.cos(angle[..., 0]), np.sin(angle[..., 0])
    k, cc = np.moveaxis(axis, -1, 0), np.moveaxis(c, -1, 0)
    return np.stack(gen.third_row_rotation(*k, *cc, cos, sin), axis=-1)


def _to_estimates(name: str, cs: np.ndarray) -> Estimates:
    phi, theta = by_runs(gen.euler_from_third_row, cs[..., 0], cs[..., 1], cs[..., 2])
    nan = np.full(phi.shape, np.nan)
    return Estimates(
        filter=name,
        roll=phi,
        pitch=theta,
        roll_sigma=nan,
        pitch_sigma=nan,
        c=cs,
        norm_error=by_runs(model.normalisation_error, cs),
    )


def run_complementary(
    inputs: Inputs, omega_c: float, xi: float, name: str = "complementary", compiled: bool = True
) -> Estimates:
    """Run the PI complementary filter (Fig. 1) over all runs (``compiled``: in
    :func:`kernels_c.complementary_runs`, numba; else the numpy loop below)."""
    k_i, k_p = gen.pi_gains(omega_c, xi)
    dt = inputs.dt
    phi0, theta0 = inputs.x0_euler[:, 0], inputs.x0_euler[:, 1]
    c = np.stack(gen.third_row_from_euler(phi0, theta0), -1)
    if compiled:
        from pipeline.altimeter_attitude import kernels_c

        cs = kernels_c.complementary_runs(
            np.ascontiguousarray(inputs.gyro, dtype=float),
            np.ascontiguousarray(inputs.accel, dtype=float),
            np.ascontiguousarray(c),
            dt,
            float(k_p),
            float(k_i),
        )
        return _to_estimates(name, cs)
    z = np.zeros_like(c)
    N, T = inputs.n_runs, inputs.n_steps
    cs = np.empty((T + 1, N, 3))  # time-major while filling
    cs[0] = c
    for step in range(T):
        f = inputs.accel[:, step]
        c_a = np.stack(gen.accel_third_row(f[:, 0], f[:, 1], f[:, 2]), -1)
        e = c_a - c
        c = rotate_third_row(c, inputs.gyro[:, step], dt) + dt * (k_p * e + k_i * z)
        z = z + dt * e
        c = c / np.linalg.norm(c, axis=-1, keepdims=True)
        cs[step + 1] = c
    return _to_estimates(name, np.ascontiguousarray(np.swapaxes(cs, 0, 1)))


def run_accel_leveling(inputs: Inputs, name: str = "accel_leveling") -> Estimates:
    """Roll/pitch from each accelerometer sample alone (eq. 17-b, eq. 11 with its sign fixed).

    The sample of step k is attributed to t_k+1 (the end of its interval); t_0 repeats it.
    """
    f = inputs.accel
    c_a = np.stack(gen.accel_third_row(f[..., 0], f[..., 1], f[..., 2]), -1)
    cs = np.concatenate([c_a[:, :1], c_a], axis=1)
    return _to_estimates(name, cs)
