"""``Factors`` of a dictionary built without a SymPy ``Dict``: :func:`lean_dict_factors`.

``sympy.core.exprtools.Factors`` (a product as a ``{base: exponent}`` dictionary) is built
tens of thousands of times by ``gcd_terms``, ``factor_terms`` and ``cancel`` inside
``simplify`` and ``trigsimp`` (the north-finding audit: ~87,000 times, ~85,000 of them from a
``dict`` or ``defaultdict`` its own methods made). For such an argument SymPy 1.14.0's
``Factors.__init__`` first tests ``factors in (None, S.One)``: ``S.One == factors`` sympifies
the dictionary into a SymPy ``Dict`` (a ``Tuple`` per item, their sort keys, a sorted
``Basic``), finds it is not a number and answers False; ``factors == 0`` is False, and the
dictionary is none of ``Number``, ``Basic`` or ``Expr``; so the ``else`` branch runs: a copy of
the dictionary, its +-1 and ``I`` exponents tidied. The ``Dict`` is thrown away: ~2.3 s of the
north-finding audit's ~26 s under a profiler.

Within :func:`lean_dict_factors`, ``Factors.__init__`` given a ``dict`` or ``defaultdict``
(that exact type) whose keys and values are all ``Expr`` or ``int`` runs :func:`_from_dict`,
SymPy 1.14.0's ``else`` branch and the end of ``__init__`` as they are (``exprtools.py``, lines
370-401), without building the ``Dict``; any other argument goes to SymPy's own
``__init__``. For those arguments SymPy's ``Dict`` of them cannot fail (sympifying an ``Expr``
or an ``int`` never does, and an ``Expr`` has a sort key), so SymPy reaches that same branch
with the same dictionary: the resulting ``Factors`` is the same (its ``factors`` an equal copy
of the same type, in the same order; the same ``gens``). The one difference is what the
discarded ``Dict`` left in SymPy's cache (the sort keys of its items), a cache of values that
do not change. The equation_audit.csv, equation_math.json, derivation.pkl and
derivation_memo.pkl of the three papers are byte-identical with it;
tests/shared/test_factors_dict.py compares the two ``Factors`` on many dictionaries.

Only for the SymPy version whose source this copies (:data:`PATCHED_VERSION`): any other runs
SymPy's ``__init__`` unchanged. The class attribute is replaced while the context is open and
restored after; nested use leaves it to the outermost. Not thread-safe (the workflow's jobs
derive in their main thread).

>>> import sympy as sp
>>> from sympy.core.exprtools import Factors
>>> x = sp.Symbol("x")
>>> with lean_dict_factors():
...     f = Factors({x: sp.Integer(2), sp.S.NegativeOne: sp.Integer(3)})
>>> f, f.gens == {x, sp.S.NegativeOne}
(Factors({-1: 1, x: 2}), True)
"""

from __future__ import annotations

import contextlib
import importlib
from collections import defaultdict
from collections.abc import Iterator
from typing import Any

import sympy as sp

__all__ = ["PATCHED_VERSION", "lean_dict_factors"]

#: the SymPy version whose ``Factors.__init__`` this copies (environment.lock)
PATCHED_VERSION = "1.14.0"

_exprtools = importlib.import_module("sympy.core.exprtools")
#: the argument types taken without the ``Dict`` (exact types: a subclass goes to SymPy)
_DICTS = (dict, defaultdict)


def _from_dict(self: Any, factors: dict[Any, Any]) -> None:
    """SymPy 1.14.0's ``Factors.__init__`` from its ``else`` branch on (exprtools.py, lines
    370-401), for a dictionary argument; only the names are qualified."""
    I, S = _exprtools.I, _exprtools.S  # SymPy's names, as in its source
    factors = factors.copy()  # /!\ should be dict-like

    # tidy up -/+1 and I exponents if Rational

    handle = [k for k in factors if k is I or k in (-1, 1)]
    if handle:
        i1 = S.One
        for k in handle:
            if not _exprtools._isnumber(factors[k]):
                continue
            i1 *= k ** factors.pop(k)
        if i1 is not S.One:
            for a in i1.args if i1.is_Mul else [i1]:  # at worst, -1.0*I*(-1)**e
                if a is S.NegativeOne:
                    factors[a] = S.One
                elif a is I:
                    factors[I] = S.One
                elif a.is_Pow:
                    factors[a.base] = factors.get(a.base, S.Zero) + a.exp
                elif _exprtools.equal_valued(a, 1):
                    factors[a] = S.One
                elif _exprtools.equal_valued(a, -1):
                    factors[-a] = S.One
                    factors[S.NegativeOne] = S.One
                else:
                    raise ValueError("unexpected factor in i1: %s" % a)  # noqa: UP031

    self.factors = factors
    keys = getattr(factors, "keys", None)
    if keys is None:
        raise TypeError("expecting Expr or dictionary")
    self.gens = frozenset(keys())


def _takes(factors: object) -> bool:
    """True for a ``dict`` or ``defaultdict`` of ``Expr`` or ``int`` keys and values: what
    SymPy's ``Factors.__init__`` sends to its ``else`` branch after building a ``Dict``."""
    if type(factors) not in _DICTS:
        return False
    expr = sp.Expr
    for k, v in factors.items():  # type: ignore[attr-defined]
        if not (isinstance(k, (expr, int)) and isinstance(v, (expr, int))):
            return False
    return True


@contextlib.contextmanager
def lean_dict_factors() -> Iterator[bool]:
    """While open, ``Factors`` of a dictionary of expressions skips the SymPy ``Dict`` its
    ``__init__`` builds and throws away (the same ``Factors``); yields whether it is patched
    (False on another SymPy version)."""
    cls = _exprtools.Factors
    original = cls.__init__
    if getattr(original, "lean_dict_factors", False):  # an outer context holds it
        yield True
        return
    if sp.__version__ != PATCHED_VERSION:
        yield False
        return

    def __init__(self: Any, factors: Any = None) -> None:
        if _takes(factors):
            _from_dict(self, factors)
        else:
            original(self, factors)

    __init__.lean_dict_factors = True  # type: ignore[attr-defined]
    __init__.__doc__ = original.__doc__
    cls.__init__ = __init__
    try:
        yield True
    finally:
        cls.__init__ = original
