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
import inspect
import os
import pickle
import types
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any, TypeVar

import sympy as sp

from derivations.canonical_pickle import canonical_dumps

__all__ = [
    "ENV_VAR",
    "derivation",
    "dumps",
    "freeze",
    "fresh_copy",
    "preload",
    "preload_env",
    "snapshot",
    "thaw",
]

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


@dataclass(frozen=True)
class _Frozen:
    """A hashable stand-in for an unhashable argument (a mutable matrix, a list) or for an object
    compared by identity (a plain class instance): its kind and its contents, frozen."""

    kind: Any  # "matrix", "list", or the object's class
    contents: Any  # an ImmutableMatrix, a tuple, or ((attribute, frozen value), ...)


def freeze(value: Any) -> Any:
    """``value`` as a key: hashable values as they are; a mutable matrix, a list, or an instance
    of a class without its own equality (compared by identity, so never equal to the same
    object rebuilt in another process) by their contents. :func:`thaw` rebuilds an equal value.

    >>> x = sp.Symbol("x")
    >>> key = freeze([sp.Matrix([x, 1]), 2])
    >>> key == freeze([sp.Matrix([x, 1]), 2]), hash(key) == hash(freeze([sp.Matrix([x, 1]), 2]))
    (True, True)
    >>> thaw(key)
    [Matrix([
    [x],
    [1]]), 2]
    """
    if isinstance(value, sp.MatrixBase) and not isinstance(value, sp.ImmutableMatrix):
        return _Frozen("matrix", sp.ImmutableMatrix(value))
    if isinstance(value, list):
        return _Frozen("list", tuple(freeze(v) for v in value))
    if isinstance(value, tuple):
        return tuple(freeze(v) for v in value)
    if (
        type(value).__eq__ is object.__eq__
        and hasattr(value, "__dict__")
        and not callable(value)  # functions and classes are keys as they are
        and not isinstance(value, types.ModuleType)
    ):
        state = tuple(sorted((k, freeze(v)) for k, v in vars(value).items()))
        return _Frozen(type(value), state)
    return value


def thaw(key: Any) -> Any:
    """The value :func:`freeze` made ``key`` of (an equal one, of the same type)."""
    if isinstance(key, tuple):
        return tuple(thaw(v) for v in key)
    if not isinstance(key, _Frozen):
        return key
    if key.kind == "matrix":
        return sp.Matrix(key.contents)
    if key.kind == "list":
        return [thaw(v) for v in key.contents]
    obj = key.kind.__new__(key.kind)
    obj.__dict__.update({k: thaw(v) for k, v in key.contents})
    return obj


def _key(args: tuple, kwargs: dict) -> Any:
    return (freeze(args), tuple(sorted((k, freeze(v)) for k, v in kwargs.items())))


def derivation(func: F) -> F:
    """Cache the pure derivation ``func`` on its arguments; each call gets a fresh copy.

    A call is keyed by its arguments bound to ``func``'s parameters, defaults filled in, so
    that ``f("x")``, ``f("x", tau)`` and ``f(axis="x", tau_=tau)`` (the same call when ``tau``
    is the default) share one result: the derive step and a notebook often spell one call
    differently.

    >>> calls = []
    >>> @derivation
    ... def scaled(a, k=2, *, offset=0):
    ...     calls.append(a)
    ...     return k * a + offset
    >>> scaled(1), scaled(1, 2), scaled(a=1, offset=0), scaled(1, k=3), len(calls)
    (2, 2, 2, 3, 2)
    """
    name = f"{func.__module__}.{func.__qualname__}"
    store = _STORES.setdefault(name, {})
    signature = inspect.signature(func)

    @functools.wraps(func)
    def wrapper(*args: Any, **kwargs: Any) -> Any:
        try:
            bound = signature.bind(*args, **kwargs)
        except TypeError:
            return func(*args, **kwargs)  # the call's own error
        bound.apply_defaults()
        key = _key(bound.args, bound.kwargs)
        try:
            value = store[key]
        except KeyError:
            value = store[key] = func(*bound.args, **bound.kwargs)
        return fresh_copy(value)

    wrapper.cache_clear = store.clear  # type: ignore[attr-defined]
    return wrapper  # type: ignore[return-value]


def snapshot() -> dict[str, dict[Any, Any]]:
    """Every result computed so far in this process, per function (sorted by name)."""
    return {name: dict(store) for name, store in sorted(_STORES.items()) if store}


def dumps(snap: dict[str, dict[Any, Any]]) -> bytes:
    """``snap`` pickled (fixed protocol), each SymPy value written once: the same bytes for the
    same derivations, whatever else the process computed before (SymPy's cache)."""
    return canonical_dumps(snap, PROTOCOL)


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
