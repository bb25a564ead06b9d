"""Batched unscented Kalman filter (Van der Merwe scaled sigma points), vectorised over trials.

One call of :func:`predict` / :func:`update` advances ``N`` independent Monte Carlo trials by
one step with no Python loop over trials or sigma points; the loop over time steps is the
caller's. The algorithm is, operation for operation, the one of filterpy 2.0.0's
``filterpy.kalman.UnscentedKalmanFilter`` with ``MerweScaledSigmaPoints`` (default
``np.subtract`` residuals, ``np.add`` state addition, Cholesky square root), so a single run
(``N = 1``) agrees with filterpy to round-off (the test suite checks 1e-9).

Conventions
-----------
* ``n`` state dimension, ``m`` measurement dimension, ``N`` trials, ``S = 2n + 1`` sigma points
  (called ``n_sigma`` in the code, since ``S`` is also the innovation covariance).
* Means are shaped ``(N, n)`` / ``(N, m)``, covariances ``(N, n, n)`` / ``(N, m, m)``, sigma
  points ``(N, S, n)``. Noise covariances ``Q`` and ``R`` may be shared, ``(n, n)`` / ``(m, m)``,
  or per trial, ``(N, n, n)`` / ``(N, m, m)``.
* Sigma points are ordered as in filterpy: ``[x, x + U[0], ..., x + U[n-1], x - U[0], ...,
  x - U[n-1]]`` where ``U`` is the *upper* Cholesky factor of ``(lam + n) P`` (``U^T U =
  (lam + n) P``, what ``scipy.linalg.cholesky`` returns), i.e. ``U[k]`` is column ``k`` of the
  lower factor ``L = np.linalg.cholesky((lam + n) P)``.
* ``fx(sigmas, dt, **fx_args) -> (N, S, n)`` receives all sigma points of all trials at once.
  ``fx_args`` are passed through **unchanged**; a per-trial input shaped ``(N, k)`` must be
  broadcast against the sigma-point axis inside ``fx``, e.g. ``omega[:, None, :]`` (shape
  ``(N, 1, k)``). ``hx(sigmas, **hx_args) -> (N, S, m)`` likewise.

filterpy 2.0.0 versus classic filterpy 1.4.5
--------------------------------------------
``unscented_transform`` and ``MerweScaledSigmaPoints`` are numerically identical in the two.
The one algorithmic change is in ``UnscentedKalmanFilter.predict``: after the unscented
transform, 2.0.0 *redraws* the sigma points from the prior, ``sigmas_f =
sigma_points(x_prior, P_prior)``, so ``update`` passes sigma points of ``(x_prior, P_prior)``
(which include ``Q``) through ``hx`` and uses them in the cross-covariance; 1.4.5 uses the
propagated points ``fx(sigma_points(x, P))`` themselves. :func:`predict` follows 2.0.0 by
default; ``redraw_sigmas=False`` gives the 1.4.5 behaviour. Other 2.0.0 changes do not alter
the numbers with default arguments: a ``state_add`` hook (default ``np.add``) for ``x + K y``,
``hx_args`` documented, ``len(zs)`` in ``batch_filter`` and ``.item()`` in ``mahalanobis``.

Update algebra (as filterpy): ``S = Pzz + R`` by the unscented transform of ``hx(sigmas_f)``;
``Pxz = sum_i Wc_i (X_i - x_prior)(Z_i - z_pred)^T``; ``K = Pxz @ inv(S)`` (explicit inverse,
``np.linalg.inv``, as filterpy's default ``inv``); ``x = x_prior + K y``; ``P = P_prior - K S
K^T`` (no Joseph form).

Symmetrisation: filterpy never symmetrises ``P``. Here ``P_prior`` (before the sigma points
are redrawn from it) and ``P_post`` are replaced by ``(P + P^T) / 2``. The asymmetry removed
is round-off (~1e-16 relative), so agreement with filterpy stays far inside 1e-9, and the
Cholesky factorisation then does not depend on which triangle LAPACK reads.

Conditioning: a small ``alpha`` makes ``Wm[0] = lam / (n + lam)`` large and negative (about
``1 - 1e6`` for ``alpha = 1e-3``, ``n = 4``), so the weighted means cancel terms ~1e6 times
larger than the result and round-off (~1e-16 per step) can grow to ~1e-7 in ``x`` over a run.
That limits agreement with filterpy (or with any reordering of the same sums) for such
settings; filterpy itself moves by as much when its input is perturbed at round-off level.
"""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass, field
from typing import Any

