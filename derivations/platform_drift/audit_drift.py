"""Equation audit of the platform-drift paper, eqs. 28-36 (section 5): the tilt-error equations and
the drift of channels 1 and 3.
"""

from __future__ import annotations

import sympy as sp

from derivations.checks import Check
from derivations.platform_drift import algorithm as alg
from derivations.platform_drift import alignment as al
from derivations.platform_drift import drift as dr
from derivations.platform_drift import printed as P
from derivations.platform_drift import specific_force as sf
from derivations.platform_drift import symbols as s
from derivations.platform_drift.approx import taylor

__all__ = ["checks"]

# well-separated Schuler and Earth frequencies for the closed forms with 1/(W^2 - k_sh)
SEPARATED = {s.k_sh: (0.6, 1.3), s.omega_e: (0.05, 0.4)}


def _eq_28() -> list[Check]:
    ex = dr.tilt_error_equations()
    pr = alg.position_rates()
    # k_sh in the platform rates: phi_dot and (lambda_dot + omega_e) cos(phi) from eq. 16
    # (explicit form, derived) with p_m ~ p, q_m ~ q (they differ by first-order tilt rates)
    rates = {
        s.lat_dot: pr["phi_i_dot"].xreplace({s.p_m: s.p, s.q_m: s.q}),
        s.lon_dot: pr["lambda_dot"].xreplace({s.p_m: s.p, s.q_m: s.q}),
    }
    k_sh = P.PRINTED["28.k"].xreplace(rates)
    k_g = P.PRINTED["28.kg"][0].xreplace({s.z: s.R})
    printed = P.PRINTED["28"].xreplace({s.k_sh: k_sh, s.k_g: k_g})
    return [
        Check(
            "28",
            printed=printed,
            derived=sp.Matrix([ex["phi_x_ddot"], ex["phi_y_ddot"]]),
            discrepancy="approximation",
            if_differs="approximation of the paper: k_sh = g/R - (p^2 + q^2) lumps the gyroscopic terms as "
            "(p^2 + q^2) phi, the constant-k_sh model that eqs. 29-36 use throughout; differentiating "
            "eq. 15 with the commands of eq. 26 gives p^2 phi_x + p q phi_y (row 1) and q^2 phi_y + "
            "p q phi_x (row 2), which differ from the lumped form by (q phi_x - p phi_y)(q, -p). "
            "Relative size (p^2 + q^2)/(g/R): 0.3 % at rest, ~2 % at 1100 m/s. The b_g3, k_g, b_a "
            "and drift-rate terms match",
        ),
        Check(
            "28.k",
            printed=P.PRINTED["28.k"],
            derived=sf.k_sh_from_specific_force(),
            if_match="k_sh is the vertical specific force of a level platform over R (the tilt "
            "coefficient of eq. 17 divided by R)",
        ),
        Check(
            "28.kg",
            not_checkable="definitions: k_g = 1/z - 1/R_GMM and R_GMM = 1/(k_I k_G k_F) (loop "
            "gains of Fig. 3, 'k_l' is the OCR of k_I); k_g = 0 when R_GMM = z",
        ),
    ]


