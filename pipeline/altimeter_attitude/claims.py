"""Claim predicates of the altimeter-attitude paper (registered in :data:`CLAIMS`).

Each is judged on the published scenario's results (:class:`ScenarioResults`), both angles:

* ``less_rms``: per-run mean squares of filter and reference over each of ``windows``
  (default the flight; one row per window, suffix its name, when given), paired one-sided
  t-test for each angle; upheld if both angles are smaller with p < alpha;
* ``nees_consistent``: one row per angle (suffix ``roll``/``pitch``): the flight-mean NEES
  inside the two-sided chi-square band (p) of a mean over n_runs samples, and the NEES at each
  time after the transient outside that band for at most ``max_outside`` of the samples; a
  failing row says whether the filter is over-confident (NEES above the band: sigma too small)
  or under-confident (below: sigma too large), with the band
  (:mod:`pipeline.altimeter_attitude.consistency`);
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

Failing rows carry their root cause where the results explain it
(:mod:`pipeline.altimeter_attitude.causes`).
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np
import pandas as pd

from pipeline.altimeter_attitude import causes
from pipeline.altimeter_attitude.columns import ALTIMETER_FILTERS, WINDOW_LABELS, WINDOWS
from pipeline.altimeter_attitude.consistency import DIRECTIONS, NeesCheck, nees_check
from pipeline.altimeter_attitude.quantities import ANGLES, ScenarioResults
from pipeline.verdicts.cause import Cause
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


def _verdict(ok: bool | str) -> str:
    return ok if isinstance(ok, str) else ("upheld" if ok else "not_upheld")


def _result(
    name: str,
    args: Mapping[str, Any],
    res: ScenarioResults,
    ok: bool | str,
    text: str,
    tol: str,
    reason: str,
    cause: Cause | None = None,
) -> list[ClaimResult]:
    """One ClaimResult: ``ok`` True/False, or a verdict word (not_checkable)."""
    return [
        ClaimResult(
            _verdict(ok), text, tol, reason, method=args["filter"], quantity=name, cause=cause
        )
    ]


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


_WINDOW_LIST = {"type": "array", "items": {"enum": list(WINDOWS)}, "minItems": 1}


def paired_less_pvalue(x: np.ndarray, y: np.ndarray) -> float:
    """p-value of the paired one-sided t-test that x is smaller than y: what
    ``scipy.stats.ttest_rel(x, y, alternative="less").pvalue`` computes (bit for bit: the same
    mean, variance and Student t distribution function), without importing ``scipy.stats``
    (~0.6 CPU-s of the verdicts step).

    >>> from scipy.stats import ttest_rel
    >>> rng = np.random.default_rng(0)
    >>> x, y = rng.gamma(2.0, 1.0, (2, 100)) ** 2
    >>> ps = [paired_less_pvalue(x, y), paired_less_pvalue(y, x), paired_less_pvalue(x, x)]
    >>> want = [ttest_rel(a, b, alternative="less").pvalue for a, b in [(x, y), (y, x), (x, x)]]
    >>> np.array_equal(ps, want, equal_nan=True)
    True
    """
    from scipy.special import stdtr

    d = np.asarray(x, dtype=float) - np.asarray(y, dtype=float)
    n = d.size
    with np.errstate(divide="ignore", invalid="ignore"):
        var = np.mean((d - np.mean(d, keepdims=True)) ** 2) * (n / (n - 1))
        t = np.mean(d) / np.sqrt(var / n)
    return float(stdtr(float(n - 1), t))


@CLAIMS.register(
    "less_rms",
    _schema(["reference", "alpha"], reference=_FILTER, alpha=_FRACTION, windows=_WINDOW_LIST),
)
def less_rms(args: Mapping[str, Any], res: ScenarioResults) -> list[ClaimResult]:
    """The filter's RMS is below the reference's for both angles (paired one-sided t-test),
    over each window."""
    _need(args, res, "less_rms")
    filt, ref = args["filter"], args["reference"]
    windows = args.get("windows")
    out = []
    for window in windows or ["flight"]:
        start = float(res.window(filt, window)["t_start_s"])
        tol = f"both angles smaller with a paired one-sided p < {args['alpha']}"
        if not math.isfinite(start):
            why = f"the scenario has no {WINDOW_LABELS[window]}"
            out.append(
                ClaimResult(
                    "not_checkable",
                    why,
                    tol,
                    why,
                    filt,
                    "less_rms",
                    suffix=window if windows else "",
                )
            )
            continue
        parts, ok = [], True
        for a in ANGLES:
            x, y = res.per_run(filt, a, window) ** 2, res.per_run(ref, a, window) ** 2
            p = paired_less_pvalue(x, y)
            rx, ry = math.sqrt(x.mean()), math.sqrt(y.mean())
            ok &= rx < ry and p < args["alpha"]
            parts.append(f"{a}: {rx:.3f} vs {ry:.3f} deg (paired one-sided p = {p:.2g})")
        end = float(res.window(filt, window)["t_end_s"])
        text = (
            f"{filt} vs {ref} over the {WINDOW_LABELS[window]} {start:.5g}-{end:.5g} s: "
            + "; ".join(parts)
        )
        why = (
            "both angles smaller and significant" if ok else "not both angles smaller at that level"
        )
        out.append(
            ClaimResult(
                _verdict(ok),
                text,
                tol,
                why,
                method=filt,
                quantity="less_rms",
                suffix=window if windows else "",
                cause=None if ok else causes.ranking_cause(res, filt, ref),
            )
        )
    return out


def _nees_args(args: Mapping[str, Any]) -> tuple[float, float]:
    return float(args["p"]), float(args.get("max_outside", 1.0))


def _nees_checks(res: ScenarioResults) -> list[NeesCheck]:
    """Every filter and angle the published nees_consistent claims judge (for shared causes)."""
    out = []
    for claim in res.published.get("claims", []):
        pred = claim.get("predicate", {})
        if pred.get("test") == "nees_consistent" and pred.get("filter") in res.summary.index:
            p, max_outside = _nees_args(pred)
            out += [nees_check(res, pred["filter"], a, p, max_outside) for a in ANGLES]
    return out


def _nees_cause(res: ScenarioResults, check: NeesCheck) -> Cause | None:
    if check.direction == "over-confident":
        return causes.bias_cause(res, check)
    if check.angle == "roll":
        same = [
            c for c in _nees_checks(res) if c.angle == "roll" and c.direction == check.direction
        ]
        return causes.level_flight_cause(res, same or [check])
    return None


@CLAIMS.register(
    "nees_consistent",
    _schema(["p"], p=_FRACTION, max_outside={"type": "number", "minimum": 0, "maximum": 1}),
)
def nees_consistent(args: Mapping[str, Any], res: ScenarioResults) -> list[ClaimResult]:
    """The filter's NEES is consistent, per angle: flight mean inside, per-time rarely outside
    the chi-square band; else over- or under-confident."""
    _need(args, res, "nees_consistent")
    filt = args["filter"]
    p, max_outside = _nees_args(args)
    out = []
    for a in ANGLES:
        c = nees_check(res, filt, a, p, max_outside)
        lo, hi = c.band
        text = (
            f"NEES {a}: flight mean {c.mean:.2f}; at {c.above:.0%} of {c.n_times} times above "
            f"the band (over-confident), at {c.below:.0%} below it (under-confident); "
            f"after-bank mean {c.after_bank_mean:.2f}"
        )
        tol = (
            f"chi-square band of a mean over {c.n_runs} runs, {p:.0%} two-sided: "
            f"[{lo:.2f}, {hi:.2f}]; flight mean inside it and at most {max_outside:.0%} of the "
            "times outside it"
        )
        if c.ok:
            why = f"{a} consistent"
        else:
            why = f"{a} {c.direction} ({DIRECTIONS[c.direction]})"
        out.append(
            ClaimResult(
                "upheld" if c.ok else "not_upheld",
                text,
                tol,
                why,
                method=filt,
                quantity=f"nees_{a}",
                suffix=a,
                cause=None if c.ok else _nees_cause(res, c),
            )
        )
    return out


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
    parts, ok, tail = [], False, {}
    for a in ANGLES:
        f_c, r_c = res.curve(filt, f"{a}_rms_deg"), res.curve(ref, f"{a}_rms_deg")
        last = f_c.index >= 0.9 * float(f_c.index.max())
        fe = float(np.sqrt(np.mean(f_c[last] ** 2)))
        re_ = float(np.sqrt(np.mean(r_c[last] ** 2)))
        ok |= (not np.isfinite(fe)) or fe >= args["ratio"] * re_
        tail[a] = (fe, re_)
        parts.append(f"{a}: {fe:.3f} vs {re_:.3f} deg ({ref}) over the last tenth")
    text = "; ".join(parts) + f" (diverged if >= {args['ratio']:g}x or not finite)"
    tol = f"last-tenth RMS >= {args['ratio']:g} x {ref}'s or not finite, some angle"
    why = "diverged" if ok else "stays within the ratio of the reference"
    cause = None if ok else causes.ekf_cause(res, filt, ref, tail)
    return _result("diverges", args, res, ok, text, tol, why, cause)


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
