"""SciPy's DOP853 integrator (``solve_ivp(method="DOP853", t_eval=...)``) without importing
``scipy.integrate``.

Importing ``scipy.integrate`` costs ~0.6 s of CPU per process in this environment (its package
imports ``scipy.special``, ``scipy.optimize``, ``scipy.sparse`` and ``scipy.linalg`` for its
other solvers), more than half of what the stationary scenario's 24 h integration costs. This
module is the path ``solve_ivp`` takes for the platform and strapdown simulations, copied from
SciPy 1.17.1 (``scipy/integrate/_ivp``: ``ivp.py``, ``base.py``, ``common.py``, ``rk.py``;
BSD-3-Clause: Copyright (c) 2001-2002 Enthought, Inc., 2003 SciPy Developers) with the same
operations in the same order: explicit DOP853, no events, no ``max_step`` or ``first_step``,
values at ``t_eval`` from the step's dense output, forward in time. Its results, the
evaluation count included, are bit for bit those of ``scipy.integrate.solve_ivp``
(tests/platform_drift/test_dop853_platform_drift.py compares the two on the platform and
strapdown systems and on a textbook problem).

>>> sol = solve_ivp(lambda t, y: -y, (0.0, 1.0), np.array([1.0]), np.array([0.0, 1.0]), 1e-3, 1e-6)
>>> sol.success, round(float(sol.y[0, -1]), 9), sol.nfev
(True, 0.367879444, 32)
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass
from warnings import warn

import numpy as np

from pipeline.platform_drift import dop853_coefficients as coef

__all__ = ["OdeResult", "solve_ivp"]

Rhs = Callable[[float, np.ndarray], np.ndarray]

EPS = np.finfo(float).eps
SAFETY = 0.9  # multiply steps computed from asymptotic behaviour of errors by this
MIN_FACTOR = 0.2  # minimum allowed decrease in a step size
MAX_FACTOR = 10  # maximum allowed increase in a step size
TOO_SMALL_STEP = "Required step size is less than spacing between numbers."
SUCCESS = "The solver successfully reached the end of the integration interval."


@dataclass(frozen=True)
class OdeResult:
    """What the callers read of ``solve_ivp``'s result: ``y`` is (n, len(t))."""

    t: np.ndarray
    y: np.ndarray
    nfev: int
    success: bool
    message: str


def _norm(x: np.ndarray) -> float:
    """RMS norm."""
    return np.linalg.norm(x) / x.size**0.5


def _select_initial_step(fun, t0, y0, t_bound, max_step, f0, direction, order, rtol, atol):
    """Empirically select a good initial step (Hairer, Norsett, Wanner, Sec. II.4)."""
    if y0.size == 0:
        return np.inf
    interval_length = abs(t_bound - t0)
    if interval_length == 0.0:
        return 0.0
    scale = atol + np.abs(y0) * rtol
    d0 = _norm(y0 / scale)
    d1 = _norm(f0 / scale)
    if d0 < 1e-5 or d1 < 1e-5:
        h0 = 1e-6
    else:
        h0 = 0.01 * d0 / d1
    h0 = min(h0, interval_length)  # t0 + h0 * direction does not pass t_bound
    y1 = y0 + h0 * direction * f0
    f1 = fun(t0 + h0 * direction, y1)
    d2 = _norm((f1 - f0) / scale) / h0
    if d1 <= 1e-15 and d2 <= 1e-15:
        h1 = max(1e-6, h0 * 1e-3)
    else:
        h1 = (0.01 / max(d1, d2)) ** (1 / (order + 1))
    return min(100 * h0, h1, interval_length, max_step)


def _rk_step(fun, t, y, f, h, A, B, C, K):
    """One Runge-Kutta step; the stages go into the rows of ``K``."""
    K[0] = f
    for s, (a, c) in enumerate(zip(A[1:], C[1:], strict=True), start=1):
        dy = np.dot(K[:s].T, a[:s]) * h
        K[s] = fun(t + c * h, y + dy)
    y_new = y + h * np.dot(K[:-1].T, B)
    f_new = fun(t + h, y_new)
    K[-1] = f_new
    return y_new, f_new


