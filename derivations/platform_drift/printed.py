"""The platform-drift paper's numbered equations, transcribed as the seed text prints them.

Source: ``../shared/papers/002_d5493e0c28f24c11.txt`` (OCR of the two-column Persian PDF,
equations as LaTeX). Each entry quotes the OCR in a comment and transcribes it literally
into SymPy. Where the OCR garbles a symbol, the comment says which reading is taken:

* dots lost on a left-hand side or on z (eq. 15: ``\\omega_y =`` is read omega_y_dot, the
  ``(\\omega_x + p) z / z`` of its second row is read ``(omega_x + p) z_dot / z``; eq. 35:
  ``\\dot\\varphi_x \\cong -k_sh \\varphi_x ...`` is read as the second derivative of eq. 33);
* ``a`` for ``alpha`` in eqs. 30, 34, 36 (the same quantities print as ``\\alpha`` in eq. 31);
* ``\\phi_L`` (eqs. 31, 34) is the latitude phi_i; ``k_l``, ``k_c`` (eqs. 26, 28) are k_I, k_G.

Nothing here is corrected: the corrections are the derivations, and ``audit.py`` compares
the two. Keys are the paper's equation numbers ('9', '31.x', 'T2.5', ...); a row of a
system is one element of a Matrix in the printed order.
"""

from __future__ import annotations

import sympy as sp

from derivations.platform_drift.symbols import (
    A2,
    B2,
    GM,
    R0,
    R_G,
    R_GMM,
    A,
    Amp,
    B,
    B_x,
    R,
    VI_c,
    alpha,
    alpha_T,
    b_a1,
    b_a2,
    b_g1,
    b_g1_dot,
    b_g2,
    b_g2_dot,
    b_g3,
    b_psi,
    ca,
    ca2,
    cb,
    cb2,
    dV_x,
    dxdot0,
    eps_y,
    eps_z_p,
    f1,
    f2,
    f3,
    g,
    g1,
    g2,
    g3,
    k_g,
    k_sh,
    k_x,
    lat,
    lat_ddot,
    lat_dot,
    lon_ddot,
    lon_dot,
    omega0,
    omega_e,
    omega_x,
    omega_y,
    p,
    p_dot,
    p_m,
    phi_x,
    phi_x_dot,
    phi_y,
    phi_y0,
    phi_y_dot,
    phi_z0,
    psi,
    psi0,
    psi_dot,
    q,
    q_dot,
    q_m,
    r,
    r0m,
    r_m,
    t,
    theta_F1,
    theta_F2,
    u,
    v,
    v_x,
    v_y,
    w,
    x,
    y,
    z,
    z_dot,
)

sin, cos, sqrt = sp.sin, sp.cos, sp.sqrt
sl, cl = sin(lat), cos(lat)
sps, cps = sin(psi), cos(psi)
sp0, cp0 = sin(psi0), cos(psi0)

PRINTED: dict[str, object] = {}

# eq. 1: {}^{m_N}_n C = [[C a_T, 0, S a_T], [0, 1, 0], [-S a_T, 0, C a_T]]
PRINTED["1"] = sp.Matrix(
    [[cos(alpha_T), 0, sin(alpha_T)], [0, 1, 0], [-sin(alpha_T), 0, cos(alpha_T)]]
)

# eq. 2: {}^{m_N}_s C = C_3(psi) C_2(phi_y) C_1(phi_x) =
#   [[C psi, -S psi, 0], [S psi, C psi, 0], [0, 0, 1]] [[C phy, 0, S phy], [0, 1, 0], [-S phy, 0, C phy]]
#   [[1, 0, 0], [0, C phx, -S phx], [0, S phx, C phx]]
_C3 = sp.Matrix([[cps, -sps, 0], [sps, cps, 0], [0, 0, 1]])
_C2 = sp.Matrix([[cos(phi_y), 0, sin(phi_y)], [0, 1, 0], [-sin(phi_y), 0, cos(phi_y)]])
_C1 = sp.Matrix([[1, 0, 0], [0, cos(phi_x), -sin(phi_x)], [0, sin(phi_x), cos(phi_x)]])
PRINTED["2"] = _C3 * _C2 * _C1
# eq. 3: {}^m_s C = C_2(phi_y) C_1(phi_x) = (the same two matrices)
PRINTED["3"] = _C2 * _C1

