"""Where the pendulum's published numbers are in its results: ``periods.csv`` of a scenario.

An item's ``select`` names the scenario, the amplitude (deg) and the curve (a column of
``periods.csv``: ``period_s``, ``small_angle_s`` or ``first_order_s``).
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

import pandas as pd

from pipeline.verdicts.kinds import Found

__all__ = ["CURVES", "check_item", "locate", "read_results"]

CURVES = ("period_s", "small_angle_s", "first_order_s")
Results = dict[str, pd.DataFrame]


def read_results(results_dir: str | Path) -> Results:
    """``periods.csv`` of every scenario folder of ``results_dir``, by scenario name."""
    root = Path(results_dir)
    return {
        d.name: pd.read_csv(d / "periods.csv")
        for d in sorted(root.glob("*/"))
        if (d / "periods.csv").is_file()
    }


def check_item(item: Mapping[str, Any]) -> list[str]:
    """Problems with an item's selectors (the engine names file, item and field)."""
    sel = item.get("select") or {}
    problems = []
    if sel.get("curve") not in CURVES:
        problems.append(f"select.curve = {sel.get('curve')!r}: must be one of {list(CURVES)}")
    if not isinstance(sel.get("amplitude_deg"), (int, float)):
        problems.append("select.amplitude_deg: must be a number (deg)")
    if not isinstance(sel.get("scenario"), str):
        problems.append("select.scenario: must name a scenario")
    return problems


def locate(item: Mapping[str, Any], results: Results) -> list[Found]:
    sel = item["select"]
    frame = results.get(sel["scenario"])
    if frame is None:
        return [Found(method=sel["curve"], missing=f"no results for scenario {sel['scenario']}")]
    row = frame[frame["amplitude_deg"] == sel["amplitude_deg"]]
    if row.empty:
        return [Found(method=sel["curve"], missing=f"no amplitude {sel['amplitude_deg']} deg")]
    return [Found(method=sel["curve"], value=float(row[sel["curve"]].iloc[0]))]