import numpy as np
from numpy.typing import ArrayLike, NDArray

__all__ = [
    "MerweWeights",
    "NotPositiveDefiniteError",
    "assert_positive_definite",
    "predict",
    "sigma_points",
    "unscented_transform",
    "update",
]

FloatArray = NDArray[np.float64]
TransitionFn = Callable[..., ArrayLike]
MeasurementFn = Callable[..., ArrayLike]

_MAX_LISTED = 20  # trial indices quoted in an error message


class NotPositiveDefiniteError(np.linalg.LinAlgError):
    """A covariance is not (numerically) positive definite in some trials.

    Subclass of :class:`numpy.linalg.LinAlgError`, hence also of :class:`ValueError`.
    ``where`` names the check, ``trials`` the failing trial indices and ``min_eigenvalues``
    their smallest eigenvalues (NaN for a non-finite matrix).
    """

    def __init__(
        self, where: str, trials: NDArray[np.intp], min_eigenvalues: FloatArray, n_trials: int
    ) -> None:
        self.where = where
        self.trials = tuple(int(i) for i in trials)
        self.min_eigenvalues = np.asarray(min_eigenvalues, dtype=float)
        shown = ", ".join(str(i) for i in self.trials[:_MAX_LISTED])
        more = f", ... ({len(self.trials) - _MAX_LISTED} more)" if len(trials) > _MAX_LISTED else ""
        eigs = ", ".join(f"{v:.3g}" for v in self.min_eigenvalues[:_MAX_LISTED])
        super().__init__(
            f"{where}: covariance not positive definite in {len(self.trials)} of {n_trials} "
            f"trial(s); trial indices [{shown}{more}]; minimum eigenvalues [{eigs}]"
        )


@dataclass(frozen=True)
class MerweWeights:
    """Van der Merwe scaled sigma-point parameters and weights (filterpy's formulas).

    ``lam = alpha**2 * (n + kappa) - n``; ``Wm = Wc = 1 / (2 (n + lam))`` except
    ``Wm[0] = lam / (n + lam)`` and ``Wc[0] = lam / (n + lam) + 1 - alpha**2 + beta``.
    ``Wm`` and ``Wc`` are read-only arrays of length ``2n + 1``.

    Raises ValueError unless ``n`` is an integer >= 1, ``alpha`` is in (0, 1], ``beta`` and
    ``kappa`` are finite and ``lam + n`` (the sigma-point scale) is > 0.

    >>> w = MerweWeights(n=1, alpha=1.0, beta=0.0, kappa=2.0)
    >>> w.lam, w.n_sigma
    (2.0, 3)
    >>> w.Wm.round(6).tolist(), w.Wc.round(6).tolist()
    ([0.666667, 0.166667, 0.166667], [0.666667, 0.166667, 0.166667])
    """

    n: int
    alpha: float
    beta: float = 2.0
    kappa: float = 0.0
    lam: float = field(init=False, compare=False)
    Wm: FloatArray = field(init=False, repr=False, compare=False)
    Wc: FloatArray = field(init=False, repr=False, compare=False)

    def __post_init__(self) -> None:
        n, alpha, beta, kappa = self.n, self.alpha, self.beta, self.kappa
        if isinstance(n, bool) or not isinstance(n, int | np.integer) or n < 1:
            raise ValueError(f"n (state dimension) must be an integer >= 1, got {n!r}")
        for name, value in (("alpha", alpha), ("beta", beta), ("kappa", kappa)):
            if isinstance(value, bool) or not isinstance(value, int | float | np.number):
                raise ValueError(f"{name} must be a real number, got {value!r}")
            if not np.isfinite(value):
                raise ValueError(f"{name} must be finite, got {value!r}")
        if not 0.0 < alpha <= 1.0:
            raise ValueError(f"alpha must be in (0, 1], got {alpha!r}")
        n = int(n)
        lam = float(alpha**2 * (n + kappa) - n)  # filterpy's lambda_
        if not lam + n > 0.0:
            raise ValueError(
                f"lam + n = alpha**2 * (n + kappa) must be > 0, got {lam + n!r} "
                f"(n={n}, alpha={alpha!r}, kappa={kappa!r}: kappa must be > -n)"
            )
        c = 0.5 / (n + lam)
        wm = np.full(2 * n + 1, c)
        wc = np.full(2 * n + 1, c)
        wc[0] = lam / (n + lam) + (1 - alpha**2 + beta)
        wm[0] = lam / (n + lam)
        wm.flags.writeable = False
        wc.flags.writeable = False
        object.__setattr__(self, "n", n)
        object.__setattr__(self, "lam", lam)
        object.__setattr__(self, "Wm", wm)
        object.__setattr__(self, "Wc", wc)

    @property
    def n_sigma(self) -> int:
        """Number of sigma points, ``2n + 1``."""
        return 2 * self.n + 1

    @property
    def scale(self) -> float:
        """``lam + n``, evaluated as filterpy does (``(alpha**2 (n + kappa) - n) + n``)."""
        return self.lam + self.n


