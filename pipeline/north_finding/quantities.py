"""Where the north-finding results hold the reproduced value of a published item.

An item selects ``{method: <L1..L5, A1c1..A6>, sensor: <ideal|real>}`` (the table's row and
sensor column). The results of the published scenario are ``estimates.csv`` (one ideal and one
noise-free real estimate per method and quantity), ``mc_trials.csv`` (the noisy Monte Carlo)
and ``error_budget.csv`` (for the claims).

* exact items (ideal sensor) -> the ``ideal`` row of estimates.csv: its estimate and % error;
* statistical items (real sensor) -> the Monte Carlo estimates of mc_trials.csv, with the
  noise-free ``real`` row of estimates.csv beside them.
"""

from __future__ import annotations

from collections.abc import Mapping
from pathlib import Path
from typing import Any

import pandas as pd

from pipeline.north_finding.columns import (
    ERROR_BUDGET_COLUMNS,
    ESTIMATE_COLUMNS,
    MC_TRIAL_COLUMNS,
    METHOD_QUANTITIES,
    METHODS,
    SENSORS,
)
from pipeline.verdicts.kinds import Found
from pipeline.verdicts.published import Problem

__all__ = ["KIND_SENSOR", "QUANTITY_UNITS", "check_item", "locate", "read_results", "rows"]

#: Unit each quantity is published in (the unit of its results column).
QUANTITY_UNITS = {
    "phi_deg": "deg",
    "theta_deg": "deg",
    "psi_deg": "deg",
    "acc_bias_ug": "ug",
    "acc_scale": "dimensionless",
    "acc_scale_approx": "dimensionless",
    "gyro_bias_rad_s": "rad_s",
    "gyro_scale": "dimensionless",
    "gyro_scale_approx": "dimensionless",
}
#: The sensor column each kind of item is printed in (ideal columns are exact, real ones noisy).
KIND_SENSOR = {"exact": "ideal", "statistical": "real"}

RESULT_FILES = {
    "estimates": ("estimates.csv", ESTIMATE_COLUMNS),
    "mc_trials": ("mc_trials.csv", MC_TRIAL_COLUMNS),
    "error_budget": ("error_budget.csv", ERROR_BUDGET_COLUMNS),
}


def check_item(item: Mapping[str, Any]) -> list[Problem]:
    """Problems of an item's selectors, kind, quantity and unit for this paper."""
    select = dict(item.get("select") or {})
    problems: list[Problem] = []
    for key in sorted(set(select) - {"method", "sensor"}):
        problems.append((f"select.{key}", select[key], "only the selectors method and sensor"))
    method, sensor = select.get("method"), select.get("sensor")
    if method not in METHODS:
        problems.append(("select.method", method, f"one of {list(METHODS)}"))
    if sensor not in SENSORS:
        problems.append(("select.sensor", sensor, f"one of {list(SENSORS)}"))
    quantity = item["quantity"]
    if quantity not in QUANTITY_UNITS:
        problems.append(("quantity", quantity, f"one of {list(QUANTITY_UNITS)}"))
    elif method in METHODS and quantity not in METHOD_QUANTITIES[method]:
        problems.append(
            (
                "quantity",
                quantity,
                f"a quantity method {method} produces: {list(METHOD_QUANTITIES[method])}",
            )
        )
    kind = item["kind"]
    if kind not in KIND_SENSOR:
        problems.append(
            ("kind", kind, f"one of {list(KIND_SENSOR)} (the paper prints no approximate value)")
        )
    elif sensor in SENSORS and sensor != KIND_SENSOR[kind]:
        problems.append(
            (
                "select.sensor",
                sensor,
                f"{KIND_SENSOR[kind]!r} for kind {kind!r} "
                "(exact items are ideal-sensor, statistical items real-sensor)",
            )
        )
    if quantity in QUANTITY_UNITS and item.get("unit") != QUANTITY_UNITS[quantity]:
        problems.append(
            ("unit", item.get("unit"), f"{QUANTITY_UNITS[quantity]!r}, the unit of {quantity}")
        )
    if item.get("error_pct") is not None and float(item["error_pct"]) < 0:
        problems.append(("error_pct", item["error_pct"], "an unsigned % error (>= 0), as printed"))
    return problems


def _check_frame(frame: pd.DataFrame, columns: list[str], name: str) -> pd.DataFrame:
    missing = [c for c in columns if c not in frame.columns]
    if missing:
        raise ValueError(f"{name}: missing column(s) {missing}; expected the columns {columns}")
    return frame


def read_results(scenario_dir: str | Path) -> dict[str, pd.DataFrame]:
    """estimates.csv, mc_trials.csv and error_budget.csv of the published scenario's folder."""
    out: dict[str, pd.DataFrame] = {}
    for key, (filename, columns) in RESULT_FILES.items():
        path = Path(scenario_dir) / filename
        if not path.is_file():
            raise ValueError(f"{path}: results file not found (expected columns {columns})")
        out[key] = _check_frame(pd.read_csv(path), columns, str(path))
    return out


def rows(frame: pd.DataFrame, method: str, quantity: str) -> pd.DataFrame:
    """The rows of one method and quantity."""
    return frame[(frame["method"] == method) & (frame["quantity"] == quantity)]


def _estimate(estimates: pd.DataFrame, sensor: str, method: str, quantity: str) -> Any:
    found = rows(estimates[estimates["sensor"] == sensor], method, quantity)
    if len(found) > 1:
        raise ValueError(
            f"estimates.csv: {len(found)} rows for sensor={sensor}, method={method}, "
            f"quantity={quantity}; allowed: exactly one"
        )
    return None if found.empty else found.iloc[0]


def locate(item: Mapping[str, Any], results: Mapping[str, pd.DataFrame]) -> list[Found]:
    """What the results hold for one published item (one row)."""
    method, quantity = item["select"]["method"], item["quantity"]
    estimates, trials = results["estimates"], results["mc_trials"]
    if item["kind"] == "exact":
        row = _estimate(estimates, "ideal", method, quantity)
        if row is None:
            return [
                Found(
                    method=method,
                    missing=f"no ideal row for method {method}, quantity {quantity} in "
                    "estimates.csv",
                )
            ]
        return [
            Found(
                method=method,
                value=float(row["estimate"]),
                error_pct=float(row["error_pct"]),
                truth=float(row["truth"]),
            )
        ]
    mc = rows(trials, method, quantity)
    if mc.empty:
        return [
            Found(
                method=method,
                missing=f"no Monte Carlo rows for method {method}, quantity {quantity} in "
                "mc_trials.csv",
            )
        ]
    real = _estimate(estimates, "real", method, quantity)
    return [
        Found(
            method=method,
            samples=mc["estimate"].to_numpy(dtype=float),
            noise_free=None if real is None else float(real["estimate"]),
            noise_free_error_pct=None if real is None else float(real["error_pct"]),
            truth=float(mc["truth"].iloc[0]),
        )
    ]
