"""Pendulum model, generated from derivations/pendulum (python -m derivations.pendulum.generate).

GENERATED FILE: do not edit; regenerate with the command above.
"""
# ruff: noqa

import numpy as np


def _broadcast(*outs):
    """Broadcast the outputs of a vector function to one common shape (fresh arrays)."""
    arrays = [np.asarray(o, dtype=float) for o in outs]
    shape = np.broadcast_shapes(*[a.shape for a in arrays])
    return tuple(
        np.array(a)
        if a.shape == shape
        else (np.full(shape, a.item()) if a.ndim == 0 else np.broadcast_to(a, shape).copy())
        for a in arrays
    )

__all__ = ['angular_acceleration', 'period_small_angle', 'period_first_order']


def angular_acceleration(theta, l, g):
    """eq. 1: theta'' (rad/s^2)."""
    out0 = -g*np.sin(theta)/l
    return out0


def period_small_angle(l, g):
    """eq. 3: T (s)."""
    out0 = 2*np.pi*np.sqrt(l)/np.sqrt(g)
    return out0


def period_first_order(l, g, theta0):
    """eq. 4 (derived form): T to second order in the amplitude (s)."""
    _x0 = np.pi*np.sqrt(l)/np.sqrt(g)
    out0 = (1/8)*_x0*theta0**2 + 2*_x0
    return out0