# eq. 4: {}^{mN} w_{emN} = [lam_dot cos(phi_i), phi_i_dot, lam_dot sin(phi_i)],
#        {}^{mN} w_ie = [w_e cos(phi_i), 0, w_e sin(phi_i)], {}^{m_i} w_{m_i m_i} = [0, 0, psi_dot]
#        (subscript garbled: the rate of m_i relative to m_N), {}^m w_{m_i} = [p_m, q_m, r_m],
#        {}^s w_is = [p, q, r], {}^m w_emN = [w_el1, w_el2, w_el3] (definitions)
PRINTED["4"] = sp.Matrix(
    [lon_dot * cl, lat_dot, lon_dot * sl, omega_e * cl, 0, omega_e * sl, 0, 0, psi_dot]
)

# eqs. 5-7: {}^s r_EB = [x y z], {}^s v_iB = [u v w], {}^s w_is = [p q r] (definitions)
PRINTED["5"] = sp.Matrix([x, y, z])
PRINTED["6"] = sp.Matrix([u, v, w])
PRINTED["7"] = sp.Matrix([p, q, r])

# eq. 8: D_s r = D_i r + w_si x r  =>  D {}^s r = D_i {}^s r + {}^s w_si x {}^s r
# (generic vectors: Dir = {}^s(D_i r), wsi = {}^s w_si, rs = {}^s r)
Dir = sp.Matrix(sp.symbols("Dir1:4", real=True))
wsi = sp.Matrix(sp.symbols("wsi1:4", real=True))
rs = sp.Matrix(sp.symbols("rs1:4", real=True))
PRINTED["8"] = Dir + wsi.cross(rs)

# eq. 9: x_dot = r y - q z + u, y_dot = p z - r x + v, z_dot = q x - p y + w
PRINTED["9"] = sp.Matrix([r * y - q * z + u, p * z - r * x + v, q * x - p * y + w])

# eq. 10: D {}^s v_tB = {}^s f_B + {}^s g_B - {}^s(2 w_it x v_tB) + {}^s(w_st x v_tB)
#         - {}^s(w_it x (w_it x r_EB))
# generic vectors (names as in kinematics.velocity_equation_general): a = f + g, w = w_it,
# W = w_st, v = v_tB, r = r_EB
_a = sp.Matrix(sp.symbols("a1:4", real=True))
_w = sp.Matrix(sp.symbols("w1:4", real=True))
_W = sp.Matrix(sp.symbols("W1:4", real=True))
_v = sp.Matrix(sp.symbols("v1:4", real=True))
_r = sp.Matrix(sp.symbols("r1:4", real=True))
PRINTED["10"] = _a - 2 * _w.cross(_v) + _W.cross(_v) - _w.cross(_w.cross(_r))

# eq. 11 (the t = i lines of the block numbered (10)): u_dot = r v - q w + f1 + g1,
#         v_dot = p w - r u + f2 + g2, w_dot = q u - p v + f3 + g3
PRINTED["11"] = sp.Matrix(
    [r * v - q * w + f1 + g1, p * w - r * u + f2 + g2, q * u - p * v + f3 + g3]
)

# eq. 12: p_dot = -f2 / z, q_dot = +f1 / z
PRINTED["12"] = sp.Matrix([-f2 / z, f1 / z])
# eq. 13: omega_y = u / z, omega_x = -v / z
PRINTED["13"] = sp.Matrix([u / z, -v / z])
# eq. 14: phi_y = -x / R_G, phi_x = y / R_G
PRINTED["14"] = sp.Matrix([-x / R_G, y / R_G])

