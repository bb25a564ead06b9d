"""A pendulum scenario file, validated (``config/schemas/pendulum_scenario.schema.json``)."""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path
from typing import Any

from pipeline.config import ConfigError, load_schema, load_yaml, validate
from pipeline.scenarios import decisions_with_values

__all__ = ["Scenario", "load_scenario"]


@dataclass(frozen=True)
class Scenario:
    name: str
    length_m: float
    g_m_s2: float
    amplitudes_deg: tuple[float, ...]
    raw: dict[str, Any]


def load_scenario(path: str | Path) -> Scenario:
    """Load and validate one scenario; ConfigError names the file, field, value and range."""
    path = Path(path)
    raw = load_yaml(path)
    if not isinstance(raw, dict):
        raise ConfigError(f"{path}: a scenario must be a mapping")
    validate(raw, load_schema("pendulum_scenario"), path)
    decisions_with_values(raw, path)  # every decision names a real field
    return Scenario(
        path.stem, float(raw["length_m"]), float(raw["g_m_s2"]), tuple(raw["amplitudes_deg"]), raw
    )
