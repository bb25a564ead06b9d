"""The IMU + altimeter attitude paper's numbered equations, transcribed as the seed text prints them.

Source: ``../shared/papers/001_7aadea7ab4710a8b.txt`` (OCR of the two-column Persian PDF,
equations as LaTeX). Each entry quotes the OCR in a comment and transcribes it literally
into SymPy. Nothing here is corrected: where the printed text looks wrong the comment says
so, and the derivations/audit decide. Where the OCR garbles a symbol, the comment says which
reading is taken:

* eq. 1: ``C_b^n = C_b^m \\Omega_{nb}^b`` is read d/dt C_b^n = C_b^n Omega (dot lost, m for n);
* eq. 4: ``tg`` is tan; eq. 11: ``arc tag 2(f_y, f_z)`` is atan2(f_y, f_z);
* eqs. 5, 6: the quaternion's ``c`` is ``cq``;
* eq. 20-21: the cut-off ``\\omega`` is ``omega_c``;
* eq. 26: the noise matrix C(x) is printed as a separate block (the ``+ ... w`` joining it is
  lost); it is read as ``+ C(x) w`` (eq. 28);
* eq. 28: ``Bu`` with u = g (the text after eq. 29: ``u_k = g``);
* appendix: ``F_x`` (6a-8a) is F_k; the mean (printed ``(7-a)``, cited in the text as 6-a) is
  keyed '6a', the covariance (also printed ``(7-a)``) '7a'.

Keys and shapes (Matrix shapes are rows x columns, in the printed order):

==============  ===========================================================================
'1'             3x3   RHS of Cdot_b^n = C_b^n Omega_nb^b
'2'             3x3   Omega_nb^b (the C_b^n matrix printed with it is ``mat_C`` itself)
'3'             3x1   omega_ie^b + omega_en^b + omega_nb^b (lhs omega_ib^b)
'4'             3x1   [phi_dot, theta_dot, psi_dot]
'5'             4x1   [a_dot, b_dot, c_dot, d_dot]
'6.euler'       1x3   C_b^n(3,:) in Euler angles (printed as a row)
'6.quat'        1x3   C_b^n(3,:) in quaternion elements (printed as a row)
'7'             3x1   [C31_dot, C32_dot, C33_dot]
'8'             scalar C31^2 + C32^2 + C33^2 - 1 (identity, lhs - rhs)
'9'             3x1   Vdot_e^n
'10'            3x1   f^b (last printed member; the condition on ||f^b|| is text)
'11.phi'        scalar roll from the accelerometers
'11.theta'      scalar pitch from the accelerometers
'12'            3x1   F_t^n (last printed member)
'13'            3x1   c_dot
'14'            3x1   c_dot with normalisation feedback
'15'            scalar gamma
'15.b'          3x1   f^b in cruise (the second equation numbered 15)
'17.a'          3x1   c_hat
'17.b'          3x1   c_a
'18'            scalar c_m (per component; ``c_g``, ``c_a`` are scalar symbols here)
'19'            scalar lim_{s->0} c_m (the printed value, c_a)
'20'            2x1   [k_i, k_p]
'21'            scalar k_p
'24'            scalar V_d_dot
'25'            scalar h_dot
'26.A'          5x5   system matrix;  '26.B' 5x1 gravity input;  '26.C' 5x6 noise matrix C(x)
'27'            1x5   H
'28'            5x1   A x + B g + C(x) w with the eq. 26 matrices
'29'            5x1   x_{k+1} with generic F_k, L_k, u_k and G(x_k) (``Fk``, ``Lk``, ``uk``, ``Gk``)
'30.G'          5x6   G(x_k) ~ dt C(x_k);   '30.L'  5x1  L_k ~ dt B
'31.xpred'      2x1   F x_hat + L u        (on the appendix's n = m = 2 instance, see below)
'31.Ppred'      2x2   F P F^T + G(x_hat) Q G^T(x_hat) + Gamma (Q kron P) Gamma^T  (same instance)
'31.K'          5x1   K_k with symmetric symbolic P_{k-1|k-1} (``P_prev``), P_{k|k-1}
                      (``P_pred``), scalar ``R_k`` and H of eq. 27
'31.P'          5x5   P_{k|k}
'31.x'          5x1   x_hat_{k|k} with symbols ``x_pred`` and ``K``, scalar ``z_k``
'1a'            2x1   y_k
'2a'            dict  the assumed moments (definitions, not derivable)
'3a', '4a'      2x1   z_k = G(x_k) w_k (last printed member of each)
'5a'            2x1   E(z_k) = 0 (the printed value)
'6a'            2x1   y_hat = F x_hat
'7a', '8a'      None  expectations with no printed closed form ('8a.FPF': its F P F^T term)
'9a'            2x1   x_hat + (x - x_hat)
'10a'           None  expectations with no printed closed form
'11a'           None  ('11a.GQG': its closed-form term G(x_hat) Q G^T(x_hat))
'12a.1'         None  the first line printed ``(12-a)``: expectations only
'12a.2'         2x2   sum_ij G_ci Q_ij P G_cj^T (first member of the second ``(12-a)`` line)
'12a.2.gamma'   2x2   Gamma (Q kron P) Gamma^T (last member of that line)
'13a'           2x2   P_y as printed (second G without transpose)
==============  ===========================================================================

The Kalman-filter prediction of eq. 31 and Appendix A hold for general F, G(x), Q, P. They
are transcribed on a small explicit instance: n = 2 states, m = 2 noises, ``F_a`` and
``Gc1``, ``Gc2`` general 2x2 symbol matrices, ``P_a``, ``Q_a`` symmetric 2x2, ``xhat_a``,
``x_a``, ``w_a`` 2x1, G(x) = [G_c1 x, G_c2 x] = G_c1 x e_1^T + G_c2 x e_2^T (eq. 33 /
4a) and Gamma = [G_c1 G_c2] (eq. 32 / 12a); all are module-level names for the audit.

Not included: eqs. 16, 22, 23 (missing from the OCR); eq. 30's F_k = exp(int A(t) dt) (no
symbolic value for a general A(t), and exp of the symbolic 5x5 A is not useful); eqs. 32
(Gamma = [G_c1 ... G_c6]) and 33 (G_ci x_k = G(x_k) e_i), which are definitions: the audit
builds G_ci and Gamma from C(x) itself.
"""

