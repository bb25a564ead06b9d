"""Scenario files of the altimeter-attitude paper: load, validate, convert to SI units.

A scenario is ``config/scenarios/altimeter_attitude/<name>.yaml`` validated against
``config/schemas/altimeter_attitude_scenario.schema.json``; then semantic checks run (the
trajectory stays in the flight envelope, the duration is a whole number of IMU steps and of
output samples, the transient is shorter than the flight), so that bad input fails with a
message naming the file, the field, the value and what is allowed before any compute starts.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from pathlib import Path
from typing import Any

from pipeline.altimeter_attitude.profiles import Profiles
from pipeline.altimeter_attitude.sensors import InitialSpec, SensorSpec
from pipeline.config import ConfigError, load_schema, load_yaml, sha256_of, validate
from pipeline.scenarios import decisions_with_values, whole_multiple

__all__ = ["Scenario", "load_scenario", "build_scenario", "DEG", "ROOT"]

ROOT = Path(__file__).resolve().parents[2]
DEG = math.pi / 180.0


@dataclass(frozen=True)
class Scenario:
    """A validated scenario, in SI units and radians."""

    name: str
    path: Path
    raw: dict[str, Any]
    profiles: Profiles
    sensors: SensorSpec
    initial: InitialSpec
    k: float
    input_matrix: str
    p0_radial: str
    ukf_alpha: float
    ukf_beta: float
    ukf_kappa: float
    omega_c: float
    xi: float
    n_runs: int
    seed: int
    transient: float
    output_rate: float
    after_bank: (
        float  # rad: the window after the first bank starts when the first bank of this roll ends
    )
    #: runs per workflow job of the Monte Carlo (monte_carlo.chunk_runs; None: one job);
    #: how the runs are spread, not what they give (pipeline/altimeter_attitude/chunks.py)
    chunk_runs: int | None = None

    @property
    def config_sha256(self) -> str:
        return sha256_of(self.raw)

    @property
    def output_every(self) -> int:
        """IMU steps per output sample."""
        return int(round(self.sensors.rate_hz / self.output_rate))

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
    validate(raw, load_schema("altimeter_attitude_scenario"), path)
    tr, se, ie, fi = raw["trajectory"], raw["sensors"], raw["initial_error"], raw["filters"]
    try:
        profiles = Profiles.from_config(tr)
    except ValueError as exc:
        raise ConfigError(f"{path}: trajectory.{exc}") from None
    rate, duration = float(se["imu_rate_hz"]), float(tr["duration_s"])
    if not whole_multiple(duration, 1.0 / rate):
        raise ConfigError(
            f"{path}: trajectory.duration_s = {duration!r}: must be a whole number of IMU steps "
            f"(1 / sensors.imu_rate_hz = {1.0 / rate:g} s)"
        )
    out_rate = float(raw["metrics"]["output_rate_hz"])
    if out_rate > rate or not whole_multiple(rate / out_rate, 1.0):
        raise ConfigError(
            f"{path}: metrics.output_rate_hz = {out_rate!r}: must divide sensors.imu_rate_hz = "
            f"{rate:g} into a whole number of steps"
        )
    if raw["metrics"]["transient_s"] >= duration:
        raise ConfigError(
            f"{path}: metrics.transient_s = {raw['metrics']['transient_s']!r}: must be shorter "
            f"than trajectory.duration_s = {duration:g}"
        )
    k = float(fi["linear_kf"]["k_per_s"])
    if k / rate > 0.5:
        raise ConfigError(
            f"{path}: filters.linear_kf.k_per_s = {k!r}: k dt = {k / rate:g} must be <= 0.5 "
            "(A is frozen over a step; a larger k dt over-corrects the norm)"
        )
    sc = Scenario(
        name=path.stem,
        path=path,
        raw=raw,
        profiles=profiles,
        sensors=SensorSpec(
            gyro_sigma=se["gyro_sigma_deg_s"] * DEG,
            accel_sigma=float(se["accel_sigma_m_s2"]),
            altimeter_sigma=float(se["altimeter_sigma_m"]),
            rate_hz=rate,
            altimeter_every=int(se["altimeter_every"]),
        ),
        initial=InitialSpec(
            roll_sigma=ie["roll_sigma_deg"] * DEG,
            pitch_sigma=ie["pitch_sigma_deg"] * DEG,
            v_d_sigma=float(ie["v_d_sigma_m_s"]),
            h_sigma=float(ie["h_sigma_m"]),
        ),
        k=k,
        input_matrix=fi["linear_kf"]["input_matrix"],
        p0_radial=fi["linear_kf"]["p0_radial"],
        ukf_alpha=float(fi["ukf"]["alpha"]),
        ukf_beta=float(fi["ukf"]["beta"]),
        ukf_kappa=float(fi["ukf"]["kappa"]),
        omega_c=float(fi["complementary"]["omega_c_rad_s"]),
        xi=float(fi["complementary"]["xi"]),
        n_runs=int(raw["monte_carlo"]["n_runs"]),
        seed=int(raw["monte_carlo"]["seed"]),
        transient=float(raw["metrics"]["transient_s"]),
        output_rate=out_rate,
        after_bank=float(raw["metrics"]["after_bank_deg"]) * DEG,
        chunk_runs=raw["monte_carlo"].get("chunk_runs"),
    )
    sc.decisions()  # every decision names a real field
    return sc
