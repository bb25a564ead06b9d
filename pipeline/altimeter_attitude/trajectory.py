"""Truth trajectory of the altimeter-aided attitude scenarios: analytic, from smooth profiles.

The vehicle's motion is given by five smooth *channels* of time (speed, flight-path angle,
heading, roll and angle of attack). Everything the simulation needs -- attitude, body rates,
specific force, velocity, acceleration, vertical velocity and altitude -- follows from them
analytically, at any requested time.

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

Profiles
--------
Each channel is ``value(t) = initial + intensity * sum_i amplitude_i S((t - start_i) /
duration_i)`` with the quintic smoothstep ``S(u) = 10 u^3 - 15 u^4 + 6 u^5`` on [0, 1]
(0 below, 1 above): C2 continuous, with analytic first and second time derivatives
``S'(u) / duration`` and ``S''(u) / duration^2``. Angles, velocities, accelerations and body
rates are therefore closed-form; the specific force is continuous.

Altitude ``h(t) = h0 + int_0^t V sin gam dt'`` has no closed form (``sin`` of a quintic); it
is integrated with 8-node Gauss-Legendre quadrature on pieces cut at the requested times, at
every maneuver start and end (so the integrand is analytic on each piece) and at most
:data:`MAX_QUAD_STEP_S` (or a quarter of the shortest maneuver) long: analytic up to
machine-precision quadrature (errors ~1e-11 m over minutes of flight).
"""

from __future__ import annotations

import math
from dataclasses import dataclass, field
from typing import Any

import numpy as np

__all__ = [
    "CHANNELS",
    "DEFAULT_GRAVITY",
    "MAX_ANGLE_DEG",
    "MIN_SPEED_M_S",
    "Maneuver",
    "Profiles",
    "Truth",
    "altitude",
    "load_factor",
    "mat_from_euler",
    "smoothstep",
    "truth",
]

CHANNELS = ("speed_m_s", "flight_path_deg", "heading_deg", "roll_deg", "alpha_deg")
DEFAULT_GRAVITY = 9.80665
MIN_SPEED_M_S = 1.0  # the speed must stay above this everywhere
MAX_ANGLE_DEG = 80.0  # |flight path|, |pitch| and |roll| must stay below this everywhere
MAX_QUAD_STEP_S = 1.0  # longest Gauss-Legendre piece of the altitude integral
_DEG = math.pi / 180.0
_SCALE = {name: (1.0 if name == "speed_m_s" else _DEG) for name in CHANNELS}
_GL_X, _GL_W = np.polynomial.legendre.leggauss(8)
_CHECK_STEP_S = 0.05  # validation grid step (refined for short maneuvers)
_CHECK_MAX_POINTS = 2_000_000


def smoothstep(u) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """Quintic smoothstep S(u) and its derivatives S'(u), S''(u) (u clipped to [0, 1])."""
    u = np.clip(np.asarray(u, dtype=float), 0.0, 1.0)
    v = 1.0 - u
    s = u**3 * (10.0 - 15.0 * u + 6.0 * u * u)
    ds = 30.0 * u * u * v * v
    dds = 60.0 * u * v * (v - u)
    return s, ds, dds


@dataclass(frozen=True)
class Maneuver:
    """One smoothstep of a channel: start (s), duration (s), effective amplitude (SI/rad).

    ``amplitude`` already includes the scenario's ``intensity`` and the degree -> radian
    conversion.
    """

    channel: str
    start: float
    duration: float
    amplitude: float

    @property
    def end(self) -> float:
        return self.start + self.duration


def _err(field_name: str, value: Any, allowed: str) -> ValueError:
    return ValueError(f"{field_name} = {value!r}: {allowed}")


def _number(value: Any, field_name: str) -> float:
    try:
        x = float(value)
    except (TypeError, ValueError):
        raise _err(field_name, value, "must be a number") from None
    if not math.isfinite(x):
        raise _err(field_name, value, "must be finite")
    return x


