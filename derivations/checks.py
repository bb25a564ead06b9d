"""Equation audit: compare each printed equation with the derivation.

A :class:`Check` pairs the paper's equation, transcribed as printed, with the
expression derived from first principles. Its status is computed, never
written by hand:

* ``match``: printed - derived is zero, symbolically or, where SymPy cannot
  simplify it, numerically at 40 seeded random points (relative 1e-9);
* ``differs``: it is not; the row gives the simplified residual, the judgement
  recorded with the check (``if_differs``: what is correct, and the evidence for the kind,
  first, in one sentence) and its kind (one of ``pipeline.columns.DIFFERS_KINDS``). The kind
  is not written by hand: the check names what the seed text shows (its ``discrepancy``, a
  key of ``derivations.discrepancies.DISCREPANCIES``) and ``kind_of`` gives the kind, so one rule classifies
  every paper. A difference without a recorded discrepancy is an error, not a row: every
  ``differs`` is reviewed;
* ``not_checkable``: nothing to compare (equation absent from the seed text, or
  a definition), with the reason.

The rule (the seed text is the authority for what a paper prints, but its OCR can garble
subscripts, signs, primes and bars), in the order of ``derivations.discrepancies``:
``convention`` when the printed form is right in a convention or approximation the paper
chose; else ``paper_error`` when the printed mathematics, legible and coherent, is wrong
beyond one mark (a term, factor or operator), or by one mark that recurs or is carried into
later equations (an OCR misread does not repeat itself), so that used as printed it gives
wrong numbers; else ``text_artefact`` when the seed text is visibly broken where it differs
(stacked lines read as a fraction, a displaced line) and undoing the break gives the derived
form; else ``unclear_from_text``: one mark, once (a sign, exponent, transpose, subscript, one
symbol for another, a bar's extent), of the kind this OCR misreads, so the text cannot tell
the paper's slip from the OCR's. A row with several discrepancies takes the first that applies.

Printed and derived forms may be expressions, matrices or tuples (compared
element by element). Both are written as "left side minus right side" or as the
right side of ``quantity = ...``, whichever the check states.

>>> import sympy as sp
>>> x = sp.Symbol("x", real=True)
>>> run_check(Check("1", printed=sp.sin(x) ** 2, derived=1 - sp.cos(x) ** 2)).status
'match'
>>> row = run_check(
...     Check("2", printed=2 * x, derived=3 * x, discrepancy="wrong_term", if_differs="typo")
... )
>>> row.status, row.residual, row.note, row.kind
('differs', '-x', 'typo', 'paper_error')
>>> run_check(Check("3", printed=2 * x, derived=3 * x))  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
ValueError: eq. 3: printed and derived forms differ (residual -x) but ... give one of approximation (convention)...
"""

from __future__ import annotations

from collections.abc import Iterable, Sequence
from dataclasses import dataclass, field
from typing import Any

import sympy as sp

from derivations.discrepancies import DISCREPANCIES, kind_of
from derivations.factors_dict import lean_dict_factors
from derivations.futrig_memo import memoised_futrig, memoised_trig_factor
from derivations.residual_tidy import tidy as _tidy

__all__ = [
    "Check",
    "AuditRow",
    "run_check",
    "run_audit",
    "numeric_residual",
    "audit_frame",
    "audit_main",
    "audit_outputs",
    "audit_records",
    "math_record",
    "STATUSES",
    "DISCREPANCIES",
    "kind_of",
]

STATUSES = ("match", "differs", "not_checkable")
N_POINTS = 40
REL_TOL = 1e-9


def _kinds() -> dict[str, str]:
    """The kinds of a ``differs`` with their labels (``pipeline.columns.DIFFERS_KINDS``)."""
    from pipeline.columns import DIFFERS_KINDS

    return DIFFERS_KINDS


def _allowed() -> str:
    return ", ".join(f"{d} ({kind})" for d, (kind, _) in DISCREPANCIES.items())


