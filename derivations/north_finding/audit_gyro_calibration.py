"""Equation audit of the north-finding paper, eqs. 53-71 (section 4): azimuth methods 4-6, which
also give the gyro bias and scale factor.
"""

from __future__ import annotations

import sympy as sp

from derivations.checks import Check, numeric_residual
from derivations.north_finding import azimuth
from derivations.north_finding import printed as P
from derivations.north_finding import symbols as s
from derivations.north_finding.audit_leveling import DEG, IDEAL, SB

__all__ = ["checks"]


def checks() -> list[Check]:
    """Equation audit of the north-finding paper, eqs. 53-71 (section 4): azimuth methods 4-6, which: the checks, in equation order."""
    out: list[Check] = []
    half = azimuth.half_angle_roots()
    gyro_sb = {**IDEAL, **SB}
    out.append(Check("53", printed=P.PRINTED["53"], derived=azimuth.real_gyro("x").subs(gyro_sb)))
    out.append(
        Check(
            "54",
            printed=P.PRINTED["54"],
            derived=sp.Matrix(
                [azimuth.real_gyro("x", d * DEG).subs(gyro_sb) for d in (0, 90, 180)]
            ),
        )
    )
    a4 = azimuth.method4()
    out.append(Check("55", printed=P.PRINTED["55"], derived=a4["bias"]))
    out.append(
        Check(
            "56.a",
            printed=P.PRINTED["56.a"].subs(s.b, a4["bias"]),
            derived=sp.Matrix([a4["omega1"], a4["omega2"]]),
        )
    )
    w_model = {d: azimuth.real_gyro("x", d * DEG).subs(gyro_sb) for d in (0, 90, 180)}
    om_model = sp.Matrix([(w_model[0] - s.b) / s.Omega, (w_model[90] - s.b) / s.Omega])
    out.append(Check("56.b", printed=P.PRINTED["56.b"], derived=sp.expand(om_model)))
    out.append(
        Check(
            "57",
            printed=P.PRINTED["57"],
            derived=om_model[0] / om_model[1],
            discrepancy="visible_garble",
            if_differs="artefact of the text: stacked lines read as a sum, the ratio (cos ps cos th cos l + sin "
            "th sin l) / ((cos ps sin th sin ph - sin ps cos ph) cos l - cos th sin ph sin l), whose "
            "numerator and denominator take two lines each, read as a sum of two fractions",
        )
    )
    out.append(
        Check(
            "58",
            printed=P.PRINTED["58"],
            derived=sp.Matrix([a4["A"], a4["B"], a4["C"]]),
            discrepancy="one_mark",
            if_differs="cannot tell from the text: one mark, the extent of B's fraction bar, in a block whose "
            "fractions the OCR visibly garbles (the '2' under each is the subscript of omega_2); B "
            "must be (omega_1/omega_2) sin th sin ph - cos th, cos th not divided by omega_2, where "
            "the seed text puts it under the bar; A and C match",
        )
    )
    out.append(
        Check(
            "59",
            printed=P.PRINTED["59"],
            derived=sp.Matrix(half),
            discrepancy="one_mark",
            if_differs="cannot tell from the text: one mark, once, the extent of the root, which ends before "
            "'- C' where eqs. 41 and 43 put C^2 under it, sqrt(A^2 + B^2 - C^2), and this OCR "
            "misplaces bars (eqs. 52, 57, 58)",
        )
    )
    om1_model = om_model[0]
    out.append(
        Check(
            "60",
            printed=P.PRINTED["60"].subs(s.om1, om1_model),
            derived=s.S,
            if_match="S recovered from omega_1 of the model",
        )
    )
    a5 = azimuth.method5()
    om_sub = {s.om1: om_model[0], s.om2: om_model[1]}
    out.append(
        Check(
            "61",
            printed=P.PRINTED["61"].subs(om_sub),
            derived=sp.Matrix([0, 0]),
            if_match="both identities hold on the model omega_1 = S X, omega_2 = S Y",
        )
    )
    om3_61 = s.om1 / (s.S * sp.cos(s.lam)) - sp.sin(s.theta) * sp.tan(s.lam)
    om4_61 = s.om2 / (s.S * sp.cos(s.lam)) + sp.cos(s.theta) * sp.sin(s.phi) * sp.tan(s.lam)
    out.append(
        Check(
            "62",
            printed=P.PRINTED["62"].subs({s.om3: om3_61, P.om4: om4_61}),
            derived=sp.Matrix([a5["cos_psi_sol"], a5["sin_psi_sol"]]),
            if_match="cos psi and sin psi solved from eq. 61 (omega_3, omega_4 of eq. 61, not of eq. 69)",
        )
    )
    out.append(
        Check(
            "63",
            printed=P.PRINTED["63"],
            derived=a5["cos_psi_sol"] ** 2 + a5["sin_psi_sol"] ** 2 - 1,
        )
    )
    # reading the last factor 'tan th' of the last term of 64.A as 'tan ph'
    cth, sth, tth, tph, tl = (
        sp.cos(s.theta),
        sp.sin(s.theta),
        sp.tan(s.theta),
        sp.tan(s.phi),
        sp.tan(s.lam),
    )
    last = 2 * cth * tph * tl**2 * sth * tth
    tan_fix = P.PRINTED["64.A"] + last * tth - last * tph
    fixed_ok = numeric_residual([tan_fix - a5["A"]], [sp.S.One]) < 1e-12
    out.append(
        Check(
            "64.A",
            printed=P.PRINTED["64.A"],
            derived=a5["A"],
            discrepancy="one_mark",
            if_differs="cannot tell from the text: one symbol, once, the last factor of the last "
            "term printed tan th where the derivation has tan ph, in a block whose C lines the OCR "
            "visibly splits into spurious fractions; the last term must be -2 cos th tan ph "
            "tan^2 l sin th tan th tan ph"
            + (
                "; with that reading the printed A equals the derived one"
                if fixed_ok
                else "; even with that reading it differs"
            ),
        )
    )
    out.append(Check("64.B", printed=P.PRINTED["64.B"], derived=a5["B"]))
    out.append(
        Check(
            "64.C",
            printed=P.PRINTED["64.C"],
            derived=a5["C"],
            if_match="reading the OCR-stacked term as -2 omega_1 tan l tan th / cos th",
        )
    )
    A5, B5, C5 = a5["_ABC"]
    to5 = {A5: P.A, B5: P.B, C5: P.C}
    out.append(Check("65.a", printed=P.PRINTED["65.a"], derived=a5["quad65"].xreplace(to5)))
    roots = sp.Matrix([r.xreplace(to5) for r in a5["scale_roots"]])
    pos = {P.A: (0.2, 1.3), P.B: (0.2, 1.3)}
    out.append(
        Check(
            "65.b",
            printed=P.PRINTED["65.b"],
            derived=roots,
            sample=pos,
            discrepancy="one_mark",
            if_differs="cannot tell from the text: one exponent, once, 4AB cos l under the root where the "
            "derivation has 4AB cos^2 l (the C^2 cos^2 l before it has its square); the simplified "
            "form that follows (65.c) is right",
        )
    )
    out.append(Check("65.c", printed=P.PRINTED["65.c"], derived=roots, sample=pos))
    out.append(Check("66", printed=P.PRINTED["66"], derived=(a5["scale_approx"] - 1).xreplace(to5)))
    out.append(
        Check(
            "67",
            printed=P.PRINTED["67"],
            derived=a5["cos_psi_sol"],
            discrepancy="one_mark",
            if_differs="cannot tell from the text: one mark, once, the extent of the fraction bar, cos psi = "
            "omega_1 / (S cos th cos l) - tan th tan l (eqs. 61-62) with the subtraction outside the "
            "fraction, where the seed text puts it inside; arccos also leaves the sign of psi to the "
            "compass",
        )
    )
    a6 = azimuth.method6()
    out.append(
        Check(
            "68",
            printed=P.PRINTED["68"],
            derived=a6["model_z"],
            discrepancy="wrong_term",
            if_differs="error of the paper: a divisor is missing, the slip of eq. 37 again: the table rate omega "
            "is multiplied by w^EI; the gyro reads S (w^EI [...] + omega) + b. The paper then sets "
            "omega = 0, where both agree",
        )
    )
    out.append(
        Check(
            "69",
            printed=P.PRINTED["69"],
            derived=sp.expand((a6["model_z"] - s.b) / s.Omega),
            discrepancy="wrong_term",
            if_differs="error of the paper: a divisor is missing, the slip of eqs. 37 and 68 again: omega_3 = "
            "S ([...] + omega / w^EI); equal at omega = 0",
        )
    )
    out.append(Check("70", printed=P.PRINTED["70"], derived=a6["scale"]))
    out.append(Check("71", printed=P.PRINTED["71"], derived=a6["scale_approx"] - 1))
    return out
