"""Numeric code of the stable-platform gyro-drift paper, generated from derivations/platform_drift.

Regenerate: python -m derivations.platform_drift.generate
Conventions: SI units, angles in rad, rates in rad/s; lat is the latitude phi_i of the mass
navigation frame m_N (north, west, up); every function broadcasts its arguments. Where the
paper prints an equation that differs from the derivation, the derived form is generated.

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


def _shaped(shape, *outs):
    """The broadcast outputs as one array of shape ``broadcast + shape``, filled row by row."""
    if all(type(o) in _SCALARS for o in outs):  # scalars: the array of their values
        return np.array(outs, dtype=float).reshape(shape)
    arrays = _broadcast(*outs)
    return np.stack(arrays, axis=-1).reshape(arrays[0].shape + shape)


__all__ = ['motion_rates', 'gravity_spherical', 'radius_rates_from_velocity', 'tilts_from_position', 'position_from_tilts', 'known_altitude_z', 'known_altitude_z_dot', 'platform_commands_rates', 'oscillation_rates', 'position_rates', 'specific_force_platform', 'specific_force_platform_linear', 'specific_force_stationary', 'tilt_kinematics_stationary', 'k_sh_stationary', 'alpha_deflection', 'alignment_tilts', 'r_alignment', 'alignment_rates', 'nav_initial_tilt_rates', 'error_ch1', 'error_ch3', 'oscillation_period', 'schuler_period', 'table2_accel_bias', 'table2_initial_tilt', 'table2_scale_factor', 'table2_gyro_drift', 'table2_azimuth_drift', 'table2_initial_velocity', 'table2_initial_azimuth', 'strapdown_velocity_rates', 'course_rate', 'velocity_at_rest', 'ground_velocity']

#: Functions the pipeline does not call, each with the reason it is generated.
AUDIT_ONLY = {
    'motion_rates': 'eqs. 9 and 11 in s, checked against eq. 15 by the tests; the simulation integrates the platform DCM and the specific force instead',
    'gravity_spherical': 'gravity model of eq. 15 (inside oscillation_rates), used by the tests',
    'specific_force_platform_linear': 'eq. 17 to first order in the tilts, for the audit; the simulation uses the exact specific_force_platform',
    'specific_force_stationary': 'eq. 18 (eq. 17 at rest), for the audit and the notebook',
    'tilt_kinematics_stationary': 'eq. 19, first-order kinematics behind eqs. 28-36; the simulation integrates the DCM',
    'alignment_tilts': 'eq. 20, first order; platform.initial_state levels the platform exactly (mass or plumb vertical) instead',
    'r_alignment': "eq. 24, the first-order form (in the tilts, alpha, theta_F) of alignment_rates' r, which platform.initial_state calls (equal to first order: tests/platform_drift); navigation commands r = 0 (eq. 25)",
    'nav_initial_tilt_rates': 'eq. 27, initial tilt rates of the analytic solution (eqs. 32, 36), used in the derivation',
    'table2_accel_bias': 'Table 2 closed form, audited and checked against the Schuler loop by the tests; the strapdown curves are simulated (strapdown.py), not evaluated from Table 2',
    'table2_initial_tilt': 'Table 2 closed form, audited and checked against the Schuler loop by the tests; the strapdown curves are simulated (strapdown.py), not evaluated from Table 2',
    'table2_scale_factor': 'Table 2 closed form, audited and checked against the Schuler loop by the tests; the strapdown curves are simulated (strapdown.py), not evaluated from Table 2',
    'table2_gyro_drift': 'Table 2 closed form, audited and checked against the Schuler loop by the tests; the strapdown curves are simulated (strapdown.py), not evaluated from Table 2',
    'table2_initial_velocity': 'Table 2 closed form, audited and checked against the Schuler loop by the tests; the strapdown curves are simulated (strapdown.py), not evaluated from Table 2',
    'table2_initial_azimuth': 'Table 2 closed form, audited and checked against the Schuler loop by the tests; the strapdown curves are simulated (strapdown.py), not evaluated from Table 2',
}


def motion_rates(x, y, z, u, v, w, p, q, r, f1, f2, f3, g1, g2, g3):
    """Navigation equations in the platform frame s (eqs. 9 and 11):
    x_dot = r y - q z + u, ..., u_dot = r v - q w + f1 + g1, ...
    Returns (x_dot, y_dot, z_dot, u_dot, v_dot, w_dot)."""
    out0 = -q*z + r*y + u
    out1 = p*z - r*x + v
    out2 = -p*y + q*x + w
    out3 = f1 + g1 - q*w + r*v
    out4 = f2 + g2 + p*w - r*u
    out5 = f3 + g3 - p*v + q*u
    return _broadcast(out0, out1, out2, out3, out4, out5)


def gravity_spherical(x, y, z, GM):
    """Spherical mass attraction -GM r / |r|^3 in s (the gravity model of eq. 15).
    Returns (g1, g2, g3)."""
    _x0 = GM/(x**2 + y**2 + z**2)**(3/2)
    out0 = -_x0*x
    out1 = -_x0*y
    out2 = -_x0*z
    return _broadcast(out0, out1, out2)


def radius_rates_from_velocity(u, v, z):
    """Eq. 13 (the definitions eq. 15 is written in): omega_x = -v/z, omega_y = u/z.
    Returns (omega_x, omega_y)."""
    out0 = -v/z
    out1 = u/z
    return _broadcast(out0, out1)


def tilts_from_position(x, y, R_G):
    """Eq. 14 (the definitions eq. 15 is written in): phi_x = y/R_G, phi_y = -x/R_G.
    Returns (phi_x, phi_y)."""
    out0 = y/R_G
    out1 = -x/R_G
    return _broadcast(out0, out1)


def position_from_tilts(phi_x, phi_y, R_G):
    """Eq. 14 solved for the position: x = -R_G phi_y, y = R_G phi_x. Returns (x, y)."""
    out0 = -R_G*phi_y
    out1 = R_G*phi_x
    return _broadcast(out0, out1)


def known_altitude_z(x, y, R_G):
    """Vertical channel, known altitude: z = sqrt(R_G^2 - x^2 - y^2) from |^s r_EB| = R_G."""
    out0 = np.sqrt(R_G**2 - x**2 - y**2)
    return out0


def known_altitude_z_dot(x, y, z, x_dot, y_dot):
    """Vertical channel, known constant altitude: z_dot = -(x x_dot + y y_dot)/z."""
    out0 = (-x*x_dot - y*y_dot)/z
    return out0


def platform_commands_rates(f1, f2, z):
    """Position-independent torquing commands (eq. 12): p_dot = -f2/z, q_dot = f1/z.
    Derived as the rates that keep a level platform level. Returns (p_dot, q_dot)."""
    _x0 = z**(-1.0)
    out0 = -_x0*f2
    out1 = _x0*f1
    return _broadcast(out0, out1)


def oscillation_rates(omega_x, omega_y, phi_x, phi_y, p, q, r, p_dot, q_dot, z, z_dot, R_G, GM):
    """Platform oscillation ODEs (eq. 15, spherical gravity), with omega_y = u/z,
    omega_x = -v/z, phi_y = -x/R_G, phi_x = y/R_G (eqs. 13-14).
    Returns (omega_x_dot, omega_y_dot, phi_x_dot, phi_y_dot)."""
    _x0 = z**(-1.0)
    _x1 = _x0*z_dot
    _x2 = omega_y*z
    _x3 = R_G*phi_x
    _x4 = R_G*phi_y
    _x5 = _x3*p + _x4*q + z_dot
    _x6 = R_G**2
    _x7 = GM/(_x6*phi_x**2 + _x6*phi_y**2 + z**2)**(3/2)
    _x8 = omega_x*z
    _x9 = R_G**(-1.0)
    out0 = -_x0*(-_x2*r - _x3*_x7 + _x5*p - p_dot*z) - _x1*omega_x
    out1 = _x0*(_x4*_x7 - _x5*q - _x8*r + q_dot*z) - _x1*omega_y
    out2 = _x9*(_x4*r - _x8 + p*z)
    out3 = -_x9*(_x2 + _x3*r - q*z)
    return _broadcast(out0, out1, out2, out3)


def position_rates(p_m, q_m, r_m, lat, psi, omega_e):
    """Explicit form of the position equation (eq. 16, derived; the printed matrix form has
    C psi for S psi in -^{m_i} omega_ie): (lambda_dot + omega_e) cos(lat) =
    cos psi p_m - sin psi q_m, lat_dot = sin psi p_m + cos psi q_m,
    psi_dot = r_m - (lambda_dot + omega_e) sin(lat). The algorithm uses p_m = omega_x,
    q_m = omega_y, r_m = 0. Singular at the poles. Returns (lon_dot, lat_dot, psi_dot)."""
    _x0 = np.cos(lat)
    _x1 = np.sin(psi)
    _x2 = _x1*q_m
    _x3 = np.cos(psi)
    _x4 = np.tan(lat)
    out0 = (-_x0*omega_e - _x2 + _x3*p_m)/_x0
    out1 = _x1*p_m + _x3*q_m
    out2 = _x2*_x4 - _x3*_x4*p_m + r_m
    return _broadcast(out0, out1, out2)


def specific_force_platform(R, g, omega_e, lat, lat_dot, lat_ddot, lon_dot, lon_ddot, psi, phi_x, phi_y):
    """Specific force on the platform of a vehicle moving on a sphere of radius R with
    Earth rate (exact in the tilts; eq. 17 is its first-order form). g is the mass
    gravity g_i. Returns (f1, f2, f3)."""
    _x0 = np.sin(psi)
    _x1 = np.cos(phi_y)
    _x2 = np.cos(lat)
    _x3 = R*_x2
    _x4 = 2*lon_dot
    _x5 = np.sin(lat)
    _x6 = R*_x5*lat_dot
    _x7 = -_x3*lon_ddot + _x4*_x6 + 2*_x6*omega_e
    _x8 = np.cos(psi)
    _x9 = lon_dot**2
    _x10 = _x3*_x5
    _x11 = omega_e**2
    _x12 = _x4*omega_e
    _x13 = R*lat_ddot + _x10*_x11 + _x10*_x12 + _x10*_x9
    _x14 = np.sin(phi_y)
    _x15 = R*_x2**2
    _x16 = -R*lat_dot**2 - _x11*_x15 - _x12*_x15 - _x15*_x9 + g
    _x17 = np.cos(phi_x)
    _x18 = _x17*_x8
    _x19 = np.sin(phi_x)
    _x20 = _x0*_x19
    _x21 = _x1*_x16
    _x22 = _x19*_x8
    out0 = _x0*_x1*_x7 + _x1*_x13*_x8 - _x14*_x16
    out1 = _x13*(-_x0*_x17 + _x14*_x22) + _x19*_x21 + _x7*(_x14*_x20 + _x18)
    out2 = _x13*(_x14*_x18 + _x20) + _x17*_x21 + _x7*(_x0*_x14*_x17 - _x22)
    return _broadcast(out0, out1, out2)


def specific_force_platform_linear(R, g, omega_e, lat, lat_dot, lat_ddot, lon_dot, lon_ddot, psi, phi_x, phi_y):
    """Eq. 17 derived (first order in the tilts; the printed Coriolis term squares
    (lambda_dot + omega_e), which is a typo). Returns (f1, f2)."""
    _x0 = np.cos(psi)
    _x1 = R*lat_ddot
    _x2 = R*lat_dot**2
    _x3 = np.sin(psi)
    _x4 = np.cos(lat)
    _x5 = R*_x4
    _x6 = _x5*lon_ddot
    _x7 = 2*lon_dot
    _x8 = np.sin(lat)
    _x9 = R*_x3*_x8*lat_dot
    _x10 = lon_dot**2
    _x11 = R*_x4**2
    _x12 = _x11*phi_y
    _x13 = omega_e**2
    _x14 = _x7*omega_e
    _x15 = _x5*_x8
    _x16 = _x0*_x15
    _x17 = _x11*phi_x
    _x18 = _x15*_x3
    out0 = _x0*_x1 + _x10*_x12 + _x10*_x16 + _x12*_x13 + _x12*_x14 + _x13*_x16 + _x14*_x16 + _x2*phi_y - _x3*_x6 + _x7*_x9 + 2*_x9*omega_e - g*phi_y
    out1 = 2*R*_x0*_x8*lat_dot*lon_dot + 2*R*_x0*_x8*lat_dot*omega_e - _x0*_x6 - _x1*_x3 - _x10*_x17 - _x10*_x18 - _x13*_x17 - _x13*_x18 - _x14*_x17 - _x14*_x18 - _x2*phi_x + g*phi_x
    return _broadcast(out0, out1)


def specific_force_stationary(R, g, omega_e, lat, psi, phi_x, phi_y):
    """Eq. 18: the specific force of eq. 17 for a vehicle at rest. Returns (f1, f2)."""
    _x0 = np.cos(lat)
    _x1 = R*omega_e**2
    _x2 = _x0**2*_x1
    _x3 = _x0*_x1*np.sin(lat)
    out0 = _x2*phi_y + _x3*np.cos(psi) - g*phi_y
    out1 = -_x2*phi_x - _x3*np.sin(psi) + g*phi_x
    return _broadcast(out0, out1)


def tilt_kinematics_stationary(p, q, r, phi_x, phi_y, psi, lat, omega_e):
    """Eq. 19: tilt and azimuth kinematics of the platform at rest, first order in the tilts.
    Returns (phi_x_dot, phi_y_dot, psi_dot)."""
    _x0 = omega_e*np.cos(lat)
    _x1 = _x0*np.cos(psi)
    out0 = -_x1 + p + phi_y*r
    out1 = _x0*np.sin(psi) - phi_x*r + q
    out2 = -_x1*phi_y - omega_e*np.sin(lat) + phi_x*q + r
    return _broadcast(out0, out1, out2)


def k_sh_stationary(g, R, omega_e, lat):
    """Schuler-like constant k_sh of eq. 28 at rest: g/R - omega_e^2 cos^2(lat)
    (the vertical specific force over R)."""
    out0 = -omega_e**2*np.cos(lat)**2 + g/R
    return out0


def alpha_deflection(R, omega_e, lat, g):
    """Plumb-line deflection alpha of eq. 21 (eq. 1's alpha_T to first order):
    R omega_e^2 sin(lat) cos(lat) / g."""
    out0 = R*omega_e**2*np.sin(lat)*np.cos(lat)/g
    return out0


def alignment_tilts(R, omega_e, lat, psi, g, b_a1, b_a2):
    """Tilts at the end of alignment (eq. 20, derived: the printed form swaps sin/cos psi).
    Returns (phi_x, phi_y)."""
    _x0 = np.cos(lat)
    _x1 = R*omega_e**2
    _x2 = _x0*_x1*np.sin(lat)
    _x3 = (_x0**2*_x1 - g)**(-1.0)
    out0 = -_x3*(_x2*np.sin(psi) + b_a2)
    out1 = -_x3*(_x2*np.cos(psi) - b_a1)
    return _broadcast(out0, out1)


def r_alignment(omega_e, lat, psi, alpha, theta_F1, theta_F2):
    """Platform rate about axis 3 at the end of alignment, r(0-) (eq. 24, derived: includes
    + alpha omega_e cos(lat), which the paper drops)."""
    _x0 = np.sin(psi)
    _x1 = omega_e*np.cos(lat)
    _x2 = np.cos(psi)
    _x3 = _x1*alpha
    out0 = _x0**2*_x3 + _x0*_x1*theta_F2 - _x1*_x2*theta_F1 + _x2**2*_x3 + omega_e*np.sin(lat)
    return out0


def alignment_rates(omega_e, lat, psi, phi_x, phi_y):
    """Exact platform rates at the end of alignment, (p(0-), q(0-), r(0-)): the rates that
    hold a platform with tilts phi_x, phi_y and azimuth psi still at rest (eq. 19
    exact, phi_dot = psi_dot = 0; eq. 24 is r(0-) to first order). phi_x, phi_y, psi
    are the angles of eq. 2. Returns (p, q, r)."""
    _x0 = np.sin(lat)
    _x1 = np.sin(phi_y)
    _x2 = np.cos(lat)
    _x3 = np.cos(phi_y)
    _x4 = np.cos(psi)
    _x5 = np.sin(phi_x)
    _x6 = _x0*_x3
    _x7 = np.cos(phi_x)
    _x8 = _x2*np.sin(psi)
    _x9 = _x1*_x2*_x4
    out0 = omega_e*(-_x0*_x1 + _x2*_x3*_x4)
    out1 = omega_e*(_x5*_x6 + _x5*_x9 - _x7*_x8)
    out2 = omega_e*(_x5*_x8 + _x6*_x7 + _x7*_x9)
    return _broadcast(out0, out1, out2)


def nav_initial_tilt_rates(b_g1, b_g2, b_g3, r_0m, phi_x, phi_y):
    """Tilt rates at the start of navigation (eq. 27): (phi_x_dot(0+), phi_y_dot(0+))."""
    out0 = b_g1 + b_g3*phi_y - phi_y*r_0m
    out1 = b_g2 - b_g3*phi_x + phi_x*r_0m
    return _broadcast(out0, out1)


def error_ch1(t, b_g1, k_sh):
    """Integrated rate errors (int p_merror, int q_merror) in rad for a constant level-gyro
    drift b_g1 at rest (eq. 32): (-b_g1 t + b_g1 sin(sqrt(k_sh) t)/sqrt(k_sh), 0);
    their norm, times R, is the position error."""
    _x0 = np.sqrt(k_sh)
    out0 = -b_g1*t + b_g1*np.sin(_x0*t)/_x0
    out1 = 0
    return _broadcast(out0, out1)


def error_ch3(t, b_g3, omega_e, lat0, psi0, k_sh, alpha):
    """Integrated rate errors (int p_merror, int q_merror) in rad for a constant azimuth-gyro
    drift b_g3 at rest (eq. 36, derived: the first term of int q_merror is
    -alpha sin(psi0) b_g3 sin(sqrt(k_sh) t)/sqrt(k_sh); the paper prints '+').
    Requires omega_e^2 sin^2(lat0) != k_sh."""
    _x0 = np.cos(psi0)
    _x1 = np.sqrt(k_sh)
    _x2 = _x1*t
    _x3 = np.sin(_x2)
    _x4 = _x1**(-1.0)
    _x5 = _x4*b_g3
    _x6 = _x3*_x5*alpha
    _x7 = np.sin(lat0)
    _x8 = _x7*omega_e
    _x9 = _x3*_x8
    _x10 = np.sin(psi0)
    _x11 = np.cos(_x2)
    _x12 = _x8*t - psi0
    _x13 = (_x7**2*omega_e**2 - k_sh)**(-1.0)
    _x14 = np.cos(lat0)
    out0 = _x0*_x6 + _x13*_x14*_x5*omega_e*(-_x0*_x9 + _x1*(_x10*_x11 + np.sin(_x12)))
    out1 = -_x10*_x6 + _x13*_x14*_x4*b_g3*omega_e*(_x1*(_x0*_x11 - np.cos(_x12)) + _x10*_x9)
    return _broadcast(out0, out1)


def oscillation_period(k_sh):
    """Period of the tilt oscillation of eq. 30, 2 pi / sqrt(k_sh) (the Schuler period for
    the k_sh of eq. 28)."""
    out0 = 2*np.pi/np.sqrt(k_sh)
    return out0


def schuler_period(g, R):
    """Schuler period 2 pi / sqrt(g / R) (eq. 30 with k_sh = g/R)."""
    out0 = 2*np.pi*np.sqrt(R)/np.sqrt(g)
    return out0


def table2_accel_bias(t, B, omega0):
    """Table 2 row 1: accelerometer bias, B/omega0^2 (1 - cos omega0 t)."""
    out0 = B*(1 - np.cos(omega0*t))/omega0**2
    return out0


def table2_initial_tilt(t, phi0, R0, omega0):
    """Table 2 row 2: initial tilt, -R0 phi0 (1 - cos omega0 t)."""
    out0 = R0*phi0*(np.cos(omega0*t) - 1)
    return out0


def table2_scale_factor(t, k, dV, omega0):
    """Table 2 row 3: scale factor k and velocity change dV at t = 0, k dV/omega0 sin omega0 t."""
    out0 = dV*k*np.sin(omega0*t)/omega0
    return out0


def table2_gyro_drift(t, eps, R0, omega0):
    """Table 2 row 4: level gyro drift, -R0 eps (t - sin(omega0 t)/omega0)."""
    _x0 = omega0*t
    out0 = R0*eps*(-_x0 + np.sin(_x0))/omega0
    return out0


def table2_azimuth_drift(t, eps_z, vx, vy, omega0):
    """Table 2 row 5, derived: azimuth drift eps_z, (dx, dy) = (eps_z/2)(v_y, -v_x)
    [t^2 - 2(1 - cos omega0 t)/omega0^2] (the paper's eps'_z is eps_z/2).
    Returns (dx, dy); the error is sqrt(dx^2 + dy^2)."""
    _x0 = omega0**2
    _x1 = _x0*t**2 + 2*np.cos(omega0*t) - 2
    _x2 = (1/2)*eps_z/_x0
    out0 = _x1*_x2*vy
    out1 = -_x1*_x2*vx
    return _broadcast(out0, out1)


def table2_initial_velocity(t, dv0, omega0):
    """Table 2 row 6: initial velocity error, dv0/omega0 sin omega0 t."""
    out0 = dv0*np.sin(omega0*t)/omega0
    return out0


def table2_initial_azimuth(t, phi_z0, v_cross, omega0):
    """Table 2 row 7: initial azimuth error, phi_z0 v_cross (t - sin(omega0 t)/omega0)."""
    _x0 = omega0*t
    out0 = phi_z0*v_cross*(_x0 - np.sin(_x0))/omega0
    return out0


def strapdown_velocity_rates(f_n, f_e, v_n, v_e, lat, rho, omega_e):
    """NED velocity equation of the strapdown comparator on the sphere of radius rho (eq. 10
    with t = Earth, s = NED; known altitude, v_D = 0): f + g - (2 omega_ie + omega_en)
    x v - omega_ie x (omega_ie x r), north and east rows. f_N, f_E: specific force in
    NED. Returns (v_N_dot, v_E_dot)."""
    _x0 = np.sin(lat)
    _x1 = 2*_x0*omega_e
    _x2 = np.tan(lat)/rho
    out0 = -_x0*omega_e**2*rho*np.cos(lat) - _x1*v_e - _x2*v_e**2 + f_n
    out1 = _x1*v_n + _x2*v_e*v_n + f_e
    return _broadcast(out0, out1)


def course_rate(dlat, dlon, lat, lat_dot):
    """Rate of the course chi = atan2(dlon cos(lat), dlat) of a path whose latitude and
    longitude change by dlat, dlon along one progress variable, at latitude rate
    lat_dot: -dlat dlon sin(lat) lat_dot / (dlat^2 + dlon^2 cos^2(lat))."""
    out0 = -dlat*dlon*lat_dot*np.sin(lat)/(dlat**2 + dlon**2*np.cos(lat)**2)
    return out0


def velocity_at_rest(omega_e, lat, R):
    """Inertial velocity of a vehicle at rest in m_N (north, west, up): omega_ie x
    [0, 0, R] = [0, -omega_e R cos(lat), 0]. Returns (..., 3)."""
    out0 = 0
    out1 = -R*omega_e*np.cos(lat)
    out2 = 0
    return _shaped((3,), out0, out1, out2)


def ground_velocity(v_x, v_y, v_z, r_x, r_y, r_z, w_x, w_y, w_z):
    """Earth-relative velocity (eq. 8 for the Earth-fixed frame): v_i - omega_ie x r, with
    v_i, r and the Earth rate w = omega_ie in one set of axes. Returns (..., 3)."""
    out0 = r_y*w_z - r_z*w_y + v_x
    out1 = -r_x*w_z + r_z*w_x + v_y
    out2 = r_x*w_y - r_y*w_x + v_z
    return _shaped((3,), out0, out1, out2)
