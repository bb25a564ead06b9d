"""Claim predicates of the north-finding paper (registered in :data:`CLAIMS`).

The statistic of argmin / argmax / close is the Monte Carlo RMS of error_pct,
sqrt(mean(error_pct^2)) over the trials of ``mc_trials.csv``: it counts a constant offset and
the spread alike. ``dominant_source`` reads ``error_budget.csv``: the error of the noise-free
real run with one source switched on at a time.

* ``argmin`` / ``argmax``: the method with the smallest / largest RMS among ``methods`` is
  ``expect``;
* ``close``: the RMS of ``a`` and ``b`` differ by at most ``rel_tol`` x the larger one;
* ``dominant_source``: the source with the largest |error| for the method and quantity (among
  ``sources``, default scale_factor, misalignment, bias, noise) is ``expect``.

``not_checkable`` (with the reason) when a method named in the predicate has no rows for the
quantity, e.g. the paper names a method that gives no such estimate.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import numpy as np
import pandas as pd

from pipeline.north_finding.columns import ERROR_SOURCES, METHOD_QUANTITIES, METHODS
from pipeline.north_finding.quantities import QUANTITY_UNITS, rows
from pipeline.verdicts.claims import ClaimRegistry, ClaimResult
from pipeline.verdicts.published import Problem

__all__ = ["BUDGET_SOURCES", "CLAIMS"]

CLAIMS = ClaimRegistry()
#: Error-budget sources a dominant_source claim chooses from.
BUDGET_SOURCES = tuple(s for s in ERROR_SOURCES if s != "all_deterministic")

_METHOD = {"enum": list(METHODS)}
_QUANTITY = {"enum": list(QUANTITY_UNITS)}
_METHOD_QUANTITY = {
    "type": "object",
    "additionalProperties": False,
    "required": ["method", "quantity"],
    "properties": {"method": _METHOD, "quantity": _QUANTITY},
}
_ARG_SCHEMA = {
    "type": "object",
    "required": ["quantity", "methods", "expect"],
    "properties": {
        "quantity": _QUANTITY,
        "methods": {"type": "array", "minItems": 2, "uniqueItems": True, "items": _METHOD},
        "expect": _METHOD,
    },
}


def _expect_among_methods(args: Mapping[str, Any]) -> list[Problem]:
    if args["expect"] in args["methods"]:
        return []
    return [("expect", args["expect"], f"one of the predicate's methods {args['methods']}")]


def _rms_pct(trials: pd.DataFrame, method: str, quantity: str) -> float | None:
    err = rows(trials, method, quantity)["error_pct"].to_numpy(dtype=float)
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


def _arg(kind: str, args: Mapping[str, Any], results: Mapping[str, pd.DataFrame]) -> ClaimResult:
    methods, quantity, expect = list(args["methods"]), args["quantity"], args["expect"]
    base = {"method": ",".join(methods), "quantity": quantity, "published": expect}
    tolerance = f"none: the {kind} of the Monte Carlo RMS of error_pct among {methods} decides"
    rms = {m: _rms_pct(results["mc_trials"], m, quantity) for m in methods}
    missing = [m for m, r in rms.items() if r is None]
    if missing:
        reason = _lacking(missing, quantity, "mc_trials.csv")
        return ClaimResult("not_checkable", "n/a", tolerance, reason, **base)
    ordered = sorted(methods, key=lambda m: rms[m], reverse=kind == "argmax")
    sep = " > " if kind == "argmax" else " < "
    reproduced = sep.join(f"{m} (rms {rms[m]:.4g} %)" for m in ordered)
    ok = ordered[0] == expect
    reason = f"{kind} of the Monte Carlo RMS of error_pct = {ordered[0]} (expected {expect})"
    return ClaimResult("upheld" if ok else "not_upheld", reproduced, tolerance, reason, **base)


@CLAIMS.register("argmin", _ARG_SCHEMA, _expect_among_methods)
def argmin(args: Mapping[str, Any], results: Mapping[str, pd.DataFrame]) -> list[ClaimResult]:
    """The method with the smallest Monte Carlo RMS of error_pct is ``expect``."""
    return [_arg("argmin", args, results)]


@CLAIMS.register("argmax", _ARG_SCHEMA, _expect_among_methods)
def argmax(args: Mapping[str, Any], results: Mapping[str, pd.DataFrame]) -> list[ClaimResult]:
    """The method with the largest Monte Carlo RMS of error_pct is ``expect``."""
    return [_arg("argmax", args, results)]


@CLAIMS.register(
    "close",
    {
        "type": "object",
        "required": ["a", "b", "rel_tol"],
        "properties": {
            "a": _METHOD_QUANTITY,
            "b": _METHOD_QUANTITY,
            "rel_tol": {"type": "number", "exclusiveMinimum": 0, "maximum": 1},
        },
    },
)
def close(args: Mapping[str, Any], results: Mapping[str, pd.DataFrame]) -> list[ClaimResult]:
    """The Monte Carlo RMS of error_pct of a and b differ by at most rel_tol x the larger."""
    a, b, rel_tol = args["a"], args["b"], float(args["rel_tol"])
    same = a["quantity"] == b["quantity"]
    base = {
        "method": f"{a['method']},{b['method']}",
        "quantity": a["quantity"] if same else f"{a['quantity']}/{b['quantity']}",
        "published": f"{a['method']} ~ {b['method']} (within {rel_tol:g} relative)",
    }
    tolerance = f"|rms_a - rms_b| <= {rel_tol:g} x max(rms_a, rms_b)"
    ra = _rms_pct(results["mc_trials"], a["method"], a["quantity"])
    rb = _rms_pct(results["mc_trials"], b["method"], b["quantity"])
    if ra is None or rb is None:
        lacking = [(s["method"], s["quantity"]) for s, r in ((a, ra), (b, rb)) if r is None]
        reason = "; ".join(_lacking([m], q, "mc_trials.csv") for m, q in lacking)
        return [ClaimResult("not_checkable", "n/a", tolerance, reason, **base)]
    scale = max(ra, rb)
    rel = abs(ra - rb) / scale if scale > 0 else 0.0
    reproduced = (
        f"{a['method']} (rms {ra:.4g} %), {b['method']} (rms {rb:.4g} %): "
        f"relative difference {rel:.3g}"
    )
    ok = rel <= rel_tol
    reason = (
        f"relative difference of the Monte Carlo RMS {rel:.3g} {'<=' if ok else '>'} {rel_tol:g}"
    )
    return [ClaimResult("upheld" if ok else "not_upheld", reproduced, tolerance, reason, **base)]


_SOURCE = {"enum": list(BUDGET_SOURCES)}


@CLAIMS.register(
    "dominant_source",
    {
        "type": "object",
        "required": ["method", "quantity", "expect"],
        "properties": {
            "method": _METHOD,
            "quantity": _QUANTITY,
            "expect": _SOURCE,
            "sources": {"type": "array", "minItems": 2, "uniqueItems": True, "items": _SOURCE},
        },
    },
)
def dominant_source(
    args: Mapping[str, Any], results: Mapping[str, pd.DataFrame]
) -> list[ClaimResult]:
    """The error source with the largest |error| in error_budget.csv is ``expect``."""
    method, quantity, expect = args["method"], args["quantity"], args["expect"]
    base = {"method": method, "quantity": quantity, "published": expect}
    sources = tuple(args.get("sources", BUDGET_SOURCES))
    tolerance = f"none: the largest |error| among the sources {', '.join(sources)} decides"
    budget = rows(results["error_budget"], method, quantity)
    notes: list[str] = []
    noise = budget[budget["source"] == "noise"]
    if "noise" not in sources and not noise.empty:
        notes.append(
            f"compared among the deterministic sources {', '.join(sources)}; the Monte Carlo "
            f"noise std is {float(noise['error_pct'].iloc[0]):.4g} % at this scenario's "
            "averaging count"
        )
    chosen = budget[budget["source"].isin(sources)]
    if chosen.empty:
        reason = _lacking([method], quantity, "error_budget.csv")
        return [ClaimResult("not_checkable", "n/a", tolerance, reason, notes=tuple(notes), **base)]
    mag = chosen.assign(mag=chosen["error"].abs()).sort_values(
        "mag", ascending=False, kind="stable"
    )
    found = str(mag["source"].iloc[0])
    reproduced = " > ".join(
        f"{s} ({e:+.4g} %)" for s, e in zip(mag["source"], mag["error_pct"], strict=True)
    )
    total = budget[budget["source"] == "all_deterministic"]
    if not total.empty:
        notes.append(
            f"all deterministic sources together: {float(total['error_pct'].iloc[0]):+.4g} %"
        )
    ok = found == expect
    reason = f"dominant source (largest |error|) = {found} (expected {expect})"
    return [
        ClaimResult(
            "upheld" if ok else "not_upheld",
            reproduced,
            tolerance,
            reason,
            notes=tuple(notes),
            **base,
        )
    ]
