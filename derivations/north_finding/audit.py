"""Equation audit of the north-finding paper: every numbered equation, printed vs derived.

``python -m derivations.north_finding.audit --out results/north_finding/equation_audit.csv``

Each check pairs ``printed.PRINTED[eq]`` (the seed text, transcribed literally)
with the expression derived in ``sensors``, ``leveling`` and ``azimuth``, one module
per section of the paper: ``audit_sensors`` (eqs. 1-18), ``audit_leveling`` (19-34),
``audit_azimuth`` (35-52) and ``audit_gyro_calibration`` (53-71). The status is computed
by :func:`derivations.checks.run_check`; the judgement texts (``if_differs``) say what is
correct and give, first, the evidence for the
kind of each difference; the kind follows from the check's ``discrepancy`` by the one rule
of :mod:`derivations.discrepancies` (``pipeline.columns.DIFFERS_KINDS``). The pipeline always uses the derived form.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from derivations.checks import AuditRow, Check, audit_main, run_audit
from derivations.checks import audit_frame as checks_audit_frame
from derivations.north_finding import (
    audit_azimuth,
    audit_gyro_calibration,
    audit_leveling,
    audit_sensors,
)

__all__ = ["checks", "audit_rows", "audit_frame", "main"]

if TYPE_CHECKING:  # pandas only for the annotations: a derive job need not import it
    import pandas as pd


def checks() -> list[Check]:
    """All checks, in equation order."""
    return [
        *audit_sensors.checks(),
        *audit_leveling.checks(),
        *audit_azimuth.checks(),
        *audit_gyro_calibration.checks(),
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
