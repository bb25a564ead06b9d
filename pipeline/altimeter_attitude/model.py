"""Numeric model of the paper's linear filter: eq. 26 matrices, discretisation, noise terms.

Conventions (pyins style): arrays over Monte Carlo runs first, then state axes; ``x`` is
(N, 5) = [c1, c2, c3, V_d, h], ``P`` (N, 5, 5); gyro outputs ``gyro`` (N, 3) rad/s and
accelerometer outputs ``accel`` (N, 3) m/s^2 are held over one step ``dt``. All formulas
come from :mod:`pipeline.generated.altimeter_attitude`; this module only reshapes them and
evaluates matrix exponentials.
"""

from __future__ import annotations

import functools
import math

import numpy as np

from pipeline.generated import altimeter_attitude as gen

__all__ = [
    "GAMMA_COLUMNS",
    "A_CONSTANT",
    "B_VECTOR",
    "normalisation_error",
    "matrix_a",
    "a_blocks",
    "noise_matrix",
    "expm_taylor",
    "discretise",
    "discretise_structured",
    "noise_matrix_eq33",
    "gamma_kron_term",
    "gamma_term_closed",
    "ChunkDiscretisation",
    "SERIES_ORDER_MAX",
    "series_coefficients",
    "input_vector",
    "third_row_cov_from_euler",
    "euler_cov_from_third_row",
]

# eq. 33: G_ci (6, 5, 5) with G_ci x = C(x) e_i; eq. 32: Gamma = [G_c1 ... G_c6]
GAMMA_COLUMNS = np.asarray(gen.noise_gamma(), dtype=float).reshape(5, 6, 5).transpose(1, 0, 2)
_GC_STACK = GAMMA_COLUMNS.reshape(30, 5)  # the G_ci stacked: rows (i, a)
_GC_STACK_T = np.ascontiguousarray(_GC_STACK.T)
B_VECTOR = np.asarray(gen.input_matrix_b(), dtype=float)  # eq. 26: B of x_dot = A x + B g


def _vertical_transition(dt: float) -> np.ndarray:
    """exp(V dt) (2, 2) of the constant (V_d, h) block V of A: F[3:, 3:] (eq. 30)."""
    return np.asarray(gen.vertical_transition(dt), dtype=float).reshape(2, 2)


def normalisation_error(c: np.ndarray) -> np.ndarray:
    """gamma = 1 - c^T c (..., ) of c (..., 3), the generated eq. 15.

    >>> float(normalisation_error(np.array([0.6, 0.0, 0.8])))
    0.0
    """
    return gen.normalisation_error(c[..., 0], c[..., 1], c[..., 2])


def matrix_a(gyro: np.ndarray, accel: np.ndarray, k: float, gamma: np.ndarray) -> np.ndarray:
    """eq. 26: A (N, 5, 5) for gyro/accel outputs (N, 3) and gamma (N,)."""
    flat = gen.model_matrix_a(*np.moveaxis(gyro, -1, 0), *np.moveaxis(accel, -1, 0), k, gamma)
    return np.moveaxis(np.asarray(flat), 0, -1).reshape(*gamma.shape, 5, 5)


def _input_basis() -> np.ndarray:
    """A of eq. 26 is linear in the IMU outputs: basis (6, 5, 5) with A(omega, f, gamma = 0)
    = sum_i u_i basis[i], u = [omega, f], read off the generated matrix at unit inputs."""
    eye = np.eye(6)
    zero = matrix_a(np.zeros((1, 3)), np.zeros((1, 3)), 1.0, np.zeros(1))[0]
    out = np.stack(
        [
            matrix_a(eye[i : i + 1, :3], eye[i : i + 1, 3:], 1.0, np.zeros(1))[0] - zero
            for i in range(6)
        ]
    )
    # the constant part (the -1 of h_dot = -V_d) is not an input term
    return out


def a_blocks(gyro: np.ndarray, accel: np.ndarray) -> tuple[np.ndarray, np.ndarray]:
    """The c block (..., 3, 3) and the f row (..., 3) of eq. 26's A at gamma = 0, for IMU
    outputs of any leading shape, from the generated matrix's linear basis."""
    basis = _INPUT_BASIS
    w = np.einsum("...i,iab->...ab", gyro, basis[:3, :3, :3])
    f = np.einsum("...i,ib->...b", accel, basis[3:, 3, :3])
    return w, f


