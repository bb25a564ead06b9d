"""Levelling (roll and pitch) from one accelerometer on the table: methods 1-5 (eqs. 19-34).

Each function derives the method's formula from the sensor model of
:mod:`derivations.north_finding.sensors` by writing the model at the method's
table positions, forming the paper's combination of readings, and solving for
the unknown. Nothing here is copied from the paper; the audit compares.

>>> import sympy as sp

>>> from derivations.north_finding.symbols import ax_0, ax_180, g
>>> method1()["sin_theta"]
(ax_0 - ax_180)/(2*g)
"""

from __future__ import annotations

import sympy as sp

from derivations.memo import derivation
from derivations.north_finding import sensors
from derivations.north_finding.symbols import (
    S,
    ax_0,
    ax_90,
    ax_180,
    ax_270,
    ay_0,
    ay_90,
    ay_180,
    ay_270,
    az,
    b,
    c_theta_s_phi,
    g,
    phi,
    s_theta,
    sf,
    tau,
    theta,
)
from derivations.north_finding.symbols import (
    a1 as A1,
)
from derivations.north_finding.symbols import (
    a2 as A2,
)
from derivations.north_finding.symbols import (
    a3 as A3,
)

__all__ = [
    "ideal_accel",
    "real_accel",
    "solve_linear",
    "design_row",
    "method1",
    "method2",
    "method3",
    "method4",
    "method5",
]

DEG = sp.pi / 180
IDEAL = {S: 1, b: 0, **{ma: 0 for row in sensors.MISALIGNMENT.values() for ma in row.values()}}


@derivation
def real_accel(axis: str, tau_: sp.Expr = tau, still: bool = True) -> sp.Expr:
    """Real accelerometer on ``axis`` at table angle ``tau_`` (eq. 18 row), noise-free."""
    f_b = sensors.specific_force_b(tau_)
    if still:
        f_b = sensors.still_table(f_b)
    return sensors.real_reading(f_b, axis)


@derivation
def ideal_accel(axis: str, tau_: sp.Expr = tau, still: bool = True) -> sp.Expr:
    """Ideal accelerometer (S = 1, b = 0, no misalignment) on ``axis`` (eqs. 17, 23, 24)."""
    return sp.expand(real_accel(axis, tau_, still).subs(IDEAL))


def solve_linear(equation: sp.Expr, unknown: sp.Expr) -> sp.Expr:
    """Solve ``equation == 0`` for ``unknown`` (a symbol or a sub-expression such as sin(theta)).

    Raises ValueError if the equation is not linear in the unknown.
    """
    dummy = sp.Dummy("u")
    eq = sp.expand(equation).subs(unknown, dummy)
    if eq.has(*unknown.free_symbols) and not unknown.is_Symbol:
        eq = sp.expand(sp.expand_trig(eq)).subs(unknown, dummy)
    poly = sp.Poly(eq, dummy)
    if poly.degree() != 1:
        raise ValueError(f"equation is not linear in {unknown}: degree {poly.degree()}")
    c1, c0 = poly.all_coeffs()
    return sp.simplify(-c0 / c1)


def design_row(reading: sp.Expr, unknowns: dict[sp.Expr, sp.Symbol]) -> list[sp.Expr]:
    """Coefficients of ``reading`` in the products listed in ``unknowns`` (LS design row).

    Checks that the reading is exactly the linear combination (no remainder).
    """
    expr = sp.expand(reading)
    row = [expr.coeff(product) for product in unknowns]
    rebuilt = sum(c * p for c, p in zip(row, unknowns, strict=True))
    if sp.simplify(expr - rebuilt) != 0:
        raise ValueError(f"reading {reading} is not linear in {list(unknowns)}")
    return [sp.simplify(c) for c in row]


@derivation
def method1() -> dict[str, sp.Expr]:
    """Method 1: x channel at tau = 0, 90, 180, 270 deg (eq. 19).

    sin(theta) from a(0) - a(180) = 2 g sin(theta); sin(phi) from a(270) - a(90).
    """
    model = {d: ideal_accel("x", d * DEG) for d in (0, 90, 180, 270)}
    # eq. 19: a(0) - a(180) = model difference, solved for sin(theta)
    sin_theta = solve_linear(ax_0 - ax_180 - (model[0] - model[180]), sp.sin(theta))
    # eq. 19 (second line): a(270) - a(90), solved for sin(phi)
    sin_phi = solve_linear(ax_270 - ax_90 - (model[270] - model[90]), sp.sin(phi))
    return {"sin_theta": sin_theta, "sin_phi": sin_phi}


