"""The paper's linear Kalman filter on x = [c1, c2, c3, V_d, h] (eqs. 26-33), vectorised.

Per IMU step (eq. 31), for all N runs at once:

    gamma  = 1 - c^T c                          (eq. 15, at xhat_{k-1|k-1})
    F, L   = exp(A dt), int exp(A s) ds B        (eq. 30; A from eq. 26 at the IMU outputs)
    xhat   = F xhat + L g                        (eq. 31, prediction)
    P      = F P F^T + G Q G^T + Gamma (Q kron P) Gamma^T,  G = dt C(xhat_{k-1|k-1})
    K      = P H^T (H P H^T + R)^-1             (with the predicted P: the printed
                                                 P_{k-1|k-1} is a typo, see the audit)
    xhat  += K (z - H xhat);  P = (I - K H) P, then symmetrised

Variants (stacked along the run axis, one pass): ``linear_kf``; ``linear_kf_no_gamma``
drops Gamma (Q kron P) Gamma^T (filter 2 of the issue); ``gyro_only`` never updates
(gyro propagation by eq. 14 with its covariance, filter 5).
"""

from __future__ import annotations

import numpy as np

from pipeline.altimeter_attitude import model
from pipeline.altimeter_attitude.estimates import Estimates, by_runs
from pipeline.altimeter_attitude.sensors import Inputs
from pipeline.generated import altimeter_attitude as gen

__all__ = ["VARIANTS", "initial_state", "run_linear_kf"]

CHUNK_TOL = 1e-17  # model.ChunkDiscretisation's default tol: where its series stop

RADIAL_SIGMA = 1e-6  # p0_radial = "none": sigma of c along itself in P0, dimensionless
P0_RADIAL = ("second_order", "none")


def initial_state(inputs: Inputs, p0_radial: str = "second_order") -> tuple[np.ndarray, np.ndarray]:
    """x0 (N, 5) and P0 (N, 5, 5) from the initial Euler estimates and their sigmas.

    The c block is J diag(sigma_phi^2, sigma_theta^2) J^T (J = dc/d(phi, theta), eq. 6) plus a
    variance along c itself (the unit-norm direction, which J does not reach):

    * ``second_order``: (sigma_phi^4 + sigma_theta^4) / 2, the variance of the second-order
      part of an attitude error on the unit sphere (a roll error d moves c by d along the
      tangent and by -d^2/2 along c; Var(d^2/2) = sigma^4/2);
    * ``none``: RADIAL_SIGMA^2, just enough for P0 to be positive definite.
    """
    if p0_radial not in P0_RADIAL:
        raise ValueError(f"p0_radial is {p0_radial!r}; allowed: {list(P0_RADIAL)}")
    sig = inputs.sigma0
    phi, theta = inputs.x0_euler[:, 0], inputs.x0_euler[:, 1]
    c0 = np.stack(gen.third_row_from_euler(phi, theta), -1)
    n = inputs.n_runs
    x0 = np.concatenate([c0, inputs.x0_euler[:, 2:4]], axis=1)
    var = sig[:, :2] ** 2
    P0 = np.zeros((n, 5, 5))
    P0[:, :3, :3] = model.third_row_cov_from_euler(phi, theta, var)
    if p0_radial == "none":
        radial_var = np.full(n, RADIAL_SIGMA**2)
    else:
        radial_var = (sig[:, 0] ** 4 + sig[:, 1] ** 4) / 2
    P0[:, :3, :3] += np.reshape(radial_var, (-1, 1, 1)) * c0[:, :, None] * c0[:, None, :]
    P0[:, 3, 3] = sig[:, 2] ** 2
    P0[:, 4, 4] = sig[:, 3] ** 2
    return x0, P0


VARIANTS = {
    "linear_kf": (True, True),  # (Gamma (Q kron P) Gamma^T term, altimeter update)
    "linear_kf_no_gamma": (False, True),
    "gyro_only": (True, False),
}


