"""Tilt-error ODEs and the position error for a constant gyro drift (eqs. 28-36).

* :func:`tilt_error_equations` (eq. 28): eq. 15 before the commands is differentiated once
  more along the motion; the platform is driven by the navigation-phase commands of eq. 26
  (p_dot = -(f2 - b_a2)/R_GMM + b_g1_dot, q_dot = (f1 - b_a1)/R_GMM + b_g2_dot), turns at
  r = b_g3 about axis 3, and the radius is constant (z = R_G = R, z_dot = 0); first order
  in the tilts. The gyroscopic terms come out as p^2 phi_x + p q phi_y (and q^2 phi_y +
  p q phi_x), which the paper lumps into the constant k_sh.
* :func:`model_rhs`: the paper's model, i.e. the tilt coupling replaced by -k_sh phi; eqs.
  29-36 are solved on it with ``sympy.dsolve``.
* channel 1 (eqs. 29-32) and channel 3 (eqs. 33-36): the tilts with and without the drift
  start from the initial conditions of eqs. 31/34 (derived in :mod:`alignment`, ideal IMU,
  first order in alpha); the rate errors are p_merror = phi'_x_dot - phi_x_dot - b_g1,
  q_merror = phi'_y_dot - phi_y_dot (eq. 32's definitions), whose integrals are the
  position error angles.
"""

from __future__ import annotations

import sympy as sp

from derivations.memo import derivation
from derivations.platform_drift import algorithm as alg
from derivations.platform_drift import alignment as al
from derivations.platform_drift import symbols as s
from derivations.platform_drift.approx import taylor

__all__ = [
    "nav_command_rates",
    "tilt_error_equations",
    "model_rhs",
    "homogeneous_solution",
    "oscillation_period",
    "channel1",
    "channel3",
    "channel3_aw",
    "channel3_forcing",
    "initial_conditions_ideal",
    "platform_azimuth_stationary",
]

IDEAL_IMU = {s.theta_F1: 0, s.theta_F2: 0, s.b_a1: 0, s.b_a2: 0}
NO_GAIN_MISMATCH = {s.R_GMM: s.R}  # k_g = 1/z - 1/R_GMM = 0
CONSTANT_DRIFT = {s.b_g1_dot: 0, s.b_g2_dot: 0}


def nav_command_rates() -> dict[str, sp.Expr]:
    """Time derivative of the navigation-phase commands (eq. 26), R_GMM = 1/(k_I k_G k_F)."""
    return {
        "p_dot": -(s.f2 - s.b_a2) / s.R_GMM + s.b_g1_dot,
        "q_dot": (s.f1 - s.b_a1) / s.R_GMM + s.b_g2_dot,
    }


@derivation
def tilt_error_equations() -> dict[str, sp.Expr]:
    """Eq. 28 derived: phi_x_ddot, phi_y_ddot (first order in the tilts).

    Returned in phi_x, phi_y, phi_x_dot, phi_y_dot, omega_x, omega_y, p, q, b_g3, f1, f2,
    b_a1, b_a2, b_g1_dot, b_g2_dot, R, R_GMM and g_i (GM = g_i R^2).
    """
    pre = alg.oscillation_equations(commands=False)
    names = {
        s.phi_x: "phx",
        s.phi_y: "phy",
        s.omega_x: "wx",
        s.omega_y: "wy",
        s.p: "P",
        s.q: "Q",
    }
    fn = {k: sp.Function(v)(s.t) for k, v in names.items()}
    back = {v: k for k, v in fn.items()}
    cmd = nav_command_rates()
    const = {s.z_dot: 0, s.r: s.b_g3}
    rates = {
        fn[s.omega_x].diff(s.t): pre["omega_x_dot"].xreplace(const).xreplace(fn),
        fn[s.omega_y].diff(s.t): pre["omega_y_dot"].xreplace(const).xreplace(fn),
        fn[s.phi_x].diff(s.t): s.phi_x_dot,
        fn[s.phi_y].diff(s.t): s.phi_y_dot,
        fn[s.p].diff(s.t): cmd["p_dot"],
        fn[s.q].diff(s.t): cmd["q_dot"],
    }
    radius = {s.z: s.R, s.R_G: s.R, s.GM: s.g * s.R**2}
    out = {}
    for key, first in (("phi_x_ddot", "phi_x_dot"), ("phi_y_ddot", "phi_y_dot")):
        e = pre[first].xreplace(const).xreplace(fn).diff(s.t)
        e = e.xreplace(rates).xreplace(back).xreplace(radius)
        out[key] = taylor(e, [s.phi_x, s.phi_y], 1)
    return out


