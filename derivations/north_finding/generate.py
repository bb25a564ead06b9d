"""Generate ``pipeline/generated/north_finding.py`` from the derivations.

Run ``python -m derivations.north_finding.generate`` (the workflow's ``codegen``
rule does); ``--check`` exits non-zero if the committed file is stale.
"""

from __future__ import annotations

from pathlib import Path

from derivations.codegen import GeneratedFunction, generate_main, render_module
from derivations.north_finding import azimuth, leveling, sensors
from derivations.north_finding import symbols as s

OUTPUT = Path(__file__).resolve().parents[2] / "pipeline" / "generated" / "north_finding.py"

NAMES = {
    s.lam: "lat",
    s.Omega: "omega_ie",
    s.w: "table_rate",
    s.w_dot: "table_accel",
    s.l: "lever_arm",
    s.S: "scale",
    s.b: "bias",
    s.a1: "a1",
    s.a2: "a2",
    s.a3: "a3",
    s.om1: "om1",
    s.om2: "om2",
    s.om3: "om3",
    s.ca: "a",
    s.cb: "b",
    s.cc: "c",
}

HEADER = """Numeric code of the north-finding paper, generated from derivations/north_finding.

Regenerate: python -m derivations.north_finding.generate
Conventions: angles in rad, rates in rad/s, accelerations in m/s^2; every function
broadcasts its arguments (vectorised over table positions and Monte Carlo trials)."""