def noise_matrix(c: np.ndarray) -> np.ndarray:
    """eq. 26: C(x) (N, 5, 6) at c (N, 3)."""
    flat = gen.noise_matrix_c(*np.moveaxis(c, -1, 0))
    return np.moveaxis(np.asarray(flat), 0, -1).reshape(*c.shape[:-1], 5, 6)


def expm_taylor(m: np.ndarray, order: int = 12) -> np.ndarray:
    """exp(m) of a stack of small matrices (||m|| < 1) by its Taylor series.

    With the step sizes used here ||A dt|| < 0.5, so 12 terms leave < 1e-13; tests compare
    with scipy.linalg.expm. Scaling and squaring keeps it accurate for larger norms.
    """
    norm = np.abs(m).sum(axis=-1).max()
    squarings = max(0, int(np.ceil(np.log2(norm / 0.5)))) if norm > 0.5 else 0
    m = m / 2.0**squarings
    out = np.broadcast_to(np.eye(m.shape[-1]), m.shape).copy()
    term = out.copy()
    for j in range(1, order + 1):
        term = term @ m / j
        out += term
    for _ in range(squarings):
        out = out @ out
    return out


def discretise(
    a: np.ndarray, dt: float, input_matrix: str = "exact"
) -> tuple[np.ndarray, np.ndarray]:
    """eqs. 29-30: F = exp(A dt) and L (N, 5) for A held over the step.

    ``input_matrix='exact'``: L = int_0^dt exp(A s) ds B from the augmented exponential
    exp([[A, B], [0, 0]] dt) (Van Loan); ``'first_order'``: the paper's L = dt B, which
    drops the -g dt^2/2 that gravity adds to h within a step. General A: see
    :func:`discretise_structured` for the fast path used by the filter.
    """
    n = a.shape[0]
    aug = np.zeros((n, 6, 6))
    aug[:, :5, :5] = a * dt
    aug[:, :5, 5] = B_VECTOR * dt
    phi = expm_taylor(aug)
    F = phi[:, :5, :5]
    if input_matrix == "exact":
        return F, phi[:, :5, 5]
    if input_matrix == "first_order":
        return F, np.broadcast_to(input_vector(dt, input_matrix), (n, 5)).copy()
    raise ValueError(f"input_matrix is {input_matrix!r}; allowed: 'exact', 'first_order'")


def discretise_structured(
    a: np.ndarray, dt: float, input_matrix: str = "exact", tol: float = 1e-16
) -> tuple[np.ndarray, np.ndarray]:
    """The same F and L as :func:`discretise`, from the block structure of eq. 26's A.

    A = [[M, 0, 0], [f^T, 0, 0], [0, -1, 0]] with M = k gamma I - [omega x] (3 x 3)
    (:func:`derivations.altimeter_attitude.model.block_structure` checks it). Its
    exponential is block lower triangular:

        F[:3, :3] = exp(M dt),   F[3, :3] = f^T Phi1,   F[4, :3] = A[4, 3] f^T Phi2,
        F[3:, 3:] = exp(V dt) (generated ``vertical_transition``),   L = ``input_vector``

    with Phi_j = sum_i M^i dt^(i+j) / (i+j)!. Only M enters the series, and ||M dt|| is
    the rotation per step (< 0.1 here): the series stops at the first order whose next term
    is below ``tol`` in the max-row-sum norm; a test checks it against scipy.linalg.expm of
    the full matrix.
    """
    m = a[:, :3, :3] * dt
    norm = float(np.abs(m).sum(axis=-1).max())
    order, bound = 1, norm
    while bound > tol and order < 30:
        order += 1
        bound *= norm / order
    f = a[:, 3, :3]
    n = a.shape[0]
    eye = np.broadcast_to(np.eye(3), m.shape)
    # sums of M^i dt^i / (i + j)! for j = 0, 1, 2 (Phi_j = dt^j times these)
    term = eye.copy()
    s0, s1, s2 = eye.copy(), eye.copy(), eye / 2.0
    fact = 1.0
    for i in range(1, order + 1):
        term = term @ m
        fact *= i
        s0 = s0 + term / fact
        s1 = s1 + term / (fact * (i + 1))
        s2 = s2 + term / (fact * (i + 1) * (i + 2))
    F = np.zeros((n, 5, 5))
    F[:, :3, :3] = s0
    F[:, 3, :3] = np.einsum("ni,nij->nj", f, s1) * dt
    F[:, 4, :3] = a[:, 4, 3:4] * (np.einsum("ni,nij->nj", f, s2) * dt**2)
    F[:, 3:, 3:] = _vertical_transition(dt)
    return F, np.broadcast_to(input_vector(dt, input_matrix), (n, 5))


