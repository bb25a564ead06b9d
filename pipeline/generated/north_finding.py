"""Numeric code of the north-finding paper, generated from derivations/north_finding.

Regenerate: python -m derivations.north_finding.generate
Conventions: angles in rad, rates in rad/s, accelerations in m/s^2; every function
broadcasts its arguments (vectorised over table positions and Monte Carlo trials).

GENERATED FILE: do not edit; regenerate with the command above.
"""
# ruff: noqa

import numpy as np


#: the types of a scalar output (a function called with scalar arguments)
_SCALARS = (float, int, np.float64)


def _broadcast(*outs):
    """Broadcast the outputs of a vector function to one common shape (fresh arrays)."""
    if all(type(o) in _SCALARS for o in outs):  # scalars: nothing to broadcast
        return tuple(np.array(o, dtype=float) for o in outs)
    arrays = [np.asarray(o, dtype=float) for o in outs]
    shapes = {a.shape for a in arrays} - {()}
    if len(shapes) == 1:  # one shape besides the scalars' (no call of broadcast_shapes, ~15 us)
        shape = shapes.pop()
    else:
        shape = np.broadcast_shapes(*[a.shape for a in arrays])
    return tuple(
        np.array(a)
        if a.shape == shape
        else (np.full(shape, a.item()) if a.ndim == 0 else np.broadcast_to(a, shape).copy())
        for a in arrays
    )

__all__ = ['specific_force_b', 'angular_rate_b', 'l1_sin_theta', 'l1_sin_phi', 'l2_design_row', 'ls_sin_phi', 'l3_sin_theta', 'l3_sin_phi', 'l4_design_row', 'l5_bias', 'l5_components', 'l5_scale', 'l5_scale_approx', 'a1c1_cos_psi', 'a1c2_coeffs', 'a2_coeffs', 'sinusoid_roots', 'a3_peak', 'a3_eq47_coeffs', 'a3_quartic_coeffs', 'a3_eq47_residual', 'a3_eq47_residual_dpsi', 'a4_bias', 'a4_omegas', 'a4_coeffs', 'a4_scale', 'a5_coeffs', 'a5_scale_roots', 'a5_scale_approx', 'a5_cos_psi', 'a6_omega3', 'a6_scale', 'a6_scale_approx']


def specific_force_b(g, omega_ie, lat, psi, theta, phi, tau, lever_arm, table_rate, table_accel):
    """Specific force [f]^B of the sensor on the turning table (eqs. 16, 22-24):
    f^B = a_T^B + 2 Omega^{EI} x v_T^B - g^B (centripetal -l w^2, tangential l w_dot,
    Coriolis on x and z). Returns (f_x, f_y, f_z)."""
    _x0 = np.sin(theta)
    _x1 = np.cos(tau)
    _x2 = np.sin(tau)
    _x3 = np.sin(phi)
    _x4 = np.cos(theta)
    _x5 = _x4*g
    _x6 = _x3*_x5
    _x7 = np.sin(lat)
    _x8 = np.cos(phi)
    _x9 = np.cos(lat)
    _x10 = 2*lever_arm*omega_ie*table_rate
    _x11 = _x10*_x9
    _x12 = _x11*np.sin(psi)
    _x13 = np.cos(psi)
    out0 = _x0*_x1*g - _x0*_x11*_x13*_x8 - _x12*_x3 - _x2*_x6 + 2*_x4*_x7*_x8*lever_arm*omega_ie*table_rate - lever_arm*table_rate**2
    out1 = -_x0*_x2*g - _x1*_x6 + lever_arm*table_accel
    out2 = 2*_x0*_x1*_x7*lever_arm*omega_ie*table_rate + 2*_x0*_x13*_x2*_x3*_x9*lever_arm*omega_ie*table_rate + 2*_x1*_x13*_x4*_x9*lever_arm*omega_ie*table_rate - _x10*_x2*_x3*_x4*_x7 - _x12*_x2*_x8 - _x5*_x8
    return _broadcast(out0, out1, out2)


def angular_rate_b(omega_ie, lat, psi, theta, phi, tau, table_rate):
    """Angular rate [omega^{BI}]^B = [0, 0, omega] + [T]^{BT}[T]^{TN}[omega^{EI}]^N (eqs. 35-37)."""
    _x0 = np.sin(theta)
    _x1 = np.cos(tau)
    _x2 = np.sin(tau)
    _x3 = np.sin(phi)
    _x4 = np.cos(theta)
    _x5 = _x3*_x4
    _x6 = omega_ie*np.sin(lat)
    _x7 = np.cos(psi)
    _x8 = _x4*_x7
    _x9 = np.sin(psi)
    _x10 = np.cos(phi)
    _x11 = _x0*_x7
    _x12 = -_x10*_x9 + _x11*_x3
    _x13 = omega_ie*np.cos(lat)
    out0 = _x13*(_x1*_x8 + _x12*_x2) - _x6*(-_x0*_x1 + _x2*_x5)
    out1 = _x13*(_x1*_x12 - _x2*_x8) - _x6*(_x0*_x2 + _x1*_x5)
    out2 = -_x10*_x4*_x6 + _x13*(_x10*_x11 + _x3*_x9) + table_rate
    return _broadcast(out0, out1, out2)


