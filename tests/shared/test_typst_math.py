"""SymPy -> Typst math printer (pipeline/report/typst_math.py).

Unit tests of single outputs, a compile test of tricky expressions, and the full corpus: every
printed, derived and residual form in the three papers' ``equation_math.json`` is printed and
compiled in one Typst document with zero errors and zero warnings. The corpus comes from
``results/`` when the workflow has run, else from the reduced workflow run that the report
tests share (``results_repo`` of tests/conftest.py).
"""

from __future__ import annotations

import json
from pathlib import Path

import pytest
import sympy as sp

from pipeline.report.typst_breakable import typst_math_breakable
from pipeline.report.typst_math import PrintMemo, symbol_name, typst_math
from tests.workflow_harness import NEEDS_RUN

typst = pytest.importorskip("typst")

ROOT = Path(__file__).resolve().parents[2]
SLUGS = ("north_finding", "platform_drift", "altimeter_attitude")
FORMS = ("printed_srepr", "derived_srepr", "residual_srepr")


def srepr_to_expr(text: str):
    """A SymPy object from ``sympy.srepr`` output (``sympify`` would re-evaluate it; ``eval``
    in SymPy's namespace rebuilds exactly the recorded tree; a tuple stays a tuple)."""
    return eval(text, vars(sp).copy())  # noqa: S307 - our own results files


def compile_math(snippets: list[str], tmp_path: Path) -> list:
    """Compile one document with every snippet as a block and as an inline equation; returns the
    warnings (an error raises typst.TypstError naming the first failing snippet's line)."""
    body = ["#set page(width: 16cm, height: auto)"]
    for i, s in enumerate(snippets):
        body.append(f"// {i}\n$ {s} $\n\n${s}$\n")
    src = tmp_path / "math.typ"
    src.write_text("\n".join(body), encoding="utf-8")
    _, warnings = typst.compile_with_warnings(
        str(src), format="pdf", root=str(tmp_path), ignore_system_fonts=True
    )
    return warnings


# ------------------------------------------------------------------------------------------
# single outputs
# ------------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("name", "expected"),
    [
        ("phi", "phi"),
        ("theta", "theta"),
        ("Omega", "Omega"),
        ("x", "x"),
        ("omega_x", "omega_x"),
        ("omegat_x", '"omegat"_x'),
        ("c_q", "c_q"),
        ("Delta_t", "Delta_t"),
        ("DeltaV_x", "Delta V_x"),
        ("P_prev_11", 'P_("prev", 11)'),
        ("xhat_1", "hat(x)_1"),
        ("G1_12", "G_(1, 12)"),
        ("C11", "C_11"),
        ("sigma_g2", "sigma_(g 2)"),
        ("V_d", "V_d"),
        ("k_sh", "k_(s h)"),
        ("b_g1", "b_(g 1)"),
        ("b_g1_dot", "dot(b)_(g 1)"),
        ("psi_dot", "dot(psi)"),
        ("phi_i_ddot", "dot.double(phi)_i"),
        ("R_GMM", 'R_"GMM"'),
        ("f_norm", 'f_"norm"'),
        ("xpred_1", '"xpred"_1'),
        ("A'", "A'"),
        ("ell", "ell"),
    ],
)
def test_symbol_names(name, expected):
    assert symbol_name(name) == expected
    assert typst_math(sp.Symbol(name)) == expected


def test_a_papers_stems_are_passed_not_built_in():
    from pipeline.altimeter_attitude.paper import PAPER

    stems = PAPER.math_stems
    assert symbol_name("omegat_x", stems) == "tilde(omega)_x"
    assert symbol_name("ft_x", stems) == "tilde(f)_x"
    assert typst_math(sp.Symbol("ft_x") + 1, stems=stems) == "tilde(f)_x + 1"
    assert symbol_name("ft_x") == "f t_x"  # two letters side by side without the paper's stems


x, y, t, theta = sp.symbols("x y t theta", real=True)
f = sp.Function("f")


@pytest.mark.parametrize(
    ("expr", "expected"),
    [
        (sp.sin(theta) ** 2, "sin(theta)^2"),
        (x / 2, "frac(x, 2)"),
        (-x / 2, "-frac(x, 2)"),
        ((x + 1) / (y - 1), "frac(x + 1, y - 1)"),
        (x**-2, "frac(1, x^2)"),
        (1 / sp.sqrt(x), "frac(1, sqrt(x))"),
        (sp.sqrt(x + y), "sqrt(x + y)"),
        (x ** sp.Rational(2, 3), "x^(2/3)"),
        (sp.Rational(-3, 4), "-frac(3, 4)"),
        (sp.Matrix([[1, x], [y, 2]]), 'mat(delim: "[", 1, x; y, 2)'),
        (sp.Matrix([x, y]), 'mat(delim: "[", x; y)'),
        (sp.atan2(y, x), '"atan2"(y, x)'),
        (sp.asin(x), "arcsin(x)"),
        (sp.atan(x), "arctan(x)"),
        (sp.Abs(x), "abs(x)"),
        (sp.exp(-(x**2)), "e^(-x^2)"),
        (sp.pi * x, "pi x"),
        (sp.Eq(x, y), "x = y"),
        (x - 2 * y, "x - 2 y"),
        (-x + y, "-x + y"),
        ((x + y) ** 2, "(x + y)^2"),
        (3 * 2**x, "3 dot 2^x"),
        (sp.Derivative(f(t), t), "frac(d, d t) f(t)"),
        (sp.Float(1.5e-7), "1.5 times 10^(-7)"),
        ((x, y), "x, quad y"),
    ],
)
def test_expressions(expr, expected):
    assert typst_math(expr) == expected


