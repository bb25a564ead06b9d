"""Truth trajectory of the platform-drift scenarios: a vehicle on a sphere over the rotating Earth.

The vehicle moves at constant altitude ``h`` on the sphere of radius ``rho = R + h``
centred on the Earth's centre (spherical Earth, spherical mass gravity GM/r^2). Its
geocentric latitude and Earth-fixed longitude are linear in one progress variable
``s(t)`` (0 -> 1)::

    lat(t) = lat0 + dlat * s(t),   lon(t) = lon0 + dlon * s(t)

so that ``dlat = 0`` is a path along a parallel, ``dlon = 0`` a path along a meridian and
``dlat = dlon = 0`` a vehicle at rest. ``s`` rises with a smooth speed profile: the speed
grows from zero over ``ramp_s`` seconds with a raised-cosine acceleration (continuous
acceleration and jerk), stays constant, and falls back to zero over the last ``ramp_s``
seconds of ``travel_time_s``; after that the vehicle is at rest.

Frames (all right-handed):

* ``i``: inertial, equal to the Earth-fixed frame at t = 0 (z along the Earth's axis);
  the inertial longitude is ``Lam = lon + omega_e t``.
* ``NWU``: the paper's m_N frame on a spherical Earth (axis 1 north, 2 west, 3 up along
  the radius, i.e. along the mass attraction). Its inertial angular rate, in NWU, is
  ``[Lam_dot cos(lat), lat_dot, Lam_dot sin(lat)]`` (eq. 4 with omega_e + lon_dot).
* body ``b``: NWU rotated about the up axis by ``psi_b(t) = psi0 - (chi(t) - chi(0))``,
  where ``chi`` is the course (clockwise from north) of the path, then by a constant
  mounting rotation ``M`` (identity unless the platform starts plumb-level). The body
  therefore yaws with the vehicle's course and stays level.

Measurements: :meth:`Trajectory.specific_force_in` gives what accelerometers along any
frame's axes read, from the generated eq. 17 (``gen.specific_force_platform``, exact in the
tilts). The inertial ``a_i`` and ``f_i`` computed here are an independent check of it (the
tests compare the two); the pipeline reads the specific force only from the generated eq. 17.

Angles: ``psi`` (the paper's azimuth of eq. 2) turns about the up axis from north toward
west; the course ``chi`` turns from north toward east. Everything is in SI units and rad.
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from functools import cached_property

import numpy as np

from pipeline.generated import frames
from pipeline.generated import platform_drift as gen

__all__ = ["Earth", "Path", "Truth", "Trajectory", "c3", "eq2_angles", "haversine"]


@dataclass(frozen=True)
class Earth:
    """Spherical Earth: radius (m), GM (m^3/s^2), rotation rate (rad/s)."""

    radius: float
    gm: float
    omega_e: float


@dataclass(frozen=True)
class Path:
    """Start point, angular changes and speed profile (rad, m, s)."""

    lat0: float
    lon0: float
    altitude: float
    dlat: float
    dlon: float
    travel_time: float
    ramp: float


@dataclass(frozen=True)
class Truth:
    """The truth at one instant (inertial-frame vectors as 3-element numpy arrays).

    The vectors ``r_i``, ``v_i``, ``a_i``, ``f_i``, the rate ``w_nwu`` and the body azimuth
    ``psi_b``, ``psi_b_dot`` are computed when first read (the integrators' right-hand sides
    read only some of them, at every evaluation), by the same operations in the same order.
    """

    lat: float
    lon: float
    lat_dot: float
    lat_ddot: float
    lon_dot: float  # Earth-relative longitude rate
    lon_ddot: float
    nwu_i: np.ndarray  # 3x3, columns N, W, U in inertial coordinates
    lam_dot: float = field(repr=False)  # inertial longitude rate
    traj: Trajectory = field(repr=False)

    @cached_property
    def _axes(self) -> tuple[np.ndarray, np.ndarray, np.ndarray, float, float]:
        """North, east, up (inertial coordinates), cos(lat), sin(lat)."""
        nwu = self.nwu_i
        return nwu[:, 0], -nwu[:, 1], nwu[:, 2], math.cos(self.lat), math.sin(self.lat)

    @cached_property
    def r_i(self) -> np.ndarray:
        """Position from the Earth's centre, m."""
        return self.traj.rho * self._axes[2]

    @cached_property
    def v_i(self) -> np.ndarray:
        """Inertial velocity, m/s."""
        north, east, _, cl, _ = self._axes
        return self.traj.rho * (self.lat_dot * north + self.lam_dot * cl * east)

    @cached_property
    def a_i(self) -> np.ndarray:
        """Inertial acceleration, m/s^2."""
        north, east, up, cl, sl = self._axes
        lat_d, lat_dd, lam_d, lam_dd = self.lat_dot, self.lat_ddot, self.lam_dot, self.lon_ddot
        return self.traj.rho * (
            (lat_dd + lam_d * lam_d * sl * cl) * north
            + (lam_dd * cl - 2.0 * lam_d * lat_d * sl) * east
            - (lat_d * lat_d + lam_d * lam_d * cl * cl) * up
        )

    @cached_property
    def f_i(self) -> np.ndarray:
        """Specific force a - g_mass, m/s^2."""
        return self.a_i + (self.traj.earth.gm / self.traj.rho**2) * self._axes[2]

    @cached_property
    def w_nwu(self) -> np.ndarray:
        """Inertial rate of NWU, in NWU, rad/s: the transport rate of NED at the inertial
        longitude rate, in NWU axes."""
        return self.traj.w_nwu_memo(self.lat, self.lat_dot, self.lam_dot)

    @cached_property
    def psi_b(self) -> float:
        """Body azimuth about up (north toward west), rad: it follows the course."""
        traj = self.traj
        return traj.psi0 - (traj.course(self.lat) - traj.chi0)

    @cached_property
    def psi_b_dot(self) -> float:
        """Its rate: chi_dot = -dlat dlon sin(lat) lat_dot / (dlat^2 + dlon^2 cos^2)."""
        p, traj = self.traj.path, self.traj
        return -(
            float(gen.course_rate(p.dlat, p.dlon, self.lat, self.lat_dot)) if traj.moving else 0.0
        )

    @cached_property
    def c3_b(self) -> np.ndarray:
        """C3(psi_b) of eq. 2 (read-only)."""
        return self.traj.c3_memo(self.psi_b)


