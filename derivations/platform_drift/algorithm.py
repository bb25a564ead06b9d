"""The position-independent navigation algorithm (eqs. 12-16, 19).

Everything follows from the motion equations 9 and 11 (:mod:`kinematics`), the
definitions 13-14 and spherical mass gravity ``g = -GM r / |r|^3``:

* :func:`oscillation_equations` -- eq. 15 (the platform oscillation ODEs). With
  ``u = z omega_y``, ``v = -z omega_x``, ``x = -R_G phi_y``, ``y = R_G phi_x`` substituted
  exactly, ``omega_y = u/z`` is differentiated along eqs. 9 and 11, the vertical inertial
  velocity w is eliminated in favour of z_dot (eq. 9, row 3), and with the commands of
  eq. 12 the specific force is replaced by ``f1 = z q_dot``, ``f2 = -z p_dot``.
* :func:`level_commands` -- eq. 12 derived: the command rates that keep a level platform
  level (phi = phi_dot = 0 stays so) for a constant radius (z_dot = 0) and r = 0.
* :func:`position_equation` / :func:`position_rates` -- eq. 16 and its explicit form.
* :func:`tilt_kinematics_stationary` -- eq. 19, exact Euler kinematics of s relative to
  m_N for a vehicle at rest, then first order in the tilts.
"""

from __future__ import annotations

import sympy as sp

from derivations import frames
from derivations.memo import derivation
from derivations.platform_drift import kinematics as kin
from derivations.platform_drift import symbols as s
from derivations.platform_drift.approx import derivative_symbols, taylor
from derivations.trig import pythagorean_reduce

__all__ = [
    "gravity_s",
    "DEFINITIONS",
    "oscillation_equations",
    "level_commands",
    "position_equation",
    "position_rates",
    "tilt_kinematics_stationary",
]

# eqs. 13-14 solved for u, v, x, y (exact substitutions in the algorithm)
DEFINITIONS = {
    s.u: s.z * s.omega_y,
    s.v: -s.z * s.omega_x,
    s.x: -s.R_G * s.phi_y,
    s.y: s.R_G * s.phi_x,
}


def known_altitude(rho: sp.Expr = s.R_G) -> dict[str, sp.Expr]:
    """The vertical channel of the algorithm: the known radius |^s r_EB| = rho gives z (the
    positive root of x^2 + y^2 + z^2 = rho^2) and, at constant rho, z_dot from its time
    derivative, in x, y, z, x_dot, y_dot."""
    xf, yf, zf = (sp.Function(n)(s.t) for n in ("X", "Y", "Z"))
    constraint = xf**2 + yf**2 + zf**2 - rho**2
    z_dot = sp.solve(constraint.diff(s.t), zf.diff(s.t))[0]
    z_dot = z_dot.subs({xf.diff(s.t): s.x_dot, yf.diff(s.t): s.y_dot}).subs(
        {xf: s.x, yf: s.y, zf: s.z}
    )
    roots = sp.solve(constraint.subs({xf: s.x, yf: s.y, zf: s.z}), s.z)
    z = next(r for r in roots if r.subs({s.x: 0, s.y: 0}) == rho)
    return {"z": z, "z_dot": sp.simplify(z_dot)}


def gravity_s() -> sp.Matrix:
    """Spherical mass attraction ``-GM r / |r|^3`` in s (the assumption of eq. 15)."""
    r_vec = sp.Matrix([s.x, s.y, s.z])
    return -s.GM * r_vec / (s.x**2 + s.y**2 + s.z**2) ** sp.Rational(3, 2)


