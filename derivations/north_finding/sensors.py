"""Sensor outputs on the rotating table, from first principles (eqs. 12-18, 22-24, 35-39).

Frames: N (NED) -> T (table, 3-2-1 Euler angles psi, theta, phi) -> B (sensor
block, turned by the table angle tau about z_T). The vehicle is at rest on the
Earth, so T and N do not move relative to E.

Specific force. The sensor sits at the lever arm ``r = l x_B``. By the
transport (Coriolis) theorem, its acceleration relative to inertial space is

    a_I = a_T + 2 omega^{EI} x v_T + omega^{EI} x (omega^{EI} x (R + r)) + ...

and the accelerometer measures f = a_I - G. Writing plumb-bob gravity
g = G - omega x (omega x R) and neglecting omega^{EI} x (omega^{EI} x r)
(|Omega^2 l| ~ 5e-9 l m/s^2) gives

    f = a_T + 2 omega^{EI} x v_T - g                                   (eq. 10 of the paper)

with a_T and v_T the acceleration and velocity of the sensor relative to the
table frame T (fixed to the Earth). At rest on a still table f = -g (eq. 15).

Angular rate. omega^{BI} = omega^{BT} + omega^{TN} + omega^{NE} + omega^{EI}
= omega^{BT} + omega^{EI} at rest (eq. 13), with omega^{BT} read off Poisson's
equation for [T]^{BT}(t).

Real sensor (eqs. 18, 39): the single physical sensor on axis i reads
S f_i + MA_ij f_j + MA_ik f_k + b + n.
"""

from __future__ import annotations

import sympy as sp

from derivations import frames
from derivations.memo import derivation
from derivations.north_finding.symbols import (
    MA_xy,
    MA_xz,
    MA_yx,
    MA_yz,
    MA_zx,
    MA_zy,
    Omega,
    S,
    b,
    g,
    l,
    lam,
    phi,
    psi,
    t,
    tau,
    theta,
    w,
    w_dot,
)
from derivations.trig import pythagorean_reduce

__all__ = [
    "mat_bt",
    "mat_bn",
    "gravity_b",
    "earth_rate_b",
    "coriolis_b",
    "specific_force_b",
    "angular_rate_b",
    "real_reading",
    "MISALIGNMENT",
]

AXES = ("x", "y", "z")
# MISALIGNMENT[i] = {j: MA_ij}: the coupling of the sensor on axis i to axes j.
MISALIGNMENT = {
    "x": {"y": MA_xy, "z": MA_xz},
    "y": {"x": MA_yx, "z": MA_yz},
    "z": {"x": MA_zx, "y": MA_zy},
}


def mat_bt(tau_: sp.Expr = tau) -> sp.Matrix:
    """``[T]^{BT}``: the table turned by ``tau`` about z_T (eq. 16)."""
    return frames.rot_z(tau_)


def mat_bn(tau_: sp.Expr = tau) -> sp.Matrix:
    """``[T]^{BN} = [T]^{BT} [T]^{TN}``."""
    return mat_bt(tau_) * frames.mat_tn(psi, theta, phi)


@derivation
def gravity_b(tau_: sp.Expr = tau) -> sp.Matrix:
    """``[T]^{BT}[T]^{TN}[g]^N``, the gravity vector in B (eq. 16)."""
    return mat_bn(tau_) * frames.gravity_n(g)


@derivation
def earth_rate_b(tau_: sp.Expr = tau) -> sp.Matrix:
    """``[T]^{BT}[T]^{TN}[omega^{EI}]^N = Omega [a_x, a_y, a_z]^T`` (eq. 36)."""
    return mat_bn(tau_) * frames.earth_rate_n(Omega, lam)


