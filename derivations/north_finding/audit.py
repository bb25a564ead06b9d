"""Equation audit of the north-finding paper: every numbered equation, printed vs derived.

``python -m derivations.north_finding.audit --out results/north_finding/equation_audit.csv``

Each check pairs ``printed.PRINTED[eq]`` (the seed text, transcribed literally)
with the expression derived in ``sensors``, ``leveling`` and ``azimuth``. The
status is computed by :func:`derivations.checks.run_check`; the judgement texts
below (``if_differs``) say what is correct and whether the difference looks like
a typo of the paper or an artefact of the OCR text. The pipeline always uses the
derived form.
"""

from __future__ import annotations

import pandas as pd
import sympy as sp

from derivations import frames
from derivations.checks import AuditRow, Check, audit_main, numeric_residual, run_audit
from derivations.checks import audit_frame as checks_audit_frame
from derivations.north_finding import azimuth, leveling, sensors
from derivations.north_finding import printed as P
from derivations.north_finding import symbols as s

__all__ = ["checks", "audit_rows", "audit_frame", "main"]

DEG = sp.pi / 180
IDEAL = leveling.IDEAL
SB = {s.S: s.S, s.b: s.b}


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
    # no simplification: the audit compares it numerically at random points
    w = frames.angular_velocity_from_dcm(mat_bi, t, simplify=False)
    return w.subs(tau_t.diff(t), s.w).subs(tau_t, s.tau).subs(t, 0)


