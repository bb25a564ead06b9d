"""Equation audit of the platform-drift paper, eqs. 20-27 (section 4): the end of alignment and the
transition to navigation.
"""

from __future__ import annotations

import sympy as sp

from derivations.checks import Check
from derivations.platform_drift import alignment as al
from derivations.platform_drift import printed as P
from derivations.platform_drift import specific_force as sf
from derivations.platform_drift import symbols as s

__all__ = ["checks"]


def _eqs_20_to_27() -> list[Check]:
    out = []
    ex = al.tilts_0m_exact()
    out.append(
        Check(
            "20",
            printed=P.PRINTED["20"],
            derived=sp.Matrix([ex["phi_y"], ex["phi_x"]]),
            discrepancy="repeated_slip",
            if_differs="error of the paper: sin(psi_0-) and cos(psi_0-) are swapped in both rows, which the seed "
            "text renders coherently; eq. 18 with f = b_a gives phi_y0- = (R omega_e^2 sin cos "
            "cos(psi) - b_a1)/(g_i - R omega_e^2 cos^2) and phi_x0- = (R omega_e^2 sin cos sin(psi) "
            "+ b_a2)/(...), as eq. 21 has it",
        )
    )
    defs = P.PRINTED["21.defs"]
    t21 = al.tilts_0m()
    first = sp.Matrix([t21["phi_y"], t21["phi_x"]]).xreplace(defs)
    out.append(
        Check(
            "21",
            printed=P.PRINTED["21"].xreplace(defs),
            derived=sp.Matrix([*first, *first]),
            if_match="eq. 20 (derived) to first order in R omega_e^2 / g_i and b_a / g_i",
        )
    )
    out.append(
        Check(
            "21.alpha",
            printed=P.PRINTED["21.alpha"],
            derived=sf.deflection_first_order(),
            if_match="alpha is the plumb-line deflection alpha_T of eq. 1, atan(R omega_e^2 sin "
            "cos / (g_i - R omega_e^2 cos^2)), to first order in R omega_e^2 / g_i",
        )
    )
    out.append(
        Check(
            "22",
            not_checkable="steady state of the channel-3 alignment loop (Fig. 4, not in the text: "
            "its gains k_psi, k_r, k_psiI, k_psiP are not given); adopted: psi_dot(0-) = 0",
        )
    )
    dr_ = al.disturbance_dr().subs(s.q, al.q_0m())
    dr_ = sp.expand(dr_)
    quad = dr_.coeff(s.phi_x, 2) * s.phi_x**2
    tilts = {s.phi_x: t21["phi_x"], s.phi_y: t21["phi_y"]}
    out.append(
        Check(
            "23",
            printed=P.PRINTED["23"],
            derived=sp.Matrix([al.disturbance_dr(), quad + sp.expand(dr_ - quad).xreplace(tilts)]),
            if_match="d_r from eq. 19 (derived); q(0-) = r phi_x + omega_y0 from phi_y_dot = 0 "
            "with omega_y0 = -omega_e cos sin psi of a vehicle at rest; tilts of eq. 21",
        )
    )
    out.append(
        Check(
            "23.approx",
            printed=P.PRINTED["23.approx"],
            derived=al.disturbance_dr_0m(first_order=True),
            if_match="first order in alpha, theta_F (r phi_x^2 dropped)",
        )
    )
    out.append(
        Check(
            "24",
            printed=P.PRINTED["24"],
            derived=al.r_0m(),
            discrepancy="wrong_term",
            if_differs="error of the paper: a whole term is dropped, alpha omega_e cos(phi_i), and eq. 31 "
            "carries the loss: r(0-) = omega_e sin(phi_i) - d_r with d_r of eq. 23 (which contains "
            "-alpha omega_e cos(phi_i)) is omega_e sin(phi_i) + alpha omega_e cos(phi_i) + omega_e "
            "cos(phi_i)(sin psi theta_F2 - cos psi theta_F1) (the plumb-aligned platform sees "
            "omega_e sin(phi_i + alpha)). The term is first order, like the theta_F terms kept; it "
            "enters eq. 31 only at second order (alpha^2), so eqs. 31-36 for an ideal IMU are "
            "unaffected",
        )
    )
    out.append(
        Check(
            "25",
            not_checkable="model statement: the third gyro is commanded zero at 0+, so the "
            "platform turns at its drift, r(0+) = b_g3 (used in eqs. 27-36)",
        )
    )
    out.append(
        Check(
            "26",
            not_checkable="navigation-phase loop of Fig. 3 with k_P = 0 (block diagram not in the "
            "text, gains not given); adopted: its derivative p_dot = -(f2 - b_a2)/R_GMM + "
            "b_g1_dot enters eq. 28. 'k_c' is the OCR of k_G",
        )
    )
    j27 = al.tilt_rates_0p()
    out.append(
        Check(
            "27",
            printed=P.PRINTED["27"],
            derived=sp.Matrix([j27["phi_y_dot"], j27["phi_x_dot"]]),
            if_match="jumps of eq. 19 (derived) at 0+: r(0-) -> r(0+) = b_g3 and the uncompensated "
            "drifts b_g1, b_g2 added to p, q; the printed middle members omit b_g2, b_g1",
        )
    )
    return out


def checks() -> list[Check]:
    """The checks of this section, in equation order."""
    return [
        *_eqs_20_to_27(),
    ]
