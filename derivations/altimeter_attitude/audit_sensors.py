"""Equation audit of the altimeter-attitude paper, eqs. 1-12 (sections 2 and 3): the attitude
kinematics of the gyros and the levelling of the accelerometers.
"""

from __future__ import annotations

import numpy as np
import sympy as sp

from derivations.altimeter_attitude import kinematics as kin
from derivations.altimeter_attitude import leveling as lv
from derivations.altimeter_attitude import printed as P
from derivations.altimeter_attitude import symbols as s
from derivations.checks import Check
from derivations.frames import earth_rate_n, mat_tn

__all__ = ["checks", "ROW3", "subs_vec"]

ROW3 = (s.C31, s.C32, s.C33)


def subs_vec(symbols, values) -> dict:
    """{symbol_i: value_i} for two equally long sequences."""
    return dict(zip(list(symbols), list(values), strict=True))


def _offsets(expr: sp.Expr, symbols: list[sp.Symbol]) -> str:
    """The distinct values of ``expr`` at seeded points in (0.15, 1.3), as a multiple of pi."""
    rng = np.random.default_rng(0)
    f = sp.lambdify(symbols, expr, "numpy")
    values = {round(float(f(*rng.uniform(0.15, 1.3, len(symbols)))) / np.pi, 12) for _ in range(40)}
    names = {-1.0: "-pi", 1.0: "pi", 0.0: "0"}
    return ", ".join(names.get(v, f"{v:g} pi") for v in sorted(values))


# ---------------------------------------------------------------- section 2: gyros


def _eqs_1_to_8() -> list[Check]:
    out = []
    w_nb = kin.body_rate_from_euler()
    to_euler = {**subs_vec(s.mat_C, kin.mat_nb()), **subs_vec(s.omega, w_nb)}
    out.append(
        Check(
            "1",
            printed=P.PRINTED["1"].xreplace(to_euler),
            derived=kin.dcm_rate(),
            if_match="OCR reading: the dot of d/dt C_b^n is lost and the right-hand C prints "
            "superscript m for n (C_b^m); read Cdot_b^n = C_b^n Omega_nb^b. Checked in Euler "
            "angles: C_b^n = mat_nb(phi, theta, psi), omega_nb^b from Poisson's equation, against "
            "the time derivative of mat_nb",
        )
    )
    out.append(
        Check(
            "2",
            printed=P.PRINTED["2"].xreplace(subs_vec(s.omega, w_nb)),
            derived=kin.mat_nb().T * kin.dcm_rate(),
            if_match="Omega_nb^b = C_n^b Cdot_b^n is the cross-product matrix [omega_nb^b x] "
            "(signs as printed); the C_b^n matrix printed with it is the definition of C11..C33",
        )
    )
    # eq. 3: the three parts computed separately (Earth rate and transport rate in NED,
    # resolved in b; omega_nb^b from the Euler angles) against omega_ib^b of the composed
    # C_b^i = C_e^i C_n^e C_b^n (kinematics.angular_velocity_addition)
    om_e = sp.Symbol("Omega_e", positive=True)
    lat, lon, lat_dot, lon_dot = sp.symbols("L l L_dot l_dot", real=True)
    mat_bn = mat_tn(s.psi, s.theta, s.phi)
    w_en_n = sp.Matrix([lon_dot * sp.cos(lat), -lat_dot, -lon_dot * sp.sin(lat)])
    parts = {
        **subs_vec(P.w_ie_b, mat_bn * earth_rate_n(om_e, lat)),
        **subs_vec(P.w_en_b, mat_bn * w_en_n),
        **subs_vec(s.omega, w_nb),
    }
    w_ib, _ = kin.angular_velocity_addition()
    out.append(
        Check(
            "3",
            printed=P.PRINTED["3"].xreplace(parts),
            derived=w_ib,
            if_match="printed sum with omega_ie^b = C_n^b Omega_e [cos L, 0, -sin L], omega_en^b = "
            "C_n^b [l_dot cos L, -L_dot, -l_dot sin L] (NED, latitude L, longitude l) and "
            "omega_nb^b from the Euler rates, against omega_ib^b of the composed C_b^i = C_e^i "
            "C_n^e C_b^n by Poisson's equation (numerically, at random angles, rates and t)",
        )
    )
    out.append(
        Check(
            "4",
            printed=P.PRINTED["4"],
            derived=kin.euler_rates(),
            if_match="'tg' is tan; singular at theta = +-90 deg (sampled in (0.15, 1.3))",
        )
    )
    out.append(
        Check(
            "5",
            printed=P.PRINTED["5"],
            derived=kin.quaternion_rates(),
            if_match="q_dot = 1/2 q (x) [0, omega_nb^b], scalar-first q = [a b c d] (c read c_q)",
        )
    )
    out.append(
        Check(
            "6.euler",
            printed=P.PRINTED["6.euler"].T,
            derived=kin.third_row_euler(),
            if_match="third row of C_b^n = mat_tn(psi, theta, phi)^T; yaw drops out",
        )
    )
    out.append(
        Check(
            "6.quat",
            printed=P.PRINTED["6.quat"].T,
            derived=kin.third_row_quaternion(),
            if_match="third row of the rotation v -> q (x) v (x) q* (c read c_q)",
        )
    )
    out.append(
        Check(
            "7",
            printed=P.PRINTED["7"],
            derived=kin.third_row_rates(sp.Matrix(ROW3)),
            if_match="third row of eq. 1: d/dt C(3,:) = C(3,:) Omega",
        )
    )
    out.append(
        Check(
            "8",
            printed=P.PRINTED["8"].xreplace(subs_vec(ROW3, kin.third_row_euler())),
            derived=sp.S.Zero,
            if_match="with C_3j of eq. 6 (Euler form): the row of an orthogonal matrix has unit "
            "norm; eq. 7 preserves it (c . (omega x c) = 0)",
        )
    )
    return out


