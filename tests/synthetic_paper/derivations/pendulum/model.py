"""The synthetic pendulum paper, derived from first principles (Lagrange).

A point mass ``m`` on a massless rod of length ``l`` swings at angle ``theta`` from the
vertical under gravity ``g``.

>>> sp.simplify(theta_ddot() + g / l * sp.sin(theta))
0
>>> sp.simplify(period_first_order() / period_small_angle() - (1 + theta0**2 / 16))
0
"""

from __future__ import annotations

import sympy as sp
from sympy.calculus.euler import euler_equations

__all__ = ["t", "l", "g", "m", "theta", "theta0", "theta_ddot", "period_small_angle"]

t = sp.Symbol("t", real=True)
l, g, m = sp.symbols("l g m", positive=True)
theta, theta0 = sp.symbols("theta theta_0", real=True)
_theta_t = sp.Function("theta")(t)


def theta_ddot() -> sp.Expr:
    """eq. 1: the equation of motion, from L = T - V with T = m l^2 theta'^2 / 2 and
    V = -m g l cos(theta), solved for theta''."""
    lagrangian = m * l**2 * _theta_t.diff(t) ** 2 / 2 + m * g * l * sp.cos(_theta_t)
    (eom,) = euler_equations(lagrangian, _theta_t, t)
    accel = sp.solve(eom.lhs, _theta_t.diff(t, 2))[0]
    return accel.subs(_theta_t, theta)


def period_small_angle() -> sp.Expr:
    """eq. 3: the period of the linearised motion (sin theta ~ theta), 2 pi / omega_0 with
    omega_0^2 = -d(theta'')/d(theta) at theta = 0 (eq. 2)."""
    omega0_sq = -sp.diff(theta_ddot(), theta).subs(theta, 0)
    return 2 * sp.pi / sp.sqrt(omega0_sq)


def period_first_order() -> sp.Expr:
    """eq. 4: the period to second order in the amplitude, from the exact period
    4 sqrt(l/g) K(sin^2(theta_0/2)) (K the complete elliptic integral, parameter m)."""
    exact = 4 * sp.sqrt(l / g) * sp.elliptic_k(sp.sin(theta0 / 2) ** 2)
    return sp.series(exact, theta0, 0, 3).removeO()
