"""WGS-84 normal gravity at a latitude and height (for the flight-log ``--latitude-deg``).

Source: NIMA TR8350.2, *Department of Defense World Geodetic System 1984*, 3rd ed. (2000):

* eq. (4-1), Somigliana's closed formula on the ellipsoid::

      gamma(phi) = gamma_e (1 + k sin^2 phi) / sqrt(1 - e^2 sin^2 phi),
      k = b gamma_p / (a gamma_e) - 1

* eq. (4-3), the second-order (Taylor) expansion in the height h above the ellipsoid::

      gamma_h = gamma(phi) [1 - 2/a (1 + f + m - 2 f sin^2 phi) h + 3 h^2 / a^2]

  with m = omega^2 a^2 b / GM. Its linear term is the free-air gradient, about
  3.086e-6 m/s^2 per m (0.3086 mGal/m); the expansion is good to ~1e-6 m/s^2 up to 20 km.

Constants are the WGS-84 defining and derived values of TR8350.2 Tables 3.1 and 3.3. The
model is the normal (ellipsoidal) field: real gravity differs by anomalies, mostly below
5e-4 m/s^2 (up to ~3e-3 in high mountains), and a barometric altitude is not an ellipsoidal
height (geoid undulation up to ~100 m, i.e. ~3e-4 m/s^2); compare the 3.35e-3 m/s^2 between
9.80665 and 9.81.

>>> round(normal_gravity(0.0), 10), round(normal_gravity(90.0), 9)
(9.7803253359, 9.832184938)
>>> round(normal_gravity(45.0), 6), round(normal_gravity(45.0, 1000.0), 6)
(9.806198, 9.803113)
"""

from __future__ import annotations

import math

__all__ = [
    "A",
    "F",
    "GAMMA_E",
    "GAMMA_P",
    "K",
    "E2",
    "M",
    "LATITUDE_RANGE",
    "HEIGHT_RANGE",
    "normal_gravity",
]

A = 6378137.0  # semi-major axis, m (Table 3.1)
F = 1.0 / 298.257223563  # flattening (Table 3.1)
GAMMA_E = 9.7803253359  # normal gravity at the equator, m/s^2 (Table 3.3)
GAMMA_P = 9.8321849378  # normal gravity at the poles, m/s^2 (Table 3.3)
K = 0.00193185265241  # Somigliana's constant b gamma_p / (a gamma_e) - 1 (Table 3.3)
E2 = 6.69437999014e-3  # first eccentricity squared (Table 3.3)
M = 0.00344978650684  # omega^2 a^2 b / GM (Table 3.3)
LATITUDE_RANGE = (-90.0, 90.0)  # deg
HEIGHT_RANGE = (-1000.0, 20000.0)  # m: where eq. (4-3) holds to ~1e-6 m/s^2


def normal_gravity(latitude_deg: float, height_m: float = 0.0) -> float:
    """WGS-84 normal gravity (m/s^2) at geodetic latitude (deg) and ellipsoidal height (m).

    Raises ValueError outside LATITUDE_RANGE / HEIGHT_RANGE or for non-finite input.

    >>> normal_gravity(91.0)
    Traceback (most recent call last):
    ...
    ValueError: latitude = 91.0 deg: must be a finite number in [-90, 90]
    """
    lat, h = float(latitude_deg), float(height_m)
    if not (math.isfinite(lat) and LATITUDE_RANGE[0] <= lat <= LATITUDE_RANGE[1]):
        raise ValueError(f"latitude = {latitude_deg!r} deg: must be a finite number in [-90, 90]")
    if not (math.isfinite(h) and HEIGHT_RANGE[0] <= h <= HEIGHT_RANGE[1]):
        raise ValueError(
            f"height = {height_m!r} m: must be a finite number in "
            f"[{HEIGHT_RANGE[0]:g}, {HEIGHT_RANGE[1]:g}] (eq. 4-3 of NIMA TR8350.2)"
        )
    s2 = math.sin(math.radians(lat)) ** 2
    gamma = GAMMA_E * (1.0 + K * s2) / math.sqrt(1.0 - E2 * s2)
    return gamma * (1.0 - 2.0 / A * (1.0 + F + M - 2.0 * F * s2) * h + 3.0 * h**2 / A**2)
