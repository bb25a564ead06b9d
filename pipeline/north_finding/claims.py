"""Claim predicates of the north-finding paper (registered in :data:`CLAIMS`).

The paper ranks its methods without giving the averaging count N. Where the results hold the
N inference, argmin / argmax / close are judged, one verdict row each (no suffix), at the N the
paper's own statistical rows imply: our Monte Carlo mixed over the grid N with their posterior
weights (:func:`pipeline.north_finding.ranking.posterior_set`), as the statistical rows are
judged; the rank sets at the fixed N of the scenario's ``ranking`` block and the noise-free
run are then a sensitivity, stated in the row's reason. Without an N inference they are judged
on every rank set of :mod:`pipeline.north_finding.ranking`: the Monte Carlo at each N of the
``ranking`` block (``ranking.csv``, ``ranking_pairs.csv``), then the noise-free run
(``estimates.csv``), one verdict row each (suffix ``N=100``, ``noise-free``); without ranking
files, the trials of ``mc_trials.csv`` (one row, no suffix). Their statistic is the RMS of
error_pct, sqrt(mean(error_pct^2)): it counts a constant offset and the spread alike. Every
row's reason ends with the N at which the claim holds and those at which it does not.

* ``argmin`` / ``argmax``: ``expect`` has the smallest / largest RMS among ``methods``, separated
  from every other: the paired difference of the squared % errors over the same trials lies
  beyond :data:`~pipeline.north_finding.ranking.Z_RESOLVE` standard errors (noise-free: any
  difference beyond the tie); a method that is the same estimator (equal on every trial) or not
  separated matches it, and the claim is not upheld at that N;
* ``close``: the RMS of ``a`` and ``b`` differ by at most ``rel_tol`` x the larger one;
* ``dominant_source`` reads ``error_budget.csv`` (the error of the noise-free real run with one
  source switched on at a time): the source with the largest |error| for the method and
  quantity (among ``sources``, default scale_factor, misalignment, bias, noise) is ``expect``.

A failing row carries its root cause (:mod:`pipeline.north_finding.causes`); a ranking that
holds at some N and not at others, with no other cause, is explained by the unpublished N.
``not_checkable`` (with the reason) when a method named in the predicate has no rows for the
quantity, e.g. the paper names a method that gives no such estimate.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import replace
from typing import Any

import pandas as pd

from pipeline.north_finding import causes
from pipeline.north_finding.columns import ERROR_SOURCES, METHOD_QUANTITIES, METHODS
from pipeline.north_finding.quantities import QUANTITY_UNITS, rows
from pipeline.north_finding.ranking import TIE_REL, Z_RESOLVE, RankSet, posterior_set, rank_sets
from pipeline.verdicts.cause import Cause
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


def _tolerance(rank_set: RankSet) -> str:
    if rank_set.noise_free:
        return (
            f"noise-free: the |% error| of each method decides; equal to {TIE_REL:g} relative "
            "is a tie"
        )
    return (
        f"{rank_set.where}: a method ranks before another when the paired difference of their "
        f"squared % errors lies beyond {Z_RESOLVE:g} standard errors; equal on every trial to "
        f"{TIE_REL:g} relative is a tie"
    )


def _summary(results: list[ClaimResult], sets: list[RankSet]) -> list[ClaimResult]:
    """Append to every row's reason at which N the claim holds and at which it does not."""
    held = [s.label for r, s in zip(results, sets, strict=True) if r.verdict == "upheld"]
    failed = [s.label for r, s in zip(results, sets, strict=True) if r.verdict == "not_upheld"]
    open_ = [s.label for r, s in zip(results, sets, strict=True) if r.verdict == "not_checkable"]
    if len(sets) < 2:
        return results
    if not failed and not open_:
        text = f"holds at every N judged ({', '.join(held)})"
    elif not held and not open_:
        text = f"holds at none of the N judged ({', '.join(failed)})"
    else:
        parts = [
            f"holds at N = {', '.join(held)}" if held else "",
            f"not at N = {', '.join(failed)}" if failed else "",
            f"not resolved at N = {', '.join(open_)}" if open_ else "",
        ]
        text = "; ".join(p for p in parts if p)
    return [replace(r, reason=f"{r.reason}; {text}") for r in results]


