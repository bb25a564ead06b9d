"""Compare the published numbers and claims of a paper with our results (DESIGN.md, invariant 3).

The published values are data: ``config/published/<slug>.yaml``, validated against
``config/schemas/published.schema.json`` and then checked semantically by
:func:`load_published`. Every value is kept as a string with exactly the printed digits, so
"the printed precision" is known: the half unit of the last printed digit of ``"50.0050"`` is
``0.00005``; of ``"88"`` it is ``0.5``; of ``"4.85e-8"`` it is ``0.005e-8``.

:func:`verdicts` gives each item and claim a verdict; no verdict is written by hand.

Verdict rules
-------------
exact (ideal-sensor items; compared with the ``ideal`` rows of ``estimates.csv``)
    ``reproduced`` = our ideal estimate (or our ideal |error_pct| when the table prints only a
    % error). The verdict is ``reproduced`` when every printed column agrees, else
    ``not_reproduced``:

    * value: |ours - published| <= half a unit of the printed last digit
      (+ 1e-12 x max(|ours|, |published|) of floating-point slack);
    * % error: |our |error_pct| - printed| <= ``tolerance_pct`` when the item gives one,
      otherwise half a unit of the printed last digit. An ideal column printing "0" for an
      exact inversion carries ``tolerance_pct: 1e-9``: "0 %" there means exact, and a half
      unit of the printed "0" (0.5 %) would accept almost anything.

statistical (real-sensor items; compared with the noisy Monte Carlo of ``mc_trials.csv``)
    ``reproduced`` = the Monte Carlo median of the estimate. The percentile rank of the
    published value in the Monte Carlo distribution of the estimate is
    100 x (#{trials < value} + 0.5 x #{trials = value}) / n. The verdict is ``consistent``
    when the rank lies in [0.5, 99.5] (the published value is a plausible draw of our noisy
    real sensor), else ``not_reproduced``. An item printing only a % error is ranked in the
    distribution of |error_pct| instead. The note gives the rank, the Monte Carlo 5-95 %
    interval, the noise-free real-sensor value (``real`` row of ``estimates.csv``) and the
    percent error the published value implies.

internal consistency (every item printing both a value and a % error)
    The % error implied by the printed value and our truth, |value - truth| / |truth| x 100,
    is compared with the printed % error. They are consistent when they differ by at most the
    rounding of the two printed numbers: half a unit of the % column's last digit plus the
    value's half unit expressed in % (half unit / |truth| x 100). Otherwise the note gets
    "table internally inconsistent: value implies X %, table prints Y %". This does not change
    the verdict: it says which printed column is not self-consistent.

claim (a predicate over our results; ``published`` = the expected answer)
    * argmin / argmax: the method with the smallest / largest Monte Carlo RMS of error_pct,
      sqrt(mean(error_pct^2)) over the trials of ``mc_trials.csv``, among the named methods;
    * close: the RMS of a and b differ by at most rel_tol x max(rms_a, rms_b);
    * dominant_source: in ``error_budget.csv`` the source (scale_factor, misalignment, bias,
      noise, or the subset the predicate lists in ``sources``) with the largest |error| for
      the method and quantity.

    ``upheld`` when the data give the expected answer, else ``not_upheld``;
    ``not_checkable`` (with the reason) when a method named in the predicate has no rows for
    the quantity, e.g. the paper names a method that gives no such estimate.

An item whose method has no rows for its quantity in our results also gets ``not_checkable``,
with the reason in the note.

Command line::

    python -m pipeline.compare --published config/published/north_finding.yaml \
        --results-dir results/north_finding/paper --out results/north_finding/verdicts.csv

From a Snakemake ``script:`` directive, ``snakemake.input.published``,
``snakemake.input.estimates`` (its folder is the scenario folder, unless
``snakemake.params.scenario_dir`` is given) and ``snakemake.output[0]`` are used.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import sys
from collections.abc import Sequence
from pathlib import Path
from typing import Any

import jsonschema
import numpy as np
import pandas as pd
import yaml

from pipeline.atomic import write_csv

try:
    from pipeline.columns import VERDICT_COLUMNS
    from pipeline.north_finding.columns import (
        ERROR_BUDGET_COLUMNS,
        ERROR_SOURCES,
        ESTIMATE_COLUMNS,
        MC_TRIAL_COLUMNS,
        METHOD_QUANTITIES,
    )
except ModuleNotFoundError:  # run as a Snakemake script: the workflow dir is the cwd
    sys.path.insert(0, os.getcwd())
    from pipeline.columns import VERDICT_COLUMNS
    from pipeline.north_finding.columns import (
        ERROR_BUDGET_COLUMNS,
        ERROR_SOURCES,
        ESTIMATE_COLUMNS,
        MC_TRIAL_COLUMNS,
        METHOD_QUANTITIES,
    )

REPO_ROOT = Path(__file__).resolve().parents[1]
SCHEMA_PATH = REPO_ROOT / "config" / "schemas" / "published.schema.json"

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
#: Which results each kind of item is compared with.
KIND_SENSOR = {"exact": "ideal", "statistical": "real"}
#: Percentile-rank band in which a published value is consistent with the Monte Carlo.
RANK_BAND = (0.5, 99.5)
#: Relative floating-point slack added to the half-unit tolerance.
REL_SLACK = 1e-12
#: Note added when the noise-free real value equals the published one to its printed precision.
NOISE_FREE_AGREES = (
    "the noise-free real value equals the published one to within one unit of its last printed "
    "digit: the table matches deterministic error propagation"
)

#: Error-budget sources a dominant_source claim chooses from.
BUDGET_SOURCES = tuple(s for s in ERROR_SOURCES if s != "all_deterministic")

RESULT_FILES = {
    "estimates": ("estimates.csv", ESTIMATE_COLUMNS),
    "mc_trials": ("mc_trials.csv", MC_TRIAL_COLUMNS),
    "error_budget": ("error_budget.csv", ERROR_BUDGET_COLUMNS),
}


# --------------------------------------------------------------------------------------------
# printed numbers
# --------------------------------------------------------------------------------------------
def half_unit(printed: str) -> float:
    """Half a unit of the last printed digit of a number string.

    ``"50.0050"`` -> 5e-5, ``"88"`` -> 0.5, ``"4.85e-8"`` -> 5e-11.
    """
    text = printed.strip().lower()
    mantissa, _, exponent = text.partition("e")
    decimals = len(mantissa.partition(".")[2])
    power = int(exponent) if exponent else 0
    return 0.5 * 10.0 ** (power - decimals)


def _fmt(x: float) -> str:
    return f"{x:.10g}"


def _fmt_full(x: float) -> str:
    """A reproduced value: 15 significant digits, enough to show any sub-digit difference."""
    return f"{x:.15g}"


def _fmt_pct(x: float, sign: bool = False) -> str:
    """A percentage with 4 significant digits in fixed notation (0.00001000, 22.60)."""
    if x == 0 or not math.isfinite(x):
        return f"{x:+g}" if sign else f"{x:g}"
    decimals = max(0, 3 - math.floor(math.log10(abs(x))))
    return f"{x:+.{decimals}f}" if sign else f"{x:.{decimals}f}"


# --------------------------------------------------------------------------------------------
# loading and validating the published file
# --------------------------------------------------------------------------------------------
def _locate(data: Any, path: Sequence[Any]) -> tuple[str, str]:
    """(entry description with its id, field path) of a schema error path."""
    if len(path) >= 2 and path[0] in ("items", "claims") and isinstance(path[1], int):
        entry = data[path[0]][path[1]]
        ident = entry.get("id") if isinstance(entry, dict) else None
        where = f"id {ident!r} ({path[0]}[{path[1]}])"
        rest = path[2:]
    else:
        where = "top level"
        rest = path
    field = ""
    for part in rest:
        field += f"[{part}]" if isinstance(part, int) else (f".{part}" if field else str(part))
    return where, field


def _describe_schema_error(err: jsonschema.ValidationError, data: Any, filename: str) -> str:
    where, field = _locate(data, list(err.absolute_path))
    instance = err.instance
    validator = err.validator
    if validator == "additionalProperties" and isinstance(instance, dict):
        allowed_keys = sorted(err.schema.get("properties", {}))
        extra = sorted(k for k in instance if k not in allowed_keys)
        key = extra[0] if extra else "?"
        field = f"{field}.{key}" if field else key
        bad = f"unknown key {key!r} (value {instance.get(key)!r})"
        allowed = f"only the keys {allowed_keys}"
    elif validator == "required" and isinstance(instance, dict):
        missing = [k for k in err.validator_value if k not in instance]
        key = missing[0] if missing else "?"
        field = f"{field}.{key}" if field else key
        bad = "missing"
        allowed = f"required keys {list(err.validator_value)}"
    else:
        bad = repr(instance)
        if validator == "enum":
            allowed = f"one of {list(err.validator_value)}"
        elif validator == "const":
            allowed = f"exactly {err.validator_value!r}"
        elif validator == "pattern":
            allowed = (
                f"a string matching {err.validator_value!r}"
                " (a printed number with '.' as decimal point, e.g. '50.0050' or '4.85e-8')"
                if "[0-9]+(" in str(err.validator_value)
                else f"a string matching {err.validator_value!r}"
            )
        elif validator == "type":
            allowed = f"type {err.validator_value}"
        else:
            allowed = f"{validator} {err.validator_value!r} ({err.message})"
    return f"{filename}: {where}, field {field or '(entry)'!r}: bad value {bad}; allowed: {allowed}"


def _problem(filename: str, where: str, field: str, value: Any, allowed: str) -> str:
    return f"{filename}: {where}, field {field!r}: bad value {value!r}; allowed: {allowed}"


def _semantic_problems(data: dict[str, Any], filename: str) -> list[str]:
    problems: list[str] = []
    seen: dict[str, str] = {}
    for section in ("items", "claims"):
        for index, entry in enumerate(data[section]):
            ident = entry["id"]
            where = f"id {ident!r} ({section}[{index}])"
            if ident in seen:
                problems.append(
                    _problem(
                        filename, where, "id", ident, f"a unique id (already used at {seen[ident]})"
                    )
                )
            else:
                seen[ident] = f"{section}[{index}]"
    for index, item in enumerate(data["items"]):
        where = f"id {item['id']!r} (items[{index}])"
        method, quantity = item["method"], item["quantity"]
        for field in ("value", "error_pct"):
            text = item[field]
            if text is None:
                continue
            try:
                number = float(text)
            except ValueError:
                number = math.nan
            if not math.isfinite(number):
                problems.append(_problem(filename, where, field, text, "a finite number string"))
            elif field == "error_pct" and number < 0:
                problems.append(
                    _problem(filename, where, field, text, "an unsigned % error (>= 0), as printed")
                )
        if item["value"] is None and item["error_pct"] is None:
            problems.append(
                _problem(filename, where, "value", None, "a printed number in value or error_pct")
            )
        if "tolerance_pct" in item and item["error_pct"] is None:
            problems.append(
                _problem(
                    filename,
                    where,
                    "tolerance_pct",
                    item["tolerance_pct"],
                    "tolerance_pct only together with a printed error_pct",
                )
            )
        if quantity not in METHOD_QUANTITIES[method]:
            problems.append(
                _problem(
                    filename,
                    where,
                    "quantity",
                    quantity,
                    f"a quantity method {method} produces: {list(METHOD_QUANTITIES[method])}",
                )
            )
        expected_sensor = KIND_SENSOR[item["kind"]]
        if item["sensor"] != expected_sensor:
            problems.append(
                _problem(
                    filename,
                    where,
                    "sensor",
                    item["sensor"],
                    f"{expected_sensor!r} for kind {item['kind']!r} "
                    "(exact items are ideal-sensor, statistical items real-sensor)",
                )
            )
        if item["unit"] != QUANTITY_UNITS[quantity]:
            problems.append(
                _problem(
                    filename,
                    where,
                    "unit",
                    item["unit"],
                    f"{QUANTITY_UNITS[quantity]!r}, the unit of {quantity}",
                )
            )
    for index, claim in enumerate(data["claims"]):
        where = f"id {claim['id']!r} (claims[{index}])"
        pred = claim["predicate"]
        if pred["type"] in ("argmin", "argmax") and pred["expect"] not in pred["methods"]:
            problems.append(
                _problem(
                    filename,
                    where,
                    "predicate.expect",
                    pred["expect"],
                    f"one of the predicate's methods {pred['methods']}",
                )
            )
    return problems


def load_published(
    path: str | os.PathLike[str], schema_path: str | os.PathLike[str] | None = None
) -> dict[str, Any]:
    """Read a published-values YAML file, validate it, and return it as a dict.

    Raises ``ValueError`` naming the file, the entry id, the field, the bad value and what is
    allowed, for a YAML syntax error, a schema violation or a semantic problem (duplicate id,
    non-finite number, a method that does not produce the item's quantity, kind/sensor or
    unit mismatch, an argmin/argmax expectation outside its methods).
    """
    path = Path(path)
    filename = str(path)
    try:
        text = path.read_text(encoding="utf-8")
    except OSError as exc:
        raise ValueError(f"{filename}: cannot read the published-values file: {exc}") from exc
    try:
        data = yaml.safe_load(text)
    except yaml.YAMLError as exc:
        raise ValueError(f"{filename}: not valid YAML: {exc}") from exc
    schema_file = Path(schema_path or SCHEMA_PATH)
    schema = json.loads(schema_file.read_text(encoding="utf-8"))
    validator = jsonschema.Draft202012Validator(schema)
    errors = sorted(validator.iter_errors(data), key=lambda e: [str(p) for p in e.absolute_path])
    if errors:
        lines = [_describe_schema_error(e, data, filename) for e in errors]
        raise ValueError(
            f"{filename}: {len(errors)} schema error(s) ({schema_file.name}):\n" + "\n".join(lines)
        )
    problems = _semantic_problems(data, filename)
    if problems:
        raise ValueError(f"{filename}: {len(problems)} problem(s):\n" + "\n".join(problems))
    return data


# --------------------------------------------------------------------------------------------
# results
# --------------------------------------------------------------------------------------------
def _check_frame(frame: pd.DataFrame, columns: Sequence[str], name: str) -> pd.DataFrame:
    missing = [c for c in columns if c not in frame.columns]
    if missing:
        raise ValueError(
            f"{name}: missing column(s) {missing}; expected the columns {list(columns)}"
        )
    return frame


def read_results(scenario_dir: str | os.PathLike[str]) -> dict[str, pd.DataFrame]:
    """Read estimates.csv, mc_trials.csv and error_budget.csv of one scenario folder."""
    out: dict[str, pd.DataFrame] = {}
    for key, (filename, columns) in RESULT_FILES.items():
        path = Path(scenario_dir) / filename
        if not path.is_file():
            raise ValueError(f"{path}: results file not found (expected columns {list(columns)})")
        out[key] = _check_frame(pd.read_csv(path), columns, str(path))
    return out


def _rows(frame: pd.DataFrame, method: str, quantity: str) -> pd.DataFrame:
    return frame[(frame["method"] == method) & (frame["quantity"] == quantity)]


def _estimate_row(
    estimates: pd.DataFrame, sensor: str, method: str, quantity: str
) -> pd.Series | None:
    rows = _rows(estimates[estimates["sensor"] == sensor], method, quantity)
    if len(rows) > 1:
        raise ValueError(
            f"estimates.csv: {len(rows)} rows for sensor={sensor}, method={method}, "
            f"quantity={quantity}; allowed: exactly one"
        )
    return None if rows.empty else rows.iloc[0]


def _truth(item: dict[str, Any], estimates: pd.DataFrame, mc_trials: pd.DataFrame) -> float | None:
    rows = _rows(estimates, item["method"], item["quantity"])
    if rows.empty:
        rows = _rows(mc_trials, item["method"], item["quantity"])
    return None if rows.empty else float(rows["truth"].iloc[0])


# --------------------------------------------------------------------------------------------
# verdict rules
# --------------------------------------------------------------------------------------------
def _consistency_note(item: dict[str, Any], truth: float | None) -> str | None:
    """Note on the printed table's own consistency (value vs % error), or None if fine."""
    if item["value"] is None or item["error_pct"] is None:
        return None
    if truth is None or truth == 0:
        return "internal consistency not checked: no non-zero truth in the results"
    value, printed = float(item["value"]), float(item["error_pct"])
    implied = abs(value - truth) / abs(truth) * 100.0
    tol = half_unit(item["error_pct"]) + half_unit(item["value"]) / abs(truth) * 100.0
    if abs(implied - printed) <= tol * (1 + 1e-9):
        return None
    return (
        f"table internally inconsistent: value implies {_fmt_pct(implied)} %, "
        f"table prints {item['error_pct']} %"
    )