from __future__ import annotations

import sympy as sp

from derivations.altimeter_attitude.symbols import (
    C31,
    C32,
    C33,
    F_norm,
    V_d,
    a,
    b,
    c,
    c1,
    c2,
    c3,
    cq,
    d,
    dt,
    f_b,
    ftx,
    fty,
    ftz,
    fx,
    fy,
    fz,
    g,
    gamma,
    k,
    k_i,
    k_p,
    mat_C,
    omega,
    omega_c,
    phi,
    q,
    s,
    theta,
    w,
    wtx,
    wty,
    wtz,
    wx,
    wy,
    wz,
    x,
    xi,
)

sin, cos, tan, sqrt = sp.sin, sp.cos, sp.tan, sp.sqrt


def skew(v: sp.Matrix) -> sp.Matrix:
    """[v x], the cross-product matrix of a 3-vector (the form printed in eq. 2)."""
    return sp.Matrix([[0, -v[2], v[1]], [v[2], 0, -v[0]], [-v[1], v[0], 0]])


def _sym_matrix(name: str, n: int) -> sp.Matrix:
    """n x n symmetric matrix of real symbols name_ij (i <= j)."""
    return sp.Matrix(
        n,
        n,
        lambda i, j: sp.Symbol(f"{name}_{min(i, j) + 1}{max(i, j) + 1}", real=True),
    )


def _gen_matrix(name: str, rows: int, cols: int) -> sp.Matrix:
    """rows x cols matrix of independent real symbols name_ij."""
    return sp.Matrix(rows, cols, lambda i, j: sp.Symbol(f"{name}_{i + 1}{j + 1}", real=True))


def _vec(name: str, n: int) -> sp.Matrix:
    return sp.Matrix(sp.symbols(f"{name}_1:{n + 1}", real=True))


PRINTED: dict[str, object] = {}

