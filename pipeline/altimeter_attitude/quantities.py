"""Where the altimeter-attitude results hold the reproduced value of a published item.

An item selects ``{filter: <name>}``; its quantity is ``roll_rms_deg`` or ``pitch_rms_deg``.
It is judged on each averaging window of ``window_summary.csv`` of the published scenario
(:mod:`pipeline.altimeter_attitude.windows`): row suffix ``flight`` (RMS over runs and over
time after the transient, as rms_summary.csv) and ``after_bank`` (after the first bank that makes
roll observable), each with the Monte Carlo standard error of that RMS (delta method over
the per-run mean squares of ``window_run_rms.csv``) as its standard error. A failing row
carries the shared cause of :func:`pipeline.altimeter_attitude.causes.rms_cause`.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from pipeline.altimeter_attitude.columns import ALTIMETER_FILTERS, WINDOW_LABELS, WINDOWS
from pipeline.config import ConfigError
from pipeline.verdicts.kinds import Found
from pipeline.verdicts.published import Problem

__all__ = ["ANGLES", "RMS_QUANTITIES", "ScenarioResults", "check_item", "locate", "standard_error"]

ANGLES = ("roll", "pitch")
RMS_QUANTITIES = ("roll_rms_deg", "pitch_rms_deg")


class ScenarioResults:
    """The result files of one scenario, read once, its transient (s), and for the causes of
    failing rows: the bank (deg) that opens its after-bank window, the sweep (sweep.csv, None if
    not given), the UKF tuning grid (ukf_tuning.csv, None if not given) and the parsed
    published file (its items and claims)."""

    def __init__(
        self,
        directory: str | Path,
        transient: float,
        *,
        bank_deg: float = math.nan,
        sweep: str | Path | None = None,
        published: Mapping[str, Any] | None = None,
        tuning: str | Path | None = None,
    ) -> None:
        d = Path(directory)
        self.directory = d
        self.transient = float(transient)
        self.bank_deg = float(bank_deg)
        self.summary = pd.read_csv(d / "rms_summary.csv").set_index("filter")
        self.noise_free = pd.read_csv(d / "noise_free.csv").set_index("filter")
        self.run_rms = pd.read_csv(d / "run_rms.csv")
        self.windows = pd.read_csv(d / "window_summary.csv")
        self.window_runs = pd.read_csv(d / "window_run_rms.csv")
        self.series = pd.read_csv(d / "timeseries.csv")
        truth = pd.read_csv(d / "truth.csv", usecols=["t_s", "load_factor", "roll_deg"])
        truth = truth.set_index(truth["t_s"].round(9))
        self.load_factor = truth["load_factor"]
        self.true_roll_deg = truth["roll_deg"]
        self.sweep = pd.read_csv(sweep) if sweep is not None else None
        self.tuning = pd.read_csv(tuning) if tuning is not None else None
        self.published = dict(published or {"items": [], "claims": []})
        self.cache: dict[Any, Any] = {}

    def need(self, filt: str, source: str) -> None:
        if filt not in self.summary.index:
            raise ConfigError(
                f"{source}: filter {filt!r} has no results in {self.directory}; "
                f"available: {sorted(self.summary.index)}"
            )

    def curve(self, filt: str, column: str) -> pd.Series:
        rows = self.series[self.series["filter"] == filt]
        return rows.set_index("t_s")[column].sort_index()

    def per_run(self, filt: str, angle: str, window: str = "flight") -> np.ndarray:
        """Per-run RMS (deg) of a filter and angle over a window, in run order."""
        w = self.window_runs
        rows = w[(w["window"] == window) & (w["filter"] == filt)].sort_values("run")
        return rows[f"{angle}_rms_deg"].to_numpy()

    def window(self, filt: str, window: str) -> pd.Series:
        """The window_summary.csv row of a filter and window (t_start_s, statistics)."""
        w = self.windows
        rows = w[(w["window"] == window) & (w["filter"] == filt)]
        if len(rows) != 1:
            raise ConfigError(
                f"{self.directory / 'window_summary.csv'}: {len(rows)} rows for filter "
                f"{filt!r} and window {window!r}; expected 1"
            )
        return rows.iloc[0]


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
    """Our RMS of the item's filter and angle over each window, with its Monte Carlo standard
    error; failing rows carry the shared cause (:func:`causes.rms_cause`)."""
    from pipeline.altimeter_attitude.causes import rms_cause

    filt = item["select"]["filter"]
    res.need(filt, item["id"])
    angle = item["quantity"].split("_")[0]
    cause = rms_cause(res)
    found = []
    for window in WINDOWS:
        row = res.window(filt, window)
        start, end = float(row["t_start_s"]), float(row["t_end_s"])
        if not math.isfinite(start):
            found.append(
                Found(
                    method=filt,
                    suffix=window,
                    missing=f"the scenario has no {WINDOW_LABELS[window]}",
                )
            )
            continue
        per_run = res.per_run(filt, angle, window)
        se = standard_error(per_run)
        found.append(
            Found(
                method=filt,
                value=float(row[item["quantity"]]),
                standard_error=se,
                suffix=window,
                notes=(
                    f"{WINDOW_LABELS[window]}: RMS over runs and over {start:.5g}-{end:.5g} s",
                    f"MC standard error of our RMS {se:.3f} deg ({len(per_run)} runs)",
                ),
                cause=cause,
            )
        )
    return found