def _exact(item: dict[str, Any], estimates: pd.DataFrame) -> tuple[str, str, list[str]]:
    """(reproduced, verdict, notes) of an exact (ideal-sensor) item."""
    row = _estimate_row(estimates, "ideal", item["method"], item["quantity"])
    if row is None:
        return (
            "",
            "not_checkable",
            [
                f"not checkable: no ideal row for method {item['method']}, quantity "
                f"{item['quantity']} in estimates.csv"
            ],
        )
    ours, our_err = float(row["estimate"]), float(row["error_pct"])
    notes: list[str] = []
    ok = True
    if item["value"] is not None:
        published = float(item["value"])
        tol = half_unit(item["value"]) + REL_SLACK * max(abs(ours), abs(published))
        diff = abs(ours - published)
        passed = diff <= tol
        ok &= passed
        notes.append(
            f"value: |ours - published| = {diff:.3g} {'<=' if passed else '>'} "
            f"half a printed digit {half_unit(item['value']):.3g}"
        )
        reproduced = _fmt_full(ours)
    else:
        reproduced = f"{abs(our_err):.3g} %"
    if item["error_pct"] is not None:
        printed = float(item["error_pct"])
        tol_pct = item.get("tolerance_pct")
        label = "tolerance_pct" if tol_pct is not None else "half a printed digit"
        tol = tol_pct if tol_pct is not None else half_unit(item["error_pct"])
        diff = abs(abs(our_err) - printed)
        passed = diff <= tol + REL_SLACK * max(abs(our_err), printed)
        ok &= passed
        notes.append(
            f"% error: ours {abs(our_err):.3g} %, printed {item['error_pct']} %, "
            f"difference {diff:.3g} {'<=' if passed else '>'} {label} {tol:.3g}"
        )
    return reproduced, "reproduced" if ok else "not_reproduced", notes


