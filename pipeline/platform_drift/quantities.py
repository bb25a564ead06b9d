"""Where the platform-drift results hold the reproduced value of a published item.

An item selects ``{scenario: <name>, case: <none|ch1|ch3|ch1_ch3>, scheme: strapdown}``: the
scenario's ``results/platform_drift/<scenario>/errors.csv`` (``t_s,case,scheme,error_m``), the
drift case and the curve the number is read off. Its quantity is

* ``error_2h_m``: the strapdown error at 7200 s (one row);
* ``crossover_s``: the first time after 300 s at which the strapdown error exceeds the
  proposed scheme's, computed against each proposed curve (analytic and simulated): one row
  per curve, id suffix ``/<curve>``; "never" when the curves do not cross within the run;
  ``not_checkable`` for the analytic curve where its equations do not hold (a moving vehicle).

A failing row carries its computed root cause where one applies (:mod:`causes`).

Values are returned in the item's printed unit (km, m, s, h).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np

from pipeline.platform_drift import causes
from pipeline.platform_drift.columns import DRIFT_CASES
from pipeline.platform_drift.curves import (
    CROSS_FROM_S,
    CROSS_MARGIN_M,
    FINAL_S,
    FIT_WINDOW_S,
    PROPOSED,
    Results,
    crossover,
    curve,
    read_results,
)
from pipeline.platform_drift.validity import analytic_invalid
from pipeline.verdicts.kinds import Found
from pipeline.verdicts.published import Problem

__all__ = [
    "CROSS_FROM_S",
    "CROSS_MARGIN_M",
    "FINAL_S",
    "FIT_WINDOW_S",
    "PROPOSED",
    "Results",
    "UNITS",
    "check_item",
    "crossover",
    "curve",
    "locate",
    "read_results",
]

#: Metres (or seconds) per printed unit.
UNITS = {"km": 1000.0, "m": 1.0, "s": 1.0, "h": 3600.0}
QUANTITY_UNITS = {"error_2h_m": ("km", "m"), "crossover_s": ("s", "h")}


def check_item(item: Mapping[str, Any], scenarios: Sequence[str] | None = None) -> list[Problem]:
    """Problems of an item's selectors, kind, quantity and unit for this paper; ``scenarios``
    (the scenario files' names), when given, are the scenarios an item may select."""
    select = dict(item.get("select") or {})
    problems: list[Problem] = []
    for key in sorted(set(select) - {"scenario", "case", "scheme"}):
        problems.append((f"select.{key}", select[key], "only the selectors scenario, case, scheme"))
    if not isinstance(select.get("scenario"), str) or not select.get("scenario"):
        problems.append(("select.scenario", select.get("scenario"), "a scenario name"))
    elif scenarios is not None and select["scenario"] not in scenarios:
        problems.append(
            ("select.scenario", select["scenario"], f"one of the scenarios {list(scenarios)}")
        )
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


def _cause_2h(item: Mapping[str, Any], errors, ours_m: float):
    """The cause of a strapdown error at 2 h with both drifts (:func:`causes.combined_direction`)."""
    if item["select"]["case"] != "ch1_ch3":
        return None
    return causes.combined_direction(errors, float(item["value"]) * UNITS[item["unit"]], ours_m)


def locate(item: Mapping[str, Any], results: Results) -> list[Found]:
    """What the results hold for one published item: one Found, or one per proposed curve.

    A crossover with the analytic curve is not checkable where eqs. 32/36 do not hold (the
    scenario's vehicle moves: :func:`pipeline.platform_drift.validity.analytic_invalid`).
    """
    sel = item["select"]
    scale = UNITS[item["unit"]]
    errors = results.get(sel["scenario"], {}).get("errors")
    if errors is None:
        return [Found(method=sel["scheme"], missing=f"no results for scenario {sel['scenario']}")]
    strap = curve(errors, sel["case"], "strapdown")
    if item["quantity"] == "error_2h_m":
        if FINAL_S not in strap.index:
            return [Found(method="strapdown", missing=f"no strapdown error at {FINAL_S:g} s")]
        ours = float(strap.loc[FINAL_S])
        return [Found(method="strapdown", value=ours / scale, cause=_cause_2h(item, errors, ours))]
    out = []
    for p in PROPOSED:
        method = f"strapdown vs {p}"
        invalid = (
            analytic_invalid(results, sel["scenario"], sel["case"])
            if p == "proposed_analytic"
            else ""
        )
        if invalid:
            out.append(Found(method=method, suffix=p, missing=invalid))
            continue
        t = crossover(strap, curve(errors, sel["case"], p))
        cause = (
            causes.explain_simulated(results, sel["scenario"], sel["case"])
            if p == "proposed_simulated"
            else None
        )
        out.append(
            Found(
                method=method,
                value=t / scale,
                suffix=p,
                shown=None if np.isfinite(t) else "never",
                cause=cause,
            )
        )
    return out
