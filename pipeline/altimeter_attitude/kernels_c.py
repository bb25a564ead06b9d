"""Compiled loops of the filters on the third DCM row c: the paper's linear KF (eqs. 26-33,
:mod:`linear_kf`) and the PI complementary filter (:mod:`complementary`), one run at a time.

Same algorithm, operation for operation, as the numpy code (the reference; tests compare
to 1e-9), with the generated formulas of :mod:`jit`. The linear KF's F of eq. 30 is built
from the gamma-free parts that :class:`model.ChunkDiscretisation` precomputes for a chunk of
steps (vectorised numpy); a step whose |k gamma dt| exceeds ``A_DT_MAX`` (where the numpy
code switches to the exact series) is flagged and the caller reruns the block in numpy.
"""

from __future__ import annotations

import math

import numpy as np

from pipeline.altimeter_attitude import jit

__all__ = ["complementary_runs", "linear_kf_chunk"]


@jit.kernel
def complementary_runs(gyro, accel, c0, dt, k_p, k_i):
    """PI complementary filter over runs (N, T): c (N, T+1, 3) (run_complementary):

    c_a = -f/|f| (eq. 17-b), e = c_a - c, c = R(-omega dt) c + dt (k_p e + k_i z),
    z += dt e, c /= |c|.
    """
    N, T = gyro.shape[0], gyro.shape[1]
    cs = np.empty((N, T + 1, 3))
    c = np.empty(3)
    z = np.empty(3)
    e = np.empty(3)
    for i in range(N):
        for a in range(3):
            c[a] = c0[i, a]
            z[a] = 0.0
            cs[i, 0, a] = c[a]
        for k in range(T):
            f = accel[i, k]
            ca = jit.accel_third_row(f[0], f[1], f[2])
            for a in range(3):
                e[a] = ca[a] - c[a]
            # rotation of c by -omega dt (rotate_third_row: Rodrigues, generated)
            v0, v1, v2 = -gyro[i, k, 0] * dt, -gyro[i, k, 1] * dt, -gyro[i, k, 2] * dt
            angle = math.sqrt(v0 * v0 + v1 * v1 + v2 * v2)
            if angle < 1e-12:
                k0, k1, k2 = 0.0, 0.0, 0.0
            else:
                k0, k1, k2 = v0 / angle, v1 / angle, v2 / angle
            r = jit.third_row_rotation(
                k0, k1, k2, c[0], c[1], c[2], math.cos(angle), math.sin(angle)
            )
            for a in range(3):
                c[a] = r[a] + dt * (k_p * e[a] + k_i * z[a])
            for a in range(3):
                z[a] = z[a] + dt * e[a]
            norm = math.sqrt(c[0] * c[0] + c[1] * c[1] + c[2] * c[2])
            for a in range(3):
                c[a] = c[a] / norm
                cs[i, k + 1, a] = c[a]
    return cs