def _statistical(
    item: dict[str, Any], estimates: pd.DataFrame, mc_trials: pd.DataFrame
) -> tuple[str, str, list[str]]:
    """(reproduced, verdict, notes) of a statistical (real-sensor, Monte Carlo) item."""
    rows = _rows(mc_trials, item["method"], item["quantity"])
    if rows.empty:
        return (
            "",
            "not_checkable",
            [
                f"not checkable: no Monte Carlo rows for method {item['method']}, quantity "
                f"{item['quantity']} in mc_trials.csv"
            ],
        )
    if item["value"] is not None:
        sample = rows["estimate"].to_numpy(dtype=float)
        published = float(item["value"])
        what = "published value"
    else:
        sample = np.abs(rows["error_pct"].to_numpy(dtype=float))
        published = float(item["error_pct"])
        what = "published % error (vs MC |error_pct|)"
    n = sample.size
    rank = 100.0 * (np.sum(sample < published) + 0.5 * np.sum(sample == published)) / n
    p05, p50, p95 = np.percentile(sample, [5.0, 50.0, 95.0])
    passed = RANK_BAND[0] <= rank <= RANK_BAND[1]
    notes = [
        f"{what} at percentile rank {rank:.1f} of {n} Monte Carlo trials "
        f"(consistent if within [{RANK_BAND[0]}, {RANK_BAND[1]}])",
        f"MC 5-95 %: [{_fmt(p05)}, {_fmt(p95)}]",
    ]
    det = _estimate_row(estimates, "real", item["method"], item["quantity"])
    if det is not None:
        notes.append(
            f"noise-free real: {_fmt(float(det['estimate']))} "
            f"(error {float(det['error_pct']):+.4g} %)"
        )
        if item["value"] is not None:
            gap = abs(float(det["estimate"]) - published) / (2.0 * half_unit(item["value"]))
            if gap <= 1.0:
                notes.append(NOISE_FREE_AGREES)
    else:
        notes.append("noise-free real: n/a (no real row in estimates.csv)")
    truth = float(rows["truth"].iloc[0])
    if item["value"] is not None and truth != 0:
        implied = 100.0 * (published - truth) / abs(truth)
        notes.append(
            f"published value implies error {_fmt_pct(implied, sign=True)} % "
            f"(printed {item['error_pct']} %)"
        )
    return _fmt_full(p50), "consistent" if passed else "not_reproduced", notes


