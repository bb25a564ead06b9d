"""Compiled loops of the Euler-angle UKF and EKF (:mod:`euler_filters`), one run at a time.

Each kernel runs the same algorithm, operation for operation, as the batched numpy code of
:mod:`pipeline.altimeter_attitude.ukf` / :func:`euler_filters.run_ekf` (which stay the
reference; tests compare the two to 1e-9), with the generated formulas of :mod:`jit`:

    UKF (filterpy 2.0.0, Van der Merwe points):  X = [x, x + L_k, x - L_k],  L L^T = (lam + n) P
        X_f = RK4(X),  x^- = sum Wm X_f,  P^- = sum Wc (X_f - x^-)(.)^T + Q,  symmetrised
        X = points(x^-, P^-);  z^ = sum Wm X_h,  S = sum Wc (X_h - z^)^2 + R,
        K = P_xz / S,  x = x^- + K (z - z^),  P = P^- - K S K^T,  symmetrised
    EKF:  F = I + dt J(x),  x^- = RK4(x),  P^- = F P F^T + Q,  Joseph-form update

The UKF integrates 5 of its 9 sigma points in full: the 4 points of the lower Cholesky
factor's V_d and h columns have the centre point's roll and pitch, and the model's roll,
pitch and V_d rates depend on roll and pitch only (dh/dt = -V_d), so they take the centre
point's RK4 stages (the same numbers, bit for bit; a test checks it against all 9 in full).
No kernel assigns slices (each such assignment compiles numba's generic broadcasting code:
~6 of the ~17 CPU-s the kernels took to compile) or allocates inside its loops.

A run whose covariance cannot be factored (Cholesky) is flagged; the caller then reruns the
block with the numpy code, which raises :class:`ukf.NotPositiveDefiniteError` naming it.
"""

from __future__ import annotations

import math

import numpy as np

from pipeline.altimeter_attitude import jit

__all__ = ["ukf_runs", "ekf_runs"]


@jit.njit
def _rk4_point(X, j, dt, w0, w1, w2, f0, f1, f2, g, Xf):
    """One RK4 step of the Euler model (euler_filters.rk4_step) of the state ``X[j]`` (4,)
    into ``Xf[j]``, the IMU outputs held (as scalars); returns the stages' V_d rates (what
    :func:`_rk4_shared` takes)."""
    x0, x1, x2, x3 = X[j, 0], X[j, 1], X[j, 2], X[j, 3]
    k1 = jit.euler_model_rhs(x0, x1, x2, x3, w0, w1, w2, f0, f1, f2, g)
    h = 0.5 * dt
    k2 = jit.euler_model_rhs(
        x0 + h * k1[0], x1 + h * k1[1], x2 + h * k1[2], x3 + h * k1[3],
        w0, w1, w2, f0, f1, f2, g,
    )  # fmt: skip
    k3 = jit.euler_model_rhs(
        x0 + h * k2[0], x1 + h * k2[1], x2 + h * k2[2], x3 + h * k2[3],
        w0, w1, w2, f0, f1, f2, g,
    )  # fmt: skip
    k4 = jit.euler_model_rhs(
        x0 + dt * k3[0], x1 + dt * k3[1], x2 + dt * k3[2], x3 + dt * k3[3],
        w0, w1, w2, f0, f1, f2, g,
    )  # fmt: skip
    c = dt / 6.0
    Xf[j, 0] = x0 + c * (k1[0] + 2 * k2[0] + 2 * k3[0] + k4[0])
    Xf[j, 1] = x1 + c * (k1[1] + 2 * k2[1] + 2 * k3[1] + k4[1])
    Xf[j, 2] = x2 + c * (k1[2] + 2 * k2[2] + 2 * k3[2] + k4[2])
    Xf[j, 3] = x3 + c * (k1[3] + 2 * k2[3] + 2 * k3[3] + k4[3])
    return k1[2], k2[2], k3[2], k4[2]