def model_rhs() -> dict[str, sp.Expr]:
    """The paper's eq. 28 model: the tilt terms of :func:`tilt_error_equations` -> -k_sh phi."""
    ex = tilt_error_equations()
    zero = {s.phi_x: 0, s.phi_y: 0}
    return {
        "phi_x_ddot": -s.k_sh * s.phi_x + ex["phi_x_ddot"].xreplace(zero),
        "phi_y_ddot": -s.k_sh * s.phi_y + ex["phi_y_ddot"].xreplace(zero),
    }


def _solve(forcing: sp.Expr, phi0: sp.Expr, phidot0: sp.Expr, hint: str = "default") -> sp.Expr:
    """Solve phi'' = -k_sh phi + forcing(t) with phi(0), phi'(0) by ``sympy.dsolve``."""
    ph = sp.Function("phi")(s.t)
    ode = sp.Eq(ph.diff(s.t, 2), -s.k_sh * ph + forcing)
    ics = {ph.subs(s.t, 0): phi0, ph.diff(s.t).subs(s.t, 0): phidot0}
    # simplify=False: dsolve's own simplification of the solution is undone by the expand
    # below (the same expanded solution for every call, measured; it cost a third of the time)
    sol = sp.dsolve(ode, ph, ics=ics, hint=hint, simplify=False)
    return sp.expand(sol.rhs)


@derivation
def homogeneous_solution(phi0: sp.Expr = s.B, phidot0: sp.Expr | None = None) -> sp.Expr:
    """Eq. 30: general solution of eq. 29, parametrised by phi(0) = B, phi_dot(0) = A sqrt(k_sh)."""
    if phidot0 is None:
        phidot0 = s.A * sp.sqrt(s.k_sh)
    return _solve(sp.S.Zero, phi0, phidot0)


def oscillation_period() -> sp.Expr:
    """Period of eq. 30's solution in k_sh: 2 pi / sqrt(k_sh) (eq. 30's one frequency)."""
    sol = homogeneous_solution()
    freqs = {a.args[0].coeff(s.t) for a in sol.atoms(sp.sin, sp.cos) if a.has(s.t)}
    assert len(freqs) == 1, freqs
    return sp.simplify(2 * sp.pi / freqs.pop())


@derivation
def initial_conditions_ideal() -> dict[str, sp.Expr]:
    """Eqs. 30-31 / 34 for an ideal IMU: phi(0), phi_dot(0+) to first order in alpha.

    From :func:`alignment.tilts_0m` and :func:`alignment.tilt_rates_0p_full` with
    theta_F = 0 (and psi = psi_0).
    """
    tilts = al.tilts_0m()
    rates = al.tilt_rates_0p_full()
    out = {
        "phi_x": tilts["phi_x"],
        "phi_y": tilts["phi_y"],
        "phi_x_dot": rates["phi_x_dot"],
        "phi_y_dot": rates["phi_y_dot"],
    }
    out = {k: taylor(v.subs(IDEAL_IMU), [s.alpha], 1) for k, v in out.items()}
    return {k: sp.expand(sp.trigsimp(v.subs(s.psi, s.psi0))) for k, v in out.items()}


@derivation
def channel1() -> dict[str, sp.Expr]:
    """Eqs. 29-32: constant drift b_g1 of the first level gyro, vehicle at rest, ideal IMU.

    Tilts with (phi') and without (phi) the drift solve eq. 29 (the model with b_g3 = 0,
    k_g = 0, b_a = 0, constant drift) from the initial conditions of eq. 31.
    """
    rhs = model_rhs()
    reps = {**IDEAL_IMU, **NO_GAIN_MISMATCH, **CONSTANT_DRIFT, s.b_g3: 0, s.b_g2: 0}
    forcing = {
        k: sp.simplify(v.subs(reps) + s.k_sh * (s.phi_x if "x" in k else s.phi_y))
        for k, v in rhs.items()
    }
    assert all(f == 0 for f in forcing.values()), forcing  # eq. 29: homogeneous
    ic = {k: v.subs({s.b_g3: 0, s.b_g2: 0}) for k, v in initial_conditions_ideal().items()}
    with_drift_x = _solve(0, ic["phi_x"], ic["phi_x_dot"])
    no_drift_x = _solve(0, ic["phi_x"], ic["phi_x_dot"].subs(s.b_g1, 0))
    with_drift_y = _solve(0, ic["phi_y"], ic["phi_y_dot"])
    no_drift_y = _solve(0, ic["phi_y"], ic["phi_y_dot"].subs(s.b_g1, 0))
    p_err = sp.simplify(with_drift_x.diff(s.t) - no_drift_x.diff(s.t) - s.b_g1)
    q_err = sp.simplify(with_drift_y.diff(s.t) - no_drift_y.diff(s.t))
    tau = sp.Dummy("tau", positive=True)
    int_p = sp.simplify(sp.integrate(p_err.subs(s.t, tau), (tau, 0, s.t)))
    int_q = sp.simplify(sp.integrate(q_err.subs(s.t, tau), (tau, 0, s.t)))
    return {
        "phi_x": with_drift_x,
        "phi_x_nodrift": no_drift_x,
        "p_merror": p_err,
        "q_merror": q_err,
        "int_p": int_p,
        "int_q": int_q,
        "norm": sp.sqrt(int_p**2 + int_q**2),
    }