def l1_sin_theta(ax_0, ax_180, g):
    """Levelling method 1, eq. 19: sin(theta)."""
    out0 = (1/2)*(ax_0 - ax_180)/g
    return out0


def l1_sin_phi(ax_90, ax_270, g, theta):
    """Levelling method 1, eq. 19: sin(phi)."""
    out0 = (1/2)*(ax_270 - ax_90)/(g*np.cos(theta))
    return out0


def l2_design_row(tau):
    """Levelling method 2, eqs. 20-21: row of H for X = [sin(theta), cos(theta) sin(phi)],
    Y = a_x / g."""
    out0 = np.cos(tau)
    out1 = -np.sin(tau)
    return _broadcast(out0, out1)


def ls_sin_phi(cth_sphi, theta):
    """Levelling methods 2 and 4, eqs. 20-21 and 25-26: sin(phi) from the least-squares
    unknown cos(theta) sin(phi) at the estimated theta."""
    out0 = cth_sphi/np.cos(theta)
    return out0


def l3_sin_theta(ay_90, ay_270, g):
    """Levelling method 3, eq. 24: sin(theta)."""
    out0 = (1/2)*(ay_270 - ay_90)/g
    return out0


def l3_sin_phi(ay_0, ay_180, g, theta):
    """Levelling method 3, eq. 24: sin(phi)."""
    out0 = (1/2)*(-ay_0 + ay_180)/(g*np.cos(theta))
    return out0


def l4_design_row(tau):
    """Levelling method 4, eqs. 25-26: row of H for X = [cos(theta) sin(phi), sin(theta)],
    Y = -a_y / g."""
    out0 = np.cos(tau)
    out1 = np.sin(tau)
    return _broadcast(out0, out1)


def l5_bias(ax_0, ax_180):
    """Levelling method 5, eq. 28: bias."""
    out0 = (1/2)*ax_0 + (1/2)*ax_180
    return out0


def l5_components(ax_0, ax_90, ax_180, az):
    """Levelling method 5, eqs. 29, 31: bias-free components a1, a2, a3."""
    _x0 = (1/2)*ax_0
    _x1 = (1/2)*ax_180
    _x2 = _x0 + _x1
    out0 = _x0 - _x1
    out1 = -_x2 + ax_90
    out2 = -_x2 + az
    return _broadcast(out0, out1, out2)


def l5_scale(a1, a2, a3, g):
    """Levelling method 5, eqs. 32-33: S = sqrt(a1^2 + a2^2 + a3^2) / g (S > 0)."""
    out0 = np.sqrt(a1**2 + a2**2 + a3**2)/g
    return out0


def l5_scale_approx(a1, a2, a3, g):
    """Levelling method 5, eq. 34: S ~ 1 + (alpha - 1)/2, alpha = (a1^2+a2^2+a3^2)/g^2."""
    _x0 = g**2
    out0 = 1 + (1/2)*(-_x0 + a1**2 + a2**2 + a3**2)/_x0
    return out0


def a1c1_cos_psi(wx_0, wx_180, omega_ie, lat, theta):
    """Azimuth method 1 case 1, eq. 40: cos(psi) from tau = 0, 180 deg."""
    out0 = (1/2)*(-2*omega_ie*np.sin(lat)*np.sin(theta) + wx_0 - wx_180)/(omega_ie*np.cos(lat)*np.cos(theta))
    return out0


def a1c2_coeffs(wx_90, wx_270, omega_ie, lat, theta, phi):
    """Azimuth method 1 case 2, eqs. 40-41: a, b, c of a sin(psi) + b cos(psi) = c."""
    _x0 = np.sin(phi)
    out0 = -np.cos(phi)
    out1 = _x0*np.sin(theta)
    out2 = (1/2)*(2*_x0*omega_ie*np.sin(lat)*np.cos(theta) - wx_270 + wx_90)/(omega_ie*np.cos(lat))
    return _broadcast(out0, out1, out2)


