"""Verdicts of the altimeter-attitude paper: published numbers and claims vs our Monte Carlo.

Inputs: ``config/published/altimeter_attitude.yaml`` and the results of the published
scenario (``rms_summary.csv``, ``run_rms.csv``, ``timeseries.csv``, ``truth.csv``).
Output: ``results/altimeter_attitude/verdicts.csv`` with the contract columns; ``method`` is the
filter a verdict is about.

Rules
-----
* Values (kind ``statistical``): the paper's approximate RMS against rms_summary.csv:
  ``consistent`` if |ours - published| <= tolerance_rel x published + 2 SE, with SE the Monte
  Carlo standard error of our RMS (delta method over the per-run mean squares); else
  ``not_reproduced``.
* Claims:
  ``less_rms``: per-run mean squares of filter and reference, paired one-sided t-test for
  each angle; upheld if both angles are smaller with p < alpha;
  ``nees_consistent``: for each angle, the flight-mean NEES inside the two-sided chi-square
  interval (p) of a mean over n_runs samples, and the NEES at each time after the transient
  (mean over runs) outside that interval for at most ``max_outside`` of the samples (a
  consistent filter is outside for 1 - p of them; the fractions above and below are reported);
  ``bounded``: RMS over the last quarter of the flight / RMS over its second quarter <=
  growth_ratio for both angles. The same test is applied to the reference (an unbounded
  solution, gyro-only): if the reference passes too, the flight is too short for the test to
  tell a bounded error from a drifting one, and the verdict is ``not_checkable``;
  ``norm_stable``: max RMS of 1 - c^T c after the transient <= max_rms and the same quarter
  ratio <= growth_ratio;
  ``fails_under_acceleration``: RMS of the filter over the accelerated samples (|load factor
  - 1| > load_deviation) >= ratio x that of the reference;
  ``diverges``: RMS over the last tenth non-finite or >= ratio x the reference's;
  ``term_matters``: relative change of the RMS error or of the sigma from reference to filter
  >= rel_change for some angle.
"""

from __future__ import annotations

import argparse
import math
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from pipeline.altimeter_attitude.metrics import nees_bounds
from pipeline.atomic import write_csv
from pipeline.columns import VERDICT_COLUMNS
from pipeline.config import ConfigError, load_schema, load_yaml, validate

__all__ = [
    "load_published",
    "ScenarioResults",
    "value_verdicts",
    "claim_verdicts",
    "verdicts",
    "main",
]

ANGLES = ("roll", "pitch")


def load_published(path: str | Path) -> dict[str, Any]:
    """Parse and validate the published-values file (ConfigError names file and field)."""
    data = load_yaml(path)
    validate(data, load_schema("published_altimeter_attitude"), path)
    ids = [x["id"] for x in data["values"]] + [c["id"] for c in data["claims"]]
    dup = sorted({i for i in ids if ids.count(i) > 1})
    if dup:
        raise ConfigError(f"{path}: duplicate ids {dup}")
    return data


class ScenarioResults:
    """The result files of one scenario, read once."""

    def __init__(self, directory: str | Path) -> None:
        d = Path(directory)
        self.directory = d
        self.summary = pd.read_csv(d / "rms_summary.csv").set_index("filter")
        self.run_rms = pd.read_csv(d / "run_rms.csv")
        self.series = pd.read_csv(d / "timeseries.csv")
        truth = pd.read_csv(d / "truth.csv", usecols=["t_s", "load_factor"])
        self.load_factor = truth.set_index(truth["t_s"].round(9))["load_factor"]

    def need(self, filt: str, source: str) -> None:
        if filt not in self.summary.index:
            raise ConfigError(
                f"{source}: filter {filt!r} has no results in {self.directory}; "
                f"available: {sorted(self.summary.index)}"
            )

    def curve(self, filt: str, column: str) -> pd.Series:
        rows = self.series[self.series["filter"] == filt]
        return rows.set_index("t_s")[column].sort_index()

    def per_run(self, filt: str, angle: str) -> np.ndarray:
        rows = self.run_rms[self.run_rms["filter"] == filt].sort_values("run")
        return rows[f"{angle}_rms_deg"].to_numpy()


def _standard_error(per_run_rms: np.ndarray) -> float:
    """SE of sqrt(mean MSE) over runs, by the delta method."""
    mse = per_run_rms**2
    rms = math.sqrt(mse.mean())
    return float(mse.std(ddof=1) / math.sqrt(len(mse)) / (2 * rms)) if rms > 0 else 0.0


