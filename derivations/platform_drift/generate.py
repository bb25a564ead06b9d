"""Generate ``pipeline/generated/platform_drift.py`` from the derivations.

Run ``python -m derivations.platform_drift.generate``; ``--check`` exits non-zero if the
committed file is stale. The strapdown comparator's velocity equation and the Earth-relative
velocity (derivations/platform_drift/strapdown.py) are generated here too. Where the printed equation differs from the derivation (eqs. 16,
17, 20, 24, 36, Table 2 row 5; see the audit), the generated function is the derived one.
"""

from __future__ import annotations

from pathlib import Path

import sympy as sp

from derivations.codegen import GeneratedFunction, generate_main, render_module
from derivations.platform_drift import algorithm as alg
from derivations.platform_drift import alignment as al
from derivations.platform_drift import drift as dr
from derivations.platform_drift import kinematics as kin
from derivations.platform_drift import schuler as sch
from derivations.platform_drift import specific_force as sf
from derivations.platform_drift import strapdown as sdn
from derivations.platform_drift import symbols as s

OUTPUT = Path(__file__).resolve().parents[2] / "pipeline" / "generated" / "platform_drift.py"

NAMES = {
    s.lat: "lat",
    s.lon: "lon",
    s.lat_dot: "lat_dot",
    s.lon_dot: "lon_dot",
    s.lat_ddot: "lat_ddot",
    s.lon_ddot: "lon_ddot",
    s.g: "g",
    s.r0m: "r_0m",
    s.psi0: "psi0",
    s.omega0: "omega0",
    s.R0: "R0",
}

HEADER = """Numeric code of the stable-platform gyro-drift paper, generated from derivations/platform_drift.

Regenerate: python -m derivations.platform_drift.generate
Conventions: SI units, angles in rad, rates in rad/s; lat is the latitude phi_i of the mass
navigation frame m_N (north, west, up); every function broadcasts its arguments. Where the
paper prints an equation that differs from the derivation, the derived form is generated."""


_TABLE2 = (
    "Table 2 closed form, audited and checked against the Schuler loop by the tests; the "
    "strapdown curves are simulated (strapdown.py), not evaluated from Table 2"
)

#: Generated functions the pipeline does not call, with the reason (DESIGN.md invariant 1).
AUDIT_ONLY = {
    "motion_rates": (
        "eqs. 9 and 11 in s, checked against eq. 15 by the tests; the simulation integrates "
        "the platform DCM and the specific force instead"
    ),
    "gravity_spherical": "gravity model of eq. 15 (inside oscillation_rates), used by the tests",
    "specific_force_platform_linear": (
        "eq. 17 to first order in the tilts, for the audit; the simulation uses the exact "
        "specific_force_platform"
    ),
    "specific_force_stationary": "eq. 18 (eq. 17 at rest), for the audit and the notebook",
    "tilt_kinematics_stationary": (
        "eq. 19, first-order kinematics behind eqs. 28-36; the simulation integrates the DCM"
    ),
    "alignment_tilts": (
        "eq. 20, first order; platform.initial_state levels the platform exactly (mass or "
        "plumb vertical) instead"
    ),
    "r_alignment": (
        "eq. 24, the first-order form (in the tilts, alpha, theta_F) of alignment_rates' r, "
        "which platform.initial_state calls (equal to first order: tests/platform_drift); "
        "navigation commands r = 0 (eq. 25)"
    ),
    "nav_initial_tilt_rates": (
        "eq. 27, initial tilt rates of the analytic solution (eqs. 32, 36), used in the derivation"
    ),
    "table2_accel_bias": _TABLE2,
    "table2_initial_tilt": _TABLE2,
    "table2_scale_factor": _TABLE2,
    "table2_gyro_drift": _TABLE2,
    "table2_initial_velocity": _TABLE2,
    "table2_initial_azimuth": _TABLE2,
}


def _fn(name, args, exprs, doc, names=None, cse=True) -> GeneratedFunction:
    return GeneratedFunction(
        name,
        tuple(args),
        exprs,
        doc,
        {**NAMES, **(names or {})},
        audit_only=AUDIT_ONLY.get(name, ""),
        cse=cse,
    )


def _definitions_solved(unknowns, knowns) -> tuple[sp.Expr, ...]:
    """The definitions of eqs. 13-14 (alg.DEFINITIONS) solved for ``unknowns``."""
    eqs = [k - alg.DEFINITIONS[k] for k in knowns]
    sol = sp.solve(eqs, unknowns, dict=True)
    assert len(sol) == 1
    return tuple(sol[0][u] for u in unknowns)