class _Dop853:
    """SciPy's ``DOP853`` solver (with the parts of ``OdeSolver`` and ``RungeKutta`` it uses)."""

    n_stages = coef.N_STAGES
    error_estimator_order = 7
    A = coef.A[:n_stages, :n_stages]
    B = coef.B
    C = coef.C[:n_stages]
    E3 = coef.E3
    E5 = coef.E5
    D = coef.D
    A_EXTRA = coef.A[n_stages + 1 :]
    C_EXTRA = coef.C[n_stages + 1 :]

    def __init__(self, fun: Rhs, t0: float, y0: np.ndarray, t_bound: float, rtol, atol):
        y0 = np.asarray(y0)
        if np.issubdtype(y0.dtype, np.complexfloating):
            raise ValueError("complex y0: not supported here")
        y0 = y0.astype(float, copy=False)
        if y0.ndim != 1:
            raise ValueError("`y0` must be 1-dimensional.")
        if not np.isfinite(y0).all():
            raise ValueError("All components of the initial state `y0` must be finite.")
        self._fun = fun
        self.t_old: float | None = None
        self.t = t0
        self.y = y0
        self.t_bound = t_bound
        self.direction = np.sign(t_bound - t0) if t_bound != t0 else 1
        self.n = self.y.size
        self.status = "running"
        self.nfev = 0
        self.y_old: np.ndarray | None = None
        self.max_step = np.inf
        self.rtol, self.atol = self._validate_tol(rtol, atol, self.n)
        self.f = self.fun(self.t, self.y)
        self.h_abs = _select_initial_step(
            self.fun,
            self.t,
            self.y,
            t_bound,
            self.max_step,
            self.f,
            self.direction,
            self.error_estimator_order,
            self.rtol,
            self.atol,
        )
        self.error_exponent = -1 / (self.error_estimator_order + 1)
        self.h_previous = None
        self.K_extended = np.empty((coef.N_STAGES_EXTENDED, self.n), dtype=self.y.dtype)
        self.K = self.K_extended[: self.n_stages + 1]

    @staticmethod
    def _validate_tol(rtol, atol, n):
        if np.any(rtol < 100 * EPS):
            warn(
                "At least one element of `rtol` is too small. "
                f"Setting `rtol = np.maximum(rtol, {100 * EPS})`.",
                stacklevel=3,
            )
            rtol = np.maximum(rtol, 100 * EPS)
        atol = np.asarray(atol)
        if atol.ndim > 0 and atol.shape != (n,):
            raise ValueError("`atol` has wrong shape.")
        if np.any(atol < 0):
            raise ValueError("`atol` must be positive.")
        return rtol, atol

    def fun(self, t, y):
        self.nfev += 1
        return np.asarray(self._fun(t, y), dtype=float)

    def step(self) -> str | None:
        if self.n == 0 or self.t == self.t_bound:
            self.t_old = self.t
            self.t = self.t_bound
            self.status = "finished"
            return None
        t = self.t
        success, message = self._step_impl()
        if not success:
            self.status = "failed"
        else:
            self.t_old = t
            if self.direction * (self.t - self.t_bound) >= 0:
                self.status = "finished"
        return message

    def _estimate_error_norm(self, K, h, scale):
        err5 = np.dot(K.T, self.E5) / scale
        err3 = np.dot(K.T, self.E3) / scale
        err5_norm_2 = np.linalg.norm(err5) ** 2
        err3_norm_2 = np.linalg.norm(err3) ** 2
        if err5_norm_2 == 0 and err3_norm_2 == 0:
            return 0.0
        denom = err5_norm_2 + 0.01 * err3_norm_2
        return np.abs(h) * err5_norm_2 / np.sqrt(denom * len(scale))

    def _step_impl(self):
        t = self.t
        y = self.y
        max_step = self.max_step
        rtol = self.rtol
        atol = self.atol
        min_step = 10 * np.abs(np.nextafter(t, self.direction * np.inf) - t)
        if self.h_abs > max_step:
            h_abs = max_step
        elif self.h_abs < min_step:
            h_abs = min_step
        else:
            h_abs = self.h_abs
        step_accepted = False
        step_rejected = False
        while not step_accepted:
            if h_abs < min_step:
                return False, TOO_SMALL_STEP
            h = h_abs * self.direction
            t_new = t + h
            if self.direction * (t_new - self.t_bound) > 0:
                t_new = self.t_bound
            h = t_new - t
            h_abs = np.abs(h)
            y_new, f_new = _rk_step(self.fun, t, y, self.f, h, self.A, self.B, self.C, self.K)
            scale = atol + np.maximum(np.abs(y), np.abs(y_new)) * rtol
            error_norm = self._estimate_error_norm(self.K, h, scale)
            if error_norm < 1:
                if error_norm == 0:
                    factor = MAX_FACTOR
                else:
                    factor = min(MAX_FACTOR, SAFETY * error_norm**self.error_exponent)
                if step_rejected:
                    factor = min(1, factor)
                h_abs *= factor
                step_accepted = True
            else:
                h_abs *= max(MIN_FACTOR, SAFETY * error_norm**self.error_exponent)
                step_rejected = True
        self.h_previous = h
        self.y_old = y
        self.t = t_new
        self.y = y_new
        self.h_abs = h_abs
        self.f = f_new
        return True, None

    def dense_output(self) -> Callable[[np.ndarray], np.ndarray]:
        """The interpolant over the last step, a function of a 1-D array of times."""
        if self.t == self.t_old:  # no integration: the constant state
            value = self.y

            def constant(t: np.ndarray) -> np.ndarray:
                ret = np.empty((value.shape[0], t.shape[0]))
                ret[:] = value[:, None]
                return ret

            return constant
        K = self.K_extended
        h = self.h_previous
        for s, (a, c) in enumerate(
            zip(self.A_EXTRA, self.C_EXTRA, strict=True), start=self.n_stages + 1
        ):
            dy = np.dot(K[:s].T, a[:s]) * h
            K[s] = self.fun(self.t_old + c * h, self.y_old + dy)
        F = np.empty((coef.INTERPOLATOR_POWER, self.n), dtype=self.y_old.dtype)
        f_old = K[0]
        delta_y = self.y - self.y_old
        F[0] = delta_y
        F[1] = h * f_old - delta_y
        F[2] = 2 * delta_y - h * (self.f + f_old)
        F[3:] = h * np.dot(self.D, K)
        t_old, step, y_old = self.t_old, self.t - self.t_old, self.y_old

        def dense(t: np.ndarray) -> np.ndarray:
            x = ((t - t_old) / step)[:, None]
            y = np.zeros((len(x), len(y_old)), dtype=y_old.dtype)
            for i, f in enumerate(reversed(F)):
                y += f
                if i % 2 == 0:
                    y *= x
                else:
                    y *= 1 - x
            y += y_old
            return y.T

        return dense


