"""Memoised derivations: a pure derivation function computed once per process.

The audits, the code generators and the notebooks call the same basic derivations (the
table rate, the Earth rate in the sensor frame, a gyro reading at a table angle) dozens of
times, and each call re-runs ``simplify``. :func:`derivation` caches a function on its
(hashable) arguments like :func:`functools.cache`, and hands every caller its own copy of
the mutable containers in the result (dicts, lists, mutable matrices), so a caller that
edits what it got cannot change what the next caller gets. SymPy expressions are immutable
and are shared.

>>> import sympy as sp
>>> calls = []
>>> @derivation
... def rates(a):
...     calls.append(a)
...     return {"m": sp.Matrix([a, 2 * a])}
>>> x = sp.Symbol("x")
>>> first = rates(x)
>>> first["m"][0] = 0
>>> rates(x)["m"].T, len(calls)
(Matrix([[x, 2*x]]), 1)
"""

from __future__ import annotations

import functools
from collections.abc import Callable
from typing import Any, TypeVar

import sympy as sp

__all__ = ["derivation", "fresh_copy"]

F = TypeVar("F", bound=Callable[..., Any])


def fresh_copy(value: Any) -> Any:
    """``value`` with its mutable containers (dict, list, tuple, mutable matrix) copied."""
    if isinstance(value, sp.MatrixBase) and not isinstance(value, sp.ImmutableMatrix):
        return value.copy()
    if isinstance(value, dict):
        return {k: fresh_copy(v) for k, v in value.items()}
    if isinstance(value, list):
        return [fresh_copy(v) for v in value]
    if isinstance(value, tuple):
        return tuple(fresh_copy(v) for v in value)
    return value


def derivation(func: F) -> F:
    """Cache the pure derivation ``func`` on its arguments; each call gets a fresh copy."""
    cached = functools.cache(func)

    @functools.wraps(func)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        return fresh_copy(cached(*args, **kwargs))

    wrapper.cache_clear = cached.cache_clear  # type: ignore[attr-defined]
    return wrapper  # type: ignore[return-value]