def _rms_pct(mc_trials: pd.DataFrame, method: str, quantity: str) -> float | None:
    err = _rows(mc_trials, method, quantity)["error_pct"].to_numpy(dtype=float)
    return None if err.size == 0 else float(np.sqrt(np.mean(err**2)))


def _lacking(methods: Sequence[str], quantity: str, source: str) -> str:
    parts = []
    for method in methods:
        produced = METHOD_QUANTITIES.get(method, ())
        extra = (
            f" (method {method} gives no {quantity} estimate: it produces {', '.join(produced)})"
            if quantity not in produced
            else ""
        )
        parts.append(f"{method}{extra}")
    return f"not checkable: no rows for quantity {quantity} from {'; '.join(parts)} in {source}"


def _claim(
    claim: dict[str, Any], mc_trials: pd.DataFrame, error_budget: pd.DataFrame
) -> dict[str, str]:
    pred = claim["predicate"]
    kind = pred["type"]
    row = {"id": claim["id"], "kind": "claim"}
    notes = [f"claim: {claim['text']} [{claim['source']}]"]
    if claim.get("note"):
        notes.append(claim["note"])
    if kind in ("argmin", "argmax"):
        methods, quantity = list(pred["methods"]), pred["quantity"]
        row.update(quantity=quantity, method=",".join(methods), published=pred["expect"])
        rms = {m: _rms_pct(mc_trials, m, quantity) for m in methods}
        missing = [m for m, r in rms.items() if r is None]
        if missing:
            return {
                **row,
                "reproduced": "n/a",
                "verdict": "not_checkable",
                "note": "; ".join([_lacking(missing, quantity, "mc_trials.csv"), *notes]),
            }
        ordered = sorted(methods, key=lambda m: rms[m], reverse=kind == "argmax")
        found = ordered[0]
        sep = " > " if kind == "argmax" else " < "
        reproduced = sep.join(f"{m} (rms {rms[m]:.4g} %)" for m in ordered)
        verdict = "upheld" if found == pred["expect"] else "not_upheld"
        notes.append(f"statistic: Monte Carlo RMS of error_pct; {kind} = {found}")
    elif kind == "close":
        a, b, rel_tol = pred["a"], pred["b"], float(pred["rel_tol"])
        same = a["quantity"] == b["quantity"]
        quantity = a["quantity"] if same else f"{a['quantity']}/{b['quantity']}"
        row.update(
            quantity=quantity,
            method=f"{a['method']},{b['method']}",
            published=f"{a['method']} ~ {b['method']} (within {rel_tol:g} relative)",
        )
        ra = _rms_pct(mc_trials, a["method"], a["quantity"])
        rb = _rms_pct(mc_trials, b["method"], b["quantity"])
        missing = [(s["method"], s["quantity"]) for s, r in ((a, ra), (b, rb)) if r is None]
        if missing:
            reason = "; ".join(_lacking([m], q, "mc_trials.csv") for m, q in missing)
            return {
                **row,
                "reproduced": "n/a",
                "verdict": "not_checkable",
                "note": "; ".join([reason, *notes]),
            }
        assert ra is not None and rb is not None
        scale = max(ra, rb)
        rel = abs(ra - rb) / scale if scale > 0 else 0.0
        reproduced = (
            f"{a['method']} (rms {ra:.4g} %), {b['method']} (rms {rb:.4g} %): "
            f"relative difference {rel:.3g}"
        )
        verdict = "upheld" if rel <= rel_tol else "not_upheld"
        notes.append("statistic: Monte Carlo RMS of error_pct")
    else:  # dominant_source
        method, quantity = pred["method"], pred["quantity"]
        row.update(quantity=quantity, method=method, published=pred["expect"])
        rows = _rows(error_budget, method, quantity)
        sources = tuple(pred.get("sources", BUDGET_SOURCES))
        noise = rows[rows["source"] == "noise"]
        rows = rows[rows["source"].isin(sources)]
        if "noise" not in sources and not noise.empty:
            notes.append(
                "compared among the deterministic sources "
                f"{', '.join(sources)}; the Monte Carlo noise std is "
                f"{float(noise['error_pct'].iloc[0]):.4g} % at this scenario's averaging count"
            )
        if rows.empty:
            return {
                **row,
                "reproduced": "n/a",
                "verdict": "not_checkable",
                "note": "; ".join([_lacking([method], quantity, "error_budget.csv"), *notes]),
            }
        mag = rows.assign(mag=rows["error"].abs()).sort_values("mag", ascending=False)
        found = str(mag["source"].iloc[0])
        reproduced = " > ".join(
            f"{s} ({e:+.4g} %)" for s, e in zip(mag["source"], mag["error_pct"], strict=True)
        )
        verdict = "upheld" if found == pred["expect"] else "not_upheld"
        total = _rows(error_budget, method, quantity)
        total = total[total["source"] == "all_deterministic"]
        if not total.empty:
            together = float(total["error_pct"].iloc[0])
            notes.append(f"all deterministic sources together: {together:+.4g} %")
        notes.append(f"dominant source (largest |error|) = {found}")
    return {**row, "reproduced": reproduced, "verdict": verdict, "note": "; ".join(notes)}


