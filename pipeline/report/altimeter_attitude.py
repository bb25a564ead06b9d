"""The altimeter_attitude HTML page: summary, audit, verdicts, per-scenario RMS, figures,
findings beyond the paper, assumptions and provenance (one self-contained page).

Inputs (``results/altimeter_attitude/`` unless given explicitly):

* ``verdicts.csv`` (required), ``equation_audit.csv`` (shown as "not available" if absent);
* ``<scenario>/rms_summary.csv`` and ``<scenario>/provenance.json`` of every scenario;
* ``sweep.csv`` (the one-at-a-time sensitivity sweep);
* ``figures/*.png`` (names from :data:`pipeline.altimeter_attitude.workflow.FIGURES` and
  ``SWEEP_FIGURE``; a missing figure is shown as "not available");
* the scenario files ``config/scenarios/altimeter_attitude/*.yaml`` (description, decisions).

Every number on the page is read or computed from these files; the prose around them is
a template. ``python -m pipeline.report.altimeter_attitude --out reports/altimeter_attitude.html``
"""

from __future__ import annotations

import argparse
import hashlib
import json
import math
import re
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from pipeline.altimeter_attitude.columns import (
    ALTIMETER_FILTERS,
    RMS_SUMMARY_COLUMNS,
    SWEEP_COLUMNS,
)
from pipeline.altimeter_attitude.paper import CITATION as PAPER_CITATION
from pipeline.altimeter_attitude.paper import TITLE as PAPER_TITLE
from pipeline.altimeter_attitude.scenario import load_scenario
from pipeline.altimeter_attitude.workflow import FIGURES, SWEEP_FIGURE
from pipeline.columns import AUDIT_COLUMNS, AUDIT_STATUSES, VERDICT_COLUMNS
from pipeline.report import html as H

__all__ = [
    "FIGURE_CAPTIONS",
    "FILTER_LABELS",
    "best_filters",
    "build_page",
    "gamma_effect",
    "group_counts",
    "main",
    "render_page",
    "sweep_ranges",
]

SLUG = "altimeter_attitude"
DASH = "—"
ANGLES = ("roll", "pitch")

FILTER_LABELS: dict[str, str] = {
    "linear_kf": "linear Kalman filter on x = [C31, C32, C33, V_d, h] (eqs. 26, 31), with the "
    "multiplicative-noise term Gamma (Q kron P) Gamma^T",
    "linear_kf_no_gamma": "the same linear filter without the Gamma (Q kron P) Gamma^T term",
    "ukf": "unscented Kalman filter on [roll, pitch, V_d, h] (Sec. 6)",
    "ekf": "extended Kalman filter on the same Euler-angle model (the paper says it diverges)",
    "complementary": "PI complementary filter of Fig. 1 (cruise levelling inside the loop)",
    "gyro_only": "gyro propagation of c (eq. 14), no correction",
    "accel_leveling": "accelerometer levelling (eqs. 17-b, 11) at every step",
}

# Figure file -> caption. The paper's figure number is part of the file name (figN_...).
_FIGURE_TEXT: dict[str, str] = {
    "fig2_third_row.png": "nominal trajectory: the third-row DCM elements C31, C32, C33 against "
    "time.",
    "fig3_specific_force.png": "specific force measured by the accelerometers (body axes). Its "
    "large vertical-plane part is why accelerometer levelling fails.",
    "fig4_vertical_channel.png": "vertical channel: down velocity V_d and altitude h against time.",
    "fig5_angular_rates.png": "angular rates measured by the gyros (body axes).",
    "fig6_roll_pitch.png": "true roll and pitch against time.",
    "fig7_lkf_rms_error.png": "linear Kalman filter: Monte Carlo RMS of the roll and pitch "
    "estimation errors against time (the paper reads its roll/pitch RMS off this figure).",
    "fig8_lkf_c_rms.png": "linear Kalman filter: Monte Carlo RMS error of the DCM parameters "
    "c1, c2, c3.",
    "fig9_lkf_sigma.png": "linear Kalman filter: RMS over runs of the filter's own roll and "
    "pitch standard deviation (compare with Fig. 7).",
    "fig10_norm_error.png": "linear Kalman filter: RMS of the normalisation error 1 - c^T c.",
    "fig11_ukf_sigma.png": "UKF: RMS over runs of the filter's own roll and pitch standard "
    "deviation (compare with Fig. 12).",
    "fig12_ukf_rms_error.png": "UKF: Monte Carlo RMS of the roll and pitch estimation errors "
    "against time (the paper reads its UKF roll/pitch RMS off this figure).",
}