# eq. 15: "\omega_y = -(\omega_y + q)\dot z / z - r \omega_x - (R_G/z) q^2 \varphi_y
#           - (R_G/z) q p \varphi_x + \dot q + (GM/R_G^3)(R_G/z) \varphi_y / (phy^2 + phx^2 + (z/R_G)^2)^(3/2)"
#         (left side read omega_y_dot); continued in the block numbered (16):
#         "\dot\omega_x = -(\omega_x + p) z / z + r \omega_y - (R_G/z) p^2 \phi_x - (R_G/z) p q \phi_y
#           + \dot p + (GM/R_G^3)(R_G/z) \phi_x / (...)^(3/2)"  (z read z_dot in the first term)
#         "\dot\phi_y = -r \phi_x - (z/R_G)(\omega_y - q)",  "\dot\phi_x = +r \phi_y - (z/R_G)(\omega_x - p)"
_D = (phi_y**2 + phi_x**2 + (z / R_G) ** 2) ** sp.Rational(3, 2)
PRINTED["15"] = sp.Matrix(
    [
        -(omega_y + q) * z_dot / z
        - r * omega_x
        - R_G / z * q**2 * phi_y
        - R_G / z * q * p * phi_x
        + q_dot
        + GM / R_G**3 * R_G / z * phi_y / _D,
        -(omega_x + p) * z_dot / z
        + r * omega_y
        - R_G / z * p**2 * phi_x
        - R_G / z * p * q * phi_y
        + p_dot
        + GM / R_G**3 * R_G / z * phi_x / _D,
        -r * phi_x - z / R_G * (omega_y - q),
        r * phi_y - z / R_G * (omega_x - p),
    ]
)

# eq. 16: {}^{mN} w_emN = {}^{mN}_m C {}^m w_emN = {}^{mN}_m C (-{}^m w_ie + {}^m w_im - {}^m w_{mN m})
#   [lam_dot cos(phi_i); phi_i_dot; lam_dot sin(phi_i)] = [[C psi, -S psi, 0], [S psi, C psi, 0], [0, 0, 1]]
#   ([-w_e C psi cos(phi_i); w_e C psi cos(phi_i); -w_e sin(phi_i)] + [p_m; q_m; r_m]) - [0; 0; psi_dot]
# (right-hand side; the second component prints C psi)
PRINTED["16"] = _C3 * (
    sp.Matrix([-omega_e * cps * cl, omega_e * cps * cl, -omega_e * sl]) + sp.Matrix([p_m, q_m, r_m])
) - sp.Matrix([0, 0, psi_dot])

# eq. 17: f1 = (R phi_ddot + R (lam_dot + w_e)^2 sin cos cos(psi) - (R lam_ddot cos(phi_i)
#              - 2 R sin(phi_i) (lam_dot + w_e)^2 phi_i_dot) sin(psi) - (-R(phi_i_dot^2
#              + (lam_dot + w_e)^2 cos^2) + g_i) phi_y
#         f2 = -(R phi_ddot + R (lam_dot + w_e)^2 sin cos sin(psi) - (R lam_ddot cos
#              - 2 R sin (lam_dot + w_e)^2 phi_i_dot) cos(psi) + (-R(...) + g_i) phi_x
# (the unmatched "(" is closed after sin cos: (R phi_ddot + R(...)^2 sin cos) cos(psi))
_L = lon_dot + omega_e
_k17 = -R * (lat_dot**2 + _L**2 * cl**2) + g
_a17 = R * lat_ddot + R * _L**2 * sl * cl
_b17 = R * lon_ddot * cl - 2 * R * sl * _L**2 * lat_dot
PRINTED["17"] = sp.Matrix(
    [_a17 * cps - _b17 * sps - _k17 * phi_y, -_a17 * sps - _b17 * cps + _k17 * phi_x]
)

