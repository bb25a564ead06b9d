"""The altimeter_attitude summary: what the paper does, the counts of the equation audit and
the verdicts, the headline comparison of the published RMS errors with ours (rms_summary.csv
of the published scenario) and the claims not upheld."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

import pandas as pd

from pipeline.altimeter_attitude.filter_comparison import ANGLES
from pipeline.altimeter_attitude.report_findings import fmt3, fmt_ratio
from pipeline.columns import AUDIT_STATUSES
from pipeline.report.model import Block, Bullets, Paragraph, frame_table, not_available

__all__ = ["CLAIM_WORDS", "VALUE_WORDS", "group_counts", "summary_blocks"]

VALUE_WORDS = ("reproduced", "consistent", "not_reproduced")
CLAIM_WORDS = ("upheld", "not_upheld", "not_checkable")


def group_counts(frame: pd.DataFrame, column: str, words: Sequence[str]) -> pd.Series:
    """Rows per value of ``column``: every word of ``words`` (zeros included, in that order),
    then any other value found (a producer bug, shown so it is not hidden)."""
    counts = frame[column].astype(str).value_counts()
    extra = sorted(set(counts.index) - set(words))
    return counts.reindex(list(words) + extra, fill_value=0).astype(int)


def _value_words(values: pd.DataFrame) -> list[str]:
    # 'reproduced' applies to exact values only; show it when the paper has any
    has_exact = (values["kind"] == "exact").any() or (values["verdict"] == "reproduced").any()
    return [w for w in VALUE_WORDS if has_exact or w != "reproduced"]


def _spelled(counts: pd.Series) -> str:
    return ", ".join(f"{int(n)} {str(w).replace('_', ' ')}" for w, n in counts.items())


def _finite(text: Any) -> bool:
    try:
        return math.isfinite(float(text))
    except (TypeError, ValueError):
        return False


# --------------------------------------------------------------------------- sections


def _headline(verdicts: pd.DataFrame, summary: pd.DataFrame | None, scenario: str) -> list[Block]:
    values = verdicts[verdicts["kind"] != "claim"]
    if values.empty:
        return [not_available("Published values in verdicts.csv")]
    if summary is None:
        return [not_available(f"rms_summary.csv of the published scenario {scenario}")]
    s = summary.set_index("filter")
    rows = []
    for r in values.itertuples():
        ours = (
            float(s.at[r.method, r.quantity])
            if r.method in s.index and r.quantity in s.columns
            else float("nan")
        )
        try:
            pub = float(r.published)
        except ValueError:
            pub = float("nan")
        rows.append(
            {
                "id": r.id,
                "filter": r.method,
                "quantity": r.quantity,
                "published": r.published,
                "ours": ours,
                "ours / published": ours / pub if pub else float("nan"),
                "verdicts.csv reproduced": r.reproduced,
                "verdict": r.verdict,
            }
        )
    table = pd.DataFrame(rows)
    parts = []
    for filt, g in table.groupby("filter", sort=False):
        by_q = g.set_index("quantity")
        qs = [q for q in (f"{a}_rms_deg" for a in ANGLES) if q in by_q.index]
        if not qs:
            continue
        ours = "/".join(fmt3(by_q.at[q, "ours"]) for q in qs)
        pub = "/".join(str(by_q.at[q, "published"]) for q in qs)
        names = "/".join(q.split("_")[0] for q in qs)
        ratios = [float(by_q.at[q, "ours / published"]) for q in qs]
        ratio = "–".join(dict.fromkeys(fmt_ratio(x, 1) for x in (min(ratios), max(ratios))))
        parts.append(
            f"{filt} {names} RMS {ours} deg (paper: {pub} deg; ours is {ratio} times the paper's)"
        )
    text = (
        f"Headline comparison, published scenario {scenario} (rms_summary.csv): "
        + "; ".join(parts)
        + "."
    )
    n_runs = s["n_runs"].dropna().unique() if "n_runs" in s.columns else []
    if len(n_runs):
        text += f" Monte Carlo runs per filter: {', '.join(str(int(n)) for n in n_runs)}."
    # the verdicts must have been computed from these rms_summary values
    stale = [
        r["id"]
        for r in rows
        if math.isfinite(r["ours"])
        and _finite(r["verdicts.csv reproduced"])
        and abs(float(r["verdicts.csv reproduced"]) - r["ours"]) > 1e-3
    ]
    blocks: list[Block] = [
        Paragraph(text),
        frame_table(
            table,
            status="verdict",
            formatters={"ours": fmt3, "ours / published": fmt_ratio},
            caption="Published RMS errors (Sec. 6, Figs. 7 and 12) against ours",
        ),
    ]
    if stale:
        blocks.append(
            Paragraph(
                "verdicts.csv and rms_summary.csv disagree for "
                + ", ".join(stale)
                + " (verdicts.csv may be older than the simulation results)."
            )
        )
    return blocks


def summary_blocks(
    audit: pd.DataFrame | None,
    verdicts: pd.DataFrame,
    summaries: Mapping[str, pd.DataFrame],
    published_scenario: str,
) -> list[Block]:
    """The blocks of the page's Summary section."""
    blocks: list[Block] = [
        Paragraph(
            "The paper estimates roll and pitch of a maneuvering vehicle from a low-cost "
            "strapdown IMU aided by a barometric altimeter. The vertical channel depends on the "
            "attitude only through the third row c of the body-to-NED direction cosine matrix, "
            "so with x = [c, V_d, h] both the attitude kinematics and the vertical channel are "
            "linear in the state and a linear Kalman filter applies; the multiplicative sensor "
            "noise adds a Gamma (Q kron P) Gamma^T covariance term (Appendix A). The paper "
            "compares this filter with a UKF on Euler angles in a Monte Carlo simulation and "
            "finds the linear filter better. This page sets its published numbers and claims "
            "beside our derivation (equation audit) and simulation, and adds baselines (EKF, "
            "complementary filter, gyro-only, accelerometer levelling, the linear filter "
            "without the Gamma term), two more scenarios and a sensitivity sweep."
        )
    ]
    if audit is None:
        audit_text = "Equation audit: equation_audit.csv not available"
    else:
        ac = group_counts(audit, "status", AUDIT_STATUSES)
        audit_text = f"Equation audit: {len(audit)} printed equations checked, {_spelled(ac)}"
    values = verdicts[verdicts["kind"] != "claim"]
    claims = verdicts[verdicts["kind"] == "claim"]
    vc = group_counts(values, "verdict", _value_words(values))
    cc = group_counts(claims, "verdict", CLAIM_WORDS)
    blocks.append(
        Bullets(
            [
                f"{audit_text}.",
                f"Published values: {len(values)}, {_spelled(vc)}.",
                f"Claims: {len(claims)}, {_spelled(cc)}.",
            ]
        )
    )
    blocks += _headline(verdicts, summaries.get(published_scenario), published_scenario)
    failed = claims[claims["verdict"] == "not_upheld"]
    if len(failed):
        blocks.append(Paragraph("Claims not upheld (evidence from verdicts.csv):"))
        blocks.append(
            Bullets(
                [
                    f"{r.id} ({r.method}): {r.published}. Computed: {r.reproduced}."
                    for r in failed.itertuples()
                ]
            )
        )
    else:
        blocks.append(Paragraph("Claims not upheld: none."))
    return blocks
