"""Figures 1-5 of the north-finding paper (percent errors per method), plus a
sensitivity figure (Fig. 6, not in the paper).

Each of Figs 1-5 shows, per method, the Monte Carlo distribution of the absolute
percent error of the noisy real sensor (box: 25-75 %, whiskers: 5-95 %, line:
median), the noise-free real-sensor error (hollow marker) and the percent error
printed in the paper (red marker). The paper's figures are bar charts of the
printed % error; here the bars become markers so the distribution can be seen
beside them.

Inputs (one scenario directory, the results contract of DESIGN.md):
``mc_trials.csv``, ``estimates.csv``, ``sensitivity.csv`` (optional),
``provenance.json`` (optional key ``n_avg``), and the published values
``config/published/north_finding.yaml``.

CLI::

    python -m pipeline.north_finding.figures --scenario-dir results/north_finding/paper \\
        --published config/published/north_finding.yaml --out-dir results/north_finding/figures

Snakemake ``script:`` use: ``params.scenario_dir`` (or the parent directory of
``input.mc_trials``), ``input.published``, and the outputs' directory (or
``params.out_dir``).

Output is deterministic: PNG at 150 dpi without a Software stamp, SVG with a
fixed ``svg.hashsalt`` and no date, so reruns are byte-identical. Files are
written atomically.
"""

# No `from __future__ import annotations`: Snakemake's script: directive prepends a
# preamble, after which a __future__ import would be a SyntaxError.
if "snakemake" in globals():  # run by Snakemake's script: directive from the repo root
    import os as _os
    import sys as _sys

    _sys.path.insert(0, _os.getcwd())

import argparse
import json
import re
from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import matplotlib
import numpy as np
import pandas as pd
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Patch

from pipeline import figure_files
from pipeline.north_finding.columns import (
    AZIMUTH_METHODS,
    ESTIMATE_COLUMNS,
    LEVELING_METHODS,
    MC_TRIAL_COLUMNS,
    QUANTITIES,
    SENSITIVITY_COLUMNS,
)
from pipeline.verdicts import published as verdicts_published

__all__ = [
    "FIGURES",
    "FIGURE_FILES",
    "PUBLISHED_ITEM_FIELDS",
    "FigureSpec",
    "Panel",
    "abs_error_quantiles",
    "canonical_quantity",
    "load_published",
    "main",
    "plot_error_figure",
    "plot_sensitivity_figure",
    "published_error_pct",
    "read_provenance",
    "real_abs_error_pct",
    "run",
    "run_from_snakemake",
]

DPI = 150
RC = {
    "font.size": 10,
    "axes.titlesize": 10.5,
    "axes.labelsize": 10,
    "xtick.labelsize": 10,
    "ytick.labelsize": 9.5,
    "legend.fontsize": 9,
    "figure.titlesize": 11.5,
    "axes.grid": True,
    "axes.grid.which": "both",
    "grid.alpha": 0.25,
    "grid.linewidth": 0.6,
}

PUBLISHED_ITEM_FIELDS = (
    "id",
    "table",
    "quantity",
    "method",
    "sensor",
    "value",
    "error_pct",
    "unit",
    "kind",
)

# Colours: Monte Carlo box, noise-free marker, published marker.
C_BOX = "#9ecae1"
C_BOX_EDGE = "#08519c"
C_REAL = "black"
C_PUB = "#d62728"

#: Axis label of the percent error of each quantity (mathtext).
ERROR_LABELS: dict[str, str] = {
    "phi_deg": r"percent error $|\hat{\varphi}-\varphi|/\varphi$ (%)",
    "theta_deg": r"percent error $|\hat{\theta}-\theta|/\theta$ (%)",
    "psi_deg": r"percent error $|\hat{\psi}-\psi|/\psi$ (%)",
    "acc_bias_ug": r"percent error $|\hat{b}_a-b_a|/b_a$ (%)",
    "acc_scale": r"percent error $|\hat{S}_a-S_a|/S_a$ (%)",
    "acc_scale_approx": r"percent error $|\hat{S}_{a,\mathrm{approx}}-S_a|/S_a$ (%)",
    "gyro_bias_rad_s": r"percent error $|\hat{b}_g-b_g|/b_g$ (%)",
    "gyro_scale": r"percent error $|\hat{S}_g-S_g|/S_g$ (%)",
    "gyro_scale_approx": r"percent error $|\hat{S}_{g,\mathrm{approx}}-S_g|/S_g$ (%)",
}


