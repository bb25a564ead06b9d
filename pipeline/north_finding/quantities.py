"""Where the north-finding results hold the reproduced value of a published item.

An item selects ``{method: <L1..L5, A1c1..A6>, sensor: <ideal|real>}`` (the table's row and
sensor column). The results of the published scenario are ``estimates.csv`` (one ideal and one
noise-free real estimate per method and quantity), ``mc_trials.csv`` (the noisy Monte Carlo)
and ``error_budget.csv``, ``ranking.csv``, ``ranking_pairs.csv`` and ``a2_scan.csv`` (for the
claims and the causes).

* exact items (ideal sensor) -> the ``ideal`` row of estimates.csv: its estimate and % error;
* statistical items (real sensor) -> the row's leave-one-out posterior predictive mixture: the
  Monte Carlo estimates at every grid N, weighted by the likelihood of the other rows at N
  (``mc_trials_judged.csv`` and ``n_rows.csv``,
  :mod:`pipeline.north_finding.judged_n`; mc_trials.csv where the results hold no N
  inference), with the noise-free ``real`` row of estimates.csv beside them and the test's
  power in % error;
* approximate items (a % error the text gives as "about", quantity ``<q>_error_pct``) -> the
  |% error| of our Monte Carlo of ``<q>``: the text restates a real-sensor number the paper's
  noisy simulation printed (one draw of it), so the item is judged on the same mixture over N
  as the statistical row of the same method and quantity (that row's leave-one-out weights;
  the main Monte Carlo where there is no such row or no N inference), with the noise-free
  ``real`` row's |% error| beside it.

A failing row carries its root cause (:func:`pipeline.north_finding.causes.for_item`).
"""

from __future__ import annotations

import json
from collections.abc import Mapping, MutableMapping
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from pipeline.north_finding.columns import (
    A2_SCAN_COLUMNS,
    ERROR_BUDGET_COLUMNS,
    ESTIMATE_COLUMNS,
    METHOD_QUANTITIES,
    METHODS,
    N_ROW_COLUMNS,
    RANKING_COLUMNS,
    RANKING_PAIR_COLUMNS,
    SENSORS,
)
from pipeline.north_finding.trials_file import COLUMNS, by_key, read_trials
from pipeline.verdicts.kinds import RANK_BAND, Found
from pipeline.verdicts.published import Problem

__all__ = [
    "ERROR_QUANTITIES",
    "KIND_SENSOR",
    "QUANTITY_UNITS",
    "check_item",
    "locate",
    "read_results",
    "rows",
]

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
#: Item quantities that are the unsigned % error of a results quantity (the text's "about").
ERROR_QUANTITIES = {"acc_bias_error_pct": "acc_bias_ug"}
#: The sensor column each kind of item is printed in (ideal columns are exact, real ones noisy;
#: the text's "about" values are of the real sensor).
KIND_SENSOR = {"exact": "ideal", "statistical": "real", "approximate": "real"}