def c3(psi: float) -> np.ndarray:
    """The paper's C3(psi) (eq. 2): maps coordinates of a frame turned by +psi about axis 3.

    The transpose of the generated frame rotation ``frames.rot_z(psi)``.
    """
    return frames.rot_z(psi).T


def eq2_angles(c_x_nwu: np.ndarray) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """(psi, phi_y, phi_x) of ``C_x^{NWU} = C3(psi) C2(phi_y) C1(phi_x)`` (eq. 2), inverted.

    ``c_x_nwu`` is 3x3 or (..., 3, 3); |phi_y| < pi/2. The inverse of the generated
    ``frames.mat_tn(psi, phi_y, phi_x).T`` (the tests compose the two).
    """
    c = np.asarray(c_x_nwu, dtype=float)
    psi = np.arctan2(c[..., 1, 0], c[..., 0, 0])
    phi_y = np.arcsin(np.clip(-c[..., 2, 0], -1.0, 1.0))
    phi_x = np.arctan2(c[..., 2, 1], c[..., 2, 2])
    return psi, phi_y, phi_x


def _haversine_h(lat1, lon1, lat2, lon2) -> np.ndarray:
    lat1, lon1, lat2, lon2 = (np.asarray(a, dtype=float) for a in (lat1, lon1, lat2, lon2))
    return (
        np.sin((lat2 - lat1) / 2) ** 2
        + np.cos(lat1) * np.cos(lat2) * np.sin((lon2 - lon1) / 2) ** 2
    )


