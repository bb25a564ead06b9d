"""Equation audit of the altimeter-attitude paper, eqs. 13-23 (section 4): the third row c of the
attitude matrix and the PI complementary filter.
"""

from __future__ import annotations

import sympy as sp

from derivations.altimeter_attitude import complementary as cf
from derivations.altimeter_attitude import kinematics as kin
from derivations.altimeter_attitude import leveling as lv
from derivations.altimeter_attitude import printed as P
from derivations.altimeter_attitude import symbols as s
from derivations.altimeter_attitude.audit_sensors import ROW3, subs_vec
from derivations.checks import Check

__all__ = ["checks"]

MISSING = "missing from the seed text (OCR): "


# ---------------------------------------------------------------- section 4: c and the PI filter


def _eqs_13_to_23() -> list[Check]:
    out = [
        Check(
            "13",
            printed=P.PRINTED["13"],
            derived=kin.third_row_rates(),
            if_match="eq. 7 in vector form: c_dot = Omega^T c = -omega x c",
        )
    ]
    gamma_c = kin.normalisation_error()  # eq. 15
    out.append(
        Check(
            "14",
            printed=P.PRINTED["14"].xreplace({s.gamma: gamma_c}),
            derived=kin.normalised_third_row_rates(),
            if_match="gamma of eq. 15 substituted. Norm dynamics (n = c^T c), computed: n_dot = "
            f"{kin.norm_dynamics()}: n = 1 is attracting at rate 2k for k > 0 (the rotation "
            "part drops out)",
        )
    )
    feedback = kin.normalised_third_row_rates() - kin.third_row_rates()
    out.append(
        Check(
            "15",
            printed=P.PRINTED["15"],
            derived=sp.factor(feedback[0] / (s.k * s.c1)),
            if_match="gamma read off the derived eq. 14 (feedback k gamma c): the normalisation "
            "error, zero on the unit sphere of eq. 8",
        )
    )
    out.append(
        Check(
            "15.b",
            printed=P.PRINTED["15.b"],
            derived=lv.specific_force_level_dcm().xreplace(subs_vec(ROW3, s.c)),
            if_match="the second equation numbered 15: -C_n^b g^n = -g C_b^n(3,:)^T = -g c "
            "(C_3j written c_j)",
        )
    )
    out.append(
        Check(
            "16",
            not_checkable=MISSING + "the Fig. 1 loop equation numbered 16 is not in the "
            "transcription; the loop s c_m = s c_g + (k_p + k_i/s)(c_a - c_m) is reconstructed "
            "from Fig. 1 and eq. 18 (complementary.output_transfer)",
        )
    )
    out.append(
        Check(
            "17.a",
            printed=P.PRINTED["17.a"],
            derived=lv.third_row_from_accel(),
            if_match="eq. 15.b solved for c ('17-alef' of the Persian numbering)",
        )
    )
    out.append(
        Check(
            "17.b",
            printed=P.PRINTED["17.b"],
            derived=lv.third_row_from_accel_unit(),
            if_match="the unit vector along eq. 17-a ('17-be'); ||f^b|| written f_norm",
        )
    )
    loop = {P.c_g: cf.c_g, P.c_a: cf.c_a}
    out.append(
        Check(
            "18",
            printed=P.PRINTED["18"].xreplace(loop),
            derived=cf.output_transfer(),
            if_match="c_m solved from the Fig. 1 loop s c_m = s c_g + (k_p + k_i/s)(c_a - c_m), "
            "per component of c",
        )
    )
    out.append(
        Check(
            "19",
            printed=P.PRINTED["19"].xreplace(loop),
            derived=cf.steady_state(),
            if_match="final value for constant c_g, c_a: the gyro solution is high-passed out",
        )
    )
    out.append(
        Check(
            "20",
            printed=P.PRINTED["20"],
            derived=cf.gains(),
            if_match="denominator of eq. 18 matched to s^2 + 2 xi omega s + omega^2 (the cut-off "
            "omega read omega_c)",
        )
    )
    ov = cf.step_overshoot()
    ov1 = cf.step_overshoot(1.0)
    out.append(
        Check(
            "21",
            printed=P.PRINTED["21"],
            derived=cf.gains_xi_0707(),
            if_match="xi = 0.707 read as 1/sqrt(2). The claim that this xi is chosen so that "
            "'the error has no overshoot' is wrong, computed (complementary.step_overshoot): the "
            f"second-order step response at xi = 0.707 overshoots "
            f"{ov['second_order_overshoot_pct']:.1f} %, and the c_a -> c_m response of eq. 18, "
            f"whose numerator k_p s + k_i adds a zero, {ov['pi_loop_overshoot_pct']:.1f} % "
            f"({ov1['pi_loop_overshoot_pct']:.1f} % even at xi = 1). xi = 0.707 is the "
            "maximally flat (Butterworth) choice; the gain formula itself is right",
        )
    )
    for key in ("22", "23"):
        out.append(
            Check(
                key,
                not_checkable=MISSING + f"equation {key} (the discrete Fig. 1 loop) is not in the "
                "transcription; the filter of Fig. 1 is implemented from eq. 18",
            )
        )
    return out


def checks() -> list[Check]:
    """The checks of this section, in equation order."""
    return [
        *_eqs_13_to_23(),
    ]
