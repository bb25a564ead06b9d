"""The equation-audit core (derivations/checks.py): every ``differs`` names what the seed text
shows (a discrepancy of derivations.discrepancies), its kind (``pipeline.columns.DIFFERS_KINDS``)
follows from that by one rule, and a difference without a discrepancy is an error, not a row."""

from __future__ import annotations

import pytest
import sympy as sp

from derivations.checks import Check, audit_frame, audit_outputs, run_check
from derivations.discrepancies import DISCREPANCIES, inconsistencies, kind_of
from pipeline.columns import AUDIT_COLUMNS, DIFFERS_KINDS

x = sp.Symbol("x", real=True)


def test_the_kinds_and_their_labels():
    assert list(DIFFERS_KINDS) == [
        "paper_error",
        "text_artefact",
        "convention",
        "unclear_from_text",
    ]
    assert DIFFERS_KINDS["paper_error"] == "error of the paper"
    assert DIFFERS_KINDS["text_artefact"] == "artefact of the text"
    assert DIFFERS_KINDS["convention"] == "approximation or convention"
    assert DIFFERS_KINDS["unclear_from_text"] == "cannot tell from the text"
    assert AUDIT_COLUMNS[AUDIT_COLUMNS.index("note") + 1] == "kind"


# the rule: each discrepancy gives one kind, every kind is reached, and the order of the table
# is the order of precedence (convention, then an error of the paper, then the text's)
def test_the_rule_gives_each_discrepancy_one_allowed_kind():
    assert {kind for kind, _ in DISCREPANCIES.values()} == set(DIFFERS_KINDS)
    assert {d: kind_of(d) for d in DISCREPANCIES} == {
        "approximation": "convention",
        "notation": "convention",
        "wrong_term": "paper_error",
        "repeated_slip": "paper_error",
        "visible_garble": "text_artefact",
        "one_mark": "unclear_from_text",
    }
    for _, test in DISCREPANCIES.values():
        assert len(test) > 60  # each kind's test is written out


def test_two_rows_with_the_same_discrepancy_get_the_same_kind():
    # the kind is not an argument of a check: it cannot be set apart from the discrepancy
    with pytest.raises(TypeError):
        Check("1", printed=x, derived=2 * x, differs_kind="paper_error", if_differs="e")  # type: ignore[call-arg]
    frame, records = audit_outputs(
        [
            Check("58", printed=x, derived=2 * x, discrepancy="one_mark", if_differs="bar"),
            Check("67", printed=x, derived=3 * x, discrepancy="one_mark", if_differs="bar"),
            Check("22", printed=x, derived=4 * x, discrepancy="wrong_term", if_differs="l"),
        ]
    )
    assert list(frame["kind"]) == ["unclear_from_text", "unclear_from_text", "paper_error"]
    rows = [(r["equation"], r["discrepancy"], r["kind"]) for r in records]
    assert inconsistencies(rows) == []
    # ... and the check of the outputs fails on rows that break the rule
    broken = [*rows[:1], ("67", "one_mark", "paper_error"), ("9", "", "text_artefact")]
    assert inconsistencies(broken) == [
        "eq. 67: one_mark gives unclear_from_text, the row says paper_error",
        "eq. 9: no known discrepancy ('')",
        "one_mark has two kinds: paper_error (67), unclear_from_text (58)",
    ]


# one synthetic check of each kind: a typo (a wrong factor), a scan artefact (a split line),
# a convention (a dropped higher-order term), a lone mark (a lost square)
@pytest.mark.parametrize(
    ("discrepancy", "kind", "printed", "derived", "residual"),
    [
        ("wrong_term", "paper_error", 2 * x, 3 * x, "-x"),
        ("visible_garble", "text_artefact", 1 / x + x, (1 + x) / x, "x - 1"),
        ("approximation", "convention", 1 + x, sp.exp(x), "x - exp(x) + 1"),
        ("one_mark", "unclear_from_text", sp.cos(x), sp.cos(x) ** 2, "(1 - cos(x))*cos(x)"),
    ],
)
def test_a_differs_row_carries_its_kind(discrepancy, kind, printed, derived, residual):
    check = Check(
        "9", printed=printed, derived=derived, discrepancy=discrepancy, if_differs="evidence"
    )
    row = run_check(check)
    assert (row.status, row.residual, row.note, row.kind) == ("differs", residual, "evidence", kind)
    assert row.discrepancy == discrepancy
    assert row.as_dict() == {
        "equation": "9",
        "status": "differs",
        "residual": residual,
        "note": "evidence",
        "kind": kind,
    }


def test_a_difference_without_a_kind_raises_naming_the_equation_and_the_kinds():
    with pytest.raises(ValueError) as err:
        run_check(Check("47.E", printed=2 * x, derived=3 * x))
    message = str(err.value)
    assert message.startswith("eq. 47.E: printed and derived forms differ (residual -x)")
    for discrepancy, (kind, _) in DISCREPANCIES.items():
        assert f"{discrepancy} ({kind})" in message


