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

Across processes: the workflow's ``derive`` step computes most of a paper's derivations; its
notebook calls the same functions again in another process (~5 CPU-s of ``simplify`` per
paper). :func:`snapshot` holds every result this process has computed, keyed by function and
arguments; ``derive`` pickles it beside the artefact (``results/<slug>/derivation_memo.pkl``)
and the notebook's kernel, started with :data:`ENV_VAR` naming that file, preloads it when it
imports :mod:`derivations`, so a call already made by ``derive`` returns its result. The
results are the same objects a fresh process derives (``tests/shared/test_memo.py`` checks
each one of a paper's snapshot against a fresh derivation); a notebook run without the variable
(in JupyterLab) derives everything itself.

>>> snap = snapshot()
>>> any(name.endswith("rates") for name in snap)
True
>>> rates.cache_clear(); preload(snap); rates(x)["m"].T, len(calls)
(Matrix([[x, 2*x]]), 1)
"""

from __future__ import annotations

import functools
import os
import pickle
from collections.abc import Callable
from pathlib import Path
from typing import Any, TypeVar

import sympy as sp

__all__ = ["ENV_VAR", "derivation", "dumps", "fresh_copy", "preload", "preload_env", "snapshot"]

#: names the pickled snapshot a process preloads when it imports :mod:`derivations`
ENV_VAR = "INERTIAL_REPRO_DERIVATION_MEMO"
PROTOCOL = 4

#: every memoised function's results, ``{module.qualname: {(args, kwargs): value}}``
_STORES: dict[str, dict[Any, Any]] = {}

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


def _key(args: tuple, kwargs: dict) -> Any:
    return (args, tuple(sorted(kwargs.items())))


def derivation(func: F) -> F:
    """Cache the pure derivation ``func`` on its arguments; each call gets a fresh copy."""
    name = f"{func.__module__}.{func.__qualname__}"
    store = _STORES.setdefault(name, {})

    @functools.wraps(func)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        key = _key(args, kwargs)
        try:
            value = store[key]
        except KeyError:
            value = store[key] = func(*args, **kwargs)
        return fresh_copy(value)

    wrapper.cache_clear = store.clear  # type: ignore[attr-defined]
    return wrapper  # type: ignore[return-value]


def snapshot() -> dict[str, dict[Any, Any]]:
    """Every result computed so far in this process, per function (sorted by name)."""
    return {name: dict(store) for name, store in sorted(_STORES.items()) if store}


def dumps(snap: dict[str, dict[Any, Any]]) -> bytes:
    """``snap`` pickled (fixed protocol; the same bytes for the same derivations)."""
    return pickle.dumps(snap, protocol=PROTOCOL)


def preload(snap: dict[str, dict[Any, Any]]) -> None:
    """Take ``snap``'s results as already computed (a function not yet imported gets them
    when its module is)."""
    for name, results in snap.items():
        _STORES.setdefault(name, {}).update(results)


def preload_env() -> Path | None:
    """Preload the snapshot the environment variable :data:`ENV_VAR` names, if any."""
    path = os.environ.get(ENV_VAR)
    if not path:
        return None
    preload(pickle.loads(Path(path).read_bytes()))
    return Path(path)