def _as_float(a: ArrayLike) -> FloatArray:
    return np.asarray(a, dtype=float)


def _check_mean_cov(x: ArrayLike, P: ArrayLike, n: int, who: str) -> tuple[FloatArray, FloatArray]:
    x = _as_float(x)
    P = _as_float(P)
    if x.ndim != 2 or x.shape[1] != n:
        raise ValueError(f"{who}: x must be shaped (N, {n}), got {x.shape}")
    N = x.shape[0]
    if P.shape != (N, n, n):
        raise ValueError(f"{who}: P must be shaped (N, n, n) = {(N, n, n)}, got {P.shape}")
    return x, P


def _batched_cov(C: ArrayLike, N: int, d: int, name: str) -> FloatArray:
    C = _as_float(C)
    if C.shape in ((d, d), (N, d, d)):
        return C
    raise ValueError(f"{name} must be shaped ({d}, {d}) or ({N}, {d}, {d}), got {C.shape}")


def _symmetrize(P: FloatArray) -> FloatArray:
    return 0.5 * (P + np.swapaxes(P, -1, -2))


def _min_eigenvalues(P: FloatArray) -> FloatArray:
    """Smallest eigenvalue of the symmetric part of each ``P[i]``; NaN if ``P[i]`` is not finite."""
    finite = np.all(np.isfinite(P), axis=(-2, -1))
    out = np.full(P.shape[0], np.nan)
    if np.any(finite):
        out[finite] = np.linalg.eigvalsh(_symmetrize(P[finite]))[:, 0]
    return out


def _not_pd_error(
    P: FloatArray, where: str, min_eig: FloatArray | None = None
) -> NotPositiveDefiniteError:
    if min_eig is None:
        min_eig = _min_eigenvalues(P)
    bad = np.flatnonzero(~(min_eig > 0.0))
    if bad.size == 0:
        # Cholesky failed although every eigenvalue is (barely) positive: name the worst trials.
        bad = np.sort(np.argsort(min_eig, kind="stable")[:_MAX_LISTED])
        where = f"{where} (Cholesky failed with all eigenvalues > 0; smallest-eigenvalue trials)"
    return NotPositiveDefiniteError(where, bad, min_eig[bad], P.shape[0])


def _cholesky_lower(A: FloatArray, where: str) -> FloatArray:
    """Batched lower Cholesky factor; NotPositiveDefiniteError names the failing trials."""
    try:
        L = np.linalg.cholesky(A)
    except np.linalg.LinAlgError as err:
        raise _not_pd_error(A, where) from err
    if not np.all(np.isfinite(L)):
        raise _not_pd_error(A, where)
    return L


def assert_positive_definite(P: ArrayLike, where: str) -> FloatArray:
    """Check that every ``P[i]`` of a ``(N, n, n)`` stack is positive definite.

    Uses the smallest eigenvalue of the symmetric part (``np.linalg.eigvalsh``); a non-finite
    matrix counts as failing. Returns the smallest eigenvalues, shape ``(N,)``.

    Raises NotPositiveDefiniteError (a ValueError) whose message starts with ``where`` and
    lists the failing trial indices.

    >>> P = np.stack([np.eye(2), np.diag([1.0, -1.0])])
    >>> assert_positive_definite(P[:1], "prior").tolist()
    [1.0]
    >>> assert_positive_definite(P, "prior")
    Traceback (most recent call last):
    ...
    pipeline.altimeter_attitude.ukf.NotPositiveDefiniteError: prior: covariance not positive \
definite in 1 of 2 trial(s); trial indices [1]; minimum eigenvalues [-1]
    """
    P = _as_float(P)
    if P.ndim != 3 or P.shape[1] != P.shape[2]:
        raise ValueError(f"{where}: P must be shaped (N, n, n), got {P.shape}")
    min_eig = _min_eigenvalues(P)
    if not np.all(min_eig > 0.0):
        raise _not_pd_error(P, where, min_eig)
    return min_eig