# ---------------------------------------------------------------------------------------
# Section 2: attitude from the gyros
# ---------------------------------------------------------------------------------------

# eq. 2: C_b^n = [[C11 C12 C13], [C21 C22 C23], [C31 C32 C33]],
#        \Omega_{nb}^b = [[0, -\omega_z, \omega_y], [\omega_z, 0, -\omega_x], [-\omega_y, \omega_x, 0]]
Omega = sp.Matrix([[0, -wz, wy], [wz, 0, -wx], [-wy, wx, 0]])
PRINTED["2"] = Omega

# eq. 1: "C_b^n = C_b^m \Omega_{nb}^b"  -- read d/dt C_b^n = C_b^n Omega_nb^b (the dot on the
# left is lost and the right-hand C prints superscript m for n); RHS stored.
PRINTED["1"] = mat_C * Omega

# eq. 3: \omega_{ib}^b = \omega_{ie}^b + \omega_{en}^b + \omega_{nb}^b   (RHS; omega_nb^b = omega)
w_ie_b = sp.Matrix(sp.symbols("omega_ie_bx omega_ie_by omega_ie_bz", real=True))
w_en_b = sp.Matrix(sp.symbols("omega_en_bx omega_en_by omega_en_bz", real=True))
PRINTED["3"] = w_ie_b + w_en_b + omega

# eq. 4: [phi_dot; theta_dot; psi_dot] = [[1, tg theta sin phi, tg theta cos phi],
#         [0, cos phi, -sin phi], [0, sin phi / cos theta, cos phi / cos theta]] [w_x; w_y; w_z]
# ("tg" = tan)
_E4 = sp.Matrix(
    [
        [1, tan(theta) * sin(phi), tan(theta) * cos(phi)],
        [0, cos(phi), -sin(phi)],
        [0, sin(phi) / cos(theta), cos(phi) / cos(theta)],
    ]
)
PRINTED["4"] = _E4 * omega

# eq. 5: [a_dot; b_dot; c_dot; d_dot] = 1/2 [[0, -w_x, -w_y, -w_z], [w_x, 0, w_z, -w_y],
#         [w_y, -w_z, 0, w_x], [w_z, w_y, -w_x, 0]] [a; b; c; d]      (c read cq)
_W5 = sp.Matrix([[0, -wx, -wy, -wz], [wx, 0, wz, -wy], [wy, -wz, 0, wx], [wz, wy, -wx, 0]])
PRINTED["5"] = sp.Rational(1, 2) * _W5 * q

# eq. 6: C_b^n(3,:) = [-sin theta  sin phi cos theta  cos phi cos theta]
#                   = [2(bd - ac)  2(cd + ab)  (a^2 - b^2 - c^2 + d^2)]     (c read cq; rows)
PRINTED["6.euler"] = sp.Matrix([[-sin(theta), sin(phi) * cos(theta), cos(phi) * cos(theta)]])
PRINTED["6.quat"] = sp.Matrix(
    [[2 * (b * d - a * cq), 2 * (cq * d + a * b), a**2 - b**2 - cq**2 + d**2]]
)

# eq. 7: C31_dot = w_z C32 - w_y C33;  C32_dot = w_x C33 - w_z C31;  C33_dot = w_y C31 - w_x C32
PRINTED["7"] = sp.Matrix([wz * C32 - wy * C33, wx * C33 - wz * C31, wy * C31 - wx * C32])

# eq. 8: C31^2 + C32^2 + C33^2 = 1   (identity: lhs - rhs)
PRINTED["8"] = C31**2 + C32**2 + C33**2 - 1

# ---------------------------------------------------------------------------------------
# Section 3: attitude from the accelerometers
# ---------------------------------------------------------------------------------------

# eq. 9: \dot V_e^n = C_b^n f^b - [2 \omega_{ie}^n + \omega_{en}^n] \times V_e^n + g^n
# V_e^n = [V_N, V_E, V_D] with V_D = V_d (velocity down, eq. 24); g^n = [0, 0, g]
V_N, V_E = sp.symbols("V_N V_E", real=True)
V_e = sp.Matrix([V_N, V_E, V_d])
w_ie_n = sp.Matrix(sp.symbols("omega_ie_N omega_ie_E omega_ie_D", real=True))
w_en_n = sp.Matrix(sp.symbols("omega_en_N omega_en_E omega_en_D", real=True))
g_n = sp.Matrix([0, 0, g])
PRINTED["9"] = mat_C * f_b - (2 * w_ie_n + w_en_n).cross(V_e) + g_n