def noise_matrix_eq33(x: np.ndarray) -> np.ndarray:
    """C(x) (N, 5, 6) assembled column by column from eq. 33: C(x) e_i = G_ci x."""
    cols = (x @ _GC_STACK.T).reshape(-1, 6, 5)  # row i = (G_ci x)^T
    return np.swapaxes(cols, -1, -2)


def gamma_kron_term(P: np.ndarray, q_diag: np.ndarray, dt: float) -> np.ndarray:
    """eq. 31's Gamma (Q kron P) Gamma^T for G(x) = dt C(x) and a diagonal Q.

    Gamma (Q kron P) Gamma^T = sum_ij Q_ij G_ci P G_cj^T (eq. 12a); with Q diagonal only
    i = j remains: sum_i q_i G_ci P G_ci^T, evaluated as two matrix products over the stacked
    G_ci (P is symmetric, so P G_ci^T = (G_ci P)^T). G_ci here include the dt of G = dt C.
    Tests compare it with the literal Kronecker product of eq. 31.
    """
    n = P.shape[0]
    left = (P.reshape(n * 5, 5) @ _GC_STACK_T).reshape(n, 5, 6, 5)  # [n, b, i, a] = (G_ci P)[a, b]
    left = np.ascontiguousarray(left.transpose(0, 3, 2, 1)).reshape(n * 5, 30)  # [(n, a), (i, b)]
    return dt**2 * (left @ _right_factor(tuple(float(v) for v in q_diag))).reshape(n, 5, 5)


@functools.lru_cache(maxsize=8)
def _right_factor(q_diag: tuple[float, ...]) -> np.ndarray:
    """[(i, b), c] = q_i G_ci[c, b], contiguous (the right factor of gamma_kron_term)."""
    h = np.asarray(q_diag)[:, None, None] * GAMMA_COLUMNS.transpose(0, 2, 1)
    return np.ascontiguousarray(h.reshape(30, 5))


def gamma_term_closed(P: np.ndarray, gyro_var: float, accel_var: float, dt: float) -> np.ndarray:
    """The same term for the paper's Q = diag(sigma_g^2 I3, sigma_a^2 I3), in closed form.

    Derived in :func:`derivations.altimeter_attitude.multiplicative_noise.paper_gamma_term`
    and generated (``gamma_term_closed``): dt^2 [sigma_g^2 (tr(P_cc) I3 - P_cc) on the c
    block, sigma_a^2 tr(P_cc) at (V_d, V_d)]; zero elsewhere. About 10x faster than
    :func:`gamma_kron_term` for a few hundred runs (tests prove the two forms equal).
    """
    upper = [P[:, i, j] for i in range(3) for j in range(i, 3)]
    *block, vv = gen.gamma_term_closed(*upper, gyro_var, accel_var, dt)
    out = np.zeros_like(P)
    out[:, :3, :3] = np.stack(block, -1).reshape(-1, 3, 3)
    out[:, 3, 3] = vv
    return out


SERIES_ORDER_MAX = 40  # ChunkDiscretisation: the longest series in (W dt)