def _figure_caption(name: str) -> str:
    m = re.match(r"fig(\d+)_", name)
    if m and name in _FIGURE_TEXT:
        return f"Fig. {m.group(1)} (paper Fig. {m.group(1)}): {_FIGURE_TEXT[name]}"
    if name == "fig_compare_filters.png":
        return (
            "Not in the paper: roll and pitch errors of every filter of this reproduction ("
            + ", ".join(ALTIMETER_FILTERS)
            + ") in the published scenario."
        )
    if name == SWEEP_FIGURE:
        return (
            "Not in the paper: one-at-a-time sweep around the published scenario; RMS roll and "
            "pitch error against each swept parameter (values in the table below)."
        )
    return name


FIGURE_CAPTIONS: dict[str, str] = {n: _figure_caption(n) for n in [*FIGURES, SWEEP_FIGURE]}


# --------------------------------------------------------------------------- readers


def _read(path: Path, columns: Sequence[str], *, as_text: bool = False) -> pd.DataFrame | None:
    """The CSV at ``path`` with the contract ``columns`` (in that order); None if absent."""
    if not path.is_file():
        return None
    df = pd.read_csv(path, dtype=str, keep_default_na=False) if as_text else pd.read_csv(path)
    missing = [c for c in columns if c not in df.columns]
    if missing:
        raise ValueError(f"{path}: missing columns {missing} (has {list(df.columns)})")
    return df[list(columns)]