@jit.njit
def _process_noise(phi, theta, dt, gyro_var, accel_var, q_floor, Q):
    """Q = dt^2 J Sigma J^T (generated euler_process_noise at roll ``phi`` and pitch
    ``theta``) + q_floor I, into Q (4, 4)."""
    q = jit.euler_process_noise(phi, theta, dt, gyro_var, accel_var)
    for a in range(4):
        for b in range(4):
            Q[a, b] = q[4 * a + b]
        Q[a, a] += q_floor


@jit.njit
def _cholesky(A, scale, L):
    """Lower Cholesky factor of scale * A (4, 4) into L; False if not positive definite (the
    size a literal, so the compiled loops are unrolled)."""
    n = 4
    for j in range(n):
        s = scale * A[j, j]
        for k in range(j):
            s -= L[j, k] * L[j, k]
        if not s > 0.0 or not math.isfinite(s):
            return False
        d = math.sqrt(s)
        L[j, j] = d
        for i in range(j + 1, n):
            t = scale * A[i, j]
            for k in range(j):
                t -= L[i, k] * L[j, k]
            L[i, j] = t / d
        for i in range(j):
            L[i, j] = 0.0
    return True


@jit.njit
def _sigma_points(x, P, scale, L, X):
    """X (2n+1, n) = [x, x + L[:, k], x - L[:, k]] (ukf.sigma_points); False if P is not PD."""
    n = 4
    if not _cholesky(P, scale, L):
        return False
    for a in range(n):
        X[0, a] = x[a]
        for k in range(n):
            X[1 + k, a] = x[a] + L[a, k]
            X[1 + n + k, a] = x[a] - L[a, k]
    return True


@jit.njit
def _symmetrize(P):
    n = 4
    for a in range(n):
        for b in range(a + 1, n):
            m = 0.5 * (P[a, b] + P[b, a])
            P[a, b] = m
            P[b, a] = m


@jit.njit
def _rk4_shared(x2, x3, dt, k12, k22, k32, k42):
    """V_d and h after the RK4 step of :func:`_rk4_point` for a state whose roll and pitch (bit for
    bit) are those of a point already propagated: d[phi, theta, V_d]/dt depend on roll and
    pitch only and dh/dt = -V_d (euler_model_rhs; tests check it), so the stages' roll,
    pitch and V_d rates ``k12``..``k42`` are that point's and only the h rates are this
    state's. The same operations as :func:`_rk4_point`, in the same order."""
    h = 0.5 * dt
    c = dt / 6.0
    out2 = x2 + c * (k12 + 2 * k22 + 2 * k32 + k42)
    out3 = x3 + c * (-x2 + 2 * -(x2 + h * k12) + 2 * -(x2 + h * k22) + -(x2 + dt * k32))
    return out2, out3


@jit.njit
def _same_bits(a, b):
    """a and b are the same float (sign of zero included)."""
    return a == b and math.copysign(1.0, a) == math.copysign(1.0, b)