# eq. 10: f^b \equiv -C_n^b g^n = g [sin theta; -cos theta sin phi; -cos theta cos phi]
#         if abs(||f^b|| - g) < \varepsilon      (last member stored; the condition is text)
PRINTED["10"] = g * sp.Matrix([sin(theta), -cos(theta) * sin(phi), -cos(theta) * cos(phi)])

# eq. 11: "\phi = arc tag 2(f_y, f_z)", "\theta = arc sin(f_x / g)"
# ("arc tag 2" read as the two-argument arctangent atan2(y = f_y, x = f_z), as printed: no
# minus signs, although eq. 10 gives f_y, f_z = -g cos(theta) (sin, cos)(phi))
PRINTED["11.phi"] = sp.atan2(fy, fz)
PRINTED["11.theta"] = sp.asin(fx / g)

# eq. 12: F_t^n = \dot V_e^n + [2 \omega_{ie}^n + \omega_{en}^n] \times V_e^n = C_b^n f^b + g^n
# (last member stored)
PRINTED["12"] = mat_C * f_b + g_n

# ---------------------------------------------------------------------------------------
# Section 4: DCM-parameter formulation and the PI complementary filter
# ---------------------------------------------------------------------------------------

# eq. 13: \dot c = [-\omega_{nb}^b \times] c
PRINTED["13"] = -skew(omega) * c

# eq. 14: \dot c = k \gamma c - \Omega_{nb}^b c = [k \gamma I - \Omega_{nb}^b] c
PRINTED["14"] = k * gamma * c - Omega * c

# eq. 15: \gamma = 1 - (c^T c)
PRINTED["15"] = 1 - (c.T * c)[0, 0]

# second eq. 15: f^b \approx -C_n^b g^n = [[C11 C21 C31], [C12 C22 C32], [C13 C23 C33]] [0; 0; -g]
#                = -g [C31; C32; C33] = -g c      (last member stored)
PRINTED["15.b"] = -g * c

# eq. 17-a ("17-الف"): \hat c = (-1/g) f^b
PRINTED["17.a"] = -f_b / g
# eq. 17-b ("17-ب"): c_a = (-1/||f^b||) f^b      (||f^b|| = F_norm)
PRINTED["17.b"] = -f_b / F_norm

# eq. 18: c_m = (s^2 c_g + k_p c_a s + k_i c_a) / (s^2 + k_p s + k_i)
c_g, c_a = sp.symbols("c_g c_a")
PRINTED["18"] = (s**2 * c_g + k_p * c_a * s + k_i * c_a) / (s**2 + k_p * s + k_i)

# eq. 19: lim_{s -> 0} c_m = c_a      (the printed value)
PRINTED["19"] = c_a

# eq. 20: k_i = \omega^2, k_p = 2 \xi \omega      (\omega read omega_c, the cut-off)
PRINTED["20"] = sp.Matrix([omega_c**2, 2 * xi * omega_c])
# eq. 21: k_p = \sqrt{2} \omega
PRINTED["21"] = sqrt(2) * omega_c

# ---------------------------------------------------------------------------------------
# Section 5: the new formulation and the linear Kalman filter
# ---------------------------------------------------------------------------------------

# eq. 24: \dot V_d = c^T f^b + g
PRINTED["24"] = (c.T * f_b)[0, 0] + g
# eq. 25: \dot h = -V_d
PRINTED["25"] = -V_d

