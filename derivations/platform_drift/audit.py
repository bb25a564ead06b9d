"""Equation audit of the platform-drift paper: every numbered equation, printed vs derived.

``python -m derivations.platform_drift.audit --out results/platform_drift/equation_audit.csv``

Each check pairs ``printed.PRINTED[eq]`` (the seed text, transcribed literally) with the
expression derived in ``kinematics``, ``algorithm``, ``specific_force``, ``alignment``,
``drift`` and ``schuler``. The status is computed by :func:`derivations.checks.run_check`;
the judgement texts below (``if_differs``) say what is correct and whether the difference
looks like a typo of the paper or an artefact of the OCR text. Where the paper linearises
("=~"), the derivation is truncated at the same order (:func:`approx.taylor`) and the note
says in which small quantities. The pipeline always uses the derived form.
"""

from __future__ import annotations

import pandas as pd
import sympy as sp

from derivations.checks import AuditRow, Check, audit_main, run_audit
from derivations.checks import audit_frame as checks_audit_frame
from derivations.platform_drift import algorithm as alg
from derivations.platform_drift import alignment as al
from derivations.platform_drift import drift as dr
from derivations.platform_drift import kinematics as kin
from derivations.platform_drift import printed as P
from derivations.platform_drift import schuler as sch
from derivations.platform_drift import specific_force as sf
from derivations.platform_drift import symbols as s
from derivations.platform_drift.approx import taylor

__all__ = ["checks", "audit_rows", "audit_frame", "main"]