@derivation
def oscillation_equations(commands: bool = True) -> dict[str, sp.Expr]:
    """Eq. 15: rates of omega_y, omega_x, phi_y, phi_x.

    Returns expressions in omega_x, omega_y, phi_x, phi_y, p, q, r, z, z_dot, R_G, GM and
    (``commands=True``) p_dot, q_dot, or (``commands=False``) the specific force f1, f2.
    """
    U, V, X, Y, Z = (sp.Function(n)(s.t) for n in ("U", "V", "X", "Y", "Z"))
    fun = {U: s.u, V: s.v, X: s.x, Y: s.y, Z: s.z}
    rdot = kin.position_rates_s()  # eq. 9
    vdot = kin.velocity_rates_s()  # eq. 11
    # quotient rule on the definitions (eqs. 13-14), then the motion equations
    raw = {
        "omega_y_dot": (U / Z).diff(s.t),
        "omega_x_dot": (-V / Z).diff(s.t),
        "phi_y_dot": (-X / s.R_G).diff(s.t),
        "phi_x_dot": (Y / s.R_G).diff(s.t),
    }
    rates = {
        U.diff(s.t): vdot[0],
        V.diff(s.t): vdot[1],
        X.diff(s.t): rdot[0],
        Y.diff(s.t): rdot[1],
        Z.diff(s.t): s.z_dot,
    }
    grav = gravity_s()
    w_of_zdot = sp.solve(rdot[2] - s.z_dot, s.w)[0]  # eq. 9 row 3: w = z_dot - q x + p y
    reps = {s.g1: grav[0], s.g2: grav[1], s.g3: grav[2], s.w: w_of_zdot}
    if commands:
        # eq. 12 solved for the specific force
        reps.update({s.f1: s.z * s.q_dot, s.f2: -s.z * s.p_dot})
    out = {}
    for key, expr in raw.items():
        e = expr.xreplace(rates).xreplace(fun)
        e = e.xreplace(reps).xreplace(reps)
        out[key] = e.xreplace(DEFINITIONS)
    return out


@derivation
def level_commands() -> dict[str, sp.Expr]:
    """Eq. 12 derived: p_dot, q_dot that keep a level platform level.

    phi_x_dot = r phi_y - (z/R_G)(omega_x - p) (eq. 15 before the commands) is
    differentiated; at the level state (phi = 0, omega_x = p, omega_y = q, i.e.
    phi_dot = 0) with z_dot = 0 and r = 0 (the third gyro is not torqued, eq. 25 / r_m = 0)
    phi_x_ddot = 0 requires p_dot = omega_x_dot there; likewise for q.
    """
    pre = oscillation_equations(commands=False)
    fns = {n: sp.Function(n)(s.t) for n in ("phx", "phy", "wx", "wy", "P", "Q", "Rr", "Zf")}
    to_fun = {
        s.phi_x: fns["phx"],
        s.phi_y: fns["phy"],
        s.omega_x: fns["wx"],
        s.omega_y: fns["wy"],
        s.p: fns["P"],
        s.q: fns["Q"],
        s.r: fns["Rr"],
        s.z: fns["Zf"],
    }
    level = {s.phi_x: 0, s.phi_y: 0, s.omega_x: s.p, s.omega_y: s.q, s.z_dot: 0, s.r: 0}
    out = {}
    for rate_key, cmd in (("phi_x_dot", s.p_dot), ("phi_y_dot", s.q_dot)):
        first = pre[rate_key].xreplace(to_fun)
        second = first.diff(s.t)
        back = {v: k for k, v in to_fun.items()}
        reps = {
            fns["wx"].diff(s.t): pre["omega_x_dot"].xreplace(to_fun),
            fns["wy"].diff(s.t): pre["omega_y_dot"].xreplace(to_fun),
            fns["phx"].diff(s.t): pre["phi_x_dot"].xreplace(to_fun),
            fns["phy"].diff(s.t): pre["phi_y_dot"].xreplace(to_fun),
            fns["P"].diff(s.t): s.p_dot,
            fns["Q"].diff(s.t): s.q_dot,
            fns["Rr"].diff(s.t): 0,
            fns["Zf"].diff(s.t): s.z_dot,
        }
        second = second.xreplace(reps).xreplace(back).xreplace(level)
        out[str(cmd)] = sp.solve(sp.simplify(second), cmd)[0]
    return out