def value_verdicts(published: dict[str, Any], res: ScenarioResults) -> list[dict[str, Any]]:
    rows = []
    for item in published["values"]:
        res.need(item["filter"], item["id"])
        ours = float(res.summary.loc[item["filter"], item["quantity"]])
        angle = item["quantity"].split("_")[0]
        se = _standard_error(res.per_run(item["filter"], angle))
        pub = float(item["value"])
        allowed = item["tolerance_rel"] * pub + 2 * se
        ok = abs(ours - pub) <= allowed
        rows.append(
            {
                "id": item["id"],
                "kind": "statistical",
                "quantity": item["quantity"],
                "method": item["filter"],
                "published": f"{pub:g}",
                "reproduced": f"{ours:.4f}",
                "verdict": "consistent" if ok else "not_reproduced",
                "note": (
                    f"{item['figure']}; ours {ours:.3f} deg (MC standard error {se:.3f}, "
                    f"{len(res.per_run(item['filter'], angle))} runs) is {ours / pub:.2f}x the "
                    f"published {pub:g}; consistent if within {item['tolerance_rel']:.0%} + 2 SE "
                    f"= +-{allowed:.3f} deg. {item['source']}"
                ),
            }
        )
    return rows


def _quarters(curve: pd.Series, start: float) -> tuple[float, float]:
    """RMS of a curve over the second and the last quarter of [start, end]."""
    c = curve[curve.index >= start]
    t0, t1 = float(c.index.min()), float(c.index.max())
    span = t1 - t0
    q2 = c[(c.index >= t0 + span / 4) & (c.index < t0 + span / 2)]
    q4 = c[c.index >= t0 + 3 * span / 4]
    return float(np.sqrt(np.mean(q2**2))), float(np.sqrt(np.mean(q4**2)))


def _claim(pred: dict[str, Any], res: ScenarioResults, transient: float) -> tuple[str, str]:
    """(verdict, what was computed) of one claim predicate."""
    kind, filt = pred["type"], pred["filter"]
    ref = pred.get("reference")
    res.need(filt, kind)
    if ref:
        res.need(ref, kind)
    if kind == "less_rms":
        from scipy.stats import ttest_rel

        parts, ok = [], True
        for a in ANGLES:
            x, y = res.per_run(filt, a) ** 2, res.per_run(ref, a) ** 2
            p = float(ttest_rel(x, y, alternative="less").pvalue)
            rx, ry = math.sqrt(x.mean()), math.sqrt(y.mean())
            ok &= rx < ry and p < pred["alpha"]
            parts.append(f"{a}: {rx:.3f} vs {ry:.3f} deg (paired one-sided p = {p:.2g})")
        return ("upheld" if ok else "not_upheld"), f"{filt} vs {ref}: " + "; ".join(parts)
    if kind == "nees_consistent":
        n = int(res.summary.loc[filt, "n_runs"])
        lo, hi = nees_bounds(n, p=pred["p"])
        max_outside = float(pred.get("max_outside", 1.0))
        parts, ok = [], True
        for a in ANGLES:
            mean = float(res.summary.loc[filt, f"nees_{a}"])
            per_time = res.curve(filt, f"nees_{a}")
            per_time = per_time[per_time.index >= transient].to_numpy(float)
            above, below = float(np.mean(per_time > hi)), float(np.mean(per_time < lo))
            ok &= lo <= mean <= hi and above + below <= max_outside
            parts.append(
                f"NEES {a}: flight mean {mean:.2f}, per time above the interval {above:.0%} "
                f"(over-confident) and below {below:.0%} of {len(per_time)} samples"
            )
        return ("upheld" if ok else "not_upheld"), "; ".join(parts) + (
            f"; {pred['p']:.0%} interval for a mean over {n} runs [{lo:.2f}, {hi:.2f}], "
            f"consistent if the mean is inside and at most {max_outside:.0%} of the times outside"
        )
    if kind == "bounded":
        parts, ok, ref_ok = [], True, True
        for a in ANGLES:
            q2, q4 = _quarters(res.curve(filt, f"{a}_rms_deg"), transient)
            r2, r4 = _quarters(res.curve(ref, f"{a}_rms_deg"), transient)
            ok &= q4 <= pred["growth_ratio"] * q2
            ref_ok &= r4 <= pred["growth_ratio"] * r2
            parts.append(
                f"{a}: last/second quarter {q4:.3f}/{q2:.3f} = {q4 / q2:.2f} ({ref}: {r4 / r2:.2f})"
            )
        text = "; ".join(parts) + f" (bounded if <= {pred['growth_ratio']})"
        if ok and ref_ok:
            return "not_checkable", text + (
                f"; {ref} passes the same test, so this flight is too short to tell a bounded "
                "error from a drifting one"
            )
        return ("upheld" if ok else "not_upheld"), text
    if kind == "norm_stable":
        c = res.curve(filt, "norm_error_rms")
        c = c[c.index >= transient]
        q2, q4 = _quarters(c, transient)
        ok = float(c.max()) <= pred["max_rms"] and q4 <= pred["growth_ratio"] * max(q2, 1e-300)
        return ("upheld" if ok else "not_upheld"), (
            f"max RMS of 1 - c^T c after {transient:g} s: {c.max():.2e} (<= {pred['max_rms']:g}); "
            f"last/second quarter {q4:.2e}/{q2:.2e}"
        )
    if kind == "fails_under_acceleration":
        parts, ok = [], True
        for a in ANGLES:
            f_c = res.curve(filt, f"{a}_rms_deg")
            r_c = res.curve(ref, f"{a}_rms_deg")
            lf = res.load_factor.reindex(f_c.index.round(9)).to_numpy()
            acc = (np.abs(lf - 1.0) > pred["load_deviation"]) & (f_c.index >= transient)
            quiet = (np.abs(lf - 1.0) <= pred["load_deviation"]) & (f_c.index >= transient)
            fa = float(np.sqrt(np.mean(f_c[acc] ** 2)))
            ra = float(np.sqrt(np.mean(r_c[acc] ** 2)))
            fq = float(np.sqrt(np.mean(f_c[quiet] ** 2)))
            ok &= fa >= pred["ratio"] * ra
            parts.append(
                f"{a}: {fa:.2f} deg accelerated vs {ra:.2f} ({ref}); {fq:.2f} unaccelerated"
            )
        share = float(np.mean(np.abs(res.load_factor.to_numpy() - 1) > pred["load_deviation"]))
        return ("upheld" if ok else "not_upheld"), "; ".join(parts) + (
            f" ({share:.0%} of the flight has |n - 1| > {pred['load_deviation']})"
        )
    if kind == "diverges":
        parts, ok = [], False
        for a in ANGLES:
            f_c, r_c = res.curve(filt, f"{a}_rms_deg"), res.curve(ref, f"{a}_rms_deg")
            t_end = float(f_c.index.max())
            tail = f_c.index >= 0.9 * t_end
            fe = float(np.sqrt(np.mean(f_c[tail] ** 2)))
            re_ = float(np.sqrt(np.mean(r_c[tail] ** 2)))
            ok |= (not np.isfinite(fe)) or fe >= pred["ratio"] * re_
            parts.append(f"{a}: {fe:.3f} vs {re_:.3f} deg ({ref}) over the last tenth")
        return ("upheld" if ok else "not_upheld"), "; ".join(parts) + (
            f" (diverged if >= {pred['ratio']:g}x or not finite)"
        )
    if kind == "term_matters":
        parts, worst = [], 0.0
        for a in ANGLES:
            for q in ("rms", "sigma"):
                x = float(res.summary.loc[filt, f"{a}_{q}_deg"])
                y = float(res.summary.loc[ref, f"{a}_{q}_deg"])
                rel = abs(x - y) / y
                worst = max(worst, rel)
                parts.append(f"{a} {q} {x:.4f} vs {y:.4f} ({rel:.1%})")
        ok = worst >= pred["rel_change"]
        return ("upheld" if ok else "not_upheld"), f"{filt} vs {ref}: " + "; ".join(parts)
    raise ConfigError(f"claim predicate type {kind!r} unknown")


