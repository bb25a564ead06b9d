"""Compiled loops of the filters on the third DCM row c: the paper's linear KF (eqs. 26-33,
:mod:`linear_kf`) and the PI complementary filter (:mod:`complementary`), one run at a time.

Same algorithm, operation for operation, as the numpy code (the reference; tests compare
to 1e-9), with the generated formulas of :mod:`jit`. The linear KF's F of eq. 30 is built
from the gamma-free parts of :class:`model.ChunkDiscretisation`, computed here per run and
step (:func:`chunk_terms`, once for the filter variants) by the very operations of the numpy
class, so they are the same numbers bit for bit (tests check it; the products of ``w @ w``
are fused multiply-adds in k order, as OpenBLAS's dgemm computes them): no per-chunk numpy
arrays (they cost ~1x the kernel). A step whose |k gamma dt| exceeds ``A_DT_MAX`` (where
the numpy code switches to the exact series) is flagged and the caller reruns the block in
numpy.
"""

from __future__ import annotations

import math

import numpy as np

from pipeline.altimeter_attitude import jit

__all__ = ["chunk_order", "chunk_terms", "complementary_runs", "linear_kf_chunk"]


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


@jit.njit
def chunk_terms(gyro, accel, i, step, basis, coef, order, dt, w, w2, v, pw, terms):
    """The gamma-free parts of F of run i's IMU step by the very operations of
    :class:`model.ChunkDiscretisation` (series of ``order`` terms): ``terms[0]`` its
    ``exp_w``, ``terms[1, j]`` its ``f_psi[j]``, ``terms[2, j]`` its ``f_xi[j]``; returns
    theta^2 = -trace((W dt)^2) / 2. Work arrays: ``w`` = W dt and ``w2`` = (W dt)^2 (3, 3),
    ``v`` (3, 3) the rows f, f^T W dt, f^T (W dt)^2, ``pw`` the powers of -theta^2.

    W and f: eq. 26's A at gamma = 0 from the generated matrix's linear ``basis``
    (model.a_blocks); einsum sums from +0, np.trace left to right, and ``w @ w`` is
    OpenBLAS's dgemm: fused multiply-adds in k order (jit.fma)."""
    for r in range(3):
        for s in range(3):
            t = 0.0
            for c in range(3):
                t += gyro[i, step, c] * basis[c, r, s]
            w[r, s] = t * dt
        t = 0.0
        for c in range(3):
            t += accel[i, step, c] * basis[3 + c, 3, r]
        v[0, r] = t
    for r in range(3):
        for s in range(3):
            t = jit.fma(w[r, 0], w[0, s], 0.0)
            t = jit.fma(w[r, 1], w[1, s], t)
            w2[r, s] = jit.fma(w[r, 2], w[2, s], t)
    t2 = -0.5 * (w2[0, 0] + w2[1, 1] + w2[2, 2])
    pw[0] = 1.0
    for q in range(order // 2 + 1):
        pw[q + 1] = pw[q] * -t2
    for s in range(3):
        v[1, s] = 0.0 + v[0, 0] * w[0, s] + v[0, 1] * w[1, s] + v[0, 2] * w[2, s]
        v[2, s] = 0.0 + v[0, 0] * w2[0, s] + v[0, 1] * w2[1, s] + v[0, 2] * w2[2, s]
    for row in range(7):  # c0 + A1 (W dt) + A2 (W dt)^2 (ChunkDiscretisation.collapse)
        a1 = 0.0
        for q in range(1, order + 1, 2):
            a1 += coef[row, q] * pw[(q - 1) // 2]
        a2 = 0.0
        for q in range(2, order + 1, 2):
            a2 += coef[row, q] * pw[(q - 2) // 2]
        c0 = coef[row, 0]
        if row == 0:
            for r in range(3):
                for s in range(3):
                    terms[0, r, s] = c0 * (1.0 if r == s else 0.0) + a1 * w[r, s] + a2 * w2[r, s]
        else:  # f^T (c0 I + A1 W dt + A2 (W dt)^2)
            for r in range(3):
                u = c0 * v[0, r] + a1 * v[1, r] + a2 * v[2, r]
                terms[1 + (row - 1) // 3, (row - 1) % 3, r] = u
    return t2


@jit.njit
def chunk_order(gyro, accel, c0, c1, basis, coef, dt, tol, w, w2, v, pw, terms):
    """ChunkDiscretisation's series order for steps c0 .. c1 - 1 of every run, from the
    largest rotation per step theta = |omega| dt; (order, theta_max)."""
    t2max, nan = 0.0, False
    lowest = np.int64(2)  # the shortest series (an int64, not a literal: one specialisation)
    for i in range(gyro.shape[0]):
        for step in range(c0, c1):
            t2 = chunk_terms(gyro, accel, i, step, basis, coef, lowest, dt, w, w2, v, pw, terms)
            if math.isnan(t2):
                nan = True
            elif t2 > t2max:
                t2max = t2
    theta_max = math.nan if nan else math.sqrt(t2max)
    order, term = 2, math.pow(theta_max, 3.0) / 6.0
    while term > tol and order < coef.shape[1] - 1:  # model.SERIES_ORDER_MAX
        order += 1
        term *= theta_max / (order + 1)
    return order, theta_max


@jit.kernel
def linear_kf_chunk(
    x, P, gyro, accel, c0, c1, basis, coef, tol, vertical, a43, L, g, k, dt, gc, q_diag, R,
    alt, use_gamma, use_update, a_dt_max, cs, var,
):  # fmt: skip
    """Advance the linear KF (eq. 31) of every run over the steps c0 .. c1 - 1 in place.

    ``x`` (M, 5), ``P`` (M, 5, 5) for M = V N (variant v of run i at v N + i), ``gyro``,
    ``accel`` (N, T, 3); F of eq. 30 from the gamma-free parts of
    :class:`model.ChunkDiscretisation` (``basis``: model._INPUT_BASIS; ``coef``:
    model.series_coefficients), computed here per run and step, once for the V variants, with
    the very operations of the numpy class; ``gc`` (6, 5, 5) the G_ci of eq. 33, ``alt``
    (N, T + 1); writes c ``cs`` (M, T + 1, 3) and the roll/pitch variances ``var``
    (M, T + 1, 2) at steps c0 + 1 .. c1. Returns (status, theta_max): 0 done; 1 some
    |k gamma dt| > a_dt_max (the numpy code then uses the exact exponential); 2 a rotation
    per step theta_max > 0.5 (ChunkDiscretisation refuses it).
    """
    N, M = gyro.shape[0], x.shape[0]
    w, w2, v, terms = np.empty((3, 3)), np.empty((3, 3)), np.empty((3, 3)), np.empty((3, 3, 3))
    pw = np.empty(coef.shape[1] // 2 + 2)
    order, theta_max = chunk_order(gyro, accel, c0, c1, basis, coef, dt, tol, w, w2, v, pw, terms)
    if theta_max > 0.5:
        return 2, theta_max
    F = np.zeros((5, 5))
    G = np.empty((5, 6))
    FP = np.empty((5, 5))
    Pn = np.empty((5, 5))
    xn = np.empty(5)
    K = np.empty(5)
    for i in range(N):
        for step in range(c0, c1):
            chunk_terms(gyro, accel, i, step, basis, coef, order, dt, w, w2, v, pw, terms)
            z = alt[i, step + 1]
            for m in range(i, M, N):  # the variants of run i: one step of eq. 31
                xm, Pm = x[m], P[m]
                gamma = jit.normalisation_error(xm[0], xm[1], xm[2])  # eq. 15 at x_{k-1|k-1}
                a = k * gamma
                if abs(a) * dt > a_dt_max:
                    return 1, theta_max
                # F of eq. 30 (ChunkDiscretisation.transition)
                ea = math.exp(a * dt)
                a2 = 0.5 * a**2
                for r in range(3):
                    for s in range(3):
                        F[r, s] = ea * terms[0, r, s]
                    F[3, r] = terms[1, 0, r] + a * terms[1, 1, r] + a2 * terms[1, 2, r]
                    F[4, r] = a43 * (terms[2, 0, r] + a * terms[2, 1, r] + a2 * terms[2, 2, r])
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
    return 0, theta_max