def solve_ivp(
    fun: Rhs, t_span: tuple[float, float], y0: np.ndarray, t_eval: np.ndarray, rtol, atol
) -> OdeResult:
    """``scipy.integrate.solve_ivp(fun, t_span, y0, method="DOP853", t_eval=t_eval,
    rtol=rtol, atol=atol)``, forward in time (``t_span[1] > t_span[0]``)."""
    t0, tf = map(float, t_span)
    if not tf > t0:
        raise ValueError("only forward integration (t_span[1] > t_span[0]) is supported")
    t_eval = np.asarray(t_eval)
    if t_eval.ndim != 1:
        raise ValueError("`t_eval` must be 1-dimensional.")
    if np.any(t_eval < min(t0, tf)) or np.any(t_eval > max(t0, tf)):
        raise ValueError("Values in `t_eval` are not within `t_span`.")
    if np.any(np.diff(t_eval) <= 0):
        raise ValueError("Values in `t_eval` are not properly sorted.")
    t_eval_i = 0
    solver = _Dop853(fun, t0, y0, tf, rtol, atol)
    ts: list[np.ndarray] = []
    ys: list[np.ndarray] = []
    status = None
    message: str | None = None
    while status is None:
        message = solver.step()
        if solver.status == "finished":
            status = 0
        elif solver.status == "failed":
            status = -1
            break
        # the value in t_eval equal to t is included
        t_eval_i_new = np.searchsorted(t_eval, solver.t, side="right")
        t_eval_step = t_eval[t_eval_i:t_eval_i_new]
        if t_eval_step.size > 0:
            ts.append(t_eval_step)
            ys.append(solver.dense_output()(t_eval_step))
            t_eval_i = t_eval_i_new
    return OdeResult(
        t=np.hstack(ts) if ts else np.empty(0),
        y=np.hstack(ys) if ys else np.empty((solver.n, 0)),
        nfev=solver.nfev,
        success=status >= 0,
        message=SUCCESS if status == 0 else str(message),
    )