@jit.kernel
def ukf_runs(gyro, accel, alt, x0, P0, wm, wc, scale, dt, g, gyro_var, accel_var, R, q_floor):
    """The UKF over runs (N, T): (states (N, T+1, 4), roll/pitch variances (N, T+1, 2),
    failed (N,) bool: a covariance that Cholesky could not factor).

    The sigma points whose roll and pitch are the centre point's (those of the V_d and h
    columns of the lower Cholesky factor, whose roll and pitch entries are 0) share its RK4
    stages (:func:`_rk4_shared`): 5 of the 9 points are integrated in full, the same numbers
    as integrating all 9.

    Where a step's time goes (this 2-core AMD EPYC, ~0.89 us per step and run): ~0.54 us
    the RK4 of the 5 points, 60 libm calls (sincos of roll, tan and sincos of pitch per
    stage; perf: ~58 % of the kernel in glibc's __sincos_fma and __tan_fma), already at
    their throughput (~9 ns a call; ~18 ns in a dependent chain), so running the points
    stage by stage or several runs side by side in lanes did not help (measured: 0 % and
    +8 %); ~0.35 us the rest (two Cholesky factorisations, the weighted sums, the update).
    The deviations X_f - x^- and their Wc-weighted copies are formed once per step, not once
    per covariance entry (~2 %: the same operations on the same numbers, bit for bit)."""
    N, T = gyro.shape[0], gyro.shape[1]
    n, S = 4, 9
    xs = np.empty((N, T + 1, 4))
    var = np.empty((N, T + 1, 2))
    failed = np.zeros(N, dtype=np.bool_)
    L = np.zeros((n, n))
    X = np.empty((S, n))
    Xf = np.empty((S, n))
    Q = np.empty((n, n))
    x = np.empty(n)
    P = np.empty((n, n))
    dz = np.empty(S)
    wdz = np.empty(S)
    D = np.empty((S, n))
    WD = np.empty((S, n))
    K = np.empty(n)
    SK = np.empty(n)
    centre = np.int64(0)  # (not a literal 0: the one specialisation of _rk4_point)
    for i in range(N):
        for a in range(n):
            x[a] = x0[i, a]
            xs[i, 0, a] = x[a]
            for b in range(n):
                P[a, b] = P0[i, a, b]
        var[i, 0, 0], var[i, 0, 1] = P[0, 0], P[1, 1]
        for k in range(T):
            w0, w1, w2 = gyro[i, k, 0], gyro[i, k, 1], gyro[i, k, 2]
            f0, f1, f2 = accel[i, k, 0], accel[i, k, 1], accel[i, k, 2]
            if not _sigma_points(x, P, scale, L, X):
                failed[i] = True
                break
            p0, p1 = X[0, 0], X[0, 1]  # the centre point: x, bit for bit
            _process_noise(p0, p1, dt, gyro_var, accel_var, q_floor, Q)
            # the centre point, keeping its stages' V_d rates for the points that share them
            v1, v2, v3, v4 = _rk4_point(X, centre, dt, w0, w1, w2, f0, f1, f2, g, Xf)
            f_0, f_1 = Xf[0, 0], Xf[0, 1]
            for j in range(1, S):
                if _same_bits(X[j, 0], p0) and _same_bits(X[j, 1], p1):
                    Xf[j, 0] = f_0
                    Xf[j, 1] = f_1
                    Xf[j, 2], Xf[j, 3] = _rk4_shared(X[j, 2], X[j, 3], dt, v1, v2, v3, v4)
                else:
                    _rk4_point(X, j, dt, w0, w1, w2, f0, f1, f2, g, Xf)
            for a in range(n):  # x^- = Wm X_f
                s = 0.0
                for j in range(S):
                    s += wm[j] * Xf[j, a]
                x[a] = s
            # P^- = (X_f - x^-)^T diag(Wc) (X_f - x^-) + Q; D = X_f - x^-, WD = diag(Wc) D
            # formed once (each product below is the same D[j, a] * (Wc[j] D[j, b]))
            for j in range(S):
                for a in range(n):
                    D[j, a] = Xf[j, a] - x[a]
                    WD[j, a] = wc[j] * D[j, a]
            for a in range(n):
                for b in range(n):
                    s = 0.0
                    for j in range(S):
                        s += D[j, a] * WD[j, b]
                    P[a, b] = s + Q[a, b]
            _symmetrize(P)
            if not _sigma_points(x, P, scale, L, X):  # redrawn from the prior (filterpy 2)
                failed[i] = True
                break
            z = alt[i, k + 1]
            if not math.isnan(z):
                zp = 0.0
                for j in range(S):
                    zp += wm[j] * X[j, 3]  # hx: the altitude h
                s_zz = 0.0
                for j in range(S):  # S = sum Wc dz^2 + R, dz = X_h - z^
                    dz[j] = X[j, 3] - zp
                    wdz[j] = wc[j] * dz[j]
                    s_zz += dz[j] * wdz[j]
                s_zz += R
                s_inv = 1.0 / s_zz
                y = z - zp
                for a in range(n):  # K = P_xz / S, P_xz = sum Wc (X - x^-) dz
                    pxz = 0.0
                    for j in range(S):
                        pxz += (X[j, a] - x[a]) * wdz[j]
                    K[a] = pxz * s_inv
                for a in range(n):
                    x[a] = x[a] + K[a] * y
                    SK[a] = s_zz * K[a]
                for a in range(n):  # P = P^- - K S K^T
                    for b in range(n):
                        P[a, b] = P[a, b] - K[a] * SK[b]
                _symmetrize(P)
            for a in range(n):
                xs[i, k + 1, a] = x[a]
            var[i, k + 1, 0], var[i, k + 1, 1] = P[0, 0], P[1, 1]
    return xs, var, failed


