"""The altimeter_attitude summary: what the paper does, the counts of the equation audit and
the verdicts, and the headline comparison of the published RMS errors with ours per averaging
window (window_summary.csv of the published scenario; rms_summary.csv for the flight when it
is absent). The comparison's table (:func:`headline_blocks`) goes with the results; the
claims not upheld and the root causes are the shared template's (its claims tables and its
list of causes)."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

import pandas as pd

from pipeline.altimeter_attitude.columns import RMS_SUMMARY_COLUMNS, WINDOW_LABELS, WINDOWS
from pipeline.altimeter_attitude.filter_comparison import ANGLES
from pipeline.altimeter_attitude.report_findings import DASH, filter_order, fmt3, fmt_ratio
from pipeline.columns import AUDIT_STATUSES
from pipeline.report.model import Block, Bullets, Paragraph, Table, frame_table, not_available
from pipeline.verdicts.kinds import NUMBER_VERDICTS

__all__ = [
    "CLAIM_WORDS",
    "VALUE_WORDS",
    "group_counts",
    "headline_blocks",
    "after_bank_blocks",
    "summary_blocks",
]

VALUE_WORDS = ("reproduced", "consistent", "not_reproduced")
CLAIM_WORDS = ("upheld", "not_upheld", "not_checkable")


def group_counts(frame: pd.DataFrame, column: str, words: Sequence[str]) -> pd.Series:
    """Rows per value of ``column``: every word of ``words`` (zeros included, in that order),
    then any other value found (a producer bug, shown so it is not hidden)."""
    counts = frame[column].astype(str).value_counts()
    extra = sorted(set(counts.index) - set(words))
    return counts.reindex(list(words) + extra, fill_value=0).astype(int)


def _value_words(values: pd.DataFrame) -> list[str]:
    """The verdict words of the kinds present (pipeline.verdicts.kinds.NUMBER_VERDICTS:
    'consistent' is the statistical kind's, 'reproduced' the exact and approximate kinds')."""
    allowed = {w for k in set(values["kind"]) for w in NUMBER_VERDICTS.get(k, ())}
    allowed |= set(values["verdict"])
    return [w for w in VALUE_WORDS if w in allowed]


def _spelled(counts: pd.Series) -> str:
    return ", ".join(f"{int(n)} {str(w).replace('_', ' ')}" for w, n in counts.items())


def _finite(text: Any) -> bool:
    try:
        return math.isfinite(float(text))
    except (TypeError, ValueError):
        return False


# --------------------------------------------------------------------------- sections


def _window_of(row_id: str) -> str:
    """The averaging window of a value row (its id suffix; ``flight`` without one)."""
    tail = row_id.rsplit("/", 1)[-1] if "/" in row_id else ""
    return tail if tail in WINDOWS else "flight"


def _ours(
    summary: pd.DataFrame, windows: pd.DataFrame | None, filt: str, quantity: str, window: str
) -> float:
    """Our value of a filter and quantity over a window (window_summary.csv; the flight
    window falls back on rms_summary.csv)."""
    if windows is not None:
        rows = windows[(windows["window"] == window) & (windows["filter"] == filt)]
        if len(rows) == 1 and quantity in rows.columns:
            return float(rows.iloc[0][quantity])
    if window == "flight" and filt in summary.index and quantity in summary.columns:
        return float(summary.at[filt, quantity])
    return float("nan")


def _window_text(windows: pd.DataFrame | None) -> str:
    if windows is None:
        return ""
    parts = []
    for w in WINDOWS:
        rows = windows[windows["window"] == w]
        if len(rows) and math.isfinite(float(rows.iloc[0]["t_start_s"])):
            r = rows.iloc[0]
            parts.append(
                f"{WINDOW_LABELS[w]} {float(r['t_start_s']):.5g}-{float(r['t_end_s']):.5g} s"
            )
        elif len(rows):
            parts.append(f"{WINDOW_LABELS[w]}: none in this scenario")
    return " Windows (window_summary.csv): " + ", ".join(parts) + "." if parts else ""


def _headline(
    verdicts: pd.DataFrame,
    summary: pd.DataFrame | None,
    scenario: str,
    windows: pd.DataFrame | None = None,
) -> list[Block]:
    values = verdicts[verdicts["kind"] != "claim"]
    if values.empty:
        return [not_available("Published values in verdicts.csv")]
    if summary is None:
        return [not_available(f"rms_summary.csv of the published scenario {scenario}")]
    s = summary.set_index("filter")
    rows = []
    for r in values.itertuples():
        window = _window_of(r.id)
        ours = _ours(s, windows, r.method, r.quantity, window)
        try:
            pub = float(r.published)
        except ValueError:
            pub = float("nan")
        rows.append(
            {
                "id": r.id,
                "filter": r.method,
                "window": window,
                "quantity": r.quantity,
                "published": r.published,
                "ours": ours,
                "ours / published": ours / pub if pub else float("nan"),
                "verdicts.csv reproduced": r.reproduced,
                "verdict": r.verdict,
            }
        )
    table = pd.DataFrame(rows).drop(columns=["id"])  # filter, window, quantity name the row
    parts = []
    for (filt, window), g in table.groupby(["filter", "window"], sort=False):
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
            f"{filt} {names} RMS over the {WINDOW_LABELS[window]} {ours} deg (paper: {pub} deg; ours is "
            f"{ratio} times the paper's)"
        )
    text = (
        f"Headline comparison, published scenario {scenario}: "
        + "; ".join(parts)
        + "."
        + _window_text(windows)
    )
    n_runs = s["n_runs"].dropna().unique() if "n_runs" in s.columns else []
    if len(n_runs):
        text += f" Monte Carlo runs per filter: {', '.join(str(int(n)) for n in n_runs)}."
    # the verdicts must have been computed from these results
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
            caption="Published RMS errors (Sec. 6, Figs. 7 and 12) against ours, per window",
        ),
    ]
    if stale:
        blocks.append(
            Paragraph(
                "verdicts.csv and the scenario's summaries disagree for "
                + ", ".join(stale)
                + " (verdicts.csv may be older than the simulation results)."
            )
        )
    return blocks


def after_bank_blocks(windows: pd.DataFrame | None) -> list[Block]:
    """The statistics of the window after the first bank of one scenario (window_summary.csv)."""
    if windows is None:
        return []
    after = windows[windows["window"] == "after_bank"]
    if after.empty:
        return []
    start, end = float(after["t_start_s"].iloc[0]), float(after["t_end_s"].iloc[0])
    if pd.isna(start):
        return [Paragraph("After-bank window: none (no bank of the set roll ends before the end).")]
    cols = list(RMS_SUMMARY_COLUMNS)
    s = after[cols].set_index("filter").reindex(filter_order(list(after["filter"])))
    fmts = {c: fmt3 for c in cols if c not in ("filter", "n_runs")}
    fmts["n_runs"] = lambda x: DASH if pd.isna(x) else str(int(x))
    return [
        Paragraph(
            f"After-bank window {start:.5g}-{end:.5g} s (from the end of the first bank that makes "
            "roll observable; window_summary.csv):"
        ),
        frame_table(s.reset_index(), formatters=fmts),
    ]


def summary_blocks(
    audit: pd.DataFrame | None,
    verdicts: pd.DataFrame,
    summaries: Mapping[str, pd.DataFrame],
    published_scenario: str,
    windows: Mapping[str, pd.DataFrame] | None = None,
) -> list[Block]:
    """The blocks of the page's Summary section (``windows``: window_summary.csv per
    scenario)."""
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
    head = _headline(
        verdicts,
        summaries.get(published_scenario),
        published_scenario,
        (windows or {}).get(published_scenario),
    )
    return blocks + [b for b in head if not isinstance(b, Table)]


def headline_blocks(
    verdicts: pd.DataFrame,
    summaries: Mapping[str, pd.DataFrame],
    published_scenario: str,
    windows: Mapping[str, pd.DataFrame] | None = None,
) -> list[Block]:
    """The table of the headline comparison: each published RMS value against ours, per
    window, with its ratio and verdict (empty without published values or results)."""
    head = _headline(
        verdicts,
        summaries.get(published_scenario),
        published_scenario,
        (windows or {}).get(published_scenario),
    )
    return [b for b in head if isinstance(b, Table)]