@jit.kernel
def linear_kf_chunk(
    x, P, exp_w, f_psi, f_xi, vertical, a43, L, g, k, dt, gc, q_diag, R, alt,
    use_gamma, use_update, a_dt_max, c0, cs, var,
):  # fmt: skip
    """Advance the linear KF (eq. 31) of every run over the steps c0 .. c0 + C - 1 in place.

    ``x`` (M, 5), ``P`` (M, 5, 5) for M = V N (variant v of run i at v N + i); the chunk's
    ``exp_w`` (N, C, 3, 3), ``f_psi``/``f_xi`` (3, N, C, 3) (ChunkDiscretisation), ``gc``
    (6, 5, 5) the G_ci of eq. 33, ``alt`` (N, T + 1); writes c ``cs`` (M, T + 1, 3) and the
    roll/pitch variances ``var`` (M, T + 1, 2) at steps c0 + 1 .. Returns False (and stops) if
    some |k gamma dt| > a_dt_max (the numpy code then uses the exact exponential).
    """
    M, C = x.shape[0], exp_w.shape[1]
    N = exp_w.shape[0]
    F = np.zeros((5, 5))
    G = np.empty((5, 6))
    FP = np.empty((5, 5))
    Pn = np.empty((5, 5))
    xn = np.empty(5)
    K = np.empty(5)
    for m in range(M):
        i = m % N
        for j in range(C):
            step = c0 + j
            xm, Pm = x[m], P[m]
            gamma = jit.normalisation_error(xm[0], xm[1], xm[2])  # eq. 15 at x_{k-1|k-1}
            a = k * gamma
            if abs(a) * dt > a_dt_max:
                return False
            # F of eq. 30 (ChunkDiscretisation.transition)
            ea = math.exp(a * dt)
            a2 = 0.5 * a**2
            for r in range(3):
                for s in range(3):
                    F[r, s] = ea * exp_w[i, j, r, s]
                F[3, r] = f_psi[0, i, j, r] + a * f_psi[1, i, j, r] + a2 * f_psi[2, i, j, r]
                F[4, r] = a43 * (f_xi[0, i, j, r] + a * f_xi[1, i, j, r] + a2 * f_xi[2, i, j, r])
            for r in range(2):
                for s in range(2):
                    F[3 + r, 3 + s] = vertical[r, s]
            # G = dt C(x), C(x) e_c = G_cc x (eq. 33)
            for c in range(6):
                for r in range(5):
                    s_ = 0.0
                    for b in range(5):
                        s_ += xm[b] * gc[c, r, b]
                    G[r, c] = dt * s_
            # eq. 31: F P F^T + G Q G^T (+ Gamma (Q kron P) Gamma^T, closed form)
            for r in range(5):
                for s in range(5):
                    t = 0.0
                    for b in range(5):
                        t += F[r, b] * Pm[b, s]
                    FP[r, s] = t
            for r in range(5):
                for s in range(5):
                    t = 0.0
                    for b in range(5):
                        t += FP[r, b] * F[s, b]
                    u = 0.0
                    for c in range(6):
                        u += (G[r, c] * q_diag[c]) * G[s, c]
                    Pn[r, s] = t + u
            if use_gamma[m]:
                gt = jit.gamma_term_closed(
                    Pm[0, 0], Pm[0, 1], Pm[0, 2], Pm[1, 1], Pm[1, 2], Pm[2, 2],
                    q_diag[0], q_diag[3], dt,
                )  # fmt: skip
                for r in range(3):
                    for s in range(3):
                        Pn[r, s] += gt[3 * r + s]
                Pn[3, 3] += gt[9]
            for r in range(5):
                t = 0.0
                for b in range(5):
                    t += F[r, b] * xm[b]
                xn[r] = t + L[r] * g
            for r in range(5):
                xm[r] = xn[r]
                for s in range(5):
                    Pm[r, s] = Pn[r, s]
            z = alt[i, step + 1]
            if use_update[m] and not math.isnan(z):
                S = Pm[4, 4] + R
                for r in range(5):
                    K[r] = Pm[r, 4] / S
                y = z - xm[4]
                for r in range(5):
                    xm[r] = xm[r] + K[r] * y
                for r in range(5):  # (I - K H) P, H = e_5^T
                    for s in range(5):
                        Pn[r, s] = Pm[r, s] - K[r] * Pm[4, s]
                for r in range(5):
                    for s in range(5):
                        Pm[r, s] = Pn[r, s]
            for r in range(5):
                for s in range(r + 1, 5):
                    h = 0.5 * (Pm[r, s] + Pm[s, r])
                    Pm[r, s] = h
                    Pm[s, r] = h
            for r in range(3):
                cs[m, step + 1, r] = xm[r]
            # roll/pitch variances: diag(J P_cc J^T), J = d(phi, theta)/dc (generated)
            J = jit.euler_jacobian_third_row(xm[0], xm[1], xm[2])
            for r in range(2):
                t = 0.0
                for b in range(3):
                    u = 0.0
                    for c in range(3):
                        u += J[3 * r + c] * Pm[c, b]
                    t += u * J[3 * r + b]
                var[m, step + 1, r] = t
    return True
