"""Comparisons of the filters computed from the altimeter_attitude results: the effect of the
Gamma (Q kron P) Gamma^T term, the best filter per scenario and angle, the range of the RMS
error over each swept parameter, and each filter on noise-free data against its Monte Carlo
RMS.

>>> _trend([1, 2, 3], [0.1, 0.2, 0.4]), _trend([1, 2, 3], [0.3, 0.2, 0.4])
('grows with', 'is not monotonic in')
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import pandas as pd

from pipeline.report.html import format_value

__all__ = ["ANGLES", "best_filters", "gamma_effect", "noise_free_comparison", "sweep_ranges"]

ANGLES = ("roll", "pitch")


def gamma_effect(summaries: Mapping[str, pd.DataFrame]) -> pd.DataFrame:
    """Per scenario and angle: RMS and sigma of linear_kf and linear_kf_no_gamma and the
    relative change (with - without) / without."""
    rows = []
    for name, s in summaries.items():
        s = s.set_index("filter")
        if not {"linear_kf", "linear_kf_no_gamma"} <= set(s.index):
            continue
        for angle in ANGLES:
            row: dict[str, Any] = {"scenario": name, "angle": angle}
            for q in ("rms", "sigma"):
                col = f"{angle}_{q}_deg"
                a, b = float(s.at["linear_kf", col]), float(s.at["linear_kf_no_gamma", col])
                row[f"{q} with"] = a
                row[f"{q} without"] = b
                row[f"{q} change"] = (a - b) / b if b else float("nan")
            rows.append(row)
    return pd.DataFrame(rows)


def best_filters(summaries: Mapping[str, pd.DataFrame]) -> pd.DataFrame:
    """Per scenario and angle: the filter with the smallest RMS error (argmin), the runner-up,
    and the RMS of the linear KF and the UKF with their ratio."""
    rows = []
    for name, s in summaries.items():
        for angle in ANGLES:
            col = f"{angle}_rms_deg"
            r = s.set_index("filter")[col].astype(float).dropna().sort_values(kind="stable")
            if r.empty:
                continue
            lkf = float(r.get("linear_kf", float("nan")))
            ukf = float(r.get("ukf", float("nan")))
            rows.append(
                {
                    "scenario": name,
                    "angle": angle,
                    "best filter": r.index[0],
                    "best RMS (deg)": float(r.iloc[0]),
                    "runner-up": r.index[1] if len(r) > 1 else "",
                    "runner-up RMS (deg)": float(r.iloc[1]) if len(r) > 1 else float("nan"),
                    "linear_kf rank": int(list(r.index).index("linear_kf")) + 1
                    if "linear_kf" in r.index
                    else 0,
                    "linear_kf / ukf": lkf / ukf if ukf else float("nan"),
                }
            )
    return pd.DataFrame(rows)


def _trend(values: Sequence[float], rms: Sequence[float]) -> str:
    pairs = sorted(zip(values, rms, strict=True))
    d = [b[1] - a[1] for a, b in zip(pairs, pairs[1:], strict=False)]
    if d and all(x > 0 for x in d):
        return "grows with"
    if d and all(x < 0 for x in d):
        return "falls with"
    return "is not monotonic in"


def sweep_ranges(sweep: pd.DataFrame) -> pd.DataFrame:
    """Per swept parameter, filter and angle: min and max RMS, where they occur, max/min, trend."""
    rows = []
    for (param, filt), g in sweep.groupby(["parameter", "filter"], sort=False):
        for angle in ANGLES:
            col = f"{angle}_rms_deg"
            r = g[["value", col]].astype(float).dropna()
            if r.empty:
                continue
            lo, hi = r.loc[r[col].idxmin()], r.loc[r[col].idxmax()]
            rows.append(
                {
                    "parameter": param,
                    "filter": filt,
                    "angle": angle,
                    "values": f"{format_value(r['value'].min())}–{format_value(r['value'].max())}",
                    "min RMS (deg)": float(lo[col]),
                    "min at": format_value(float(lo["value"])),
                    "max RMS (deg)": float(hi[col]),
                    "max at": format_value(float(hi["value"])),
                    "max / min": float(hi[col]) / float(lo[col]) if lo[col] else float("nan"),
                    "trend": _trend(list(r["value"]), list(r[col])),
                }
            )
    return pd.DataFrame(rows)


def noise_free_comparison(
    summaries: Mapping[str, pd.DataFrame], noise_free: Mapping[str, pd.DataFrame]
) -> pd.DataFrame:
    """Per scenario, filter and angle: the RMS error of one noise-free run with an exact start
    (``noise_free.csv``), the Monte Carlo RMS (``rms_summary.csv``) and their ratio."""
    rows = []
    for name, nf in noise_free.items():
        mc = summaries.get(name)
        for r in nf.itertuples():
            m = None if mc is None else mc[mc["filter"] == r.filter]
            for angle in ANGLES:
                clean = float(getattr(r, f"{angle}_rms_deg"))
                noisy = float(m[f"{angle}_rms_deg"].iloc[0]) if m is not None and len(m) else np.nan
                rows.append(
                    {
                        "scenario": name,
                        "filter": r.filter,
                        "angle": angle,
                        "noise-free RMS": clean,
                        "Monte Carlo RMS": noisy,
                        "share": clean / noisy if noisy else np.nan,
                    }
                )
    return pd.DataFrame(rows)
