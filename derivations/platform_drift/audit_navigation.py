"""Equation audit of the platform-drift paper, eqs. 1-19 (sections 2-4): frames, the equations of
motion, the position-independent algorithm and the specific force on the platform.
"""

from __future__ import annotations

import sympy as sp

from derivations.checks import Check
from derivations.platform_drift import algorithm as alg
from derivations.platform_drift import kinematics as kin
from derivations.platform_drift import printed as P
from derivations.platform_drift import specific_force as sf
from derivations.platform_drift import symbols as s
from derivations.platform_drift.approx import taylor

__all__ = ["checks"]

TILTS = [s.phi_x, s.phi_y]


def _eqs_1_to_11() -> list[Check]:
    out = [
        Check(
            "1",
            printed=P.PRINTED["1"],
            derived=kin.mat_mN_n(),
            if_match="m_N (NWU at the mass latitude) vs n (NWU at the plumb latitude "
            "phi_i + alpha_T) built from their axes: a rotation about the common west axis",
        ),
        Check(
            "2",
            printed=P.PRINTED["2"],
            derived=kin.mat_mN_s(),
            if_match="C_k are the active elementary rotations (transposes of rot_x/y/z): "
            "^{mN}_s C = mat_tn(psi, phi_y, phi_x)^T",
        ),
        Check("3", printed=P.PRINTED["3"], derived=kin.mat_mi_s()),
        Check(
            "4",
            printed=P.PRINTED["4"],
            derived=sp.Matrix(
                [*kin.transport_rate_mN(), *kin.earth_rate_mN(), *kin.azimuth_rate_mi()]
            ),
            if_match="transport rate and psi rate from Poisson's equation, Earth rate = NWU "
            "[omega^EI]^N; the subscript of the third vector is garbled in the OCR "
            "(omega_{m_i m_i}: read the rate of m_i relative to m_N); [p_m, q_m, r_m], [p, q, r] "
            "and [w_el1..3] are definitions",
        ),
    ]
    defn = "definition of the state (adopted as printed)"
    out += [
        Check("5", not_checkable=defn + ": ^s r_EB = [x, y, z], E the Earth's centre"),
        Check("6", not_checkable=defn + ": ^s v_iB = [u, v, w], the inertial velocity in s"),
        Check(
            "7",
            not_checkable=defn + ": ^s omega_is = [p, q, r], the platform's inertial rate "
            "(the sign of eq. 9 confirms that omega_is is the rate of s relative to i)",
        ),
    ]
    c = kin.coriolis_theorem()
    sub8 = {
        **dict(zip(P.Dir, c["D_i_r"], strict=True)),
        **dict(zip(P.wsi, c["w_si"], strict=True)),
        **dict(zip(P.rs, c["r_s"], strict=True)),
    }
    out.append(
        Check(
            "8",
            printed=P.PRINTED["8"].xreplace(sub8),
            derived=c["lhs"],
            if_match="checked on a concrete motion: s turning by 3-2-1 angles a(t), b(t), c(t) "
            "relative to i, r with arbitrary i-components; omega_si = -omega_is from Poisson's "
            "equation",
        )
    )
    out.append(Check("9", printed=P.PRINTED["9"], derived=kin.position_rates_s()))
    d10, _ = kin.velocity_equation_general()
    out.append(
        Check(
            "10",
            printed=P.PRINTED["10"],
            derived=d10,
            if_match="eq. 8 applied twice with omega_it constant and D_i D_i r = f + g",
        )
    )
    out.append(Check("11", printed=P.PRINTED["11"], derived=kin.velocity_rates_s()))
    return out