@dataclass(frozen=True)
class Check:
    """One equation of the paper (``equation`` is its number as a string: '47', '47.E', '19.b').

    ``discrepancy`` and ``if_differs`` go together: a judgement of a difference names what the
    seed text shows (a key of :data:`DISCREPANCIES`, which gives the kind), and comes with its
    evidence; a ValueError otherwise.
    """

    equation: str
    printed: Any = None
    derived: Any = None
    if_differs: str = (
        ""  # judgement when the forms differ: the evidence for the kind, then what is right
    )
    discrepancy: str = ""  # a key of DISCREPANCIES; the kind follows from it (kind_of)
    if_match: str = ""  # optional remark when they agree
    not_checkable: str = ""  # reason, when there is nothing to compare
    sample: dict[sp.Symbol, tuple[float, float]] | None = None  # sampling ranges per symbol

    def __post_init__(self) -> None:
        if self.discrepancy and self.discrepancy not in DISCREPANCIES:
            raise ValueError(
                f"eq. {self.equation}: discrepancy {self.discrepancy!r} is not one of {_allowed()}"
            )
        if self.if_differs and not self.discrepancy:
            raise ValueError(
                f"eq. {self.equation}: if_differs is given without discrepancy; give one of "
                f"{_allowed()}"
            )
        if self.discrepancy and not self.if_differs:
            raise ValueError(
                f"eq. {self.equation}: discrepancy {self.discrepancy!r} is given without "
                "if_differs, the judgement and its evidence"
            )

    @property
    def differs_kind(self) -> str:
        """The kind of a difference (``pipeline.columns.DIFFERS_KINDS``), from the discrepancy."""
        return kind_of(self.discrepancy) if self.discrepancy else ""


@dataclass(frozen=True)
class AuditRow:
    """A row of ``equation_audit.csv``; the expressions (not in the CSV) feed the reports."""

    equation: str
    status: str
    residual: str
    note: str
    kind: str = ""  # one of pipeline.columns.DIFFERS_KINDS on a differs row, else blank
    discrepancy: str = ""  # the key of DISCREPANCIES the kind follows from (differs rows)
    printed_expr: Any = field(default=None, compare=False, repr=False)
    derived_expr: Any = field(default=None, compare=False, repr=False)
    residual_expr: Any = field(default=None, compare=False, repr=False)

    def as_dict(self) -> dict[str, str]:
        return {
            "equation": self.equation,
            "status": self.status,
            "residual": self.residual,
            "note": self.note,
            "kind": self.kind,
        }


def _elements(obj: Any) -> list[sp.Expr]:
    if isinstance(obj, sp.MatrixBase):
        return [sp.sympify(e) for e in obj]
    if isinstance(obj, (tuple, list)):
        out: list[sp.Expr] = []
        for o in obj:
            out.extend(_elements(o))
        return out
    return [sp.sympify(obj)]


def numeric_residual(
    residuals: Sequence[sp.Expr],
    scales: Sequence[sp.Expr],
    sample: dict[sp.Symbol, tuple[float, float]] | None = None,
    seed: int = 0,
) -> float:
    """Largest |residual| / (|scale| + 1e-300) over seeded random points of all free symbols.

    Symbols are drawn uniformly from ``sample[sym]`` or, by default, from (0.15, 1.3)
    (positive angles away from 0 and pi/2, where tan and 1/cos are finite).
    """
    symbols = sorted(
        set().union(*(e.free_symbols for e in [*residuals, *scales])), key=lambda s: s.name
    )
    import numpy as np  # here only: a derive or codegen check job need not import it

    rng = np.random.default_rng(seed)
    ranges = [(sample or {}).get(s, (0.15, 1.3)) for s in symbols]
    # the points drawn one after the other, each symbol in turn (the draws of a loop over points)
    points = np.array([[rng.uniform(*r) for r in ranges] for _ in range(N_POINTS)])
    # one function for every residual and scale (one lambdify, not two per element), called once
    # on all the points (arrays: the same values as a call per point, ~0.05 CPU-s an audit less);
    # without lambdify's docstring, which prints every expression as text (~0.08 CPU-s an audit)
    values_at = sp.lambdify(symbols, [*residuals, *scales], "numpy", docstring_limit=0)
    with np.errstate(all="ignore"):
        values = np.array(
            [
                np.broadcast_to(np.asarray(v, dtype=complex), (N_POINTS,))
                for v in values_at(*points.T)
            ]
        )
        n = len(residuals)
        ratios = np.abs(values[:n]) / (np.abs(values[n:]) + 1e-300)
    # a residual that is not finite skipped; a NaN ratio (a NaN scale) counts for nothing
    kept = ratios[np.isfinite(values[:n]) & ~np.isnan(ratios)]
    return max(0.0, float(kept.max())) if kept.size else 0.0