def _eqs_29_to_32() -> list[Check]:
    out = []
    model = dr.model_rhs()
    reps29 = {**dr.IDEAL_IMU, **dr.NO_GAIN_MISMATCH, **dr.CONSTANT_DRIFT, s.b_g3: 0}
    out.append(
        Check(
            "29",
            printed=P.PRINTED["29"],
            derived=sp.Matrix([model["phi_x_ddot"], model["phi_y_ddot"]]).xreplace(reps29),
            if_match="eq. 28 model with b_g3 = 0, ideal accelerometers, k_g = 0, constant drift",
        )
    )
    out.append(
        Check(
            "30",
            printed=P.PRINTED["30"],
            derived=sp.Matrix(
                [
                    dr.homogeneous_solution(s.B, s.A * sp.sqrt(s.k_sh)),
                    dr.homogeneous_solution(s.B2, s.A2 * sp.sqrt(s.k_sh)),
                ]
            ),
            if_match="dsolve of eq. 29 with phi(0) = B, phi_dot(0) = A sqrt(k_sh)",
        )
    )
    t21 = al.tilts_0m()
    phx0 = t21["phi_x"].subs(s.psi, s.psi0)
    out.append(
        Check(
            "30.B",
            printed=P.PRINTED["30.B"],
            derived=sp.Matrix([phx0, phx0.subs(s.theta_F2, 0)]),
            if_match="phi_x(0) of eq. 21; ideal IMU theta_F2 = 0 ('a' of the OCR read alpha)",
        )
    )
    full = {k: v.subs(s.psi, s.psi0) for k, v in al.tilt_rates_0p_full().items()}
    ic = dr.initial_conditions_ideal()
    out.append(
        Check(
            "31.x",
            printed=P.PRINTED["31.x"],
            derived=full["phi_x_dot"],
            discrepancy="wrong_term",
            if_differs="error of the paper: whole second-order terms are missing, -alpha^2 omega_e cos cos psi_0 "
            "+ alpha omega_e cos theta_F1, lost with eq. 24's alpha omega_e cos(phi_i); besides, one "
            "subscript (which alone the OCR could have misread): (-omega_e cos cos psi_0) theta_F2^2 "
            "must be theta_F1^2 (from r(0-) theta_F1 in (b_g3 - r(0-))(alpha cos psi_0 - "
            "theta_F1)). The first-order and ideal-IMU parts (31.x.ideal) match",
        )
    )
    out.append(
        Check(
            "31.x.ideal",
            printed=P.PRINTED["31.x.ideal"],
            derived=ic["phi_x_dot"].subs(s.b_g3, 0),
            if_match="ideal IMU, channel-1 drift only (b_g3 = 0), first order in alpha",
        )
    )
    out.append(
        Check(
            "31.y0",
            printed=P.PRINTED["31.y0"],
            derived=sp.Matrix(
                [
                    t21["phi_y"].subs(s.psi, s.psi0),
                    t21["phi_y"].subs({s.psi: s.psi0, s.theta_F1: 0}),
                ]
            ),
        )
    )
    out.append(
        Check(
            "31.y",
            printed=P.PRINTED["31.y"],
            derived=full["phi_y_dot"],
            discrepancy="wrong_term",
            if_differs="error of the paper: whole second-order terms are missing, alpha^2 omega_e cos sin psi_0 "
            "+ alpha omega_e cos theta_F2, lost with eq. 24, and the b_g3 terms carry the sign slip "
            "that recurs in eq. 34: eq. 27 gives phi_y_dot(0+) = (r(0-) - b_g3) phi_x0 + b_g2, so "
            "they are -(alpha sin psi_0) b_g3 - b_g3 theta_F2, printed with '+'. The ideal-IMU, "
            "b_g3 = 0 reduction (31.y.ideal) matches",
        )
    )
    out.append(
        Check(
            "31.y.ideal",
            printed=P.PRINTED["31.y.ideal"],
            derived=ic["phi_y_dot"].subs({s.b_g3: 0, s.b_g2: 0}),
            if_match="ideal IMU, channel-1 drift only (b_g2 = b_g3 = 0), first order in alpha",
        )
    )
    c1 = dr.channel1()
    out.append(
        Check(
            "32.def",
            not_checkable="definitions of the rate errors: p_merror = phi'_x_dot - phi_x_dot - "
            "b_g1, q_merror = phi'_y_dot - phi_y_dot (primes: with the drift); adopted by the "
            "derivation of 32.p, 32.q and 32",
        )
    )
    pos = {s.t: (0.0, 20.0), s.b_g1: (0.1, 2.0)}
    out.append(
        Check(
            "32.p",
            printed=P.PRINTED["32.p"],
            derived=sp.Matrix([c1["p_merror"], c1["int_p"]]),
            sample=pos,
            if_match="dsolve of eq. 29 with and without b_g1 from the ICs of eq. 31 (ideal IMU)",
        )
    )
    out.append(
        Check(
            "32.q",
            printed=P.PRINTED["32.q"],
            derived=sp.Matrix([c1["q_merror"], c1["int_q"]]),
        )
    )
    out.append(
        Check(
            "32",
            printed=P.PRINTED["32"],
            derived=c1["norm"],
            sample=pos,
            if_match="sqrt(int_p^2 + int_q^2) = |b_g1| (t - sin(sqrt(k_sh) t)/sqrt(k_sh)); "
            "sampled with b_g1 > 0; this is Table 2 row 4 with omega_0 = sqrt(k_sh), R_0 = 1, "
            "up to the sign convention",
        )
    )
    return out


