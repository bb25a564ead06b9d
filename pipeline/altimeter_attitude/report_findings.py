"""The altimeter_attitude findings beyond the paper, as report sections: the UKF on perfect
data, the Gamma term, the best filter per scenario and angle, and the sensitivity to what the
paper leaves open (sweep.csv). Every number is computed by
:mod:`pipeline.altimeter_attitude.filter_comparison` from the results."""

from __future__ import annotations

import math
from collections.abc import Mapping, Sequence
from typing import Any

import pandas as pd

from pipeline.altimeter_attitude.columns import ALTIMETER_FILTERS
from pipeline.altimeter_attitude.filter_comparison import (
    ANGLES,
    best_filters,
    gamma_effect,
    noise_free_comparison,
    sweep_ranges,
)
from pipeline.report.html import format_value
from pipeline.report.model import (
    Block,
    Bullets,
    Paragraph,
    Section,
    Table,
    frame_table,
    not_available,
)

__all__ = ["DASH", "filter_order", "findings_section", "fmt3", "fmt_ratio", "sweep_table"]

DASH = "—"


def fmt3(x: Any) -> str:
    """3 decimals; NaN/None as an em dash."""
    if x is None:
        return DASH
    try:
        v = float(x)
    except (TypeError, ValueError):
        return str(x)
    return DASH if math.isnan(v) else f"{v:.3f}"


def fmt_ratio(x: Any, digits: int = 2) -> str:
    """A ratio with ``digits`` decimals; NaN/inf as an em dash."""
    v = float(x)
    return f"{v:.{digits}f}" if math.isfinite(v) else DASH


def _abs_pct(x: float) -> str:
    return DASH if not math.isfinite(x) else f"{100 * abs(x):.1f} %"


def _pct(x: float) -> str:
    return DASH if not math.isfinite(x) else f"{100 * x:+.1f} %"


def filter_order(names: Sequence[str]) -> list[str]:
    pos = {f: i for i, f in enumerate(ALTIMETER_FILTERS)}
    return sorted(dict.fromkeys(names), key=lambda f: (pos.get(f, len(pos)), f))


def sweep_table(sweep: pd.DataFrame) -> Table | Paragraph:
    """sweep.csv as parameter, value, then roll/pitch RMS per filter (and n_runs)."""
    params = list(dict.fromkeys(sweep["parameter"]))
    filters = filter_order(list(sweep["filter"]))
    wide = sweep.pivot_table(
        index=["parameter", "value"],
        columns="filter",
        values=["roll_rms_deg", "pitch_rms_deg"],
        aggfunc="first",
    )
    cols = [(f"{a}_rms_deg", f) for f in filters for a in ANGLES]
    wide = wide.reindex(columns=cols)
    wide.columns = [f"{f} {c.split('_')[0]} RMS (deg)" for c, f in cols]
    runs = sweep.groupby(["parameter", "value"])["n_runs"].max()
    wide["n_runs"] = runs
    wide = wide.reset_index()
    wide["_p"] = wide["parameter"].map({p: i for i, p in enumerate(params)})
    wide = wide.sort_values(["_p", "value"], kind="stable").drop(columns="_p")
    wide["value"] = wide["value"].map(format_value)
    fmts = {c: fmt3 for c in wide.columns if c.endswith("RMS (deg)")}
    return frame_table(wide, formatters=fmts, caption="sweep.csv")


def _noise_free(
    summaries: Mapping[str, pd.DataFrame], noise_free: Mapping[str, pd.DataFrame]
) -> list[Block]:
    """Each filter on one noise-free run with an exact start (noise_free.csv), against its
    Monte Carlo RMS: what the model and the update do on perfect data."""
    if not noise_free:
        return [not_available("noise_free.csv")]
    frame = noise_free_comparison(summaries, noise_free)
    kf = frame[frame["filter"].isin(["linear_kf", "ekf"])]
    ukf = frame[frame["filter"] == "ukf"]
    text = ""
    if len(kf) and len(ukf):
        worst = ukf.loc[ukf["noise-free RMS"].idxmax()]
        text = (
            "With noise-free sensors and an exact start (the filters still assume the scenario's "
            f"noise), the linear KF and the EKF stay within {kf['noise-free RMS'].max():.2g} deg of "
            f"the truth in every scenario, but the UKF does not: its {worst['angle']} error in "
            f"scenario {worst['scenario']} is {worst['noise-free RMS']:.3f} deg, "
            f"{worst['share']:.0%} of its Monte Carlo RMS there. Its sigma points spread the "
            "attitude, so the predicted mean of c^T f (and of the altitude) moves even when the "
            "estimate is exact, and the linear measurement update turns that into an attitude "
            "error. This is a mechanism behind the paper's claim that the linear formulation is "
            "better (it holds here for pitch, not for roll)."
        )
    table = frame.pivot_table(
        index=["scenario", "filter"],
        columns="angle",
        values=["noise-free RMS", "Monte Carlo RMS"],
        sort=False,
    )
    table.columns = [f"{a} {v}" for v, a in table.columns]
    table = table.reset_index()
    return [
        Paragraph(text),
        frame_table(
            table,
            formatters={c: fmt3 for c in table.columns if "RMS" in c},
            caption="RMS error (deg) after the transient: one noise-free run vs the Monte Carlo",
        ),
    ]


