"""Motion profiles of the altimeter-aided attitude scenarios: five smooth *channels* of time
(speed, flight-path angle, heading, roll and angle of attack), read from the scenario file and
checked against the flight envelope. :mod:`pipeline.altimeter_attitude.trajectory` turns them
into the truth (attitude, body rates, specific force, altitude).

Profiles
--------
Each channel is ``value(t) = initial + intensity * sum_i amplitude_i S((t - start_i) /
duration_i)`` with the quintic smoothstep ``S(u) = 10 u^3 - 15 u^4 + 6 u^5`` on [0, 1]
(0 below, 1 above): C2 continuous, with analytic first and second time derivatives
``S'(u) / duration`` and ``S''(u) / duration^2``. Angles, velocities, accelerations and body
rates are therefore closed-form; the specific force is continuous.

Units are SI and radians inside; degrees appear only in the scenario file (channel names
ending in ``_deg``).

>>> s, ds, dds = smoothstep([0.0, 0.5, 1.0])
>>> s.tolist(), ds.tolist()
([0.0, 0.5, 1.0], [0.0, 1.875, 0.0])
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
    "smoothstep",
]

CHANNELS = ("speed_m_s", "flight_path_deg", "heading_deg", "roll_deg", "alpha_deg")
DEFAULT_GRAVITY = 9.80665
MIN_SPEED_M_S = 1.0  # the speed must stay above this everywhere
MAX_ANGLE_DEG = 80.0  # |flight path|, |pitch| and |roll| must stay below this everywhere
_DEG = math.pi / 180.0
_SCALE = {name: (1.0 if name == "speed_m_s" else _DEG) for name in CHANNELS}
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

    def channel_value(self, name: str, t: np.ndarray) -> np.ndarray:
        """Channel value only, no derivatives (what the altitude quadrature needs)."""
        val = np.full(t.shape, self.initial[name])
        for m in self.maneuvers:
            if m.channel == name:
                u = np.clip((t - m.start) / m.duration, 0.0, 1.0)
                val += m.amplitude * (u**3 * (10.0 - 15.0 * u + 6.0 * u * u))
        return val
