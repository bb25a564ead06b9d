"""``trigsimp`` with each subexpression simplified once: :func:`memoised_futrig`; and each
expression ``futrig`` factors factored once: :func:`memoised_trig_factor`.

``trigsimp`` (its default method, ``futrig``) walks an expression from the leaves up and runs
its greedy search of Fu's rules (``sympy.simplify.trigsimp._futrig``) on every node; so does
``simplify``, which calls it. The same node comes back often: a residual's denominator
repeated in several terms, ``sin(phi)*cos(theta)`` in every sum that holds it, the same
coefficients simplified by one derivation after another. On the three papers' derivations and
audits about two in three of those calls repeat a node already seen (the north-finding audit:
567 of 812).

``_futrig`` is a function of its argument's value: its rules are rewritings, the greedy search
picks the first of the shortest candidates (a fixed order), and the one random step in it
(Wang's factoring, inside ``factor``) draws points that change the work, not the factorisation
it returns (which is unique). So within :func:`memoised_futrig`, each distinct node (SymPy's
structural equality, which the dictionary's lookup uses) is simplified once and its result
handed back after that; ``trigsimp`` and ``simplify`` give the same expressions as without it
(equation_audit.csv, equation_math.json, derivation.pkl and derivation_memo.pkl of the three
papers byte-identical; tests/shared/test_futrig_memo.py compares the two on residuals).

The node's simplification is looked up where ``futrig`` finds it, the module attribute
``sympy.simplify.trigsimp._futrig``, which the context replaces while it is open and restores
after; only for the SymPy version it was written for (:data:`PATCHED_VERSION`), any other
runs unchanged. Not thread-safe (the workflow's jobs derive in their main thread).

Inside a node's search the same holds one level down: three of its steps ``factor`` the node
(``factor(x)``, ``factor(x.normal())``), and the audit's nodes hand ``factor`` the same
expression again and again (the north-finding audit: 537 calls, 226 distinct expressions; the
same node after steps that changed nothing, a denominator shared by several residuals). Within
:func:`memoised_trig_factor` (the audit's, :func:`derivations.checks.run_audit`) each distinct
expression is factored once: the name ``factor`` of ``sympy.simplify.trigsimp`` (the one those
steps call) is replaced while the context is open. The factorisation is unique, so the results
are the same (equation_audit.csv and equation_math.json of the three papers byte-identical;
Python function calls of the north-finding audit 42.0 -> 40.0 million, of the platform-drift
one 15.1 -> 14.1 million; tests/shared/test_futrig_memo.py compares the two on residuals).

>>> import sympy as sp
>>> x = sp.Symbol("x")
>>> e = sp.sin(x) ** 2 / (1 - sp.cos(x) ** 2) + sp.cos(x) ** 2 + sp.sin(x) ** 2
>>> with memoised_futrig() as memo:
...     first = sp.trigsimp(e)
...     again = sp.trigsimp(e)
>>> first, again, sp.trigsimp(e), len(memo) > 0
(2, 2, 2, True)
"""

from __future__ import annotations

import contextlib
import importlib
from collections.abc import Iterator

import sympy as sp

__all__ = ["PATCHED_VERSION", "memoised_futrig", "memoised_trig_factor"]

#: the SymPy version whose ``trigsimp`` internals this was written for (environment.lock)
PATCHED_VERSION = "1.14.0"

_trigsimp = importlib.import_module("sympy.simplify.trigsimp")


@contextlib.contextmanager
def memoised_futrig() -> Iterator[dict[sp.Basic, sp.Basic]]:
    """While open, ``futrig``'s per-node simplification is computed once per distinct node;
    yields the memo (node -> simplified node). Nested use shares the outer memo."""
    original = _trigsimp._futrig
    if sp.__version__ != PATCHED_VERSION or getattr(original, "memo", None) is not None:
        yield getattr(original, "memo", {})
        return
    memo: dict[sp.Basic, sp.Basic] = {}

    def _futrig(e: sp.Basic) -> sp.Basic:
        try:
            return memo[e]
        except KeyError:
            pass
        except TypeError:  # an unhashable node: nothing to remember it by
            return original(e)
        out = memo[e] = original(e)
        return out

    _futrig.memo = memo  # type: ignore[attr-defined]
    _trigsimp._futrig = _futrig
    try:
        yield memo
    finally:
        _trigsimp._futrig = original


@contextlib.contextmanager
def memoised_trig_factor() -> Iterator[dict[sp.Basic, sp.Basic]]:
    """While open, ``factor`` as ``trigsimp``'s module calls it (one expression, no options)
    is computed once per distinct expression; yields the memo (expression -> factored).
    Nested use shares the outer memo; another SymPy version runs unchanged."""
    original = _trigsimp.factor
    if sp.__version__ != PATCHED_VERSION or getattr(original, "memo", None) is not None:
        yield getattr(original, "memo", {})
        return
    memo: dict[sp.Basic, sp.Basic] = {}

    def factor(f: sp.Basic, *gens: sp.Basic, **args: object) -> sp.Basic:
        if gens or args:  # options: not the calls of futrig's steps, not remembered
            return original(f, *gens, **args)
        try:
            return memo[f]
        except KeyError:
            pass
        except TypeError:  # unhashable: nothing to remember it by
            return original(f)
        out = memo[f] = original(f)
        return out

    factor.memo = memo  # type: ignore[attr-defined]
    _trigsimp.factor = factor
    try:
        yield memo
    finally:
        _trigsimp.factor = original
