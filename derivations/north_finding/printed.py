"""The north-finding paper's numbered equations, transcribed as the seed text prints them.

Source: ``../shared/papers/000_d5833b6222974346.txt`` (OCR of the two-column PDF).
Each entry quotes the OCR (LaTeX as extracted) in a comment and transcribes it
literally into SymPy; where the OCR splits a sum over two stacked lines, e.g.
``(g_x; g_y)``, the two lines are added (the digest's reading). Where a reading of
a garbled line is needed, the comment says which. Nothing here is corrected: the
corrections are the derivations, and ``audit.py`` compares the two.

Equations 1-11 are not in the seed text.
"""

from __future__ import annotations

import sympy as sp

from derivations.north_finding.symbols import (
    Omega,
    S,
    a1,
    a2,
    a3,
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
    ca,
    cb,
    cc,
    g,
    l,
    lam,
    om1,
    om2,
    om3,
    phi,
    psi,
    sf,
    tau,
    theta,
    w,
    w_dot,
    wx_0,
    wx_90,
    wx_180,
    wx_270,
    wx_max,
    wz,
)

sin, cos, tan, atan, sqrt = sp.sin, sp.cos, sp.tan, sp.atan, sp.sqrt
sl, cl, tl = sin(lam), cos(lam), tan(lam)
sth, cth, tth = sin(theta), cos(theta), tan(theta)
sph, cph, tph = sin(phi), cos(phi), tan(phi)
sps, cps = sin(psi), cos(psi)
st, ct = sin(tau), cos(tau)

# Generic coefficient symbols of eqs. 47-50 (A..E) and 64-65 (A, B, C).
A, B, C, D, E = sp.symbols("A B C D E", real=True)
F, G, H, I, J = sp.symbols("F G H I J", real=True)
c_psi, s_psi = sp.symbols("c_psi s_psi", real=True)
tau_i = sp.Symbol("tau_i", real=True)
a_xi, a_yi = sp.symbols("a_xi a_yi", real=True)

PRINTED: dict[str, object] = {}

# eq. 16: -g [[cos t, sin t, 0], [-sin t, cos t, 0], [0, 0, 1]] [-sin th, cos th sin ph, cos th cos ph]
#          = -g [ -cos t sin th + sin t cos th ; sin t sin th + cos t cos th ; cos th cos ph ]
PRINTED["16.a"] = (
    -g * sp.Matrix([[ct, st, 0], [-st, ct, 0], [0, 0, 1]]) * sp.Matrix([-sth, cth * sph, cth * cph])
)
PRINTED["16.b"] = -g * sp.Matrix([-ct * sth + st * cth, st * sth + ct * cth, cth * cph])

# eq. 17: a_x = g cos t sin th - g sin t cos th sin ph
PRINTED["17"] = g * ct * sth - g * st * cth * sph

# eq. 19: sin th = (a_x|0 - a_x|180) / (2g);  sin ph = (a_x|270 - a_x|90) / (2 g cos th)
#         with a_x|0 = g sin th, a_x|180 = -g sin th, a_x|90 = -g cos th sin ph, a_x|270 = g cos th sin ph
PRINTED["19.a"] = (ax_0 - ax_180) / (2 * g)
PRINTED["19.b"] = (ax_270 - ax_90) / (2 * g * cth)
PRINTED["19.c"] = sp.Matrix([g * sth, -g * sth, -g * cth * sph, g * cth * sph])

# eq. 20: [g cos t, -g sin t] [sin th; cos th sin ph] = a_x
PRINTED["20"] = sp.Matrix([[g * ct, -g * st]])

# eq. 21: H = [cos t_i, -sin t_i] (rows), X = [sin th; cos th sin ph], Y = [a_x1 ... a_xn]; HX = Y
PRINTED["21"] = sp.Matrix([[cos(tau_i), -sin(tau_i)]])  # row of H for Y = a_x (as printed)

# eq. 22: p_x = -2 w^EI w (cos l sin ph sin ps - cos ph cos th sin l + cos ph cos l cos ps sin th)
#         p_y = 0;  p_z = 2 w^EI w (g_x ; g_y)   [stacked pair read as the sum g_x + g_y]
#         g_x = cos t sin l sin th + cos t cos l cos ps cos th - cos ph cos l sin t sin ps
#         g_y = -cos th sin ph sin t sin l + cos l cos ps sin ph sin t sin th
_g_x = ct * sl * sth + ct * cl * cps * cth - cph * cl * st * sps
_g_y = -cth * sph * st * sl + cl * cps * sph * st * sth
_p_x = -2 * Omega * w * (cl * sph * sps - cph * cth * sl + cph * cl * cps * sth)
PRINTED["22"] = sp.Matrix([_p_x, 0, 2 * Omega * w * (_g_x + _g_y)])

