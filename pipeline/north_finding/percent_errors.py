"""Absolute percent errors per (method, quantity), the numbers Figs 1-6 compare: quantiles over
the Monte Carlo trials of the noisy real sensor, the noise-free run, and the percent error the
paper prints.

>>> import pandas as pd
>>> trials = pd.DataFrame({"method": "L1", "quantity": "phi_deg", "error_pct": [-1.0, 2.0, -3.0]})
>>> abs_error_quantiles(trials).loc[("L1", "phi_deg"), ["p50", "n"]].tolist()
[2.0, 3.0]
"""

from __future__ import annotations

import pandas as pd

__all__ = [
    "QUANTILE_LEVELS",
    "QUANTILE_NAMES",
    "abs_error_quantiles",
    "real_abs_error_pct",
    "published_error_pct",
]

QUANTILE_LEVELS = (0.05, 0.25, 0.50, 0.75, 0.95)
QUANTILE_NAMES = ("p05", "p25", "p50", "p75", "p95")


def abs_error_quantiles(trials: pd.DataFrame) -> pd.DataFrame:
    """Quantiles of ``|error_pct|`` per (method, quantity) over Monte Carlo trials.

    Returns a frame indexed by ``(method, quantity)`` with columns
    ``p05, p25, p50, p75, p95, n`` (vectorised groupby; no loop over trials).
    """
    if trials.empty:
        idx = pd.MultiIndex.from_arrays([[], []], names=["method", "quantity"])
        return pd.DataFrame(columns=[*QUANTILE_NAMES, "n"], index=idx, dtype=float)
    abs_err = trials["error_pct"].astype(float).abs()
    grouped = abs_err.groupby([trials["method"].astype(str), trials["quantity"].astype(str)])
    q = grouped.quantile(list(QUANTILE_LEVELS)).unstack()
    q.columns = list(QUANTILE_NAMES)
    q["n"] = grouped.count()
    q.index.names = ["method", "quantity"]
    return q


def real_abs_error_pct(estimates: pd.DataFrame, sensor: str = "real") -> pd.Series:
    """``|error_pct|`` of the noise-free run of ``sensor``, indexed by (method, quantity)."""
    sel = estimates[estimates["sensor"].astype(str) == sensor]
    s = (
        sel.set_index([sel["method"].astype(str), sel["quantity"].astype(str)])["error_pct"]
        .astype(float)
        .abs()
    )
    s.index.names = ["method", "quantity"]
    return s[~s.index.duplicated(keep="first")]


def published_error_pct(items: pd.DataFrame, sensor: str = "real") -> pd.Series:
    """Published ``|% error|`` per (method, quantity) for ``sensor`` (rows without one dropped)."""
    sel = items[(items["sensor"] == sensor) & items["error_pct_value"].notna()]
    s = sel.set_index([sel["method"].astype(str), sel["quantity"].astype(str)])[
        "error_pct_value"
    ].abs()
    s.index.names = ["method", "quantity"]
    return s[~s.index.duplicated(keep="first")]
