"""Small-quantity truncation used by the paper's linearised equations.

The paper linearises in small quantities (tilts, plumb deflection, biases, drift). Its
"=~" steps are checked here by Taylor-expanding the exact derivation in a bookkeeping
parameter ``eps`` that scales the small symbols, and keeping terms up to ``order``:

>>> import sympy as sp
>>> a, b = sp.symbols("a b")
>>> taylor(sp.sin(a) * sp.cos(b) + 1, [a, b], 2)
a + 1
>>> taylor(sp.sin(a) * sp.cos(b) + 1, [a], 1)
a*cos(b) + 1
"""

from __future__ import annotations

from collections.abc import Iterable

import sympy as sp

__all__ = ["taylor", "derivative_symbols"]


def taylor(expr, small: Iterable[sp.Symbol], order: int = 1):
    """Terms of ``expr`` up to total degree ``order`` in the ``small`` symbols (expanded).

    Works element-wise on matrices and tuples. Uses repeated differentiation in the
    bookkeeping parameter (robust where ``series`` is slow on long trigonometric sums).
    """
    if isinstance(expr, sp.MatrixBase):
        return expr.applyfunc(lambda e: taylor(e, small, order))
    if isinstance(expr, (tuple, list)):
        return type(expr)(taylor(e, small, order) for e in expr)
    eps = sp.Dummy("eps")
    scaled = sp.sympify(expr).xreplace({s: eps * s for s in small})
    out = sp.S.Zero
    d = scaled
    for k in range(order + 1):
        out += d.subs(eps, 0) / sp.factorial(k)
        if k < order:
            d = d.diff(eps)
    return sp.expand(out)


def derivative_symbols(expr, mapping: dict):
    """Replace functions of t and their derivatives by symbols.

    ``mapping`` maps ``f(t)`` to a tuple of symbols ``(f, f_dot, f_ddot, ...)``; the
    highest derivatives are replaced first.
    """
    reps = {}
    for fun, syms in mapping.items():
        var = fun.args[0]
        for k in range(len(syms) - 1, 0, -1):
            reps[fun.diff(var, k)] = syms[k]
    out = expr.xreplace(reps) if hasattr(expr, "xreplace") else expr
    return out.xreplace({fun: syms[0] for fun, syms in mapping.items()})