def _sha256(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest()


def _fmt3(x: Any) -> str:
    """3 decimals; NaN/None as an em dash."""
    if x is None:
        return DASH
    try:
        v = float(x)
    except (TypeError, ValueError):
        return str(x)
    return DASH if math.isnan(v) else f"{v:.3f}"


def _fmt_ratio(x: Any, digits: int = 2) -> str:
    """A ratio with ``digits`` decimals; NaN/inf as an em dash."""
    v = float(x)
    return f"{v:.{digits}f}" if math.isfinite(v) else DASH


def _abs_pct(x: float) -> str:
    return DASH if not math.isfinite(x) else f"{100 * abs(x):.1f} %"


def _pct(x: float) -> str:
    return DASH if not math.isfinite(x) else f"{100 * x:+.1f} %"


def _value_text(value: Any) -> str:
    """A config value as text: strings as they are, everything else compact JSON."""
    if isinstance(value, str):
        return value
    return json.dumps(value, ensure_ascii=False, default=str)


def _filter_order(names: Sequence[str]) -> list[str]:
    pos = {f: i for i, f in enumerate(ALTIMETER_FILTERS)}
    return sorted(dict.fromkeys(names), key=lambda f: (pos.get(f, len(pos)), f))


def _scenario_order(names: Sequence[str], published: str) -> list[str]:
    return sorted(dict.fromkeys(names), key=lambda n: (n != published, n))


# --------------------------------------------------------------------------- computed facts


def group_counts(frame: pd.DataFrame, column: str, words: Sequence[str]) -> pd.Series:
    """Rows per value of ``column``: every word of ``words`` (zeros included, in that order),
    then any other value found (a producer bug, shown so it is not hidden)."""
    counts = frame[column].astype(str).value_counts()
    extra = sorted(set(counts.index) - set(words))
    return counts.reindex(list(words) + extra, fill_value=0).astype(int)


VALUE_WORDS = ("reproduced", "consistent", "not_reproduced")
CLAIM_WORDS = ("upheld", "not_upheld", "not_checkable")


def _value_words(values: pd.DataFrame) -> list[str]:
    # 'reproduced' applies to exact values only; show it when the paper has any
    has_exact = (values["kind"] == "exact").any() or (values["verdict"] == "reproduced").any()
    return [w for w in VALUE_WORDS if has_exact or w != "reproduced"]


def gamma_effect(summaries: Mapping[str, pd.DataFrame]) -> pd.DataFrame:
    """Per scenario and angle: RMS and sigma of linear_kf and linear_kf_no_gamma and the
    relative change (with - without) / without."""
    rows = []
    for name, s in summaries.items():
        s = s.set_index("filter")
        if not {"linear_kf", "linear_kf_no_gamma"} <= set(s.index):
            continue
        for angle in ANGLES:
            row: dict[str, Any] = {"scenario": name, "angle": angle}
            for q in ("rms", "sigma"):
                col = f"{angle}_{q}_deg"
                a, b = float(s.at["linear_kf", col]), float(s.at["linear_kf_no_gamma", col])
                row[f"{q} with"] = a
                row[f"{q} without"] = b
                row[f"{q} change"] = (a - b) / b if b else float("nan")
            rows.append(row)
    return pd.DataFrame(rows)


def best_filters(summaries: Mapping[str, pd.DataFrame]) -> pd.DataFrame:
    """Per scenario and angle: the filter with the smallest RMS error (argmin), the runner-up,
    and the RMS of the linear KF and the UKF with their ratio."""
    rows = []
    for name, s in summaries.items():
        for angle in ANGLES:
            col = f"{angle}_rms_deg"
            r = s.set_index("filter")[col].astype(float).dropna().sort_values(kind="stable")
            if r.empty:
                continue
            lkf = float(r.get("linear_kf", float("nan")))
            ukf = float(r.get("ukf", float("nan")))
            rows.append(
                {
                    "scenario": name,
                    "angle": angle,
                    "best filter": r.index[0],
                    "best RMS (deg)": float(r.iloc[0]),
                    "runner-up": r.index[1] if len(r) > 1 else "",
                    "runner-up RMS (deg)": float(r.iloc[1]) if len(r) > 1 else float("nan"),
                    "linear_kf rank": int(list(r.index).index("linear_kf")) + 1
                    if "linear_kf" in r.index
                    else 0,
                    "linear_kf / ukf": lkf / ukf if ukf else float("nan"),
                }
            )
    return pd.DataFrame(rows)


def _trend(values: Sequence[float], rms: Sequence[float]) -> str:
    pairs = sorted(zip(values, rms, strict=True))
    d = [b[1] - a[1] for a, b in zip(pairs, pairs[1:], strict=False)]
    if d and all(x > 0 for x in d):
        return "grows with"
    if d and all(x < 0 for x in d):
        return "falls with"
    return "is not monotonic in"


def sweep_ranges(sweep: pd.DataFrame) -> pd.DataFrame:
    """Per swept parameter, filter and angle: min and max RMS, where they occur, max/min, trend."""
    rows = []
    for (param, filt), g in sweep.groupby(["parameter", "filter"], sort=False):
        for angle in ANGLES:
            col = f"{angle}_rms_deg"
            r = g[["value", col]].astype(float).dropna()
            if r.empty:
                continue
            lo, hi = r.loc[r[col].idxmin()], r.loc[r[col].idxmax()]
            rows.append(
                {
                    "parameter": param,
                    "filter": filt,
                    "angle": angle,
                    "values": f"{H.format_value(r['value'].min())}–"
                    f"{H.format_value(r['value'].max())}",
                    "min RMS (deg)": float(lo[col]),
                    "min at": H.format_value(float(lo["value"])),
                    "max RMS (deg)": float(hi[col]),
                    "max at": H.format_value(float(hi["value"])),
                    "max / min": float(hi[col]) / float(lo[col]) if lo[col] else float("nan"),
                    "trend": _trend(list(r["value"]), list(r[col])),
                }
            )
    return pd.DataFrame(rows)


def _sweep_pivot(sweep: pd.DataFrame) -> pd.DataFrame:
    """parameter, value, then roll/pitch RMS per filter (and n_runs)."""
    params = list(dict.fromkeys(sweep["parameter"]))
    filters = _filter_order(list(sweep["filter"]))
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
    wide["value"] = wide["value"].map(H.format_value)
    return wide


# --------------------------------------------------------------------------- sections


def _count_span(group: str, attr: str, word: str, n: int) -> str:
    """``<span data-group=.. data-{attr}=word>n</span> word``: machine-readable counts."""
    return (
        f'<span class="count {H.css_class(word)}" data-group="{H.escape(group)}" '
        f'data-{attr}="{H.escape(word)}">{int(n)}</span> {H.escape(word.replace("_", " "))}'
    )


def _headline(verdicts: pd.DataFrame, summary: pd.DataFrame | None, scenario: str) -> str:
    values = verdicts[verdicts["kind"] != "claim"]
    if values.empty:
        return H.not_available("Published values in verdicts.csv")
    if summary is None:
        return H.not_available(f"rms_summary.csv of the published scenario {scenario}")
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
        ours = "/".join(_fmt3(by_q.at[q, "ours"]) for q in qs)
        pub = "/".join(str(by_q.at[q, "published"]) for q in qs)
        names = "/".join(q.split("_")[0] for q in qs)
        ratios = [float(by_q.at[q, "ours / published"]) for q in qs]
        ratio = "–".join(dict.fromkeys(_fmt_ratio(x, 1) for x in (min(ratios), max(ratios))))
        parts.append(
            f"{filt} {names} RMS {ours} deg (paper: {pub} deg; ours is {ratio} times the paper's)"
        )
    text = (
        f"Headline comparison, published scenario <code>{H.escape(scenario)}</code> "
        f"(rms_summary.csv): " + H.escape("; ".join(parts)) + "."
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
    body = H.paragraph(text, raw=True) + H.table(
        table,
        class_column="verdict",
        formatters={"ours": _fmt3, "ours / published": _fmt_ratio},
        caption="Published RMS errors (Sec. 6, Figs. 7 and 12) against ours",
    )
    if stale:
        body += H.paragraph(
            "verdicts.csv and rms_summary.csv disagree for "
            + ", ".join(stale)
            + " (verdicts.csv may be older than the simulation results).",
            cls="na",
        )
    return body


def _finite(text: Any) -> bool:
    try:
        return math.isfinite(float(text))
    except (TypeError, ValueError):
        return False


def _summary_section(
    audit: pd.DataFrame | None,
    verdicts: pd.DataFrame,
    summaries: Mapping[str, pd.DataFrame],
    published_scenario: str,
) -> str:
    body = H.paragraph(
        "The paper estimates roll and pitch of a maneuvering vehicle from a low-cost strapdown "
        "IMU aided by a barometric altimeter. The vertical channel depends on the attitude only "
        "through the third row c of the body-to-NED direction cosine matrix, so with "
        "x = [c, V_d, h] both the attitude kinematics and the vertical channel are linear in the "
        "state and a linear Kalman filter applies; the multiplicative sensor noise adds a "
        "Gamma (Q kron P) Gamma^T covariance term (Appendix A). The paper compares this filter "
        "with a UKF on Euler angles in a Monte Carlo simulation and finds the linear filter "
        "better. This page sets its published numbers and claims beside our derivation "
        "(equation audit) and simulation, and adds baselines (EKF, complementary filter, "
        "gyro-only, accelerometer levelling, the linear filter without the Gamma term), two "
        "more scenarios and a sensitivity sweep."
    )
    if audit is None:
        audit_text = "Equation audit: equation_audit.csv not available"
    else:
        ac = group_counts(audit, "status", AUDIT_STATUSES)
        audit_text = f"Equation audit: {len(audit)} printed equations checked, " + ", ".join(
            _count_span("audit", "status", w, n) for w, n in ac.items()
        )
    values = verdicts[verdicts["kind"] != "claim"]
    claims = verdicts[verdicts["kind"] == "claim"]
    vc = group_counts(values, "verdict", _value_words(values))
    cc = group_counts(claims, "verdict", CLAIM_WORDS)
    items = [
        audit_text,
        f"Published values: {len(values)}, "
        + ", ".join(_count_span("values", "verdict", w, n) for w, n in vc.items()),
        f"Claims: {len(claims)}, "
        + ", ".join(_count_span("claims", "verdict", w, n) for w, n in cc.items()),
    ]
    body += '<ul class="counts">\n' + "".join(f"<li>{i}.</li>\n" for i in items) + "</ul>\n"
    body += _headline(verdicts, summaries.get(published_scenario), published_scenario)
    failed = claims[claims["verdict"] == "not_upheld"]
    if len(failed):
        lis = "".join(
            f"<li><strong>{H.escape(r.id)}</strong> ({H.escape(r.method)}): "
            f"{H.escape(r.published)}. Computed: {H.escape(r.reproduced)}.</li>\n"
            for r in failed.itertuples()
        )
        body += H.paragraph("Claims not upheld (evidence from verdicts.csv):")
        body += f'<ul class="not-upheld">\n{lis}</ul>\n'
    else:
        body += H.paragraph("Claims not upheld: none.")
    return body


def _audit_section(audit: pd.DataFrame | None, path: Path) -> str:
    if audit is None:
        return H.not_available(f"Equation audit ({path.as_posix()})")
    differs = audit[audit["status"] == "differs"]
    if len(differs):
        lis = "".join(
            f"<li><strong>Eq. {H.escape(r.equation)}</strong>: {H.escape(r.note) or 'no note'} "
            f"(residual <code>{H.escape(r.residual)}</code>)</li>\n"
            for r in differs.itertuples()
        )
        body = (
            H.paragraph(
                f"{len(differs)} of {len(audit)} printed equations differ from the derivation "
                "(the pipeline uses the derived form):"
            )
            + f'<ul class="differs">\n{lis}</ul>\n'
        )
    else:
        body = H.paragraph(
            f"None of the {len(audit)} printed equations differs from the derivation."
        )
    ordered = pd.concat([differs, audit[audit["status"] != "differs"]])
    body += H.table(
        ordered,
        class_column="status",
        caption="equation_audit.csv (differs rows first, then in file order)",
    )
    return body


def _verdicts_section(verdicts: pd.DataFrame) -> str:
    body = H.paragraph(
        "Values: the paper's approximate RMS errors against rms_summary.csv of the published "
        "scenario (tolerance and Monte Carlo standard error in the note). Claims: a predicate "
        "over the results; the reproduced column is its computed evidence."
    )
    values = verdicts[verdicts["kind"] != "claim"]
    claims = verdicts[verdicts["kind"] == "claim"]
    body += H.section(
        "Published values",
        H.table(values, class_column="verdict"),
        anchor="verdicts-values",
        level=3,
    )
    body += H.section(
        "Claims", H.table(claims, class_column="verdict"), anchor="verdicts-claims", level=3
    )
    return body


def _summary_table(s: pd.DataFrame) -> str:
    s = s.set_index("filter").reindex(_filter_order(list(s["filter"]))).reset_index()
    fmts = {c: _fmt3 for c in RMS_SUMMARY_COLUMNS if c not in ("filter", "n_runs")}
    fmts["n_runs"] = lambda x: DASH if pd.isna(x) else str(int(x))
    return H.table(s, formatters=fmts)


def _results_section(
    summaries: Mapping[str, pd.DataFrame], descriptions: Mapping[str, str], published: str
) -> str:
    body = H.paragraph(
        "rms_summary.csv per scenario: RMS over runs and over time after the transient; sigma: "
        "RMS of the filter's own standard deviation; NEES: mean of error^2 / sigma^2 (1 for a "
        f"consistent filter). {DASH}: the filter has no covariance. Filters:"
    )
    body += H.definition_list(FILTER_LABELS, value_format=str)
    if not summaries:
        return body + H.not_available("rms_summary.csv")
    for name, s in summaries.items():
        missing = [f for f in ALTIMETER_FILTERS if f not in set(s["filter"])]
        inner = H.paragraph(descriptions.get(name, "")) if descriptions.get(name) else ""
        inner += _summary_table(s)
        if missing:
            inner += H.paragraph(f"Filters without results: {', '.join(missing)}.", cls="na")
        title = f"Scenario {name}" + (" (published scenario)" if name == published else "")
        body += H.section(title, inner, anchor=f"results-{H.slugify(name)}", level=3)
    return body


def _figures_section(figures_dir: Path, sweep: pd.DataFrame | None) -> str:
    body = ""
    for name in FIGURES:
        body += H.figure(
            figures_dir / name,
            alt=name,
            caption=FIGURE_CAPTIONS[name],
            anchor=H.slugify(Path(name).stem),
            missing_text=f"{name}: not available",
        )
    inner = H.figure(
        figures_dir / SWEEP_FIGURE,
        alt=SWEEP_FIGURE,
        caption=FIGURE_CAPTIONS[SWEEP_FIGURE],
        anchor=H.slugify(Path(SWEEP_FIGURE).stem),
        missing_text=f"{SWEEP_FIGURE}: not available",
    )
    if sweep is None or sweep.empty:
        inner += H.not_available("sweep.csv")
    else:
        inner += H.paragraph(
            "Parameters varied one at a time around the published scenario: "
            + ", ".join(
                f"{p} ({', '.join(H.format_value(v) for v in sorted(g['value'].unique()))})"
                for p, g in sweep.groupby("parameter", sort=False)
            )
            + "."
        )
        pivot = _sweep_pivot(sweep)
        fmts = {c: _fmt3 for c in pivot.columns if c.endswith("RMS (deg)")}
        inner += H.table(pivot, formatters=fmts, caption="sweep.csv", table_id="sweep-table")
    body += H.section("Sensitivity sweep", inner, anchor="sweep", level=3)
    return body


def _noise_free_part(
    summaries: Mapping[str, pd.DataFrame], noise_free: Mapping[str, pd.DataFrame]
) -> str:
    """Each filter on one noise-free run with an exact start (noise_free.csv), against its
    Monte Carlo RMS: what the model and the update do on perfect data."""
    if not noise_free:
        return H.not_available("noise_free.csv")
    rows = []
    for name, nf in noise_free.items():
        mc = summaries.get(name)
        for r in nf.itertuples():
            m = None if mc is None else mc[mc["filter"] == r.filter]
            for angle in ("roll", "pitch"):
                clean = float(getattr(r, f"{angle}_rms_deg"))
                noisy = float(m[f"{angle}_rms_deg"].iloc[0]) if m is not None and len(m) else np.nan
                rows.append(
                    {
                        "scenario": name,
                        "filter": r.filter,
                        "angle": angle,
                        "noise-free RMS": clean,
                        "Monte Carlo RMS": noisy,
                        "share": clean / noisy if noisy else np.nan,
                    }
                )
    frame = pd.DataFrame(rows)
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
    return H.paragraph(text) + H.table(
        table,
        formatters={c: _fmt3 for c in table.columns if "RMS" in c},
        caption="RMS error (deg) after the transient: one noise-free run vs the Monte Carlo",
    )


def _findings_section(
    summaries: Mapping[str, pd.DataFrame],
    sweep: pd.DataFrame | None,
    noise_free: Mapping[str, pd.DataFrame] | None = None,
) -> str:
    body = H.section(
        "Perfect data: the UKF's sigma points bias its estimate",
        _noise_free_part(summaries, noise_free or {}),
        anchor="findings-noise-free",
        level=3,
    )
    # 1. the Gamma (Q kron P) Gamma^T term
    g = gamma_effect(summaries)
    inner = ""
    if g.empty:
        inner += H.not_available("linear_kf and linear_kf_no_gamma in rms_summary.csv")
    else:
        change = g[["rms change", "sigma change"]].abs()
        i, col = divmod(int(change.to_numpy().argmax()), 2)
        row = g.iloc[i]
        q = ("rms", "sigma")[col]
        inner += H.paragraph(
            "Adding the Gamma (Q kron P) Gamma^T term changes the linear filter's RMS error by "
            f"{_abs_pct(g['rms change'].abs().min())} to {_abs_pct(g['rms change'].abs().max())} "
            f"(absolute relative change over {g['scenario'].nunique()} scenarios and both angles) "
            f"and its own sigma by {_abs_pct(g['sigma change'].abs().min())} to "
            f"{_abs_pct(g['sigma change'].abs().max())}. The largest change is the {row['angle']} "
            f"{'RMS error' if q == 'rms' else 'sigma'} in scenario {row['scenario']}: "
            f"{_fmt3(row[f'{q} without'])} deg without, {_fmt3(row[f'{q} with'])} deg with the "
            f"term ({_pct(row[f'{q} change'])})."
        )
        inner += H.table(
            g,
            formatters={
                **{c: _fmt3 for c in g.columns if c.endswith(("with", "without"))},
                "rms change": _pct,
                "sigma change": _pct,
            },
            caption="linear_kf (with) against linear_kf_no_gamma (without); deg",
        )
    body += H.section("The Gamma term", inner, anchor="findings-gamma", level=3)

    # 2. best filter per scenario and angle
    b = best_filters(summaries)
    inner = ""
    if b.empty:
        inner += H.not_available("rms_summary.csv")
    else:
        sentences = []
        for r in b.itertuples(index=False):
            sentences.append(
                f"{r.scenario} {r.angle}: {r[2]} ({_fmt3(r[3])} deg), then {r[4]} "
                f"({_fmt3(r[5])} deg); linear_kf ranks {r[6]}, linear_kf / ukf = "
                f"{_fmt_ratio(r[7])}"
            )
        lkf_wins = b[b["linear_kf / ukf"] < 1]
        inner += H.paragraph(
            "Lowest RMS error among all filters (argmin over rms_summary.csv): "
            + "; ".join(sentences)
            + ". "
            + f"The linear filter beats the UKF in {len(lkf_wins)} of {len(b)} "
            "scenario-angle pairs"
            + (
                " (" + ", ".join(f"{r.scenario} {r.angle}" for r in lkf_wins.itertuples()) + ")."
                if len(lkf_wins)
                else "."
            )
        )
        inner += H.table(
            b,
            formatters={
                "best RMS (deg)": _fmt3,
                "runner-up RMS (deg)": _fmt3,
                "linear_kf / ukf": _fmt_ratio,
            },
        )
    body += H.section("Best filter per scenario and angle", inner, anchor="findings-best", level=3)

    # 3. sweep
    inner = ""
    if sweep is None or sweep.empty:
        inner += H.not_available("sweep.csv")
    else:
        ranges = sweep_ranges(sweep)
        lis = ""
        for param, rg in ranges.groupby("parameter", sort=False):
            parts = [
                f"{r.filter} {r.angle} RMS {r.trend} it, {_fmt3(r[4])}–{_fmt3(r[6])} deg "
                f"(lowest at {r[5]}, highest at {r[7]}; max/min {_fmt_ratio(r[8])})"
                for r in rg.itertuples(index=False)
            ]
            lis += (
                f"<li><strong>{H.escape(param)}</strong> ({H.escape(rg['values'].iloc[0])}): "
                + H.escape("; ".join(parts))
                + ".</li>\n"
            )
        inner += H.paragraph("Dependence on the parameters the paper does not give (sweep.csv):")
        inner += f'<ul class="sweep-findings">\n{lis}</ul>\n'
        wide = sweep.pivot_table(
            index=["parameter", "value"], columns="filter", values=["roll_rms_deg", "pitch_rms_deg"]
        )
        if {"linear_kf", "ukf"} <= set(sweep["filter"]):
            wins = {
                a: int((wide[(f"{a}_rms_deg", "linear_kf")] < wide[(f"{a}_rms_deg", "ukf")]).sum())
                for a in ANGLES
            }
            inner += H.paragraph(
                "linear_kf has a lower RMS error than ukf at "
                + " and ".join(f"{n} ({a})" for a, n in wins.items())
                + f" of the {len(wide)} (parameter, value) points of sweep.csv (the base point "
                "counts once per parameter)."
            )
        inner += H.table(
            ranges,
            formatters={
                "min RMS (deg)": _fmt3,
                "max RMS (deg)": _fmt3,
                "max / min": _fmt_ratio,
            },
            caption="Range of the RMS error over each swept parameter",
        )
    body += H.section(
        "Sensitivity to what the paper leaves open", inner, anchor="findings-sweep", level=3
    )
    return body


def _assumptions_section(scenario_files: Sequence[Path]) -> str:
    if not scenario_files:
        return H.not_available("Scenario files")
    body = H.paragraph(
        "Where the paper is silent, each scenario file decides; the value shown is read from the "
        "file at the named field."
    )
    for path in scenario_files:
        sc = load_scenario(path)
        rows = [
            {"field": d["field"], "value": _value_text(d["value"]), "decision": str(d["text"])}
            for d in sc.decisions()
        ]
        inner = H.paragraph(str(sc.raw.get("description", "")).strip() or "(no description)")
        inner += H.table(
            pd.DataFrame(rows, columns=["field", "value", "decision"]),
            empty_text="no decisions listed",
        )
        body += H.section(
            f"Scenario {path.stem} ({path.as_posix()})",
            inner,
            anchor=f"assumptions-{H.slugify(path.stem)}",
            level=3,
        )
    return body


def _flatten(data: Mapping[str, Any], prefix: str = "") -> dict[str, Any]:
    out: dict[str, Any] = {}
    for k, v in data.items():
        key = f"{prefix}{k}"
        if isinstance(v, Mapping):
            out.update(_flatten(v, f"{key}."))
        elif isinstance(v, list):
            out[key] = ", ".join(map(str, v))
        else:
            out[key] = v
    return out


def _provenance_section(
    scenario_dirs: Mapping[str, Path], scenario_files: Mapping[str, Path], inputs: Sequence[Path]
) -> str:
    body = ""
    for name, d in scenario_dirs.items():
        p = d / "provenance.json"
        if not p.is_file():
            inner = H.not_available(f"{p.as_posix()}")
        else:
            data = json.loads(p.read_text(encoding="utf-8"))
            flat = _flatten({k: v for k, v in data.items() if k != "packages"})
            if name in scenario_files and "config_sha256" in data:
                now = load_scenario(scenario_files[name]).config_sha256
                flat["config_sha256 equals the scenario file's now"] = (
                    "yes" if now == data["config_sha256"] else f"no (file now: {now})"
                )
            inner = H.definition_list(flat, value_format=_value_text)
            pkgs = data.get("packages")
            if isinstance(pkgs, Mapping) and pkgs:
                inner += H.table(
                    pd.DataFrame(sorted(pkgs.items()), columns=["package", "version"]),
                    caption="packages",
                )
        body += H.section(
            f"Scenario {name}", inner, anchor=f"provenance-{H.slugify(name)}", level=3
        )
    rows = [
        {"file": p.as_posix(), "sha256": _sha256(p)}
        for p in inputs
        if p is not None and p.is_file()
    ]
    body += H.section(
        "Input files of this page",
        H.table(pd.DataFrame(rows, columns=["file", "sha256"])),
        anchor="provenance-inputs",
        level=3,
    )
    return body


# --------------------------------------------------------------------------- page


def render_page(
    results_dir: str | Path = "results/altimeter_attitude",
    scenarios_dir: str | Path = "config/scenarios/altimeter_attitude",
    *,
    published_scenario: str = "paper",
    audit: str | Path | None = None,
    verdicts: str | Path | None = None,
    summaries: Sequence[str | Path] | None = None,
    sweep: str | Path | None = None,
    figures_dir: str | Path | None = None,
) -> str:
    """The page as an HTML string. File arguments default to their place under
    ``results_dir``; ``summaries`` defaults to every ``<results_dir>/*/rms_summary.csv``."""
    results_dir, scenarios_dir = Path(results_dir), Path(scenarios_dir)
    audit_path = Path(audit) if audit is not None else results_dir / "equation_audit.csv"
    verdicts_path = Path(verdicts) if verdicts is not None else results_dir / "verdicts.csv"
    sweep_path = Path(sweep) if sweep is not None else results_dir / "sweep.csv"
    figures_dir = Path(figures_dir) if figures_dir is not None else results_dir / "figures"
    summary_paths = (
        [Path(p) for p in summaries]
        if summaries is not None
        else sorted(results_dir.glob("*/rms_summary.csv"))
    )

    audit_df = _read(audit_path, AUDIT_COLUMNS, as_text=True)
    verdicts_df = _read(verdicts_path, VERDICT_COLUMNS, as_text=True)
    if verdicts_df is None:
        raise FileNotFoundError(f"{verdicts_path}: required input is missing")
    sweep_df = _read(sweep_path, SWEEP_COLUMNS)
    by_name: dict[str, pd.DataFrame] = {}
    dirs: dict[str, Path] = {}
    for p in summary_paths:
        df = _read(p, RMS_SUMMARY_COLUMNS)
        if df is None:
            raise FileNotFoundError(f"{p}: required input is missing")
        by_name[p.parent.name] = df
        dirs[p.parent.name] = p.parent
    noise_free = {
        name: df
        for name, d in dirs.items()
        if (df := _read(d / "noise_free.csv", RMS_SUMMARY_COLUMNS)) is not None
    }
    order = _scenario_order(list(by_name), published_scenario)
    sums = {n: by_name[n] for n in order}
    dirs = {n: dirs[n] for n in order}
    files = sorted(
        scenarios_dir.glob("*.yaml"), key=lambda f: (f.stem != published_scenario, f.stem)
    )
    file_by_name = {f.stem: f for f in files}
    descriptions = {f.stem: str(load_scenario(f).raw.get("description", "")).strip() for f in files}

    sections = [
        ("summary", "Summary", _summary_section(audit_df, verdicts_df, sums, published_scenario)),
        ("equation-audit", "Equation audit", _audit_section(audit_df, audit_path)),
        ("verdicts", "Published numbers and claims", _verdicts_section(verdicts_df)),
        (
            "results",
            "Results per scenario",
            _results_section(sums, descriptions, published_scenario),
        ),
        ("figures", "Figures", _figures_section(figures_dir, sweep_df)),
        (
            "findings",
            "Findings beyond the paper",
            _findings_section(sums, sweep_df, noise_free),
        ),
        ("assumptions", "Assumptions", _assumptions_section(files)),
        (
            "provenance",
            "Provenance",
            _provenance_section(
                dirs, file_by_name, [audit_path, verdicts_path, *summary_paths, sweep_path]
            ),
        ),
    ]
    title = f"Reproduction report: {PAPER_TITLE}"
    body = (
        f"<header><h1>{H.escape(title)}</h1>\n"
        f"<p>{H.escape(PAPER_CITATION)} — slug <code>{SLUG}</code></p>\n</header>\n"
    )
    body += H.toc([(a, t) for a, t, _ in sections])
    body += "".join(H.section(t, b, anchor=a) for a, t, b in sections)
    return H.page(title, body)


def build_page(
    results_dir: str | Path = "results/altimeter_attitude",
    scenarios_dir: str | Path = "config/scenarios/altimeter_attitude",
    out: str | Path = "reports/altimeter_attitude.html",
    **kwargs: Any,
) -> Path:
    """Render the page (see :func:`render_page` for ``kwargs``) and write it atomically."""
    return H.write_atomic(out, render_page(results_dir, scenarios_dir, **kwargs))


def main(argv: Sequence[str] | None = None) -> int:
    ap = argparse.ArgumentParser(
        prog="python -m pipeline.report.altimeter_attitude", description=__doc__.split("\n\n")[0]
    )
    ap.add_argument("--results-dir", default="results/altimeter_attitude")
    ap.add_argument("--scenarios-dir", default="config/scenarios/altimeter_attitude")
    ap.add_argument("--published-scenario", default="paper")
    ap.add_argument("--figures-dir", default=None)
    ap.add_argument("--out", default="reports/altimeter_attitude.html")
    a = ap.parse_args(argv)
    print(
        build_page(
            a.results_dir,
            a.scenarios_dir,
            a.out,
            published_scenario=a.published_scenario,
            figures_dir=a.figures_dir,
        )
    )
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