def _short(text: str, limit: int = 200) -> str:
    return text if len(text) <= limit else text[: limit - 3] + "..."


def run_check(check: Check) -> AuditRow:
    """Compute the status, residual and note of one check."""
    if check.printed is None or check.derived is None:
        if not check.not_checkable:
            raise ValueError(f"eq. {check.equation}: not checkable but no reason given")
        return AuditRow(check.equation, "not_checkable", "", check.not_checkable)
    printed, derived = _elements(check.printed), _elements(check.derived)
    if len(printed) != len(derived):
        raise ValueError(
            f"eq. {check.equation}: printed has {len(printed)} elements, derived {len(derived)}"
        )
    # each side expanded once: the residual is the difference of the expanded sides, expanded
    # (the same expression as expand(printed - derived), on the 600 elements of the three papers)
    sides = [(sp.expand(p), sp.expand(d)) for p, d in zip(printed, derived, strict=True)]
    raw = [sp.expand(p - d) for p, d in sides]
    exprs = {"printed_expr": check.printed, "derived_expr": check.derived}
    if all(r == 0 for r in raw):
        return AuditRow(check.equation, "match", "0", check.if_match, **exprs)
    # scale: the sum of the magnitudes of the terms on both sides, so that cancelling
    # terms of size ~1 that leave ~1e-16 count as zero
    scales = [
        sp.Add(*(sp.Abs(t) for t in sp.Add.make_args(p) + sp.Add.make_args(d))) for p, d in sides
    ]
    err = numeric_residual(raw, scales, check.sample)
    if err < REL_TOL:
        note = check.if_match or "zero numerically at 40 random points"
        return AuditRow(check.equation, "match", "0", note, **exprs)
    # each distinct residual tidied once (the elements of a matrix often repeat one residual)
    tidied: dict[sp.Expr, sp.Expr] = {}
    simplified = [tidied[r] if r in tidied else tidied.setdefault(r, _tidy(r)) for r in raw]
    if all(r == 0 for r in simplified):
        return AuditRow(check.equation, "match", "0", check.if_match, **exprs)
    text = "; ".join(str(r) for r in simplified) if len(simplified) > 1 else str(simplified[0])
    if not check.discrepancy:
        raise ValueError(
            f"eq. {check.equation}: printed and derived forms differ (residual {_short(text)}) but the "
            f"check records no discrepancy; give one of {_allowed()}, with the evidence "
            "in if_differs"
        )
    residual = simplified[0] if len(simplified) == 1 else sp.Matrix(simplified)
    return AuditRow(
        check.equation,
        "differs",
        text,
        check.if_differs,
        check.differs_kind,
        check.discrepancy,
        residual_expr=residual,
        **exprs,
    )