@derivation
def method2() -> dict[str, sp.Expr]:
    """Method 2: x channel at n arbitrary tau, least squares (eqs. 20-21).

    Row of H in H X = Y with X = [sin(theta), cos(theta) sin(phi)] and Y = a_x / g.
    """
    products = {sp.sin(theta): s_theta, sp.cos(theta) * sp.sin(phi): c_theta_s_phi}
    row = design_row(ideal_accel("x") / g, products)
    # sin(phi) from the second unknown X2 = cos(theta) sin(phi) at the estimated theta
    sin_phi = solve_linear(c_theta_s_phi - sp.cos(theta) * sp.sin(phi), sp.sin(phi))
    return {"h_sin_theta": row[0], "h_cth_sphi": row[1], "sin_phi": sin_phi}


@derivation
def method3() -> dict[str, sp.Expr]:
    """Method 3: y channel at tau = 0, 90, 180, 270 deg on the turning table (eq. 24).

    The l*omega_dot term of the y channel (eq. 24) is common to all positions and
    cancels in the differences, so the still-table and turning-table answers agree.
    """
    model = {d: ideal_accel("y", d * DEG, still=False) for d in (0, 90, 180, 270)}
    sin_theta = solve_linear(ay_270 - ay_90 - (model[270] - model[90]), sp.sin(theta))
    sin_phi = solve_linear(ay_180 - ay_0 - (model[180] - model[0]), sp.sin(phi))
    return {"sin_theta": sin_theta, "sin_phi": sin_phi}


@derivation
def method4() -> dict[str, sp.Expr]:
    """Method 4: y channel at n arbitrary tau, least squares (eqs. 25-26, omega_dot ~ 0).

    Row of H in H X = Y with X = [cos(theta) sin(phi), sin(theta)] and Y = -a_y / g.
    """
    products = {sp.cos(theta) * sp.sin(phi): c_theta_s_phi, sp.sin(theta): s_theta}
    row = design_row(-ideal_accel("y") / g, products)
    return {"h_cth_sphi": row[0], "h_sin_theta": row[1]}


@derivation
def method5() -> dict[str, sp.Expr]:
    """Method 5: accelerometer bias and scale factor (eqs. 27-34).

    Readings at tau = 0, 90, 180 deg on x, and the sensor turned by -pi/2 about y
    so that it reads along z (eq. 30). Scale factor S and bias b, no misalignment.
    """
    sb = {S: S, b: b}
    model = {d: real_accel("x", d * DEG).subs({**IDEAL, **sb}) for d in (0, 90, 180)}
    model_z = real_accel("z").subs({**IDEAL, **sb})
    # eq. 28: a(0) + a(180) = 2 b
    bias = solve_linear(ax_0 + ax_180 - (model[0] + model[180]), b)
    # eqs. 29, 31: bias-free components
    a1, a2, a3 = ax_0 - bias, ax_90 - bias, az - bias
    comps = (model[0] - b, model[90] - b, model_z - b)
    # eq. 32: the sum of squares of the three components is S^2 g^2
    norm2 = sp.simplify(sum(c**2 for c in comps))
    if sp.simplify(norm2 - S**2 * g**2) != 0:
        raise AssertionError("eq. 32: components do not span the gravity vector")
    alpha = (A1**2 + A2**2 + A3**2) / g**2  # eq. 34, in the components a1, a2, a3
    # eq. 33: S^2 = alpha; the sign of S is fixed by calibration (S > 0)
    scale = [r for r in sp.solve(sp.Eq(S**2, alpha), S) if r.could_extract_minus_sign() is False]
    # eq. 34: (1 + sf)^2 = alpha, linearised by dropping sf^2
    sf_approx = sp.solve(sp.expand((1 + sf) ** 2 - alpha).subs(sf**2, 0), sf)[0]
    return {
        "bias": bias,
        "a1": a1,
        "a2": a2,
        "a3": a3,
        "alpha": alpha,
        "scale": scale[0],
        "scale_approx": 1 + sf_approx,
    }