def test_a_long_residual_is_shortened_in_the_error():
    wide = sum(sp.Symbol(f"y_{k}") for k in range(200))
    with pytest.raises(ValueError, match=r"^eq\. 5: .*\.\.\.\) but the check records no") as err:
        run_check(Check("5", printed=wide, derived=0))
    assert len(str(err.value)) < 600  # the 200 symbols in full would take over 1000


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        (
            {"discrepancy": "typo", "if_differs": "evidence"},
            "eq. 12: discrepancy 'typo' is not one of approximation (convention), notation "
            "(convention), wrong_term (paper_error), repeated_slip (paper_error), "
            "visible_garble (text_artefact), one_mark (unclear_from_text)",
        ),
        (
            {"if_differs": "evidence"},
            "eq. 12: if_differs is given without discrepancy; give one of approximation",
        ),
        (
            {"discrepancy": "notation"},
            "eq. 12: discrepancy 'notation' is given without if_differs, the judgement and "
            "its evidence",
        ),
    ],
)
def test_a_kind_and_its_evidence_go_together(kwargs, message):
    with pytest.raises(ValueError) as err:
        Check("12", printed=x, derived=x, **kwargs)
    assert str(err.value).startswith(message)


def test_match_and_not_checkable_rows_have_no_kind():
    match = run_check(
        Check("1", printed=sp.sin(x) ** 2, derived=1 - sp.cos(x) ** 2, **_judged("wrong_term"))
    )
    assert (match.status, match.kind) == ("match", "")
    nc = run_check(Check("2", not_checkable="a definition"))
    assert (nc.status, nc.kind) == ("not_checkable", "")


def test_the_audit_frame_writes_the_kind_column():
    frame = audit_frame(
        [
            Check("1", printed=x, derived=x),
            Check("2", printed=2 * x, derived=x, **_judged("visible_garble")),
            Check("3", not_checkable="absent from the seed text"),
        ]
    )
    assert list(frame.columns) == AUDIT_COLUMNS
    assert list(frame["kind"]) == ["", "text_artefact", ""]


def _judged(discrepancy: str) -> dict[str, str]:
    return {"discrepancy": discrepancy, "if_differs": "a judgement with its evidence"}


# the simplify budget of a residual's text is CPU time, so the text does not depend on the load
def test_waiting_does_not_use_up_the_simplify_budget(monkeypatch):
    import time

    import derivations.residual_tidy as rt

    def slow_but_idle(expr):
        time.sleep(0.5)  # wall-clock time, no CPU: what a loaded machine adds
        return sp.Symbol("simplified")

    monkeypatch.setattr(rt, "SIMPLIFY_SECONDS", 0.1)
    monkeypatch.setattr(rt.sp, "simplify", slow_but_idle)
    assert rt.tidy(2 * x + 2) == sp.Symbol("simplified")


def test_a_residual_over_the_cpu_budget_is_shown_factored(monkeypatch):
    import time

    import derivations.residual_tidy as rt

    def busy(expr):
        end = time.process_time() + 5.0
        while time.process_time() < end:
            pass
        return sp.Symbol("simplified")

    monkeypatch.setattr(rt, "SIMPLIFY_SECONDS", 0.1)
    monkeypatch.setattr(rt.sp, "simplify", busy)
    assert str(rt.tidy(2 * x + 2)) == "2*(x + 1)"  # factor_terms, not the simplified form


# a residual of more than LARGE_OPS operations after trigsimp gets the shorter of simplify's
# first two candidates instead of simplify's further (costly) passes
def _large_residual() -> sp.Expr:
    a, b, c = sp.symbols("a b c", real=True)
    y, z = sp.symbols("y z", real=True)
    terms = a * sp.sin(x) + b * sp.cos(y) + c * sp.sin(z)
    return sp.expand((terms + 1) ** 3 - terms**3)


def test_a_large_residual_is_shown_as_simplify_shows_it_without_calling_it(monkeypatch):
    import derivations.residual_tidy as rt

    residual = _large_residual()
    assert sp.count_ops(sp.trigsimp(residual)) > rt.LARGE_OPS
    expected = sp.simplify(sp.trigsimp(residual))

    def not_called(expr):
        raise AssertionError("simplify called on a large residual")

    monkeypatch.setattr(rt.sp, "simplify", not_called)
    assert rt.tidy(residual) == expected


def test_a_small_residual_still_goes_through_simplify(monkeypatch):
    import derivations.residual_tidy as rt

    seen = []
    monkeypatch.setattr(rt.sp, "simplify", lambda expr: seen.append(expr) or expr)
    rt.tidy(sp.sin(x) ** 2 + sp.cos(x) ** 2 + x)
    assert seen == [x + 1]


