"""Equation audit of the synthetic pendulum paper: each printed equation against the derivation.

``python -m derivations.pendulum.audit`` prints it.
"""

from __future__ import annotations

import sympy as sp
from derivations.pendulum.model import (
    g,
    l,
    period_first_order,
    period_small_angle,
    theta,
    theta0,
    theta_ddot,
)

from derivations.checks import Check, audit_main

__all__ = ["checks"]


def checks() -> list[Check]:
    return [
        # eq. 1 as printed: theta'' = -(g/l) sin(theta)
        Check("1", printed=-g / l * sp.sin(theta), derived=theta_ddot()),
        # eq. 3 as printed: T = 2 pi sqrt(l/g)
        Check("3", printed=2 * sp.pi * sp.sqrt(l / g), derived=period_small_angle()),
        # eq. 4 as printed: T = 2 pi sqrt(l/g) (1 + theta_0^2 / 8)
        Check(
            "4",
            printed=2 * sp.pi * sp.sqrt(l / g) * (1 + theta0**2 / 8),
            derived=period_first_order(),
            discrepancy="wrong_term",
            if_differs="error of the paper: the amplitude term is theta_0^2/16, not /8 (the "
            "series of the complete elliptic integral, 1 + theta_0^2/16 + ...)",
        ),
    ]


if __name__ == "__main__":
    raise SystemExit(audit_main(checks, __doc__))
