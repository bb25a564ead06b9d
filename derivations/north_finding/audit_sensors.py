"""Equation audit of the north-finding paper, eqs. 1-18 (section 2-1): the table kinematics and
the accelerometer model.
"""

from __future__ import annotations

import sympy as sp

from derivations import frames
from derivations.checks import Check
from derivations.north_finding import leveling, sensors
from derivations.north_finding import printed as P
from derivations.north_finding import symbols as s

__all__ = ["checks"]


def _still(expr):
    return sensors.still_table(expr)


def _omega_bi_from_dcm_chain() -> sp.Matrix:
    """[omega^{BI}]^B from Poisson's equation on [T]^{BI} = [T]^{BT}(t) [T]^{TN} [T]^{NE} [T]^{EI}(t)."""
    t = s.t
    tau_t = sp.Function("tau")(t)
    lon = sp.Symbol("ell", real=True)
    mat_bi = (
        frames.rot_z(tau_t)
        * frames.mat_tn(s.psi, s.theta, s.phi)
        * frames.mat_ne(s.lam, lon)
        * frames.rot_z(s.Omega * t)
    )
    # no simplification: the audit compares it numerically at random points (xreplace: the
    # exact atoms, as subs replaced them here, without its pattern search on the long product)
    w = frames.angular_velocity_from_dcm(mat_bi, t, simplify=False)
    return w.xreplace({tau_t.diff(t): s.w}).xreplace({tau_t: s.tau}).xreplace({t: 0})


def checks() -> list[Check]:
    """Equation audit of the north-finding paper, eqs. 1-18 (section 2-1): the table kinematics and: the checks, in equation order."""
    out: list[Check] = []
    out: list[Check] = []
    missing = (
        "not in the seed text (eqs. 1-11, the general kinematics and specific-force equations, are "
        "missing from the OCR; the text refers to them and eqs. 12-16, 22-23 restate their "
        "rotating-table form, which is checked)"
    )
    out += [Check(str(k), not_checkable=missing) for k in range(1, 12)]
    out.append(
        Check(
            "12",
            not_checkable="definition: the accelerometer triad reads the specific force in B "
            "(adopted as the model; eq. 16 checks its consequence)",
        )
    )
    # eqs. 13-14: angular rate of B from the full DCM chain vs omega^BT + omega^EI in B
    w_chain = _omega_bi_from_dcm_chain()
    w_printed = sensors.mat_bt() * sp.Matrix([0, 0, s.w]) + sensors.mat_bn() * frames.earth_rate_n(
        s.Omega, s.lam
    )
    out.append(
        Check(
            "13",
            printed=w_printed,
            derived=w_chain,
            if_match="omega^BI from Poisson's equation on [T]^BT(t)[T]^TN[T]^NE[T]^EI(t) equals "
            "omega^BT + omega^EI (omega^TN = omega^NE = 0 at rest)",
        )
    )
    out.append(
        Check(
            "14",
            printed=w_printed,
            derived=sensors.angular_rate_b(),
            if_match="[T]^BT[omega^BT]^T + [T]^BT[T]^TN[omega^EI]^N",
        )
    )
    f_b = sensors.specific_force_b()
    out.append(
        Check(
            "15",
            printed=-sensors.gravity_b(),
            derived=_still(f_b).subs(s.l, 0),
            if_match="f = a_T + 2 omega x v_T - g reduces to -g for a sensor at rest",
        )
    )
    ideal_f = _still(f_b).subs(s.l, 0)
    out.append(Check("16.a", printed=P.PRINTED["16.a"], derived=ideal_f))
    out.append(
        Check(
            "16.b",
            printed=P.PRINTED["16.b"],
            derived=ideal_f,
            discrepancy="wrong_term",
            if_differs="error of the paper: a whole factor is missing, sin(phi) at the end of the first two rows "
            "of the expansion, which the seed text renders coherently in both rows; they must read "
            "-cos t sin th + sin t cos th sin ph and sin t sin th + cos t cos th sin ph; the product "
            "form (16.a) and eq. 17 are right",
        )
    )
    out.append(Check("17", printed=P.PRINTED["17"], derived=leveling.ideal_accel("x")))
    out.append(
        Check(
            "18",
            not_checkable="definition of the real-sensor error model (scale factor, misalignment, "
            "bias, noise); adopted as printed, one row per physical sensor",
        )
    )
    return out