def verdicts(
    published: dict[str, Any],
    estimates: pd.DataFrame,
    mc_trials: pd.DataFrame,
    error_budget: pd.DataFrame,
) -> pd.DataFrame:
    """One verdict row per published item and claim, with exactly VERDICT_COLUMNS."""
    _check_frame(estimates, ESTIMATE_COLUMNS, "estimates")
    _check_frame(mc_trials, MC_TRIAL_COLUMNS, "mc_trials")
    _check_frame(error_budget, ERROR_BUDGET_COLUMNS, "error_budget")
    out: list[dict[str, str]] = []
    for item in published["items"]:
        if item["kind"] == "exact":
            reproduced, verdict, notes = _exact(item, estimates)
        else:
            reproduced, verdict, notes = _statistical(item, estimates, mc_trials)
        consistency = _consistency_note(item, _truth(item, estimates, mc_trials))
        if consistency:
            notes.append(consistency)
        if item.get("note"):
            notes.append(item["note"])
        shown = item["value"] if item["value"] is not None else f"{item['error_pct']} %"
        out.append(
            {
                "id": item["id"],
                "kind": item["kind"],
                "quantity": item["quantity"],
                "method": item["method"],
                "published": shown,
                "reproduced": reproduced,
                "verdict": verdict,
                "note": "; ".join(notes),
            }
        )
    for claim in published.get("claims", []):
        out.append(_claim(claim, mc_trials, error_budget))
    return pd.DataFrame(out, columns=VERDICT_COLUMNS)