# eq. 18: f1 = (R w_e^2 sin cos cos(psi) + (R w_e^2 cos^2 - g_i) phi_y
#         f2 = -(R w_e^2 sin cos sin(psi) + (-R w_e^2 cos^2 + g_i) phi_x
PRINTED["18"] = sp.Matrix(
    [
        R * omega_e**2 * sl * cl * cps + (R * omega_e**2 * cl**2 - g) * phi_y,
        -R * omega_e**2 * sl * cl * sps + (-R * omega_e**2 * cl**2 + g) * phi_x,
    ]
)

# eq. 19: phi_x_dot = p - w_e cos cos(psi) + phi_y r; phi_y_dot = q + w_e cos sin(psi) - phi_x r
#         psi_dot = phi_x q - w_e cos cos(psi) phi_y - w_e sin(phi_i) + r
PRINTED["19"] = sp.Matrix(
    [
        p - omega_e * cl * cps + phi_y * r,
        q + omega_e * cl * sps - phi_x * r,
        phi_x * q - omega_e * cl * cps * phi_y - omega_e * sl + r,
    ]
)

# eq. 20: phi_x_dot(0-) = 0, phi_y_dot(0-) = 0, f2 = b_a2, f1 = b_a1;
#   phi_y0- = R w_e^2 sin cos sin(psi_0-) / (g_i - R w_e^2 cos^2) - b_a1 / (g_i - R w_e^2 cos^2)
#   phi_x0- = R w_e^2 sin cos cos(psi_0-) / (g_i - R w_e^2 cos^2) + b_a2 / (g_i - R w_e^2 cos^2)
_den = g - R * omega_e**2 * cl**2
PRINTED["20"] = sp.Matrix(
    [
        R * omega_e**2 * sl * cl * sps / _den - b_a1 / _den,
        R * omega_e**2 * sl * cl * cps / _den + b_a2 / _den,
    ]
)

# eq. 21: theta_F1 (Delta=) b_a1 / g_i, theta_F2 (Delta=) b_a2 / g_i,
#         alpha (Delta=) R w_e^2 sin cos / g_i  =>
#   phi_y0- ~= R w_e^2 sin cos cos(psi_0-) / g_i - b_a1 / g_i = alpha cos(psi_0-) - theta_F1
#   phi_x0- ~= R w_e^2 sin cos sin(psi_0-) / g_i + b_a2 / g_i = alpha sin(psi_0-) + theta_F2
PRINTED["21"] = sp.Matrix(
    [
        R * omega_e**2 * sl * cl * cps / g - b_a1 / g,
        R * omega_e**2 * sl * cl * sps / g + b_a2 / g,
        alpha * cps - theta_F1,
        alpha * sps + theta_F2,
    ]
)
PRINTED["21.defs"] = {alpha: R * omega_e**2 * sl * cl / g, theta_F1: b_a1 / g, theta_F2: b_a2 / g}
PRINTED["21.alpha"] = R * omega_e**2 * sl * cl / g

# eq. 22: psi_dot(0-) = 0, psi_g(0-) = b_psi
PRINTED["22"] = sp.Matrix([0, b_psi])

