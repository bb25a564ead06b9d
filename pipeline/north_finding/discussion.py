"""The north_finding part of the report's discussion: what was easy (the ideal-sensor tables),
what was hard (the real-sensor tables and the printed equations), what the paper left open.
Every number is read from the results (verdicts.csv, equation_audit.csv, the published
scenario's n_profile.csv, mc_summary.csv and sensitivity.csv) or its scenario file."""

from __future__ import annotations

import numpy as np
import pandas as pd
import yaml

from pipeline.north_finding.columns import N_PROFILE_COLUMNS, SENSITIVITY_COLUMNS
from pipeline.north_finding.n_inference import fmt_grid
from pipeline.report.discussion import Results, three_parts
from pipeline.report.model import Block, ReportInputs
from pipeline.verdicts import NOISE_FREE_AGREES

__all__ = ["discussion"]


def _averaging(inputs: ReportInputs) -> str:
    scenario = str(inputs.settings.get("published_scenario", "paper"))
    prof = inputs.results / scenario / "n_profile.csv"
    if prof.is_file():
        p = pd.read_csv(prof)
        if set(N_PROFILE_COLUMNS) <= set(p.columns) and p["inferred"].astype(bool).any():
            n = int(p.loc[p["inferred"].astype(bool), "n_avg"].iloc[0])
            return (
                "each row judged on our Monte Carlo mixed over N with the weights the other rows' "
                f"likelihood gives (all rows: maximum at N = {fmt_grid(n)} samples per table "
                "position)"
            )
    path = inputs.scenarios / f"{scenario}.yaml"
    if not path.is_file():
        return "an averaging count of our choice"
    data = yaml.safe_load(path.read_text(encoding="utf-8")) or {}
    n = (data.get("averaging") or {}).get("n_samples")
    return f"{int(n):,} samples per table position" if n else "an averaging count of our choice"


def _sensitivity(inputs: ReportInputs) -> str:
    scenario = str(inputs.settings.get("published_scenario", "paper"))
    path = inputs.results / scenario / "sensitivity.csv"
    if not path.is_file():
        return ""
    s = pd.read_csv(path)
    if not set(SENSITIVITY_COLUMNS) <= set(s.columns) or s.empty:
        return ""
    counts = sorted(s["n_avg"].unique())
    slopes = []
    for _, g in s.groupby(["method", "quantity"]):
        g = g[(g["rms_error_pct"] > 0) & (g["n_avg"] > 0)]
        if len(g) >= 2:
            slopes.append(float(np.polyfit(np.log(g["n_avg"]), np.log(g["rms_error_pct"]), 1)[0]))
    if not slopes:
        return ""
    return (
        f" Over the sensitivity sweep ({int(counts[0]):,} to {int(counts[-1]):,} samples "
        f"averaged) the RMS error falls as the count to the power {np.median(slopes):.2f} "
        f"(median over {len(slopes)} method and quantity pairs), so a printed error pins the "
        "count only through that law."
    )


def discussion(inputs: ReportInputs) -> list[Block]:
    r = Results.read(inputs)
    exact = r.rows(kind="exact")
    stat = r.rows(kind="statistical")
    noise_free = int(stat["note"].astype(str).str.contains(NOISE_FREE_AGREES, regex=False).sum())
    unchecked = r.unchecked_claims()
    easy = (
        f"The ideal-sensor tables: {r.held(exact)} exact values of Tables 1-8 came out to the "
        "printed digits (rounded or truncated) once the turntable kinematics were derived. Of "
        f"the printed equations, {r.equations()}."
    )
    hard = (
        "The real-sensor tables depend on how much the noise is averaged, which the paper does "
        f"not say; with {_averaging(inputs)} {r.held(stat)} real-sensor values fall inside our "
        f"Monte Carlo distribution, and {noise_free} equal our noise-free value to within one "
        "unit of their last printed digit: the printed tables reflect the deterministic sensor "
        "errors with the noise averaged out." + _sensitivity(inputs) + " The printed equations "
        "that differ had to be read against the derivation before any could be coded, and every "
        "half-angle, arccos and quartic solution needed a rule to choose its root."
    )
    left_open = (
        "The averaging count, which misalignment terms are non-zero and their signs, which level "
        "angles feed the azimuth methods, the root choice of every multi-root formula (a "
        "magnetic compass in the paper), the table positions of the least-squares methods and "
        "the definition of the percent error; each is decided in a scenario file (the "
        "assumptions appendix)."
        + (
            " Not checkable from what the paper publishes: " + "; ".join(unchecked) + "."
            if unchecked
            else ""
        )
    )
    return three_parts(easy, hard, left_open)
