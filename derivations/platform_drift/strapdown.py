"""The strapdown comparator's navigation equations (our model of the paper's comparison).

The paper compares its scheme with a strapdown INS (Figs. 5-8) without printing that
mechanisation; ``pipeline/platform_drift/strapdown.py`` integrates a NED mechanisation on
the same spherical Earth. Its velocity equation is eq. 10 (the Coriolis theorem twice,
:func:`derivations.platform_drift.kinematics.velocity_equation_general`) with

* t = e, the Earth-fixed frame turning at omega_ie, and s = n (NED), which turns relative to
  e at the transport rate omega_en, so omega_{n e} = -omega_en;
* every vector in NED components: omega_ie = ``frames.earth_rate_n``, omega_en =
  ``frames.transport_rate_n_velocity``, the position r = [0, 0, -rho] (the vehicle on the
  sphere of radius rho), the ground velocity v = [v_N, v_E, 0] (known altitude: the down
  velocity is zero), the acceleration a = f + [0, 0, g] (specific force plus mass gravity).

That gives ``dv/dt = f + g - (2 omega_ie + omega_en) x v - omega_ie x (omega_ie x r)``; with
the altitude known only the north and east rows are integrated.

:func:`ground_velocity` is eq. 8 for the Earth-fixed frame: v_e = D_e r = D_i r -
omega_ie x r, all three vectors in one set of axes (the pipeline passes the Earth rate of
``frames.earth_rate_e``). :func:`course_rate` is the yaw rate of the strapdown IMU's body,
which turns with the course of the truth path (``pipeline/platform_drift/trajectory.py``).
"""

from __future__ import annotations

from collections.abc import Mapping

import sympy as sp

from derivations import frames
from derivations.codegen import GeneratedFunction
from derivations.memo import derivation
from derivations.platform_drift import kinematics as kin
from derivations.platform_drift import symbols as s

__all__ = ["SYMBOLS", "velocity_rates_n", "ground_velocity", "course_rate", "functions"]

#: symbols of the strapdown equations: specific force in NED, ground velocity, radius
f_n, f_e, f_d = sp.symbols("f_N f_E f_D", real=True)
v_n, v_e = sp.symbols("v_N v_E", real=True)
rho = sp.Symbol("rho", positive=True)
r_vec = sp.Matrix(sp.symbols("r_x r_y r_z", real=True))
v_vec = sp.Matrix(sp.symbols("v_x v_y v_z", real=True))
w_vec = sp.Matrix(sp.symbols("w_x w_y w_z", real=True))
dlat, dlon = sp.symbols("dlat dlon", real=True)
SYMBOLS = {"f_n": f_n, "f_e": f_e, "f_d": f_d, "v_n": v_n, "v_e": v_e, "rho": rho}


@derivation
def velocity_rates_n() -> dict[str, sp.Expr]:
    """(v_N_dot, v_E_dot, v_D_dot) of the NED mechanisation on the sphere (eq. 10, t = e, s = n).

    v_D_dot is the down row; with the known altitude it is not integrated.
    """
    d_s_v, vec = kin.velocity_equation_general()
    w_ie = frames.earth_rate_n(s.omega_e, s.lat)
    w_en = frames.transport_rate_n_velocity(v_n, v_e, s.lat, rho)
    values = {
        "r": sp.Matrix([0, 0, -rho]),
        "v": sp.Matrix([v_n, v_e, 0]),
        "a": sp.Matrix([f_n, f_e, f_d]) + frames.gravity_n(s.g),
        "w": w_ie,
        "W": -w_en,
    }
    reps = {vec[k][i]: values[k][i] for k in values for i in range(3)}
    out = sp.expand(d_s_v.xreplace(reps))
    return {k: out[i] for i, k in enumerate(("v_N_dot", "v_E_dot", "v_D_dot"))}


def ground_velocity() -> sp.Matrix:
    """Eq. 8 for the Earth-fixed frame: D_e r = D_i r - omega_ie x r (v = D_i r, r and
    omega_ie = w in one set of axes)."""
    return v_vec - w_vec.cross(r_vec)


def course_rate() -> sp.Expr:
    """chi_dot of the truth path's course chi = atan2(dlon cos(lat), dlat) (clockwise from
    north; lat and lon linear in one progress variable), in lat and lat_dot."""
    la = sp.Function("phi_i")(s.t)
    chi_dot = sp.atan2(dlon * sp.cos(la), dlat).diff(s.t)
    chi_dot = chi_dot.subs(la.diff(s.t), s.lat_dot).subs(la, s.lat)
    return sp.factor(sp.simplify(chi_dot))


def functions(names: Mapping[sp.Symbol, str]) -> list[GeneratedFunction]:
    """The generated functions of these equations (for derivations/platform_drift/generate.py);
    ``names`` maps the paper's symbols to argument names."""
    vel = velocity_rates_n()
    return [
        GeneratedFunction(
            "strapdown_velocity_rates",
            (f_n, f_e, v_n, v_e, s.lat, rho, s.omega_e),
            (vel["v_N_dot"], vel["v_E_dot"]),
            "NED velocity equation of the strapdown comparator on the sphere of radius rho (eq. 10\n"
            "    with t = Earth, s = NED; known altitude, v_D = 0): f + g - (2 omega_ie + omega_en)\n"
            "    x v - omega_ie x (omega_ie x r), north and east rows. f_N, f_E: specific force in\n"
            "    NED. Returns (v_N_dot, v_E_dot).",
            {**names, f_n: "f_n", f_e: "f_e", v_n: "v_n", v_e: "v_e"},
        ),
        GeneratedFunction(
            "course_rate",
            (dlat, dlon, s.lat, s.lat_dot),
            course_rate(),
            "Rate of the course chi = atan2(dlon cos(lat), dlat) of a path whose latitude and\n"
            "    longitude change by dlat, dlon along one progress variable, at latitude rate\n"
            "    lat_dot: -dlat dlon sin(lat) lat_dot / (dlat^2 + dlon^2 cos^2(lat)).",
            names,
        ),
        GeneratedFunction(
            "velocity_at_rest",
            (s.omega_e, s.lat, s.R),
            tuple(kin.velocity_at_rest_mN()),
            "Inertial velocity of a vehicle at rest in m_N (north, west, up): omega_ie x\n"
            "    [0, 0, R] = [0, -omega_e R cos(lat), 0]. Returns (..., 3).",
            names,
            shape=(3,),
        ),
        GeneratedFunction(
            "ground_velocity",
            (*v_vec, *r_vec, *w_vec),
            tuple(ground_velocity()),
            "Earth-relative velocity (eq. 8 for the Earth-fixed frame): v_i - omega_ie x r, with\n"
            "    v_i, r and the Earth rate w = omega_ie in one set of axes. Returns (..., 3).",
            names,
            shape=(3,),
        ),
    ]
