"""The new formulation: vertical channel, the linear model of eq. 26, its discretisation,
and the Euler-angle model of the comparison UKF.

Sensor model (Sec. 5: "white Gaussian noise added to the gyro outputs ... appearing in the
accelerometer outputs"): omega_tilde = omega_nb^b + n_w, f_tilde = f^b + n_a, so the truth
the kinematics need is omega = omega_tilde - n_w, f = f_tilde - n_a.

* eq. 24: V_d_dot = c^T f^b + g (third row of eq. 9, Coriolis dropped);
* eq. 25: h_dot = -V_d (h up, V_d down);
* eq. 26: x = [c1 c2 c3 V_d h], x_dot = A x + B g + C(x) w, with A, B, C the Jacobians of
  the right-hand side built from eqs. 14, 24, 25 (gamma kept as a symbol, as the paper
  does: A depends on the state only through gamma);
* eq. 27: z = H x + v, H = dh/dx;
* eqs. 29-30: for A, B, C held over [t_k, t_k+1], the exact discrete model is
  F = exp(A dt), L = int_0^dt exp(A s) ds B, G = int_0^dt exp(A s) ds C(x); the paper's
  G = dt C(x), L = dt B are their first-order truncations;
* UKF model: state [phi, theta, V_d, h] with eqs. 4, 6, 24, 25.

>>> A = model_matrices()["A"]
>>> A.shape, A[3, :3] == sp.Matrix([[s.ftx, s.fty, s.ftz]])
((5, 5), True)
"""

from __future__ import annotations

import sympy as sp

from derivations.altimeter_attitude import symbols as s
from derivations.altimeter_attitude.kinematics import (
    euler_rates,
    third_row_euler,
    third_row_rates,
)
from derivations.altimeter_attitude.leveling import navigation_symbols, velocity_rate
from derivations.frames import skew
from derivations.memo import derivation

__all__ = [
    "vertical_velocity_rate",
    "altitude_rate",
    "state_rhs",
    "model_matrices",
    "measurement_matrix",
    "discretisation_series",
    "input_vectors",
    "block_structure",
    "noise_columns",
    "euler_state",
    "euler_model_rhs",
    "euler_noise_jacobian",
    "euler_process_noise",
    "euler_state_jacobian",
]


def vertical_velocity_rate(f: sp.Matrix = s.f_b) -> sp.Expr:
    """eq. 24: third row of eq. 9 without the Coriolis/transport term, in c."""
    nav = navigation_symbols()
    vdot = velocity_rate().subs(dict.fromkeys([*nav["w_ie"], *nav["w_en"]], 0))
    third = vdot[2].subs({s.C31: s.c1, s.C32: s.c2, s.C33: s.c3})
    return third.subs(dict(zip(s.f_b, f, strict=True)))


def altitude_rate() -> sp.Expr:
    """eq. 25: h = -p_D (altitude up, position down), so h_dot = -V_d."""
    p_d = sp.Function("p_D", real=True)(s.t)
    return (-p_d).diff(s.t).subs(p_d.diff(s.t), s.V_d)


def state_rhs() -> sp.Matrix:
    """Right-hand side of eq. 26 from eqs. 14, 24, 25 with the sensor model."""
    omega_true = s.omega_t - s.n_w
    f_true = s.f_t - s.n_a
    # eq. 14 with gamma as a symbol: c_dot = k gamma c - Omega c
    cdot = s.k * s.gamma * s.c + third_row_rates(s.c, omega_true)
    return sp.Matrix([*cdot, vertical_velocity_rate(f_true), altitude_rate()])


def model_matrices() -> dict[str, sp.Matrix]:
    """eq. 26: A = d rhs/dx (noise-free), B = d rhs/dg, C(x) = d rhs/dw."""
    rhs = state_rhs()
    zero_noise = dict.fromkeys(s.w, 0)
    A = rhs.subs(zero_noise).jacobian(s.x).subs(s.g, 0)
    B = rhs.diff(s.g)
    C = rhs.jacobian(s.w)
    # the model is exactly linear in x, g and w (C(x) linear in x): check it here
    assert sp.expand(A * s.x + B * s.g + C * s.w - rhs) == sp.zeros(5, 1)
    return {"A": sp.simplify(A), "B": B, "C": C}


def measurement_matrix() -> sp.Matrix:
    """eq. 27: z = h + v, so H = dz/dx = [0 0 0 0 1]."""
    return sp.Matrix([s.h]).jacobian(s.x)


@derivation
def discretisation_series(order: int = 3) -> dict[str, sp.Matrix]:
    """eqs. 29-30 for A, B, C held over a step: truncated series of the exact ZOH model.

    int_0^dt exp(A s) ds = sum_j A^j dt^(j+1) / (j+1)!; F = I + A int(...). Returns the
    terms up to dt**order of L (input) and G (noise), and the first-order ones the paper
    uses (``L1 = dt B``, ``G1 = dt C``).
    """
    m = model_matrices()
    A, B, C = m["A"], m["B"], m["C"]
    integral = sp.zeros(5, 5)
    power = sp.eye(5)
    for j in range(order):
        integral += power * s.dt ** (j + 1) / sp.factorial(j + 1)
        power = power * A
    return {
        "F": sp.eye(5) + A * integral,
        "L": integral * B,
        "G": integral * C,
        "L1": (integral * B).applyfunc(lambda e: sp.series(e, s.dt, 0, 2).removeO()),
        "G1": (integral * C).applyfunc(lambda e: sp.series(e, s.dt, 0, 2).removeO()),
    }


