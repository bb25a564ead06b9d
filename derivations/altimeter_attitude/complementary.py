"""The PI complementary filter of Fig. 1 (eqs. 18-21).

The loop of Fig. 1 (its equations 16, 22, 23 are missing from the OCR) adds to the gyro
solution's rate a PI correction of the difference between the accelerometer attitude
c_a (eq. 17-b) and the filter output c_m:

    s c_m = s c_g + (k_p + k_i / s) (c_a - c_m)

Solving for c_m gives eq. 18; its static gain from c_a is 1 and from c_g is 0 (eq. 19);
matching the denominator with s^2 + 2 xi omega s + omega^2 gives the gains (eqs. 20-21).

>>> output_transfer()
(c_a*k_i + c_a*k_p*s + c_g*s**2)/(k_i + k_p*s + s**2)
"""

from __future__ import annotations

import math

import numpy as np
import sympy as sp

from derivations.altimeter_attitude import symbols as s

__all__ = [
    "c_g",
    "c_a",
    "c_m",
    "output_transfer",
    "steady_state",
    "gains",
    "gains_xi_0707",
    "step_overshoot",
]

c_g, c_a, c_m = sp.symbols("c_g c_a c_m")


def output_transfer() -> sp.Expr:
    """eq. 18: c_m from the loop equation of Fig. 1."""
    # s c_m = s c_g + (k_p + k_i/s)(c_a - c_m)
    loop = sp.Eq(s.s * c_m, s.s * c_g + (s.k_p + s.k_i / s.s) * (c_a - c_m))
    sol = sp.solve(loop, c_m)[0]
    num, den = sp.fraction(sp.together(sol))
    return sp.collect(sp.expand(num), s.s) / sp.collect(sp.expand(den), s.s)


def steady_state() -> sp.Expr:
    """eq. 19: the limit s -> 0 of eq. 18 for constant c_g, c_a (final-value theorem)."""
    return sp.limit(output_transfer(), s.s, 0)


def gains() -> sp.Matrix:
    """eq. 20: [k_i, k_p] from s^2 + k_p s + k_i = s^2 + 2 xi omega s + omega^2."""
    char = s.s**2 + s.k_p * s.s + s.k_i - (s.s**2 + 2 * s.xi * s.omega_c * s.s + s.omega_c**2)
    sol = sp.solve(sp.Poly(char, s.s).coeffs(), [s.k_p, s.k_i], dict=True)[0]
    return sp.Matrix([sol[s.k_i], sol[s.k_p]])


def gains_xi_0707() -> sp.Expr:
    """eq. 21: k_p at xi = 0.707, read as 1/sqrt(2) (the paper's value, rounded)."""
    return gains()[1].subs(s.xi, 1 / sp.sqrt(2))


def _unit_step(xi: float, t: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """Step response y of 1 / (s^2 + 2 xi s + 1) and its rate y' (the impulse response), in
    closed form from the poles p1, p2: y = 1 + (p2 e^{p1 t} - p1 e^{p2 t}) / (p1 - p2) (y(0) =
    y'(0) = 0), and y = 1 - (1 + t) e^{-t} for the double pole at xi = 1."""
    if xi == 1.0:
        return 1.0 - (1.0 + t) * np.exp(-t), t * np.exp(-t)
    root = np.sqrt(complex(xi**2 - 1.0))
    p1, p2 = -xi + root, -xi - root
    e1, e2 = np.exp(p1 * t), np.exp(p2 * t)
    y = 1.0 + (p2 * e1 - p1 * e2) / (p1 - p2)
    return y.real, (p1 * p2 * (e1 - e2) / (p1 - p2)).real


def step_overshoot(xi: float = 1 / math.sqrt(2)) -> dict[str, float]:
    """Peak overshoot (%) of c_m after a unit step of c_a (eq. 18, c_g fixed), and of the
    plain second-order system omega^2 / (s^2 + 2 xi omega s + omega^2), at omega = 1.

    The paper picks xi = 0.707 "so that the error has no overshoot"; the numerator
    k_p s + k_i of eq. 18 adds a zero, so the c_a -> c_m response overshoots even though the
    poles are well damped. Computed on a fine grid of the closed-form responses: with
    k_i = omega^2 = 1 and k_p = 2 xi, c_m's response is y + k_p y' (:func:`_unit_step`; this
    is SciPy's ``signal.step`` of both systems to 1e-12, without importing scipy.signal).
    """
    t = np.linspace(0.0, 30.0, 30001)
    kp, ki = 2 * xi, 1.0
    y_2, dy_2 = _unit_step(xi, t)
    y_pi = ki * y_2 + kp * dy_2
    return {
        "pi_loop_overshoot_pct": float(100 * (y_pi.max() - 1.0)),
        "second_order_overshoot_pct": float(100 * (y_2.max() - 1.0)),
    }