# eq. 23 (displayed): a_x = -l w^2 - g (sin t cos th sin ph - cos t sin th)
# the block printed beside eq. 24 carries the full right-hand sides:
#   a_x = -l w^2 - 2 w^El l w (cos l sin ph sin ps - cos ph cos th sin l + cos ph cos l cos ps sin th)
#         - g (sin t cos th sin ph - cos t sin th)          [its first line is eq. 23's]
#   a_y = + l w_dot - g (sin t sin th + cos t cos th sin ph)
#   a_z = -g cos th cos ph + 2 w^El l w (g_x ; g_y)
PRINTED["23"] = -l * w**2 - g * (st * cth * sph - ct * sth)
PRINTED["23.x"] = (
    -l * w**2
    - 2 * Omega * l * w * (cl * sph * sps - cph * cth * sl + cph * cl * cps * sth)
    - g * (st * cth * sph - ct * sth)
)
PRINTED["23.y"] = l * w_dot - g * (st * sth + ct * cth * sph)
PRINTED["23.z"] = -g * cth * cph + 2 * Omega * l * w * (_g_x + _g_y)

# eq. 24: a_y|90 = l w_dot - g sin th, a_y|270 = l w_dot + g sin th -> sin th = (a_y|270 - a_y|90)/(2g)
#         a_y|0 = l w_dot - g cos th sin ph, a_y|180 = l w_dot + g cos th sin ph
#         -> sin ph = (a_y|180 - a_y|0) / (2 g cos th)
PRINTED["24.a"] = sp.Matrix(
    [l * w_dot - g * sth, l * w_dot + g * sth, l * w_dot - g * cth * sph, l * w_dot + g * cth * sph]
)
PRINTED["24.b"] = (ay_270 - ay_90) / (2 * g)
PRINTED["24.c"] = (ay_180 - ay_0) / (2 * g * cth)

# eq. 25: [cos t_i, sin t_i] [cos th sin ph; sin th] = (1/g) [l w_dot(t_i) - a_yi]
PRINTED["25"] = (ct * cth * sph + st * sth) - (l * w_dot - a_yi) / g
# eq. 26: the same with w_dot ~ 0: = (-1/g) [a_yi]
PRINTED["26"] = (ct * cth * sph + st * sth) - (-1 / g) * a_yi

# eq. 27: a_x = S (g cos t sin th - g sin t cos th sin ph) + b
PRINTED["27"] = S * (g * ct * sth - g * st * cth * sph) + b
# eq. 28: a_x|0 = S g sin th + b, a_x|180 = -S g sin th + b -> b = (a_x|0 + a_x|180)/2
PRINTED["28.a"] = sp.Matrix([S * g * sth + b, -S * g * sth + b])
PRINTED["28.b"] = (ax_0 + ax_180) / 2
# eq. 29: a_1 = a_x|0 - b = S g sin th ; a_2 = a_x|90 - b = -S g cos th sin ph
PRINTED["29"] = sp.Matrix([S * g * sth, -S * g * cth * sph])
# eq. 30: a_z = -S g cos th cos ph + b   (the x sensor turned by -pi/2 about y)
PRINTED["30"] = -S * g * cth * cph + b
# eq. 31: a_3 = a_z - b = -S g cos th cos ph
PRINTED["31"] = -S * g * cth * cph
# eq. 32: a1^2 + a2^2 + a3^2 = S^2 g^2 (sin^2 th + cos^2 th sin^2 ph + cos^2 th cos^2 ph) = S^2 g^2
PRINTED["32"] = sp.Matrix([S**2 * g**2 * (sth**2 + cth**2 * sph**2 + cth**2 * cph**2), S**2 * g**2])
# eq. 33: S = -/+ sqrt((a1^2 + a2^2 + a3^2) / g^2), sf = S - 1
PRINTED["33"] = sp.Matrix(
    [-sqrt((a1**2 + a2**2 + a3**2) / g**2), sqrt((a1**2 + a2**2 + a3**2) / g**2)]
)
# eq. 34: S^2 = (1 + sf)^2 = (a1^2+a2^2+a3^2)/g^2 = alpha -> sf^2 + 2 sf + 1 - alpha = 0;
#         sf^2 ~ 0 -> 2 sf + 1 - alpha = 0 -> sf = (alpha - 1)/2
_alpha = (a1**2 + a2**2 + a3**2) / g**2
PRINTED["34"] = (_alpha - 1) / 2