def _eqs_12_to_19() -> list[Check]:
    out = []
    lc = alg.level_commands()
    out.append(
        Check(
            "12",
            printed=P.PRINTED["12"],
            derived=sp.Matrix([lc["p_dot"], lc["q_dot"]]),
            if_match="the command rates that keep a level platform level (phi = phi_dot = 0 "
            "invariant) at constant radius (z_dot = 0) with r = 0",
        )
    )
    out.append(
        Check(
            "13",
            printed=P.PRINTED["13"],
            derived=kin.radius_rate_level()[::-1, :],
            if_match="omega_y, omega_x are the inertial rate of the radius vector, r x v / |r|^2, "
            "to first order in x, y (nearly level platform) and w (constant altitude)",
        )
    )
    exact_xy = kin.position_from_tilts()
    out.append(
        Check(
            "14",
            printed=taylor(
                P.PRINTED["14"].xreplace({s.x: exact_xy[0], s.y: exact_xy[1]}), TILTS, 1
            ),
            derived=sp.Matrix([s.phi_y, s.phi_x]),
            if_match="with the exact ^s r = ^s_{mN}C [0, 0, R_G] (x = -R_G sin phi_y, "
            "y = R_G cos phi_y sin phi_x), -x/R_G and y/R_G are phi_y and phi_x to first order",
        )
    )
    osc = alg.oscillation_equations()
    out.append(
        Check(
            "15",
            printed=P.PRINTED["15"],
            derived=sp.Matrix(
                [osc[k] for k in ("omega_y_dot", "omega_x_dot", "phi_y_dot", "phi_x_dot")]
            ),
            if_match="exact consequence of eqs. 9, 11-14 and spherical gravity; OCR drops the dot "
            "of omega_y_dot (first row) and of z_dot in the omega_x_dot row (read as dotted)",
        )
    )
    lhs16, rhs16 = alg.position_equation()
    out.append(
        Check(
            "16",
            printed=P.PRINTED["16"],
            derived=rhs16,
            discrepancy="one_mark",
            if_differs="cannot tell from the text: one symbol, once, C psi where S psi belongs in the second "
            "component of -^{m_i} omega_ie, and eq. 19's phi_y_dot has the right + omega_e "
            "cos(phi_i) sin(psi); the component must be +omega_e sin(psi) cos(phi_i) (C3(psi)^T "
            "[omega_e cos, 0, omega_e sin] = [omega_e cos cos psi, -omega_e cos sin psi, omega_e "
            "sin]). With the derived vector the equation gives (lambda_dot + omega_e) cos(phi_i) = "
            "cos psi p_m - sin psi q_m, phi_i_dot = sin psi p_m + cos psi q_m, psi_dot = r_m - "
            "(lambda_dot + omega_e) sin(phi_i) (generated position_rates)",
        )
    )
    f17 = sf.specific_force_s()
    out.append(
        Check(
            "17",
            printed=P.PRINTED["17"],
            derived=sp.Matrix([f17[0], f17[1]]),
            discrepancy="repeated_slip",
            if_differs="error of the paper: one exponent, but in both f1 and f2, the Coriolis term printed "
            "2 R sin(phi_i) (lambda_dot + omega_e)^2 phi_i_dot where it is 2 R sin(phi_i) "
            "(lambda_dot + omega_e) phi_i_dot (dimensionally the square is wrong); the rest matches "
            "the specific force of a vehicle on the sphere, first order in the tilts (reading the "
            "unmatched '(' as (R phi_ddot + R(...)^2 sin cos) cos psi)",
        )
    )
    f18 = sf.specific_force_stationary()
    out.append(Check("18", printed=P.PRINTED["18"], derived=sp.Matrix([f18[0], f18[1]])))
    k19 = alg.tilt_kinematics_stationary()
    out.append(
        Check(
            "19",
            printed=P.PRINTED["19"],
            derived=sp.Matrix([k19[k] for k in ("phi_x_dot", "phi_y_dot", "psi_dot")]),
            if_match="exact Euler kinematics of s relative to m_N for a vehicle at rest "
            "(omega_{mN s} = [p, q, r] - ^s_{mN}C omega_ie), first order in the tilts",
        )
    )
    return out


def checks() -> list[Check]:
    """The checks of this section, in equation order."""
    return [
        *_eqs_1_to_11(),
        *_eqs_12_to_19(),
    ]
