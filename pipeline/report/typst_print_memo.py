"""A SymPy printer that prints each distinct object once per :class:`PrintMemo` (the base of
:class:`pipeline.report.typst_math.TypstMathPrinter` and so of the breakable printer).

The PDF's equation forms repeat their parts: an equation's printed, derived and residual forms
share terms, and each form is printed twice, whole and as breakable inline math (below its top
level the breakable printer prints as the other). On the combined report, without a memo: 1199
orderings of a sum's terms for 237 distinct sums; the forms' printing took 0.63 CPU-s, with
one memo per paper 0.49 (medians of 7 alternating runs; the same Typst source).

>>> import sympy as sp
>>> class Upper(MemoPrinter):
...     def _print_Symbol(self, expr):
...         return expr.name.upper()
>>> memo = PrintMemo()
>>> Upper(memo=memo).doprint(sp.Symbol("x")), memo
('X', {x: 'X'})
"""

from __future__ import annotations

from typing import Any

import sympy as sp
from sympy.printing.printer import Printer

__all__ = ["MemoPrinter", "PrintMemo"]


class PrintMemo(dict):
    """The text of each SymPy object printed with one set of printer settings (one printer
    class, or classes that print objects alike)."""


class MemoPrinter(Printer):
    """A :class:`~sympy.printing.printer.Printer` whose ``_print`` looks each SymPy object up
    in its memo first (none: prints as the base class)."""

    def __init__(self, settings: dict[str, Any] | None = None, memo: PrintMemo | None = None):
        super().__init__(settings)
        self._memo = memo

    def _print(self, expr: Any, **kwargs: Any) -> str:
        """An object's text; with a memo, each distinct SymPy object printed once (its text
        depends on it and the settings only; SymPy's equality is structural and strict: 1, 1.0
        and 1.00 are three keys)."""
        memo = self._memo
        if memo is None or kwargs or not isinstance(expr, sp.Basic):
            return super()._print(expr, **kwargs)
        text = memo.get(expr)
        if text is None:
            text = memo[expr] = super()._print(expr)
        return text
