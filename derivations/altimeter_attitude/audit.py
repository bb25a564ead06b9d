"""Equation audit of the altimeter-attitude paper: every numbered equation, printed vs derived.

``python -m derivations.altimeter_attitude.audit --out results/altimeter_attitude/equation_audit.csv``

Each check pairs ``printed.PRINTED[eq]`` (the seed text, transcribed literally) with the
expression derived in ``kinematics``, ``leveling``, ``complementary``, ``model`` and
``multiplicative_noise``, one module per section of the paper: ``audit_sensors`` (eqs.
1-12), ``audit_complementary`` (13-23), ``audit_model`` (24-33) and ``audit_appendix``
(Appendix A, 1a-13a). The status is computed by :func:`derivations.checks.run_check`;
the judgement texts (``if_differs``) say what is correct and give, first, the evidence for the
kind of each difference; the kind follows from the check's ``discrepancy`` by the one rule
of :mod:`derivations.discrepancies` (``pipeline.columns.DIFFERS_KINDS``). Both sides are put in the
same symbols first: where the paper writes a quantity as a symbol (omega_ie^b, gamma, C_3j,
c_g, ...) the check substitutes the derived expression and says so in the note.

Eq. 31's prediction and Appendix A (1a-13a) hold for any F, G(x) linear in x, Q, P; they
are checked on the appendix's instance of ``printed.py`` (n = 2 states, m = 2 noises, every
entry of F, G_c1, G_c2, P, Q, x_hat a free symbol), where the expectations are computed by
:func:`multiplicative_noise.expect` from the moments of eq. 2a, and eq. 32 on the paper's own
G(x) = dt C(x) (n = 5, m = 6). Where an appendix step prints an expectation with no closed
form, the printed side keeps that expectation (computed the same way) and the check is on the
printed closed-form terms. The pipeline always uses the derived form.
"""

from __future__ import annotations

from typing import TYPE_CHECKING

from derivations.altimeter_attitude import (
    audit_appendix,
    audit_complementary,
    audit_model,
    audit_sensors,
)
from derivations.checks import AuditRow, Check, audit_main, run_audit
from derivations.checks import audit_frame as checks_audit_frame

__all__ = ["checks", "audit_rows", "audit_frame", "main"]

if TYPE_CHECKING:  # pandas only for the annotations: a derive job need not import it
    import pandas as pd


def checks() -> list[Check]:
    """All checks, in equation order."""
    return [
        *audit_sensors.checks(),
        *audit_complementary.checks(),
        *audit_model.checks(),
        *audit_appendix.checks(),
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