# ---------------------------------------------------------------- section 3: accelerometers


def _eqs_9_to_12() -> list[Check]:
    out = []
    nav = lv.navigation_symbols()
    sub9 = {
        P.V_d: nav["V"][2],
        **subs_vec(P.w_ie_n, nav["w_ie"]),
        **subs_vec(P.w_en_n, nav["w_en"]),
    }
    out.append(
        Check(
            "9",
            printed=P.PRINTED["9"].xreplace(sub9),
            derived=lv.velocity_rate(),
            if_match="adopted, not derived: the paper cites the NED ground-speed equation "
            "(Titterton & Weston, eq. 3.16) and leveling.velocity_rate writes it down; checked "
            "that the printed form is that equation (V_e^n = [V_N, V_E, V_D], Earth and transport "
            "rates in NED, g^n = [0, 0, g]). The Coriolis theorem behind it is derived in the "
            "platform_drift paper, not here",
        )
    )
    f10 = lv.specific_force_level()
    out.append(
        Check(
            "10",
            printed=P.PRINTED["10"],
            derived=f10,
            if_match="-C_n^b g^n with C_b^n of the 3-2-1 angles; valid when V_dot + (2 omega_ie + "
            "omega_en) x V = 0 (the condition |(||f^b|| - g)| < epsilon is text)",
        )
    )
    on_f10 = subs_vec(s.f_b, f10)
    roll = P.PRINTED["11.phi"].xreplace(on_f10)
    offsets = _offsets(roll - s.phi, [s.phi, s.theta, s.g])
    out.append(
        Check(
            "11.phi",
            printed=roll,
            derived=s.phi,
            discrepancy="repeated_slip",
            if_differs="error of the paper: one sign, but missing from both arguments, "
            "atan2(f_y, f_z) where eq. 10's f_y = -g cos(theta) sin(phi), f_z = -g cos(theta) "
            "cos(phi) need atan2(-f_y, -f_z) (leveling.leveling_angles); as printed it gives "
            "atan2(-sin(phi), -cos(phi)) = phi - pi (mod 2 pi) for cos(theta) > 0 (computed: the "
            f"residual is {offsets} at the sampled phi, theta in (0.15, 1.3))",
        )
    )
    out.append(
        Check(
            "11.theta",
            printed=P.PRINTED["11.theta"].xreplace(on_f10),
            derived=s.theta,
            if_match="asin(f_x / g) with f_x = g sin(theta) of eq. 10 returns theta for |theta| "
            "< 90 deg",
        )
    )
    out.append(
        Check(
            "12",
            printed=P.PRINTED["12"],
            derived=lv.total_acceleration(),
            if_match="F_t^n = V_dot + (2 omega_ie + omega_en) x V (definition, first member) "
            "equals C_b^n f^b + g^n by eq. 9",
        )
    )
    return out


def checks() -> list[Check]:
    """The checks of this section, in equation order."""
    return [
        *_eqs_1_to_8(),
        *_eqs_9_to_12(),
    ]
