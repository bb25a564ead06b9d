"""Claim predicates of the altimeter-attitude paper (registered in :data:`CLAIMS`).

Each is judged on the published scenario's results (:class:`ScenarioResults`), both angles:

* ``less_rms``: per-run mean squares of filter and reference, paired one-sided t-test for each
  angle; upheld if both angles are smaller with p < alpha;
* ``nees_consistent``: for each angle, the flight-mean NEES inside the two-sided chi-square
  interval (p) of a mean over n_runs samples, and the NEES at each time after the transient
  outside that interval for at most ``max_outside`` of the samples (the fractions above,
  over-confident, and below, under-confident, are reported);
* ``bounded``: RMS over the last quarter of the flight / RMS over its second quarter <=
  growth_ratio for both angles; the same test on the reference (an unbounded solution,
  gyro-only): if the reference passes too, the flight is too short to tell a bounded error
  from a drifting one, and the verdict is ``not_checkable``;
* ``norm_stable``: max RMS of 1 - c^T c after the transient <= max_rms and the same quarter
  ratio <= growth_ratio;
* ``fails_under_acceleration``: RMS of the filter over the accelerated samples
  (|load factor - 1| > load_deviation) >= ratio x that of the reference;
* ``diverges``: RMS over the last tenth non-finite or >= ratio x the reference's;
* ``term_matters``: relative change of the RMS error or of the sigma from reference to filter
  >= rel_change for some angle.
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np
import pandas as pd

from pipeline.altimeter_attitude.columns import ALTIMETER_FILTERS
from pipeline.altimeter_attitude.metrics import nees_bounds
from pipeline.altimeter_attitude.quantities import ANGLES, ScenarioResults
from pipeline.verdicts.claims import ClaimRegistry, ClaimResult

__all__ = ["CLAIMS"]

CLAIMS = ClaimRegistry()

_FILTER = {"enum": list(ALTIMETER_FILTERS)}
_POS = {"type": "number", "exclusiveMinimum": 0}
_ABOVE_1 = {"type": "number", "exclusiveMinimum": 1}
_FRACTION = {"type": "number", "exclusiveMinimum": 0, "exclusiveMaximum": 1}


def _schema(required: list[str], **props: Any) -> dict[str, Any]:
    return {
        "type": "object",
        "required": ["filter", *required],
        "properties": {"filter": _FILTER, **props},
    }


def _result(
    name: str,
    args: Mapping[str, Any],
    res: ScenarioResults,
    ok: bool | str,
    text: str,
    tol: str,
    reason: str,
) -> list[ClaimResult]:
    """One ClaimResult: ``ok`` True/False, or a verdict word (not_checkable)."""
    verdict = ok if isinstance(ok, str) else ("upheld" if ok else "not_upheld")
    return [ClaimResult(verdict, text, tol, reason, method=args["filter"], quantity=name)]


def _need(args: Mapping[str, Any], res: ScenarioResults, name: str) -> None:
    res.need(args["filter"], name)
    if args.get("reference"):
        res.need(args["reference"], name)


def _quarters(curve: pd.Series, start: float) -> tuple[float, float]:
    """RMS of a curve over the second and the last quarter of [start, end]."""
    c = curve[curve.index >= start]
    t0, t1 = float(c.index.min()), float(c.index.max())
    span = t1 - t0
    q2 = c[(c.index >= t0 + span / 4) & (c.index < t0 + span / 2)]
    q4 = c[c.index >= t0 + 3 * span / 4]
    return float(np.sqrt(np.mean(q2**2))), float(np.sqrt(np.mean(q4**2)))


@CLAIMS.register("less_rms", _schema(["reference", "alpha"], reference=_FILTER, alpha=_FRACTION))
def less_rms(args: Mapping[str, Any], res: ScenarioResults) -> list[ClaimResult]:
    """The filter's RMS is below the reference's for both angles (paired one-sided t-test)."""
    from scipy.stats import ttest_rel

    _need(args, res, "less_rms")
    filt, ref = args["filter"], args["reference"]
    parts, ok = [], True
    for a in ANGLES:
        x, y = res.per_run(filt, a) ** 2, res.per_run(ref, a) ** 2
        p = float(ttest_rel(x, y, alternative="less").pvalue)
        rx, ry = math.sqrt(x.mean()), math.sqrt(y.mean())
        ok &= rx < ry and p < args["alpha"]
        parts.append(f"{a}: {rx:.3f} vs {ry:.3f} deg (paired one-sided p = {p:.2g})")
    text = f"{filt} vs {ref}: " + "; ".join(parts)
    tol = f"both angles smaller with a paired one-sided p < {args['alpha']}"
    why = "both angles smaller and significant" if ok else "not both angles smaller at that level"
    return _result("less_rms", args, res, ok, text, tol, why)


@CLAIMS.register(
    "nees_consistent",
    _schema(["p"], p=_FRACTION, max_outside={"type": "number", "minimum": 0, "maximum": 1}),
)
def nees_consistent(args: Mapping[str, Any], res: ScenarioResults) -> list[ClaimResult]:
    """The filter's NEES is consistent: flight mean inside, per-time rarely outside the interval."""
    _need(args, res, "nees_consistent")
    filt = args["filter"]
    n = int(res.summary.loc[filt, "n_runs"])
    lo, hi = nees_bounds(n, p=args["p"])
    max_outside = float(args.get("max_outside", 1.0))
    parts, ok, failed = [], True, []
    for a in ANGLES:
        mean = float(res.summary.loc[filt, f"nees_{a}"])
        per_time = res.curve(filt, f"nees_{a}")
        per_time = per_time[per_time.index >= res.transient].to_numpy(float)
        above, below = float(np.mean(per_time > hi)), float(np.mean(per_time < lo))
        good = lo <= mean <= hi and above + below <= max_outside
        ok &= good
        if not good:
            failed.append(f"{a} ({above:.0%} over-confident, {below:.0%} under-confident)")
        parts.append(
            f"NEES {a}: flight mean {mean:.2f}, per time above the interval {above:.0%} "
            f"(over-confident) and below {below:.0%} of {len(per_time)} samples"
        )
    text = "; ".join(parts)
    tol = (
        f"flight-mean NEES in the {args['p']:.0%} interval for a mean over {n} runs "
        f"[{lo:.2f}, {hi:.2f}] and at most {max_outside:.0%} of the times outside it"
    )
    why = "both angles inside" if ok else "outside for " + ", ".join(failed)
    return _result("nees_consistent", args, res, ok, text, tol, why)


