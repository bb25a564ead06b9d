"""Where the platform-drift results hold the reproduced value of a published item.

An item selects ``{scenario: <name>, case: <none|ch1|ch3|ch1_ch3>, scheme: strapdown}``: the
scenario's ``results/platform_drift/<scenario>/errors.csv`` (``t_s,case,scheme,error_m``), the
drift case and the curve the number is read off. Its quantity is

* ``error_2h_m``: the strapdown error at 7200 s (one row);
* ``crossover_s``: the first time after 300 s at which the strapdown error exceeds the
  proposed scheme's, computed against each proposed curve (analytic and simulated): one row
  per curve, id suffix ``/<curve>``; "never" when the curves do not cross within the run.

Values are returned in the item's printed unit (km, m, s, h).
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from pipeline.platform_drift.columns import DRIFT_CASES
from pipeline.verdicts.kinds import Found
from pipeline.verdicts.published import Problem

__all__ = [
    "CROSS_FROM_S",
    "CROSS_MARGIN_M",
    "FINAL_S",
    "FIT_WINDOW_S",
    "PROPOSED",
    "UNITS",
    "check_item",
    "crossover",
    "curve",
    "locate",
    "read_results",
]

PROPOSED = ("proposed_analytic", "proposed_simulated")
#: Metres (or seconds) per printed unit.
UNITS = {"km": 1000.0, "m": 1.0, "s": 1.0, "h": 3600.0}
QUANTITY_UNITS = {"error_2h_m": ("km", "m"), "crossover_s": ("s", "h")}
FINAL_S = 7200.0
CROSS_FROM_S = 300.0
FIT_WINDOW_S = (1800.0, 7200.0)
CROSS_MARGIN_M = 1.0

#: results: scenario name -> {"errors": errors.csv, "errors_long": errors_long.csv if any}
Results = Mapping[str, Mapping[str, pd.DataFrame]]


def check_item(item: Mapping[str, Any]) -> list[Problem]:
    """Problems of an item's selectors, kind, quantity and unit for this paper."""
    select = dict(item.get("select") or {})
    problems: list[Problem] = []
    for key in sorted(set(select) - {"scenario", "case", "scheme"}):
        problems.append((f"select.{key}", select[key], "only the selectors scenario, case, scheme"))
    if not isinstance(select.get("scenario"), str) or not select.get("scenario"):
        problems.append(("select.scenario", select.get("scenario"), "a scenario name"))
    if select.get("case") not in DRIFT_CASES:
        problems.append(("select.case", select.get("case"), f"one of {list(DRIFT_CASES)}"))
    if select.get("scheme") != "strapdown":
        problems.append(("select.scheme", select.get("scheme"), "'strapdown'"))
    quantity = item["quantity"]
    if quantity not in QUANTITY_UNITS:
        problems.append(("quantity", quantity, f"one of {list(QUANTITY_UNITS)}"))
    elif item.get("unit") not in QUANTITY_UNITS[quantity]:
        problems.append(("unit", item.get("unit"), f"one of {list(QUANTITY_UNITS[quantity])}"))
    if item["kind"] != "approximate":
        problems.append(
            ("kind", item["kind"], "'approximate' (the paper's numbers are read off its plots)")
        )
    return problems


def read_results(results_dir: str | Path) -> dict[str, dict[str, pd.DataFrame]]:
    """errors.csv (and a non-empty errors_long.csv) of every scenario folder of results_dir."""
    out: dict[str, dict[str, pd.DataFrame]] = {}
    for d in sorted(Path(results_dir).iterdir()):
        if (d / "errors.csv").is_file():
            out[d.name] = {"errors": pd.read_csv(d / "errors.csv")}
            long = d / "errors_long.csv"
            if long.is_file() and not (frame := pd.read_csv(long)).empty:
                out[d.name]["errors_long"] = frame
    return out


def curve(errors: pd.DataFrame, case: str, scheme: str) -> pd.Series:
    """error_m of one case and scheme, indexed by t_s."""
    rows = errors[(errors["case"] == case) & (errors["scheme"] == scheme)]
    return rows.set_index("t_s")["error_m"].sort_index()


def crossover(strapdown: pd.Series, proposed: pd.Series, from_s: float = CROSS_FROM_S) -> float:
    """First t >= from_s at which strapdown > proposed (linear interpolation); NaN if never.

    A 1 m margin: where the curves coincide (to integration precision) there is no crossover.

    >>> t = np.arange(0.0, 1001.0, 100.0)
    >>> crossover(pd.Series(t, index=t), pd.Series(np.full_like(t, 499.0), index=t))
    500.0
    """
    t = strapdown.index.to_numpy(float)
    d = (
        strapdown.to_numpy(float)
        - proposed.reindex(strapdown.index).to_numpy(float)
        - CROSS_MARGIN_M
    )
    keep = t >= from_s
    t, d = t[keep], d[keep]
    if d.size == 0 or d[0] > 0:
        return float("nan") if d.size == 0 else float(t[0])
    idx = np.flatnonzero(d > 0)
    if idx.size == 0:
        return float("nan")
    k = idx[0]
    return float(t[k - 1] + (t[k] - t[k - 1]) * (-d[k - 1]) / (d[k] - d[k - 1]))


def locate(item: Mapping[str, Any], results: Results) -> list[Found]:
    """What the results hold for one published item: one Found, or one per proposed curve."""
    sel = item["select"]
    scale = UNITS[item["unit"]]
    errors = results.get(sel["scenario"], {}).get("errors")
    if errors is None:
        return [Found(method=sel["scheme"], missing=f"no results for scenario {sel['scenario']}")]
    strap = curve(errors, sel["case"], "strapdown")
    if item["quantity"] == "error_2h_m":
        if FINAL_S not in strap.index:
            return [Found(method="strapdown", missing=f"no strapdown error at {FINAL_S:g} s")]
        return [Found(method="strapdown", value=float(strap.loc[FINAL_S]) / scale)]
    out = []
    for p in PROPOSED:
        t = crossover(strap, curve(errors, sel["case"], p))
        out.append(
            Found(
                method=f"strapdown vs {p}",
                value=t / scale,
                suffix=p,
                shown=None if np.isfinite(t) else "never",
            )
        )
    return out