def claim_verdicts(
    published: dict[str, Any], res: ScenarioResults, transient: float
) -> list[dict[str, Any]]:
    rows = []
    for claim in published["claims"]:
        verdict, computed = _claim(claim["predicate"], res, transient)
        rows.append(
            {
                "id": claim["id"],
                "kind": "claim",
                "quantity": claim["predicate"]["type"],
                "method": claim["predicate"]["filter"],
                "published": claim["text"],
                "reproduced": computed,
                "verdict": verdict,
                "note": claim["source"],
            }
        )
    return rows


def verdicts(published: dict[str, Any], scenario_dir: str | Path, transient: float) -> pd.DataFrame:
    res = ScenarioResults(scenario_dir)
    rows = value_verdicts(published, res) + claim_verdicts(published, res, transient)
    return pd.DataFrame(rows, columns=VERDICT_COLUMNS)


def main(argv: list[str] | None = None) -> int:
    from pipeline.altimeter_attitude.scenario import load_scenario

    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--published", type=Path, default=Path("config/published/altimeter_attitude.yaml")
    )
    parser.add_argument(
        "--scenario", type=Path, required=True, help="the published scenario's YAML"
    )
    parser.add_argument("--results", type=Path, required=True, help="its results directory")
    parser.add_argument("--out", type=Path, required=True, help="verdicts.csv to write")
    args = parser.parse_args(argv)
    try:
        published = load_published(args.published)
        sc = load_scenario(args.scenario)
    except (ValueError, OSError) as exc:
        print(f"error: {exc}")
        return 2
    frame = verdicts(published, args.results, sc.transient)
    write_csv(args.out, frame, VERDICT_COLUMNS)
    print(frame["verdict"].value_counts().to_dict())
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