# eq. 23: d_r = phi_x0- q_0- - w_e cos(phi_i) cos(psi_0-) phi_y0-   [q_0- = r_0- phi_x0- + w_y0]
#         = phi_x0- (r_0- phi_x0- + w_y0) - w_e cos cos(psi_0-) phi_y0-
#   => d_r = (r_0- phi_x0-^2) - alpha w_e cos - w_e cos sin(psi_0-) theta_F2 + w_e cos cos(psi_0-) theta_F1
#      ~= -alpha w_e cos - w_e cos sin(psi_0-) theta_F2 + w_e cos cos(psi_0-) theta_F1
PRINTED["23"] = sp.Matrix(
    [
        phi_x * q - omega_e * cl * cps * phi_y,
        r * phi_x**2
        - alpha * omega_e * cl
        - omega_e * cl * sps * theta_F2
        + omega_e * cl * cps * theta_F1,
    ]
)
PRINTED["23.approx"] = (
    -alpha * omega_e * cl - omega_e * cl * sps * theta_F2 + omega_e * cl * cps * theta_F1
)
# eq. 24: r_0- = w_e sin(phi_i) - d_r = w_e sin(phi_i) + w_e cos(phi_i)(sin(psi_0-) theta_F2 - cos(psi_0-) theta_F1)
PRINTED["24"] = omega_e * sl + omega_e * cl * (sps * theta_F2 - cps * theta_F1)

# eq. 25: r_0+ = b_g3
PRINTED["25"] = b_g3
# eq. 26: p = p_0+ - int_0^t k_I k_c k_F (f2 - b_a2) dt + (b_g1(t) - b_g1(0))
#         q = q_0+ + int_0^t k_I k_c k_F (f1 - b_a1) dt + (b_g2(t) - b_g2(0))
_kI, _kc, _kF = sp.symbols("k_I k_c k_F", positive=True)
_p0, _q0 = sp.symbols("p_0p q_0p", real=True)
_bg1, _bg2 = sp.Function("b_g1")(t), sp.Function("b_g2")(t)
PRINTED["26"] = sp.Matrix(
    [
        _p0 - sp.Integral(_kI * _kc * _kF * (f2 - b_a2), (t, 0, t)) + (_bg1 - _bg1.subs(t, 0)),
        _q0 + sp.Integral(_kI * _kc * _kF * (f1 - b_a1), (t, 0, t)) + (_bg2 - _bg2.subs(t, 0)),
    ]
)

# eq. 27: phi_y_dot(0+) = (-r_0+ + r_0-) phi_x0 = (-b_g3 + r_0-) phi_x0 + b_g2
#         phi_x_dot(0+) = (r_0+ - r_0-) phi_y0 = (b_g3 - r_0-) phi_y0 + b_g1
# (last members; the middle members omit b_g2, b_g1)
PRINTED["27"] = sp.Matrix([(-b_g3 + r0m) * phi_x + b_g2, (b_g3 - r0m) * phi_y + b_g1])

# eq. 28: phi_x_ddot = -k_sh phi_x - b_g3 w_y + b_g3 phi_y_dot + k_g f2 + b_a2 / R_GMM + b_g1_dot(t)
#         phi_y_ddot = -k_sh phi_y + b_g3 w_x - b_g3 phi_x_dot - k_g f1 - b_a1 / R_GMM + b_g2_dot(t)
#         k_sh (Delta=) -phi_dot^2 - (lam_dot + w_e)^2 cos^2(phi) + g_i / R;
#         k_g (Delta=) (1/z - 1/R_GMM); R_GMM = 1 / (k_l k_G k_F)
PRINTED["28"] = sp.Matrix(
    [
        -k_sh * phi_x - b_g3 * omega_y + b_g3 * phi_y_dot + k_g * f2 + b_a2 / R_GMM + b_g1_dot,
        -k_sh * phi_y + b_g3 * omega_x - b_g3 * phi_x_dot - k_g * f1 - b_a1 / R_GMM + b_g2_dot,
    ]
)
PRINTED["28.k"] = -(lat_dot**2) - (lon_dot + omega_e) ** 2 * cl**2 + g / R
PRINTED["28.kg"] = sp.Matrix([1 / z - 1 / R_GMM, 1 / (_kI * sp.Symbol("k_G", positive=True) * _kF)])