@CLAIMS.register(
    "bounded", _schema(["reference", "growth_ratio"], reference=_FILTER, growth_ratio=_ABOVE_1)
)
def bounded(args: Mapping[str, Any], res: ScenarioResults) -> list[ClaimResult]:
    """The error does not grow (last / second quarter), unlike the drifting reference."""
    _need(args, res, "bounded")
    filt, ref, ratio = args["filter"], args["reference"], args["growth_ratio"]
    parts, ok, ref_ok = [], True, True
    for a in ANGLES:
        q2, q4 = _quarters(res.curve(filt, f"{a}_rms_deg"), res.transient)
        r2, r4 = _quarters(res.curve(ref, f"{a}_rms_deg"), res.transient)
        ok &= q4 <= ratio * q2
        ref_ok &= r4 <= ratio * r2
        parts.append(
            f"{a}: last/second quarter {q4:.3f}/{q2:.3f} = {q4 / q2:.2f} ({ref}: {r4 / r2:.2f})"
        )
    text = "; ".join(parts) + f" (bounded if <= {ratio})"
    tol = f"RMS over the last quarter <= {ratio} x over the second quarter, both angles"
    if ok and ref_ok:
        why = (
            f"{ref} passes the same test, so this flight is too short to tell a bounded "
            "error from a drifting one"
        )
        return _result("bounded", args, res, "not_checkable", text + "; " + why, tol, why)
    why = "within the ratio" if ok else "grows beyond the ratio"
    return _result("bounded", args, res, ok, text, tol, why)


@CLAIMS.register(
    "norm_stable", _schema(["max_rms", "growth_ratio"], max_rms=_POS, growth_ratio=_ABOVE_1)
)
def norm_stable(args: Mapping[str, Any], res: ScenarioResults) -> list[ClaimResult]:
    """The normalisation error 1 - c^T c stays small and does not grow."""
    _need(args, res, "norm_stable")
    c = res.curve(args["filter"], "norm_error_rms")
    c = c[c.index >= res.transient]
    q2, q4 = _quarters(c, res.transient)
    small = float(c.max()) <= args["max_rms"]
    flat = q4 <= args["growth_ratio"] * max(q2, 1e-300)
    text = (
        f"max RMS of 1 - c^T c after {res.transient:g} s: {c.max():.2e} (<= {args['max_rms']:g}); "
        f"last/second quarter {q4:.2e}/{q2:.2e}"
    )
    tol = f"max RMS <= {args['max_rms']:g} and last/second quarter <= {args['growth_ratio']}"
    why = f"{'small' if small else 'too large'}, {'not growing' if flat else 'growing'}"
    return _result("norm_stable", args, res, small and flat, text, tol, why)