def functions() -> list[GeneratedFunction]:
    """The generated functions, each derived in derivations/north_finding."""
    ang = (s.psi, s.theta, s.phi)
    f_b = sensors.specific_force_b()
    w_b = sensors.angular_rate_b()
    l1, l2, l3, l4, l5 = (
        leveling.method1(),
        leveling.method2(),
        leveling.method3(),
        leveling.method4(),
        leveling.method5(),
    )
    a11, a12, a2, a3 = (
        azimuth.method1_case1(),
        azimuth.method1_case2(),
        azimuth.method2(),
        azimuth.method3(),
    )
    a4, a5, a6 = azimuth.method4(), azimuth.method5(), azimuth.method6()
    A_, B_, C_, D_, E_ = a3["_quartic_symbols"]
    c_, s_ = a3["_cs"]
    A5, B5, C5 = a5["_ABC"]
    fns = [
        GeneratedFunction(
            "specific_force_b",
            (s.g, s.Omega, s.lam, *ang, s.tau, s.l, s.w, s.w_dot),
            tuple(f_b),
            "Specific force [f]^B of the sensor on the turning table (eqs. 16, 22-24):\n"
            "    f^B = a_T^B + 2 Omega^{EI} x v_T^B - g^B (centripetal -l w^2, tangential l w_dot,\n"
            "    Coriolis on x and z). Returns (f_x, f_y, f_z).",
        ),
        GeneratedFunction(
            "angular_rate_b",
            (s.Omega, s.lam, *ang, s.tau, s.w),
            tuple(w_b),
            "Angular rate [omega^{BI}]^B = [0, 0, omega] + [T]^{BT}[T]^{TN}[omega^{EI}]^N (eqs. 35-37).",
        ),
        GeneratedFunction(
            "l1_sin_theta",
            (s.ax_0, s.ax_180, s.g),
            l1["sin_theta"],
            "Levelling method 1, eq. 19: sin(theta).",
        ),
        GeneratedFunction(
            "l1_sin_phi",
            (s.ax_90, s.ax_270, s.g, s.theta),
            l1["sin_phi"],
            "Levelling method 1, eq. 19: sin(phi).",
        ),
        GeneratedFunction(
            "l2_design_row",
            (s.tau,),
            (l2["h_sin_theta"], l2["h_cth_sphi"]),
            "Levelling method 2, eqs. 20-21: row of H for X = [sin(theta), cos(theta) sin(phi)],\n"
            "    Y = a_x / g.",
        ),
        GeneratedFunction(
            "ls_sin_phi",
            (s.c_theta_s_phi, s.theta),
            l2["sin_phi"],
            "Levelling methods 2 and 4, eqs. 20-21 and 25-26: sin(phi) from the least-squares\n"
            "    unknown cos(theta) sin(phi) at the estimated theta.",
        ),
        GeneratedFunction(
            "l3_sin_theta",
            (s.ay_90, s.ay_270, s.g),
            l3["sin_theta"],
            "Levelling method 3, eq. 24: sin(theta).",
        ),
        GeneratedFunction(
            "l3_sin_phi",
            (s.ay_0, s.ay_180, s.g, s.theta),
            l3["sin_phi"],
            "Levelling method 3, eq. 24: sin(phi).",
        ),
        GeneratedFunction(
            "l4_design_row",
            (s.tau,),
            (l4["h_cth_sphi"], l4["h_sin_theta"]),
            "Levelling method 4, eqs. 25-26: row of H for X = [cos(theta) sin(phi), sin(theta)],\n"
            "    Y = -a_y / g.",
        ),
        GeneratedFunction(
            "l5_bias", (s.ax_0, s.ax_180), l5["bias"], "Levelling method 5, eq. 28: bias."
        ),
        GeneratedFunction(
            "l5_components",
            (s.ax_0, s.ax_90, s.ax_180, s.az),
            (l5["a1"], l5["a2"], l5["a3"]),
            "Levelling method 5, eqs. 29, 31: bias-free components a1, a2, a3.",
        ),
        GeneratedFunction(
            "l5_scale",
            (s.a1, s.a2, s.a3, s.g),
            l5["scale"],
            "Levelling method 5, eqs. 32-33: S = sqrt(a1^2 + a2^2 + a3^2) / g (S > 0).",
        ),
        GeneratedFunction(
            "l5_scale_approx",
            (s.a1, s.a2, s.a3, s.g),
            l5["scale_approx"],
            "Levelling method 5, eq. 34: S ~ 1 + (alpha - 1)/2, alpha = (a1^2+a2^2+a3^2)/g^2.",
        ),
        GeneratedFunction(
            "a1c1_cos_psi",
            (s.wx_0, s.wx_180, s.Omega, s.lam, s.theta),
            a11["cos_psi"],
            "Azimuth method 1 case 1, eq. 40: cos(psi) from tau = 0, 180 deg.",
        ),
        GeneratedFunction(
            "a1c2_coeffs",
            (s.wx_90, s.wx_270, s.Omega, s.lam, s.theta, s.phi),
            (a12["a"], a12["b"], a12["c"]),
            "Azimuth method 1 case 2, eqs. 40-41: a, b, c of a sin(psi) + b cos(psi) = c.",
        ),
        GeneratedFunction(
            "a2_coeffs",
            (s.w_tau, s.tau, s.Omega, s.lam, s.theta, s.phi),
            (a2["A"], a2["B"], a2["C"]),
            "Azimuth method 2, eq. 42: A, B, C of A sin(psi) + B cos(psi) = C.",
        ),
        GeneratedFunction(
            "sinusoid_roots",
            (s.ca, s.cb, s.cc),
            azimuth.phase_roots(),
            "Both roots psi of a sin(psi) + b cos(psi) = c (eqs. 41, 43, 59 in phase form:\n"
            "    psi = atan2(a, b) -/+ acos(c / sqrt(a^2 + b^2))), the ratio clipped to [-1, 1]:\n"
            "    the double root where |c| >= sqrt(a^2 + b^2) (callers count |c| > it as trouble).",
        ),
        GeneratedFunction(
            "a3_peak",
            (s.Omega, s.lam, *ang),
            (a3["tau_star"], a3["w_peak"]),
            "Azimuth method 3, eqs. 45, 51-52: location tau* and value sqrt(A^2 + B^2) of the\n"
            "    largest ideal gyro reading over tau.",
        ),
        GeneratedFunction(
            "a3_eq47_coeffs",
            (s.wx_max, s.Omega, s.lam, s.theta, s.phi),
            (a3["A47"], a3["B47"], a3["C47"], a3["D47"], a3["E47"]),
            "Azimuth method 3, eqs. 46-47: A..E of A c^2 + B c + C c s + D s + E = 0,\n"
            "    c = cos(psi), s = sin(psi).",
        ),
        GeneratedFunction(
            "a3_quartic_coeffs",
            (A_, B_, C_, D_, E_),
            (a3["F"], a3["G"], a3["H"], a3["I"], a3["J"]),
            "Azimuth method 3, eqs. 48-50: F..J of the quartic F c^4 + G c^3 + H c^2 + I c + J = 0.",
        ),
        GeneratedFunction(
            "a3_eq47_residual",
            (c_, s_, A_, B_, C_, D_, E_),
            a3["residual47"],
            "Azimuth method 3, eq. 47 before squaring: its residual, which rejects the roots\n"
            "    that squaring (eq. 49) introduces.",
        ),
        GeneratedFunction(
            "a3_eq47_residual_dpsi",
            (c_, s_, A_, B_, C_, D_, E_),
            a3["residual47_dpsi"],
            "Azimuth method 3, eq. 47: d/dpsi of its residual (sympy diff with c = cos psi,\n"
            "    s = sin psi), the derivative of the Newton polish.",
        ),
        GeneratedFunction(
            "a4_bias", (s.wx_0, s.wx_180), a4["bias"], "Azimuth method 4, eq. 55: gyro bias."
        ),
        GeneratedFunction(
            "a4_omegas",
            (s.wx_0, s.wx_90, s.wx_180, s.Omega),
            (a4["omega1"], a4["omega2"]),
            "Azimuth method 4, eq. 56: omega_1, omega_2 (bias-free readings over Omega).",
        ),
        GeneratedFunction(
            "a4_coeffs",
            (s.om1, s.om2, s.lam, s.theta, s.phi),
            (a4["A"], a4["B"], a4["C"]),
            "Azimuth method 4, eqs. 57-58: A, B, C of A sin(psi) + B cos(psi) = C.",
        ),
        GeneratedFunction(
            "a4_scale",
            (s.om1, s.psi, s.lam, s.theta),
            a4["scale"],
            "Azimuth method 4, eq. 60: S = omega_1 / (cos psi cos theta cos lambda + sin theta sin lambda).",
        ),
        GeneratedFunction(
            "a5_coeffs",
            (s.om1, s.om2, s.lam, s.theta, s.phi),
            (a5["A"], a5["B"], a5["C"]),
            "Azimuth method 5, eqs. 61-64: A, B, C of A = B/(S^2 cos^2 lambda) + C/(S cos lambda).",
        ),
        GeneratedFunction(
            "a5_scale_roots",
            (A5, B5, C5, s.lam),
            tuple(a5["scale_roots"]),
            "Azimuth method 5, eq. 65: both roots S of A cos^2(lambda) S^2 - C cos(lambda) S - B = 0.",
        ),
        GeneratedFunction(
            "a5_scale_approx",
            (A5, B5, C5, s.lam),
            a5["scale_approx"],
            "Azimuth method 5, eq. 66: S ~ 1 + sf with sf^2 dropped from eq. 65.",
        ),
        GeneratedFunction(
            "a5_cos_psi",
            (s.om1, s.S, s.lam, s.theta),
            a5["cos_psi_sol"],
            "Azimuth method 5, eqs. 62, 67: cos(psi) = omega_1/(S cos theta cos lambda) - tan theta tan lambda.",
        ),
        GeneratedFunction(
            "a6_omega3",
            (s.wz, s.wx_0, s.wx_180, s.Omega),
            a6["omega3"],
            "Azimuth method 6, eq. 69: omega_3 = (w_z - b)/Omega with b from eq. 55.",
        ),
        GeneratedFunction(
            "a6_scale",
            (s.om1, s.om2, s.om3),
            a6["scale"],
            "Azimuth method 6, eq. 70: S = sqrt(omega_1^2 + omega_2^2 + omega_3^2).",
        ),
        GeneratedFunction(
            "a6_scale_approx",
            (s.om1, s.om2, s.om3),
            a6["scale_approx"],
            "Azimuth method 6, eq. 71: S ~ 1 + (beta - 1)/2, beta = omega_1^2+omega_2^2+omega_3^2.",
        ),
    ]
    return [GeneratedFunction(f.name, f.args, f.exprs, f.doc, NAMES) for f in fns]


def source() -> str:
    """The module source text."""
    return render_module(functions(), HEADER)


def main(argv: list[str] | None = None) -> int:
    return generate_main(source, OUTPUT, "derivations.north_finding.generate", argv)


if __name__ == "__main__":
    raise SystemExit(main())