def haversine(lat1, lon1, lat2, lon2) -> np.ndarray:
    """Great-circle angle (rad) between two points; exact also for tiny separations. The
    haversine ``h`` is clipped to [0, 1] (:func:`haversine_clipped` says where it was)."""
    return 2 * np.arcsin(np.sqrt(np.clip(_haversine_h(lat1, lon1, lat2, lon2), 0.0, 1.0)))


def haversine_clipped(lat1, lon1, lat2, lon2) -> np.ndarray:
    """Where :func:`haversine` clipped its arcsine's argument (h outside [0, 1]; h lies in
    [0, 1] in exact arithmetic for every two latitudes, so only round-off or a non-finite
    position reach the clip), as a boolean array.

    >>> a = 0.6976923076923077  # antipodal points: h = 1 + 2e-16
    >>> haversine_clipped([0.5, a], 0.0, [0.5, -a], [0.0, np.pi]).tolist()
    [False, True]
    """
    h = _haversine_h(lat1, lon1, lat2, lon2)
    return (h < 0.0) | (h > 1.0)


class Trajectory:
    """Analytic truth kinematics of one scenario."""

    def __init__(self, earth: Earth, path: Path, psi0: float):
        self.earth = earth
        self.path = path
        self.rho = earth.radius + path.altitude
        self.psi0 = float(psi0)
        moving = path.dlat != 0.0 or path.dlon != 0.0
        self.moving = moving
        tr, tt = path.ramp, path.travel_time
        # cruise rate of s: the two ramps each cover ramp/2 of cruise-speed time
        self.s_dot_cruise = 1.0 / (tt - tr) if moving else 0.0
        self.chi0 = self.course(path.lat0)
        self.mount = np.eye(3)
        self._c3_last: tuple[tuple[float, float], np.ndarray] | None = None
        self._w_nwu_last: tuple[tuple[tuple[float, float], ...], np.ndarray] | None = None

    # ---- progress s(t) and its derivatives ---------------------------------------------
    def progress(self, t: float) -> tuple[float, float, float]:
        """(s, s_dot, s_ddot) of the smooth speed profile."""
        if not self.moving:
            return 0.0, 0.0, 0.0
        tr, tt, vc = self.path.ramp, self.path.travel_time, self.s_dot_cruise
        two_pi = 2.0 * math.pi
        if t <= 0.0:
            return 0.0, 0.0, 0.0
        if t >= tt:
            return 1.0, 0.0, 0.0
        if t < tr:
            tau = t / tr
            s = vc * tr * (tau * tau / 2 + (math.cos(two_pi * tau) - 1) / (2 * two_pi * math.pi))
            sd = vc * (tau - math.sin(two_pi * tau) / two_pi)
            sdd = vc * (1 - math.cos(two_pi * tau)) / tr
            return s, sd, sdd
        if t > tt - tr:
            tau = (tt - t) / tr
            s = 1.0 - vc * tr * (
                tau * tau / 2 + (math.cos(two_pi * tau) - 1) / (2 * two_pi * math.pi)
            )
            sd = vc * (tau - math.sin(two_pi * tau) / two_pi)
            sdd = -vc * (1 - math.cos(two_pi * tau)) / tr
            return s, sd, sdd
        s_ramp = vc * tr / 2
        return s_ramp + vc * (t - tr), vc, 0.0

    def course(self, lat: float) -> float:
        """Course chi (clockwise from north) of the path at latitude ``lat``; 0 at rest."""
        p = self.path
        if not (p.dlat != 0.0 or p.dlon != 0.0):
            return 0.0
        return math.atan2(p.dlon * math.cos(lat), p.dlat)

    def latlon(self, t) -> tuple[np.ndarray, np.ndarray]:
        """True latitude and longitude (rad) at the times ``t`` (array)."""
        s = np.array([self.progress(float(x))[0] for x in np.atleast_1d(t)])
        return self.path.lat0 + self.path.dlat * s, self.path.lon0 + self.path.dlon * s

    # ---- full truth at one instant -------------------------------------------------------
    def latlon_rates(self, t: float) -> tuple[float, float, float, float, float, float]:
        """(lat, lon, lat_dot, lat_ddot, lon_dot, lon_ddot) at ``t``: the Earth-relative part
        of :meth:`at`, without the frames."""
        p = self.path
        s, sd, sdd = self.progress(t)
        return (
            p.lat0 + p.dlat * s,
            p.lon0 + p.dlon * s,
            p.dlat * sd,
            p.dlat * sdd,
            p.dlon * sd,
            p.dlon * sdd,
        )

    def at(self, t: float) -> Truth:
        e = self.earth
        lat, lon, lat_dot, lat_ddot, lon_dot, lon_ddot = self.latlon_rates(t)
        lam = lon + e.omega_e * t
        # rows of [T]^{NE} at the inertial longitude: north, east, down in inertial axes
        mat_n_i = frames.mat_ne(lat, lam)
        nwu = np.column_stack((mat_n_i[0], -mat_n_i[1], -mat_n_i[2]))
        return Truth(
            lat=lat,
            lon=lon,
            lat_dot=lat_dot,
            lat_ddot=lat_ddot,
            lon_dot=lon_dot,
            lon_ddot=lon_ddot,
            nwu_i=nwu,
            lam_dot=lon_dot + e.omega_e,
            traj=self,
        )

    def specific_force_in(self, tr: Truth, c_xi: np.ndarray) -> np.ndarray:
        """What ideal accelerometers along the axes of frame(s) ``c_xi`` measure (m/s^2).

        ``c_xi`` is C_x^i (3x3, or n x 3 x 3 for n frames). The attitude relative to NWU is
        split into the paper's C3(psi) C2(phi_y) C1(phi_x) (eq. 2, exact) and the specific
        force comes from the generated eq. 17 (exact in the tilts):
        ``gen.specific_force_platform``. Returns (3,) or (n, 3).
        """
        c = np.einsum("ji,...jk->...ik", tr.nwu_i, c_xi)  # C_x^{NWU}
        psi, phi_y, phi_x = eq2_angles(c)
        e = self.earth
        f = gen.specific_force_platform(
            self.rho,
            e.gm / self.rho**2,
            e.omega_e,
            tr.lat,
            tr.lat_dot,
            tr.lat_ddot,
            tr.lon_dot,
            tr.lon_ddot,
            psi,
            phi_x,
            phi_y,
        )
        return np.stack(f, axis=-1)

    def c3_memo(self, psi: float) -> np.ndarray:
        """:func:`c3` of ``psi``, read-only, kept for the next call with the same ``psi`` (at
        rest the body azimuth never changes)."""
        key = (float(psi), math.copysign(1.0, psi))  # -0.0 is not 0.0 here: sin(-0.0) = -0.0
        if self._c3_last is None or self._c3_last[0] != key:
            matrix = c3(psi)
            matrix.flags.writeable = False
            self._c3_last = (key, matrix)
        return self._c3_last[1]

    def w_nwu_memo(self, lat: float, lat_dot: float, lam_dot: float) -> np.ndarray:
        """The inertial rate of NWU in NWU axes (:attr:`Truth.w_nwu`), read-only, kept for the
        next call with the same arguments (at rest they never change)."""
        key = tuple((float(a), math.copysign(1.0, a)) for a in (lat, lat_dot, lam_dot))
        if self._w_nwu_last is None or self._w_nwu_last[0] != key:
            w = frames.transport_rate_n(lat, lat_dot, lam_dot) * np.array([1.0, -1.0, -1.0])
            w.flags.writeable = False
            self._w_nwu_last = (key, w)
        return self._w_nwu_last[1]

    def body_i(self, tr: Truth) -> np.ndarray:
        """C_b^i (columns = body axes in inertial coordinates) for the truth ``tr``."""
        return tr.nwu_i @ tr.c3_b @ self.mount

    def body_rate(self, tr: Truth) -> np.ndarray:
        """True inertial angular rate of the body, in body axes (rad/s)."""
        w = tr.c3_b.T @ tr.w_nwu + np.array([0.0, 0.0, tr.psi_b_dot])
        return self.mount.T @ w