# eq. 26: [c1_dot; c2_dot; c3_dot; V_d_dot; h_dot] =
#   [[k\gamma, wt_z, -wt_y, 0, 0], [-wt_z, k\gamma, wt_x, 0, 0], [wt_y, -wt_x, k\gamma, 0, 0],
#    [ft_x, ft_y, ft_z, 0, 0], [0, 0, 0, -1, 0]] [c1; c2; c3; V_d; h] + [0; 0; 0; 1; 0] g
# and, in a separate OCR block (the "+" joining it lost; read "+ C(x) w"):
#   [[0, -c3, c2, 0, 0, 0], [c3, 0, -c1, 0, 0, 0], [-c2, c1, 0, 0, 0, 0], [0, 0, 0, c1, c2, c3],
#    [0, 0, 0, 0, 0, 0]] [n_wx; n_wy; n_wz; n_ax; n_ay; n_az]
A26 = sp.Matrix(
    [
        [k * gamma, wtz, -wty, 0, 0],
        [-wtz, k * gamma, wtx, 0, 0],
        [wty, -wtx, k * gamma, 0, 0],
        [ftx, fty, ftz, 0, 0],
        [0, 0, 0, -1, 0],
    ]
)
B26 = sp.Matrix([0, 0, 0, 1, 0])
C26 = sp.Matrix(
    [
        [0, -c3, c2, 0, 0, 0],
        [c3, 0, -c1, 0, 0, 0],
        [-c2, c1, 0, 0, 0, 0],
        [0, 0, 0, c1, c2, c3],
        [0, 0, 0, 0, 0, 0],
    ]
)
PRINTED["26.A"] = A26
PRINTED["26.B"] = B26
PRINTED["26.C"] = C26

# eq. 27: z = Hx + v,  H = [0 0 0 0 1]
H = sp.Matrix([[0, 0, 0, 0, 1]])
PRINTED["27"] = H

# eq. 28: \dot x = A(t) x + B u + C(x) w;  z = Hx + v      (u = g: "u_k = g" after eq. 29)
PRINTED["28"] = A26 * x + B26 * g + C26 * w

# eq. 29: x_{k+1} = F_k x_k + L_k u_k + G(x_k) w_k      (generic F_k, L_k, u_k, G(x_k))
Fk = _gen_matrix("F_k", 5, 5)
Lk = _vec("L_k", 5)
uk = sp.Symbol("u_k", real=True)
Gk = _gen_matrix("G_k", 5, 6)
PRINTED["29"] = Fk * x + Lk * uk + Gk * w

# eq. 30: F_k = exp(\int_{t_k}^{t_{k+1}} A(t) dt),  G(x_k) \approx \Delta t C(x_k),
#         L_k \approx \Delta t B      (F_k not stored; see the module docstring)
PRINTED["30.G"] = dt * C26
PRINTED["30.L"] = dt * B26

# --- Appendix-A instance (n = 2 states, m = 2 noises), used by eq. 31's prediction and 1a-13a
F_a = _gen_matrix("F", 2, 2)
Gc1 = _gen_matrix("Gc1", 2, 2)
Gc2 = _gen_matrix("Gc2", 2, 2)
P_a = _sym_matrix("P", 2)
Q_a = _sym_matrix("Q", 2)
xhat_a = _vec("xhat", 2)
x_a = _vec("x", 2)
w_a = _vec("w", 2)
e1_a = sp.Matrix([1, 0])
e2_a = sp.Matrix([0, 1])
Gamma_a = sp.Matrix.hstack(Gc1, Gc2)  # eq. 32 / 12a: [G_c1 G_c2 ... G_cm]
L_a = _vec("L", 2)
u_a = sp.Symbol("u", real=True)


def G_a(xv: sp.Matrix) -> sp.Matrix:
    """G(x) of the instance: column i is G_ci x (eq. 33, 4a)."""
    return sp.Matrix.hstack(Gc1 * xv, Gc2 * xv)


G_xhat = G_a(xhat_a)
_kron = sp.kronecker_product(Q_a, P_a)

# eq. 31 (line 1): \hat x_{k|k-1} = F_{k-1} \hat x_{k-1|k-1} + L_{k-1} u_{k-1}
PRINTED["31.xpred"] = F_a * xhat_a + L_a * u_a
# eq. 31 (line 2): P_{k|k-1} = F_{k-1} P_{k-1|k-1} F_{k-1}^T
#   + G(\hat x_{k-1|k-1}) Q_{k-1} G^T(\hat x_{k-1|k-1}) + \Gamma (Q_{k-1} \otimes P_{k-1|k-1}) \Gamma^T
PRINTED["31.Ppred"] = F_a * P_a * F_a.T + G_xhat * Q_a * G_xhat.T + Gamma_a * _kron * Gamma_a.T

