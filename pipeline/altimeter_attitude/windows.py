"""Averaging windows of the RMS errors: ``window_summary.csv`` and ``window_run_rms.csv``.

The paper quotes one RMS per filter and angle without saying over which times. Two windows:

* ``flight``: the state times after ``metrics.transient_s`` (the window of rms_summary.csv and
  run_rms.csv, which these files repeat so that both windows are read the same way);
* ``after_bank``: from the end of the first bank with |roll| >= ``metrics.after_bank_deg``
  (found on the scenario's true roll at the state times) to the end of the flight, and not
  before the transient. In wings-level flight a roll error moves the vertical specific force
  only to second order, so the altimeter sees roll first in a bank; after the first one the
  error no longer carries the initial roll error. A scenario without such a bank, or whose
  first bank lasts to the end, has no after-bank window: its rows hold NaN statistics.

Both files have one block per window; the statistics are those of
:func:`pipeline.altimeter_attitude.metrics.summary_row` and ``run_rms_frame`` from the
window's first state time.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass

import numpy as np
import pandas as pd

from pipeline.altimeter_attitude import metrics
from pipeline.altimeter_attitude.columns import (
    RMS_SUMMARY_COLUMNS,
    RUN_RMS_COLUMNS,
    WINDOW_RUN_RMS_COLUMNS,
    WINDOW_SUMMARY_COLUMNS,
    WINDOWS,
)
from pipeline.altimeter_attitude.estimates import Estimates
from pipeline.altimeter_attitude.scenario import Scenario
from pipeline.altimeter_attitude.trajectory import Truth

__all__ = ["Window", "bank_end_index", "run_frame", "scenario_windows", "summary_frame"]


@dataclass(frozen=True)
class Window:
    """An averaging window: state indices ``first:`` (None: the scenario has none)."""

    name: str
    first: int | None
    start: float  # s (NaN without a window)
    end: float  # s

    @property
    def defined(self) -> bool:
        return self.first is not None


def bank_end_index(roll: np.ndarray, bank: float) -> int | None:
    """Index of the first sample after the first stretch with |roll| >= bank (rad); None if
    roll never reaches the bank or stays there to the last sample.

    >>> bank_end_index(np.radians([0, 5, 12, 20, 12, 8, 0, 15]), np.radians(10))
    5
    >>> bank_end_index(np.radians([0, 5, 8]), np.radians(10)) is None
    True
    >>> bank_end_index(np.radians([0, 12, 15]), np.radians(10)) is None
    True
    """
    banked = np.abs(np.asarray(roll, dtype=float)) >= bank
    if not banked.any():
        return None
    start = int(np.argmax(banked))
    level = ~banked[start:]
    if not level.any():
        return None
    return start + int(np.argmax(level))


def state_times(sc: Scenario) -> np.ndarray:
    """The state times t_k of the scenario (as :func:`sensors.simulate_inputs` forms them)."""
    dt = 1.0 / sc.sensors.rate_hz
    n_steps = int(round(sc.profiles.duration * sc.sensors.rate_hz))
    return np.arange(n_steps + 1) * dt


def scenario_windows(sc: Scenario) -> tuple[Window, ...]:
    """The ``flight`` and ``after_bank`` windows of a scenario (in :data:`WINDOWS` order)."""
    t = state_times(sc)
    first = int(round(sc.transient * sc.sensors.rate_hz))
    flight = Window("flight", first, float(t[first]), float(t[-1]))
    k = bank_end_index(sc.profiles.roll(t)[0], sc.after_bank)
    if k is None:
        after = Window("after_bank", None, math.nan, float(t[-1]))
    else:
        k = max(k, first)
        after = Window("after_bank", k, float(t[k]), float(t[-1]))
    out = {"flight": flight, "after_bank": after}
    return tuple(out[w] for w in WINDOWS)


def summary_frame(
    windows: tuple[Window, ...], estimates: Mapping[str, Estimates], truth: Truth
) -> pd.DataFrame:
    """window_summary.csv: per window and filter, the rms_summary.csv statistics."""
    rows = []
    for w in windows:
        for est in estimates.values():
            if w.defined:
                row = metrics.summary_row(est, truth, w.first)
            else:
                row = {c: math.nan for c in RMS_SUMMARY_COLUMNS}
                row.update(filter=est.filter, n_runs=est.roll.shape[0])
            rows.append({"window": w.name, "t_start_s": w.start, "t_end_s": w.end, **row})
    return pd.DataFrame(rows, columns=WINDOW_SUMMARY_COLUMNS)


def run_frame(
    windows: tuple[Window, ...], estimates: Mapping[str, Estimates], truth: Truth
) -> pd.DataFrame:
    """window_run_rms.csv: per window, run and filter, the run_rms.csv RMS."""
    parts = []
    for w in windows:
        for est in estimates.values():
            if w.defined:
                frame = metrics.run_rms_frame(est, truth, w.first)
            else:
                n = est.roll.shape[0]
                frame = pd.DataFrame(
                    {"run": np.arange(n), "filter": est.filter, "roll_rms_deg": math.nan}
                )
                frame["pitch_rms_deg"] = math.nan
            parts.append(frame[RUN_RMS_COLUMNS].assign(window=w.name))
    return pd.concat(parts, ignore_index=True)[WINDOW_RUN_RMS_COLUMNS]
