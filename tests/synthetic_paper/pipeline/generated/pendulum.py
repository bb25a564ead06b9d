"""Pendulum model, generated from derivations/pendulum (python -m derivations.pendulum.generate).

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
