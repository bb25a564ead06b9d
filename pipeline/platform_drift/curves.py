"""The error curves of the platform-drift results, as the verdicts read them.

``results``: scenario name -> ``{"errors": errors.csv, "errors_long": errors_long.csv (24 h,
when non-empty), "diagnostic": errors_diagnostic.csv, "scenario": the validated scenario
config}`` (:func:`read_results`). A curve is one case and scheme of a table, indexed by t_s.
"""

from __future__ import annotations

import weakref
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from pipeline.platform_drift.scenario import load_scenario

__all__ = [
    "CROSS_FROM_S",
    "CROSS_MARGIN_M",
    "FINAL_S",
    "FIT_WINDOW_S",
    "PROPOSED",
    "Results",
    "crossover",
    "curve",
    "loglog_slope",
    "read_results",
]

PROPOSED = ("proposed_analytic", "proposed_simulated")
FINAL_S = 7200.0
CROSS_FROM_S = 300.0
FIT_WINDOW_S = (1800.0, 7200.0)
CROSS_MARGIN_M = 1.0

#: scenario name -> {"errors", "errors_long", "diagnostic": DataFrame, "scenario": Scenario}
Results = Mapping[str, Mapping[str, Any]]


def read_results(
    results_dir: str | Path, scenarios_dir: str | Path | None = None
) -> dict[str, dict[str, Any]]:
    """errors.csv (and a non-empty errors_long.csv, errors_diagnostic.csv) of every scenario
    folder of results_dir, with the scenario's config from ``scenarios_dir/<name>.yaml``."""
    out: dict[str, dict[str, Any]] = {}
    for d in sorted(Path(results_dir).iterdir()):
        if not (d / "errors.csv").is_file():
            continue
        out[d.name] = {"errors": pd.read_csv(d / "errors.csv")}
        long = d / "errors_long.csv"
        if long.is_file() and not (frame := pd.read_csv(long)).empty:
            out[d.name]["errors_long"] = frame
        if (d / "errors_diagnostic.csv").is_file():
            out[d.name]["diagnostic"] = pd.read_csv(d / "errors_diagnostic.csv")
        if scenarios_dir is not None and (f := Path(scenarios_dir) / f"{d.name}.yaml").is_file():
            out[d.name]["scenario"] = load_scenario(f)
    return out


#: id of an errors table -> (a weak reference to it, its length, the row positions of each
#: (case, scheme)); an entry leaves with its table
_POSITIONS: dict[int, tuple[weakref.ref, int, dict[tuple[Any, Any], np.ndarray]]] = {}


def _rows(errors: pd.DataFrame, case: str, scheme: str) -> pd.DataFrame:
    """The rows of one case and scheme, in table order. Where each (case, scheme) sits is
    found once per table (the verdicts ask ~200 curves of a few tables, and comparing every
    row's strings took 2-10 ms a curve); the rows are taken from the table at each call, so a
    change to its values is seen (a table whose case or scheme labels change in place, or
    that grows or shrinks, would need a new frame: none does)."""
    key = id(errors)
    hit = _POSITIONS.get(key)
    if hit is None or hit[0]() is not errors or hit[1] != len(errors):
        where = errors.groupby(["case", "scheme"], sort=False).indices
        hit = (weakref.ref(errors, lambda _ref, k=key: _POSITIONS.pop(k, None)), len(errors), where)
        _POSITIONS[key] = hit
    positions = hit[2].get((case, scheme))
    return errors.iloc[:0] if positions is None else errors.iloc[positions]


def curve(errors: pd.DataFrame, case: str, scheme: str) -> pd.Series:
    """error_m of one case and scheme, indexed by t_s.

    >>> e = pd.DataFrame({"t_s": [10.0, 0.0, 0.0], "case": ["a", "a", "b"],
    ...                   "scheme": ["s", "s", "s"], "error_m": [2.0, 1.0, 5.0]})
    >>> curve(e, "a", "s").to_dict(), curve(e, "c", "s").empty
    ({0.0: 1.0, 10.0: 2.0}, True)
    """
    return _rows(errors, case, scheme).set_index("t_s")["error_m"].sort_index()


def loglog_slope(t: np.ndarray, y: np.ndarray) -> float:
    """Least-squares slope of log y against log t (the positive samples only).

    >>> t = np.linspace(1800.0, 7200.0, 10)
    >>> round(loglog_slope(t, 3.0 * t**2), 12)
    2.0
    """
    t, y = np.asarray(t, dtype=float), np.asarray(y, dtype=float)
    keep = (t > 0) & (y > 0)
    return float(np.polyfit(np.log(t[keep]), np.log(y[keep]), 1)[0])


def crossover(strapdown: pd.Series, proposed: pd.Series, from_s: float = CROSS_FROM_S) -> float:
    """The time the strapdown curve, first below the proposed one, rises above it: the first
    t >= from_s after the strapdown was below by more than a 1 m margin at which it is above
    by more than the margin (linear interpolation); NaN if the strapdown is never below (a
    crossover needs one curve below the other first: curves that start together and part
    later do not cross) or never rises above.

    >>> t = np.arange(0.0, 1001.0, 100.0)
    >>> crossover(pd.Series(t, index=t), pd.Series(np.full_like(t, 499.0), index=t))
    500.0
    >>> crossover(pd.Series(t, index=t), pd.Series(t - 0.5 * t * (t > 300), index=t))
    nan
    """
    t = strapdown.index.to_numpy(float)
    diff = strapdown.to_numpy(float) - proposed.reindex(strapdown.index).to_numpy(float)
    keep = t >= from_s
    t, diff = t[keep], diff[keep]
    below = np.flatnonzero(diff < -CROSS_MARGIN_M)
    if below.size == 0:
        return float("nan")
    t, diff = t[below[0] :], diff[below[0] :]
    d = diff - CROSS_MARGIN_M
    idx = np.flatnonzero(d > 0)
    if idx.size == 0:
        return float("nan")
    k = idx[0]
    return float(t[k - 1] + (t[k] - t[k - 1]) * (-d[k - 1]) / (d[k] - d[k - 1]))
