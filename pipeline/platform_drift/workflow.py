"""Helpers for a platform_drift Snakemake rule (scenario discovery, validation at parse time)."""

from __future__ import annotations

from pathlib import Path

from pipeline.platform_drift.scenario import load_scenario
from pipeline.scenarios import scenario_names, validate_all

__all__ = ["SIMULATION_CODE", "RESULT_FILES", "scenarios", "validate_scenarios"]

SIMULATION_CODE = [
    "pipeline/generated/platform_drift.py",
    "pipeline/platform_drift/scenario.py",
    "pipeline/platform_drift/trajectory.py",
    "pipeline/platform_drift/platform.py",
    "pipeline/platform_drift/strapdown.py",
    "pipeline/platform_drift/analytic.py",
    "pipeline/platform_drift/run.py",
]
# every scenario writes these; scenarios with long_duration_s also errors_long*.csv
RESULT_FILES = ["errors.csv", "errors_diagnostic.csv", "summary.csv", "provenance.json"]


def scenarios(directory: str | Path = "config/scenarios/platform_drift") -> list[str]:
    """Names of every scenario file ``<directory>/<name>.yaml`` (the workflow runs them all)."""
    return scenario_names(directory)


def validate_scenarios(
    names: list[str], directory: str | Path = "config/scenarios/platform_drift"
) -> None:
    """Load and validate every scenario; the first bad file stops the workflow before any job."""
    validate_all(names, directory, load_scenario)
