"""Helpers for the altimeter_attitude Snakemake rules (scenario discovery, parse-time validation)."""

from __future__ import annotations

from pathlib import Path

from pipeline.altimeter_attitude.scenario import load_scenario
from pipeline.scenarios import scenario_names, validate_all

__all__ = ["SIMULATION_CODE", "RESULT_FILES", "FIGURES", "scenarios", "validate_scenarios"]

SIMULATION_CODE = [
    "pipeline/generated/altimeter_attitude.py",
    "pipeline/altimeter_attitude/scenario.py",
    "pipeline/altimeter_attitude/trajectory.py",
    "pipeline/altimeter_attitude/sensors.py",
    "pipeline/altimeter_attitude/model.py",
    "pipeline/altimeter_attitude/linear_kf.py",
    "pipeline/altimeter_attitude/ukf.py",
    "pipeline/altimeter_attitude/euler_filters.py",
    "pipeline/altimeter_attitude/complementary.py",
    "pipeline/altimeter_attitude/estimates.py",
    "pipeline/altimeter_attitude/metrics.py",
    "pipeline/altimeter_attitude/run.py",
]
# every scenario writes these
RESULT_FILES = ["rms_summary", "noise_free", "run_rms", "timeseries", "truth"]
# Figs 2-12 of the paper (published scenario), our filter comparison, and the sweep
FIGURES = [
    "fig2_third_row.png",
    "fig3_specific_force.png",
    "fig4_vertical_channel.png",
    "fig5_angular_rates.png",
    "fig6_roll_pitch.png",
    "fig7_lkf_rms_error.png",
    "fig8_lkf_c_rms.png",
    "fig9_lkf_sigma.png",
    "fig10_norm_error.png",
    "fig11_ukf_sigma.png",
    "fig12_ukf_rms_error.png",
    "fig_compare_filters.png",
]
SWEEP_FIGURE = "fig_sweep.png"


def scenarios(directory: str | Path = "config/scenarios/altimeter_attitude") -> list[str]:
    """Names of every scenario file ``<directory>/<name>.yaml`` (the workflow runs them all)."""
    return scenario_names(directory)


def validate_scenarios(
    names: list[str], directory: str | Path = "config/scenarios/altimeter_attitude"
) -> None:
    """Load and validate every scenario; the first bad file stops the workflow before any job."""
    validate_all(names, directory, load_scenario)
