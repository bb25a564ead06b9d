"""Table 2 (appendix; Pitman): classical stable-platform position errors, derived.

Two-axis Schuler-loop error model of a local-level platform over a non-rotating sphere of
radius R_0 (omega_0^2 = g / R_0), in level axes x, y and z up:

* the platform is misaligned by the small rotation phi = [phi_x, phi_y, phi_z] (level frame
  -> platform); its accelerometers see ``f - phi x f`` with ``f = [0, 0, g]``, so the
  acceleration error is ``delta_a = nabla - phi x f`` (nabla: accelerometer error);
* the platform is torqued at the transport rate ``omega = z x v / R_0`` computed from the
  indicated velocity, about its own (misaligned) axes, and drifts at ``epsilon``:
  ``phi_dot = z x delta_v / R_0 + epsilon + phi x omega``;
* the azimuth error grows at the azimuth drift, ``phi_z = phi_z(0) + epsilon_z t`` (the
  level-tilt feed into phi_z is second order and dropped).

Per channel this is a third-order ODE for the position error, solved with ``dsolve``.
A velocity change DeltaV_x at t = 0 through an accelerometer scale-factor error k_x is an
impulse k_x DeltaV_x delta(t) of the acceleration error, i.e. an initial velocity error.
"""

from __future__ import annotations

import sympy as sp

from derivations import frames
from derivations.memo import derivation
from derivations.platform_drift import symbols as s

__all__ = ["error_model", "position_errors", "ENTRIES", "table2", "schuler_period"]

ENTRIES = {
    "T2.1": (s.B_x,),
    "T2.2": (s.phi_y0,),
    "T2.3": (s.k_x, s.dV_x),
    "T2.4": (s.eps_y,),
    "T2.5": (s.eps_z,),
    "T2.6": (s.dxdot0,),
    "T2.7": (s.phi_z0,),
}
EPS_X, B_Y = sp.symbols("epsilon_x B_y", real=True)  # y-channel sources (not in Table 2)
SOURCES = (s.B_x, s.phi_y0, s.k_x, s.eps_y, s.eps_z, s.dxdot0, s.phi_z0, EPS_X, B_Y)


def error_model() -> dict[str, sp.Matrix]:
    """Vector error equations: acceleration error and tilt rate (first order in the errors)."""
    g = s.omega0**2 * s.R0
    phi = sp.Matrix(sp.symbols("phi_x phi_y phi_z", real=True))
    dv = sp.Matrix(sp.symbols("dv_x dv_y dv_z", real=True))
    nabla = sp.Matrix([s.B_x, B_Y, 0])
    eps = sp.Matrix([EPS_X, s.eps_y, s.eps_z])
    up = sp.Matrix([0, 0, 1])
    v = sp.Matrix([s.v_x, s.v_y, 0])
    omega = frames.skew(up) * v / s.R0
    delta_a = nabla - frames.skew(phi) * sp.Matrix([0, 0, g])
    phi_dot = frames.skew(up) * dv / s.R0 + eps + frames.skew(phi) * omega
    return {"phi": phi, "dv": dv, "delta_a": delta_a, "phi_dot": phi_dot}


@derivation
def position_errors() -> dict[str, sp.Expr]:
    """delta_x(t) and delta_y(t) with every error source of Table 2 at once (linear model)."""
    m = error_model()
    phi_x, phi_y, phi_z = m["phi"]
    dvx, dvy, _ = m["dv"]
    g = s.omega0**2 * s.R0
    phi_z_t = s.phi_z0 + s.eps_z * s.t
    out = {}
    for ax in ("x", "y"):
        d = sp.Function(f"d{ax}")(s.t)
        i = 0 if ax == "x" else 1
        # acceleration-error row solved for the level tilt it involves
        tilt = phi_y if ax == "x" else phi_x
        tilt_of_d = sp.solve(m["delta_a"][i] - d.diff(s.t, 2), tilt)[0]
        j = 1 if ax == "x" else 0  # the tilt-rate row of that tilt
        own, other = (dvx, dvy) if ax == "x" else (dvy, dvx)
        rate = m["phi_dot"][j].xreplace({own: d.diff(s.t), other: 0})
        rate = rate.xreplace({phi_z: phi_z_t, phi_x: 0, phi_y: 0})  # cross tilts do not couple
        ode = sp.Eq(tilt_of_d.diff(s.t), rate)
        if ax == "x":
            ics = {
                d.subs(s.t, 0): 0,
                d.diff(s.t).subs(s.t, 0): s.dxdot0 + s.k_x * s.dV_x,
                d.diff(s.t, 2).subs(s.t, 0): s.B_x - g * s.phi_y0,
            }
        else:
            ics = {d.subs(s.t, 0): 0, d.diff(s.t).subs(s.t, 0): 0, d.diff(s.t, 2).subs(s.t, 0): 0}
        # simplify=False: dsolve's own simplification of the solution is undone by the expand
        # below (the same expanded solution, measured; it cost a third of the dsolve time)
        sol = sp.dsolve(ode, d, ics=ics, simplify=False)
        out[f"d{ax}"] = sp.expand(sol.rhs)
    return out


def _only(expr: sp.Expr, keep: tuple[sp.Symbol, ...]) -> sp.Expr:
    zero = {src: 0 for src in SOURCES if src not in keep}
    return sp.simplify(expr.subs(zero))


@derivation
def table2() -> dict[str, sp.Expr | tuple[sp.Expr, sp.Expr]]:
    """The position error of each Table 2 row, one error source at a time.

    T2.5 (azimuth drift) is the pair (delta_x, delta_y); T2.7 (initial azimuth error) is
    delta_x, whose cross-direction velocity is v_y.
    """
    pe = position_errors()
    out: dict[str, sp.Expr | tuple[sp.Expr, sp.Expr]] = {}
    for key, keep in ENTRIES.items():
        if key == "T2.5":
            out[key] = (_only(pe["dx"], keep), _only(pe["dy"], keep))
        else:
            out[key] = _only(pe["dx"], keep)
    return out


def schuler_period(g: sp.Expr = s.g, R: sp.Expr = s.R) -> sp.Expr:
    """Period of eq. 29's solution (eq. 30) with k_sh = g/R (no Earth rate): 2 pi / sqrt(g/R)."""
    from derivations.platform_drift.drift import oscillation_period

    return sp.simplify(oscillation_period().subs(s.k_sh, g / R))