def _gamma(summaries: Mapping[str, pd.DataFrame]) -> list[Block]:
    g = gamma_effect(summaries)
    if g.empty:
        return [not_available("linear_kf and linear_kf_no_gamma in rms_summary.csv")]
    change = g[["rms change", "sigma change"]].abs()
    i, col = divmod(int(change.to_numpy().argmax()), 2)
    row = g.iloc[i]
    q = ("rms", "sigma")[col]
    text = (
        "Adding the Gamma (Q kron P) Gamma^T term changes the linear filter's RMS error by "
        f"{_abs_pct(g['rms change'].abs().min())} to {_abs_pct(g['rms change'].abs().max())} "
        f"(absolute relative change over {g['scenario'].nunique()} scenarios and both angles) "
        f"and its own sigma by {_abs_pct(g['sigma change'].abs().min())} to "
        f"{_abs_pct(g['sigma change'].abs().max())}. The largest change is the {row['angle']} "
        f"{'RMS error' if q == 'rms' else 'sigma'} in scenario {row['scenario']}: "
        f"{fmt3(row[f'{q} without'])} deg without, {fmt3(row[f'{q} with'])} deg with the "
        f"term ({_pct(row[f'{q} change'])})."
    )
    fmts = {
        **{c: fmt3 for c in g.columns if c.endswith(("with", "without"))},
        "rms change": _pct,
        "sigma change": _pct,
    }
    return [
        Paragraph(text),
        frame_table(
            g, formatters=fmts, caption="linear_kf (with) against linear_kf_no_gamma (without); deg"
        ),
    ]


def _best(summaries: Mapping[str, pd.DataFrame]) -> list[Block]:
    b = best_filters(summaries)
    if b.empty:
        return [not_available("rms_summary.csv")]
    sentences = [
        f"{r.scenario} {r.angle}: {r[2]} ({fmt3(r[3])} deg), then {r[4]} "
        f"({fmt3(r[5])} deg); linear_kf ranks {r[6]}, linear_kf / ukf = {fmt_ratio(r[7])}"
        for r in b.itertuples(index=False)
    ]
    lkf_wins = b[b["linear_kf / ukf"] < 1]
    text = (
        "Lowest RMS error among all filters (argmin over rms_summary.csv): "
        + "; ".join(sentences)
        + ". "
        + f"The linear filter beats the UKF in {len(lkf_wins)} of {len(b)} scenario-angle pairs"
        + (
            " (" + ", ".join(f"{r.scenario} {r.angle}" for r in lkf_wins.itertuples()) + ")."
            if len(lkf_wins)
            else "."
        )
    )
    fmts = {"best RMS (deg)": fmt3, "runner-up RMS (deg)": fmt3, "linear_kf / ukf": fmt_ratio}
    return [Paragraph(text), frame_table(b, formatters=fmts)]


def _sweep(sweep: pd.DataFrame | None) -> list[Block]:
    if sweep is None or sweep.empty:
        return [not_available("sweep.csv")]
    ranges = sweep_ranges(sweep)
    items = []
    for param, rg in ranges.groupby("parameter", sort=False):
        parts = [
            f"{r.filter} {r.angle} RMS {r.trend} it, {fmt3(r[4])}–{fmt3(r[6])} deg "
            f"(lowest at {r[5]}, highest at {r[7]}; max/min {fmt_ratio(r[8])})"
            for r in rg.itertuples(index=False)
        ]
        items.append(f"{param} ({rg['values'].iloc[0]}): " + "; ".join(parts) + ".")
    blocks: list[Block] = [
        Paragraph("Dependence on the parameters the paper does not give (sweep.csv):"),
        Bullets(items),
    ]
    wide = sweep.pivot_table(
        index=["parameter", "value"], columns="filter", values=["roll_rms_deg", "pitch_rms_deg"]
    )
    if {"linear_kf", "ukf"} <= set(sweep["filter"]):
        wins = {
            a: int((wide[(f"{a}_rms_deg", "linear_kf")] < wide[(f"{a}_rms_deg", "ukf")]).sum())
            for a in ANGLES
        }
        blocks.append(
            Paragraph(
                "linear_kf has a lower RMS error than ukf at "
                + " and ".join(f"{n} ({a})" for a, n in wins.items())
                + f" of the {len(wide)} (parameter, value) points of sweep.csv (the base point "
                "counts once per parameter)."
            )
        )
    blocks.append(
        frame_table(
            ranges,
            formatters={"min RMS (deg)": fmt3, "max RMS (deg)": fmt3, "max / min": fmt_ratio},
            caption="Range of the RMS error over each swept parameter",
        )
    )
    return blocks


def findings_section(
    summaries: Mapping[str, pd.DataFrame],
    sweep: pd.DataFrame | None,
    noise_free: Mapping[str, pd.DataFrame],
) -> Section:
    """The "Findings beyond the paper" section of the page."""
    return Section(
        "findings",
        "Findings beyond the paper",
        [],
        [
            Section(
                "findings-noise-free",
                "Perfect data: the UKF's sigma points bias its estimate",
                _noise_free(summaries, noise_free),
            ),
            Section("findings-gamma", "The Gamma term", _gamma(summaries)),
            Section("findings-best", "Best filter per scenario and angle", _best(summaries)),
            Section("findings-sweep", "Sensitivity to what the paper leaves open", _sweep(sweep)),
        ],
    )
