"""End of alignment (0-) and start of navigation (0+): eqs. 20-27.

* eq. 20: at the end of alignment the loops of Figs. 3-4 hold the platform still
  (phi_dot = 0) and the accelerometers read their biases, f = b_a; eq. 18 solved for the
  tilts;
* eq. 21: the same to first order in R omega_e^2 / g_i and b_a / g_i, written with
  alpha = R omega_e^2 sin cos / g_i and theta_F = b_a / g_i (the definitions of eq. 21);
* eqs. 23-24: the third channel at 0-: psi_dot = 0 in eq. 19 gives r(0-) = omega_e sin(phi)
  - d_r with the disturbance d_r = phi_x q - omega_e cos cos(psi) phi_y, and q(0-) from
  phi_y_dot = 0;
* :func:`rates_0m_exact`: the exact p(0-), q(0-), r(0-) that hold a platform with tilts
  phi_x, phi_y and azimuth psi at rest (the exact kinematics behind eq. 19 with
  phi_dot = psi_dot = 0, eq. 22); eq. 24 and q(0-) are their first-order forms (the tests
  prove it symbolically); ``platform.initial_state`` calls the generated exact form;
* eq. 27: the jumps at 0+: eq. 19 with r -> r(0+) = b_g3 (third gyro commanded zero, eq. 25)
  and the uncompensated drifts b_g1, b_g2 added to p, q (the paper's assumption that drift
  compensation is lost at 0+); phi, psi, p, q do not jump (Table 1).
"""

from __future__ import annotations

import sympy as sp

from derivations.memo import derivation
from derivations.platform_drift import algorithm as alg
from derivations.platform_drift import specific_force as sf
from derivations.platform_drift import symbols as s
from derivations.platform_drift.approx import taylor

__all__ = [
    "tilts_0m_exact",
    "tilts_0m",
    "TO_ALPHA",
    "disturbance_dr",
    "q_0m",
    "r_0m",
    "rates_0m_exact",
    "tilt_rates_0p",
]

# change of variables of eq. 21 (R, b_a1, b_a2 -> alpha, theta_F1, theta_F2)
TO_ALPHA = {
    s.R: s.alpha * s.g / (s.omega_e**2 * sp.sin(s.lat) * sp.cos(s.lat)),
    s.b_a1: s.theta_F1 * s.g,
    s.b_a2: s.theta_F2 * s.g,
}


@derivation
def tilts_0m_exact() -> dict[str, sp.Expr]:
    """Eq. 20: phi_y(0-), phi_x(0-) from eq. 18 with f1 = b_a1, f2 = b_a2."""
    f = sf.specific_force_stationary()
    sol = sp.solve([f[0] - s.b_a1, f[1] - s.b_a2], [s.phi_y, s.phi_x], dict=True)[0]
    return {
        k: sp.factor(sp.expand_trig(sol[v])) for k, v in (("phi_y", s.phi_y), ("phi_x", s.phi_x))
    }


@derivation
def tilts_0m() -> dict[str, sp.Expr]:
    """Eq. 21: eq. 20 to first order in R omega_e^2 and the biases, in alpha and theta_F."""
    X = sp.Symbol("X", positive=True)  # R omega_e^2
    out = {}
    for k, e in tilts_0m_exact().items():
        e1 = taylor(e.subs(s.R, X / s.omega_e**2), [X, s.b_a1, s.b_a2], 1)
        out[k] = sp.expand(e1.subs(X, s.R * s.omega_e**2).subs(TO_ALPHA))
    return out


def disturbance_dr() -> sp.Expr:
    """d_r of eq. 19/23: psi_dot - r + omega_e sin(phi_i) = phi_x q - omega_e cos cos(psi) phi_y."""
    k19 = alg.tilt_kinematics_stationary()
    return sp.expand(k19["psi_dot"] - s.r + s.omega_e * sp.sin(s.lat))


def q_0m() -> sp.Expr:
    """q(0-) from phi_y_dot = 0 in eq. 19: r phi_x + omega_y0 (omega_y0 of a vehicle at rest)."""
    k19 = alg.tilt_kinematics_stationary()
    return sp.solve(k19["phi_y_dot"], s.q)[0]


def disturbance_dr_0m(first_order: bool = True) -> sp.Expr:
    """Eq. 23: d_r at 0- with q(0-) and the tilts of eq. 21 (first order drops r phi_x^2)."""
    e = disturbance_dr().subs(s.q, q_0m())
    e = e.subs({s.phi_x: tilts_0m()["phi_x"], s.phi_y: tilts_0m()["phi_y"]})
    e = sp.expand(e)
    if first_order:
        e = taylor(e, [s.alpha, s.theta_F1, s.theta_F2], 1)
    return e


def r_0m() -> sp.Expr:
    """Eq. 24: r(0-) = omega_e sin(phi_i) - d_r from psi_dot(0-) = 0 (eq. 22) in eq. 19."""
    return sp.expand(s.omega_e * sp.sin(s.lat) - disturbance_dr_0m(first_order=True))


@derivation
def rates_0m_exact() -> dict[str, sp.Expr]:
    """p(0-), q(0-), r(0-) exactly: the exact stationary kinematics (behind eq. 19) with
    phi_x_dot = phi_y_dot = psi_dot = 0 (eqs. 20, 22: alignment holds the platform still),
    solved for the platform rates. Exact in the tilts phi_x, phi_y and the azimuth psi."""
    ex = alg.tilt_kinematics_exact_stationary()
    eqs = [ex[k] for k in ("phi_x_dot", "phi_y_dot", "psi_dot")]
    sol = sp.solve(eqs, [s.p, s.q, s.r], dict=True)
    assert len(sol) == 1
    # the solutions are sums of products already (the reduced Jacobian of the kinematics):
    # factor_terms pulls out the common omega_e, the form simplify gave at 100 times the time
    return {str(k): sp.factor_terms(sp.expand_trig(sol[0][k])) for k in (s.p, s.q, s.r)}


def tilt_rates_0p() -> dict[str, sp.Expr]:
    """Eq. 27: phi_x_dot(0+), phi_y_dot(0+) from the jumps of eq. 19 (phi_dot(0-) = 0).

    Before: (p, q, r(0-)); after: (p + b_g1, q + b_g2, r(0+)), with phi, psi continuous.
    Returned with r(0+) = b_g3 (eq. 25) and r(0-) kept as the symbol r_0m.
    """
    k19 = alg.tilt_kinematics_stationary()
    out = {}
    for key in ("phi_x_dot", "phi_y_dot"):
        before = k19[key].subs(s.r, s.r0m)
        after = k19[key].subs({s.p: s.p + s.b_g1, s.q: s.q + s.b_g2, s.r: s.r0p}, simultaneous=True)
        out[key] = sp.expand((after - before).subs(s.r0p, s.b_g3))
    return out


def tilt_rates_0p_full() -> dict[str, sp.Expr]:
    """Eq. 31 before reduction: eq. 27 with r(0-) of eq. 24 and the tilts of eq. 21."""
    tilts = tilts_0m()
    reps = {s.r0m: r_0m(), s.phi_x: tilts["phi_x"], s.phi_y: tilts["phi_y"]}
    return {k: sp.expand(v.subs(reps)) for k, v in tilt_rates_0p().items()}