def test_breakable_keeps_sums_at_top_level():
    expr = (x + y) * (x - y) / (t + 1)
    assert "frac(" not in typst_math_breakable(x + y)
    text = typst_math_breakable(expr)
    # a sum in the denominator goes after a literal slash, so it can break too (frac cannot)
    assert text.endswith("\\/ \\( t + 1 \\)") and "frac(" not in text
    assert text.count("\\(") == text.count("\\)") == 3
    assert typst_math_breakable((x + y) / (t * x)).startswith("frac(1, t x)")
    assert typst_math_breakable(sp.Matrix([x])) == typst_math(sp.Matrix([x]))


TRICKY = [
    sp.Matrix([[sp.atan2(y, x), (x + y) / 2], [sp.sin(x) ** -2, -(x**-1)]]),
    sp.Matrix(3, 1, [sp.Symbol("omegat_x"), sp.Symbol("ft_y"), sp.Symbol("P_pred_11")]),
    sp.Piecewise((x, x > 0), (-x, True)),
    sp.Derivative(f(t), (t, 2)) + sp.Derivative(sp.Function("phi_x")(t, x), t, x),
    sp.kronecker_product(sp.Matrix([[1, x], [0, 1]]), sp.Matrix([[y]])),
    sp.KroneckerProduct(sp.MatrixSymbol("Q", 2, 2), sp.MatrixSymbol("P", 2, 2)),
    sp.MatrixSymbol("Gamma", 2, 4) * sp.MatrixSymbol("Q", 4, 4) * sp.MatrixSymbol("Gamma", 2, 4).T,
    sp.Inverse(sp.MatrixSymbol("S", 2, 2)),
    sp.Symbol("A'") ** 2 + sp.Symbol("B'"),
    sp.E ** (sp.I * sp.pi) + sp.oo - sp.zoo * 0 + sp.nan,
    sp.Float(123456789.0) + sp.Float(1e-12) + sp.Float(0.5),
    sp.Integral(sp.sin(x), (x, 0, sp.pi)),
    sp.sign(x) * sp.floor(y) * sp.Max(x, y) * sp.log(x) * sp.sinh(x),
    sp.And(x > 0, y <= 1) | sp.Not(sp.Eq(x, y)),
    sp.Subs(f(x).diff(x), x, 0),
    sp.Symbol('weird"name\\#$'),
    sp.Symbol("Deltaxdot_0") * sp.Symbol("w_en_x") * sp.Symbol("theta_F1") / sp.Symbol("GM"),
    sp.Matrix(0, 0, []),
    sp.Tuple(x, sp.Matrix([y])),
]


def test_memo_prints_the_same():
    """Printed with one memo shared by both printers, in an order that prints parts before the
    wholes and the wholes again, every expression has the text it has without a memo (a key
    that confused 1 with 1.0, or the breakable top level with the other, would differ)."""
    memo = PrintMemo()
    parts = [x + 1, x + 1.0, x + sp.Float(1.0, 30), (x + 1) / (y - 1), t * (x + y) / (x - 1)]
    exprs = [*parts, *TRICKY, *parts, *TRICKY]
    for e in exprs:
        assert typst_math(e, memo=memo) == typst_math(e)
        assert typst_math_breakable(e, memo=memo) == typst_math_breakable(e)
    assert len(set(parts[:3]) & memo.keys()) == 3  # three keys, whatever their texts


def test_tricky_expressions_compile(tmp_path):
    snippets = [typst_math(e) for e in TRICKY] + [typst_math_breakable(e) for e in TRICKY]
    assert compile_math(snippets, tmp_path) == []


# ------------------------------------------------------------------------------------------
# the full corpus of the equation audits
# ------------------------------------------------------------------------------------------
def corpus(root: Path) -> list[tuple[str, str, str, object]]:
    items = []
    for slug in SLUGS:
        path = root / "results" / slug / "equation_math.json"
        for rec in json.loads(path.read_text(encoding="utf-8")):
            for form in FORMS:
                if rec.get(form):
                    items.append((slug, rec["equation"], form, srepr_to_expr(rec[form])))
    return items


@pytest.mark.parametrize("_", [pytest.param(None, marks=NEEDS_RUN)])
def test_every_audit_expression_typesets(results_repo, tmp_path, _):
    items = corpus(results_repo)
    assert {slug for slug, *_ in items} == set(SLUGS)
    assert len(items) > 300  # 402 when written
    snippets, failed = [], []
    for slug, eq, form, expr in items:
        try:
            snippets += [typst_math(expr), typst_math_breakable(expr)]
        except Exception as exc:  # noqa: BLE001 - collect every failure
            failed.append(f"{slug} {eq} {form}: {exc!r}")
    assert failed == []
    # a compile error names the failing line: the comment above it names the snippet
    try:
        warnings = compile_math(snippets, tmp_path)
    except typst.TypstError as exc:
        pytest.fail(f"typst: {exc.message}\n{exc.diagnostic}"[:3000])
    assert [w.message for w in warnings] == []
