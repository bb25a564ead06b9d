"""Columns and curves of one scenario's result frames (``truth.csv``, ``timeseries.csv``,
``rms_summary.csv``; the contract of :mod:`pipeline.altimeter_attitude.columns`), as the
figures read them: checked for the columns they need, sorted by time.

>>> import pandas as pd
>>> ts = pd.DataFrame({"t_s": [0.2, 0.1], "filter": ["ukf", "ukf"], "roll_rms_deg": [1.0, 2.0]})
>>> filter_curve(ts, "ukf", "roll_rms_deg")
(array([0.1, 0.2]), array([2., 1.]))
>>> filter_curve(ts, "ekf", "roll_rms_deg")
Traceback (most recent call last):
...
ValueError: timeseries: no rows for filter 'ekf' (present: ['ukf'])
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import pandas as pd

from pipeline.altimeter_attitude.columns import ALTIMETER_FILTERS

__all__ = [
    "require_columns",
    "filter_curve",
    "truth_column",
    "filters_present",
    "summary_value",
]


def require_columns(frame: pd.DataFrame, columns: Sequence[str], what: str) -> None:
    """Raise ValueError naming ``what`` and the columns of ``columns`` that ``frame`` lacks."""
    missing = [c for c in columns if c not in frame.columns]
    if missing:
        raise ValueError(f"{what}: missing columns {missing}")


def filter_curve(ts: pd.DataFrame, filt: str, column: str) -> tuple[np.ndarray, np.ndarray]:
    """(t, y) of one filter's column of timeseries.csv, sorted by time."""
    require_columns(ts, ["t_s", "filter", column], "timeseries")
    rows = ts[ts["filter"] == filt]
    if rows.empty:
        present = sorted(ts["filter"].unique())
        raise ValueError(f"timeseries: no rows for filter {filt!r} (present: {present})")
    rows = rows.sort_values("t_s", kind="stable")
    return rows["t_s"].to_numpy(float), rows[column].to_numpy(float)


def truth_column(truth: pd.DataFrame, column: str) -> tuple[np.ndarray, np.ndarray]:
    """(t, y) of one column of truth.csv, sorted by time."""
    require_columns(truth, ["t_s", column], "truth")
    frame = truth.sort_values("t_s", kind="stable")
    return frame["t_s"].to_numpy(float), frame[column].to_numpy(float)


def filters_present(ts: pd.DataFrame) -> list[str]:
    """The filters of timeseries.csv: this reproduction's in their order, then others sorted."""
    present = list(dict.fromkeys(ts["filter"]))
    return [f for f in ALTIMETER_FILTERS if f in present] + sorted(
        f for f in present if f not in ALTIMETER_FILTERS
    )


def summary_value(summary: pd.DataFrame | None, filt: str, column: str) -> float | None:
    """One filter's value of a column of rms_summary.csv; None if absent or not finite."""
    if summary is None or column not in summary.columns:
        return None
    rows = summary[summary["filter"] == filt]
    if rows.empty or not np.isfinite(rows[column].iloc[0]):
        return None
    return float(rows[column].iloc[0])
