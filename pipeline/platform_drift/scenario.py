"""Scenario files of the platform-drift paper: load, validate, convert to SI units.

A scenario is ``config/scenarios/platform_drift/<name>.yaml`` validated against
``config/schemas/platform_drift_scenario.schema.json`` (unknown keys, unknown drift cases,
non-positive durations and out-of-range latitudes fail there); then semantic checks run
(the path stays away from the poles, the ramps fit in the travel time, the durations are
whole numbers of output steps), so that bad input fails with a message naming the file,
the field, the value and what is allowed before any compute starts.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import numpy as np

from pipeline.config import ConfigError, load_schema, load_yaml, sha256_of, validate
from pipeline.platform_drift.trajectory import Earth, Trajectory
from pipeline.platform_drift.trajectory import Path as TrajPath
from pipeline.scenarios import decisions_with_values, whole_multiple

__all__ = [
    "Scenario",
    "load_scenario",
    "build_scenario",
    "CASES",
    "DEG",
    "DEG_PER_H",
    "MAX_PATH_LAT_DEG",
    "ROOT",
]

ROOT = Path(__file__).resolve().parents[2]
DEG = math.pi / 180.0
DEG_PER_H = DEG / 3600.0  # 1 deg/h in rad/s
CASES = ("none", "ch1", "ch3", "ch1_ch3")
AXES = {"x": 0, "y": 1, "z": 2}
# eq. 16 (lon_dot = .../cos(lat)) and the NED strapdown are singular at the poles
MAX_PATH_LAT_DEG = 85.0


@dataclass(frozen=True)
class Scenario:
    """A validated scenario, in SI units and radians."""

    name: str
    path: Path
    raw: dict[str, Any]
    earth: Earth
    route: TrajPath
    psi0: float
    initial_level: str
    drift_compensation_lost: bool
    b_g1: float  # rad/s
    b_g3: float  # rad/s
    cases: tuple[str, ...]
    ch1_axis: int
    ch3_axis: int
    analytic_alpha: str
    duration: float
    output_step: float
    long_duration: float | None
    rtol: float

    @property
    def config_sha256(self) -> str:
        return sha256_of(self.raw)

    def trajectory(self) -> Trajectory:
        return Trajectory(self.earth, self.route, self.psi0)

    def platform_drift(self, case: str) -> np.ndarray:
        """Drift [b_g1, b_g2, b_g3] of the platform gyros (rad/s) in ``case``.

        Channel 1/2 drift is dropped when the alignment's compensation is kept (eq. 26);
        channel 3 always acts (eq. 25: r_0+ = b_g3).
        """
        b1 = self.b_g1 if case in ("ch1", "ch1_ch3") and self.drift_compensation_lost else 0.0
        b3 = self.b_g3 if case in ("ch3", "ch1_ch3") else 0.0
        return np.array([b1, 0.0, b3])

    def strapdown_drift(self, case: str) -> np.ndarray:
        """Drift of the strapdown gyros in body axes (rad/s) in ``case``."""
        out = np.zeros(3)
        if case in ("ch1", "ch1_ch3"):
            out[self.ch1_axis] += self.b_g1
        if case in ("ch3", "ch1_ch3"):
            out[self.ch3_axis] += self.b_g3
        return out

    def times(self, duration: float) -> np.ndarray:
        """Output times 0, step, ..., duration (exact multiples of the step)."""
        n = int(round(duration / self.output_step))
        return self.output_step * np.arange(n + 1, dtype=float)

    def decisions(self) -> list[dict[str, Any]]:
        """Each decision with the value found at its field (ConfigError if the field is missing)."""
        return decisions_with_values(self.raw, self.path)


def load_scenario(path: str | Path) -> Scenario:
    """Load and validate one scenario file; ConfigError names file, field, value and range."""
    path = Path(path)
    return build_scenario(load_yaml(path), path)


def build_scenario(raw: Any, path: Path) -> Scenario:
    """Validate a parsed scenario; ``path`` names it in errors."""
    if not isinstance(raw, dict):
        raise ConfigError(f"{path}: a scenario must be a mapping, got {type(raw).__name__}")
    validate(raw, load_schema("platform_drift_scenario"), path)
    e, s, p, pf = raw["earth"], raw["start"], raw["path"], raw["platform"]
    lat_end = s["lat_deg"] + p["delta_lat_deg"]
    if not -MAX_PATH_LAT_DEG <= lat_end <= MAX_PATH_LAT_DEG:
        raise ConfigError(
            f"{path}: path.delta_lat_deg = {p['delta_lat_deg']!r}: the path would end at latitude "
            f"{lat_end:g} deg; start.lat_deg + path.delta_lat_deg must lie in "
            f"[-{MAX_PATH_LAT_DEG:g}, {MAX_PATH_LAT_DEG:g}] (eq. 16 and the NED strapdown are "
            "singular at the poles)"
        )
    if abs(s["lat_deg"]) > MAX_PATH_LAT_DEG:
        raise ConfigError(
            f"{path}: start.lat_deg = {s['lat_deg']!r}: must lie in "
            f"[-{MAX_PATH_LAT_DEG:g}, {MAX_PATH_LAT_DEG:g}] (eq. 16 is singular at the poles)"
        )
    # latitude 0 is allowed: eq. 36 (which divides by sin(lat0)) is then not_checkable
    moving = p["delta_lat_deg"] != 0 or p["delta_lon_deg"] != 0
    if moving and 2 * p["ramp_s"] > p["travel_time_s"]:
        raise ConfigError(
            f"{path}: path.ramp_s = {p['ramp_s']!r}: must be <= travel_time_s / 2 = "
            f"{p['travel_time_s'] / 2:g} (acceleration and deceleration must fit in the travel time)"
        )
    step = raw["output_step_s"]
    for key in ("duration_s", "long_duration_s"):
        if key in raw and not whole_multiple(raw[key], step):
            raise ConfigError(
                f"{path}: {key} = {raw[key]!r}: must be a whole number of output_step_s = {step!r}"
            )
    if "long_duration_s" in raw and raw["long_duration_s"] < raw["duration_s"]:
        raise ConfigError(
            f"{path}: long_duration_s = {raw['long_duration_s']!r}: must be >= duration_s = "
            f"{raw['duration_s']!r}"
        )
    sc = Scenario(
        name=path.stem,
        path=path,
        raw=raw,
        earth=Earth(float(e["radius_m"]), float(e["gm_m3_s2"]), float(e["omega_e_rad_s"])),
        route=TrajPath(
            lat0=s["lat_deg"] * DEG,
            lon0=s["lon_deg"] * DEG,
            altitude=float(s["altitude_m"]),
            dlat=p["delta_lat_deg"] * DEG,
            dlon=p["delta_lon_deg"] * DEG,
            travel_time=float(p["travel_time_s"]),
            ramp=float(p["ramp_s"]),
        ),
        psi0=pf["psi0_deg"] * DEG,
        initial_level=pf["initial_level"],
        drift_compensation_lost=bool(pf["drift_compensation_lost"]),
        b_g1=raw["drift"]["ch1_deg_h"] * DEG_PER_H,
        b_g3=raw["drift"]["ch3_deg_h"] * DEG_PER_H,
        cases=tuple(raw["cases"]),
        ch1_axis=AXES[raw["strapdown"]["ch1_axis"]],
        ch3_axis=AXES[raw["strapdown"]["ch3_axis"]],
        analytic_alpha=raw["analytic"]["alpha"],
        duration=float(raw["duration_s"]),
        output_step=float(step),
        long_duration=float(raw["long_duration_s"]) if "long_duration_s" in raw else None,
        rtol=float(raw["integrator"]["rtol"]),
    )
    sc.decisions()  # every decision names a real field
    return sc