TILTS = [s.phi_x, s.phi_y]
# well-separated Schuler and Earth frequencies for the closed forms with 1/(W^2 - k_sh)
SEPARATED = {s.k_sh: (0.6, 1.3), s.omega_e: (0.05, 0.4)}


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
            if_differs="the second component of -^{m_i} omega_ie must be +omega_e sin(psi) "
            "cos(phi_i) (C3(psi)^T [omega_e cos, 0, omega_e sin] = [omega_e cos cos psi, "
            "-omega_e cos sin psi, omega_e sin]); printed C psi, likely an S/C confusion of the "
            "OCR or a typo. With the derived vector the equation gives (lambda_dot + omega_e) "
            "cos(phi_i) = cos psi p_m - sin psi q_m, phi_i_dot = sin psi p_m + cos psi q_m, "
            "psi_dot = r_m - (lambda_dot + omega_e) sin(phi_i) (generated position_rates)",
        )
    )
    f17 = sf.specific_force_s()
    out.append(
        Check(
            "17",
            printed=P.PRINTED["17"],
            derived=sp.Matrix([f17[0], f17[1]]),
            if_differs="typo of the paper: the Coriolis term is 2 R sin(phi_i) (lambda_dot + "
            "omega_e) phi_i_dot, not (lambda_dot + omega_e)^2 (dimensionally the square is "
            "wrong); the rest matches the specific force of a vehicle on the sphere, first order "
            "in the tilts (reading the unmatched '(' as (R phi_ddot + R(...)^2 sin cos) cos psi)",
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


def _eqs_20_to_27() -> list[Check]:
    out = []
    ex = al.tilts_0m_exact()
    out.append(
        Check(
            "20",
            printed=P.PRINTED["20"],
            derived=sp.Matrix([ex["phi_y"], ex["phi_x"]]),
            if_differs="typo of the paper: sin(psi_0-) and cos(psi_0-) are swapped; eq. 18 with "
            "f = b_a gives phi_y0- = (R omega_e^2 sin cos cos(psi) - b_a1)/(g_i - R omega_e^2 "
            "cos^2) and phi_x0- = (R omega_e^2 sin cos sin(psi) + b_a2)/(...), as eq. 21 has it",
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
            if_differs="error of the paper: r(0-) = omega_e sin(phi_i) - d_r with d_r of eq. 23 "
            "(which contains -alpha omega_e cos(phi_i)) is omega_e sin(phi_i) + alpha omega_e "
            "cos(phi_i) + omega_e cos(phi_i)(sin psi theta_F2 - cos psi theta_F1): the printed "
            "result drops alpha omega_e cos(phi_i) (the plumb-aligned platform sees omega_e "
            "sin(phi_i + alpha)). The term is first order, like the theta_F terms kept; it enters "
            "eq. 31 only at second order (alpha^2), so eqs. 31-36 for an ideal IMU are unaffected",
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
            if_differs="approximation of the paper: differentiating eq. 15 with the commands of "
            "eq. 26 gives the gyroscopic terms p^2 phi_x + p q phi_y (row 1) and q^2 phi_y + p q "
            "phi_x (row 2); k_sh = g/R - phi_dot^2 - (lambda_dot + omega_e)^2 cos^2 = g/R - (p^2 "
            "+ q^2) lumps them as (p^2 + q^2) phi, which differs by (q phi_x - p phi_y)(q, -p). "
            "Relative size (p^2 + q^2)/(g/R): 0.3 % at rest, ~2 % at 1100 m/s. The b_g3, k_g, "
            "b_a and drift-rate terms match; eqs. 29-36 use the paper's constant-k_sh model",
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
            if_differs="two slips: (i) typo (-omega_e cos cos psi_0) theta_F2^2 must be theta_F1^2 "
            "(from r(0-) theta_F1 in (b_g3 - r(0-))(alpha cos psi_0 - theta_F1)); (ii) the "
            "second-order terms -alpha^2 omega_e cos cos psi_0 + alpha omega_e cos theta_F1 are "
            "missing because eq. 24 dropped alpha omega_e cos(phi_i). The first-order and "
            "ideal-IMU parts (31.x.ideal) match",
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
            if_differs="sign error of the paper: eq. 27 gives phi_y_dot(0+) = (r(0-) - b_g3) "
            "phi_x0 + b_g2, so the b_g3 terms are -(alpha sin psi_0) b_g3 - b_g3 theta_F2, printed "
            "with '+'; plus the second-order alpha^2 omega_e cos sin psi_0 + alpha omega_e cos "
            "theta_F2 lost with eq. 24. The ideal-IMU, b_g3 = 0 reduction (31.y.ideal) matches",
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
            if_differs="sign error (as in eq. 31): from eq. 27, phi_y_dot(0+) = alpha omega_e "
            "sin(phi_i) sin psi_0 - alpha sin psi_0 b_g3 (printed + alpha sin psi_0 b_g3); the "
            "other three rows match ('a' of the OCR read alpha). Propagates into eq. 36's "
            "int q_merror",
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
            if_differs="the first term inherits the sign error of eq. 34: derived -(alpha sin psi_0 "
            "b_g3 / sqrt(k_sh)) sin(sqrt(k_sh) t); the forced and homogeneous A-terms with a', b' "
            "match. The generated error_ch3 uses the derived form",
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


def _table2() -> list[Check]:
    t2 = sch.table2()
    out = []
    notes = {
        "T2.1": "x-channel Schuler loop with accelerometer bias B_x",
        "T2.2": "initial tilt phi_y(0) about the y axis (delta_a_x = -g phi_y)",
        "T2.3": "velocity change DeltaV_x at t = 0 through scale factor k_x: impulse k_x DeltaV_x",
        "T2.4": "gyro drift eps_y: phi_y_dot = delta_v_x / R_0 + eps_y",
        "T2.6": "initial velocity error",
        "T2.7": "initial azimuth error phi_z(0) couples the cross velocity v_y into phi_y_dot "
        "(phi x omega term); VI_c = v_y",
    }
    for key in ("T2.1", "T2.2", "T2.3", "T2.4"):
        out.append(Check(key, printed=P.PRINTED[key], derived=t2[key], if_match=notes[key]))
    out.append(
        Check(
            "T2.5",
            printed=P.PRINTED["T2.5"].xreplace({s.eps_z_p: s.eps_z}),
            derived=sp.Matrix(t2["T2.5"]),
            if_differs="with eps'_z read as the row's azimuth drift eps_z, the printed Dx, Dy are "
            "twice the derived (eps_z v_y / 2)[t^2 - 2(1 - cos w_0 t)/w_0^2]: phi_z = eps_z t "
            "gives delta_x'' + w_0^2 delta_x = w_0^2 v_y eps_z t^2 / 2. They agree for "
            "eps'_z = eps_z / 2, which the paper does not define (Pitman's notation). The "
            "generated table2_azimuth_drift takes eps_z and uses the derived form",
        )
    )
    out.append(
        Check(
            "T2.6",
            printed=P.PRINTED["T2.6"],
            derived=t2["T2.6"],
            if_match=notes["T2.6"],
        )
    )
    out.append(
        Check(
            "T2.7",
            printed=P.PRINTED["T2.7"].xreplace({s.VI_c: s.v_y}),
            derived=t2["T2.7"],
            if_match=notes["T2.7"],
        )
    )
    out.append(
        Check(
            "T2.8",
            not_checkable="legend row: omega_0 Schuler frequency, R_0 Earth radius, DeltaV_x "
            "velocity change, VI_c cross inertial velocity; example v_x = v_y = 1000 ft/s",
        )
    )
    return out


def checks() -> list[Check]:
    """All checks, in equation order."""
    return [
        *_eqs_1_to_11(),
        *_eqs_12_to_19(),
        *_eqs_20_to_27(),
        *_eq_28(),
        *_eqs_29_to_32(),
        *_eqs_33_to_36(),
        *_table2(),
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