@derivation
def _table_kinematics() -> tuple[sp.Matrix, sp.Matrix]:
    """Velocity and acceleration of the sensor relative to T, expressed in B.

    r^T = [T]^{TB} [l, 0, 0]^T with tau = tau(t); differentiate in T, then map to B
    and replace tau', tau'' by the table rate omega and acceleration omega-dot.
    """
    tau_t = sp.Function("tau")(t)
    mat_tb = mat_bt(tau_t).T
    r_t = mat_tb * sp.Matrix([l, 0, 0])
    v_t = r_t.diff(t)
    a_t = v_t.diff(t)
    subs = {tau_t.diff(t, 2): w_dot, tau_t.diff(t): w}
    # sin^2 = 1 - cos^2 (exact, derivations.trig) leaves [0, l omega, 0] and
    # [-l omega^2, l omega_dot, 0], as simplify did (immutable, as simplify returned them)
    v_b = (mat_bt(tau_t) * v_t).subs(subs).applyfunc(pythagorean_reduce)
    a_b = (mat_bt(tau_t) * a_t).subs(subs).applyfunc(pythagorean_reduce)
    return sp.ImmutableMatrix(v_b.subs(tau_t, tau)), sp.ImmutableMatrix(a_b.subs(tau_t, tau))


@derivation
def coriolis_b(tau_: sp.Expr = tau) -> sp.Matrix:
    """``2 [Omega^{EI}]^B [v_B^T]^B = [p_x, p_y, p_z]^T`` (eq. 22).

    [Omega^{EI}]^B = [T]^{BT}[T]^{TN}[Omega^{EI}]^N [T]^{NT}[T]^{TB} (similarity
    transform of the skew matrix).
    """
    v_b, _ = _table_kinematics()
    return 2 * frames.skew(earth_rate_b(tau_)) * v_b.subs(tau, tau_)


@derivation
def specific_force_b(tau_: sp.Expr = tau) -> sp.Matrix:
    """``[f]^B`` of the sensor on the rotating table (eqs. 16, 23 and the a_y, a_z lines of 24).

    f^B = a_T^B + 2 Omega^{EI} x v_T^B - g^B; at rest on a still table
    (l*omega = l*omega_dot = 0) this is eq. 16, f^B = -[T]^{BT}[T]^{TN}[g]^N.
    """
    _, a_b = _table_kinematics()
    return sp.expand(a_b.subs(tau, tau_) + coriolis_b(tau_) - gravity_b(tau_))


@derivation
def table_rate_b(tau_: sp.Expr = tau) -> sp.Matrix:
    """``[T]^{BT}[omega^{BT}]^T = [0, 0, omega]^T`` (eq. 35), from Poisson's equation."""
    tau_t = sp.Function("tau")(t)
    w_b = frames.angular_velocity_from_dcm(mat_bt(tau_t), t)
    return sp.simplify(w_b.subs(tau_t.diff(t), w).subs(tau_t, tau_))


@derivation
def angular_rate_b(tau_: sp.Expr = tau) -> sp.Matrix:
    """``[omega^{BI}]^B = [omega^{BT}]^B + [T]^{BT}[T]^{TN}[omega^{EI}]^N`` (eqs. 14, 37)."""
    return table_rate_b(tau_) + earth_rate_b(tau_)


def real_reading(vec_b: sp.Matrix, axis: str) -> sp.Expr:
    """Reading of the single real sensor on ``axis`` of B (row of eq. 18 / eq. 39), noise-free.

    reading_i = S f_i + sum_j MA_ij f_j + b
    """
    if axis not in AXES:
        raise ValueError(f"axis must be one of {AXES}, got {axis!r}")
    i = AXES.index(axis)
    expr = S * vec_b[i] + b
    for other, ma in MISALIGNMENT[axis].items():
        expr += ma * vec_b[AXES.index(other)]
    return expr


def still_table(expr: sp.Expr | sp.Matrix) -> sp.Expr | sp.Matrix:
    """Substitute a table at rest at the reading (omega = omega_dot = 0)."""
    return expr.subs({w: 0, w_dot: 0})