def platform_azimuth_stationary() -> sp.Expr:
    """psi(t) of the platform at rest with r = b_g3: eq. 19 at zeroth order in the tilts.

    psi_dot = r - omega_e sin(phi_i), psi(0) = psi_0.
    """
    k19 = alg.tilt_kinematics_stationary()
    ps = sp.Function("psi")(s.t)
    rate = k19["psi_dot"].subs({s.phi_x: 0, s.phi_y: 0, s.r: s.b_g3})
    sol = sp.dsolve(sp.Eq(ps.diff(s.t), rate), ps, ics={ps.subs(s.t, 0): s.psi0}, simplify=False)
    return sp.expand(sol.rhs)


@derivation
def channel3_forcing() -> dict[str, sp.Expr]:
    """Forcing of eq. 33/35: -b_g3 omega_y and b_g3 omega_x along psi(t), first order in b_g3.

    The b_g3 phi_dot terms of eq. 28 are second order (b_g3 times a tilt rate) and dropped
    (eq. 33). omega_x, omega_y are those of a vehicle at rest (eq. 35).
    """
    rhs = model_rhs()
    reps = {**IDEAL_IMU, **NO_GAIN_MISMATCH, **CONSTANT_DRIFT, s.b_g1: 0, s.b_g2: 0}
    w = alg.stationary_radius_rates(s.lat, platform_azimuth_stationary())
    out = {}
    for k, v in rhs.items():
        f = v.subs(reps) + s.k_sh * (s.phi_x if "x" in k else s.phi_y)
        f = taylor(f.subs({s.phi_x_dot: 0, s.phi_y_dot: 0}), [s.b_g3], 1)  # eq. 33
        out[k] = taylor(f.subs({s.omega_x: w["omega_x"], s.omega_y: w["omega_y"]}), [s.b_g3], 1)
    return out


# eq. 35's shorthand: A = b_g3 omega_e cos(phi_i0), W = omega_e sin(phi_i0)
TO_AW = {s.omega_e * sp.sin(s.lat): s.W, s.b_g3 * s.omega_e * sp.cos(s.lat): s.Amp}
FROM_AW = {s.W: s.omega_e * sp.sin(s.lat), s.Amp: s.b_g3 * s.omega_e * sp.cos(s.lat)}


@derivation
def channel3_aw() -> dict[str, sp.Expr]:
    """Eqs. 33-36 in eq. 35's shorthand A, W (see :func:`channel3`)."""
    forcing = channel3_forcing()
    target = {
        "x": s.Amp * sp.sin(s.psi0 - s.W * s.t),
        "y": s.Amp * sp.cos(s.psi0 - s.W * s.t),
    }
    ic = initial_conditions_ideal()
    ic = {k: v.subs({s.b_g1: 0, s.b_g2: 0}).subs(TO_AW) for k, v in ic.items()}
    out = {}
    for ax in ("x", "y"):
        # the derived forcing is A sin(psi_0 - W t) (x) and A cos(psi_0 - W t) (y)
        diff = sp.simplify(forcing[f"phi_{ax}_ddot"] - target[ax].subs(FROM_AW))
        assert diff == 0, (ax, diff)
        with_drift = _solve(
            target[ax],
            ic[f"phi_{ax}"],
            ic[f"phi_{ax}_dot"],
            hint="nth_linear_constant_coeff_undetermined_coefficients",
        )
        no_drift = _solve(0, ic[f"phi_{ax}"], ic[f"phi_{ax}_dot"].subs(s.b_g3, 0))
        out[f"phi_{ax}"] = with_drift
        # tidy: simplify the coefficients of A and alpha (the drift-free alpha terms cancel)
        terms = sp.collect(sp.expand(with_drift - no_drift), [s.Amp, s.alpha], evaluate=False)
        tidy = sp.Add(*(key * sp.simplify(val) for key, val in terms.items()))
        out["int_p" if ax == "x" else "int_q"] = tidy
    return out


def channel3() -> dict[str, sp.Expr]:
    """Eqs. 33-36: constant drift b_g3 of the azimuth gyro, vehicle at rest, ideal IMU.

    The drift-free tilts (b_g3 = 0) solve the homogeneous eq. 29; with the drift, eq. 35's
    forced ODE from the initial conditions of eq. 34. int p_merror = phi'_x - phi_x (both
    start from the same tilt), likewise for q. In omega_e, phi_i (A, W substituted).
    """
    return {k: v.subs(FROM_AW) for k, v in channel3_aw().items()}
