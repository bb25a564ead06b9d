"""Azimuth (north finding) from one rate gyro on the table: methods 1-6 (eqs. 40-71).

Roll, pitch and latitude are known. The ideal x-gyro reads (eq. 38)

    w_x(tau) = Omega (cos(tau) X + sin(tau) Y),
    X = cos(psi) cos(theta) cos(lambda) + sin(theta) sin(lambda),
    Y = (cos(psi) sin(theta) sin(phi) - sin(psi) cos(phi)) cos(lambda)
        - cos(theta) sin(phi) sin(lambda),

which this module obtains from :func:`derivations.north_finding.sensors.angular_rate_b`
and never types in. Every formula below is derived from that model.

>>> from derivations.north_finding.symbols import wx_0, wx_180
>>> method1_case1()["cos_psi"]
(-2*Omega*sin(lambda)*sin(theta) + wx_0 - wx_180)/(2*Omega*cos(lambda)*cos(theta))
"""

from __future__ import annotations

import sympy as sp

from derivations.memo import derivation
from derivations.north_finding import sensors
from derivations.north_finding.leveling import IDEAL, solve_linear
from derivations.north_finding.symbols import (
    Omega,
    S,
    b,
    ca,
    cb,
    cc,
    lam,
    om1,
    om2,
    om3,
    phi,
    psi,
    sf,
    tau,
    w,
    w_tau,
    wx_0,
    wx_90,
    wx_180,
    wx_270,
    wx_max,
    wz,
)
from derivations.trig import pythagorean_reduce

__all__ = [
    "ideal_gyro",
    "real_gyro",
    "sinusoid_coeffs",
    "half_angle_roots",
    "phase_roots",
    "method1_case1",
    "method1_case2",
    "method2",
    "method3",
    "method4",
    "method5",
    "method6",
]

DEG = sp.pi / 180
SB = {S: S, b: b}


@derivation
def real_gyro(axis: str, tau_: sp.Expr = tau, still: bool = True) -> sp.Expr:
    """Real gyro on ``axis`` at table angle ``tau_`` (eq. 39 row), noise-free."""
    w_b = sensors.angular_rate_b(tau_)
    if still:
        w_b = sensors.still_table(w_b)
    return sensors.real_reading(w_b, axis)


@derivation
def ideal_gyro(axis: str, tau_: sp.Expr = tau, still: bool = True) -> sp.Expr:
    """Ideal gyro (S = 1, b = 0, no misalignment) on ``axis`` (eqs. 37-38)."""
    return sp.expand(real_gyro(axis, tau_, still).subs(IDEAL))


@derivation
def sinusoid_coeffs(equation: sp.Expr, x: sp.Symbol) -> tuple[sp.Expr, sp.Expr, sp.Expr]:
    """Write ``equation == 0`` as ``a sin(x) + b cos(x) = c`` and return (a, b, c)."""
    expr = sp.expand(equation)
    a = expr.coeff(sp.sin(x))
    bb = expr.coeff(sp.cos(x))
    c = -sp.expand(expr - a * sp.sin(x) - bb * sp.cos(x))
    if c.has(x) or a.has(x) or bb.has(x):
        raise ValueError(f"equation is not of the form a sin({x}) + b cos({x}) = c")
    return sp.simplify(a), sp.simplify(bb), sp.simplify(c)


@derivation
def half_angle_roots() -> tuple[sp.Expr, sp.Expr]:
    """Both roots of ``a sin(psi) + b cos(psi) = c`` by the tangent half-angle (eqs. 41, 43).

    With t = tan(psi/2): (b + c) t^2 - 2 a t + (c - b) = 0.
    """
    t = sp.Symbol("t", real=True)
    quad = sp.expand(
        (ca * 2 * t + cb * (1 - t**2) - cc * (1 + t**2)) * -1
    )  # a sin + b cos - c, times (1 + t^2), sign chosen so the t^2 coefficient is b + c
    roots = sp.solve(quad, t)
    roots = sorted(roots, key=lambda r: sp.default_sort_key(r))
    return tuple(2 * sp.atan(r) for r in roots)