def run_linear_kf(
    inputs: Inputs,
    k: float,
    input_matrix: str = "exact",
    variants: tuple[str, ...] = ("linear_kf",),
    p0_radial: str = "second_order",
    chunk: int = 256,
    compiled: bool = True,
) -> list[Estimates]:
    """Run the filter variants (keys of VARIANTS) over all runs and steps.

    The variants see the same inputs and are stacked along the run axis, so they cost about
    one filter. Returns one :class:`Estimates` per variant (roll/pitch, sigmas, c, 1 - c^T c).
    ``compiled``: the step loop runs in :func:`kernels_c.linear_kf_chunk` (numba), unless a
    step needs the exact exponential (|k gamma dt| > ChunkDiscretisation.A_DT_MAX), when the
    numpy loop below (the reference) runs instead.
    """
    for v in variants:
        if v not in VARIANTS:
            raise ValueError(f"variant {v!r} unknown; allowed: {sorted(VARIANTS)}")
    dt, g = inputs.dt, inputs.g
    sens = inputs.sensors
    q_diag = np.array([sens.gyro_sigma**2] * 3 + [sens.accel_sigma**2] * 3)
    R = sens.altimeter_sigma**2
    x1, P1 = initial_state(inputs, p0_radial)
    n1, V = inputs.n_runs, len(variants)
    x, P = np.tile(x1, (V, 1)), np.tile(P1, (V, 1, 1))
    use_gamma = np.repeat([VARIANTS[v][0] for v in variants], n1).astype(float)
    use_update = np.repeat([VARIANTS[v][1] for v in variants], n1)
    N, T = x.shape[0], inputs.n_steps
    xs = np.empty((T + 1, N, 5))  # time-major while filling (contiguous writes)
    var = np.empty((T + 1, N, 2))  # roll/pitch variances J P_cc J^T (diagonal)

    def euler_var(x, P):  # x (..., 5), P (..., 5, 5): every leading axis at once
        cov = model.euler_cov_from_third_row(x[..., :3], P[..., :3, :3])
        return np.stack([cov[..., 0, 0], cov[..., 1, 1]], -1)

    xs[0], var[0] = x, euler_var(x, P)
    L = model.input_vector(dt, input_matrix)
    done = (
        _compiled_loop(inputs, k, x, P, L, use_gamma, use_update, chunk, var[0])
        if compiled
        else None
    )
    for c0 in range(0, 0 if done else T, chunk):  # the numpy loop (reference)
        c1 = min(T, c0 + chunk)
        gyro = np.tile(inputs.gyro[:, c0:c1], (V, 1, 1))
        accel = np.tile(inputs.accel[:, c0:c1], (V, 1, 1))
        # eq. 26 at gamma = 0 for the whole chunk; k gamma enters per step (eq. 30)
        disc = model.ChunkDiscretisation(*model.a_blocks(gyro, accel), dt)
        p_c = np.empty((c1 - c0, N, 5, 5))  # the chunk's P, for its variances in one pass
        for j, step in enumerate(range(c0, c1)):
            gamma = model.normalisation_error(x[:, :3])  # at xhat_{k-1|k-1}
            F = disc.transition(j, k * gamma)
            G = dt * model.noise_matrix_eq33(x)  # G(xhat_{k-1|k-1}) = dt C(x), eq. 30
            # eq. 31: F P F^T + G Q G^T + Gamma (Q kron P_{k-1|k-1}) Gamma^T
            P_new = F @ P @ np.swapaxes(F, -1, -2) + (G * q_diag) @ np.swapaxes(G, -1, -2)
            P_new += use_gamma[:, None, None] * model.gamma_term_closed(P, q_diag[0], q_diag[3], dt)
            x = np.einsum("nij,nj->ni", F, x) + L * g
            P = P_new
            z = inputs.altimeter[:, step + 1]
            if not np.isnan(z[0]):
                zz = np.tile(z, V)
                S = P[:, 4, 4] + R
                K = P[:, :, 4] / S[:, None] * use_update[:, None]
                x = x + K * (zz - x[:, 4])[:, None]
                P = P - K[:, :, None] * P[:, None, 4, :]  # (I - K H) P
            P = 0.5 * (P + np.swapaxes(P, -1, -2))
            xs[step + 1] = x
            p_c[j] = P
        var[c0 + 1 : c1 + 1] = euler_var(xs[c0 + 1 : c1 + 1], p_c)
    if done:
        c, var = done  # run-major already
    else:
        c = np.ascontiguousarray(np.swapaxes(xs[:, :, :3], 0, 1))
        var = np.swapaxes(var, 0, 1)
    phi, theta = by_runs(gen.euler_from_third_row, c[..., 0], c[..., 1], c[..., 2])
    norm_error = by_runs(model.normalisation_error, c)
    out = []
    for i, name in enumerate(variants):
        sl = slice(i * n1, (i + 1) * n1)
        out.append(
            Estimates(
                filter=name,
                roll=phi[sl],
                pitch=theta[sl],
                roll_sigma=np.sqrt(var[sl, :, 0]),
                pitch_sigma=np.sqrt(var[sl, :, 1]),
                c=c[sl],
                norm_error=norm_error[sl],
            )
        )
    return out


def _compiled_loop(
    inputs, k, x, P, L, use_gamma, use_update, chunk, var0
) -> tuple[np.ndarray, np.ndarray] | None:
    """The step loop of :func:`run_linear_kf` in numba, chunk by chunk: c (M, T + 1, 3) and
    the roll/pitch variances (M, T + 1, 2), run-major; None if a step needs the exact
    exponential (the numpy loop then runs instead)."""
    from pipeline.altimeter_attitude import kernels_c

    dt, g, sens = inputs.dt, inputs.g, inputs.sensors
    q_diag = np.array([sens.gyro_sigma**2] * 3 + [sens.accel_sigma**2] * 3)
    R = sens.altimeter_sigma**2
    x, P = x.copy(), P.copy()
    T, M = inputs.n_steps, x.shape[0]
    cs = np.empty((M, T + 1, 3))
    var = np.empty((M, T + 1, 2))
    cs[:, 0], var[:, 0] = x[:, :3], var0
    vertical = np.asarray(model.gen.vertical_transition(dt), dtype=float).reshape(2, 2)
    gc = np.ascontiguousarray(model.GAMMA_COLUMNS)
    alt = np.ascontiguousarray(inputs.altimeter)
    gyro = np.ascontiguousarray(inputs.gyro, dtype=float)
    accel = np.ascontiguousarray(inputs.accel, dtype=float)
    basis = np.ascontiguousarray(model._INPUT_BASIS)
    coef = model.series_coefficients(dt)
    gamma, update = use_gamma.astype(bool), np.asarray(use_update, dtype=bool)
    for c0 in range(0, T, chunk):
        status, theta_max = kernels_c.linear_kf_chunk(
            x, P, gyro, accel, c0, min(T, c0 + chunk), basis, coef, CHUNK_TOL, vertical,
            float(model.A_CONSTANT[4, 3]), np.asarray(L, dtype=float), g, float(k), dt, gc,
            q_diag, R, alt, gamma, update, model.ChunkDiscretisation.A_DT_MAX, cs, var,
        )  # fmt: skip
        if status == 2:
            model.ChunkDiscretisation.check_rotation(theta_max)
        if status:
            return None
    return cs, var