def a2_coeffs(w_tau, tau, omega_ie, lat, theta, phi):
    """Azimuth method 2, eq. 42: A, B, C of A sin(psi) + B cos(psi) = C."""
    _x0 = np.sin(tau)
    _x1 = omega_ie*np.cos(lat)
    _x2 = np.cos(tau)
    _x3 = np.cos(theta)
    _x4 = np.sin(theta)
    _x5 = _x0*np.sin(phi)
    _x6 = omega_ie*np.sin(lat)
    out0 = -_x0*_x1*np.cos(phi)
    out1 = _x1*(_x2*_x3 + _x4*_x5)
    out2 = -_x2*_x4*_x6 + _x3*_x5*_x6 + w_tau
    return _broadcast(out0, out1, out2)


def sinusoid_roots(a, b, c):
    """Both roots psi of a sin(psi) + b cos(psi) = c (eqs. 41, 43, 59 in phase form:
    psi = atan2(a, b) -/+ acos(c / sqrt(a^2 + b^2))), the ratio clipped to [-1, 1]:
    the double root where |c| >= sqrt(a^2 + b^2) (callers count |c| > it as trouble)."""
    _x0 = np.arctan2(a, b)
    _x1 = np.arccos(np.maximum(-1, np.minimum(1, c/np.sqrt(a**2 + b**2))))
    out0 = _x0 - _x1
    out1 = _x0 + _x1
    return _broadcast(out0, out1)


def a3_peak(omega_ie, lat, psi, theta, phi):
    """Azimuth method 3, eqs. 45, 51-52: location tau* and value sqrt(A^2 + B^2) of the
    largest ideal gyro reading over tau."""
    _x0 = np.sin(lat)
    _x1 = np.sin(phi)
    _x2 = np.cos(theta)
    _x3 = np.cos(lat)
    _x4 = np.sin(theta)
    _x5 = np.cos(psi)
    _x6 = -_x0*_x1*_x2 + _x1*_x3*_x4*_x5 - _x3*np.sin(psi)*np.cos(phi)
    _x7 = _x0*_x4 + _x2*_x3*_x5
    _x8 = omega_ie**2
    out0 = np.arctan2(_x6*omega_ie, _x7*omega_ie)
    out1 = np.sqrt(_x6**2*_x8 + _x7**2*_x8)
    return _broadcast(out0, out1)


def a3_eq47_coeffs(wx_max, omega_ie, lat, theta, phi):
    """Azimuth method 3, eqs. 46-47: A..E of A c^2 + B c + C c s + D s + E = 0,
    c = cos(psi), s = sin(psi)."""
    _x0 = np.cos(lat)
    _x1 = _x0**2
    _x2 = np.cos(phi)
    _x3 = _x2**2
    _x4 = 2*_x3
    _x5 = np.cos(theta)
    _x6 = _x5**2
    _x7 = np.sin(theta)
    _x8 = np.sin(lat)
    _x9 = _x0*_x5*_x8
    _x10 = np.sin(phi)
    _x11 = 2*_x10*_x2
    _x12 = omega_ie**2
    _x13 = _x12*_x8**2
    out0 = _x1*(_x3*_x6 - _x4 + 1)
    out1 = _x4*_x7*_x9
    out2 = -_x1*_x11*_x7
    out3 = _x11*_x9
    out4 = (_x1*_x12*_x3 + _x10**2*_x13*_x6 + _x13*_x7**2 - wx_max**2)/_x12
    return _broadcast(out0, out1, out2, out3, out4)


def a3_quartic_coeffs(A, B, C, D, E):
    """Azimuth method 3, eqs. 48-50: F..J of the quartic F c^4 + G c^3 + H c^2 + I c + J = 0."""
    _x0 = C**2
    _x1 = 2*A
    _x2 = 2*C*D
    _x3 = D**2
    out0 = A**2 + _x0
    out1 = B*_x1 + _x2
    out2 = B**2 + E*_x1 - _x0 + _x3
    out3 = 2*B*E - _x2
    out4 = E**2 - _x3
    return _broadcast(out0, out1, out2, out3, out4)


def a3_eq47_residual(c_psi, s_psi, A, B, C, D, E):
    """Azimuth method 3, eq. 47 before squaring: its residual, which rejects the roots
    that squaring (eq. 49) introduces."""
    out0 = A*c_psi**2 + B*c_psi + C*c_psi*s_psi + D*s_psi + E
    return out0


def a3_eq47_residual_dpsi(c_psi, s_psi, A, B, C, D, E):
    """Azimuth method 3, eq. 47: d/dpsi of its residual (sympy diff with c = cos psi,
    s = sin psi), the derivative of the Newton polish."""
    out0 = -2*A*c_psi*s_psi - B*s_psi + C*(c_psi**2 - s_psi**2) + D*c_psi
    return out0