# eq. 31 (lines 3-5), 5-state:
#   K_k = P_{k|k-1} H^T (H P_{k-1|k-1} H^T + R_k)^{-1}
#   P_{k|k} = P_{k|k-1} - P_{k|k-1} H^T (H P_{k-1|k-1} H^T + R_k)^{-1} H P_{k|k-1}
#   \hat x_{k|k} = \hat x_{k|k-1} + K_k (z_k - H \hat x_{k|k-1})
# (as printed: P_{k-1|k-1}, not P_{k|k-1}, inside the inverted bracket of both K_k and P_{k|k})
P_prev = _sym_matrix("P_prev", 5)  # P_{k-1|k-1}
P_pred = _sym_matrix("P_pred", 5)  # P_{k|k-1}
R_k = sp.Symbol("R_k", positive=True)
z_k = sp.Symbol("z_k", real=True)
x_pred = _vec("xpred", 5)  # \hat x_{k|k-1}
K = _vec("K", 5)  # K_k as symbols (used in '31.x')
_S_printed = (H * P_prev * H.T + sp.Matrix([[R_k]])).inv()
PRINTED["31.K"] = P_pred * H.T * _S_printed
PRINTED["31.P"] = P_pred - P_pred * H.T * _S_printed * H * P_pred
PRINTED["31.x"] = x_pred + K * (z_k - (H * x_pred)[0, 0])

# eqs. 32 (\Gamma = [G_{c1} G_{c2} ... G_{c6}]) and 33 (G_{ci} x_k = G(x_k) e_i): definitions,
# not stored (the text calls G_ci "\in R^{5 \times 6}"; G_ci x_k with x_k in R^5 needs 5x5).

# ---------------------------------------------------------------------------------------
# Appendix A (printed 1-a ... 13-a)
# ---------------------------------------------------------------------------------------

# eq. 1-a: y_k = F_k x_k + G(x_k) w_k
PRINTED["1a"] = F_a * x_a + G_a(x_a) * w_a

# eq. 2-a: E(w_k) = 0, E(x_k) = \hat x_k, E(w_k w_k^T) = Q_k,
#          E[(x_k - \hat x_k)(x_k - \hat x_k)^T] = P_k      (assumptions: stored as definitions)
PRINTED["2a"] = {
    "E(w)": sp.zeros(2, 1),
    "E(x)": xhat_a,
    "E(w w^T)": Q_a,
    "E[(x - xhat)(x - xhat)^T]": P_a,
}

# eq. 3-a: z_k = G(x_k) w_k = G(x_k) (\sum_{i=1}^m w_{i,k} e_i)      (last member)
PRINTED["3a"] = G_a(x_a) * (w_a[0] * e1_a + w_a[1] * e2_a)

# eq. 4-a: z_k = G(x_k) w_k = \sum_i w_{i,k} [G(x_k) e_i] = \sum_i w_{i,k} (G_{ci} x_k)
#              = (\sum_i w_{i,k} G_{ci}) x_k      (last member)
PRINTED["4a"] = (w_a[0] * Gc1 + w_a[1] * Gc2) * x_a

# eq. 5-a: E(z_k) = E[(\sum_i w_{i,k} G_{ci}) x_k] = \sum_i E(w_{i,k}) G_{ci} E(x_k) = 0
PRINTED["5a"] = sp.zeros(2, 1)

# eq. "7-a" (the first of two; the text cites it as 6-a): \hat y_k = F_x \hat x_k  (F_x read F_k)
PRINTED["6a"] = F_a * xhat_a

# eq. 7-a (the second): P_{y_k} = E[(y_k - \hat y_k)(y_k - \hat y_k)^T]
#   = F_x E[(x_k - \hat x_k)(x_k - \hat x_k)^T] F_x^T + F_x E[(x_k - \hat x_k) w_k^T G^T(x_k)]
#     + E[G(x_k) w_k (x_k - \hat x_k)^T] + E[G(x_k) w_k w_k^T G^T(x_k)]
# Expectations with no printed closed form: None. (The third term prints no F_x^T.)
PRINTED["7a"] = None

