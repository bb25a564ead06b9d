"""SymPy expressions as Typst math for an *inline* equation that may break across lines (the
PDF's fallback for an expression wider than the page): Typst breaks an inline equation after
top-level ``+``, ``-`` and relations only, so the printer keeps sums at the top level.
"""

from __future__ import annotations

from typing import Any

import sympy as sp
from sympy.printing.precedence import PRECEDENCE

from pipeline.report.typst_math import PrintMemo, TypstMathPrinter

__all__ = ["typst_math_breakable"]


class _BreakablePrinter(TypstMathPrinter):
    """For inline (line-breaking) math: Typst breaks an inline equation after top-level ``+``,
    ``-`` and relations only, never inside ``frac`` or a ``(...)`` group. This printer keeps
    sums at the top level: ``frac(a + b, c)`` becomes ``frac(1, c) \\( a + b \\)``, a sum inside
    a product is bracketed with literal parentheses (which do not form a group), and a sum in a
    denominator is written after a literal slash: ``\\( a + b \\) \\/ \\( c + d \\)``."""

    def _top(self, expr: Any) -> str:
        if isinstance(expr, sp.Add):
            out = ""
            for i, term in enumerate(self._as_ordered_terms(expr, order=self._settings["order"])):
                text = self._top(term)
                if text.startswith("-"):
                    out += ("-" if i == 0 else " - ") + text[1:].lstrip()
                else:
                    out += text if i == 0 else " + " + text
            return out
        if isinstance(expr, sp.Mul) and any(isinstance(f, sp.Add) for f in self._flat(expr)):
            sign, num, den = self._split_fraction(expr)
            order = {a: i for i, a in enumerate(expr.as_ordered_factors())}
            num.sort(key=lambda a: order.get(a, -1))
            parts = []
            for f in num:
                if isinstance(f, sp.Add):
                    parts.append(f"\\( {self._top(f)} \\)")
                else:
                    parts.append(self.parenthesize(f, PRECEDENCE["Mul"]))
            if any(isinstance(d, sp.Add) for d in den):
                # a sum in the denominator: "(num) / (den)" with literal parentheses and slash,
                # so both sums break across lines (a frac never does)
                top = " ".join(parts) if parts else "1"
                return ("-" if sign < 0 else "") + f"{top} \\/ \\( {self._top(sp.Mul(*den))} \\)"
            if den:
                parts.insert(0, f"frac(1, {self._product(den)})")
            return ("-" if sign < 0 else "") + " ".join(parts)
        return self._print(expr)

    def _flat(self, expr: sp.Mul) -> list[Any]:
        out = []
        for f in expr.args:
            if f.is_Pow and f.exp.is_negative:
                out.append(f.base)
            out.append(f)
        return out


def typst_math_breakable(expr: Any, *, memo: PrintMemo | None = None, **settings: Any) -> str:
    """Like :func:`typst_math`, for an *inline* equation that may break across lines: the
    top-level sum of a scalar expression stays breakable (also inside a fraction's numerator or
    a product). Matrices and tuples print as :func:`typst_math` would. ``memo``: as for
    :func:`typst_math`, and the same one may serve both (only the breakable top level, which
    is not memoised, differs; below it this printer is :func:`typst_math`'s)."""
    printer = _BreakablePrinter(settings, memo)
    if isinstance(expr, (tuple, list, sp.Tuple)):
        return ", quad ".join(printer._top(sp.sympify(e)) for e in expr)
    return printer._top(sp.sympify(expr))