def _at_posterior(
    claim: str, judged: ClaimResult, results: list[ClaimResult], sets: list[RankSet]
) -> ClaimResult:
    """The row judged at the inferred N, with the fixed-N and noise-free verdicts as a
    sensitivity in its reason (and, when it fails with no other cause but holds at some fixed
    N, the unpublished N as its cause)."""
    held = [s.label for r, s in zip(results, sets, strict=True) if r.verdict == "upheld"]
    failed = [s.label for r, s in zip(results, sets, strict=True) if r.verdict == "not_upheld"]
    open_ = [s.label for r, s in zip(results, sets, strict=True) if r.verdict == "not_checkable"]
    parts = [
        f"holds at N = {', '.join(held)}" if held else "",
        f"not at N = {', '.join(failed)}" if failed else "",
        f"not resolved at N = {', '.join(open_)}" if open_ else "",
    ]
    text = "; ".join(p for p in parts if p)
    out = replace(judged, reason=f"{judged.reason}; at the fixed N of the sensitivity: {text}")
    if out.verdict == "not_upheld" and out.cause is None and held:
        out = replace(
            out,
            cause=Cause(
                "unpublished",
                "the averaging count N is not given",
                f"The paper does not give the averaging count N, and its ranking ({claim}) "
                f"holds at N = {', '.join(held)} but not at the N its own tables imply "
                f"({judged.notes[0] if judged.notes else judged.reason})",
            ),
        )
    return out


def _n_cause(claim: str, results: list[ClaimResult], sets: list[RankSet]) -> Cause | None:
    """The averaging count: a ranking that holds at some N and not at others."""
    held = [s.label for r, s in zip(results, sets, strict=True) if r.verdict == "upheld"]
    failed = [(r, s) for r, s in zip(results, sets, strict=True) if r.verdict == "not_upheld"]
    if not held or not failed:
        return None
    why = "; ".join(f"{s.label}: {r.notes[0]}" for r, s in failed if r.notes)
    return Cause(
        "unpublished",
        "the averaging count N is not given",
        f"The paper does not give the averaging count N, and its ranking ({claim}) holds at "
        f"N = {', '.join(held)} but not at N = {', '.join(s.label for _, s in failed)} ({why})",
    )


def _arg_one(kind: str, args: Mapping[str, Any], rank_set: RankSet, results: Any) -> ClaimResult:
    methods, quantity, expect = list(args["methods"]), args["quantity"], args["expect"]
    base = {"method": ",".join(methods), "quantity": quantity, "published": expect}
    rms = {m: rank_set.get(m, quantity) for m in methods}
    sign = -1.0 if kind == "argmax" else 1.0
    ordered = sorted(methods, key=lambda m: sign * rms[m])
    sep = " > " if kind == "argmax" else " < "
    stat = "|error|" if rank_set.noise_free else "rms"
    reproduced = sep.join(f"{m} ({stat} {rms[m]:.4g} %)" for m in ordered)
    comps = [rank_set.compare(quantity, expect, m) for m in methods if m != expect]
    # refuted: a rival is the same estimator, or is separated on the wrong side; unresolved: a
    # rival the Monte Carlo cannot tell from the expected method (more trials would decide,
    # so the claim is not checkable at this N rather than refuted)
    refuting = [c for c in comps if c.identical or (c.separated and sign * c.d > 0)]
    unresolved = [c for c in comps if not c.identical and not c.separated]
    identical = [c.b for c in comps if c.identical]
    how = "smaller" if kind == "argmin" else "larger"
    if refuting:
        worst = max(refuting, key=lambda c: (c.identical, sign * c.d))
        note = worst.describe() if worst.identical else f"{worst.b} {how} than {expect}"
        reason = f"{kind} of the RMS % error ({rank_set.where}) is not {expect} alone: {note}"
        cause = causes.for_ranking(quantity, expect, [c.b for c in refuting], identical, results)
        return ClaimResult(
            "not_upheld", reproduced, _tolerance(rank_set), reason, suffix=rank_set.suffix,
            notes=(note,), cause=cause, **base,
        )  # fmt: skip
    if unresolved:
        worst = min(unresolved, key=lambda c: abs(c.z))
        note = f"{expect} not distinguishably {how} than {worst.b} ({worst.describe()})"
        reason = (
            f"not resolved at {rank_set.where}: {note}; no rival is separated from {expect} on "
            "the wrong side, so more trials (or another N) decide"
        )
        return ClaimResult(
            "not_checkable", reproduced, _tolerance(rank_set), reason, suffix=rank_set.suffix,
            notes=(note,), **base,
        )  # fmt: skip
    closest = min(comps, key=lambda c: abs(c.z))
    reason = (
        f"{kind} of the RMS % error ({rank_set.where}) = {expect}, separated from every other "
        f"method (closest: {closest.describe()})"
    )
    return ClaimResult(
        "upheld", reproduced, _tolerance(rank_set), reason, suffix=rank_set.suffix, **base
    )