@dataclass(frozen=True)
class Profiles:
    """The five channel profiles of a scenario, in SI units and radians.

    ``initial`` maps each channel name of :data:`CHANNELS` to its value at t = 0 (SI/rad).
    """

    duration: float  # s, scenario length
    gravity: float  # m/s^2
    altitude0: float  # m, h(0)
    intensity: float
    initial: dict[str, float] = field(hash=False)
    maneuvers: tuple[Maneuver, ...] = ()
    coordinated: bool = False  # roll adds the coordinated-turn bank atan(V chi_dot cos(gam) / g)

    # ---- construction -----------------------------------------------------------------
    @classmethod
    def from_config(cls, cfg: dict) -> Profiles:
        """Profiles from the parsed scenario dict (degrees at this edge only).

        Raises ValueError, naming the field, its value and what is allowed, for an unknown
        channel, a non-positive duration, a maneuver starting outside [0, duration_s), a
        speed reaching <= 1 m/s, or |flight path|, |pitch| or |roll| reaching >= 80 deg
        anywhere in [0, duration_s] (checked on a fine grid).
        """
        duration = _number(cfg.get("duration_s"), "duration_s")
        if duration <= 0.0:
            raise _err("duration_s", cfg.get("duration_s"), "must be > 0 s")
        gravity = _number(cfg.get("gravity_m_s2", DEFAULT_GRAVITY), "gravity_m_s2")
        if gravity <= 0.0:
            raise _err("gravity_m_s2", gravity, "must be > 0 m/s^2")
        intensity = _number(cfg.get("intensity", 1.0), "intensity")
        init_cfg = cfg.get("initial")
        if not isinstance(init_cfg, dict):
            raise _err("initial", init_cfg, f"must be a mapping with {CHANNELS + ('altitude_m',)}")
        initial: dict[str, float] = {}
        for name in CHANNELS:
            if name not in init_cfg:
                raise _err(f"initial.{name}", None, "is required")
            initial[name] = _number(init_cfg[name], f"initial.{name}") * _SCALE[name]
        if "altitude_m" not in init_cfg:
            raise _err("initial.altitude_m", None, "is required")
        altitude0 = _number(init_cfg["altitude_m"], "initial.altitude_m")
        for name in init_cfg:
            if name not in CHANNELS and name != "altitude_m":
                raise _err(
                    f"initial.{name}",
                    init_cfg[name],
                    f"unknown; allowed: {CHANNELS + ('altitude_m',)}",
                )

        maneuvers = []
        for i, m in enumerate(cfg.get("maneuvers") or ()):
            key = f"maneuvers[{i}]"
            if not isinstance(m, dict):
                raise _err(key, m, "must be a mapping with channel, start_s, duration_s, amplitude")
            ch = m.get("channel")
            if ch not in CHANNELS:
                raise _err(f"{key}.channel", ch, f"unknown channel; allowed: {', '.join(CHANNELS)}")
            start = _number(m.get("start_s"), f"{key}.start_s")
            if not 0.0 <= start < duration:
                raise _err(f"{key}.start_s", start, f"must lie in [0, duration_s = {duration:g}) s")
            dur = _number(m.get("duration_s"), f"{key}.duration_s")
            if dur <= 0.0:
                raise _err(f"{key}.duration_s", dur, "must be > 0 s")
            amp = _number(m.get("amplitude"), f"{key}.amplitude")
            maneuvers.append(Maneuver(ch, start, dur, intensity * amp * _SCALE[ch]))

        coordinated = cfg.get("coordinated_turns", False)
        if not isinstance(coordinated, bool):
            raise _err("coordinated_turns", coordinated, "must be true or false")
        prof = cls(duration, gravity, altitude0, intensity, initial, tuple(maneuvers), coordinated)
        prof._check_envelope()
        return prof

    def _check_envelope(self) -> None:
        """Speed and angle limits on a fine grid of [0, duration] plus every breakpoint."""
        step = _CHECK_STEP_S
        if self.maneuvers:
            step = min(step, min(m.duration for m in self.maneuvers) / 100.0)
        n = int(min(math.ceil(self.duration / step) + 1, _CHECK_MAX_POINTS))
        t = np.linspace(0.0, self.duration, n)
        bps = self.breakpoints()
        t = np.union1d(t, bps[(bps >= 0.0) & (bps <= self.duration)])

        def worst(values, name, unit, scale, limit, low):
            i = int(np.argmin(values) if low else np.argmax(np.abs(values)))
            v = values[i] / scale
            bad = v <= limit if low else abs(v) >= limit
            if bad:
                rel = f"> {limit:g} {unit}" if low else f"within (-{limit:g}, {limit:g}) {unit}"
                raise ValueError(
                    f"{name} reaches {v:.6g} {unit} at t = {t[i]:.6g} s: must stay {rel} "
                    "everywhere in [0, duration_s]; change initial values / maneuver amplitudes"
                )

        speed = self.channel("speed_m_s", t)[0]
        worst(speed, "speed_m_s", "m/s", 1.0, MIN_SPEED_M_S, True)
        gam = self.channel("flight_path_deg", t)[0]
        worst(gam, "flight_path_deg", "deg", _DEG, MAX_ANGLE_DEG, False)
        pitch = gam + self.channel("alpha_deg", t)[0]
        worst(pitch, "pitch (flight_path_deg + alpha_deg)", "deg", _DEG, MAX_ANGLE_DEG, False)
        roll = self.roll(t)[0]
        worst(roll, "roll_deg", "deg", _DEG, MAX_ANGLE_DEG, False)

    # ---- evaluation -------------------------------------------------------------------
    def roll(self, t) -> tuple[np.ndarray, np.ndarray]:
        """Roll and its rate (rad, rad/s): the roll channel, plus with ``coordinated`` the bank
        of a coordinated turn, tan(phi_c) = V chi_dot cos(gam) / g (no side force: the
        horizontal turn acceleration V cos(gam) chi_dot is supplied by the tilted lift)."""
        phi, phi_dot, _ = self.channel("roll_deg", t)
        if not self.coordinated:
            return phi, phi_dot
        V, V_dot, _ = self.channel("speed_m_s", t)
        gam, gam_dot, _ = self.channel("flight_path_deg", t)
        _, chi_dot, chi_ddot = self.channel("heading_deg", t)
        u = V * chi_dot * np.cos(gam) / self.gravity
        u_dot = (
            V_dot * chi_dot * np.cos(gam)
            + V * chi_ddot * np.cos(gam)
            - V * chi_dot * np.sin(gam) * gam_dot
        ) / self.gravity
        return phi + np.arctan(u), phi_dot + u_dot / (1.0 + u**2)

    def breakpoints(self) -> np.ndarray:
        """Sorted unique maneuver starts and ends (s): the profiles are analytic between."""
        pts = [m.start for m in self.maneuvers] + [m.end for m in self.maneuvers]
        return np.unique(np.asarray(pts, dtype=float))

    def channel(self, name: str, t) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """(value, d/dt, d2/dt2) of a channel at times ``t`` (SI; radians for angles)."""
        if name not in CHANNELS:
            raise _err("channel", name, f"unknown channel; allowed: {', '.join(CHANNELS)}")
        t = np.asarray(t, dtype=float)
        val = np.full(t.shape, self.initial[name])
        d1 = np.zeros(t.shape)
        d2 = np.zeros(t.shape)
        for m in self.maneuvers:
            if m.channel != name:
                continue
            s, ds, dds = smoothstep((t - m.start) / m.duration)
            val += m.amplitude * s
            d1 += (m.amplitude / m.duration) * ds
            d2 += (m.amplitude / m.duration**2) * dds
        return val, d1, d2

    def _value(self, name: str, t: np.ndarray) -> np.ndarray:
        """Channel value only (the altitude quadrature needs no derivatives)."""
        val = np.full(t.shape, self.initial[name])
        for m in self.maneuvers:
            if m.channel == name:
                u = np.clip((t - m.start) / m.duration, 0.0, 1.0)
                val += m.amplitude * (u**3 * (10.0 - 15.0 * u + 6.0 * u * u))
        return val


