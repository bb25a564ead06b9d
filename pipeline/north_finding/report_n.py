"""Report block of the N inference: the averaging count N the paper's own values imply.

Reads ``n_profile.csv`` and ``n_rows.csv`` of the published scenario (written by
:mod:`pipeline.north_finding.run_inference`); absent files are shown as not available.
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from pipeline.north_finding.columns import (
    N_PROFILE_COLUMNS,
    N_ROBUSTNESS_COLUMNS,
    N_ROW_COLUMNS,
    N_SENSITIVITY_COLUMNS,
)
from pipeline.north_finding.n_inference import fmt_grid, posterior_range
from pipeline.north_finding.report_results import read_csv
from pipeline.north_finding.report_trouble import trouble_blocks
from pipeline.report.model import Block, Paragraph, Section, frame_table, not_available
from pipeline.report.vocabulary import word

__all__ = ["KS_5PCT", "n_inference_section"]

#: Asymptotic 5 % critical value of the Kolmogorov-Smirnov distance, times sqrt(n).
KS_5PCT = 1.358


def _profile_table(prof: pd.DataFrame) -> Block:
    best = float(prof["log_lik"].max())
    w = np.exp(prof["log_lik"].to_numpy(dtype=float) - best)
    table = pd.DataFrame(
        {
            "N (samples averaged per position)": prof["n_avg"].map(fmt_grid),
            "log-likelihood (nats)": prof["log_lik"].map(lambda x: f"{x:.1f}"),
            "below the maximum (nats)": (best - prof["log_lik"]).map(lambda x: f"{x:.1f}"),
            "weight, all rows (flat prior)": [f"{x:.3f}" for x in w / w.sum()],
            "plain Gaussian, eps = 0 (nats)": prof["log_lik_gaussian"].map(
                lambda x: f"{x:.1f}" if math.isfinite(x) else "-inf"
            ),
            "rows inside the rank band": prof["n_rows_in_band"].astype(int).astype(str),
            "largest KS distance": prof["max_ks"].map(lambda x: f"{x:.3f}"),
            "maximum likelihood": prof["inferred"].map(lambda b: "yes" if b else ""),
        }
    )
    return frame_table(
        table,
        caption="Profile log-likelihood of the paper's statistical rows against N (robust rule; "
        "the plain-Gaussian column shows what the rows our model cannot place would do to it)",
    )


def _robustness(d: Path, label: Callable[[str], str]) -> list[Block]:
    rob = read_csv(d / "n_robustness.csv", N_ROBUSTNESS_COLUMNS)
    if rob is None or rob.empty:
        return []
    table = pd.DataFrame(
        {
            "grid": rob["grid"].map({"grid": "half-decades", "decades": "decades"}),
            "contamination eps": rob["contamination"].map(lambda x: f"{x:g}"),
            "N inferred from all rows": rob["n_inferred"].astype(int).map(fmt_grid),
            "rows not consistent in their leave-one-out mixture": [
                f"{int(k)}: {'; '.join(label(i) for i in str(ids).split(';'))}" if int(k) else "0"
                for k, ids in zip(rob["n_not_consistent"], rob["not_consistent"], strict=True)
            ],
        }
    )
    return [
        frame_table(
            table,
            caption="How much the verdicts rest on the grid and on eps: the inference rerun "
            "(first row: the scenario's choice)",
        )
    ]


#: the sensitivity's variants in words
_VARIANT_WORDS = {
    "as judged": "as judged (correlated rows down-weighted)",
    "rows as independent": "every row weighs 1 (as if independent)",
    "explained rows excluded": "as judged, rows failing for a known cause excluded",
}


def _row_weights(d: Path, label: Callable[[str], str]) -> list[Block]:
    """The sensitivity of the verdicts to how the rows are weighed (n_sensitivity.csv)."""
    sens = read_csv(d.parent / "n_sensitivity.csv", N_SENSITIVITY_COLUMNS)
    if sens is None or sens.empty:
        return []

    def changes(text: Any) -> str:
        if not isinstance(text, str) or not text:
            return "none"
        parts = []
        for change in text.split("; "):
            row_id, _, verdicts = change.partition(": ")
            old, _, new = verdicts.partition(" -> ")
            parts.append(f"{label(row_id)}: {word(old)} -> {word(new)}")
        return "; ".join(parts)

    table = pd.DataFrame(
        {
            "rows weighed": sens["variant"].map(lambda v: _VARIANT_WORDS.get(v, v)),
            "N inferred": sens["n_inferred"].astype(int).map(fmt_grid),
            "weight there": sens["weight_at_n"].map(lambda x: f"{x:.2f}"),
            "effective rows": sens["effective_rows"].map(lambda x: f"{x:.1f}"),
            "verdicts that change": sens["changed"].map(changes),
        }
    )
    return [
        frame_table(
            table,
            caption="How much the verdicts rest on weighing the rows: correlated rows share "
            "one vote (as judged), all rows as independent, and the failing rows with a known "
            "cause left out of the likelihood",
        )
    ]


def labeller(published: Mapping[str, Any] | None) -> Callable[[str], str]:
    """A row's name for readers: its item's label and the paper's name of the method
    ('Table 9, azimuth method 3'), or a claim's text; the id itself for an id the published
    file lacks.

    >>> labeller({"items": [{"id": "T9.psi.A3", "label": "Table 9",
    ...   "select": {"method": "A3"}}], "names": {"A3": "azimuth method 3"}})("T9.psi.A3")
    'Table 9, azimuth method 3'
    """
    published = published or {}
    names = published.get("names") or {}
    by_id = {}
    for item in published.get("items", []):
        method = (item.get("select") or {}).get("method")
        name = names.get(method, f"method {method}") if method else ""
        by_id[item["id"]] = f"{item.get('label', item['id'])}" + (f", {name}" if name else "")
    for claim in published.get("claims", []):
        by_id[claim["id"]] = f"the claim '{claim['text']}' ({claim.get('label', '')})"
    return lambda row_id: by_id.get(row_id, row_id)


def n_inference_section(
    results: Path,
    scenario: str,
    shown: Callable[[Path], str],
    published: Mapping[str, Any] | None = None,
) -> Section:
    """The N inference of the published scenario ``results/<scenario>/`` (rows named by the
    ``published`` file's labels)."""
    label = labeller(published)
    d = results / scenario
    prof = read_csv(d / "n_profile.csv", N_PROFILE_COLUMNS)
    rows = read_csv(d / "n_rows.csv", N_ROW_COLUMNS)
    title = "The averaging count N the paper's values imply"
    if prof is None or rows is None or prof.empty:
        return Section("n-inference", title, [not_available(f"N inference in {shown(d)}")])
    grid = prof["n_avg"].astype(int).tolist()
    best = int(prof.loc[prof["inferred"].astype(bool), "n_avg"].iloc[0])
    ranges: dict[str, list[str]] = {}
    for item_id, r in rows.groupby("id", sort=False):
        r = r.sort_values("n_avg")
        text_range = posterior_range(r["n_avg"].tolist(), r["weight"].tolist(), heaviest=False)
        ranges.setdefault(text_range.removeprefix("90 % of the weight on "), []).append(
            label(str(item_id))
        )
    n_items, n_trials = rows["id"].nunique(), int(prof["n_trials"].iloc[0])
    excluded = [label(i) for i in sorted(set(rows.loc[~rows["used"].astype(bool), "id"]))]
    small, rest = prof.iloc[0], prof.iloc[1:]
    at_best = rows[rows["n_avg"] == best]
    far = [label(i) for i in at_best.loc[at_best["outlier_prob"] > 0.5, "id"].tolist()]
    plain_best = int(prof["n_avg"].iloc[int(prof["log_lik_gaussian"].to_numpy().argmax())])
    first = rows.drop_duplicates("id")
    n_used = int(first["used"].astype(bool).sum())
    eff = float(first.loc[first["used"].astype(bool), "row_weight"].sum())
    text = (
        "The paper averages its 5 % white noise 'as much as possible' but gives no number of "
        "samples N, and the spread of every real-sensor value scales as 1/sqrt(N); the "
        f"{n_items} statistical rows are therefore judged against the N the paper's own printed "
        "values imply, not at one we chose. For each row and each N of the grid "
        f"({fmt_grid(grid[0])} to {fmt_grid(grid[-1])}, half-decades), a Gaussian fitted to our "
        "Monte Carlo trials at that N gives the probability of the printed value (every number "
        "that prints as it); the robust rule and the leave-one-out posterior predictive check are "
        "the decision 'n_inference' in the assumptions. Rows that share readings are "
        "correlated and share their vote: each row's log-likelihood counts 1 / sum_j r_ij^2 "
        f"(r the correlation of the rows' trials), {eff:.1f} effective rows of {n_used} used. "
        "All rows together imply "
        f"N = {fmt_grid(best)} samples averaged per table position (the maximum; the profile "
        "below shows how flat it is). Each row is judged on the mixture over the grid N of our "
        "Monte Carlo trials at N, weighted by the likelihood of the other rows at N (flat prior "
        "over log10 N): its percentile rank is sum_N w_N rank_N. Where 90 % of the weight "
        "lies: "
        + "; ".join(
            f"{where} for {len(ids)} row{'s' if len(ids) != 1 else ''}"
            + (f" ({'; '.join(ids)})" if len(ids) <= 4 else "")
            for where, ids in sorted(ranges.items(), key=lambda kv: (-len(kv[1]), kv[0]))
        )
        + f" (n_rows.csv, column weight; at 1 kHz, N = {fmt_grid(best)} is {best / 1000 / 60:.0f} min per table position). "
        + (
            f"At N = {fmt_grid(best)} the rows {'; '.join(far)} are more likely (posterior > 0.5) "
            "from a run the paper does not describe than from our model: the robust rule bounds "
            "their pull on N (with the plain Gaussian, eps = 0, they would drag the estimate "
            f"to N = {fmt_grid(plain_best)}). "
            if far
            else ""
        )
        + (
            f"Excluded (outside the rank band at every grid N): {'; '.join(excluded)}. "
            if excluded
            else "No row lies outside the rank band at every grid N, so none is excluded. "
        )
        + "The Gaussian fits the trials: the largest Kolmogorov-Smirnov distance over the rows "
        f"is {float(rest['max_ks'].max()):.3f} for N >= {fmt_grid(grid[1])} and "
        f"{float(small['max_ks']):.3f} at N = {fmt_grid(grid[0])}, against "
        f"{KS_5PCT:.3f}/sqrt({n_trials}) = {KS_5PCT / math.sqrt(n_trials):.3f} for "
        f"{n_trials} trials at the 5 % level."
    )
    # where each row is consistent on the grid is in its verdict row's notes (the page budget
    # of the PDF's main part leaves no room for a second per-row table)
    blocks = [
        Paragraph(text),
        _profile_table(prof),
        *_robustness(d, label),
        *_row_weights(d, label),
        *trouble_blocks(d / "n_trouble.csv"),
    ]
    return Section("n-inference", title, blocks)
