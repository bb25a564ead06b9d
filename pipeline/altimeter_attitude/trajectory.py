"""Truth trajectory of the altimeter-aided attitude scenarios: analytic, from smooth profiles.

The vehicle's motion is given by five smooth *channels* of time (speed, flight-path angle,
heading, roll and angle of attack; :mod:`pipeline.altimeter_attitude.profiles`). Everything
the simulation needs -- attitude, body rates, specific force, velocity, acceleration, vertical
velocity and altitude -- follows from them analytically, at any requested time.

Coordinate frames and conventions
---------------------------------
* ``n``: navigation frame NED (x north, y east, z down). The Earth is flat and does not
  rotate: the filter model ignores Earth rate, transport rate and curvature, and the gyros
  are taken "after earth-rate compensation", i.e. they measure ``omega_nb^b``.
* gravity ``g^n = [0, 0, g]`` (down), ``g`` a parameter (default 9.80665 m/s^2).
* ``b``: body frame, x forward, y right, z down.
* attitude: Euler 3-2-1 angles yaw ``psi``, pitch ``theta``, roll ``phi``;
  ``mat_nb = C_b^n = Rz(psi) Ry(theta) Rx(phi)`` (active rotations, maps body -> NED
  coordinates). Its third row is ``c = [-sin theta, sin phi cos theta, cos phi cos theta]``.
* body rate relative to NED, in body axes (``rate_b = omega_nb^b``)::

      [phi_dot - psi_dot sin theta,
       theta_dot cos phi + psi_dot cos theta sin phi,
       -theta_dot sin phi + psi_dot cos theta cos phi]

  so that ``d/dt C_b^n = C_b^n [omega_nb^b x]``.
* specific force ``force_b = f^b = C_n^b (a^n - g^n)`` with ``a^n = d/dt v^n``.
* velocity ``v^n = V [cos gam cos chi, cos gam sin chi, -sin gam]`` (speed ``V``,
  flight-path angle ``gam`` positive climbing, heading ``chi`` from north toward east);
  ``v_d = v^n[2] = -V sin gam``; altitude ``h`` is up, ``h_dot = -v_d = V sin gam``.
* attitude from the channels: ``psi = chi``, ``theta = gam + alpha`` (``alpha`` the angle
  of attack channel), ``phi`` the roll channel.

Units are SI and radians inside; degrees appear only in the scenario file (channel names
ending in ``_deg``). Array names follow pyins: ``rate_b``, ``force_b``, ``vel_n``,
``acc_n``, ``mat_nb``.

Altitude
--------
``h(t) = h0 + int_0^t V sin gam dt'`` has no closed form (``sin`` of a quintic); it
is integrated with 8-node Gauss-Legendre quadrature on pieces cut at the requested times, at
every maneuver start and end (so the integrand is analytic on each piece) and at most
:data:`MAX_QUAD_STEP_S` (or a quarter of the shortest maneuver) long: analytic up to
machine-precision quadrature (errors ~1e-11 m over minutes of flight).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from pipeline.altimeter_attitude.profiles import Profiles
from pipeline.generated import altimeter_attitude as gen
from pipeline.generated import frames

__all__ = ["MAX_QUAD_STEP_S", "Truth", "altitude", "load_factor", "mat_from_euler", "truth"]

MAX_QUAD_STEP_S = 1.0  # longest Gauss-Legendre piece of the altitude integral
_GL_X, _GL_W = np.polynomial.legendre.leggauss(8)


def mat_from_euler(roll, pitch, yaw) -> np.ndarray:
    """C_b^n = Rz(yaw) Ry(pitch) Rx(roll) for arrays of angles (rad): shape (..., 3, 3).

    The transpose of the generated 3-2-1 ``[T]^{TN}`` (``pipeline.generated.frames.mat_tn``).
    """
    return np.swapaxes(frames.mat_tn(yaw, pitch, roll), -1, -2)


@dataclass(frozen=True)
class Truth:
    """Truth at the times ``t`` (n,): angles in rad, vectors (n, 3) in SI units."""

    t: np.ndarray  # s
    roll: np.ndarray  # phi, rad
    pitch: np.ndarray  # theta = gam + alpha, rad
    yaw: np.ndarray  # psi = chi, rad
    rate_b: np.ndarray  # omega_nb^b, rad/s
    force_b: np.ndarray  # f^b = C_n^b (a^n - g^n), m/s^2
    vel_n: np.ndarray  # v^n (NED), m/s
    acc_n: np.ndarray  # a^n = d/dt v^n, m/s^2
    v_d: np.ndarray  # v^n[2] (down), m/s
    h: np.ndarray  # altitude (up), m
    c: np.ndarray  # third row of C_b^n
    speed: np.ndarray  # V, m/s
    flight_path: np.ndarray  # gam, rad
    alpha: np.ndarray  # angle of attack channel, rad
    gravity: float  # g, m/s^2

    @property
    def mat_nb(self) -> np.ndarray:
        """C_b^n (n, 3, 3), body -> NED."""
        return mat_from_euler(self.roll, self.pitch, self.yaw)

    @property
    def gravity_n(self) -> np.ndarray:
        """g^n = [0, 0, g]."""
        return np.array([0.0, 0.0, self.gravity])


def _times(t) -> np.ndarray:
    t = np.atleast_1d(np.asarray(t, dtype=float))
    if t.ndim != 1:
        raise ValueError(
            f"t = 'array of shape {t.shape}': must be a scalar or a 1-D array of times"
        )
    if not np.all(np.isfinite(t)):
        raise ValueError("t = 'non-finite time': all times must be finite")
    return t


def altitude(profiles: Profiles, t) -> np.ndarray:
    """h(t) = h0 + int_0^t V sin(gam) dt' (m), 8-node Gauss-Legendre on analytic pieces.

    The pieces are cut at 0, at every requested time and at every maneuver start/end, and
    are subdivided to at most ``min(MAX_QUAD_STEP_S, shortest maneuver / 4)``. Times may be
    in any order, repeated, start after 0 (or even before: the profiles are constant there).
    """
    t = _times(t)
    knots = np.unique(np.concatenate(([0.0], t)))
    bps = profiles.breakpoints()
    bps = bps[(bps > knots[0]) & (bps < knots[-1])]
    knots = np.unique(np.concatenate((knots, bps)))
    a, b = knots[:-1], knots[1:]
    max_step = MAX_QUAD_STEP_S
    if profiles.maneuvers:
        max_step = min(max_step, min(m.duration for m in profiles.maneuvers) / 4.0)
    n_sub = np.maximum(1, np.ceil((b - a) / max_step)).astype(np.int64)
    piece = np.repeat(np.arange(a.size), n_sub)
    first = np.repeat(np.cumsum(n_sub) - n_sub, n_sub)
    j = np.arange(piece.size) - first
    width = (b - a)[piece] / n_sub[piece]
    lo = a[piece] + width * j
    hi = np.where(j + 1 == n_sub[piece], b[piece], lo + width)
    mid, half = 0.5 * (lo + hi), 0.5 * (hi - lo)
    nodes = mid[:, None] + half[:, None] * _GL_X[None, :]
    integrand = gen.climb_rate(
        profiles.channel_value("speed_m_s", nodes), profiles.channel_value("flight_path_deg", nodes)
    )
    sub = half * (integrand @ _GL_W)
    per_piece = np.bincount(piece, weights=sub, minlength=a.size)
    cum = np.concatenate(([0.0], np.cumsum(per_piece)))
    cum -= cum[np.searchsorted(knots, 0.0)]
    return profiles.altitude0 + cum[np.searchsorted(knots, t)]


def truth(profiles: Profiles, t) -> Truth:
    """The truth at times ``t`` (s; any order, repeats allowed), all analytic and vectorised."""
    t = _times(t)
    V, V_dot, _ = profiles.channel("speed_m_s", t)
    gam, gam_dot, _ = profiles.channel("flight_path_deg", t)
    chi, chi_dot, _ = profiles.channel("heading_deg", t)
    phi, phi_dot = profiles.roll(t)
    alpha, alpha_dot, _ = profiles.channel("alpha_deg", t)
    theta, theta_dot = gam + alpha, gam_dot + alpha_dot
    psi, psi_dot = chi, chi_dot

    # eq. 4: body rate relative to NED from the Euler rates (generated 3-2-1 Euler-rate map)
    rate_b = frames.body_rate_from_euler_rates(theta, phi, phi_dot, theta_dot, psi_dot)

    # v^n = V u(gam, chi) and the partials of u (generated flight-path direction)
    u = np.stack(gen.flight_path_direction(gam, chi), axis=-1).reshape(-1, 3, 3)
    unit, d_gam, d_chi = u[:, 0], u[:, 1], u[:, 2]
    vel_n = V[:, None] * unit
    acc_n = V_dot[:, None] * unit + (V * gam_dot)[:, None] * d_gam + (V * chi_dot)[:, None] * d_chi

    mat_nb = mat_from_euler(phi, theta, psi)
    g_n = np.array([0.0, 0.0, profiles.gravity])
    force_b = np.einsum("nji,nj->ni", mat_nb, acc_n - g_n)
    return Truth(
        t=t,
        roll=phi,
        pitch=theta,
        yaw=psi,
        rate_b=rate_b,
        force_b=force_b,
        vel_n=vel_n,
        acc_n=acc_n,
        v_d=vel_n[:, 2].copy(),
        h=altitude(profiles, t),
        c=mat_nb[:, 2, :].copy(),
        speed=V,
        flight_path=gam,
        alpha=alpha,
        gravity=profiles.gravity,
    )


def load_factor(tr: Truth) -> np.ndarray:
    """||f^b|| / g (n,): 1 in steady flight; far from 1, accelerometer leveling fails."""
    return np.linalg.norm(tr.force_b, axis=-1) / tr.gravity