# eq. 8-a: P_{y_k} = F_x P_k F_x^T + E[G(x_k) w_k w_k^T G^T(x_k)]
# The second term has no printed closed form: None; its first term is stored as '8a.FPF'.
PRINTED["8a"] = None
PRINTED["8a.FPF"] = F_a * P_a * F_a.T

# eq. 9-a: x_k = \hat x_k + (x_k - \hat x_k)      (RHS; SymPy evaluates it to x_k)
PRINTED["9a"] = xhat_a + (x_a - xhat_a)

# eq. 10-a: E[G(x_k) w_k w_k^T G^T(x_k)] = [G(\hat x_k) w_k w_k^T G^T(\hat x_k)]
#   + E[G(\hat x_k) w_k w_k^T G^T(x_k - \hat x_k)] + E[G(x_k - \hat x_k) w_k w_k^T G^T(\hat x_k)]
#   + E[G(x_k - \hat x_k) w_k w_k^T G^T(x_k - \hat x_k)]
# Expectations only: None. (The first term prints no E.)
PRINTED["10a"] = None

# eq. 11-a: E[G(x_k) w_k w_k^T G^T(x_k)] = [G(\hat x_k) E(w_k w_k^T) G^T(\hat x_k)]
#   + E[G(x_k - \hat x_k) w_k w_k^T G^T(x_k - \hat x_k)]
#   = [G(\hat x_k) Q_k G^T(\hat x_k)] + E[G(x_k - \hat x_k) w_k w_k^T G^T(x_k - \hat x_k)]
# The E[...] term has no closed form here (it is 12-a): None; the closed-form term is '11a.GQG'.
PRINTED["11a"] = None
PRINTED["11a.GQG"] = G_xhat * Q_a * G_xhat.T

# eq. 12-a (first line): E[G(x - \hat x_k) w_k w_k^T G^T(x - \hat x_k)]
#   = E[\sum_i \sum_j G_{ci} w_{i,k} w_{j,k} (x_k - \hat x_k)(x_k - \hat x_k)^T G_{cj}^T]
#   = \sum_i \sum_j G_{ci} E[w_{i,k} w_{j,k} (x_k - \hat x_k)(x_k - \hat x_k)^T] G_{cj}^T
#   = \sum_i \sum_j G_{ci} E[w_{i,k} w_{j,k}] E[(x_k - \hat x_k)(x_k - \hat x_k)^T] G_{cj}^T
# Expectations only: None.
PRINTED["12a.1"] = None

# eq. 12-a (second line): = \sum_i \sum_j G_{ci} Q_{ij} P_k G_{cj}^T
#   = \sum_i \sum_j G_{ci} [Q \otimes P_k] G_{cj}^T
#   = [G_{c1} G_{c2} ... G_{cm}] [Q \otimes P_k] [G_{c1} G_{c2} ... G_{cm}]^T = \Gamma (Q \otimes P_k) \Gamma^T
# First member -> '12a.2', last member -> '12a.2.gamma'. (The middle member, G_ci [Q kron P]
# G_cj^T, is not conformable as printed: n x n times mn x mn; not stored.)
_Gc = [Gc1, Gc2]
PRINTED["12a.2"] = sum(
    (_Gc[i] * Q_a[i, j] * P_a * _Gc[j].T for i in range(2) for j in range(2)),
    sp.zeros(2, 2),
)
PRINTED["12a.2.gamma"] = Gamma_a * _kron * Gamma_a.T

# eq. 13-a: P_{y_k} = F_k P_k F_k^T + G(\hat x_k) Q_k G(\hat x_k) + \Gamma (Q \otimes P_k) \Gamma^T
# (as printed: the second G(\hat x_k) has no transpose)
PRINTED["13a"] = F_a * P_a * F_a.T + G_xhat * Q_a * G_xhat + Gamma_a * _kron * Gamma_a.T
