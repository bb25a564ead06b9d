"""Specific force on the tilted platform (eqs. 17-18) and the Schuler-like constant (eq. 28).

The vehicle moves on a sphere of radius R (constant) at mass latitude phi_i(t) and
longitude lambda(t); the Earth turns at omega_e, so the inertial longitude is
``Lambda = lambda + omega_e t``. Its inertial position is
``r_i = R [cos phi cos Lambda, cos phi sin Lambda, sin phi]``; the specific force is
``f = r_i'' - G`` with the spherical mass attraction ``G = -g_i up``. In m_N (NWU at the
instant, :func:`kinematics.mat_nwu_e` with Lambda as the longitude) and then in s
(``^s_{mN}C``), to first order in the tilts, this is eq. 17; at rest, eq. 18.

The vertical component of f divided by R is the Schuler-like constant k_sh of eq. 28.
"""

from __future__ import annotations

import sympy as sp

from derivations.memo import derivation
from derivations.platform_drift import kinematics as kin
from derivations.platform_drift import symbols as s
from derivations.platform_drift.approx import derivative_symbols, taylor
from derivations.trig import pythagorean_reduce

__all__ = [
    "specific_force_mN",
    "specific_force_s_exact",
    "specific_force_s",
    "specific_force_stationary",
    "k_sh_from_specific_force",
    "deflection_first_order",
]

STATIONARY = {s.lat_dot: 0, s.lat_ddot: 0, s.lon_dot: 0, s.lon_ddot: 0}


@derivation
def specific_force_mN() -> sp.Matrix:
    """``^{mN} f`` of a vehicle on the sphere (N, W, U components)."""
    la, lo = sp.Function("phi_i")(s.t), sp.Function("lambda")(s.t)
    Lam = lo + s.omega_e * s.t
    r_i = s.R * sp.Matrix([sp.cos(la) * sp.cos(Lam), sp.cos(la) * sp.sin(Lam), sp.sin(la)])
    a_mN = kin.mat_nwu_e(la, Lam) * r_i.diff(s.t, 2)
    f_mN = a_mN - sp.Matrix([0, 0, -s.g])
    f_mN = derivative_symbols(
        f_mN, {la: (s.lat, s.lat_dot, s.lat_ddot), lo: (s.lon, s.lon_dot, s.lon_ddot)}
    )
    # sin**2 = 1 - cos**2 on the expanded sines and cosines of lat, lon and omega_e t: exact,
    # and the inertial longitude drops out (f does not depend on it); simplify of the
    # unexpanded product gave the same form at 20 times the CPU time (immutable, as before)
    return sp.ImmutableMatrix(f_mN.applyfunc(lambda e: pythagorean_reduce(sp.expand_trig(e))))


def specific_force_s_exact() -> sp.Matrix:
    """``^s f = ^s_{mN}C ^{mN} f`` for finite tilts (no linearisation)."""
    return kin.mat_s_mN() * specific_force_mN()


@derivation
def specific_force_s() -> sp.Matrix:
    """Eq. 17: ``^s f`` to first order in the tilts (rows f1, f2, f3)."""
    return taylor(specific_force_s_exact(), [s.phi_x, s.phi_y], 1)


def specific_force_stationary() -> sp.Matrix:
    """Eq. 18: eq. 17 at rest (latitude and longitude constant)."""
    return specific_force_s().subs(STATIONARY)


def k_sh_from_specific_force() -> sp.Expr:
    """k_sh of eq. 28 as the vertical specific force of a level platform over R."""
    return sp.expand(specific_force_mN()[2] / s.R)


def deflection_first_order() -> sp.Expr:
    """alpha of eq. 21: the plumb deflection alpha_T (eq. 1) to first order in R omega_e^2 / g."""
    X = sp.Symbol("X", positive=True)  # stands for R omega_e^2
    exact = kin.plumb_deflection(R=X / s.omega_e**2)
    return taylor(exact, [X], 1).subs(X, s.R * s.omega_e**2)