def phase_roots() -> tuple[sp.Expr, sp.Expr]:
    """Both roots of ``a sin(psi) + b cos(psi) = c`` in phase form, used for the numerics.

    a sin(psi) + b cos(psi) = R cos(psi - delta), R = sqrt(a^2 + b^2), delta = atan2(a, b),
    so psi = delta -/+ acos(c / R). Unlike the half-angle form it has no pole at b + c = 0.

    The ratio c / R is clipped to [-1, 1] (Max/Min: the identity wherever the roots exist).
    The estimators count |c| > R as ``unreachable_root`` and take the double root there; without
    the clip, c set to exactly R still gave NaN in 8 % of cases, because ``np.hypot(a, b)`` and
    ``sqrt(a**2 + b**2)`` differ in the last bit (high_latitude's a2_scan: 1 of its 8 clipped
    table angles came out NaN).
    """
    r = sp.sqrt(ca**2 + cb**2)
    delta = sp.atan2(ca, cb)
    ratio = sp.Max(-1, sp.Min(1, cc / r))
    return delta - sp.acos(ratio), delta + sp.acos(ratio)


@derivation
def method1_case1() -> dict[str, sp.Expr]:
    """Method 1, case 1: tau = 0, 180 deg; cos(psi) from the difference (eq. 40)."""
    m0, m180 = ideal_gyro("x", 0), ideal_gyro("x", sp.pi)
    cos_psi = solve_linear(wx_0 - wx_180 - (m0 - m180), sp.cos(psi))
    return {"cos_psi": cos_psi}


@derivation
def method1_case2() -> dict[str, sp.Expr]:
    """Method 1, case 2: tau = 90, 270 deg; a sin(psi) + b cos(psi) = c (eqs. 40-41).

    Normalised, like the paper, so that a = -cos(phi).
    """
    m90, m270 = ideal_gyro("x", 90 * DEG), ideal_gyro("x", 270 * DEG)
    a, bb, c = sinusoid_coeffs(m90 - m270 - (wx_90 - wx_270), psi)
    k = sp.simplify(-a / sp.cos(phi))
    return {"a": sp.simplify(a / k), "b": sp.simplify(bb / k), "c": sp.simplify(c / k)}


@derivation
def method2() -> dict[str, sp.Expr]:
    """Method 2: one arbitrary tau; A sin(psi) + B cos(psi) = C (eqs. 42-43)."""
    a, bb, c = sinusoid_coeffs(ideal_gyro("x") - w_tau, psi)
    return {"A": a, "B": bb, "C": c}