def sigma_points(
    x: ArrayLike, P: ArrayLike, weights: MerweWeights, where: str = "sigma_points"
) -> FloatArray:
    """Scaled sigma points of ``(x[i], P[i])`` for every trial, shape ``(N, 2n+1, n)``.

    Same order and square root as filterpy's ``MerweScaledSigmaPoints.sigma_points``:
    ``[x, x + U[0..n-1], x - U[0..n-1]]`` with ``U`` the upper Cholesky factor of
    ``(lam + n) P`` (column ``k`` of the lower factor). Raises NotPositiveDefiniteError (a
    ``LinAlgError`` and ``ValueError``) naming ``where`` and the trials whose ``P`` is not
    positive definite.

    >>> w = MerweWeights(n=1, alpha=1.0, beta=0.0, kappa=2.0)
    >>> sigma_points([[0.0]], [[[3.0]]], w)[..., 0].tolist()
    [[0.0, 3.0, -3.0]]
    """
    x, P = _check_mean_cov(x, P, weights.n, where)
    L = _cholesky_lower(weights.scale * P, where)
    U = np.swapaxes(L, -1, -2)  # U[:, k] = row k of the upper factor = column k of L
    xs = x[:, None, :]
    return np.concatenate([xs, xs + U, xs - U], axis=1)


def unscented_transform(
    sigmas: ArrayLike, weights: MerweWeights, noise_cov: ArrayLike | None = None
) -> tuple[FloatArray, FloatArray]:
    """Weighted mean ``(N, m)`` and covariance ``(N, m, m)`` of sigma points ``(N, 2n+1, m)``.

    ``mean = Wm @ sigmas``; ``cov = sum_i Wc_i (s_i - mean)(s_i - mean)^T + noise_cov``, as
    filterpy's ``unscented_transform`` (``y.T @ diag(Wc) @ y``). ``noise_cov`` is ``(m, m)``,
    ``(N, m, m)`` or None.

    The mean below is zero only up to round-off: with ``Wm[1] = Wm[2] = 1/6`` (not exact in
    binary), ``3 Wm[1] - 3 Wm[2]`` comes out ~3e-17 when the BLAS fuses multiply-adds, with a
    sign that depends on its summation order; hence the rounding and the comparison.

    >>> w = MerweWeights(n=1, alpha=1.0, beta=0.0, kappa=2.0)
    >>> mean, cov = unscented_transform([[[0.0], [3.0], [-3.0]]], w, noise_cov=[[1.0]])
    >>> mean.round(12).tolist() == [[0.0]], cov.round(12).tolist()
    (True, [[[4.0]]])
    """
    sigmas = _as_float(sigmas)
    if sigmas.ndim != 3 or sigmas.shape[1] != weights.n_sigma:
        raise ValueError(
            f"sigmas must be shaped (N, {weights.n_sigma}, m) for n={weights.n}, got {sigmas.shape}"
        )
    N, _, m = sigmas.shape
    mean = weights.Wm @ sigmas
    y = sigmas - mean[:, None, :]
    cov = np.swapaxes(y, -1, -2) @ (weights.Wc[:, None] * y)
    if noise_cov is not None:
        cov = cov + _batched_cov(noise_cov, N, m, "noise_cov")
    return mean, cov