@dataclass(frozen=True)
class Panel:
    """One axes: a quantity and the methods (x categories) that estimate it."""

    quantity: str
    methods: tuple[str, ...]
    title: str = ""
    xlabel: str = "method"


@dataclass(frozen=True)
class FigureSpec:
    """One output figure (``stem`` -> ``stem.png`` and ``stem.svg``)."""

    stem: str
    title: str
    panels: tuple[Panel, ...]
    size: tuple[float, float] = (6.6, 4.8)


FIGURES: tuple[FigureSpec, ...] = (
    FigureSpec(
        "fig1_roll",
        "Fig. 1 — roll φ percent error per levelling method (real sensor)",
        (Panel("phi_deg", LEVELING_METHODS[:4], xlabel="levelling method"),),
    ),
    FigureSpec(
        "fig2_pitch",
        "Fig. 2 — pitch θ percent error per levelling method (real sensor)",
        (Panel("theta_deg", LEVELING_METHODS[:4], xlabel="levelling method"),),
    ),
    FigureSpec(
        "fig3_azimuth",
        "Fig. 3 — azimuth ψ percent error per azimuth method (real sensor)",
        (Panel("psi_deg", ("A1c1", "A1c2", "A2", "A3", "A4", "A5"), xlabel="azimuth method"),),
        size=(7.4, 4.8),
    ),
    FigureSpec(
        "fig4_bias",
        "Fig. 4 — sensor bias percent error (real sensor)",
        (
            Panel("acc_bias_ug", ("L5",), "(a) accelerometer bias", "levelling method"),
            Panel("gyro_bias_rad_s", ("A4",), "(b) gyro bias", "azimuth method"),
        ),
        size=(7.0, 4.8),
    ),
    FigureSpec(
        "fig5_scale",
        "Fig. 5 — scale-factor percent error (real sensor)",
        (
            Panel("acc_scale", ("L5",), "(a) accelerometer S", "levelling method"),
            Panel("gyro_scale", ("A4", "A5", "A6"), "(b) gyro S", "azimuth method"),
            Panel(
                "gyro_scale_approx",
                ("A5", "A6"),
                "(c) gyro S (first-order approx.)",
                "azimuth method",
            ),
        ),
        size=(10.0, 4.8),
    ),
)
SENSITIVITY_STEM = "fig6_sensitivity"
SENSITIVITY_TITLE = "Fig. 6 (not in the paper) — azimuth RMS percent error vs samples averaged"
#: Every figure stem this module writes, in order (``.png`` and ``.svg`` each).
FIGURE_FILES: tuple[str, ...] = tuple(f.stem for f in FIGURES) + (SENSITIVITY_STEM,)


# --------------------------------------------------------------------------- inputs


def canonical_quantity(name: object) -> str:
    """Map a quantity name to the results-contract name (``phi`` -> ``phi_deg``,
    ``gyro_bias`` -> ``gyro_bias_rad_s``); unknown names are returned unchanged."""
    q = str(name).strip()
    if q in QUANTITIES:
        return q
    hits = [c for c in QUANTITIES if c.startswith(q + "_") and not c.endswith("_approx")]
    return hits[0] if len(hits) == 1 else q


def _table_number(value: object) -> float:
    """``1``, ``"1"``, ``"T1"``, ``"Table 1"`` -> 1.0; anything else -> NaN."""
    if value is None:
        return float("nan")
    m = re.search(r"\d+", str(value))
    return float(m.group()) if m else float("nan")