@CLAIMS.register(
    "fails_under_acceleration",
    _schema(
        ["reference", "ratio", "load_deviation"],
        reference=_FILTER,
        ratio=_ABOVE_1,
        load_deviation=_POS,
    ),
)
def fails_under_acceleration(args: Mapping[str, Any], res: ScenarioResults) -> list[ClaimResult]:
    """Over the accelerated samples the filter's RMS is >= ratio x the reference's."""
    _need(args, res, "fails_under_acceleration")
    filt, ref, dev = args["filter"], args["reference"], args["load_deviation"]
    parts, ok = [], True
    for a in ANGLES:
        f_c, r_c = res.curve(filt, f"{a}_rms_deg"), res.curve(ref, f"{a}_rms_deg")
        lf = res.load_factor.reindex(f_c.index.round(9)).to_numpy()
        late = f_c.index >= res.transient
        acc, quiet = (np.abs(lf - 1.0) > dev) & late, (np.abs(lf - 1.0) <= dev) & late
        fa = float(np.sqrt(np.mean(f_c[acc] ** 2)))
        ra = float(np.sqrt(np.mean(r_c[acc] ** 2)))
        fq = float(np.sqrt(np.mean(f_c[quiet] ** 2)))
        ok &= fa >= args["ratio"] * ra
        parts.append(f"{a}: {fa:.2f} deg accelerated vs {ra:.2f} ({ref}); {fq:.2f} unaccelerated")
    share = float(np.mean(np.abs(res.load_factor.to_numpy() - 1) > dev))
    text = "; ".join(parts) + f" ({share:.0%} of the flight has |n - 1| > {dev})"
    tol = f"RMS over |n - 1| > {dev} >= {args['ratio']:g} x {ref}'s, both angles"
    why = "far worse under acceleration" if ok else "not that much worse under acceleration"
    return _result("fails_under_acceleration", args, res, ok, text, tol, why)


@CLAIMS.register("diverges", _schema(["reference", "ratio"], reference=_FILTER, ratio=_ABOVE_1))
def diverges(args: Mapping[str, Any], res: ScenarioResults) -> list[ClaimResult]:
    """Over the last tenth the filter's RMS is not finite or >= ratio x the reference's."""
    _need(args, res, "diverges")
    filt, ref = args["filter"], args["reference"]
    parts, ok = [], False
    for a in ANGLES:
        f_c, r_c = res.curve(filt, f"{a}_rms_deg"), res.curve(ref, f"{a}_rms_deg")
        tail = f_c.index >= 0.9 * float(f_c.index.max())
        fe = float(np.sqrt(np.mean(f_c[tail] ** 2)))
        re_ = float(np.sqrt(np.mean(r_c[tail] ** 2)))
        ok |= (not np.isfinite(fe)) or fe >= args["ratio"] * re_
        parts.append(f"{a}: {fe:.3f} vs {re_:.3f} deg ({ref}) over the last tenth")
    text = "; ".join(parts) + f" (diverged if >= {args['ratio']:g}x or not finite)"
    tol = f"last-tenth RMS >= {args['ratio']:g} x {ref}'s or not finite, some angle"
    why = "diverged" if ok else "stays within the ratio of the reference"
    return _result("diverges", args, res, ok, text, tol, why)


@CLAIMS.register(
    "term_matters", _schema(["reference", "rel_change"], reference=_FILTER, rel_change=_POS)
)
def term_matters(args: Mapping[str, Any], res: ScenarioResults) -> list[ClaimResult]:
    """Dropping the term changes the RMS error or the sigma by >= rel_change for some angle."""
    _need(args, res, "term_matters")
    filt, ref = args["filter"], args["reference"]
    parts, worst = [], 0.0
    for a in ANGLES:
        for q in ("rms", "sigma"):
            x = float(res.summary.loc[filt, f"{a}_{q}_deg"])
            y = float(res.summary.loc[ref, f"{a}_{q}_deg"])
            rel = abs(x - y) / y
            worst = max(worst, rel)
            parts.append(f"{a} {q} {x:.4f} vs {y:.4f} ({rel:.1%})")
    ok = worst >= args["rel_change"]
    text = f"{filt} vs {ref}: " + "; ".join(parts)
    tol = f"largest relative change >= {args['rel_change']:.0%}"
    why = f"largest relative change {worst:.1%} {'>=' if ok else '<'} {args['rel_change']:.0%}"
    return _result("term_matters", args, res, ok, text, tol, why)