def run_audit(checks: Iterable[Check]) -> list[AuditRow]:
    """Run every check; equation numbers must be unique. The residuals are tidied with each
    ``trigsimp`` node simplified once and each expression its steps factor factored once, for
    all checks (:mod:`derivations.futrig_memo`), and ``Factors`` of a dict built without a SymPy
    ``Dict`` (:mod:`derivations.factors_dict`)."""
    with memoised_futrig(), memoised_trig_factor(), lean_dict_factors():
        rows = [run_check(c) for c in checks]
    seen: set[str] = set()
    for r in rows:
        if r.equation in seen:
            raise ValueError(f"equation {r.equation} audited twice")
        seen.add(r.equation)
    return rows


def _mathml(obj: Any) -> str | None:
    """Presentation MathML (one ``<math>`` element per part) of an expression, a matrix or a
    tuple of them; None if there is nothing to show or SymPy cannot print it."""
    from sympy.printing.mathml import mathml

    if obj is None:
        return None
    parts = list(obj) if isinstance(obj, (tuple, list)) else [obj]
    out = []
    for part in parts:
        try:
            body = mathml(sp.sympify(part), printer="presentation")
        except Exception:  # noqa: BLE001 - an unprintable expression is shown as text instead
            return None
        out.append(f'<math xmlns="http://www.w3.org/1998/Math/MathML">{body}</math>')
    return ", ".join(out)


def _srepr(obj: Any) -> str | None:
    if obj is None:
        return None
    try:
        return sp.srepr(obj if not isinstance(obj, list) else tuple(obj))
    except Exception:  # noqa: BLE001
        return None


def math_record(row: AuditRow) -> dict[str, Any]:
    """The printed, derived and residual forms of one audit row as MathML and SymPy srepr."""
    rec: dict[str, Any] = {"equation": row.equation, "status": row.status}
    if row.status == "differs":
        rec["kind"], rec["discrepancy"] = row.kind, row.discrepancy
    for key in ("printed", "derived", "residual"):
        obj = getattr(row, f"{key}_expr")
        rec[f"{key}_mathml"] = _mathml(obj)
        rec[f"{key}_srepr"] = _srepr(obj)
    return rec


def audit_records(checks: Iterable[Check]) -> tuple[list[dict[str, str]], list[dict[str, Any]]]:
    """(the rows of equation_audit.csv as dicts of strings, list of math records) from one
    audit run, without pandas (the audit job writes them with ``pipeline.atomic.write_text_csv``)."""
    rows = run_audit(checks)
    return [r.as_dict() for r in rows], [math_record(r) for r in rows]


def audit_outputs(checks: Iterable[Check]):
    """(DataFrame with the contract columns, list of math records) from one audit run."""
    import pandas as pd

    from pipeline.columns import AUDIT_COLUMNS

    rows, records = audit_records(checks)
    return pd.DataFrame(rows, columns=AUDIT_COLUMNS), records


def audit_frame(checks: Iterable[Check]):
    """Run the checks and return a DataFrame with the contract columns of equation_audit.csv."""
    import pandas as pd

    from pipeline.columns import AUDIT_COLUMNS

    return pd.DataFrame([r.as_dict() for r in run_audit(checks)], columns=AUDIT_COLUMNS)


def audit_main(checks_fn, description: str, argv: list[str] | None = None) -> int:
    """Command line of a paper's audit module: ``--out equation_audit.csv`` and, optionally,
    ``--math equation_math.json`` (the forms, and the kind and discrepancy of each difference)."""
    import argparse
    from pathlib import Path

    from pipeline.atomic import write_csv, write_json
    from pipeline.columns import AUDIT_COLUMNS

    parser = argparse.ArgumentParser(description=description)
    parser.add_argument("--out", type=Path, required=True, help="equation_audit.csv to write")
    parser.add_argument("--math", type=Path, help="equation_math.json to write (optional)")
    args = parser.parse_args(argv)
    frame, records = audit_outputs(checks_fn())
    write_csv(args.out, frame, AUDIT_COLUMNS)
    if args.math is not None:
        write_json(args.math, records)
    print(f"equation audit: {len(frame)} rows, {frame['status'].value_counts().to_dict()}")
    return 0