# eq. 35: [T]^BT [0, 0, w] = [0, 0, w]
PRINTED["35"] = sp.Matrix([0, 0, w])
# eq. 36: [T]^BT [T]^TN [w^EI]^N = w^EI [a_x, a_y, a_z]
#   a_x = cos t [cos ps cos th cos l + sin th sin l] + sin t [(cos ps sin th sin ph - sin ps cos ph) cos l
#         - cos th sin ph sin l];  a_y = (a_y1 ; a_y2);  a_y1 = -sin t [cos ps cos th cos l + sin th sin l]
#   a_y2 = + cos t [(cos ps sin th sin ph - sin ps cos ph) cos l - cos th sin ph sin l]
#   a_z = (cos ps sin th cos ph + sin ps sin ph) cos l - cos th cos ph sin l
_X = cps * cth * cl + sth * sl
_Y = (cps * sth * sph - sps * cph) * cl - cth * sph * sl
_Z = (cps * sth * cph + sps * sph) * cl - cth * cph * sl
PRINTED["36"] = Omega * sp.Matrix([ct * _X + st * _Y, -st * _X + ct * _Y, _Z])
# eq. 37 (c vector): c_x = a_x, c_y = a_y, c_z = (cos ps sin th cos ph + sin ps sin ph) cos l
#                    - cos th cos ph sin l + w; read as [w~] = w^EI [c_x, c_y, c_z]
PRINTED["37"] = Omega * sp.Matrix([ct * _X + st * _Y, -st * _X + ct * _Y, _Z + w])
# eq. 38: w~_x = w^EI sin t [(...) cos l - cos th sin ph sin l] + w^EI cos t [cos ps cos th cos l + ...]
PRINTED["38"] = Omega * st * _Y + Omega * ct * _X