def position_equation() -> tuple[sp.Matrix, sp.Matrix]:
    """Eq. 16: ``^{mN} omega_emN = C3(psi)(-^{mi} omega_ie + [p_m, q_m, r_m]) - [0, 0, psi_dot]``.

    omega_{e mN} = omega_{e i} + omega_{i mi} + omega_{mi mN}; in m_N coordinates the m_i
    vectors are turned by ``^{mN}_{mi} C = C3(psi)``; ``^{mi} omega_ie = C3(psi)^T ^{mN} omega_ie``
    and omega_{mN mi} = [0, 0, psi_dot] are those of eq. 4. Returns (lhs, rhs) with lhs the
    transport rate of eq. 4.
    """
    w_ie_mi = kin.C3(s.psi).T * kin.earth_rate_mN()
    rhs = kin.C3(s.psi) * (-w_ie_mi + sp.Matrix([s.p_m, s.q_m, s.r_m])) - kin.azimuth_rate_mi()
    return kin.transport_rate_mN(), sp.expand(rhs)


@derivation
def position_rates() -> dict[str, sp.Expr]:
    """Explicit form of eq. 16: lon_dot, lat_dot, psi_dot (singular at the poles)."""
    lhs, rhs = position_equation()
    sol = sp.solve(list(lhs - rhs), [s.lon_dot, s.lat_dot, s.psi_dot], dict=True)[0]
    return {str(k): sp.simplify(v) for k, v in sol.items()}


@derivation
def tilt_kinematics_exact_stationary() -> dict[str, sp.Expr]:
    """Exact rates of phi_x, phi_y, psi of the platform s for a vehicle at rest (behind eq. 19).

    omega_{mN s} = omega_{i s} - omega_{i mN}: in s, [p, q, r] - ^s_{mN}C ^{mN} omega_ie (the
    transport rate is zero at rest); omega_{mN s} from Poisson's equation on
    ^s_{mN}C(psi(t), phi_y(t), phi_x(t)). It is linear in the angle rates, which are solved for.
    """
    ps, py, px = (sp.Function(n)(s.t) for n in ("psi", "phy", "phx"))
    mat = kin.mat_s_mN(ps, py, px)
    w_mN_s = frames.angular_velocity_from_dcm(mat, s.t, simplify=False)
    mapping = {ps: (s.psi, s.psi_dot), py: (s.phi_y, s.phi_y_dot), px: (s.phi_x, s.phi_x_dot)}
    w_mN_s = sp.expand(derivative_symbols(w_mN_s, mapping))
    unknowns = [s.phi_x_dot, s.phi_y_dot, s.psi_dot]
    # the Jacobian's elements reduced by sin**2 = 1 - cos**2 (exact; trigsimp gave the same
    # elements at 50 times the CPU time)
    M = w_mN_s.jacobian(unknowns).applyfunc(pythagorean_reduce)
    w_rhs = sp.Matrix([s.p, s.q, s.r]) - kin.mat_s_mN() * kin.earth_rate_mN()
    sol = M.LUsolve(w_rhs)
    return {str(k): sol[i] for i, k in enumerate(unknowns)}


@derivation
def tilt_kinematics_stationary() -> dict[str, sp.Expr]:
    """Eq. 19: the exact stationary kinematics to first order in the tilts."""
    ex = tilt_kinematics_exact_stationary()
    return {k: taylor(v, [s.phi_x, s.phi_y], 1) for k, v in ex.items()}


def stationary_radius_rates(lat: sp.Expr = s.lat, psi: sp.Expr = s.psi) -> dict[str, sp.Expr]:
    """omega_x, omega_y (eq. 13) of a vehicle at rest on a level platform (used in eqs. 23, 35).

    Inertial velocity at rest: ^{mN} v = omega_ie x [0, 0, R]; in s (level, azimuth psi):
    [u, v] = first two rows of ^s_{mN}C ^{mN} v, z = R; omega_y = u/z, omega_x = -v/z.
    """
    v_mN = kin.velocity_at_rest_mN(s.omega_e, lat, s.R)
    v_s = kin.mat_s_mN(psi, 0, 0) * v_mN
    return {"omega_x": sp.simplify(-v_s[1] / s.R), "omega_y": sp.simplify(v_s[0] / s.R)}
