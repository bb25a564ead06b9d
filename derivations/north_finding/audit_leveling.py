"""Equation audit of the north-finding paper, eqs. 19-34 (section 3): levelling methods 1-5 and
the accelerometer bias and scale factor.
"""

from __future__ import annotations

import sympy as sp

from derivations.checks import Check
from derivations.north_finding import leveling, sensors
from derivations.north_finding import printed as P
from derivations.north_finding import symbols as s

DEG = leveling.DEG
IDEAL = leveling.IDEAL
SB = {s.S: s.S, s.b: s.b}

__all__ = ["checks"]


def checks() -> list[Check]:
    """Equation audit of the north-finding paper, eqs. 19-34 (section 3): levelling methods 1-5 and: the checks, in equation order."""
    out: list[Check] = []
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
            discrepancy="wrong_term",
            if_differs="error of the paper: a whole factor is missing, g in the rows of H, in a coherent line of "
            "the seed text; with Y = a_x (as printed) the rows of H must carry g, as in eq. 20 (the "
            "readings are not in units of g: eqs. 20 and 25-26 keep g explicit); the pipeline uses "
            "H = [cos t, -sin t] with Y = a_x / g",
        )
    )
    out.append(
        Check(
            "22",
            printed=P.PRINTED["22"],
            derived=sensors.coriolis_b(),
            discrepancy="wrong_term",
            if_differs="error of the paper: a whole factor is missing, the lever arm l in both p_x and p_z, which "
            "the seed text renders coherently (dimensionally they must carry l: 2 Omega x v_T with "
            "|v_T| = l omega); the block beside eq. 24 prints 2 w^EI l w; the derivation (transport "
            "theorem) gives 2 Omega l omega [-a_z, 0, a_x]",
        )
    )
    out.append(
        Check(
            "23",
            printed=P.PRINTED["23"],
            derived=leveling.ideal_accel("x", still=False),
            discrepancy="visible_garble",
            if_differs="artefact of the text: a line is displaced to another block, the Coriolis line p_x of eq. "
            "22, which the displayed eq. 23 omits and the block printed beside eq. 24 has (23.x, which "
            "matches); the two-column layout split the equation",
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
    return out