def load_published(path: str | Path) -> tuple[pd.DataFrame, pd.DataFrame]:
    """Read ``config/published/<slug>.yaml`` -> ``(items, claims)``.

    The file is read and checked by :func:`pipeline.verdicts.load_published` (the shared
    format); the items are flattened into the columns :data:`PUBLISHED_ITEM_FIELDS` (values as
    printed, strings; ``table`` is the item's ``label``, ``method`` and ``sensor`` its
    selectors) plus ``table_no`` (float, NaN if no table) and ``error_pct_value`` (float, NaN
    if the paper prints none); ``quantity`` is canonicalised with :func:`canonical_quantity`.
    ``claims`` has ``id, text, source, predicate``.
    """
    data = verdicts_published.load_published(path)
    raw_items = []
    for i in data["items"]:
        select = i.get("select") or {}
        raw_items.append(
            {
                **{k: v for k, v in i.items() if k not in ("select", "label")},
                "table": i["label"],
                "method": select.get("method"),
                "sensor": select.get("sensor"),
            }
        )
    items = pd.DataFrame(raw_items)
    for field in PUBLISHED_ITEM_FIELDS:
        if field not in items.columns:
            items[field] = None
    items = items.astype({f: object for f in PUBLISHED_ITEM_FIELDS})
    items["quantity"] = items["quantity"].map(canonical_quantity)
    items["method"] = items["method"].map(lambda m: None if m is None else str(m))
    items["sensor"] = items["sensor"].map(lambda s: None if s is None else str(s).lower())
    items["table_no"] = items["table"].map(_table_number).astype(float)
    items["error_pct_value"] = pd.to_numeric(items["error_pct"], errors="coerce").astype(float)
    claims = pd.DataFrame([dict(c) for c in data["claims"]], columns=None)
    for field in ("id", "text", "source", "predicate"):
        if field not in claims.columns:
            claims[field] = None
    return items, claims


def _read_csv(path: Path, columns: Sequence[str], optional: bool = False) -> pd.DataFrame:
    if not path.is_file():
        if optional:
            return pd.DataFrame(columns=list(columns))
        raise FileNotFoundError(f"{path}: required input is missing")
    df = pd.read_csv(path)
    missing = [c for c in columns if c not in df.columns]
    if missing:
        raise ValueError(f"{path}: missing columns {missing} (has {list(df.columns)})")
    return df


def read_provenance(scenario_dir: str | Path) -> dict[str, Any]:
    """``provenance.json`` of a scenario, or ``{}`` if absent."""
    p = Path(scenario_dir) / "provenance.json"
    return json.loads(p.read_text(encoding="utf-8")) if p.is_file() else {}


# --------------------------------------------------------------------------- statistics

QUANTILE_LEVELS = (0.05, 0.25, 0.50, 0.75, 0.95)
QUANTILE_NAMES = ("p05", "p25", "p50", "p75", "p95")


def abs_error_quantiles(trials: pd.DataFrame) -> pd.DataFrame:
    """Quantiles of ``|error_pct|`` per (method, quantity) over Monte Carlo trials.

    Returns a frame indexed by ``(method, quantity)`` with columns
    ``p05, p25, p50, p75, p95, n`` (vectorised groupby; no loop over trials).
    """
    if trials.empty:
        idx = pd.MultiIndex.from_arrays([[], []], names=["method", "quantity"])
        return pd.DataFrame(columns=[*QUANTILE_NAMES, "n"], index=idx, dtype=float)
    abs_err = trials["error_pct"].astype(float).abs()
    grouped = abs_err.groupby([trials["method"].astype(str), trials["quantity"].astype(str)])
    q = grouped.quantile(list(QUANTILE_LEVELS)).unstack()
    q.columns = list(QUANTILE_NAMES)
    q["n"] = grouped.count()
    q.index.names = ["method", "quantity"]
    return q


def real_abs_error_pct(estimates: pd.DataFrame, sensor: str = "real") -> pd.Series:
    """``|error_pct|`` of the noise-free run of ``sensor``, indexed by (method, quantity)."""
    sel = estimates[estimates["sensor"].astype(str) == sensor]
    s = (
        sel.set_index([sel["method"].astype(str), sel["quantity"].astype(str)])["error_pct"]
        .astype(float)
        .abs()
    )
    s.index.names = ["method", "quantity"]
    return s[~s.index.duplicated(keep="first")]


def published_error_pct(items: pd.DataFrame, sensor: str = "real") -> pd.Series:
    """Published ``|% error|`` per (method, quantity) for ``sensor`` (rows without one dropped)."""
    sel = items[(items["sensor"] == sensor) & items["error_pct_value"].notna()]
    s = sel.set_index([sel["method"].astype(str), sel["quantity"].astype(str)])[
        "error_pct_value"
    ].abs()
    s.index.names = ["method", "quantity"]
    return s[~s.index.duplicated(keep="first")]


# --------------------------------------------------------------------------- plotting