def mat_from_euler(roll, pitch, yaw) -> np.ndarray:
    """C_b^n = Rz(yaw) Ry(pitch) Rx(roll) for arrays of angles (rad): shape (..., 3, 3)."""
    roll, pitch, yaw = np.broadcast_arrays(
        *(np.asarray(a, dtype=float) for a in (roll, pitch, yaw))
    )
    sr, cr = np.sin(roll), np.cos(roll)
    sp, cp = np.sin(pitch), np.cos(pitch)
    sy, cy = np.sin(yaw), np.cos(yaw)
    mat = np.empty(roll.shape + (3, 3))
    mat[..., 0, 0] = cy * cp
    mat[..., 0, 1] = cy * sp * sr - sy * cr
    mat[..., 0, 2] = cy * sp * cr + sy * sr
    mat[..., 1, 0] = sy * cp
    mat[..., 1, 1] = sy * sp * sr + cy * cr
    mat[..., 1, 2] = sy * sp * cr - cy * sr
    mat[..., 2, 0] = -sp
    mat[..., 2, 1] = cp * sr
    mat[..., 2, 2] = cp * cr
    return mat


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
        raise _err("t", f"array of shape {t.shape}", "must be a scalar or a 1-D array of times")
    if not np.all(np.isfinite(t)):
        raise _err("t", "non-finite time", "all times must be finite")
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
    integrand = profiles._value("speed_m_s", nodes) * np.sin(
        profiles._value("flight_path_deg", nodes)
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

    s_phi, c_phi = np.sin(phi), np.cos(phi)
    s_th, c_th = np.sin(theta), np.cos(theta)
    rate_b = np.stack(
        [
            phi_dot - psi_dot * s_th,
            theta_dot * c_phi + psi_dot * c_th * s_phi,
            -theta_dot * s_phi + psi_dot * c_th * c_phi,
        ],
        axis=-1,
    )

    s_g, c_g = np.sin(gam), np.cos(gam)
    s_c, c_c = np.sin(chi), np.cos(chi)
    unit = np.stack([c_g * c_c, c_g * s_c, -s_g], axis=-1)  # d v^n / d V
    d_gam = np.stack([-s_g * c_c, -s_g * s_c, -c_g], axis=-1)  # d unit / d gam
    d_chi = np.stack([-c_g * s_c, c_g * c_c, np.zeros_like(gam)], axis=-1)  # d unit / d chi
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
