"""Scenario files of the north-finding paper: load, validate, and check method needs.

A scenario is ``config/scenarios/north_finding/<name>.yaml`` validated against
``config/schemas/north_finding_scenario.schema.json``; then semantic checks run
(table positions each method needs, the readings CSV) so that bad input fails
with a clear message before any compute starts.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cache
from pathlib import Path
from typing import Any

import numpy as np

from pipeline.config import (
    ConfigError,
    inside_repository,
    load_schema,
    load_yaml,
    sha256_of,
    validate,
)
from pipeline.scenarios import decisions_with_values

__all__ = [
    "Scenario",
    "load_scenario",
    "build_scenario",
    "POSITION_NEEDS",
    "ROOT",
    "scenario_data_files",
    "scenario_trials_format",
]

ROOT = Path(__file__).resolve().parents[2]
ARCSEC = np.pi / (180 * 3600)
DEG_PER_H = np.pi / (180 * 3600)  # 1 deg/h in rad/s
MICRO_G = 1e-6

# Table positions (axis, tau_deg) each method reads; "ls" = the least-squares set,
# "a2" = the method-2 angle, "peak" = the method-3 maximum search.
POSITION_NEEDS: dict[str, tuple[tuple[str, float | str], ...]] = {
    "L1": (("x", 0.0), ("x", 90.0), ("x", 180.0), ("x", 270.0)),
    "L2": (("x", "ls"),),
    "L3": (("y", 0.0), ("y", 90.0), ("y", 180.0), ("y", 270.0)),
    "L4": (("y", "ls"),),
    "L5": (("x", 0.0), ("x", 90.0), ("x", 180.0), ("z", "z")),
    "A1c1": (("x", 0.0), ("x", 180.0)),
    "A1c2": (("x", 90.0), ("x", 270.0)),
    "A2": (("x", "a2"),),
    "A3": (("x", "peak"),),
    "A4": (("x", 0.0), ("x", 90.0), ("x", 180.0)),
    "A5": (("x", 0.0), ("x", 90.0), ("x", 180.0)),
    "A6": (("x", 0.0), ("x", 90.0), ("x", 180.0), ("z", "z")),
}
MIN_LS_POSITIONS = 3  # eqs. 21, 26: "n >= 3"


@dataclass(frozen=True)
class SensorErrors:
    """Errors of the single real sensor, in SI units (rad, m/s^2 or rad/s)."""

    scale: float  # S = 1 + sf
    misalignment: dict[str, float]  # rad, keys xy, xz, yx, yz, zx, zy
    bias: float  # m/s^2 (accelerometer) or rad/s (gyro)
    sigma: float  # per-sample noise sigma, m/s^2 or rad/s

    def without(self, *sources: str) -> SensorErrors:
        """A copy with the named error sources switched off (scale_factor, misalignment, bias, noise)."""
        return SensorErrors(
            scale=1.0 if "scale_factor" in sources else self.scale,
            misalignment={k: 0.0 for k in self.misalignment}
            if "misalignment" in sources
            else dict(self.misalignment),
            bias=0.0 if "bias" in sources else self.bias,
            sigma=0.0 if "noise" in sources else self.sigma,
        )


@dataclass(frozen=True)
class Scenario:
    """A validated scenario with values converted to SI units and radians."""

    name: str
    path: Path
    raw: dict[str, Any]
    kind: str  # simulated | readings
    lat: float
    g: float
    omega_ie: float
    methods: tuple[str, ...]
    level_source: str
    compass_offset: float | None
    compass_heading: float | None
    truth: dict[str, float] | None  # psi, theta, phi in rad
    table: dict[str, Any] | None
    accel: SensorErrors | None
    gyro: SensorErrors | None
    n_samples: int | None
    n_trials: int | None
    seed: int | None
    sensitivity: dict[str, Any] | None
    readings_csv: Path | None
    ranking: dict[str, Any] | None = None
    n_inference: dict[str, Any] | None = None
    #: the per-trial results' form: auto (CSV up to trials_file.CSV_MAX_TRIALS trials, else
    #: binary), csv or npy (pipeline/north_finding/trials_file.py)
    trials_file: str = "auto"

    @property
    def config_sha256(self) -> str:
        return sha256_of(self.raw)

    def ls_positions_deg(self) -> list[float]:
        return [float(x) for x in self.table["ls_positions_deg"]] if self.table else []

    def decisions(self) -> list[dict[str, Any]]:
        """Each decision with the value found at its field (ConfigError if the field is missing)."""
        return decisions_with_values(self.raw, self.path)


def _sensor(raw: dict[str, Any], bias_unit: float, nominal: float) -> SensorErrors:
    return SensorErrors(
        scale=1.0 + raw["scale_factor_ppm"] * 1e-6,
        misalignment={k: v * ARCSEC for k, v in raw["misalignment_arcsec"].items()},
        bias=raw["bias"] * bias_unit,
        sigma=raw["noise_sigma_frac"] * nominal,
    )


def load_scenario(path: str | Path) -> Scenario:
    """Load and validate one scenario file; ConfigError names file, field, value and range."""
    path = Path(path)
    return build_scenario(load_yaml(path), path)


def build_scenario(raw: Any, path: Path, base: Path = ROOT) -> Scenario:
    """Validate a parsed scenario (from a file or the CLI); ``path`` names it in errors.

    ``readings_csv`` is resolved relative to ``base`` (the repository root for files).
    """
    if not isinstance(raw, dict):
        raise ConfigError(f"{path}: a scenario must be a mapping, got {type(raw).__name__}")
    validate(raw, load_schema("north_finding_scenario"), path)
    site = raw["site"]
    lat = np.deg2rad(site["lat_deg"])
    g, omega_ie = float(site["g_m_s2"]), float(site["omega_ie_rad_s"])
    compass = raw["compass"]
    if raw["type"] == "simulated" and "offset_deg" not in compass:
        raise ConfigError(f"{path}: compass.offset_deg is required for a simulated scenario")
    if raw["type"] == "readings" and "heading_deg" not in compass:
        raise ConfigError(
            f"{path}: compass.heading_deg (the coarse heading of your compass, deg) is required "
            "for a readings scenario"
        )
    truth = raw.get("truth")
    sc = Scenario(
        name=path.stem,
        path=path,
        raw=raw,
        kind=raw["type"],
        lat=float(lat),
        g=g,
        omega_ie=omega_ie,
        methods=tuple(raw["methods"]),
        level_source=raw["level_source"],
        compass_offset=np.deg2rad(compass["offset_deg"]) if "offset_deg" in compass else None,
        compass_heading=np.deg2rad(compass["heading_deg"]) if "heading_deg" in compass else None,
        truth={k.removesuffix("_deg"): float(np.deg2rad(v)) for k, v in truth.items()}
        if truth
        else None,
        table=raw.get("table"),
        accel=_sensor(raw["accelerometer"], MICRO_G * g, g) if "accelerometer" in raw else None,
        gyro=_sensor(raw["gyro"], DEG_PER_H, omega_ie) if "gyro" in raw else None,
        n_samples=raw.get("averaging", {}).get("n_samples"),
        n_trials=raw.get("monte_carlo", {}).get("n_trials"),
        seed=raw.get("monte_carlo", {}).get("seed"),
        sensitivity=raw.get("sensitivity"),
        readings_csv=_readings_path(raw, path, base),
        ranking=raw.get("ranking"),
        n_inference=raw.get("n_inference"),
        trials_file=raw.get("monte_carlo", {}).get("trials_file", "auto"),
    )
    _check_semantics(sc)
    sc.decisions()  # every decision names a real field
    return sc


def _readings_path(raw: dict[str, Any], path: Path, base: Path) -> Path | None:
    """``base / readings_csv``. A workflow scenario file (``<repo>/config/scenarios/<slug>/``)
    reads a CSV inside its repository (a workflow input, resolved against that root); the
    command line (``base`` /) and a scenario file elsewhere any file."""
    if "readings_csv" not in raw:
        return None
    where = Path(path).absolute().parents
    if (
        base == ROOT
        and len(where) > 3
        and where[1].name == "scenarios"
        and where[2].name == "config"
    ):
        return inside_repository(str(raw["readings_csv"]), "readings_csv", path, where[3])
    return base / raw["readings_csv"]


def _check_semantics(sc: Scenario) -> None:
    if sc.level_source != "truth" and sc.level_source not in sc.methods:
        raise ConfigError(
            f"{sc.path}: level_source = {sc.level_source!r} must be 'truth' or one of the "
            f"levelling methods listed in methods {list(sc.methods)}"
        )
    if (
        sc.level_source == "truth"
        and sc.truth is None
        and any(m.startswith("A") for m in sc.methods)
    ):
        raise ConfigError(
            f"{sc.path}: level_source = 'truth' needs a 'truth' block; give one or use a levelling "
            "method (L1..L4)"
        )
    if sc.kind == "simulated":
        n_ls = len(sc.ls_positions_deg())
        for m in ("L2", "L4"):
            if m in sc.methods and n_ls < MIN_LS_POSITIONS:
                raise ConfigError(
                    f"{sc.path}: table.ls_positions_deg has {n_ls} positions, but method {m} "
                    f"(least squares, eqs. 21/26) needs at least {MIN_LS_POSITIONS}"
                )
        if sc.ranking is not None and sc.n_trials is None:
            raise ConfigError(
                f"{sc.path}: ranking needs monte_carlo (its seed): add a monte_carlo block"
            )
        _check_n_inference(sc)
        ms = sc.table["max_search"]
        if ms["mode"] == "scan" and "step_deg" not in ms:
            raise ConfigError(
                f"{sc.path}: table.max_search.step_deg is required when mode = 'scan' "
                "(allowed: 0 < step_deg <= 90)"
            )
    else:
        if "A2" in sc.methods and "a2_tau_deg" not in sc.raw:
            raise ConfigError(f"{sc.path}: a2_tau_deg is required when method A2 runs on readings")
        if sc.readings_csv is None or not sc.readings_csv.is_file():
            raise ConfigError(
                f"{sc.path}: readings_csv = {sc.raw.get('readings_csv')!r}: file not found"
            )
        _check_readings(sc)


def _check_readings(sc: Scenario) -> None:
    """Load the readings CSV (its errors name the file, row, column and value) and check that
    every method finds the readings it needs, before any compute."""
    from pipeline.north_finding import readings as rd  # readings imports this module

    readings = rd.load_readings_csv(sc.readings_csv)
    rd.check_site(readings, sc.readings_csv, sc.g, sc.omega_ie)
    try:
        rd.check_needs(readings, sc.methods, sc.raw.get("a2_tau_deg"))
    except ValueError as exc:
        raise ConfigError(f"{sc.path}: readings_csv {sc.readings_csv.name}: {exc}") from exc


def _check_n_inference(sc: Scenario) -> None:
    if sc.n_inference is None:
        return
    if sc.n_trials is None:
        raise ConfigError(
            f"{sc.path}: n_inference needs monte_carlo (its seed and trials): add a monte_carlo block"
        )
    grid = list(sc.n_inference["n_avg"])
    if grid != sorted(grid):
        raise ConfigError(
            f"{sc.path}: n_inference.n_avg = {grid}: allowed: strictly ascending counts >= 1 "
            "(the robust likelihood takes the first, smallest N as the widest spread)"
        )


def scenario_data_files(path: str | Path) -> list[str]:
    """The data files a scenario reads besides itself (its ``readings_csv``), as written in it
    (paths relative to the repository root): inputs of the step that runs it."""
    raw = load_yaml(path)
    if isinstance(raw, dict) and isinstance(raw.get("readings_csv"), str):
        return [raw["readings_csv"]]
    return []


@cache
def scenario_trials_format(path: str | Path) -> str:
    """``csv`` or ``npy``: the form of a scenario's per-trial results
    (:func:`pipeline.north_finding.trials_file.trials_format` of its ``monte_carlo`` block; CSV
    for a readings scenario), read when the workflow is parsed to name the step's outputs."""
    from pipeline.north_finding.trials_file import FORMATS, trials_format

    raw = load_yaml(path)
    mc = raw.get("monte_carlo") if isinstance(raw, dict) else None
    if not isinstance(mc, dict) or raw.get("type") != "simulated":
        return "csv"
    n, setting = mc.get("n_trials"), mc.get("trials_file", "auto")
    if not isinstance(n, int) or setting not in ("auto", *FORMATS):
        return "csv"  # a bad value: the scenario's validation names it
    return trials_format(n, setting)