def checks() -> list[Check]:
    """All checks, in equation order."""
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
            if_differs="typo of the paper: the expanded first two rows drop sin(phi) "
            "(-cos t sin th + sin t cos th sin ph; sin t sin th + cos t cos th sin ph); the "
            "product form (16.a) and eq. 17 are right",
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
    m1 = leveling.method1()
    out.append(Check("19.a", printed=P.PRINTED["19.a"], derived=m1["sin_theta"]))
    out.append(Check("19.b", printed=P.PRINTED["19.b"], derived=m1["sin_phi"]))
    out.append(
        Check(
            "19.c",
            printed=P.PRINTED["19.c"],
            derived=sp.Matrix([leveling.ideal_accel("x", d * DEG) for d in (0, 180, 90, 270)]),
        )
    )
    m2 = leveling.method2()
    out.append(
        Check(
            "20",
            printed=P.PRINTED["20"],
            derived=s.g * sp.Matrix([[m2["h_sin_theta"], m2["h_cth_sphi"]]]),
        )
    )
    out.append(
        Check(
            "21",
            printed=P.PRINTED["21"],
            derived=s.g * sp.Matrix([[m2["h_sin_theta"], m2["h_cth_sphi"]]]).subs(s.tau, P.tau_i),
            if_differs="typo of the paper: with Y = a_x (as printed) the rows of H must carry g, as "
            "in eq. 20; the pipeline uses H = [cos t, -sin t] with Y = a_x / g",
        )
    )
    out.append(
        Check(
            "22",
            printed=P.PRINTED["22"],
            derived=sensors.coriolis_b(),
            if_differs="p_x and p_z lack the lever arm l (dimensionally they must carry l: "
            "2 Omega x v_T with |v_T| = l omega); the block beside eq. 24 prints 2 w^EI l w, so this "
            "looks like a typo; the derivation (transport theorem) gives 2 Omega l omega [-a_z, 0, a_x]",
        )
    )
    out.append(
        Check(
            "23",
            printed=P.PRINTED["23"],
            derived=leveling.ideal_accel("x", still=False),
            if_differs="the displayed eq. 23 omits the Coriolis line p_x of eq. 22; the block printed "
            "beside eq. 24 has it (23.x), so this is an artefact of the two-column text",
        )
    )
    out.append(
        Check("23.x", printed=P.PRINTED["23.x"], derived=leveling.ideal_accel("x", still=False))
    )
    out.append(
        Check("23.y", printed=P.PRINTED["23.y"], derived=leveling.ideal_accel("y", still=False))
    )
    out.append(
        Check("23.z", printed=P.PRINTED["23.z"], derived=leveling.ideal_accel("z", still=False))
    )
    m3 = leveling.method3()
    out.append(
        Check(
            "24.a",
            printed=P.PRINTED["24.a"],
            derived=sp.Matrix(
                [
                    leveling.ideal_accel("y", d * DEG, still=False).subs(s.w, 0)
                    for d in (90, 270, 0, 180)
                ]
            ),
            if_match="with the table stopped at each position (omega = 0, omega-dot kept)",
        )
    )
    out.append(Check("24.b", printed=P.PRINTED["24.b"], derived=m3["sin_theta"]))
    out.append(Check("24.c", printed=P.PRINTED["24.c"], derived=m3["sin_phi"]))
    ay = leveling.ideal_accel("y", still=False).subs(s.w, 0)
    m4 = leveling.method4()
    row = m4["h_cth_sphi"] * sp.cos(s.theta) * sp.sin(s.phi) + m4["h_sin_theta"] * sp.sin(s.theta)
    out.append(
        Check(
            "25",
            printed=P.PRINTED["25"].subs(P.a_yi, ay),
            derived=row - (s.w_dot * s.l - ay) / s.g,
            if_match="H X - Y vanishes on the model of a_y (with l omega-dot)",
        )
    )
    ay0 = leveling.ideal_accel("y")
    out.append(
        Check(
            "26",
            printed=P.PRINTED["26"].subs(P.a_yi, ay0),
            derived=row.subs(s.w_dot, 0) + ay0 / s.g,
            if_match="H X - Y vanishes on the model of a_y with omega-dot = 0",
        )
    )
    sf_model = {**IDEAL, **SB}
    out.append(
        Check("27", printed=P.PRINTED["27"], derived=leveling.real_accel("x").subs(sf_model))
    )
    m5 = leveling.method5()
    out.append(
        Check(
            "28.a",
            printed=P.PRINTED["28.a"],
            derived=sp.Matrix([leveling.real_accel("x", d * DEG).subs(sf_model) for d in (0, 180)]),
        )
    )
    out.append(Check("28.b", printed=P.PRINTED["28.b"], derived=m5["bias"]))
    a_model = {d: leveling.real_accel("x", d * DEG).subs(sf_model) for d in (0, 90, 180)}
    az_model = leveling.real_accel("z").subs(sf_model)
    bias_model = m5["bias"].subs({s.ax_0: a_model[0], s.ax_180: a_model[180]})
    out.append(
        Check(
            "29",
            printed=P.PRINTED["29"],
            derived=sp.Matrix([a_model[0] - bias_model, a_model[90] - bias_model]),
        )
    )
    out.append(
        Check(
            "30",
            printed=P.PRINTED["30"],
            derived=az_model,
            if_match="the x sensor turned by -pi/2 about y_B reads along +z_B",
        )
    )
    out.append(Check("31", printed=P.PRINTED["31"], derived=az_model - s.b))
    comps = [a_model[0] - s.b, a_model[90] - s.b, az_model - s.b]
    out.append(
        Check(
            "32",
            printed=P.PRINTED["32"],
            derived=sp.Matrix([sum(c**2 for c in comps)] * 2),
        )
    )
    out.append(Check("33", printed=P.PRINTED["33"], derived=sp.Matrix([-m5["scale"], m5["scale"]])))
    out.append(Check("34", printed=P.PRINTED["34"], derived=m5["scale_approx"] - 1))
    out.append(Check("35", printed=P.PRINTED["35"], derived=sensors.table_rate_b()))
    out.append(Check("36", printed=P.PRINTED["36"], derived=sensors.earth_rate_b()))
    out.append(
        Check(
            "37",
            printed=P.PRINTED["37"],
            derived=sensors.angular_rate_b(),
            if_differs="dimension slip of the paper: with [w~] = w^EI [c_x, c_y, c_z], c_z must add "
            "omega / w^EI, not omega (the same slip recurs in eqs. 68-69); at rest (omega = 0) both agree",
        )
    )
    out.append(Check("38", printed=P.PRINTED["38"], derived=azimuth.ideal_gyro("x")))
    out.append(
        Check(
            "39",
            not_checkable="definition of the gyro error model (as eq. 18); adopted as printed",
        )
    )
    a11 = azimuth.method1_case1()
    out.append(
        Check(
            "40.a",
            printed=P.PRINTED["40.a"],
            derived=sp.Matrix([azimuth.ideal_gyro("x", 0), azimuth.ideal_gyro("x", sp.pi)]),
        )
    )
    out.append(
        Check(
            "40.b",
            printed=P.PRINTED["40.b"],
            derived=a11["cos_psi"],
            if_match="the left-hand side 'cos psi =' is lost in the OCR; the right-hand side matches",
        )
    )
    out.append(
        Check(
            "40.c",
            printed=P.PRINTED["40.c"],
            derived=sp.Matrix(
                [azimuth.ideal_gyro("x", 90 * DEG), azimuth.ideal_gyro("x", 270 * DEG)]
            ),
        )
    )
    a12 = azimuth.method1_case2()
    out.append(
        Check(
            "40.d",
            printed=P.PRINTED["40.d"],
            derived=a12["c"],
            if_differs="the numerator must end in + 2 w^EI cos(th) sin(ph) sin(l), not + 2 w^EI: the "
            "factor is lost (OCR line break or typo); the derivation gives "
            "(w90 - w270 + 2 Omega cos th sin ph sin l) / (2 Omega cos l)",
        )
    )
    half = azimuth.half_angle_roots()
    out.append(
        Check(
            "41",
            printed=P.PRINTED["41"],
            derived=sp.Matrix(half),
            if_differs="OCR artefact: the factor 2 of the half-angle formula is read as 'tau' "
            "(psi = 2 atan(...), as eq. 43 prints it)",
        )
    )
    a2 = azimuth.method2()
    out.append(Check("42", printed=P.PRINTED["42"], derived=sp.Matrix([a2["A"], a2["B"], a2["C"]])))
    out.append(Check("43", printed=P.PRINTED["43"], derived=sp.Matrix(half)))
    a3 = azimuth.method3()
    out.append(Check("44", printed=P.PRINTED["44"], derived=sp.Matrix([a3["amp_A"], a3["amp_B"]])))
    # eq. 45: value of A sin t + B cos t at its stationary point tau* = atan2(A, B)
    A_, B_ = sp.symbols("A B", positive=True)
    tstar = sp.atan2(A_, B_)
    out.append(
        Check(
            "45",
            printed=P.PRINTED["45"].subs({P.A: A_, P.B: B_}),
            derived=sp.simplify(A_ * sp.sin(tstar) + B_ * sp.cos(tstar)),
            if_match="value at tau* = atan2(A, B), the zero of the derivative (eq. 51) that is a maximum",
        )
    )
    c_, s_ = a3["_cs"]
    eq46 = (a3["w_peak"] / s.Omega) ** 2
    out.append(
        Check(
            "46",
            printed=P.PRINTED["46"],
            derived=sp.expand(eq46),
            if_differs="garbled in print/OCR: the cos(psi) and cos(psi) sin(psi) terms lose factors "
            "(sin(l), sin(psi)) and the constant is wrong; the derivation gives "
            "(A^2 + B^2)/Omega^2 with A, B of eq. 44, whose coefficients are eq. 47's A-D (which match) "
            "and the constant cos^2 l cos^2 ph + sin^2 l (1 - cos^2 th cos^2 ph)",
        )
    )
    for key in ("A", "B", "C", "D"):
        out.append(Check(f"47.{key}", printed=P.PRINTED[f"47.{key}"], derived=a3[f"{key}47"]))
    out.append(
        Check(
            "47.E",
            printed=P.PRINTED["47.E"],
            derived=a3["E47"],
            if_differs="error of the paper (not explained by OCR): the constant must be "
            "cos^2 l cos^2 ph + sin^2 l (1 - cos^2 th cos^2 ph) - (w_max / w^EI)^2; the printed "
            "constant differs and the ratio lacks its square. With the printed E the quartic does "
            "not return the true azimuth even for ideal sensors (tests/test_audit_north_finding.py); "
            "the pipeline uses the derived E",
        )
    )
    Aq, Bq, Cq, Dq, Eq = a3["_quartic_symbols"]
    to_printed = {Aq: P.A, Bq: P.B, Cq: P.C, Dq: P.D, Eq: P.E}
    eq47 = P.A * P.c_psi**2 + P.B * P.c_psi + P.C * P.c_psi * P.s_psi + P.D * P.s_psi + P.E
    out.append(Check("48", printed=P.PRINTED["48"], derived=eq47))
    out.append(
        Check(
            "49",
            printed=P.PRINTED["49"],
            derived=sp.expand(
                (P.A * P.c_psi**2 + P.B * P.c_psi + P.E) ** 2
                - P.s_psi**2 * (P.C * P.c_psi + P.D) ** 2
            ),
        )
    )
    quartic = sp.Matrix([a3[k].xreplace(to_printed) for k in ("F", "G", "H", "I", "J")])
    out.append(
        Check(
            "50",
            printed=P.PRINTED["50"],
            derived=quartic,
            if_match="F..J from expanding eq. 49 with sin^2 psi = 1 - cos^2 psi",
        )
    )
    f_tau = P.A * sp.sin(s.tau) + P.B * sp.cos(s.tau)
    out.append(
        Check(
            "51",
            printed=P.PRINTED["51"],
            derived=sp.Matrix([sp.diff(f_tau, s.tau), sp.tan(sp.atan2(P.A, P.B))]),
            sample={P.B: (0.2, 1.3)},
            if_match="tan(tau*) = A/B (B > 0 sampled; atan2(A, B) picks the maximum, tan^-1 alone "
            "is ambiguous by pi)",
        )
    )
    out.append(
        Check(
            "52",
            printed=P.PRINTED["52"],
            derived=a3["amp_A"] / a3["amp_B"],
            if_differs="OCR artefact: the two-line numerator A = cos ps sin th sin ph cos l - sin ps "
            "cos ph cos l - cos th sin ph sin l is split into a fraction; the intended form is "
            "tan(tau*) = A/B with A, B of eq. 44 (eq. 51). The pipeline uses tau* = atan2(A, B)",
        )
    )
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
            if_differs="OCR artefact: the ratio (cos ps cos th cos l + sin th sin l) / ((cos ps sin th "
            "sin ph - sin ps cos ph) cos l - cos th sin ph sin l) has two-line numerator and denominator, "
            "read as a sum of two fractions",
        )
    )
    out.append(
        Check(
            "58",
            printed=P.PRINTED["58"],
            derived=sp.Matrix([a4["A"], a4["B"], a4["C"]]),
            if_differs="B is wrong as printed: B = (omega_1/omega_2) sin th sin ph - cos th (cos th is "
            "not divided by omega_2); A and C match. Likely the extent of the fraction bar lost in the "
            "OCR (the '2' under each fraction is the subscript of omega_2)",
        )
    )
    out.append(
        Check(
            "59",
            printed=P.PRINTED["59"],
            derived=sp.Matrix(half),
            if_differs="typo or OCR: C^2 belongs under the root, sqrt(A^2 + B^2 - C^2), as in eqs. 41 "
            "and 43",
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
            if_differs="typo: the last term must be -2 cos th tan ph tan^2 l sin th tan th tan ph "
            "(printed tan th tan th)"
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
            if_differs="typo: under the root 4AB cos^2 l, not 4AB cos l; the simplified form that "
            "follows (65.c) is right",
        )
    )
    out.append(Check("65.c", printed=P.PRINTED["65.c"], derived=roots, sample=pos))
    out.append(Check("66", printed=P.PRINTED["66"], derived=(a5["scale_approx"] - 1).xreplace(to5)))
    out.append(
        Check(
            "67",
            printed=P.PRINTED["67"],
            derived=a5["cos_psi_sol"],
            if_differs="fraction-bar extent (OCR or typo): cos psi = omega_1 / (S cos th cos l) - "
            "tan th tan l (eqs. 61-62), the subtraction is outside the fraction; arccos also leaves "
            "the sign of psi to the compass",
        )
    )
    a6 = azimuth.method6()
    out.append(
        Check(
            "68",
            printed=P.PRINTED["68"],
            derived=a6["model_z"],
            if_differs="dimension slip (as eq. 37): the table rate omega is multiplied by w^EI; the "
            "gyro reads S (w^EI [...] + omega) + b. The paper then sets omega = 0, where both agree",
        )
    )
    out.append(
        Check(
            "69",
            printed=P.PRINTED["69"],
            derived=sp.expand((a6["model_z"] - s.b) / s.Omega),
            if_differs="same slip as eq. 68: omega_3 = S ([...] + omega / w^EI); equal at omega = 0",
        )
    )
    out.append(Check("70", printed=P.PRINTED["70"], derived=a6["scale"]))
    out.append(Check("71", printed=P.PRINTED["71"], derived=a6["scale_approx"] - 1))
    return out


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