def _eqs_33_to_36() -> list[Check]:
    out = []
    model = dr.model_rhs()
    reps = {**dr.IDEAL_IMU, **dr.NO_GAIN_MISMATCH, **dr.CONSTANT_DRIFT, s.b_g1: 0, s.b_g2: 0}
    m33 = sp.Matrix([model["phi_x_ddot"], model["phi_y_ddot"]]).xreplace(reps)
    out.append(
        Check(
            "33",
            printed=P.PRINTED["33"],
            derived=m33,
            if_match="eq. 28 model at rest, ideal IMU, channel-3 drift only",
        )
    )
    small = [s.b_g3, s.phi_x, s.phi_y, s.phi_x_dot, s.phi_y_dot]
    out.append(
        Check(
            "33.approx",
            printed=P.PRINTED["33.approx"],
            derived=taylor(m33, small, 1),
            if_match="first order in b_g3 and the tilts (b_g3 phi_dot is second order)",
        )
    )
    ic = dr.initial_conditions_ideal()
    ic34 = {k: v.subs({s.b_g1: 0, s.b_g2: 0}) for k, v in ic.items()}
    out.append(
        Check(
            "34",
            printed=P.PRINTED["34"],
            derived=sp.Matrix([ic34[k] for k in ("phi_x", "phi_x_dot", "phi_y", "phi_y_dot")]),
            discrepancy="repeated_slip",
            if_differs="error of the paper: one sign, the slip of eq. 31 again, carried into eq. 36: from eq. 27, "
            "phi_y_dot(0+) = alpha omega_e sin(phi_i) sin psi_0 - alpha sin psi_0 b_g3 (printed + "
            "alpha sin psi_0 b_g3); the other three rows match ('a' of the OCR read alpha). "
            "Propagates into eq. 36's int q_merror",
        )
    )
    out.append(
        Check(
            "35.ode",
            printed=P.PRINTED["35.ode"],
            derived=taylor(m33, small, 1),
            if_match="the first lines of eq. 35 repeat eq. 33 (OCR shows one dot; read phi_ddot)",
        )
    )
    w = alg.stationary_radius_rates()
    out.append(
        Check(
            "35.w",
            printed=P.PRINTED["35.w"],
            derived=sp.Matrix([w["omega_y"], w["omega_x"]]),
            if_match="omega = r x v / |r|^2 of a vehicle at rest on a level platform (eq. 13)",
        )
    )
    out.append(
        Check(
            "35.psi",
            printed=P.PRINTED["35.psi"],
            derived=taylor(dr.platform_azimuth_stationary(), [s.b_g3], 0),
            if_match="platform azimuth from eq. 19 at rest: psi_dot = b_g3 - omega_e sin(phi_i); "
            "the b_g3 t part changes the forcing only at order b_g3^2 and is dropped",
        )
    )
    forcing = dr.channel3_forcing()
    fx = -s.k_sh * s.phi_x + forcing["phi_x_ddot"]
    fy = -s.k_sh * s.phi_y + forcing["phi_y_ddot"]
    out.append(
        Check(
            "35",
            printed=P.PRINTED["35"].xreplace({s.Amp: P.AMP_35}),
            derived=sp.Matrix([fx, fx, fy, fy]),
            if_match="eq. 33 with omega(psi(t)), first order in b_g3; A = b_g3 omega_e cos(phi_i0) "
            "as the equality in eq. 35 defines it",
        )
    )
    c3 = dr.channel3()
    coef = P.PRINTED["36.coef"]
    sub36 = {**coef, s.Amp: P.AMP_35}
    out.append(
        Check(
            "36.p",
            printed=P.PRINTED["36.p"].xreplace(sub36),
            derived=c3["int_p"],
            sample=SEPARATED,
            if_match="dsolve of eq. 35 from the ICs of eq. 34 (x rows match) minus the drift-free "
            "solution of eq. 29 ('a' in the first term read alpha)",
        )
    )
    out.append(
        Check(
            "36.q",
            printed=P.PRINTED["36.q"].xreplace(sub36),
            derived=c3["int_q"],
            sample=SEPARATED,
            discrepancy="repeated_slip",
            if_differs="error of the paper: one sign, carried on from eqs. 31 and 34 into the first term: derived "
            "-(alpha sin psi_0 b_g3 / sqrt(k_sh)) sin(sqrt(k_sh) t); the forced and homogeneous "
            "A-terms with a', b' match. The generated error_ch3 uses the derived form",
        )
    )
    out.append(
        Check(
            "36.coef",
            not_checkable="definitions of a, b, a', b' (with W = omega_e sin(phi_i0)); checked "
            "through 36.p and 36.q, where they are substituted",
        )
    )
    return out


def checks() -> list[Check]:
    """The checks of this section, in equation order."""
    return [
        *_eq_28(),
        *_eqs_29_to_32(),
        *_eqs_33_to_36(),
    ]
