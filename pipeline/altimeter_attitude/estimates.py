"""What every filter returns: roll/pitch estimates and (where it has one) their sigma."""

from __future__ import annotations

from collections.abc import Callable
from dataclasses import dataclass

import numpy as np

__all__ = ["POST_RUNS", "Estimates", "by_runs"]

#: runs per slice of :func:`by_runs` (16 runs x 10,001 state times: 1.3 MB per temporary)
POST_RUNS = 16


@dataclass(frozen=True)
class Estimates:
    """Estimates at the state times t_k, k = 0..T, for N runs (arrays (N, T + 1)).

    ``roll_sigma``/``pitch_sigma`` are NaN for a filter without a covariance; ``c`` (N, T+1, 3)
    is the estimated third DCM row (for the c-based filters; else computed from the angles);
    ``norm_error`` is 1 - c^T c of the filter's own c (0 for the angle-based filters).
    """

    filter: str
    roll: np.ndarray
    pitch: np.ndarray
    roll_sigma: np.ndarray
    pitch_sigma: np.ndarray
    c: np.ndarray
    norm_error: np.ndarray


def by_runs(fn: Callable, *arrays: np.ndarray, runs: int = POST_RUNS):
    """``fn(*arrays)`` for an elementwise ``fn`` (numpy ufuncs, e.g. a generated formula),
    computed on slices of ``runs`` runs (axis 0) into arrays of the whole: every element is
    computed by the same operations as in one call (an elementwise ufunc computes each element
    alone), so the numbers are the same bit for bit, but the temporaries are a slice's (in
    cache, reused from the heap) rather than the whole block's (each a fresh mapping the
    kernel zeroes page by page: ~1/4 of the linear KF's time at 256 runs x 10,000 steps).
    Returns what ``fn`` returns (an array or a tuple of arrays).

    >>> a = np.arange(6.0).reshape(3, 2)
    >>> by_runs(np.sqrt, a, runs=2).tolist() == np.sqrt(a).tolist()
    True
    >>> [x.tolist() for x in by_runs(lambda x: (x, -x), a, runs=2)][1]
    [[-0.0, -1.0], [-2.0, -3.0], [-4.0, -5.0]]
    """
    n = arrays[0].shape[0]
    out: tuple[np.ndarray, ...] = ()
    single = False
    for start in range(0, n, runs):
        part = fn(*(a[start : start + runs] for a in arrays))
        single = not isinstance(part, tuple)
        parts = (part,) if single else part
        if not out:
            out = tuple(np.empty((n, *np.shape(p)[1:]), dtype=np.result_type(p)) for p in parts)
        for whole, p in zip(out, parts, strict=True):
            whole[start : start + runs] = p
    return out[0] if single else out