# eq. 40 (case 1): w~_x|0 = w^EI [..], w~_x|180 = -w^EI [..]; (cos ps =)
#     (w~_x|0 - w~_x|180 - 2 w^EI sin th sin l) / (2 w^EI cos th cos l)   [the "cos psi =" is lost]
PRINTED["40.a"] = sp.Matrix([Omega * _X, -Omega * _X])
PRINTED["40.b"] = (wx_0 - wx_180 - 2 * Omega * sth * sl) / (2 * Omega * cth * cl)
# eq. 40 (case 2): w~_x|90 = w^EI (cos ps sin th sin ph - sin ps cos ph) cos l - w^EI cos th sin ph sin l
#     w~_x|270 = -w^EI (...) cos l + w^EI cos th sin ph sin l ->
#     cos ps sin th sin ph - sin ps cos ph = (w~_x|90 - w~_x|270 + 2 w^EI) / (2 w^EI cos l)
PRINTED["40.c"] = sp.Matrix([Omega * _Y, -Omega * _Y])
PRINTED["40.d"] = (wx_90 - wx_270 + 2 * Omega) / (2 * Omega * cl)
# eq. 41: a sin ps + b cos ps = c -> ps = "tau" tan^-1((a -/+ sqrt(a^2 + b^2 - c^2)) / (b + c))
PRINTED["41"] = sp.Matrix(
    [
        tau * atan((ca - sqrt(ca**2 + cb**2 - cc**2)) / (cb + cc)),
        tau * atan((ca + sqrt(ca**2 + cb**2 - cc**2)) / (cb + cc)),
    ]
)
# eq. 42: A sin ps + B cos ps = C, A = -w^EI cos ph cos l sin t,
#   B = w^EI sin th sin ph cos l sin t + w^EI cos th cos l cos t,
#   C = w~_x - w^EI sin th sin l cos t + w^EI cos th sin ph sin l sin t
w_tau = sp.Symbol("w_tau", real=True)
PRINTED["42"] = sp.Matrix(
    [
        -Omega * cph * cl * st,
        Omega * sth * sph * cl * st + Omega * cth * cl * ct,
        w_tau - Omega * sth * sl * ct + Omega * cth * sph * sl * st,
    ]
)
# eq. 43: ps = 2 tan^-1((A -/+ sqrt(A^2 + B^2 - C^2)) / (B + C))
PRINTED["43"] = sp.Matrix(
    [
        2 * atan((ca - sqrt(ca**2 + cb**2 - cc**2)) / (cb + cc)),
        2 * atan((ca + sqrt(ca**2 + cb**2 - cc**2)) / (cb + cc)),
    ]
)
# eq. 44: A sin t + B cos t = w~_x(t); A = w^EI cos ps sin th sin ph cos l - w^EI sin ps cos ph cos l
#   - w^EI cos th sin ph sin l ; B = w^EI cos ps cos th cos l + w^EI sin th sin l
PRINTED["44"] = sp.Matrix(
    [
        Omega * cps * sth * sph * cl - Omega * sps * cph * cl - Omega * cth * sph * sl,
        Omega * cps * cth * cl + Omega * sth * sl,
    ]
)
# eq. 45: max(A sin t + B cos t) = sqrt(A^2 + B^2)
PRINTED["45"] = sqrt(A**2 + B**2)
# eq. 46: (w~_xmax / w^EI)^2 = (cos^2 ph cos^2 th - 2 cos^2 ph + 1) cos^2 l cos^2 ps
#   + 2 cos ph cos l sin th cos ph cos th sin ps - 2 cos ph cos l sin th cos l sin ph cos ps
#   + 2 cos ph cos l cos th sin ph sin l sin ps + cos^2 ph cos^2 l cos^2 th + cos^2 ph cos^2 l
#   + cos^2 ph cos^2 th + sin^2 l
PRINTED["46"] = (
    (cph**2 * cth**2 - 2 * cph**2 + 1) * cl**2 * cps**2
    + 2 * cph * cl * sth * cph * cth * sps
    - 2 * cph * cl * sth * cl * sph * cps
    + 2 * cph * cl * cth * sph * sl * sps
    + cph**2 * cl**2 * cth**2
    + cph**2 * cl**2
    + cph**2 * cth**2
    + sl**2
)
# eq. 47: A cos^2 ps + B cos ps + C cos ps sin ps + D sin ps + E = 0
#   A = (cos^2 ph cos^2 th - 2 cos^2 ph + 1) cos^2 l ; B = 2 cos^2 ph cos l sin th cos th sin l
#   C = -2 cos^2 l cos ph sin th sin ph ; D = 2 cos ph cos l cos th sin ph sin l
#   E = cos^2 ph cos^2 l cos^2 th + cos^2 ph cos^2 th + sin^2 l - (w~_xmax / w^El)   [no square]
PRINTED["47.A"] = (cph**2 * cth**2 - 2 * cph**2 + 1) * cl**2
PRINTED["47.B"] = 2 * cph**2 * cl * sth * cth * sl
PRINTED["47.C"] = -2 * cl**2 * cph * sth * sph
PRINTED["47.D"] = 2 * cph * cl * cth * sph * sl
PRINTED["47.E"] = cph**2 * cl**2 * cth**2 + cph**2 * cth**2 + sl**2 - (wx_max / Omega)
# eq. 48: A cos^2 ps + B cos ps + E = -C cos ps sin ps - D sin ps
PRINTED["48"] = (A * c_psi**2 + B * c_psi + E) - (-C * c_psi * s_psi - D * s_psi)
# eq. 49: (A cos^2 ps + B cos ps + E)^2 = (-C cos ps sin ps - D sin ps)^2
PRINTED["49"] = (A * c_psi**2 + B * c_psi + E) ** 2 - (-C * c_psi * s_psi - D * s_psi) ** 2
# eq. 50: F = A^2 + C^2, G = 2AB + 2CD, H = B^2 + 2AE - C^2 + D^2, I = 2BE - 2CD, J = E^2 - D^2
PRINTED["50"] = sp.Matrix(
    [
        A**2 + C**2,
        2 * A * B + 2 * C * D,
        B**2 + 2 * A * E - C**2 + D**2,
        2 * B * E - 2 * C * D,
        E**2 - D**2,
    ]
)
# eq. 51: df/dt = 0 -> A cos t - B sin t = 0 -> tan t = A / B
PRINTED["51"] = sp.Matrix([A * ct - B * st, A / B])
# eq. 52: tan^-1(A/B) = t* = tan^-1( (cos ps sin th sin ph cos l) / (sin ps cos ph cos l - cos th sin ph sin l) )
#         / cos ps cos th cos l + sin th sin l       [tan of both sides transcribed]
PRINTED["52"] = (cps * sth * sph * cl / (sps * cph * cl - cth * sph * sl)) / (
    cps * cth * cl + sth * sl
)