def _lookup(s: pd.Series, methods: Sequence[str], quantity: str) -> np.ndarray:
    idx = pd.MultiIndex.from_arrays([list(methods), [quantity] * len(methods)])
    return s.reindex(idx).to_numpy(dtype=float)


def _plot_panel(
    ax: Any,
    panel: Panel,
    mc: pd.DataFrame,
    real: pd.Series,
    published: pd.Series,
) -> None:
    methods = list(panel.methods)
    x = np.arange(len(methods), dtype=float)
    stats = mc.reindex(pd.MultiIndex.from_arrays([methods, [panel.quantity] * len(methods)]))
    have_mc = stats["p50"].notna().to_numpy()
    bxp = [
        {
            "med": r.p50,
            "q1": r.p25,
            "q3": r.p75,
            "whislo": r.p05,
            "whishi": r.p95,
            "fliers": [],
            "label": m,
        }
        for m, r, ok in zip(methods, stats.itertuples(), have_mc, strict=True)
        if ok
    ]
    if bxp:
        ax.bxp(
            bxp,
            positions=list(x[have_mc] - 0.14),
            widths=0.3,
            patch_artist=True,
            showfliers=False,
            boxprops={"facecolor": C_BOX, "edgecolor": C_BOX_EDGE, "linewidth": 1.0},
            medianprops={"color": C_BOX_EDGE, "linewidth": 1.8},
            whiskerprops={"color": C_BOX_EDGE, "linewidth": 1.0},
            capprops={"color": C_BOX_EDGE, "linewidth": 1.0},
            manage_ticks=False,
        )
    real_v = _lookup(real, methods, panel.quantity)
    pub_v = _lookup(published, methods, panel.quantity)
    pos = lambda v: np.where(v > 0, v, np.nan)  # noqa: E731 - log axis: zero is off scale
    ax.plot(
        x + 0.12,
        pos(real_v),
        ls="none",
        marker="o",
        ms=8,
        mfc="none",
        mec=C_REAL,
        mew=1.6,
        zorder=4,
    )
    ax.plot(x + 0.3, pos(pub_v), ls="none", marker="D", ms=7, color=C_PUB, zorder=5)
    # Values that a log axis cannot show, said in words at the bottom.
    for xi, rv, pv in zip(x, real_v, pub_v, strict=True):
        notes = [txt for v, txt in ((rv, "noise-free 0"), (pv, "published 0")) if v == 0]
        if notes:
            ax.annotate(
                "\n".join(notes),
                (xi, 0),
                xycoords=("data", "axes fraction"),
                xytext=(0, 3),
                textcoords="offset points",
                ha="center",
                va="bottom",
                fontsize=8.5,
                color="#444",
            )
    absent = ~have_mc & np.isnan(real_v) & np.isnan(pub_v)
    for xi in x[absent]:
        ax.annotate(
            "no data",
            (xi, 0.5),
            xycoords=("data", "axes fraction"),
            ha="center",
            va="center",
            fontsize=9,
            color="#777",
            rotation=90,
        )
    ax.set_yscale("log")
    ax.set_xticks(x, methods)
    ax.set_xlim(-0.6, len(methods) - 0.4)
    ax.set_xlabel(panel.xlabel)
    ax.set_ylabel(ERROR_LABELS.get(panel.quantity, f"percent error of {panel.quantity} (%)"))
    if panel.title:
        ax.set_title(panel.title)
    ax.grid(False, axis="x")
    values = np.concatenate([stats[["p05", "p95"]].to_numpy(dtype=float).ravel(), real_v, pub_v])
    values = values[np.isfinite(values) & (values > 0)]
    if values.size:
        lo, hi = values.min(), values.max()
        ax.set_ylim(lo / 3.0, hi * 3.0)


def _error_legend_handles(n_trials: int | None) -> list[Any]:
    mc = "Monte Carlo |error|" + (f", {n_trials} trials" if n_trials else "")
    return [
        Patch(
            facecolor=C_BOX,
            edgecolor=C_BOX_EDGE,
            label=f"{mc}\nmedian, box 25–75 %, whiskers 5–95 %",
        ),
        Line2D(
            [],
            [],
            ls="none",
            marker="o",
            ms=8,
            mfc="none",
            mec=C_REAL,
            mew=1.6,
            label="real sensor,\nnoise-free",
        ),
        Line2D(
            [], [], ls="none", marker="D", ms=7, color=C_PUB, label="published\n(paper's table)"
        ),
    ]