def predict(
    x: ArrayLike,
    P: ArrayLike,
    fx: TransitionFn,
    Q: ArrayLike,
    dt: float,
    weights: MerweWeights,
    *,
    redraw_sigmas: bool = True,
    **fx_args: Any,
) -> tuple[FloatArray, FloatArray, FloatArray]:
    """UKF prediction of ``N`` trials: ``(x_prior (N, n), P_prior (N, n, n), sigmas_f)``.

    Sigma points of ``(x, P)`` go through ``fx(sigmas (N, S, n), dt, **fx_args) -> (N, S, n)``
    (``fx_args`` are passed unchanged: broadcast per-trial ``(N, k)`` arrays inside ``fx`` as
    ``a[:, None, :]``); the unscented transform plus ``Q`` (``(n, n)`` or ``(N, n, n)``) gives
    the prior, which is symmetrised. As filterpy 2.0.0, the returned ``sigmas_f`` are redrawn
    from the prior, ``sigma_points(x_prior, P_prior)``; with ``redraw_sigmas=False`` they are
    the propagated points, as filterpy 1.4.5. Pass ``sigmas_f`` on to :func:`update`.

    >>> w = MerweWeights(n=1, alpha=1.0, beta=2.0, kappa=0.0)
    >>> xp, Pp, sf = predict([[1.0]], [[[1.0]]], lambda s, dt: s + dt, [[0.5]], 2.0, w)
    >>> xp.tolist(), Pp.tolist(), sf.shape
    ([[3.0]], [[[1.5]]], (1, 3, 1))
    """
    x, P = _check_mean_cov(x, P, weights.n, "predict")
    N, n = x.shape
    Q = _batched_cov(Q, N, n, "Q")
    sigmas = sigma_points(x, P, weights, where="predict: posterior covariance P")
    sigmas_f = _as_float(fx(sigmas, dt, **fx_args))
    if sigmas_f.shape != sigmas.shape:
        raise ValueError(f"fx must return shape {sigmas.shape}, got {sigmas_f.shape}")
    x_prior, P_prior = unscented_transform(sigmas_f, weights, Q)
    P_prior = _symmetrize(P_prior)
    if redraw_sigmas:
        sigmas_f = sigma_points(x_prior, P_prior, weights, where="predict: prior covariance")
    return x_prior, P_prior, sigmas_f


def update(
    x_prior: ArrayLike,
    P_prior: ArrayLike,
    sigmas_f: ArrayLike,
    z: ArrayLike,
    hx: MeasurementFn,
    R: ArrayLike,
    weights: MerweWeights,
    **hx_args: Any,
) -> tuple[FloatArray, FloatArray, FloatArray, FloatArray]:
    """UKF measurement update of ``N`` trials: ``(x_post, P_post, innovation (N, m), S)``.

    ``sigmas_f`` are :func:`predict`'s sigma points; ``hx(sigmas_f, **hx_args) -> (N, S, m)``.
    ``S = Pzz + R`` (``R`` is ``(m, m)`` or ``(N, m, m)``), ``K = Pxz @ inv(S)``,
    ``x_post = x_prior + K (z - z_pred)``, ``P_post = P_prior - K S K^T`` (then symmetrised),
    exactly as filterpy's ``update``.

    >>> w = MerweWeights(n=1, alpha=1.0, beta=2.0, kappa=0.0)
    >>> xp, Pp = np.array([[0.0]]), np.array([[[1.0]]])
    >>> sf = sigma_points(xp, Pp, w)
    >>> x, P, y, S = update(xp, Pp, sf, [[2.0]], lambda s: s, [[1.0]], w)
    >>> x.tolist(), P.tolist(), y.tolist(), S.tolist()
    ([[1.0]], [[[0.5]]], [[2.0]], [[[2.0]]])
    """
    x_prior, P_prior = _check_mean_cov(x_prior, P_prior, weights.n, "update")
    N, n = x_prior.shape
    sigmas_f = _as_float(sigmas_f)
    if sigmas_f.shape != (N, weights.n_sigma, n):
        raise ValueError(f"sigmas_f must be shaped {(N, weights.n_sigma, n)}, got {sigmas_f.shape}")
    sigmas_h = _as_float(hx(sigmas_f, **hx_args))
    if sigmas_h.ndim != 3 or sigmas_h.shape[:2] != (N, weights.n_sigma):
        raise ValueError(
            f"hx must return shape {(N, weights.n_sigma)} + (m,), got {sigmas_h.shape}"
        )
    m = sigmas_h.shape[2]
    z = _as_float(z)
    if z.shape != (N, m):
        raise ValueError(f"z must be shaped (N, m) = {(N, m)}, got {z.shape}")
    z_pred, S = unscented_transform(sigmas_h, weights, _batched_cov(R, N, m, "R"))
    S_inv = np.linalg.inv(S)
    dx = sigmas_f - x_prior[:, None, :]
    dz = sigmas_h - z_pred[:, None, :]
    Pxz = np.swapaxes(dx, -1, -2) @ (weights.Wc[:, None] * dz)
    K = Pxz @ S_inv
    innovation = z - z_pred
    x_post = x_prior + (K @ innovation[..., None])[..., 0]
    P_post = _symmetrize(P_prior - K @ (S @ np.swapaxes(K, -1, -2)))
    return x_post, P_post, innovation, S
