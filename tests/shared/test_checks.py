"""The equation-audit core (derivations/checks.py): every ``differs`` carries one of the kinds of
``pipeline.columns.DIFFERS_KINDS``, and a difference without a kind is an error, not a row."""

from __future__ import annotations

import pytest
import sympy as sp

from derivations.checks import Check, audit_frame, run_check
from pipeline.columns import AUDIT_COLUMNS, DIFFERS_KINDS

x = sp.Symbol("x", real=True)


def test_the_kinds_and_their_labels():
    assert list(DIFFERS_KINDS) == ["paper_error", "text_artefact", "convention"]
    assert DIFFERS_KINDS["paper_error"] == "error of the paper"
    assert DIFFERS_KINDS["text_artefact"] == "artefact of the text"
    assert DIFFERS_KINDS["convention"] == "approximation or convention"
    assert AUDIT_COLUMNS[AUDIT_COLUMNS.index("note") + 1] == "kind"


# one synthetic check of each kind: a typo (a wrong factor), a scan artefact (a lost square),
# a convention (a dropped higher-order term)
@pytest.mark.parametrize(
    ("kind", "printed", "derived", "residual"),
    [
        ("paper_error", 2 * x, 3 * x, "-x"),
        ("text_artefact", sp.cos(x), sp.cos(x) ** 2, "(1 - cos(x))*cos(x)"),
        ("convention", 1 + x, sp.exp(x), "x - exp(x) + 1"),
    ],
)
def test_a_differs_row_carries_its_kind(kind, printed, derived, residual):
    row = run_check(
        Check("9", printed=printed, derived=derived, differs_kind=kind, if_differs="evidence")
    )
    assert (row.status, row.residual, row.note, row.kind) == ("differs", residual, "evidence", kind)
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
    for kind, label in DIFFERS_KINDS.items():
        assert f"{kind} ({label})" in message


def test_a_long_residual_is_shortened_in_the_error():
    wide = sum(sp.Symbol(f"y_{k}") for k in range(200))
    with pytest.raises(ValueError, match=r"^eq\. 5: .*\.\.\.\) but the check records no") as err:
        run_check(Check("5", printed=wide, derived=0))
    assert len(str(err.value)) < 500


@pytest.mark.parametrize(
    ("kwargs", "message"),
    [
        (
            {"differs_kind": "typo", "if_differs": "evidence"},
            "eq. 12: differs_kind 'typo' is not one of paper_error (error of the paper), "
            "text_artefact (artefact of the text), convention (approximation or convention)",
        ),
        (
            {"if_differs": "evidence"},
            "eq. 12: if_differs is given without differs_kind; give one of paper_error",
        ),
        (
            {"differs_kind": "convention"},
            "eq. 12: differs_kind 'convention' is given without if_differs, the judgement and "
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
        Check("1", printed=sp.sin(x) ** 2, derived=1 - sp.cos(x) ** 2, **_judged("paper_error"))
    )
    assert (match.status, match.kind) == ("match", "")
    nc = run_check(Check("2", not_checkable="a definition"))
    assert (nc.status, nc.kind) == ("not_checkable", "")


def test_the_audit_frame_writes_the_kind_column():
    frame = audit_frame(
        [
            Check("1", printed=x, derived=x),
            Check("2", printed=2 * x, derived=x, **_judged("text_artefact")),
            Check("3", not_checkable="absent from the seed text"),
        ]
    )
    assert list(frame.columns) == AUDIT_COLUMNS
    assert list(frame["kind"]) == ["", "text_artefact", ""]


def _judged(kind: str) -> dict[str, str]:
    return {"differs_kind": kind, "if_differs": "a judgement with its evidence"}


# the simplify budget of a residual's text is CPU time, so the text does not depend on the load
def test_waiting_does_not_use_up_the_simplify_budget(monkeypatch):
    import time

    import derivations.checks as checks

    def slow_but_idle(expr):
        time.sleep(0.5)  # wall-clock time, no CPU: what a loaded machine adds
        return sp.Symbol("simplified")

    monkeypatch.setattr(checks, "SIMPLIFY_SECONDS", 0.1)
    monkeypatch.setattr(checks.sp, "simplify", slow_but_idle)
    assert checks._tidy(2 * x + 2) == sp.Symbol("simplified")


def test_a_residual_over_the_cpu_budget_is_shown_factored(monkeypatch):
    import time

    import derivations.checks as checks

    def busy(expr):
        end = time.process_time() + 5.0
        while time.process_time() < end:
            pass
        return sp.Symbol("simplified")

    monkeypatch.setattr(checks, "SIMPLIFY_SECONDS", 0.1)
    monkeypatch.setattr(checks.sp, "simplify", busy)
    assert str(checks._tidy(2 * x + 2)) == "2*(x + 1)"  # factor_terms, not the simplified form