def plot_error_figure(
    spec: FigureSpec,
    mc: pd.DataFrame,
    real: pd.Series,
    published: pd.Series,
) -> Figure:
    """Build one of Figs 1-5 from precomputed statistics.

    ``mc``: :func:`abs_error_quantiles`; ``real``: :func:`real_abs_error_pct`;
    ``published``: :func:`published_error_pct`.
    """
    fig = _new_figure(spec.size)
    widths = [max(len(p.methods), 1.6) for p in spec.panels]
    axes = fig.subplots(1, len(spec.panels), squeeze=False, width_ratios=widths)[0]
    for ax, panel in zip(axes, spec.panels, strict=True):
        _plot_panel(ax, panel, mc, real, published)
    fig.suptitle(spec.title)
    n = mc["n"].dropna()
    n_trials = int(n.max()) if len(n) else None
    legend = fig.legend(
        handles=_error_legend_handles(n_trials),
        loc="lower center",
        ncol=3,
        frameon=False,
        bbox_to_anchor=(0.5, 0.0),
        columnspacing=1.5,
        handletextpad=0.5,
    )
    _tight(fig, bottom_artist=legend)
    return fig


def _new_figure(size: tuple[float, float]) -> Figure:
    fig = Figure(figsize=size, dpi=DPI)
    FigureCanvasAgg(fig)  # a renderer for measuring text before the layout is fixed
    return fig


def _tight(fig: Figure, bottom_artist: Any | None = None) -> None:
    """Fix the layout once with ``tight_layout`` (plain arithmetic on text
    extents). Constrained layout is avoided on purpose: its solver result
    varies in the last bits with PYTHONHASHSEED, which changes SVG clip ids."""
    bottom = 0.0
    if bottom_artist is not None:
        renderer = fig.canvas.get_renderer()
        bottom = bottom_artist.get_window_extent(renderer).height / fig.bbox.height + 0.01
    fig.tight_layout(rect=(0.0, bottom, 1.0, 1.0), pad=0.6, w_pad=1.2)


def plot_sensitivity_figure(
    sensitivity: pd.DataFrame,
    published: pd.Series,
    default_n_avg: float | None = None,
    quantity: str = "psi_deg",
    methods: Sequence[str] = AZIMUTH_METHODS,
) -> Figure:
    """Fig. 6: RMS percent error of ``quantity`` against ``n_avg`` (log-log), one
    line per method; ``default_n_avg`` as a vertical line; the published % error
    of each method as a short horizontal tick at the right edge."""
    fig = _new_figure((7.4, 5.6))
    ax = fig.subplots()
    sel = sensitivity[sensitivity["quantity"].astype(str) == quantity]
    wide = sel.pivot_table(index="n_avg", columns="method", values="rms_error_pct", aggfunc="first")
    present = [m for m in methods if m in wide.columns]
    colors = matplotlib.colormaps["tab10"]
    handles: list[Any] = []
    xs = wide.index.to_numpy(float)
    xs = xs[xs > 0]
    if xs.size:
        # room at the right for the published ticks (drawn at 93-99 % of the axes width)
        lo, hi = np.log10(xs.min()), np.log10(xs.max())
        span = max(hi - lo, 1.0)
        ax.set_xlim(10 ** (lo - 0.03 * span), 10 ** (hi + 0.13 * span))
    for k, m in enumerate(present):
        col = wide[m].dropna()
        col = col[col > 0]
        (line,) = ax.plot(
            col.index.to_numpy(float),
            col.to_numpy(float),
            marker="o",
            ms=4,
            lw=1.5,
            color=colors(k),
            label=m,
        )
        handles.append(line)
        pub = published.get((m, quantity), np.nan)
        if np.isfinite(pub) and pub > 0:
            ax.plot(
                [0.93, 0.99],
                [pub, pub],
                transform=ax.get_yaxis_transform(),
                color=colors(k),
                lw=3.5,
                solid_capstyle="butt",
            )
    ax.set_xscale("log")
    ax.set_yscale("log")
    if not present:
        ax.set_xlim(1e2, 1e8)
        ax.set_ylim(1e-4, 1e1)
        ax.text(
            0.5,
            0.5,
            f"sensitivity of {quantity}: not available",
            transform=ax.transAxes,
            ha="center",
            va="center",
            fontsize=11,
            color="#777",
        )
    if default_n_avg is not None and np.isfinite(default_n_avg) and default_n_avg > 0:
        handles.append(
            ax.axvline(
                default_n_avg,
                color="#555",
                ls="--",
                lw=1.2,
                label=f"scenario default $n_\\mathrm{{avg}}$ = {default_n_avg:.3g}",
            )
        )
    handles.append(
        Line2D(
            [],
            [],
            color="#555",
            lw=3.5,
            solid_capstyle="butt",
            label="published % error (tick at right, method colour)",
        )
    )
    ax.set_xlabel(r"samples averaged per table position, $n_\mathrm{avg}$")
    ax.set_ylabel(r"RMS percent error of $\hat{\psi}$ (%)")
    fig.suptitle(SENSITIVITY_TITLE)
    legend = fig.legend(
        handles=handles,
        loc="lower center",
        ncol=4,
        frameon=False,
        bbox_to_anchor=(0.5, 0.0),
        columnspacing=1.2,
    )
    _tight(fig, bottom_artist=legend)
    return fig