RESULT_FILES = {
    "estimates": ("estimates.csv", ESTIMATE_COLUMNS),
    "error_budget": ("error_budget.csv", ERROR_BUDGET_COLUMNS),
}
#: Results files the claims and causes read where present (a scenario without a ranking block
#: writes them empty).
OPTIONAL_FILES = {
    "ranking": ("ranking.csv", RANKING_COLUMNS),
    "ranking_pairs": ("ranking_pairs.csv", RANKING_PAIR_COLUMNS),
    "a2_scan": ("a2_scan.csv", A2_SCAN_COLUMNS),
    "n_rows": ("n_rows.csv", N_ROW_COLUMNS),
}
#: per-trial results, CSV or binary (:func:`pipeline.north_finding.trials_file.read_trials`):
#: key -> required
TRIAL_FILES = {"mc_trials": True, "mc_trials_judged": False}


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
    units = {**QUANTITY_UNITS, **{q: "%" for q in ERROR_QUANTITIES}}
    base = ERROR_QUANTITIES.get(quantity, quantity)
    if quantity not in units:
        problems.append(("quantity", quantity, f"one of {list(units)}"))
    elif method in METHODS and base not in METHOD_QUANTITIES[method]:
        problems.append(
            (
                "quantity",
                quantity,
                f"a quantity method {method} produces: {list(METHOD_QUANTITIES[method])}",
            )
        )
    kind = item["kind"]
    approximate_ok = kind != "approximate" or quantity in ERROR_QUANTITIES
    if kind not in KIND_SENSOR or not approximate_ok:
        problems.append(
            (
                "kind",
                kind,
                f"exact or statistical for {quantity} (approximate only for the 'about' % "
                f"errors {list(ERROR_QUANTITIES)})",
            )
        )
    elif (kind == "approximate") != (quantity in ERROR_QUANTITIES):
        problems.append(
            ("quantity", quantity, f"one of {list(ERROR_QUANTITIES)} for kind {kind!r}")
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
    if quantity in units and item.get("unit") != units[quantity]:
        problems.append(("unit", item.get("unit"), f"{units[quantity]!r}, the unit of {quantity}"))
    if item.get("error_pct") is not None and float(item["error_pct"]) < 0:
        problems.append(("error_pct", item["error_pct"], "an unsigned % error (>= 0), as printed"))
    return problems


def _check_frame(frame: pd.DataFrame, columns: list[str], name: str) -> pd.DataFrame:
    missing = [c for c in columns if c not in frame.columns]
    if missing:
        raise ValueError(f"{name}: missing column(s) {missing}; expected the columns {columns}")
    return frame


def read_results(
    scenario_dir: str | Path,
    *,
    scenario: Any = None,
    audit: str | Path | None = None,
    published: Mapping[str, Any] | None = None,
) -> dict[str, Any]:
    """The published scenario's folder: estimates.csv, mc_trials.csv and error_budget.csv
    (required), ranking.csv, ranking_pairs.csv, a2_scan.csv and provenance.json (where
    present); with the scenario (its decisions), the equation audit and the published file,
    which the causes of failing rows cite."""
    out: dict[str, Any] = {}
    for key, (filename, columns) in RESULT_FILES.items():
        path = Path(scenario_dir) / filename
        if not path.is_file():
            raise ValueError(f"{path}: results file not found (expected columns {columns})")
        out[key] = _check_frame(pd.read_csv(path), columns, str(path))
    for key, (filename, columns) in OPTIONAL_FILES.items():
        path = Path(scenario_dir) / filename
        frame = pd.read_csv(path) if path.is_file() else pd.DataFrame(columns=columns)
        out[key] = _check_frame(frame, columns, str(path))
    for key, required in TRIAL_FILES.items():
        frame = read_trials(scenario_dir, key)
        if frame is None and required:
            path = Path(scenario_dir) / f"{key}.csv"
            raise ValueError(f"{path}: results file not found (expected columns {COLUMNS[key]})")
        out[key] = frame if frame is not None else pd.DataFrame(columns=COLUMNS[key])
    prov = Path(scenario_dir) / "provenance.json"
    out["provenance"] = json.loads(prov.read_text(encoding="utf-8")) if prov.is_file() else {}
    out["scenario"] = scenario
    out["audit"] = pd.read_csv(audit, dtype=str) if audit is not None else None
    out["published"] = published
    return out


def mc_values(results: Mapping[str, Any], method: str, quantity: str, column: str) -> np.ndarray:
    """``column`` of mc_trials' rows of one method and quantity, in row order (empty if none);
    the grouping is computed once per results mapping and column."""
    cache = f"_mc_trials_{column}"
    groups = results.get(cache) if isinstance(results, Mapping) else None
    if groups is None:
        groups = by_key(results["mc_trials"], ["method", "quantity"], column, by_trial=False)
        if isinstance(results, MutableMapping):
            results[cache] = groups
    return groups.get((method, quantity), np.empty(0))


def rows(frame: pd.DataFrame, method: str, quantity: str) -> pd.DataFrame:
    """The rows of one method and quantity."""
    return frame[(frame["method"] == method) & (frame["quantity"] == quantity)]


def _estimate(results: Mapping[str, Any], sensor: str, method: str, quantity: str) -> Any:
    """The estimates.csv row of one sensor, method and quantity (None if there is none); the
    rows are indexed by (sensor, method, quantity) once per results mapping."""
    estimates = results["estimates"]
    index = results.get("_estimate_rows")
    if index is None:
        index = {}
        columns = [estimates[c].tolist() for c in ("sensor", "method", "quantity")]
        keys = zip(*columns, strict=True)
        for position, key in enumerate(keys):
            index.setdefault(key, []).append(position)
        if isinstance(results, MutableMapping):
            results["_estimate_rows"] = index
    found = index.get((sensor, method, quantity), [])
    if len(found) > 1:
        raise ValueError(
            f"estimates.csv: {len(found)} rows for sensor={sensor}, method={method}, "
            f"quantity={quantity}; allowed: exactly one"
        )
    return estimates.iloc[found[0]] if found else None


def _power(
    sample: np.ndarray, truth: float, published: float, weights: np.ndarray | None = None
) -> str:
    """The statistical test's power in % error: the band of errors it accepts (``weights``:
    per-sample weights of a mixture, weighted percentiles)."""
    q = (
        np.percentile(sample, RANK_BAND)
        if weights is None
        else np.percentile(sample, RANK_BAND, weights=weights, method="inverted_cdf")
    )
    lo, hi = 100.0 * (q - truth) / abs(truth)
    implied = 100.0 * (published - truth) / abs(truth)
    ratio = f", {(hi - lo) / abs(implied):.3g} times the published |error|" if implied else ""
    return (
        f"power: the rank band accepts any error from {lo:+.4g} % to {hi:+.4g} %{ratio} "
        f"(the published value implies {implied:+.4g} %)"
    )


def locate(item: Mapping[str, Any], results: Mapping[str, Any]) -> list[Found]:
    """What the results hold for one published item (one row)."""
    from pipeline.north_finding.causes import for_item
    from pipeline.north_finding.judged_n import judged_at, mixed_n

    method, quantity = item["select"]["method"], item["quantity"]
    if item["kind"] == "exact":
        row = _estimate(results, "ideal", method, quantity)
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
    cause = for_item(item, results)
    if item["kind"] == "approximate":
        return [_approximate(item, results, cause)]
    sample = mc_values(results, method, quantity, "estimate")
    if sample.size == 0:
        return [
            Found(
                method=method,
                missing=f"no Monte Carlo rows for method {method}, quantity {quantity} in "
                "mc_trials.csv",
            )
        ]
    real = _estimate(results, "real", method, quantity)
    finite = np.isfinite(sample)
    left_out = (
        (
            f"{int((~finite).sum())} of {sample.size} trials non-finite (numerical trouble), left out",
        )
        if not finite.all()
        else ()
    )
    sample = sample[finite]  # a rank over NaN trials would count them as neither below nor above
    truth = float(mc_values(results, method, quantity, "truth")[0])
    at = judged_at(results, item)
    weights = None
    if at is not None:
        sample, weights, cause = at.samples, at.weights, cause or mixed_n(results, item)
        left_out = ()  # the mixture says its own
    power = (_power(sample, truth, float(item["value"]), weights),) if truth else ()
    power = (*(at.notes if at is not None else ()), *left_out, *power)
    return [
        Found(
            method=method,
            samples=sample,
            weights=weights,
            noise_free=None if real is None else float(real["estimate"]),
            noise_free_error_pct=None if real is None else float(real["error_pct"]),
            truth=truth,
            notes=power,
            cause=cause,
        )
    ]


def _approximate(item: Mapping[str, Any], results: Mapping[str, Any], cause: Any) -> Found:
    """An 'about' % error: the |% error| of our Monte Carlo of the restated real-sensor number
    (mixed over N as its table row is), the noise-free |% error| beside it."""
    from pipeline.north_finding.judged_n import judged_at

    method, base = item["select"]["method"], ERROR_QUANTITIES[item["quantity"]]
    real = _estimate(results, "real", method, base)
    mc = rows(results["mc_trials"], method, base)
    if real is None or mc.empty:
        return Found(
            method=method,
            missing=f"no real row and Monte Carlo for method {method}, quantity {base} in "
            "estimates.csv and mc_trials.csv",
        )
    truth = float(mc["truth"].iloc[0])
    names = (results.get("published") or {}).get("names") or {}
    words = names.get(base, base.replace("_", " "))
    notes = [f"noise-free real {words}: {float(real['estimate']):.6g} {QUANTITY_UNITS[base]}"]
    row = next(
        (
            i
            for i in (results.get("published") or {}).get("items", [])
            if i["kind"] == "statistical" and i["quantity"] == base
            and i["select"]["method"] == method
        ),
        None,
    )  # fmt: skip
    at = judged_at(results, row) if row is not None else None
    if at is not None:
        sample, weights = at.samples, at.weights
        notes.append(f"judged on the Monte Carlo mixture over N of {row['label']} ({at.notes[0]})")
    else:
        sample, weights = mc["estimate"].to_numpy(float), None
        notes.append("judged on the main Monte Carlo")
    return Found(
        method=method,
        value=abs(float(real["error_pct"])),
        samples=np.abs(100.0 * (sample - truth) / truth),
        weights=weights,
        notes=tuple(notes),
        cause=cause,
    )