# eq. 53: w~_x = S (d_x ; d_y) + b, d_x = w^El sin t [(...) cos l - cos th sin ph sin l],
#         d_y = + w^El cos t [cos ps cos th cos l + sin th sin l]
PRINTED["53"] = S * (Omega * st * _Y + Omega * ct * _X) + b
# eq. 54: w~_x|0 = S w^EI [X] + b ; w~_x|90 = S w^EI [Y] + b ; w~_x|180 = -S w^EI [X] + b
PRINTED["54"] = sp.Matrix([S * Omega * _X + b, S * Omega * _Y + b, -S * Omega * _X + b])
# eq. 55: b = (w~_x|0 + w~_x|180) / 2
PRINTED["55"] = (wx_0 + wx_180) / 2
# eq. 56: omega_1 = (w~_x|0 - b)/w^EI = S [X] ; omega_2 = (w~_x|90 - b)/w^EI = S [Y]
PRINTED["56.a"] = sp.Matrix([(wx_0 - b) / Omega, (wx_90 - b) / Omega])
PRINTED["56.b"] = sp.Matrix([S * _X, S * _Y])
# eq. 57: omega_1/omega_2 = (cos ps cos th cos l)/(sin th sin l)
#         + (cos ps sin th sin ph - sin ps cos ph cos l)/(-cos th sin ph sin l)
PRINTED["57"] = (cps * cth * cl) / (sth * sl) + (cps * sth * sph - sps * cph * cl) / (
    -cth * sph * sl
)
# eq. 58: A sin ps + B cos ps = C, A = -omega_1 cos ph / "2", B = omega_1 (sin th sin ph - cos th) / "2",
#         C = sin th tan l + omega_1 cos th sin ph tan l / "2"   ["2" read as omega_2, its subscript]
PRINTED["58"] = sp.Matrix(
    [-om1 * cph / om2, om1 * (sth * sph - cth) / om2, sth * tl + om1 * cth * sph * tl / om2]
)
# eq. 59: ps = 2 tan^-1((A -/+ sqrt(A^2 + B^2) - C) / (B + C))
PRINTED["59"] = sp.Matrix(
    [
        2 * atan((ca - sqrt(ca**2 + cb**2) - cc) / (cb + cc)),
        2 * atan((ca + sqrt(ca**2 + cb**2) - cc) / (cb + cc)),
    ]
)
# eq. 60: S = omega_1 / (cos ps cos th cos l + sin th sin l)
PRINTED["60"] = om1 / (cps * cth * cl + sth * sl)
# eq. 61: omega_3 = omega_1/(S cos l) - sin th tan l = cos ps cos th
#         omega_4 = omega_2/(S cos l) + cos th sin ph tan l = cos ps sin th sin ph - sin ps cos ph
PRINTED["61"] = sp.Matrix(
    [
        om1 / (S * cl) - sth * tl - cps * cth,
        om2 / (S * cl) + cth * sph * tl - (cps * sth * sph - sps * cph),
    ]
)
# eq. 62: cos ps = omega_3 / cos th ; sin ps = omega_3 tan th tan ph - omega_4 / cos ph
om4 = sp.Symbol("omega_4", real=True)
PRINTED["62"] = sp.Matrix([om3 / cth, om3 * tth * tph - om4 / cph])
# eq. 63: ((omega_1/(S cos l) - sin th tan l) tan th tan ph - (omega_2/(S cos l) + cos th sin ph tan l)/cos ph)^2
#         + ((omega_1/(S cos l) - sin th tan l) / cos th)^2 = 1
PRINTED["63"] = (
    ((om1 / (S * cl) - sth * tl) * tth * tph - (om2 / (S * cl) + cth * sph * tl) / cph) ** 2
    + ((om1 / (S * cl) - sth * tl) / cth) ** 2
    - 1
)
# eq. 64: A = B/(S^2 cos^2 l) + C/(S cos l)
#   A = 1 - tan^2 l tan^2 th - cos^2 th tan^2 l tan^2 ph - tan^2 ph tan^2 l sin^2 th tan^2 th
#       - 2 cos th tan ph tan^2 l sin th tan th tan th
#   B = omega_2^2/cos^2 ph + omega_1^2/cos^2 th + omega_1^2 tan^2 ph tan^2 th - 2 omega_1 omega_2 tan ph tan th / cos ph
#   C = 2 omega_2 tan ph tan l sin th tan th / cos ph - 2 omega_1 cos th tan^2 ph tan l tan th
#       - [2 omega_1 tan l tan th over cos th, OCR-stacked] - 2 omega_1 tan^2 ph tan l sin th tan^2 th
#       + 2 omega_2 cos th tan ph tan l / cos ph
PRINTED["64.A"] = (
    1
    - tl**2 * tth**2
    - cth**2 * tl**2 * tph**2
    - tph**2 * tl**2 * sth**2 * tth**2
    - 2 * cth * tph * tl**2 * sth * tth * tth
)
PRINTED["64.B"] = (
    om2**2 / cph**2 + om1**2 / cth**2 + om1**2 * tph**2 * tth**2 - 2 * om1 * om2 * tph * tth / cph
)
PRINTED["64.C"] = (
    2 * om2 * tph * tl * sth * tth / cph
    - 2 * om1 * cth * tph**2 * tl * tth
    - 2 * om1 * tl * tth / cth
    - 2 * om1 * tph**2 * tl * sth * tth**2
    + 2 * om2 * cth * tph * tl / cph
)
# eq. 65: A cos^2 l S^2 - C cos l S - B = 0 ->
#   S = (C cos l -/+ sqrt(C^2 cos^2 l + 4AB cos l)) / (2A cos^2 l) = (C -/+ sqrt(C^2 + 4AB)) / (2A cos l)
PRINTED["65.a"] = A * cl**2 * S**2 - C * cl * S - B
PRINTED["65.b"] = sp.Matrix(
    [
        (C * cl - sqrt(C**2 * cl**2 + 4 * A * B * cl)) / (2 * A * cl**2),
        (C * cl + sqrt(C**2 * cl**2 + 4 * A * B * cl)) / (2 * A * cl**2),
    ]
)
PRINTED["65.c"] = sp.Matrix(
    [(C - sqrt(C**2 + 4 * A * B)) / (2 * A * cl), (C + sqrt(C**2 + 4 * A * B)) / (2 * A * cl)]
)
# eq. 66: S^2 = (1 + sf)^2 ~ 1 + 2 sf -> sf = (-A cos^2 l + B + C cos l) / (2 A cos^2 l - C cos l)
PRINTED["66"] = (-A * cl**2 + B + C * cl) / (2 * A * cl**2 - C * cl)
# eq. 67: ps = cos^-1( omega_1 / (S cos th cos l - tan th tan l) )   [cos of both sides transcribed]
PRINTED["67"] = om1 / (S * cth * cl - tth * tl)
# eq. 68: w~_z = S w^EI [(cos ps sin th cos ph + sin ps sin ph) cos l - cos th cos ph sin l + w] + b
PRINTED["68"] = S * Omega * (_Z + w) + b
# eq. 69: omega_3 = (w~_z - b)/w^EI = S [(...) cos l - cos th cos ph sin l + w]
PRINTED["69"] = S * (_Z + w)
# eq. 70: S^2 = omega_1^2 + omega_2^2 + omega_3^2 -> S = sqrt(omega_1^2 + omega_2^2 + omega_3^2)
PRINTED["70"] = sqrt(om1**2 + om2**2 + om3**2)
# eq. 71: S^2 = (1 + sf)^2 = omega_1^2 + omega_2^2 + omega_3^2 = beta -> sf^2 + 2sf + 1 - beta = 0
#         sf^2 ~ 0 -> sf = (beta - 1)/2
PRINTED["71"] = (om1**2 + om2**2 + om3**2 - 1) / 2

__all__ = [
    "PRINTED",
    "A",
    "B",
    "C",
    "D",
    "E",
    "F",
    "G",
    "H",
    "I",
    "J",
    "c_psi",
    "s_psi",
    "tau_i",
    "a_yi",
    "om4",
    "w_tau",
]

# keep linters quiet about names used only in comments/transcriptions
_ = (ax_0, ax_90, ax_180, ax_270, ay_0, ay_90, ay_180, ay_270, az, a_xi, sf, wz, F, G, H, I, J, psi)
