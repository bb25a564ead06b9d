"""Exact reduction of polynomials in sines and cosines by ``sin(a)**2 = 1 - cos(a)**2``.

A derivation that multiplies rotation matrices and differentiates them produces long sums of
products of sines and cosines whose simple form only appears through ``sin**2 + cos**2 = 1``.
``sympy.simplify`` finds it, at the price of trying many rewritings (``trigsimp``'s ``futrig``,
factorisations that draw random points) on the long expression. :func:`pythagorean_reduce`
applies the identity directly: expanded, every ``sin(a)**n`` with ``n >= 2`` becomes
``sin(a)**(n - 2) * (1 - cos(a)**2)`` until none is left. The result is equal to the input
(the identity holds for every ``a``), and for a polynomial in the sines and cosines of
independent angles it is the unique form with each sine to at most the first power: an
expression that does not depend on an angle loses every term in it (the inertial longitude of
a vehicle on the Earth below), and two expressions equal as functions give the same form.

>>> import sympy as sp
>>> a, b, x = sp.symbols("a b x", real=True)
>>> pythagorean_reduce(sp.sin(a) ** 2 * x + sp.cos(a) ** 2 * x)
x
>>> pythagorean_reduce(sp.expand_trig(sp.sin(a + b) ** 2 + sp.cos(a + b) ** 2))
1
>>> pythagorean_reduce(sp.sin(a) ** 3)
-sin(a)*cos(a)**2 + sin(a)
"""

from __future__ import annotations

import sympy as sp

__all__ = ["pythagorean_reduce"]


def pythagorean_reduce(expr: sp.Expr) -> sp.Expr:
    """``expr`` expanded, with every ``sin(a)**n`` (``n >= 2``) reduced by ``sin**2 = 1 - cos**2``.

    ``sin(a + b)`` and the like are angles of their own: expand them first
    (``sp.expand_trig``) where the reduction should see through them.
    """
    expr = sp.expand(expr)
    while True:
        powers = {
            p: p.base ** (p.exp - 2) * (1 - sp.cos(p.base.args[0]) ** 2)
            for p in expr.atoms(sp.Pow)
            if isinstance(p.base, sp.sin) and p.exp.is_Integer and p.exp >= 2
        }
        if not powers:
            return expr
        expr = sp.expand(expr.xreplace(powers))