def _arg(kind: str, args: Mapping[str, Any], results: Mapping[str, Any]) -> list[ClaimResult]:
    methods, quantity, expect = list(args["methods"]), args["quantity"], args["expect"]
    base = {"method": ",".join(methods), "quantity": quantity, "published": expect}
    every = rank_sets(results)
    sets = [s for s in every if all(s.get(m, quantity) is not None for m in methods)]
    if not sets:
        missing = sorted({m for m in methods for s in every if s.get(m, quantity) is None})
        tolerance = f"none: the {kind} of the RMS % error among {methods} decides"
        reason = _lacking(missing or methods, quantity, "the Monte Carlo results")
        return [ClaimResult("not_checkable", "n/a", tolerance, reason, **base)]
    posterior = posterior_set(results)
    if posterior is not None and all(posterior.get(m, quantity) is not None for m in methods):
        judged = _arg_one(kind, args, posterior, results)
        fixed = [_arg_one(kind, args, s, results) for s in sets]
        return [_at_posterior(f"{kind} {expect}", judged, fixed, sets)]
    out = _summary([_arg_one(kind, args, s, results) for s in sets], sets)
    n_cause = _n_cause(f"{kind} {expect}", out, sets)
    return [r if r.cause or r.verdict != "not_upheld" else replace(r, cause=n_cause) for r in out]


@CLAIMS.register("argmin", _ARG_SCHEMA, _expect_among_methods)
def argmin(args: Mapping[str, Any], results: Mapping[str, pd.DataFrame]) -> list[ClaimResult]:
    """The method with the smallest RMS % error is ``expect``, at each N judged."""
    return _arg("argmin", args, results)


@CLAIMS.register("argmax", _ARG_SCHEMA, _expect_among_methods)
def argmax(args: Mapping[str, Any], results: Mapping[str, pd.DataFrame]) -> list[ClaimResult]:
    """The method with the largest RMS % error is ``expect``, at each N judged."""
    return _arg("argmax", args, results)


def _close_one(args: Mapping[str, Any], rank_set: RankSet, results: Any) -> ClaimResult:
    a, b, rel_tol = args["a"], args["b"], float(args["rel_tol"])
    same = a["quantity"] == b["quantity"]
    base = {
        "method": f"{a['method']},{b['method']}",
        "quantity": a["quantity"] if same else f"{a['quantity']}/{b['quantity']}",
        "published": f"{a['method']} ~ {b['method']} (within {rel_tol:g} relative)",
    }
    tolerance = f"{rank_set.where}: |rms_a - rms_b| <= {rel_tol:g} x max(rms_a, rms_b)"
    ra, rb = rank_set.get(a["method"], a["quantity"]), rank_set.get(b["method"], b["quantity"])
    scale = max(ra, rb)
    rel = abs(ra - rb) / scale if scale > 0 else 0.0
    stat = "|error|" if rank_set.noise_free else "rms"
    reproduced = (
        f"{a['method']} ({stat} {ra:.4g} %), {b['method']} ({stat} {rb:.4g} %): "
        f"relative difference {rel:.3g}"
    )
    ok = rel <= rel_tol
    compared = f"{rel:.3g} {'<=' if ok else '>'} {rel_tol:g}"
    note = f"relative difference {compared}"
    reason = f"relative difference of the RMS % error ({rank_set.where}) {compared}"
    cause = None
    if not ok and same:
        cause = causes.for_ranking(a["quantity"], None, [b["method"]], [], results)
    return ClaimResult(
        "upheld" if ok else "not_upheld", reproduced, tolerance, reason,
        suffix=rank_set.suffix, notes=() if ok else (note,), cause=cause, **base,
    )  # fmt: skip


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
    """The RMS % errors of a and b differ by at most rel_tol x the larger, at each N judged."""
    a, b, rel_tol = args["a"], args["b"], float(args["rel_tol"])
    every = rank_sets(results)
    sets = [
        rs for rs in every if all(rs.get(s["method"], s["quantity"]) is not None for s in (a, b))
    ]
    if not sets:
        lacking = [
            (s["method"], s["quantity"])
            for s in (a, b)
            if not every or any(rs.get(s["method"], s["quantity"]) is None for rs in every)
        ]
        base = {
            "method": f"{a['method']},{b['method']}",
            "quantity": a["quantity"]
            if a["quantity"] == b["quantity"]
            else f"{a['quantity']}/{b['quantity']}",  # fmt: skip
            "published": f"{a['method']} ~ {b['method']} (within {rel_tol:g} relative)",
        }
        tolerance = f"|rms_a - rms_b| <= {rel_tol:g} x max(rms_a, rms_b)"
        reason = "; ".join(_lacking([m], q, "the Monte Carlo results") for m, q in lacking)
        return [ClaimResult("not_checkable", "n/a", tolerance, reason, **base)]
    posterior = posterior_set(results)
    if posterior is not None and all(
        posterior.get(s["method"], s["quantity"]) is not None for s in (a, b)
    ):
        judged = _close_one(args, posterior, results)
        fixed = [_close_one(args, s, results) for s in sets]
        return [_at_posterior(f"{a['method']} ~ {b['method']}", judged, fixed, sets)]
    out = _summary([_close_one(args, s, results) for s in sets], sets)
    n_cause = _n_cause(f"{a['method']} ~ {b['method']}", out, sets)
    return [r if r.cause or r.verdict != "not_upheld" else replace(r, cause=n_cause) for r in out]


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