def a4_bias(wx_0, wx_180):
    """Azimuth method 4, eq. 55: gyro bias."""
    out0 = (1/2)*wx_0 + (1/2)*wx_180
    return out0


def a4_omegas(wx_0, wx_90, wx_180, omega_ie):
    """Azimuth method 4, eq. 56: omega_1, omega_2 (bias-free readings over Omega)."""
    _x0 = omega_ie**(-1.0)
    _x1 = (1/2)*wx_0
    _x2 = (1/2)*wx_180
    out0 = _x0*(_x1 - _x2)
    out1 = _x0*(-_x1 - _x2 + wx_90)
    return _broadcast(out0, out1)


def a4_coeffs(om1, om2, lat, theta, phi):
    """Azimuth method 4, eqs. 57-58: A, B, C of A sin(psi) + B cos(psi) = C."""
    _x0 = om2**(-1.0)
    _x1 = _x0*om1
    _x2 = np.cos(theta)
    _x3 = np.sin(theta)
    _x4 = np.sin(phi)
    out0 = -_x1*np.cos(phi)
    out1 = _x1*_x3*_x4 - _x2
    out2 = _x0*(_x2*_x4*om1 + _x3*om2)*np.tan(lat)
    return _broadcast(out0, out1, out2)


def a4_scale(om1, psi, lat, theta):
    """Azimuth method 4, eq. 60: S = omega_1 / (cos psi cos theta cos lambda + sin theta sin lambda)."""
    out0 = om1/(np.sin(lat)*np.sin(theta) + np.cos(lat)*np.cos(psi)*np.cos(theta))
    return out0


def a5_coeffs(om1, om2, lat, theta, phi):
    """Azimuth method 5, eqs. 61-64: A, B, C of A = B/(S^2 cos^2 lambda) + C/(S cos lambda)."""
    _x0 = np.cos(lat)**2
    _x1 = np.cos(phi)**2
    _x2 = _x1**(-1.0)
    _x3 = np.cos(theta)
    _x4 = _x3**2
    _x5 = _x4**(-1.0)
    _x6 = om1**2
    _x7 = _x2*_x6
    _x8 = np.sin(phi)
    _x9 = om1*np.tan(theta)
    _x10 = 2*_x2
    out0 = _x2*_x5*(_x0 + _x1*_x4 - 1)/_x0
    out1 = -_x10*_x8*_x9*om2 + _x2*om2**2 + _x5*_x7 + _x6 - _x7
    out2 = _x10*(_x8*om2 - _x9)*np.tan(lat)/_x3
    return _broadcast(out0, out1, out2)


def a5_scale_roots(A, B, C, lat):
    """Azimuth method 5, eq. 65: both roots S of A cos^2(lambda) S^2 - C cos(lambda) S - B = 0."""
    _x0 = np.sqrt(4*A*B + C**2)
    _x1 = (1/2)/(A*np.cos(lat))
    out0 = _x1*(C - _x0)
    out1 = _x1*(C + _x0)
    return _broadcast(out0, out1)


def a5_scale_approx(A, B, C, lat):
    """Azimuth method 5, eq. 66: S ~ 1 + sf with sf^2 dropped from eq. 65."""
    _x0 = np.cos(lat)
    _x1 = A*_x0
    out0 = 1 + (B/_x0 + C - _x1)/(-C + 2*_x1)
    return out0


def a5_cos_psi(om1, scale, lat, theta):
    """Azimuth method 5, eqs. 62, 67: cos(psi) = omega_1/(S cos theta cos lambda) - tan theta tan lambda."""
    out0 = om1/(scale*np.cos(lat)*np.cos(theta)) - np.tan(lat)*np.tan(theta)
    return out0


def a6_omega3(wz, wx_0, wx_180, omega_ie):
    """Azimuth method 6, eq. 69: omega_3 = (w_z - b)/Omega with b from eq. 55."""
    out0 = (-1/2*wx_0 - 1/2*wx_180 + wz)/omega_ie
    return out0


def a6_scale(om1, om2, om3):
    """Azimuth method 6, eq. 70: S = sqrt(omega_1^2 + omega_2^2 + omega_3^2)."""
    out0 = np.sqrt(om1**2 + om2**2 + om3**2)
    return out0


def a6_scale_approx(om1, om2, om3):
    """Azimuth method 6, eq. 71: S ~ 1 + (beta - 1)/2, beta = omega_1^2+omega_2^2+omega_3^2."""
    out0 = (1/2)*om1**2 + (1/2)*om2**2 + (1/2)*om3**2 + 1/2
    return out0
