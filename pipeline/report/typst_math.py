"""SymPy expressions as Typst math-mode source (for the PDF report).

``typst_math(expr)`` returns what goes between ``$ ... $`` in a Typst document: no delimiters,
no ``#`` code, only math syntax, so the result can be pasted into any equation. Symbol names
are printed by :func:`pipeline.report.typst_symbols.symbol_name` (its docstring has the
conventions); a paper's own stems are passed as ``stems``:
``typst_math(x, stems={"xt": "tilde(x)"})``.

Matrices use square brackets (``mat(delim: "[", ...)``), fractions ``frac(a, b)``, square roots
``sqrt``; ``atan2`` is upright text applied to its arguments; ``Abs`` is ``abs``. Anything the
printer does not know becomes its class name as upright text applied to the printed arguments,
so the output is always valid Typst.
"""

from __future__ import annotations

import re
from typing import Any

import sympy as sp
from sympy.core.function import AppliedUndef
from sympy.printing.precedence import PRECEDENCE, precedence

from pipeline.report.typst_print_memo import MemoPrinter, PrintMemo
from pipeline.report.typst_symbols import symbol_name, typst_string

__all__ = ["PrintMemo", "TypstMathPrinter", "symbol_name", "typst_math", "typst_string"]

FUNCTIONS = {
    "sin": "sin",
    "cos": "cos",
    "tan": "tan",
    "cot": "cot",
    "sec": "sec",
    "csc": "csc",
    "asin": "arcsin",
    "acos": "arccos",
    "atan": "arctan",
    "sinh": "sinh",
    "cosh": "cosh",
    "tanh": "tanh",
    "coth": "coth",
    "log": "ln",
    "Max": "max",
    "Min": "min",
    "det": "det",
    "exp_polar": "exp",
    "floor": "floor",
    "ceiling": "ceil",
}
#: SymPy function names printed as upright text (no Typst operator of that name).
TEXT_FUNCTIONS = {
    "atan2": "atan2",
    "acot": "arccot",
    "asec": "arcsec",
    "acsc": "arccsc",
    "asinh": "arsinh",
    "acosh": "arcosh",
    "atanh": "artanh",
    "sign": "sgn",
    "re": "Re",
    "im": "Im",
    "arg": "arg",
}