def input_vectors() -> dict[str, sp.Matrix]:
    """eq. 30: L of the exact zero-order hold and the paper's first-order L = dt B.

    int_0^dt exp(A s) ds B = dt B + dt^2/2 A B + ..., and A^2 B = 0 (B drives V_d, A maps
    V_d only to h, and nothing depends on h), so the series stops: exact L = [0, 0, 0, dt,
    -dt^2/2] for any omega, f, gamma.

    >>> input_vectors()["exact"].T
    Matrix([[0, 0, 0, Delta_t, -Delta_t**2/2]])
    """
    m = model_matrices()
    A, B = m["A"], m["B"]
    assert sp.expand(A * A * B) == sp.zeros(5, 1)
    ds = discretisation_series(order=2)
    return {"B": B, "exact": ds["L"].applyfunc(sp.expand), "first_order": ds["L1"]}


def block_structure() -> dict[str, sp.Matrix]:
    """eq. 26: the block structure of A that the filter's fast discretisation relies on.

    A = [[M, 0], [N, V]] with M = k gamma I - [omega x] (3 x 3, the c block), N = A[3:, :3]
    = [[f^T], [0]] and V = A[3:, 3:] = [[0, 0], [-1, 0]] (h_dot = -V_d) constant: A is block
    lower triangular, so exp(A dt) = [[exp(M dt), 0], [int_0^dt exp(V (dt - s)) N exp(M s)
    ds, exp(V dt)]], and V is nilpotent, so exp(V dt) = I + V dt (``vertical_transition``).
    The function checks the zero blocks and that N, V are as stated; it returns M, N, V and
    exp(V dt).

    >>> block_structure()["vertical_transition"]
    Matrix([
    [       1, 0],
    [-Delta_t, 1]])
    """
    A = model_matrices()["A"]
    M, N, V = A[:3, :3], A[3:, :3], A[3:, 3:]
    assert A[:3, 3:] == sp.zeros(3, 2)
    assert N == sp.Matrix([[*s.f_t], [0, 0, 0]])
    assert not V.free_symbols and V * V == sp.zeros(2, 2)
    exp_v = (V * s.dt).exp()
    assert sp.simplify(exp_v - (sp.eye(2) + V * s.dt)) == sp.zeros(2, 2)
    return {"M": M, "N": N, "V": V, "vertical_transition": exp_v}


def noise_columns() -> list[sp.Matrix]:
    """eqs. 32-33: G_ci with G_ci x = G(x) e_i, the Jacobian of column i of G(x) = C(x).

    G(x) is linear and homogeneous in x (no constant part), so G_ci is constant; the
    function checks that G_ci x reproduces column i exactly.
    """
    C = model_matrices()["C"]
    out = []
    for i in range(C.shape[1]):
        col = C[:, i]
        gci = col.jacobian(s.x)
        assert sp.expand(gci * s.x - col) == sp.zeros(5, 1)
        out.append(gci)
    return out


def euler_state() -> sp.Matrix:
    """State of the comparison UKF: [phi, theta, V_d, h]."""
    return sp.Matrix([s.phi, s.theta, s.V_d, s.h])


def euler_model_rhs(noise: bool = False) -> sp.Matrix:
    """UKF model: eq. 4 (phi, theta rows), eq. 24 with c from eq. 6, eq. 25.

    Driven by the sensor outputs (omega_tilde, f_tilde); with ``noise=True`` the sensor
    noise w appears as in the sensor model (omega = omega_tilde - n_w, f = f_tilde - n_a).
    """
    omega = s.omega_t - (s.n_w if noise else sp.zeros(3, 1))
    f = s.f_t - (s.n_a if noise else sp.zeros(3, 1))
    rates = euler_rates().subs(dict(zip(s.omega, omega, strict=True)))
    c = third_row_euler()
    vdot = vertical_velocity_rate(f).subs(dict(zip(s.c, c, strict=True)))
    return sp.Matrix([rates[0], rates[1], vdot, altitude_rate()])


def euler_noise_jacobian() -> sp.Matrix:
    """d(UKF rhs)/dw at w = 0 (4 x 6): maps sensor noise to the Euler-model state rates."""
    return euler_model_rhs(noise=True).jacobian(s.w).subs(dict.fromkeys(s.w, 0))


def euler_process_noise() -> sp.Matrix:
    """dt^2 J Sigma J^T (4 x 4): the per-step process noise of the UKF/EKF model, with
    J = :func:`euler_noise_jacobian` and Sigma = diag(sigma_g^2 I3, sigma_a^2 I3) per sample
    (first order in dt, the counterpart of the linear filter's G Q G^T with G = dt C)."""
    sg2, sa2 = sp.symbols("sigma_g2 sigma_a2", positive=True)
    J = euler_noise_jacobian()
    sigma = sp.diag(sg2, sg2, sg2, sa2, sa2, sa2)
    return (s.dt**2 * J * sigma * J.T).applyfunc(sp.simplify)


def euler_state_jacobian() -> sp.Matrix:
    """d(UKF rhs)/d[phi, theta, V_d, h] (4 x 4), for an EKF on the Euler formulation."""
    return euler_model_rhs().jacobian(euler_state())


def omega_cross_check() -> bool:
    """The attitude block of A is k gamma I - [omega_tilde x] (eq. 14 with the gyro outputs)."""
    A = model_matrices()["A"]
    return sp.expand(A[:3, :3] - (s.k * s.gamma * sp.eye(3) - skew(s.omega_t))) == sp.zeros(3, 3)