# --------------------------------------------------------------------------------------------
# entry points
# --------------------------------------------------------------------------------------------
def write_csv_atomic(frame: pd.DataFrame, out_path: str | os.PathLike[str]) -> None:
    """Write the verdict table atomically (pipeline.atomic)."""
    write_csv(out_path, frame, list(frame.columns))


def run(
    published_path: str | os.PathLike[str],
    scenario_dir: str | os.PathLike[str],
    out_path: str | os.PathLike[str],
) -> pd.DataFrame:
    """Load, compare, write ``out_path`` atomically; return the verdict table."""
    published = load_published(published_path)
    results = read_results(scenario_dir)
    table = verdicts(published, results["estimates"], results["mc_trials"], results["error_budget"])
    write_csv_atomic(table, out_path)
    return table


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m pipeline.compare",
        description="Give every published number and claim a verdict (writes verdicts.csv).",
    )
    parser.add_argument("--published", required=True, help="config/published/<slug>.yaml")
    parser.add_argument(
        "--results-dir",
        help="scenario results folder (default: results/<paper>/<scenario> of the published file)",
    )
    parser.add_argument("--out", required=True, help="verdicts CSV to write")
    args = parser.parse_args(argv)
    results_dir = args.results_dir
    if results_dir is None:
        published = load_published(args.published)
        results_dir = Path("results") / published["paper"] / published["scenario"]
    table = run(args.published, results_dir, args.out)
    counts = table["verdict"].value_counts().to_dict()
    print(f"{args.out}: {len(table)} verdicts {counts}")
    return 0


def _snakemake_entry(smk: Any) -> None:
    scenario_dir = getattr(smk.params, "scenario_dir", None) or Path(smk.input.estimates).parent
    run(smk.input.published, scenario_dir, smk.output[0])


if "snakemake" in globals():
    _snakemake_entry(globals()["snakemake"])
elif __name__ == "__main__":
    raise SystemExit(main())