@derivation
def method3() -> dict[str, sp.Expr]:
    """Method 3: the largest gyro reading over tau; quartic in cos(psi) (eqs. 44-52).

    Returns the amplitudes A, B of eq. 44, the location tau* of the maximum
    (eqs. 51-52), the maximum (eq. 45), the five coefficients of eq. 47 and the
    five of the quartic of eq. 50.
    """
    reading = ideal_gyro("x")
    # eq. 44: w_x(tau) = A sin(tau) + B cos(tau)
    amp_a, amp_b, rest = sinusoid_coeffs(reading, tau)
    assert sp.simplify(rest) == 0
    # eqs. 51-52: d/dtau = 0 -> tan(tau*) = A / B; the maximum is at atan2(A, B)
    tau_star = sp.atan2(amp_a, amp_b)
    # eq. 45: value at the maximum
    w_peak = sp.sqrt(amp_a**2 + amp_b**2)
    # eq. 46: (wx_max / Omega)^2 = (A^2 + B^2) / Omega^2, sin^2(psi) -> 1 - cos^2(psi)
    c_, s_ = sp.symbols("c_psi s_psi", real=True)
    lhs = sp.expand((amp_a**2 + amp_b**2) / Omega**2 - (wx_max / Omega) ** 2)
    lhs = sp.expand(lhs.subs({sp.sin(psi): s_, sp.cos(psi): c_}).subs(s_**2, 1 - c_**2))
    poly = sp.Poly(lhs, c_, s_)
    # eq. 47: A cos^2 + B cos + C cos sin + D sin + E = 0
    coeff = {
        "A47": poly.coeff_monomial(c_**2),
        "B47": poly.coeff_monomial(c_),
        "C47": poly.coeff_monomial(c_ * s_),
        "D47": poly.coeff_monomial(s_),
        "E47": poly.coeff_monomial(1),
    }
    assert (
        sp.expand(sum(poly.coeff_monomial(m) * m for m in (c_**2, c_, c_ * s_, s_, 1)) - lhs) == 0
    )
    coeff = {k: sp.factor(sp.simplify(v)) for k, v in coeff.items()}
    # eqs. 48-50: square (A c^2 + B c + E) = -(C c + D) s with s^2 = 1 - c^2
    A_, B_, C_, D_, E_ = sp.symbols("A B C D E", real=True)
    quartic = sp.Poly(
        sp.expand((A_ * c_**2 + B_ * c_ + E_) ** 2 - (1 - c_**2) * (C_ * c_ + D_) ** 2), c_
    )
    quartic_coeffs = dict(zip(("F", "G", "H", "I", "J"), quartic.all_coeffs(), strict=True))
    # eq. 47 before squaring, in the coefficient symbols: the residual that rejects the roots
    # squaring (eq. 49) adds, and its derivative in psi for the Newton polish (c = cos psi,
    # s = sin psi, so dc/dpsi = -s, ds/dpsi = c)
    residual = A_ * c_**2 + B_ * c_ + C_ * c_ * s_ + D_ * s_ + E_
    on_circle = {c_: sp.cos(psi), s_: sp.sin(psi)}
    back = {sp.cos(psi): c_, sp.sin(psi): s_}
    d_residual = sp.collect(sp.expand(residual.subs(on_circle).diff(psi).subs(back)), C_)
    return {
        "amp_A": amp_a,
        "amp_B": amp_b,
        "tau_star": tau_star,
        "w_peak": w_peak,
        **coeff,
        **quartic_coeffs,
        "residual47": residual,
        "residual47_dpsi": d_residual,
        "_quartic_symbols": (A_, B_, C_, D_, E_),
        "_cs": (c_, s_),
    }


@derivation
def method4() -> dict[str, sp.Expr]:
    """Method 4: gyro bias, azimuth and scale factor from tau = 0, 90, 180 deg (eqs. 53-60)."""
    m = {d: real_gyro("x", d * DEG).subs({**IDEAL, **SB}) for d in (0, 90, 180)}
    # eq. 55: w(0) + w(180) = 2 b
    bias = solve_linear(wx_0 + wx_180 - (m[0] + m[180]), b)
    # eq. 56: omega_1 = (w(0) - b)/Omega = S X, omega_2 = (w(90) - b)/Omega = S Y
    omega1 = (wx_0 - bias) / Omega
    omega2 = (wx_90 - bias) / Omega
    model1 = sp.expand((m[0] - b) / Omega)
    model2 = sp.expand((m[90] - b) / Omega)
    # eq. 57: omega_1 / omega_2 = X / Y, so omega_1 Y - omega_2 X = 0 (S cancels)
    ratio_eq = sp.expand(om1 * model2 / S - om2 * model1 / S)
    a, bb, c = sinusoid_coeffs(ratio_eq, psi)
    # eq. 58: normalise like the paper (divide by omega_2 cos(lambda))
    k = om2 * sp.cos(lam)
    coeffs = {"A": sp.simplify(a / k), "B": sp.simplify(bb / k), "C": sp.simplify(c / k)}
    # eq. 60: S = omega_1 / X
    scale = solve_linear(om1 - model1, S)
    return {"bias": bias, "omega1": omega1, "omega2": omega2, **coeffs, "scale": scale}