def test_the_large_form_is_the_shorter_candidate_and_equals_the_residual():
    import derivations.residual_tidy as rt

    a, b, c = sp.symbols("a b c", real=True)
    split = a / (x + 1) + b / (x + 1) - c / (x + 1) + a * b / (x + 1)
    shown = rt._tidy_large(split)
    assert shown == (a * b + a + b - c) / (x + 1)  # cancelled: fewer operations
    assert sp.simplify(shown - split) == 0
    residual = _large_residual()  # a polynomial: cancelling gains nothing, it stays as it is
    assert sp.expand(rt._tidy_large(residual) - residual) == 0


# SymPy's factoring draws random points: each residual is tidied from the generator freshly
# seeded, so the draws (hence the work, not the result) do not depend on what ran before it
def test_each_residual_is_tidied_from_a_freshly_seeded_generator(monkeypatch):
    import sympy.core.random as sympy_random

    import derivations.residual_tidy as rt

    draws = []
    real = rt._simplified
    monkeypatch.setattr(rt, "_simplified", lambda r: draws.append(sympy_random.random()) or real(r))
    residual = sp.sin(x) ** 2 + sp.cos(x) ** 2 + x
    shown = [rt.tidy(residual)]
    for _ in range(3):  # another random state before the next tidy
        sympy_random.random()
    shown.append(rt.tidy(residual))
    assert draws[0] == draws[1] and shown == [x + 1, x + 1]


def test_a_repeated_residual_is_tidied_once_and_shown_for_every_element(monkeypatch):
    import derivations.checks as checks

    calls = []
    real = checks._tidy
    monkeypatch.setattr(checks, "_tidy", lambda r: calls.append(r) or real(r))
    printed = sp.Matrix([[2 * x, 2 * x], [x, 2 * x]])
    derived = sp.Matrix([[3 * x, 3 * x], [x, 3 * x]])
    row = run_check(Check("m", printed, derived, **_judged("wrong_term")))
    assert sorted(calls, key=str) == [-x, 0]
    assert row.residual == "-x; -x; 0; -x"


def _numeric_residual_point_by_point(residuals, scales, sample=None, seed=0) -> float:
    """numeric_residual as it was written before it called its function on all points at once:
    one call per point, the worst finite ratio kept (a NaN ratio never replaces it)."""
    import numpy as np

    from derivations.checks import N_POINTS

    symbols = sorted(set().union(*(e.free_symbols for e in [*residuals, *scales])), key=str)
    rng = np.random.default_rng(seed)
    values_at = sp.lambdify(symbols, [*residuals, *scales], "numpy")
    n, worst = len(residuals), 0.0
    for _ in range(N_POINTS):
        point = [rng.uniform(*((sample or {}).get(s, (0.15, 1.3)))) for s in symbols]
        with np.errstate(all="ignore"):
            values = [complex(v) for v in values_at(*point)]
        for r, s in zip(values[:n], values[n:], strict=True):
            if np.isfinite(r):
                worst = max(worst, abs(r) / (abs(s) + 1e-300))
    return worst


def test_the_numeric_residual_is_the_one_of_a_call_per_point():
    from derivations.checks import numeric_residual

    y = sp.Symbol("y", real=True)
    cases = [
        ([sp.sin(x) * sp.cos(y) - sp.sin(x + y) / 2, sp.S(3)], [sp.Abs(sp.sin(x)) + 1, sp.S.One]),
        ([sp.sqrt(x - 1) - x, x], [x + 1, sp.nan]),  # NaN residuals skipped, NaN scale ignored
        ([sp.atan2(y, -x) + sp.tan(x) * y], [sp.Abs(sp.tan(x) * y) + 1]),
        ([sp.S(2)], [sp.S.One]),  # no symbols at all
    ]
    for residuals, scales in cases:
        assert numeric_residual(residuals, scales) == _numeric_residual_point_by_point(
            residuals, scales
        )
    sample = {x: (2.0, 3.0)}
    residuals, scales = [sp.sqrt(x - 1) - x], [x]
    assert numeric_residual(residuals, scales, sample, seed=3) == (
        _numeric_residual_point_by_point(residuals, scales, sample, seed=3)
    )


def test_the_numeric_residual_of_several_elements_is_the_worst_element():
    from derivations.checks import numeric_residual

    y = sp.Symbol("y", real=True)
    residuals = [sp.sin(x) - x + y * 1e-3, x**2 - x * y, sp.S.Zero]
    scales = [sp.Abs(sp.sin(x)) + x, x**2 + x * y, sp.S.One]
    # one element at a time, at the same points (a zero element whose scale has both symbols)
    each = [
        numeric_residual([r, sp.S.Zero], [s, x + y]) for r, s in zip(residuals, scales, strict=True)
    ]
    assert numeric_residual(residuals, scales) == max(each) > 0
    # each residual is paired with its own scale
    assert numeric_residual(residuals[:2], scales[::-1][1:]) != max(each[:2])