class TypstMathPrinter(MemoPrinter):
    """Typst math-mode printer; ``doprint(expr)`` returns the source without ``$``."""

    printmethod = "_typst"
    _default_settings: dict[str, Any] = {"order": None, "float_digits": 6, "stems": {}}

    # ---- helpers ------------------------------------------------------------------------
    def parenthesize(self, item: Any, level: int, strict: bool = False) -> str:
        prec = precedence(item)
        if prec < level or (strict and prec <= level):
            return f"({self._print(item)})"
        return self._print(item)

    def _group(self, text: str) -> str:
        """Wrap ``text`` in parentheses unless it is one token (for ``^``/``_`` arguments)."""
        if re.fullmatch(r"[A-Za-z]|[0-9]+|[A-Za-z][A-Za-z.]*", text):
            return text
        return f"({text})"

    def emptyPrinter(self, expr: Any) -> str:  # noqa: N802 - SymPy's printer API
        if isinstance(expr, str):
            return typst_string(expr)
        if isinstance(expr, (list, tuple)):
            return self._print_seq(expr)
        if isinstance(expr, sp.Basic) and expr.args:
            args = ", ".join(self._print(a) for a in expr.args)
            return f"{typst_string(type(expr).__name__)}({args})"
        return typst_string(str(expr))

    def _print_seq(self, seq: Any) -> str:
        return "(" + ", ".join(self._print(a) for a in seq) + ")"

    # ---- atoms --------------------------------------------------------------------------
    def _print_Symbol(self, expr: sp.Symbol) -> str:
        return symbol_name(expr.name, self._settings["stems"])

    _print_Dummy = _print_Symbol

    def _print_MatrixSymbol(self, expr: Any) -> str:
        return symbol_name(expr.name, self._settings["stems"])

    def _print_Integer(self, expr: sp.Integer) -> str:
        return str(expr.p)

    def _print_int(self, expr: int) -> str:
        return str(expr)

    def _print_Rational(self, expr: sp.Rational) -> str:
        if expr.q == 1:
            return str(expr.p)
        sign = "-" if expr.p < 0 else ""
        return f"{sign}frac({abs(expr.p)}, {expr.q})"

    def _print_Float(self, expr: sp.Float) -> str:
        return self._float(float(expr))

    def _print_float(self, expr: float) -> str:
        return self._float(expr)

    def _float(self, value: float) -> str:
        if value != value:  # NaN
            return typst_string("NaN")
        if value in (float("inf"), float("-inf")):
            return ("-" if value < 0 else "") + "infinity"
        text = f"{value:.{self._settings['float_digits']}g}"
        if "e" in text:
            mant, exp = text.split("e")
            return f"{mant} times 10^({int(exp)})"
        return text

    def _print_Pi(self, expr: Any) -> str:
        return "pi"

    def _print_Exp1(self, expr: Any) -> str:
        return "e"

    def _print_ImaginaryUnit(self, expr: Any) -> str:
        return "i"

    def _print_Infinity(self, expr: Any) -> str:
        return "infinity"

    def _print_NegativeInfinity(self, expr: Any) -> str:
        return "-infinity"

    def _print_ComplexInfinity(self, expr: Any) -> str:
        return "tilde(infinity)"

    def _print_NaN(self, expr: Any) -> str:
        return typst_string("NaN")

    def _print_BooleanTrue(self, expr: Any) -> str:
        return typst_string("true")

    def _print_BooleanFalse(self, expr: Any) -> str:
        return typst_string("false")

    # ---- arithmetic ---------------------------------------------------------------------
    def _print_Add(self, expr: sp.Add) -> str:
        terms = self._as_ordered_terms(expr, order=self._settings["order"])
        out = ""
        for i, term in enumerate(terms):
            text = self._print(term)
            if precedence(term) < PRECEDENCE["Add"]:
                text = f"({text})"
            if text.startswith("-"):
                out += ("-" if i == 0 else " - ") + text[1:].lstrip()
            else:
                out += text if i == 0 else " + " + text
        return out

    def _split_fraction(self, expr: sp.Mul) -> tuple[sp.Expr, list[Any], list[Any]]:
        """(sign coefficient, numerator factors, denominator factors) of a product."""
        coeff, rest = expr.as_coeff_mul()
        num: list[Any] = []
        den: list[Any] = []
        if coeff.is_Rational:
            if abs(coeff.p) != 1:
                num.append(sp.Integer(abs(coeff.p)))
            if coeff.q != 1:
                den.append(sp.Integer(coeff.q))
            sign = -1 if coeff < 0 else 1
        else:
            num.append(abs(coeff))
            sign = -1 if coeff < 0 else 1
        factors = sp.Mul(*rest, evaluate=False) if rest else sp.S.One
        for f in sp.Mul.make_args(factors) if rest else []:
            if (
                f.is_Pow
                and f.exp.is_Rational
                and f.exp.is_negative
                and not (f.base.is_Integer and f.exp != -1)
            ):
                den.append(f.base if f.exp == -1 else sp.Pow(f.base, -f.exp, evaluate=False))
            else:
                num.append(f)
        return sign, num, den

    def _product(self, factors: list[Any]) -> str:
        if not factors:
            return "1"
        if len(factors) == 1:
            return self._print(factors[0])
        parts: list[str] = []
        for f in factors:
            text = self.parenthesize(f, PRECEDENCE["Mul"])
            if text.startswith("-"):
                text = f"({text})"
            if parts and text[0].isdigit():
                parts.append("dot")  # "x 2" would read as x2
            parts.append(text)
        return " ".join(parts)

    def _print_Mul(self, expr: sp.Mul) -> str:
        if expr.args and any(isinstance(a, sp.MatrixBase) for a in expr.args):
            return " ".join(self.parenthesize(a, PRECEDENCE["Mul"]) for a in expr.args)
        sign, num, den = self._split_fraction(expr)
        # keep the printed order of SymPy (coefficient first, then sorted factors)
        order = {a: i for i, a in enumerate(expr.as_ordered_factors())}
        num.sort(key=lambda a: order.get(a, -1))
        # the numerator printed once: printing it again for the fraction (as this did) doubled
        # the work at every level of nested fractions (the PDF's equation forms: 1199 term
        # orderings of 237 distinct sums; the forms' printing 0.60 -> see the commit)
        body = self._product(num)
        if den:
            body = f"frac({body}, {self._product(den)})"
        return ("-" if sign < 0 else "") + body

    def _print_Pow(self, expr: sp.Pow) -> str:
        base, exp = expr.base, expr.exp
        if exp == sp.S.Half:
            return f"sqrt({self._print(base)})"
        if exp.is_Rational and exp.is_negative and not base.is_Integer:
            return f"frac(1, {self._print(sp.Pow(base, -exp, evaluate=False))})"
        if exp == -sp.S.Half:
            return f"frac(1, sqrt({self._print(base)}))"
        if base is sp.S.Exp1:
            return f"e^{self._group(self._print(exp))}"
        if exp.is_Rational and exp.q != 1:
            exp_text = f"{exp.p}/{exp.q}"
        else:
            exp_text = self._print(exp)
        base_text = self._print(base)
        if (
            precedence(base) <= PRECEDENCE["Pow"]
            or base_text.startswith("-")
            or (base.is_Number and not base.is_Integer)
            or "^" in base_text
            or base_text.endswith("'")
        ):
            base_text = f"({base_text})"
        return f"{base_text}^{self._group(exp_text)}"

    # ---- functions ----------------------------------------------------------------------
    def _args(self, expr: Any) -> str:
        return ", ".join(self._print(a) for a in expr.args)

    def _print_Function(self, expr: Any) -> str:
        name = type(expr).__name__
        if name in FUNCTIONS:
            return f"{FUNCTIONS[name]}({self._args(expr)})"
        if name in TEXT_FUNCTIONS:
            return f"{typst_string(TEXT_FUNCTIONS[name])}({self._args(expr)})"
        if isinstance(expr, AppliedUndef):
            head = symbol_name(name)
            # "phi_x(t)" would put "(t)" into the subscript: a space ends the attachment
            sep = " " if ("_" in head or "^" in head) else ""
            return f"{head}{sep}({self._args(expr)})"
        return f"{typst_string(name)}({self._args(expr)})"

    def _print_exp(self, expr: Any) -> str:
        return f"e^{self._group(self._print(expr.args[0]))}"

    def _print_Max(self, expr: Any) -> str:
        return f"max({self._args(expr)})"

    def _print_Min(self, expr: Any) -> str:
        return f"min({self._args(expr)})"

    def _print_Integral(self, expr: Any) -> str:
        out = ""
        for lim in expr.limits:
            if len(lim) == 3:
                low, high = (self._group(self._print(b)) for b in lim[1:])
                out += f"integral_{low}^{high} "
            else:
                out += "integral "
        body = self.parenthesize(expr.function, PRECEDENCE["Mul"])
        dvars = " ".join(f"dif {self._print(lim[0])}" for lim in expr.limits)
        return f"{out}{body} {dvars}"

    def _print_Abs(self, expr: Any) -> str:
        return f"abs({self._print(expr.args[0])})"

    def _print_sqrt(self, expr: Any) -> str:  # pragma: no cover - sqrt is a Pow in SymPy
        return f"sqrt({self._print(expr.args[0])})"

    def _print_Derivative(self, expr: sp.Derivative) -> str:
        variables = list(expr.variable_count)
        total = sum(n for _, n in variables)
        d = "partial" if len(variables) > 1 or len(expr.expr.free_symbols) > 1 else "d"
        den = " ".join(f"{d} {self._print(v)}" + (f"^{n}" if n != 1 else "") for v, n in variables)
        num = d + (f"^{total}" if total != 1 else "")
        inner = self.parenthesize(expr.expr, PRECEDENCE["Mul"])
        return f"frac({num}, {den}) {inner}"

    def _print_Subs(self, expr: Any) -> str:
        inner, old, new = expr.args
        at = ", ".join(
            f"{self._print(o)} = {self._print(n)}" for o, n in zip(old, new, strict=True)
        )
        return f"lr(({self._print(inner)}) |)_({at})"

    # ---- relations, logic, piecewise ----------------------------------------------------
    _REL = {"==": "=", "!=": "!=", "<": "<", "<=": "<=", ">": ">", ">=": ">="}

    def _print_Relational(self, expr: Any) -> str:
        op = self._REL.get(expr.rel_op, typst_string(expr.rel_op))
        return f"{self._print(expr.lhs)} {op} {self._print(expr.rhs)}"

    def _print_And(self, expr: Any) -> str:
        return ' "and" '.join(self.parenthesize(a, PRECEDENCE["And"]) for a in expr.args)

    def _print_Or(self, expr: Any) -> str:
        return ' "or" '.join(self.parenthesize(a, PRECEDENCE["Or"]) for a in expr.args)

    def _print_Not(self, expr: Any) -> str:
        return f"not {self.parenthesize(expr.args[0], PRECEDENCE['Not'])}"

    def _print_Piecewise(self, expr: sp.Piecewise) -> str:
        rows = []
        for e, c in expr.args:
            cond = '"otherwise"' if c is sp.true else f'"if " {self._print(c)}'
            rows.append(f"{self._print(e)} & {cond}")
        return "cases(" + ", ".join(rows) + ")"

    # ---- containers ---------------------------------------------------------------------
    def _print_MatrixBase(self, expr: Any) -> str:
        if expr.rows == 0 or expr.cols == 0:
            return 'mat(delim: "[", )'
        rows = "; ".join(
            ", ".join(self._print(expr[i, j]) for j in range(expr.cols)) for i in range(expr.rows)
        )
        return f'mat(delim: "[", {rows})'

    def _print_Tuple(self, expr: Any) -> str:
        return self._print_seq(expr.args)

    def _print_tuple(self, expr: tuple) -> str:
        return self._print_seq(expr)

    _print_list = _print_tuple

    # ---- matrix expressions -------------------------------------------------------------
    def _print_KroneckerProduct(self, expr: Any) -> str:
        return " times.o ".join(
            self.parenthesize(a, PRECEDENCE["Mul"], strict=True) for a in expr.args
        )

    _print_TensorProduct = _print_KroneckerProduct

    def _print_MatMul(self, expr: Any) -> str:
        return " ".join(self.parenthesize(a, PRECEDENCE["Mul"]) for a in expr.args)

    def _print_MatAdd(self, expr: Any) -> str:
        return " + ".join(self.parenthesize(a, PRECEDENCE["Add"]) for a in expr.args)

    def _print_Transpose(self, expr: Any) -> str:
        return f"{self.parenthesize(expr.arg, PRECEDENCE['Pow'], strict=True)}^T"

    def _print_Inverse(self, expr: Any) -> str:
        return f"{self.parenthesize(expr.arg, PRECEDENCE['Pow'], strict=True)}^(-1)"

    def _print_MatPow(self, expr: Any) -> str:
        base = self.parenthesize(expr.base, PRECEDENCE["Pow"], strict=True)
        return f"{base}^{self._group(self._print(expr.exp))}"

    def _print_Identity(self, expr: Any) -> str:
        return "I"

    def _print_ZeroMatrix(self, expr: Any) -> str:
        return "0"


def typst_math(expr: Any, *, memo: PrintMemo | None = None, **settings: Any) -> str:
    """Typst math-mode source of a SymPy expression, matrix, or tuple/list of them.

    A top-level tuple or list prints its members separated by commas (no parentheses), as the
    audits record several parts of one equation that way. ``memo``: the texts of the objects
    printed so far with the same ``settings`` (see :class:`PrintMemo`), filled here.

    >>> x, y = sp.symbols("x y")
    >>> memo = PrintMemo()
    >>> typst_math((x + y) / (x - y), memo=memo), typst_math(x + y, memo=memo) == typst_math(x + y)
    ('frac(x + y, x - y)', True)
    >>> memo[x - y]
    'x - y'
    """
    printer = TypstMathPrinter(settings, memo)
    if isinstance(expr, (tuple, list, sp.Tuple)):
        return ", quad ".join(printer.doprint(sp.sympify(e)) for e in expr)
    return printer.doprint(expr)