@derivation
def method5() -> dict[str, sp.Expr]:
    """Method 5: eliminate psi with cos^2 + sin^2 = 1; quadratic in S (eqs. 61-67)."""
    m4 = method4()
    model1 = sp.expand((real_gyro("x", 0).subs({**IDEAL, **SB}) - b) / Omega)
    model2 = sp.expand((real_gyro("x", 90 * DEG).subs({**IDEAL, **SB}) - b) / Omega)
    # eqs. 61-62: solve omega_1 = S X, omega_2 = S Y for cos(psi), sin(psi)
    c_, s_ = sp.symbols("c_psi s_psi", real=True)
    sol = sp.solve(
        [
            sp.Eq(om1, model1.subs({sp.cos(psi): c_, sp.sin(psi): s_})),
            sp.Eq(om2, model2.subs({sp.cos(psi): c_, sp.sin(psi): s_})),
        ],
        [c_, s_],
        dict=True,
    )[0]
    # eq. 63: cos^2 + sin^2 = 1; with u = 1/(S cos(lambda)) it is a quadratic in u (expanded
    # as it is: its coefficients are simplified below, to the same forms as when the whole
    # sum was simplified first, which took twice the CPU time of the rest of this method)
    u = sp.Symbol("u", positive=True)
    unit = sp.expand((sol[c_] ** 2 + sol[s_] ** 2).subs(S, 1 / (u * sp.cos(lam))))
    poly = sp.Poly(unit, u)
    # eq. 64: A = B u^2 + C u  (A = 1 - constant term)
    B64 = poly.coeff_monomial(u**2)
    C64 = poly.coeff_monomial(u)
    A64 = 1 - poly.coeff_monomial(1)
    A_, B_, C_ = sp.symbols("A B C", real=True)
    # eq. 65: A cos^2(lambda) S^2 - C cos(lambda) S - B = 0
    quad65 = sp.expand(
        (B_ * u**2 + C_ * u - A_).subs(u, 1 / (S * sp.cos(lam))) * -(S**2) * sp.cos(lam) ** 2
    )
    roots = sp.solve(quad65, S)
    # eq. 66: S = 1 + sf with sf^2 dropped
    sf_approx = sp.solve(sp.expand(quad65.subs(S, 1 + sf)).subs(sf**2, 0), sf)[0]
    # eq. 67: cos(psi) from omega_1 once S is known
    cos_psi = sp.simplify(sol[c_])
    return {
        "cos_psi_sol": cos_psi,
        "sin_psi_sol": sp.simplify(sol[s_]),
        "A": sp.simplify(A64),
        "B": sp.simplify(B64),
        "C": sp.simplify(C64),
        "quad65": quad65,
        "scale_roots": tuple(roots),
        "scale_approx": 1 + sp.simplify(sf_approx),
        "_ABC": (A_, B_, C_),
        "omega1": m4["omega1"],
        "omega2": m4["omega2"],
        "bias": m4["bias"],
    }


@derivation
def method6() -> dict[str, sp.Expr]:
    """Method 6: gyro turned into z; S from the norm of three components (eqs. 68-71)."""
    m4 = method4()
    # eq. 68: the x gyro turned by -pi/2 about y reads along z_B (table still: omega = 0)
    model_z = real_gyro("z", still=False).subs({**IDEAL, **SB})
    omega3 = (wz - b) / Omega  # eq. 69
    model1 = sp.expand((real_gyro("x", 0).subs({**IDEAL, **SB}) - b) / Omega)
    model2 = sp.expand((real_gyro("x", 90 * DEG).subs({**IDEAL, **SB}) - b) / Omega)
    model3 = sp.expand(((model_z - b) / Omega).subs(w, 0))
    # eq. 70: omega_1^2 + omega_2^2 + omega_3^2 = S^2 (unit Earth-rate vector); reduced by
    # sin^2 = 1 - cos^2 (exact: derivations.trig), which gives S^2 at a 30th of simplify's time
    norm2 = pythagorean_reduce(model1**2 + model2**2 + model3**2)
    if sp.simplify(norm2 - S**2) != 0:
        raise AssertionError("eq. 70: the three components do not span the Earth rate")
    beta = om1**2 + om2**2 + om3**2
    scale = sp.sqrt(beta)
    sf_approx = sp.solve(sp.expand((1 + sf) ** 2 - beta).subs(sf**2, 0), sf)[0]  # eq. 71
    return {
        "model_z": model_z,
        "omega3": omega3.subs(b, m4["bias"]),
        "scale": scale,
        "scale_approx": 1 + sf_approx,
        "bias": m4["bias"],
    }
