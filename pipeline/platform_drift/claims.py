"""Claim predicates of the platform-drift paper (registered in :data:`CLAIMS`).

A claim about "the proposed scheme" is judged on each proposed curve (analytic eq. 36 and
simulated), one row per curve; a predicate naming ``scheme`` is judged on that curve only.

* ``close``: max relative difference to the reference curve over t >= 1800 s <= rel_tol;
* ``bounded`` (24 h run, errors_long.csv): max |error| over 24 h <= ratio x max over the first 2 h;
* ``growth_exponent``: slope of log error vs log t over 1800-7200 s within tol of expect;
* ``below``: proposed < reference at every t >= from_s;
* ``final_order``: the sign of reference - proposed at 7200 s is ``expect``.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from typing import Any

import numpy as np
import pandas as pd

from pipeline.platform_drift.columns import DRIFT_CASES, DRIFT_SCHEMES
from pipeline.platform_drift.quantities import FINAL_S, FIT_WINDOW_S, PROPOSED, Results, curve
from pipeline.verdicts.claims import ClaimRegistry, ClaimResult

__all__ = ["CLAIMS"]

CLAIMS = ClaimRegistry()

_COMMON = {
    "scenario": {"type": "string", "minLength": 1},
    "case": {"enum": list(DRIFT_CASES)},
    "scheme": {"enum": list(DRIFT_SCHEMES)},
}
_REFERENCE = {"reference": {"enum": ["strapdown"]}}


def _schema(required: list[str], **props: Any) -> dict[str, Any]:
    return {
        "type": "object",
        "required": ["scenario", "case", *required],
        "properties": {**_COMMON, **props},
    }


#: One curve's test: (the curve, its results table, its scheme) -> (passed, reproduced, reason).
CurveTest = Callable[[pd.Series, pd.DataFrame, str], tuple[bool, str, str]]


def _judge(
    args: Mapping[str, Any], results: Results, long: bool, tolerance: str, one: CurveTest
) -> list[ClaimResult]:
    """Run ``one(cur, table, scheme) -> (ok, reproduced, reason)`` on each curve of the claim."""
    res = results.get(args["scenario"], {})
    table = res.get("errors_long" if long else "errors")
    base = {"quantity": "error_m"}
    if table is None:
        what = f"no {'24 h ' if long else ''}results for scenario {args['scenario']}"
        return [ClaimResult("not_checkable", "", tolerance, what, **base)]
    out = []
    for scheme in [args["scheme"]] if "scheme" in args else list(PROPOSED):
        cur = curve(table, args["case"], scheme)
        row = {**base, "method": scheme, "suffix": scheme}
        if cur.empty:
            why = f"no {scheme} curve for case {args['case']}"
            out.append(ClaimResult("not_checkable", "", tolerance, why, **row))
            continue
        ok, reproduced, reason = one(cur, table, scheme)
        out.append(
            ClaimResult("upheld" if ok else "not_upheld", reproduced, tolerance, reason, **row)
        )
    return out


@CLAIMS.register(
    "close",
    _schema(
        ["reference", "rel_tol"], **_REFERENCE, rel_tol={"type": "number", "exclusiveMinimum": 0}
    ),
)
def close(args: Mapping[str, Any], results: Results) -> list[ClaimResult]:
    """The curve stays within rel_tol (relative) of the reference over t >= 1800 s."""

    def one(cur, table, scheme):
        ref = curve(table, args["case"], args["reference"]).reindex(cur.index)
        late = cur.index >= FIT_WINDOW_S[0]
        rel = float(np.max(np.abs(cur[late] - ref[late]) / np.maximum(np.abs(ref[late]), 1e-9)))
        ok = rel <= args["rel_tol"]
        text = f"max relative difference to {args['reference']} over t >= 1800 s: {rel:.3g}"
        return ok, text, f"{rel:.3g} {'<=' if ok else '>'} {args['rel_tol']:g}"

    tol = f"max relative difference over t >= 1800 s <= {args['rel_tol']:g}"
    return _judge(args, results, False, tol, one)


@CLAIMS.register("bounded", _schema(["ratio"], ratio={"type": "number", "exclusiveMinimum": 1}))
def bounded(args: Mapping[str, Any], results: Results) -> list[ClaimResult]:
    """Over the 24 h run the error stays below ratio x its maximum over the first 2 h."""

    def one(cur, table, scheme):
        first = float(cur[cur.index <= FINAL_S].abs().max())
        whole = float(cur.abs().max())
        ok = whole <= args["ratio"] * first
        hours = cur.index.max() / 3600
        text = (
            f"max error over the first 2 h {first:.4g} m, over {hours:.0f} h {whole:.4g} m "
            f"(bounded if <= {args['ratio']}x)"
        )
        return (
            ok,
            text,
            f"{whole / first:.3g}x the first 2 h {'<=' if ok else '>'} {args['ratio']}x",
        )

    tol = f"max |error| over the whole run <= {args['ratio']} x the max over the first 2 h"
    return _judge(args, results, True, tol, one)


@CLAIMS.register(
    "growth_exponent",
    _schema(
        ["expect", "tol"],
        expect={"type": "number", "exclusiveMinimum": 0},
        tol={"type": "number", "exclusiveMinimum": 0},
    ),
)
def growth_exponent(args: Mapping[str, Any], results: Results) -> list[ClaimResult]:
    """The log-log slope of the error over 1800-7200 s is expect, within tol."""

    def one(cur, table, scheme):
        win = cur[(cur.index >= FIT_WINDOW_S[0]) & (cur.index <= FIT_WINDOW_S[1])]
        win = win[win > 0]
        slope = float(
            np.polyfit(np.log(win.index.to_numpy(float)), np.log(win.to_numpy(float)), 1)[0]
        )
        ok = abs(slope - float(args["expect"])) <= args["tol"]
        text = f"log-log slope over 1800-7200 s: {slope:.3g} (expected {args['expect']})"
        return ok, text, f"|{slope:.3g} - {args['expect']}| {'<=' if ok else '>'} {args['tol']}"

    tol = f"|log-log slope over 1800-7200 s - {args['expect']}| <= {args['tol']}"
    return _judge(args, results, False, tol, one)


@CLAIMS.register(
    "below",
    _schema(["reference"], **_REFERENCE, from_s={"type": "number", "minimum": 0}),
)
def below(args: Mapping[str, Any], results: Results) -> list[ClaimResult]:
    """The curve is below the reference at every t >= from_s."""
    from_s = float(args.get("from_s", 0.0))

    def one(cur, table, scheme):
        ref = curve(table, args["case"], args["reference"]).reindex(cur.index)
        sel = cur.index >= from_s
        bad = cur.index[sel][(cur[sel] >= ref[sel]).to_numpy()]
        ok = bad.size == 0
        text = "below the reference throughout" if ok else f"not below from t = {bad[0]:.0f} s"
        return ok, text, text

    tol = f"{args.get('reference')} - curve > 0 at every t >= {from_s:g} s"
    return _judge(args, results, False, tol, one)


@CLAIMS.register(
    "final_order",
    _schema(
        ["reference", "expect"],
        **_REFERENCE,
        expect={"enum": ["reference_below", "reference_above"]},
    ),
)
def final_order(args: Mapping[str, Any], results: Results) -> list[ClaimResult]:
    """At 7200 s the reference curve is below (or above) the judged one, as expected."""

    def one(cur, table, scheme):
        ref = float(curve(table, args["case"], args["reference"]).loc[FINAL_S])
        mine = float(cur.loc[FINAL_S])
        found = "reference_below" if ref < mine else "reference_above"
        text = f"at 7200 s: {args['reference']} {ref:.4g} m, {scheme} {mine:.4g} m ({found})"
        return found == args["expect"], text, f"{found} (expected {args['expect']})"

    tol = f"none: the sign of {args.get('reference')} - curve at 7200 s decides"
    return _judge(args, results, False, tol, one)