def series_coefficients(dt: float) -> np.ndarray:
    """The coefficients c_i of the series sum_i c_i (W dt)^i of :class:`ChunkDiscretisation`,
    rows exp(W dt), Psi_0..2, Xi_0..2 (7, SERIES_ORDER_MAX + 1): 1/i!,
    dt^(j+1) / (i! (i+j+1)) and dt^(j+2) / i! (1/(i+j+1) - 1/(i+j+2)).

    >>> series_coefficients(0.5)[:, 0].tolist()
    [1.0, 0.5, 0.125, 0.041666666666666664, 0.125, 0.020833333333333336, 0.005208333333333332]
    """
    out = np.empty((7, SERIES_ORDER_MAX + 1))
    for i in range(SERIES_ORDER_MAX + 1):
        inv_fact = 1.0 / math.factorial(i)
        out[0, i] = inv_fact
        for j in range(3):
            out[1 + j, i] = inv_fact * dt ** (j + 1) / (i + j + 1)
            out[4 + j, i] = inv_fact * dt ** (j + 2) * (1.0 / (i + j + 1) - 1.0 / (i + j + 2))
    return out


class ChunkDiscretisation:
    """F of eq. 30 for a run of steps, with the gamma-free part computed for all steps at once.

    The c block of A is M = a I + W with a = k gamma and W = -[omega x]. a I commutes with W,
    so exp(M s) = e^(a s) exp(W s) and (see :func:`discretise_structured` for the blocks)

        F[:3, :3] = e^(a dt) exp(W dt)
        F[3, :3]  =  f^T Phi1(a),  Phi1(a) = sum_j a^j / j! Psi_j,  Psi_j = int_0^dt s^j exp(W s) ds
        F[4, :3]  = A[4, 3] f^T Phi2(a),  Phi2(a) = sum_j a^j / j! Xi_j,
                    Xi_j = int_0^dt (dt - s) s^j exp(W s) ds

    Psi_j and Xi_j (j = 0, 1, 2) are series in W; W is skew, so each collapses to
    c0 I + A1 W dt + A2 (W dt)^2 with scalar series A1, A2 in theta^2 = |omega dt|^2
    (Rodrigues), evaluated vectorised over runs and steps; a step then costs a few
    element-wise operations. The a-series is cut after a^2: the
    relative error is below (a dt)^3 / 6; :meth:`transition` falls back to the exact
    :func:`discretise_structured` when |a dt| > A_DT_MAX. Tests compare with scipy's expm.
    """

    A_DT_MAX = 1e-4

    def __init__(
        self, w_block: np.ndarray, f_row: np.ndarray, dt: float, tol: float = 1e-17
    ) -> None:
        # w_block (N, C, 3, 3): the c block of A at gamma = 0 (W = -[omega x]); f_row (N, C, 3)
        self.w_block, self.f_row, self.dt = w_block, f_row, dt
        self._vertical = _vertical_transition(dt)
        w = w_block * dt  # W dt, skew-symmetric (eq. 26 at gamma = 0)
        w2 = w @ w
        f = f_row
        # a power series sum_i c_i (W dt)^i of a skew W collapses to c_0 I + A1 W dt +
        # A2 (W dt)^2, since (W dt)^3 = -theta^2 W dt with theta = |omega| dt (Rodrigues)
        theta2 = -0.5 * np.trace(w2, axis1=-2, axis2=-1)
        theta_max = float(np.sqrt(theta2.max(initial=0.0)))
        self.check_rotation(theta_max)
        # order: first i with theta^(i+1) / (i+1)! < tol (the coefficients below are <= 1/i!)
        order, term = 2, theta_max**3 / 6.0
        while term > tol and order < SERIES_ORDER_MAX:
            order += 1
            term *= theta_max / (order + 1)
        powers = [np.ones_like(theta2)]
        for _ in range(order // 2 + 1):
            powers.append(powers[-1] * -theta2)

        def collapse(coeff):
            c0 = coeff(0)
            a1 = sum(coeff(i) * powers[(i - 1) // 2] for i in range(1, order + 1, 2))
            a2 = sum(coeff(i) * powers[(i - 2) // 2] for i in range(2, order + 1, 2))
            return c0, a1, a2

        fw = np.einsum("nci,ncij->ncj", f, w)
        fw2 = np.einsum("nci,ncij->ncj", f, w2)

        def apply_f(c0, a1, a2):  # f^T (c0 I + a1 W dt + a2 (W dt)^2)
            return c0 * f + a1[..., None] * fw + a2[..., None] * fw2

        coef = series_coefficients(dt)  # rows: exp, Psi_0..2, Xi_0..2
        c0, a1, a2 = collapse(lambda i: coef[0, i])
        self.exp_w = c0 * np.eye(3) + a1[..., None, None] * w + a2[..., None, None] * w2
        self.f_psi = [apply_f(*collapse(lambda i, j=j: coef[1 + j, i])) for j in range(3)]
        self.f_xi = [apply_f(*collapse(lambda i, j=j: coef[4 + j, i])) for j in range(3)]

    @staticmethod
    def check_rotation(theta_max: float) -> None:
        """ValueError if the largest rotation per step exceeds 0.5 rad."""
        if theta_max > 0.5:
            raise ValueError(
                f"rotation per step |omega| dt = {theta_max:.3g} rad: must be <= 0.5 "
                "(the series below are summed term by term)"
            )

    def transition(self, j: int, a: np.ndarray) -> np.ndarray:
        """F (N, 5, 5) of step j of the chunk for a = k gamma (N,)."""
        if np.abs(a).max() * self.dt > self.A_DT_MAX:
            full = np.broadcast_to(A_CONSTANT, (a.shape[0], 5, 5)).copy()
            full[:, :3, :3] = self.w_block[:, j] + a[:, None, None] * np.eye(3)
            full[:, 3, :3] = self.f_row[:, j]
            return discretise_structured(full, self.dt)[0]
        n = a.shape[0]
        F = np.zeros((n, 5, 5))
        F[:, :3, :3] = np.exp(a * self.dt)[:, None, None] * self.exp_w[:, j]
        a1, a2 = a[:, None], 0.5 * a[:, None] ** 2
        F[:, 3, :3] = self.f_psi[0][:, j] + a1 * self.f_psi[1][:, j] + a2 * self.f_psi[2][:, j]
        F[:, 4, :3] = A_CONSTANT[4, 3] * (
            self.f_xi[0][:, j] + a1 * self.f_xi[1][:, j] + a2 * self.f_xi[2][:, j]
        )
        F[:, 3:, 3:] = self._vertical
        return F


def input_vector(dt: float, input_matrix: str = "exact") -> np.ndarray:
    """L of eq. 30: exact [0, 0, 0, dt, -dt^2/2] or the paper's first-order dt B.

    >>> input_vector(0.5).tolist()
    [0.0, 0.0, 0.0, 0.5, -0.125]
    """
    if input_matrix == "exact":
        return np.asarray(gen.input_vector_exact(dt), dtype=float)
    if input_matrix == "first_order":
        return np.asarray(gen.input_vector_first_order(dt), dtype=float)
    raise ValueError(f"input_matrix is {input_matrix!r}; allowed: 'exact', 'first_order'")


def third_row_cov_from_euler(
    phi: np.ndarray, theta: np.ndarray, var_euler: np.ndarray
) -> np.ndarray:
    """Covariance (N, 3, 3) of c for roll/pitch variances var_euler (N, 2): J diag J^T.

    J = dc/d(phi, theta) from eq. 6 by central differences of the generated map (the
    radial direction of c has zero variance; callers add a small radial term).
    """
    eps = 1e-7
    cols = []
    for dphi, dth in ((eps, 0.0), (0.0, eps)):
        cp = np.stack(gen.third_row_from_euler(phi + dphi, theta + dth), -1)
        cm = np.stack(gen.third_row_from_euler(phi - dphi, theta - dth), -1)
        cols.append((cp - cm) / (2 * eps))
    J = np.stack(cols, -1)  # (N, 3, 2)
    return np.einsum("nij,nj,nkj->nik", J, var_euler, J)


def euler_cov_from_third_row(c: np.ndarray, P_c: np.ndarray) -> np.ndarray:
    """Roll/pitch covariance (N, 2, 2) from that of c: J P_c J^T, J = d(phi, theta)/dc."""
    J = np.moveaxis(np.asarray(gen.euler_jacobian_third_row(*np.moveaxis(c, -1, 0))), 0, -1)
    J = J.reshape(*c.shape[:-1], 2, 3)
    return J @ P_c @ np.swapaxes(J, -1, -2)


_INPUT_BASIS = _input_basis()
# the constant part of eq. 26's A (its only entry: A[4, 3] = -1 of h_dot = -V_d)
A_CONSTANT = matrix_a(np.zeros((1, 3)), np.zeros((1, 3)), 1.0, np.zeros(1))[0]