# eq. 29: phi_x_ddot = -k_sh phi_x, phi_y_ddot = -k_sh phi_y
PRINTED["29"] = sp.Matrix([-k_sh * phi_x, -k_sh * phi_y])
# eq. 30: phi_x = A sin(sqrt(K_sh) t) + B cos(sqrt(K_sh) t); phi_y = A' sin(...) + B' cos(...)
#         phi_x0 = B = a sin psi_0 + theta_F2 = a sin psi_0        ("a" read alpha)
_sk = sqrt(k_sh)
PRINTED["30"] = sp.Matrix(
    [A * sin(_sk * t) + B * cos(_sk * t), A2 * sin(_sk * t) + B2 * cos(_sk * t)]
)
PRINTED["30.B"] = sp.Matrix([alpha * sp0 + theta_F2, alpha * sp0])

# eq. 31: phi_x0_dot = A sqrt(K_sh) = -alpha w_e sin(phi_L) cos psi_0 + (alpha cos psi_0) b_g3
#   + (w_e sin(phi_L) + alpha w_e cos(phi_i) cos^2 psi_0) theta_F1 + (-alpha w_e cos sin psi_0 cos psi_0) theta_F2
#   + (-1) b_g3 theta_F1 + (-w_e cos cos psi_0) theta_F2^2 + (w_e cos sin psi_0) theta_F1 theta_F2 + b_g1
#   = -alpha w_e sin(phi_L) cos psi_0 + b_g1
# phi_y0 = B' = alpha cos psi_0 - theta_F1 = alpha cos psi_0
# phi_y0_dot = A' sqrt(K_sh) = alpha w_e sin(phi_L) sin psi_0 + (alpha sin psi_0) b_g3
#   + (-alpha w_e cos sin psi_0 cos psi_0) theta_F1 + (w_e sin(phi_L) + alpha w_e cos sin^2 psi_0) theta_F2
#   + (1) b_g3 theta_F2 + (w_e cos sin psi_0) theta_F2^2 + (-w_e cos cos psi_0) theta_F1 theta_F2 + b_g2
#   = alpha w_e sin(phi_L) sin psi_0
PRINTED["31.x"] = (
    -alpha * omega_e * sl * cp0
    + (alpha * cp0) * b_g3
    + (omega_e * sl + alpha * omega_e * cl * cp0**2) * theta_F1
    + (-alpha * omega_e * cl * sp0 * cp0) * theta_F2
    + (-1) * b_g3 * theta_F1
    + (-omega_e * cl * cp0) * theta_F2**2
    + (omega_e * cl * sp0) * theta_F1 * theta_F2
    + b_g1
)
PRINTED["31.x.ideal"] = -alpha * omega_e * sl * cp0 + b_g1
PRINTED["31.y0"] = sp.Matrix([alpha * cp0 - theta_F1, alpha * cp0])
PRINTED["31.y"] = (
    alpha * omega_e * sl * sp0
    + (alpha * sp0) * b_g3
    + (-alpha * omega_e * cl * sp0 * cp0) * theta_F1
    + (omega_e * sl + alpha * omega_e * cl * sp0**2) * theta_F2
    + (1) * b_g3 * theta_F2
    + (omega_e * cl * sp0) * theta_F2**2
    + (-omega_e * cl * cp0) * theta_F1 * theta_F2
    + b_g2
)
PRINTED["31.y.ideal"] = alpha * omega_e * sl * sp0

# eq. 32: p_False = p_m + phi'_x_dot - b_g1, q_False = q_m + phi'_y_dot;
#   p'_m = p_False - phi_x_dot => p'_m - p_m = phi'_x_dot - phi_x_dot - b_g1 = p_merror;
#   q'_m - q_m = phi'_y_dot - phi_y_dot = q_merror   (definitions)
#   p_merror = -b_g1 + b_g1 cos(sqrt(K_sh) t), int p_merror = -b_g1 t + b_g1/sqrt(K_sh) sin(sqrt(K_sh) t)
#   q_merror = 0, int q_merror = 0
#   sqrt((int_0^t p_merror dt)^2 + (int_0^t q_merror dt)^2) = b_g1 (t - sin(sqrt(K_sh) t) / sqrt(K_sh))
PRINTED["32.p"] = sp.Matrix([-b_g1 + b_g1 * cos(_sk * t), -b_g1 * t + b_g1 / _sk * sin(_sk * t)])
PRINTED["32.q"] = sp.Matrix([0, 0])
PRINTED["32"] = b_g1 * (t - sin(_sk * t) / _sk)

