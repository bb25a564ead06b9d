"""Helpers the north_finding Snakemake rules call at parse time (scenario discovery, validation)."""

from __future__ import annotations

from pathlib import Path

from pipeline.north_finding.scenario import load_scenario
from pipeline.scenarios import scenario_names, validate_all

__all__ = ["DERIVATION_CODE", "SIMULATION_CODE", "scenarios", "validate_scenarios"]

DERIVATION_CODE = [
    "derivations/frames.py",
    "derivations/codegen.py",
    "derivations/north_finding/symbols.py",
    "derivations/north_finding/sensors.py",
    "derivations/north_finding/leveling.py",
    "derivations/north_finding/azimuth.py",
    "derivations/north_finding/generate.py",
]
SIMULATION_CODE = [
    "pipeline/generated/north_finding.py",
    "pipeline/north_finding/scenario.py",
    "pipeline/north_finding/readings.py",
    "pipeline/north_finding/estimators.py",
    "pipeline/north_finding/run.py",
]


def scenarios(directory: str | Path) -> list[str]:
    """Names of every scenario file ``<directory>/<name>.yaml`` (the workflow runs them all)."""
    return scenario_names(directory)


def validate_scenarios(
    names: list[str], directory: str | Path = "config/scenarios/north_finding"
) -> None:
    """Load and validate every scenario; the first bad file stops the workflow before any job."""
    validate_all(names, directory, load_scenario)
