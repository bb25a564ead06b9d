"""Numeric code of the IMU + altimeter attitude paper, generated from derivations/altimeter_attitude.

Regenerate: python -m derivations.altimeter_attitude.generate
Conventions: SI units, angles in rad, rates in rad/s; NED navigation frame, g down positive;
c = [C31, C32, C33] is the third row of C_b^n (body -> NED); x = [c1, c2, c3, V_d, h] with
V_d down and h up; omegat_*, ft_* are the gyro and accelerometer outputs. Every function
broadcasts its arguments; matrices are returned flattened row by row.

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

__all__ = ['model_matrix_a', 'noise_matrix_c', 'input_matrix_b', 'input_vector_exact', 'input_vector_first_order', 'vertical_transition', 'gamma_term_closed', 'noise_gamma', 'normalisation_error', 'third_row_from_euler', 'euler_from_third_row', 'euler_jacobian_third_row', 'euler_model_rhs', 'euler_noise_jacobian', 'euler_process_noise', 'euler_state_jacobian', 'accel_third_row', 'leveling_angles', 'third_row_rotation', 'flight_path_direction', 'climb_rate', 'pi_gains']

#: Functions the pipeline does not call, each with the reason it is generated.
AUDIT_ONLY = {
    'euler_noise_jacobian': 'd(UKF model)/d[n_w, n_a]; the filters take it through euler_process_noise (dt^2 J Sigma J^T), generated from the same derivation',
    'leveling_angles': 'eq. 11 as derived, for the audit; levelling runs through accel_third_row (eq. 17-b) and euler_from_third_row, equal to it when ||f|| = g',
}


def model_matrix_a(omegat_x, omegat_y, omegat_z, ft_x, ft_y, ft_z, k, gamma):
    """Eq. 26: the 5 x 5 system matrix A (row by row) of x = [c1, c2, c3, V_d, h] for
    gyro outputs omegat, accelerometer outputs ft, gain k and gamma = 1 - c^T c."""
    _x0 = gamma*k
    out0 = _x0
    out1 = omegat_z
    out2 = -omegat_y
    out3 = 0
    out4 = 0
    out5 = -omegat_z
    out6 = _x0
    out7 = omegat_x
    out8 = 0
    out9 = 0
    out10 = omegat_y
    out11 = -omegat_x
    out12 = _x0
    out13 = 0
    out14 = 0
    out15 = ft_x
    out16 = ft_y
    out17 = ft_z
    out18 = 0
    out19 = 0
    out20 = 0
    out21 = 0
    out22 = 0
    out23 = -1
    out24 = 0
    return _broadcast(out0, out1, out2, out3, out4, out5, out6, out7, out8, out9, out10, out11, out12, out13, out14, out15, out16, out17, out18, out19, out20, out21, out22, out23, out24)


def noise_matrix_c(c1, c2, c3):
    """Eq. 26: the 5 x 6 noise matrix C(x) (row by row) for w = [n_w, n_a], with the
    sensor model omegat = omega + n_w, ft = f + n_a (the negative of the printed
    matrix; the sign of w is immaterial for the covariances)."""
    _x0 = -c2
    _x1 = -c3
    _x2 = -c1
    out0 = 0
    out1 = c3
    out2 = _x0
    out3 = 0
    out4 = 0
    out5 = 0
    out6 = _x1
    out7 = 0
    out8 = c1
    out9 = 0
    out10 = 0
    out11 = 0
    out12 = c2
    out13 = _x2
    out14 = 0
    out15 = 0
    out16 = 0
    out17 = 0
    out18 = 0
    out19 = 0
    out20 = 0
    out21 = _x2
    out22 = _x0
    out23 = _x1
    out24 = 0
    out25 = 0
    out26 = 0
    out27 = 0
    out28 = 0
    out29 = 0
    return _broadcast(out0, out1, out2, out3, out4, out5, out6, out7, out8, out9, out10, out11, out12, out13, out14, out15, out16, out17, out18, out19, out20, out21, out22, out23, out24, out25, out26, out27, out28, out29)


def input_matrix_b():
    """Eq. 26: the input vector B of x_dot = A x + B g + C(x) w (gravity drives V_d)."""
    out0 = 0
    out1 = 0
    out2 = 0
    out3 = 1
    out4 = 0
    return _broadcast(out0, out1, out2, out3, out4)


def input_vector_exact(dt):
    """Eq. 30: L = int_0^dt exp(A s) ds B of the exact zero-order hold (the series stops:
    A^2 B = 0), independent of the IMU outputs and gamma."""
    out0 = 0
    out1 = 0
    out2 = 0
    out3 = dt
    out4 = -1/2*dt**2
    return _broadcast(out0, out1, out2, out3, out4)


def input_vector_first_order(dt):
    """Eq. 30 as the paper discretises: L = dt B (first order in dt)."""
    out0 = 0
    out1 = 0
    out2 = 0
    out3 = dt
    out4 = 0
    return _broadcast(out0, out1, out2, out3, out4)


def vertical_transition(dt):
    """Eq. 30: exp(V dt) (2 x 2, row by row) of the constant (V_d, h) block V of eq. 26's A,
    the lower-right block of F = exp(A dt) (A is block lower triangular)."""
    out0 = 1
    out1 = 0
    out2 = -dt
    out3 = 1
    return _broadcast(out0, out1, out2, out3)


def gamma_term_closed(P_11, P_12, P_13, P_22, P_23, P_33, sigma_g2, sigma_a2, dt):
    """Eq. 31's Gamma (Q kron P) Gamma^T for G = dt C(x) of eq. 26 and Q = diag(sigma_g2 I3,
    sigma_a2 I3), in closed form from the c block P_cc of P (upper triangle P_11 ..
    P_33): its c block (3 x 3, row by row), then its (V_d, V_d) entry; every other
    entry is 0. Equal to the literal Kronecker form of eqs. 32-33 (a test)."""
    _x0 = P_22 + P_33
    _x1 = dt**2
    _x2 = _x1*sigma_g2
    _x3 = -P_12*_x2
    _x4 = -P_13*_x2
    _x5 = -P_23*_x2
    out0 = _x0*_x2
    out1 = _x3
    out2 = _x4
    out3 = _x3
    out4 = _x2*(P_11 + P_33)
    out5 = _x5
    out6 = _x4
    out7 = _x5
    out8 = _x2*(P_11 + P_22)
    out9 = _x1*sigma_a2*(P_11 + _x0)
    return _broadcast(out0, out1, out2, out3, out4, out5, out6, out7, out8, out9)


def noise_gamma():
    """Eqs. 32-33: Gamma = [G_c1 ... G_c6] (5 x 30, row by row), G_ci x = C(x) e_i."""
    out0 = 0
    out1 = 0
    out2 = 0
    out3 = 0
    out4 = 0
    out5 = 0
    out6 = 0
    out7 = 1
    out8 = 0
    out9 = 0
    out10 = 0
    out11 = -1
    out12 = 0
    out13 = 0
    out14 = 0
    out15 = 0
    out16 = 0
    out17 = 0
    out18 = 0
    out19 = 0
    out20 = 0
    out21 = 0
    out22 = 0
    out23 = 0
    out24 = 0
    out25 = 0
    out26 = 0
    out27 = 0
    out28 = 0
    out29 = 0
    out30 = 0
    out31 = 0
    out32 = -1
    out33 = 0
    out34 = 0
    out35 = 0
    out36 = 0
    out37 = 0
    out38 = 0
    out39 = 0
    out40 = 1
    out41 = 0
    out42 = 0
    out43 = 0
    out44 = 0
    out45 = 0
    out46 = 0
    out47 = 0
    out48 = 0
    out49 = 0
    out50 = 0
    out51 = 0
    out52 = 0
    out53 = 0
    out54 = 0
    out55 = 0
    out56 = 0
    out57 = 0
    out58 = 0
    out59 = 0
    out60 = 0
    out61 = 1
    out62 = 0
    out63 = 0
    out64 = 0
    out65 = -1
    out66 = 0
    out67 = 0
    out68 = 0
    out69 = 0
    out70 = 0
    out71 = 0
    out72 = 0
    out73 = 0
    out74 = 0
    out75 = 0
    out76 = 0
    out77 = 0
    out78 = 0
    out79 = 0
    out80 = 0
    out81 = 0
    out82 = 0
    out83 = 0
    out84 = 0
    out85 = 0
    out86 = 0
    out87 = 0
    out88 = 0
    out89 = 0
    out90 = 0
    out91 = 0
    out92 = 0
    out93 = 0
    out94 = 0
    out95 = 0
    out96 = 0
    out97 = 0
    out98 = 0
    out99 = 0
    out100 = 0
    out101 = 0
    out102 = 0
    out103 = 0
    out104 = 0
    out105 = -1
    out106 = 0
    out107 = 0
    out108 = 0
    out109 = 0
    out110 = 0
    out111 = -1
    out112 = 0
    out113 = 0
    out114 = 0
    out115 = 0
    out116 = 0
    out117 = -1
    out118 = 0
    out119 = 0
    out120 = 0
    out121 = 0
    out122 = 0
    out123 = 0
    out124 = 0
    out125 = 0
    out126 = 0
    out127 = 0
    out128 = 0
    out129 = 0
    out130 = 0
    out131 = 0
    out132 = 0
    out133 = 0
    out134 = 0
    out135 = 0
    out136 = 0
    out137 = 0
    out138 = 0
    out139 = 0
    out140 = 0
    out141 = 0
    out142 = 0
    out143 = 0
    out144 = 0
    out145 = 0
    out146 = 0
    out147 = 0
    out148 = 0
    out149 = 0
    return _broadcast(out0, out1, out2, out3, out4, out5, out6, out7, out8, out9, out10, out11, out12, out13, out14, out15, out16, out17, out18, out19, out20, out21, out22, out23, out24, out25, out26, out27, out28, out29, out30, out31, out32, out33, out34, out35, out36, out37, out38, out39, out40, out41, out42, out43, out44, out45, out46, out47, out48, out49, out50, out51, out52, out53, out54, out55, out56, out57, out58, out59, out60, out61, out62, out63, out64, out65, out66, out67, out68, out69, out70, out71, out72, out73, out74, out75, out76, out77, out78, out79, out80, out81, out82, out83, out84, out85, out86, out87, out88, out89, out90, out91, out92, out93, out94, out95, out96, out97, out98, out99, out100, out101, out102, out103, out104, out105, out106, out107, out108, out109, out110, out111, out112, out113, out114, out115, out116, out117, out118, out119, out120, out121, out122, out123, out124, out125, out126, out127, out128, out129, out130, out131, out132, out133, out134, out135, out136, out137, out138, out139, out140, out141, out142, out143, out144, out145, out146, out147, out148, out149)


def normalisation_error(c1, c2, c3):
    """Eq. 15: gamma = 1 - c^T c, summed as (c1^2 + c3^2) + c2^2 (the rounding of
    numpy's einsum over a 3-vector)."""
    out0 = 1 - (c2**2 + (c1**2 + c3**2))
    return out0


def third_row_from_euler(phi, theta):
    """Eq. 6: c = C_b^n(3,:) = [-sin theta, sin phi cos theta, cos phi cos theta]."""
    _x0 = np.cos(theta)
    out0 = -np.sin(theta)
    out1 = _x0*np.sin(phi)
    out2 = _x0*np.cos(phi)
    return _broadcast(out0, out1, out2)


def euler_from_third_row(c1, c2, c3):
    """Inverse of eq. 6: (phi, theta) = (atan2(c2, c3), atan2(-c1, sqrt(c2^2 + c3^2)));
    independent of the norm of c."""
    out0 = np.arctan2(c2, c3)
    out1 = np.arctan2(-c1, np.sqrt(c2**2 + c3**2))
    return _broadcast(out0, out1)


def euler_jacobian_third_row(c1, c2, c3):
    """d(phi, theta)/dc (2 x 3, row by row): maps a covariance of c to roll/pitch."""
    _x0 = c2**2 + c3**2
    _x1 = _x0**(-1.0)
    _x2 = np.sqrt(_x0)
    _x3 = (_x0 + c1**2)**(-1.0)
    _x4 = _x3*c1/_x2
    out0 = 0
    out1 = _x1*c3
    out2 = -_x1*c2
    out3 = -_x2*_x3
    out4 = _x4*c2
    out5 = _x4*c3
    return _broadcast(out0, out1, out2, out3, out4, out5)


def euler_model_rhs(phi, theta, V_d, h, omegat_x, omegat_y, omegat_z, ft_x, ft_y, ft_z, g):
    """UKF model (eqs. 4, 6, 24, 25): d/dt [phi, theta, V_d, h] for sensor outputs."""
    _x0 = np.sin(phi)
    _x1 = np.tan(theta)
    _x2 = np.cos(phi)
    _x3 = np.cos(theta)
    out0 = _x0*_x1*omegat_y + _x1*_x2*omegat_z + omegat_x
    out1 = -_x0*omegat_z + _x2*omegat_y
    out2 = _x0*_x3*ft_y + _x2*_x3*ft_z - ft_x*np.sin(theta) + g
    out3 = -V_d
    return _broadcast(out0, out1, out2, out3)


def euler_noise_jacobian(phi, theta):
    """d(UKF model)/d[n_w, n_a] (4 x 6, row by row): sensor noise to state rates."""
    _x0 = np.sin(phi)
    _x1 = np.tan(theta)
    _x2 = np.cos(phi)
    _x3 = np.cos(theta)
    out0 = -1
    out1 = -_x0*_x1
    out2 = -_x1*_x2
    out3 = 0
    out4 = 0
    out5 = 0
    out6 = 0
    out7 = -_x2
    out8 = _x0
    out9 = 0
    out10 = 0
    out11 = 0
    out12 = 0
    out13 = 0
    out14 = 0
    out15 = np.sin(theta)
    out16 = -_x0*_x3
    out17 = -_x2*_x3
    out18 = 0
    out19 = 0
    out20 = 0
    out21 = 0
    out22 = 0
    out23 = 0
    return _broadcast(out0, out1, out2, out3, out4, out5, out6, out7, out8, out9, out10, out11, out12, out13, out14, out15, out16, out17, out18, out19, out20, out21, out22, out23)


def euler_process_noise(phi, theta, dt, sigma_g2, sigma_a2):
    """dt^2 J Sigma J^T (4 x 4, row by row): per-step process noise of the UKF/EKF model
    for per-sample gyro/accelerometer variances sigma_g2, sigma_a2."""
    _x0 = dt**2
    _x1 = _x0*sigma_g2
    out0 = _x1/np.cos(theta)**2
    out1 = 0
    out2 = 0
    out3 = 0
    out4 = 0
    out5 = _x1
    out6 = 0
    out7 = 0
    out8 = 0
    out9 = 0
    out10 = _x0*sigma_a2
    out11 = 0
    out12 = 0
    out13 = 0
    out14 = 0
    out15 = 0
    return _broadcast(out0, out1, out2, out3, out4, out5, out6, out7, out8, out9, out10, out11, out12, out13, out14, out15)


def euler_state_jacobian(phi, theta, omegat_x, omegat_y, omegat_z, ft_x, ft_y, ft_z):
    """d(UKF model)/d[phi, theta, V_d, h] (4 x 4, row by row), for the EKF comparison."""
    _x0 = np.cos(phi)
    _x1 = np.tan(theta)
    _x2 = np.sin(phi)
    _x3 = _x1**2 + 1
    _x4 = _x2*omegat_y
    _x5 = _x0*omegat_z
    _x6 = np.cos(theta)
    _x7 = np.sin(theta)
    out0 = _x0*_x1*omegat_y - _x1*_x2*omegat_z
    out1 = _x3*_x4 + _x3*_x5
    out2 = 0
    out3 = 0
    out4 = -_x4 - _x5
    out5 = 0
    out6 = 0
    out7 = 0
    out8 = _x0*_x6*ft_y - _x2*_x6*ft_z
    out9 = -_x0*_x7*ft_z - _x2*_x7*ft_y - _x6*ft_x
    out10 = 0
    out11 = 0
    out12 = 0
    out13 = 0
    out14 = -1
    out15 = 0
    return _broadcast(out0, out1, out2, out3, out4, out5, out6, out7, out8, out9, out10, out11, out12, out13, out14, out15)


def accel_third_row(ft_x, ft_y, ft_z):
    """Eq. 17-b: c_a = -f / ||f||, the accelerometer estimate of c (cruise assumption)."""
    _x0 = 1/np.sqrt(ft_x**2 + ft_y**2 + ft_z**2)
    out0 = -_x0*ft_x
    out1 = -_x0*ft_y
    out2 = -_x0*ft_z
    return _broadcast(out0, out1, out2)


def leveling_angles(ft_x, ft_y, ft_z, g):
    """Eq. 11 as derived from eq. 10: phi = atan2(-f_y, -f_z), theta = asin(f_x / g)
    (the printed atan2(f_y, f_z) is off by 180 deg)."""
    out0 = np.arctan2(-ft_y, -ft_z)
    out1 = np.arcsin(ft_x/g)
    return _broadcast(out0, out1)


def third_row_rotation(k1, k2, k3, c1, c2, c3, cos_a, sin_a):
    """Eq. 13 over one step with omega held: c rotated by a about the unit axis k
    (a k = -omega dt), c cos a + (k x c) sin a + k (k . c)(1 - cos a) (Rodrigues),
    summed in the order of numpy's np.cross and np.sum."""
    _x0 = c3*k3 + (c1*k1 + c2*k2)
    _x1 = 1 - cos_a
    out0 = _x1*(_x0*k1) + (c1*cos_a + sin_a*(-c2*k3 + c3*k2))
    out1 = _x1*(_x0*k2) + (c2*cos_a + sin_a*(c1*k3 - c3*k1))
    out2 = _x1*(_x0*k3) + (c3*cos_a + sin_a*(-c1*k2 + c2*k1))
    return _broadcast(out0, out1, out2)


def flight_path_direction(gam, chi):
    """Truth trajectory: u = v^n / V = [cos gam cos chi, cos gam sin chi, -sin gam] (the x
    axis after yaw chi and pitch gam), then du/dgam, then du/dchi (9 values)."""
    _x0 = np.cos(chi)
    _x1 = np.cos(gam)
    _x2 = _x0*_x1
    _x3 = np.sin(chi)
    _x4 = _x1*_x3
    _x5 = np.sin(gam)
    out0 = _x2
    out1 = _x4
    out2 = -_x5
    out3 = -_x0*_x5
    out4 = -_x3*_x5
    out5 = -_x1
    out6 = -_x4
    out7 = _x2
    out8 = 0
    return _broadcast(out0, out1, out2, out3, out4, out5, out6, out7, out8)


def climb_rate(V, gam):
    """Truth trajectory, eq. 25: h_dot = -V_d = V sin gam."""
    out0 = V*np.sin(gam)
    return out0


def pi_gains(omega_c, xi):
    """Eq. 20: (k_i, k_p) = (omega^2, 2 xi omega) of the PI complementary filter."""
    out0 = omega_c**2
    out1 = 2*omega_c*xi
    return _broadcast(out0, out1)