@jit.kernel
def ekf_runs(gyro, accel, alt, x0, P0, dt, g, gyro_var, accel_var, R, q_floor):
    """The EKF over runs (N, T): (states (N, T+1, 4), roll/pitch variances (N, T+1, 2))."""
    N, T = gyro.shape[0], gyro.shape[1]
    n = 4
    xs = np.empty((N, T + 1, 4))
    var = np.empty((N, T + 1, 2))
    Q = np.empty((n, n))
    F = np.empty((n, n))
    FP = np.empty((n, n))
    M = np.empty((n, n))
    xx = np.empty((1, n))  # the state, a row for _rk4_point
    xn = np.empty((1, n))
    x = xx[0]
    P = np.empty((n, n))
    K = np.empty(n)
    for i in range(N):
        for a in range(n):
            x[a] = x0[i, a]
            xs[i, 0, a] = x[a]
            for b in range(n):
                P[a, b] = P0[i, a, b]
        var[i, 0, 0], var[i, 0, 1] = P[0, 0], P[1, 1]
        for k in range(T):
            w0, w1, w2 = gyro[i, k, 0], gyro[i, k, 1], gyro[i, k, 2]
            f0, f1, f2 = accel[i, k, 0], accel[i, k, 1], accel[i, k, 2]
            _process_noise(x[0], x[1], dt, gyro_var, accel_var, q_floor, Q)
            J = jit.euler_state_jacobian(x[0], x[1], w0, w1, w2, f0, f1, f2)
            for a in range(n):
                for b in range(n):
                    F[a, b] = (1.0 if a == b else 0.0) + dt * J[4 * a + b]
            _rk4_point(xx, np.int64(0), dt, w0, w1, w2, f0, f1, f2, g, xn)
            for a in range(n):
                x[a] = xn[0, a]
            for a in range(n):  # P = F P F^T + Q
                for b in range(n):
                    s = 0.0
                    for c in range(n):
                        s += F[a, c] * P[c, b]
                    FP[a, b] = s
            for a in range(n):
                for b in range(n):
                    s = 0.0
                    for c in range(n):
                        s += FP[a, c] * F[b, c]
                    M[a, b] = s + Q[a, b]
            for a in range(n):
                for b in range(n):
                    P[a, b] = M[a, b]
            z = alt[i, k + 1]
            if not math.isnan(z):
                S = P[3, 3] + R
                for a in range(n):
                    K[a] = P[a, 3] / S
                y = z - x[3]
                for a in range(n):
                    x[a] = x[a] + K[a] * y
                # Joseph form: (I - K H) P (I - K H)^T + R K K^T, H = e_3^T
                for a in range(n):  # FP = (I - K H) P
                    for b in range(n):
                        FP[a, b] = P[a, b] - K[a] * P[3, b]
                for a in range(n):
                    for b in range(n):
                        M[a, b] = FP[a, b] - FP[a, 3] * K[b] + R * K[a] * K[b]
                for a in range(n):
                    for b in range(n):
                        P[a, b] = M[a, b]
            _symmetrize(P)
            for a in range(n):
                xs[i, k + 1, a] = x[a]
            var[i, k + 1, 0], var[i, k + 1, 1] = P[0, 0], P[1, 1]
    return xs, var
