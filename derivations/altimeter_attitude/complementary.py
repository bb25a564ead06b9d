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


def step_overshoot(xi: float = 1 / math.sqrt(2)) -> dict[str, float]:
    """Peak overshoot (%) of c_m after a unit step of c_a (eq. 18, c_g fixed), and of the
    plain second-order system omega^2 / (s^2 + 2 xi omega s + omega^2), at omega = 1.

    The paper picks xi = 0.707 "so that the error has no overshoot"; the numerator
    k_p s + k_i of eq. 18 adds a zero, so the c_a -> c_m response overshoots even though the
    poles are well damped. Computed on a fine grid of the closed-form responses.
    """
    from scipy import signal

    t = np.linspace(0.0, 30.0, 30001)
    kp, ki = 2 * xi, 1.0
    _, y_pi = signal.step(signal.lti([kp, ki], [1.0, kp, ki]), T=t)
    _, y_2 = signal.step(signal.lti([ki], [1.0, kp, ki]), T=t)
    return {
        "pi_loop_overshoot_pct": float(100 * (y_pi.max() - 1.0)),
        "second_order_overshoot_pct": float(100 * (y_2.max() - 1.0)),
    }
