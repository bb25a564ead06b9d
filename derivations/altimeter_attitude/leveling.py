"""Attitude from the accelerometers (eqs. 9-12, 15.b, 17-a, 17-b).

The navigation equation in NED (eq. 9, adopted from Titterton & Weston) gives, at rest or
in unaccelerated flight (V_dot = 0, Coriolis neglected), f^b = -C_n^b g^n (eq. 10), which is
-g times the third DCM row (eq. 15.b). Inverting it gives roll and pitch (eq. 11) and the
accelerometer estimate of c (eqs. 17-a, 17-b). With acceleration, only the total
acceleration F_t^n = C_b^n f^b + g^n (eq. 12) carries the attitude.

>>> specific_force_level().T
Matrix([[g*sin(theta), -g*sin(phi)*cos(theta), -g*cos(phi)*cos(theta)]])
>>> leveling_angles().T
Matrix([[atan2(-f_y, -f_z), asin(f_x/g)]])
"""

from __future__ import annotations

import sympy as sp

from derivations.altimeter_attitude import symbols as s
from derivations.altimeter_attitude.kinematics import mat_nb
from derivations.frames import gravity_n, skew

__all__ = [
    "navigation_symbols",
    "velocity_rate",
    "specific_force_level",
    "specific_force_level_dcm",
    "leveling_angles",
    "total_acceleration",
    "third_row_from_accel",
    "third_row_from_accel_unit",
]

V_N, V_E, V_D = sp.symbols("V_N V_E V_D", real=True)
w_ie = sp.Matrix(sp.symbols("w_ie_x w_ie_y w_ie_z", real=True))
w_en = sp.Matrix(sp.symbols("w_en_x w_en_y w_en_z", real=True))


def navigation_symbols() -> dict[str, sp.Matrix]:
    """The symbols of eq. 9: ground velocity in NED, Earth rate and transport rate in NED."""
    return {"V": sp.Matrix([V_N, V_E, V_D]), "w_ie": w_ie, "w_en": w_en}


def velocity_rate() -> sp.Matrix:
    """eq. 9: V_dot = C_b^n f^b - (2 w_ie + w_en) x V + g^n (Titterton & Weston, eq. 3.16)."""
    vel = navigation_symbols()["V"]
    return s.mat_C * s.f_b - skew(2 * w_ie + w_en) * vel + gravity_n(s.g)


def specific_force_level() -> sp.Matrix:
    """eq. 10: f^b = -C_n^b g^n when V_dot + (2 w_ie + w_en) x V = 0, in Euler angles."""
    return sp.simplify(-mat_nb().T * gravity_n(s.g))


def specific_force_level_dcm() -> sp.Matrix:
    """eq. 15.b: the same in DCM elements: -C_n^b g^n = -g C_b^n(3,:)^T = -g c."""
    return -s.mat_C.T * gravity_n(s.g)


def leveling_angles() -> sp.Matrix:
    """eq. 11: roll and pitch that solve eq. 10 for a measured f^b (|theta| < 90 deg).

    From eq. 10: f_y = -g cos(theta) sin(phi), f_z = -g cos(theta) cos(phi), f_x = g sin(theta);
    with cos(theta) > 0, phi = atan2(-f_y, -f_z) and theta = asin(f_x / g).
    """
    return sp.Matrix([sp.atan2(-s.fy, -s.fz), sp.asin(s.fx / s.g)])


def total_acceleration() -> sp.Matrix:
    """eq. 12: F_t^n = V_dot + (2 w_ie + w_en) x V, which by eq. 9 equals C_b^n f^b + g^n."""
    vel = navigation_symbols()["V"]
    return velocity_rate() + skew(2 * w_ie + w_en) * vel


def third_row_from_accel() -> sp.Matrix:
    """eq. 17-a: c from f^b = -g c (eq. 15.b) solved for c."""
    sol = sp.solve(list(s.f_b + s.g * s.c), list(s.c), dict=True)[0]
    return sp.Matrix([sol[ci] for ci in s.c])


def third_row_from_accel_unit() -> sp.Matrix:
    """eq. 17-b: the unit vector along eq. 17-a, -f^b / ||f^b|| (||f^b|| written f_norm)."""
    est = third_row_from_accel()
    scale = s.g / s.F_norm  # ||-f/g|| = ||f|| / g
    return est * scale