# eq. 33: phi_x_ddot = -k_sh phi_x - b_g3 w_y + b_g3 phi_y_dot ~= -k_sh phi_x - b_g3 w_y
#         phi_y_ddot = -k_sh phi_y + b_g3 w_x - b_g3 phi_x_dot ~= -k_sh phi_y + b_g3 w_x
PRINTED["33"] = sp.Matrix(
    [
        -k_sh * phi_x - b_g3 * omega_y + b_g3 * phi_y_dot,
        -k_sh * phi_y + b_g3 * omega_x - b_g3 * phi_x_dot,
    ]
)
PRINTED["33.approx"] = sp.Matrix([-k_sh * phi_x - b_g3 * omega_y, -k_sh * phi_y + b_g3 * omega_x])

# eq. 34: phi_x0 = B = a sin psi_0; phi_x0_dot = A sqrt(K_sh) = -alpha w_e sin(phi_L) cos psi_0
#         + a cos psi_0 b_g3; phi_y0 = B' = a cos psi_0;
#         phi_y0_dot = A' sqrt(K_sh) = alpha w_e sin(phi_L) sin psi_0 + a sin psi_0 b_g3   ("a" read alpha)
PRINTED["34"] = sp.Matrix(
    [
        alpha * sp0,
        -alpha * omega_e * sl * cp0 + alpha * cp0 * b_g3,
        alpha * cp0,
        alpha * omega_e * sl * sp0 + alpha * sp0 * b_g3,
    ]
)

# eq. 35: {phi_x_dot ~= -k_sh phi_x - b_g3 w_y; phi_y_dot ~= -k_sh phi_y + b_g3 w_x} (read phi_ddot)
#         {w_y ~= -w_e cos(phi_i0) S psi; w_x ~= w_e cos(phi_i0) C psi}, psi ~= psi_0 - w_e sin(phi_i0) t
#         phi_x_dot = -k_sh phi_x + b_g3 w_e cos(phi_i0) sin(psi_0 - w_e sin(phi_i0) t)
#                   = -k_sh phi_x + A sin(psi_0 - w_e sin(phi_i0) t)
#         phi_y_dot = -k_sh phi_y + b_g3 w_e cos(phi_i0) cos(psi_0 - w_e sin(phi_i0) t)
#                   = -k_sh phi_y + A cos(psi_0 - w_e sin(phi_i0) t)      (phi_i0: the latitude)
PRINTED["35.ode"] = PRINTED["33.approx"]
PRINTED["35.w"] = sp.Matrix([-omega_e * cl * sps, omega_e * cl * cps])
PRINTED["35.psi"] = psi0 - omega_e * sl * t
_arg = psi0 - omega_e * sl * t
PRINTED["35"] = sp.Matrix(
    [
        -k_sh * phi_x + b_g3 * omega_e * cl * sin(_arg),
        -k_sh * phi_x + Amp * sin(_arg),
        -k_sh * phi_y + b_g3 * omega_e * cl * cos(_arg),
        -k_sh * phi_y + Amp * cos(_arg),
    ]
)