def functions() -> list[GeneratedFunction]:
    """The generated functions, each derived in derivations/platform_drift."""
    rdot, vdot = kin.position_rates_s(), kin.velocity_rates_s()
    grav = alg.gravity_s()
    osc = alg.oscillation_equations()
    lc = alg.level_commands()
    pr = alg.position_rates()
    k19 = alg.tilt_kinematics_stationary()
    f_exact = sf.specific_force_s_exact()
    f17 = sf.specific_force_s()
    t20 = al.tilts_0m_exact()
    rates0 = al.rates_0m_exact()
    ka = alg.known_altitude()
    j27 = al.tilt_rates_0p()
    c1, c3 = dr.channel1(), dr.channel3()
    t2 = sch.table2()
    stat = sf.STATIONARY
    fns = [
        _fn(
            "motion_rates",
            (s.x, s.y, s.z, s.u, s.v, s.w, s.p, s.q, s.r, s.f1, s.f2, s.f3, s.g1, s.g2, s.g3),
            (*rdot, *vdot),
            "Navigation equations in the platform frame s (eqs. 9 and 11):\n"
            "    x_dot = r y - q z + u, ..., u_dot = r v - q w + f1 + g1, ...\n"
            "    Returns (x_dot, y_dot, z_dot, u_dot, v_dot, w_dot).",
        ),
        _fn(
            "gravity_spherical",
            (s.x, s.y, s.z, s.GM),
            tuple(grav),
            "Spherical mass attraction -GM r / |r|^3 in s (the gravity model of eq. 15).\n"
            "    Returns (g1, g2, g3).",
        ),
        # eq. 13
        _fn(
            "radius_rates_from_velocity",
            (s.u, s.v, s.z),
            _definitions_solved((s.omega_x, s.omega_y), (s.u, s.v)),
            "Eq. 13 (the definitions eq. 15 is written in): omega_x = -v/z, omega_y = u/z.\n"
            "    Returns (omega_x, omega_y).",
            cse=False,
        ),
        # eq. 14
        _fn(
            "tilts_from_position",
            (s.x, s.y, s.R_G),
            _definitions_solved((s.phi_x, s.phi_y), (s.x, s.y)),
            "Eq. 14 (the definitions eq. 15 is written in): phi_x = y/R_G, phi_y = -x/R_G.\n"
            "    Returns (phi_x, phi_y).",
            cse=False,
        ),
        # eq. 14 solved for the position
        _fn(
            "position_from_tilts",
            (s.phi_x, s.phi_y, s.R_G),
            (alg.DEFINITIONS[s.x], alg.DEFINITIONS[s.y]),
            "Eq. 14 solved for the position: x = -R_G phi_y, y = R_G phi_x. Returns (x, y).",
        ),
        _fn(
            "known_altitude_z",
            (s.x, s.y, s.R_G),
            ka["z"],
            "Vertical channel, known altitude: z = sqrt(R_G^2 - x^2 - y^2) from |^s r_EB| = R_G.",
            cse=False,
        ),
        _fn(
            "known_altitude_z_dot",
            (s.x, s.y, s.z, s.x_dot, s.y_dot),
            ka["z_dot"],
            "Vertical channel, known constant altitude: z_dot = -(x x_dot + y y_dot)/z.",
            cse=False,
        ),
        _fn(
            "platform_commands_rates",
            (s.f1, s.f2, s.z),
            (lc["p_dot"], lc["q_dot"]),
            "Position-independent torquing commands (eq. 12): p_dot = -f2/z, q_dot = f1/z.\n"
            "    Derived as the rates that keep a level platform level. Returns (p_dot, q_dot).",
        ),
        _fn(
            "oscillation_rates",
            (
                s.omega_x,
                s.omega_y,
                s.phi_x,
                s.phi_y,
                s.p,
                s.q,
                s.r,
                s.p_dot,
                s.q_dot,
                s.z,
                s.z_dot,
                s.R_G,
                s.GM,
            ),
            tuple(osc[k] for k in ("omega_x_dot", "omega_y_dot", "phi_x_dot", "phi_y_dot")),
            "Platform oscillation ODEs (eq. 15, spherical gravity), with omega_y = u/z,\n"
            "    omega_x = -v/z, phi_y = -x/R_G, phi_x = y/R_G (eqs. 13-14).\n"
            "    Returns (omega_x_dot, omega_y_dot, phi_x_dot, phi_y_dot).",
        ),
        _fn(
            "position_rates",
            (s.p_m, s.q_m, s.r_m, s.lat, s.psi, s.omega_e),
            (pr["lambda_dot"], pr["phi_i_dot"], pr["psi_dot"]),
            "Explicit form of the position equation (eq. 16, derived; the printed matrix form has\n"
            "    C psi for S psi in -^{m_i} omega_ie): (lambda_dot + omega_e) cos(lat) =\n"
            "    cos psi p_m - sin psi q_m, lat_dot = sin psi p_m + cos psi q_m,\n"
            "    psi_dot = r_m - (lambda_dot + omega_e) sin(lat). The algorithm uses p_m = omega_x,\n"
            "    q_m = omega_y, r_m = 0. Singular at the poles. Returns (lon_dot, lat_dot, psi_dot).",
        ),
        _fn(
            "specific_force_platform",
            (
                s.R,
                s.g,
                s.omega_e,
                s.lat,
                s.lat_dot,
                s.lat_ddot,
                s.lon_dot,
                s.lon_ddot,
                s.psi,
                s.phi_x,
                s.phi_y,
            ),
            tuple(f_exact),
            "Specific force on the platform of a vehicle moving on a sphere of radius R with\n"
            "    Earth rate (exact in the tilts; eq. 17 is its first-order form). g is the mass\n"
            "    gravity g_i. Returns (f1, f2, f3).",
        ),
        _fn(
            "specific_force_platform_linear",
            (
                s.R,
                s.g,
                s.omega_e,
                s.lat,
                s.lat_dot,
                s.lat_ddot,
                s.lon_dot,
                s.lon_ddot,
                s.psi,
                s.phi_x,
                s.phi_y,
            ),
            (f17[0], f17[1]),
            "Eq. 17 derived (first order in the tilts; the printed Coriolis term squares\n"
            "    (lambda_dot + omega_e), which is a typo). Returns (f1, f2).",
        ),
        _fn(
            "specific_force_stationary",
            (s.R, s.g, s.omega_e, s.lat, s.psi, s.phi_x, s.phi_y),
            (f17[0].subs(stat), f17[1].subs(stat)),
            "Eq. 18: the specific force of eq. 17 for a vehicle at rest. Returns (f1, f2).",
        ),
        _fn(
            "tilt_kinematics_stationary",
            (s.p, s.q, s.r, s.phi_x, s.phi_y, s.psi, s.lat, s.omega_e),
            tuple(k19[k] for k in ("phi_x_dot", "phi_y_dot", "psi_dot")),
            "Eq. 19: tilt and azimuth kinematics of the platform at rest, first order in the tilts.\n"
            "    Returns (phi_x_dot, phi_y_dot, psi_dot).",
        ),
        _fn(
            "k_sh_stationary",
            (s.g, s.R, s.omega_e, s.lat),
            sf.k_sh_from_specific_force().subs(stat),
            "Schuler-like constant k_sh of eq. 28 at rest: g/R - omega_e^2 cos^2(lat)\n"
            "    (the vertical specific force over R).",
        ),
        _fn(
            "alpha_deflection",
            (s.R, s.omega_e, s.lat, s.g),
            sf.deflection_first_order(),
            "Plumb-line deflection alpha of eq. 21 (eq. 1's alpha_T to first order):\n"
            "    R omega_e^2 sin(lat) cos(lat) / g.",
        ),
        _fn(
            "alignment_tilts",
            (s.R, s.omega_e, s.lat, s.psi, s.g, s.b_a1, s.b_a2),
            (t20["phi_x"], t20["phi_y"]),
            "Tilts at the end of alignment (eq. 20, derived: the printed form swaps sin/cos psi).\n"
            "    Returns (phi_x, phi_y).",
        ),
        _fn(
            "r_alignment",
            (s.omega_e, s.lat, s.psi, s.alpha, s.theta_F1, s.theta_F2),
            al.r_0m(),
            "Platform rate about axis 3 at the end of alignment, r(0-) (eq. 24, derived: includes\n"
            "    + alpha omega_e cos(lat), which the paper drops).",
        ),
        _fn(
            "alignment_rates",
            (s.omega_e, s.lat, s.psi, s.phi_x, s.phi_y),
            (rates0["p"], rates0["q"], rates0["r"]),
            "Exact platform rates at the end of alignment, (p(0-), q(0-), r(0-)): the rates that\n"
            "    hold a platform with tilts phi_x, phi_y and azimuth psi still at rest (eq. 19\n"
            "    exact, phi_dot = psi_dot = 0; eq. 24 is r(0-) to first order). phi_x, phi_y, psi\n"
            "    are the angles of eq. 2. Returns (p, q, r).",
        ),
        _fn(
            "nav_initial_tilt_rates",
            (s.b_g1, s.b_g2, s.b_g3, s.r0m, s.phi_x, s.phi_y),
            (j27["phi_x_dot"], j27["phi_y_dot"]),
            "Tilt rates at the start of navigation (eq. 27): (phi_x_dot(0+), phi_y_dot(0+)).",
        ),
        _fn(
            "error_ch1",
            (s.t, s.b_g1, s.k_sh),
            (c1["int_p"], c1["int_q"]),
            "Integrated rate errors (int p_merror, int q_merror) in rad for a constant level-gyro\n"
            "    drift b_g1 at rest (eq. 32): (-b_g1 t + b_g1 sin(sqrt(k_sh) t)/sqrt(k_sh), 0);\n"
            "    their norm, times R, is the position error.",
        ),
        _fn(
            "error_ch3",
            (s.t, s.b_g3, s.omega_e, s.lat, s.psi0, s.k_sh, s.alpha),
            (c3["int_p"], c3["int_q"]),
            "Integrated rate errors (int p_merror, int q_merror) in rad for a constant azimuth-gyro\n"
            "    drift b_g3 at rest (eq. 36, derived: the first term of int q_merror is\n"
            "    -alpha sin(psi0) b_g3 sin(sqrt(k_sh) t)/sqrt(k_sh); the paper prints '+').\n"
            "    Requires omega_e^2 sin^2(lat0) != k_sh.",
            {s.lat: "lat0"},
        ),
        _fn(
            "oscillation_period",
            (s.k_sh,),
            dr.oscillation_period(),
            "Period of the tilt oscillation of eq. 30, 2 pi / sqrt(k_sh) (the Schuler period for\n"
            "    the k_sh of eq. 28).",
        ),
        _fn(
            "schuler_period",
            (s.g, s.R),
            sch.schuler_period(),
            "Schuler period 2 pi / sqrt(g / R) (eq. 30 with k_sh = g/R).",
        ),
        _fn(
            "table2_accel_bias",
            (s.t, s.B_x, s.omega0),
            t2["T2.1"],
            "Table 2 row 1: accelerometer bias, B/omega0^2 (1 - cos omega0 t).",
            {s.B_x: "B"},
        ),
        _fn(
            "table2_initial_tilt",
            (s.t, s.phi_y0, s.R0, s.omega0),
            t2["T2.2"],
            "Table 2 row 2: initial tilt, -R0 phi0 (1 - cos omega0 t).",
            {s.phi_y0: "phi0"},
        ),
        _fn(
            "table2_scale_factor",
            (s.t, s.k_x, s.dV_x, s.omega0),
            t2["T2.3"],
            "Table 2 row 3: scale factor k and velocity change dV at t = 0, k dV/omega0 sin omega0 t.",
            {s.k_x: "k", s.dV_x: "dV"},
        ),
        _fn(
            "table2_gyro_drift",
            (s.t, s.eps_y, s.R0, s.omega0),
            t2["T2.4"],
            "Table 2 row 4: level gyro drift, -R0 eps (t - sin(omega0 t)/omega0).",
            {s.eps_y: "eps"},
        ),
        _fn(
            "table2_azimuth_drift",
            (s.t, s.eps_z, s.v_x, s.v_y, s.omega0),
            tuple(t2["T2.5"]),
            "Table 2 row 5, derived: azimuth drift eps_z, (dx, dy) = (eps_z/2)(v_y, -v_x)\n"
            "    [t^2 - 2(1 - cos omega0 t)/omega0^2] (the paper's eps'_z is eps_z/2).\n"
            "    Returns (dx, dy); the error is sqrt(dx^2 + dy^2).",
            {s.eps_z: "eps_z", s.v_x: "vx", s.v_y: "vy"},
        ),
        _fn(
            "table2_initial_velocity",
            (s.t, s.dxdot0, s.omega0),
            t2["T2.6"],
            "Table 2 row 6: initial velocity error, dv0/omega0 sin omega0 t.",
            {s.dxdot0: "dv0"},
        ),
        _fn(
            "table2_initial_azimuth",
            (s.t, s.phi_z0, s.v_y, s.omega0),
            t2["T2.7"],
            "Table 2 row 7: initial azimuth error, phi_z0 v_cross (t - sin(omega0 t)/omega0).",
            {s.phi_z0: "phi_z0", s.v_y: "v_cross"},
        ),
    ]
    return fns + sdn.functions(NAMES)


def source() -> str:
    """The module source text."""
    return render_module(functions(), HEADER)


def main(argv: list[str] | None = None) -> int:
    return generate_main(source, OUTPUT, "derivations.platform_drift.generate", argv)


if __name__ == "__main__":
    raise SystemExit(main())