def _write_figure(fig: Figure, out_dir: Path, stem: str) -> list[Path]:
    return figure_files.write_png_svg(fig, out_dir / f"{stem}.png", DPI)


# --------------------------------------------------------------------------- entry points


def run(
    scenario_dir: str | Path,
    published: str | Path,
    out_dir: str | Path,
) -> list[Path]:
    """Write fig1..fig6 (``.png`` and ``.svg``) for one scenario into ``out_dir``.

    ``mc_trials.csv`` and ``estimates.csv`` are required; ``sensitivity.csv``
    and ``provenance.json`` are optional (Fig. 6 then says "not available" /
    omits the default-n_avg line). Returns the written paths.
    """
    scenario_dir, out_dir = Path(scenario_dir), Path(out_dir)
    items, _ = load_published(published)
    pub = published_error_pct(items, "real")
    trials = _read_csv(scenario_dir / "mc_trials.csv", MC_TRIAL_COLUMNS)
    estimates = _read_csv(scenario_dir / "estimates.csv", ESTIMATE_COLUMNS)
    sensitivity = _read_csv(scenario_dir / "sensitivity.csv", SENSITIVITY_COLUMNS, optional=True)
    n_avg = read_provenance(scenario_dir).get("n_avg")
    mc = abs_error_quantiles(trials)
    real = real_abs_error_pct(estimates, "real")
    written: list[Path] = []
    with matplotlib.rc_context(RC):
        for spec in FIGURES:
            written += _write_figure(plot_error_figure(spec, mc, real, pub), out_dir, spec.stem)
        fig6 = plot_sensitivity_figure(
            sensitivity, pub, float(n_avg) if n_avg is not None else None
        )
        written += _write_figure(fig6, out_dir, SENSITIVITY_STEM)
    return written


def run_from_snakemake(smk: Any) -> list[Path]:
    """Entry for Snakemake's ``script:`` directive (see the module docstring)."""
    params, inputs = smk.params, smk.input
    scenario_dir = params.get("scenario_dir") if hasattr(params, "get") else None
    if scenario_dir is None:
        scenario_dir = Path(inputs.mc_trials).parent
    out_dir = params.get("out_dir") if hasattr(params, "get") else None
    if out_dir is None:
        out_dir = Path(smk.output[0]).parent
    return run(scenario_dir, inputs.published, out_dir)


def main(argv: Sequence[str] | None = None) -> int:
    ap = argparse.ArgumentParser(
        prog="python -m pipeline.north_finding.figures", description=__doc__.split("\n\n")[0]
    )
    ap.add_argument("--scenario-dir", default="results/north_finding/paper", type=Path)
    ap.add_argument("--published", default="config/published/north_finding.yaml", type=Path)
    ap.add_argument("--out-dir", default="results/north_finding/figures", type=Path)
    args = ap.parse_args(argv)
    for p in run(args.scenario_dir, args.published, args.out_dir):
        print(p)
    return 0


if __name__ == "__main__":
    if "snakemake" in globals():
        run_from_snakemake(snakemake)  # type: ignore[name-defined]  # noqa: F821
    else:
        raise SystemExit(main())