# eq. 36: int p_merror = (a cos psi_0 b_g3 / sqrt(K_sh)) sin(sqrt(K_sh) t)     ("a" read alpha)
#           + A [a cos(sqrt(k_sh) t) + b / sqrt(k_sh) sin(sqrt(k_sh) t) - a cos(w_e sin(phi_i0) t)
#           - b / (w_e sin(phi_i0)) sin(w_e sin(phi_i0) t)]
#         int q_merror = (a sin psi_0 b_g3 / sqrt(K_sh)) sin(sqrt(K_sh) t)
#           + A [a' cos(...) + b' / sqrt(k_sh) sin(...) - a' cos(w_e sin t) - b' / (w_e sin) sin(w_e sin t)]
#         a = sin psi_0 / (w_e^2 sin^2 - k_sh), b = -w_e sin cos psi_0 / (w_e^2 sin^2 - k_sh),
#         a' = cos psi_0 / (w_e^2 sin^2 - k_sh), b' = w_e sin sin psi_0 / (w_e^2 sin^2 - k_sh)
_Wp = omega_e * sl
PRINTED["36.p"] = alpha * cp0 * b_g3 / _sk * sin(_sk * t) + Amp * (
    ca * cos(_sk * t) + cb / _sk * sin(_sk * t) - ca * cos(_Wp * t) - cb / _Wp * sin(_Wp * t)
)
PRINTED["36.q"] = alpha * sp0 * b_g3 / _sk * sin(_sk * t) + Amp * (
    ca2 * cos(_sk * t) + cb2 / _sk * sin(_sk * t) - ca2 * cos(_Wp * t) - cb2 / _Wp * sin(_Wp * t)
)
_den36 = omega_e**2 * sl**2 - k_sh
PRINTED["36.coef"] = {
    ca: sp0 / _den36,
    cb: -omega_e * sl * cp0 / _den36,
    ca2: cp0 / _den36,
    cb2: omega_e * sl * sp0 / _den36,
}
# A of eqs. 35-36 (read off the equality in eq. 35): A = b_g3 w_e cos(phi_i0); W = w_e sin(phi_i0)
AMP_35 = b_g3 * omega_e * cl

# Table 2 (appendix 1, after Pitman [5]): position error per error source
#  1 Accelerometer bias B_x:            B_x / w_0^2 (1 - cos w_0 t)
#  2 Initial platform tilt phi_y(0):    -R_0 phi_y(0) (1 - cos w_0 t)
#  3 Accelerometer scale factor k_x:    k_x DeltaV_x / w_0 sin w_0 t
#  4 Gyro drift eps_y:                  -R_0 eps_y (t - sin w_0 t / w_0)
#  5 Azimuth gyro drift eps_z:          sqrt(Dx^2 + Dy^2), Dx = eps'_z v_y [t^2 - 2/w_0^2 (1 - cos w_0 t)],
#                                       Dy = -eps'_z v_x [t^2 - 2/w_0^2 (1 - cos w_0 t)]
#  6 Initial velocity error Dx_dot(0):  Dx_dot(0) / w_0 sin w_0 t
#  7 Initial azimuth error phi_z(0):    phi_z(0) VI_c (t - sin w_0 t / w_0)
#  8 w_0 Schuler frequency, R_0 Earth's radius, DeltaV_x x velocity change,
#    v_x = v_y = 1000 ft/sec, VI_c inertial velocity, cross direction
_w0t = omega0 * t
_br = t**2 - 2 / omega0**2 * (1 - cos(_w0t))
PRINTED["T2.1"] = B_x / omega0**2 * (1 - cos(_w0t))
PRINTED["T2.2"] = -R0 * phi_y0 * (1 - cos(_w0t))
PRINTED["T2.3"] = k_x * dV_x / omega0 * sin(_w0t)
PRINTED["T2.4"] = -R0 * eps_y * (t - sin(_w0t) / omega0)
PRINTED["T2.5"] = sp.Matrix([eps_z_p * v_y * _br, -eps_z_p * v_x * _br])
PRINTED["T2.6"] = dxdot0 / omega0 * sin(_w0t)
PRINTED["T2.7"] = phi_z0 * VI_c * (t - sin(_w0t) / omega0)
PRINTED["T2.8"] = {"v_x": "1000 ft/s", "v_y": "1000 ft/s"}
