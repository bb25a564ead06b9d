"""Where the altimeter-attitude results hold the reproduced value of a published item.

An item selects ``{filter: <name>}``; its quantity is ``roll_rms_deg`` or ``pitch_rms_deg``,
read from ``rms_summary.csv`` of the published scenario (RMS over runs and over time after
the transient), with the Monte Carlo standard error of that RMS (delta method over the per-run
mean squares of ``run_rms.csv``) as its standard error.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from pipeline.altimeter_attitude.columns import ALTIMETER_FILTERS
from pipeline.config import ConfigError
from pipeline.verdicts.kinds import Found
from pipeline.verdicts.published import Problem

__all__ = ["ANGLES", "RMS_QUANTITIES", "ScenarioResults", "check_item", "locate", "standard_error"]

ANGLES = ("roll", "pitch")
RMS_QUANTITIES = ("roll_rms_deg", "pitch_rms_deg")


class ScenarioResults:
    """The result files of one scenario, read once, and its transient (s)."""

    def __init__(self, directory: str | Path, transient: float) -> None:
        d = Path(directory)
        self.directory = d
        self.transient = float(transient)
        self.summary = pd.read_csv(d / "rms_summary.csv").set_index("filter")
        self.run_rms = pd.read_csv(d / "run_rms.csv")
        self.series = pd.read_csv(d / "timeseries.csv")
        truth = pd.read_csv(d / "truth.csv", usecols=["t_s", "load_factor"])
        self.load_factor = truth.set_index(truth["t_s"].round(9))["load_factor"]

    def need(self, filt: str, source: str) -> None:
        if filt not in self.summary.index:
            raise ConfigError(
                f"{source}: filter {filt!r} has no results in {self.directory}; "
                f"available: {sorted(self.summary.index)}"
            )

    def curve(self, filt: str, column: str) -> pd.Series:
        rows = self.series[self.series["filter"] == filt]
        return rows.set_index("t_s")[column].sort_index()

    def per_run(self, filt: str, angle: str) -> np.ndarray:
        rows = self.run_rms[self.run_rms["filter"] == filt].sort_values("run")
        return rows[f"{angle}_rms_deg"].to_numpy()


def standard_error(per_run_rms: np.ndarray) -> float:
    """SE of sqrt(mean MSE) over runs, by the delta method.

    >>> round(standard_error(np.array([1.0, 1.0, 1.0])), 12)
    0.0
    """
    mse = per_run_rms**2
    rms = math.sqrt(mse.mean())
    return float(mse.std(ddof=1) / math.sqrt(len(mse)) / (2 * rms)) if rms > 0 else 0.0


def check_item(item: Mapping[str, Any]) -> list[Problem]:
    """Problems of an item's selectors, kind, quantity and unit for this paper."""
    select = dict(item.get("select") or {})
    problems: list[Problem] = []
    for key in sorted(set(select) - {"filter"}):
        problems.append((f"select.{key}", select[key], "only the selector filter"))
    if select.get("filter") not in ALTIMETER_FILTERS:
        problems.append(
            ("select.filter", select.get("filter"), f"one of {list(ALTIMETER_FILTERS)}")
        )
    if item["quantity"] not in RMS_QUANTITIES:
        problems.append(("quantity", item["quantity"], f"one of {list(RMS_QUANTITIES)}"))
    if item.get("unit") != "deg":
        problems.append(("unit", item.get("unit"), "'deg'"))
    if item["kind"] != "approximate":
        problems.append(
            ("kind", item["kind"], "'approximate' (the paper prints its RMS 'approximately')")
        )
    return problems


def locate(item: Mapping[str, Any], res: ScenarioResults) -> list[Found]:
    """Our RMS of the item's filter and angle, with its Monte Carlo standard error."""
    filt = item["select"]["filter"]
    res.need(filt, item["id"])
    angle = item["quantity"].split("_")[0]
    per_run = res.per_run(filt, angle)
    se = standard_error(per_run)
    return [
        Found(
            method=filt,
            value=float(res.summary.loc[filt, item["quantity"]]),
            standard_error=se,
            notes=(f"MC standard error of our RMS {se:.3f} deg ({len(per_run)} runs)",),
        )
    ]
