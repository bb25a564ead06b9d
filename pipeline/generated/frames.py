"""Frames and Earth (shared by every paper), generated from derivations/frames.py.

Regenerate: python -m derivations.generate_frames
Conventions: NED navigation frame; mat_ab maps coordinates in frame B to frame A; 3-2-1 Euler
angles (yaw psi, pitch theta, roll phi) in rad; rates in rad/s. Every function broadcasts its
arguments; a matrix is returned with trailing axes (3, 3), a vector with a trailing axis (3,).

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


__all__ = ['rot_z', 'mat_tn', 'mat_ne', 'body_rate_from_euler_rates', 'skew', 'earth_rate_e', 'earth_rate_n', 'transport_rate_n', 'latlon_rates', 'transport_rate_n_velocity']


def rot_z(a):
    """Frame rotation by a about z: [[c, s, 0], [-s, c, 0], [0, 0, 1]] (its transpose is
    the active rotation by a)."""
    _x0 = np.cos(a)
    _x1 = np.sin(a)
    out0 = _x0
    out1 = _x1
    out2 = 0
    out3 = -_x1
    out4 = _x0
    out5 = 0
    out6 = 0
    out7 = 0
    out8 = 1
    return _shaped((3, 3), out0, out1, out2, out3, out4, out5, out6, out7, out8)


def mat_tn(psi, theta, phi):
    """[T]^{TN} of the 3-2-1 sequence, rot_x(phi) rot_y(theta) rot_z(psi): NED -> body.
    Its transpose (swapaxes(-1, -2)) is C_b^n."""
    _x0 = np.cos(psi)
    _x1 = np.cos(theta)
    _x2 = np.sin(psi)
    _x3 = np.sin(theta)
    _x4 = np.cos(phi)
    _x5 = np.sin(phi)
    _x6 = _x0*_x5
    _x7 = _x0*_x4
    _x8 = _x2*_x5
    out0 = _x0*_x1
    out1 = _x1*_x2
    out2 = -_x3
    out3 = -_x2*_x4 + _x3*_x6
    out4 = _x3*_x8 + _x7
    out5 = _x1*_x5
    out6 = _x3*_x7 + _x8
    out7 = _x2*_x3*_x4 - _x6
    out8 = _x1*_x4
    return _shaped((3, 3), out0, out1, out2, out3, out4, out5, out6, out7, out8)


def mat_ne(lat, lon):
    """[T]^{NE}: Earth-fixed (or inertial, with the inertial longitude) -> NED at latitude
    lat and longitude lon; its rows are the north, east and down axes."""
    _x0 = np.sin(lat)
    _x1 = np.cos(lon)
    _x2 = np.sin(lon)
    _x3 = np.cos(lat)
    out0 = -_x0*_x1
    out1 = -_x0*_x2
    out2 = _x3
    out3 = -_x2
    out4 = _x1
    out5 = 0
    out6 = -_x1*_x3
    out7 = -_x2*_x3
    out8 = -_x0
    return _shaped((3, 3), out0, out1, out2, out3, out4, out5, out6, out7, out8)


def body_rate_from_euler_rates(theta, phi, phi_dot, theta_dot, psi_dot):
    """Euler-rate map of the 3-2-1 sequence: [omega^{TN}]^T = E(theta, phi) [phi_dot,
    theta_dot, psi_dot], from Poisson's equation on mat_tn."""
    _x0 = np.cos(phi)
    _x1 = np.sin(phi)
    _x2 = psi_dot*np.cos(theta)
    out0 = phi_dot - psi_dot*np.sin(theta)
    out1 = _x0*theta_dot + _x1*_x2
    out2 = _x0*_x2 - _x1*theta_dot
    return _shaped((3,), out0, out1, out2)


def skew(w1, w2, w3):
    """Cross-product matrix [w x]: skew(w) @ v == cross(w, v)."""
    out0 = 0
    out1 = -w3
    out2 = w2
    out3 = w3
    out4 = 0
    out5 = -w1
    out6 = -w2
    out7 = w1
    out8 = 0
    return _shaped((3, 3), out0, out1, out2, out3, out4, out5, out6, out7, out8)


def earth_rate_e(omega_ie):
    """Earth rate in the Earth-fixed (or inertial) frame, z along the spin axis: [0, 0, omega_ie]."""
    out0 = 0
    out1 = 0
    out2 = omega_ie
    return _shaped((3,), out0, out1, out2)


def earth_rate_n(omega_ie, lat):
    """Earth rate in NED, [T]^{NE} [0, 0, omega_ie] = omega_ie [cos lat, 0, -sin lat]."""
    out0 = omega_ie*np.cos(lat)
    out1 = 0
    out2 = -omega_ie*np.sin(lat)
    return _shaped((3,), out0, out1, out2)


def transport_rate_n(lat, lat_dot, lon_dot):
    """[omega^{NE}]^N = [lon_dot cos lat, -lat_dot, -lon_dot sin lat] (Poisson's equation
    on mat_ne); with the inertial longitude rate it is the inertial rate of NED."""
    out0 = lon_dot*np.cos(lat)
    out1 = -lat_dot
    out2 = -lon_dot*np.sin(lat)
    return _shaped((3,), out0, out1, out2)


def latlon_rates(v_n, v_e, lat, rho):
    """[lat_dot, lon_dot] = [v_n / rho, v_e / (rho cos lat)] at constant radius rho."""
    out0 = v_n/rho
    out1 = v_e/(rho*np.cos(lat))
    return _shaped((2,), out0, out1)


def transport_rate_n_velocity(v_n, v_e, lat, rho):
    """[omega^{NE}]^N = [v_e, -v_n, -v_e tan lat] / rho: transport_rate_n of latlon_rates."""
    out0 = v_e/rho
    out1 = -v_n/rho
    out2 = -v_e*np.tan(lat)/rho
    return _shaped((3,), out0, out1, out2)
