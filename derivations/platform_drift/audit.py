"""Equation audit of the platform-drift paper: every numbered equation, printed vs derived.

``python -m derivations.platform_drift.audit --out results/platform_drift/equation_audit.csv``

Each check pairs ``printed.PRINTED[eq]`` (the seed text, transcribed literally) with the
expression derived in ``kinematics``, ``algorithm``, ``specific_force``, ``alignment``,
``drift`` and ``schuler``, one module per section of the paper: ``audit_navigation``
(eqs. 1-19), ``audit_alignment`` (20-27), ``audit_drift`` (28-36) and ``audit_table2``
(Table 2). The status is computed by :func:`derivations.checks.run_check`;
the judgement texts (``if_differs``) say what is correct and give, first, the evidence for the
kind of each difference; the kind follows from the check's ``discrepancy`` by the one rule
of :mod:`derivations.discrepancies` (``pipeline.columns.DIFFERS_KINDS``). Where the paper linearises
("=~"), the derivation is truncated at the same order (:func:`approx.taylor`) and the note
says in which small quantities. The pipeline always uses the derived form.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from derivations.checks import AuditRow, Check, audit_main, run_audit
from derivations.checks import audit_frame as checks_audit_frame
from derivations.platform_drift import (
    audit_alignment,
    audit_drift,
    audit_navigation,
    audit_table2,
)

__all__ = ["checks", "audit_rows", "audit_frame", "main"]

if TYPE_CHECKING:  # pandas only for the annotations: a derive job need not import it
    import pandas as pd


def checks() -> list[Check]:
    """All checks, in equation order."""
    return [
        *audit_navigation.checks(),
        *audit_alignment.checks(),
        *audit_drift.checks(),
        *audit_table2.checks(),
    ]


def audit_rows() -> list[AuditRow]:
    """Run the whole audit."""
    return run_audit(checks())


def audit_frame() -> pd.DataFrame:
    """The audit as a DataFrame with the contract columns."""
    return checks_audit_frame(checks())


def main(argv: list[str] | None = None) -> int:
    return audit_main(checks, __doc__, argv)


if __name__ == "__main__":
    raise SystemExit(main())
