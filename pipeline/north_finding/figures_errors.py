"""Figs 1-5 of the north-finding paper: per method, the Monte Carlo distribution of the absolute
percent error of the noisy real sensor (box: 25-75 %, whiskers: 5-95 %, line: median), the
noise-free real-sensor error (hollow marker) and the percent error printed in the paper (red
marker), on a log axis. The paper's figures are bar charts of the printed % error; here the bars
become markers so the distribution can be seen beside them.

The statistics come from :mod:`pipeline.north_finding.percent_errors`; the panels of each figure
from :mod:`pipeline.north_finding.figures_spec`.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import numpy as np
import pandas as pd
from matplotlib.figure import Figure
from matplotlib.lines import Line2D
from matplotlib.patches import Patch

from pipeline.figure_print import FONT_PT
from pipeline.north_finding.figures_spec import FigureSpec, Panel
from pipeline.north_finding.figures_style import new_figure, tight, title

__all__ = ["ERROR_LABELS", "plot_error_figure"]

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
        ms=5.5,
        mfc="none",
        mec=C_REAL,
        mew=1.2,
        zorder=4,
    )
    ax.plot(x + 0.3, pos(pub_v), ls="none", marker="D", ms=5, color=C_PUB, zorder=5)
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
                fontsize=FONT_PT["note"],
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
            fontsize=FONT_PT["note"],
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
    # the box and whisker percentiles are in the caption; the legend names the three marks
    mc = "Monte Carlo\n" + (f"({n_trials} trials)" if n_trials else "(box plot)")
    return [
        Patch(
            facecolor=C_BOX,
            edgecolor=C_BOX_EDGE,
            label=mc,
        ),
        Line2D(
            [],
            [],
            ls="none",
            marker="o",
            ms=5.5,
            mfc="none",
            mec=C_REAL,
            mew=1.2,
            label="real sensor,\nnoise-free",
        ),
        Line2D(
            [], [], ls="none", marker="D", ms=5, color=C_PUB, label="published\n(paper's table)"
        ),
    ]


def plot_error_figure(
    spec: FigureSpec,
    mc: pd.DataFrame,
    real: pd.Series,
    published: pd.Series,
) -> Figure:
    """Build one of Figs 1-5 from precomputed statistics.

    ``mc``, ``real``, ``published``: :func:`~pipeline.north_finding.percent_errors.abs_error_quantiles`,
    :func:`~pipeline.north_finding.percent_errors.real_abs_error_pct` and
    :func:`~pipeline.north_finding.percent_errors.published_error_pct`.
    """
    fig = new_figure(spec.size)
    widths = [max(len(p.methods), 1.6) for p in spec.panels]
    axes = fig.subplots(1, len(spec.panels), squeeze=False, width_ratios=widths)[0]
    for ax, panel in zip(axes, spec.panels, strict=True):
        _plot_panel(ax, panel, mc, real, published)
    title(fig, spec.title)
    n = mc["n"].dropna()
    n_trials = int(n.max()) if len(n) else None
    legend = fig.legend(
        handles=_error_legend_handles(n_trials),
        loc="lower center",
        ncol=3,
        frameon=False,
        bbox_to_anchor=(0.5, 0.0),
        columnspacing=1.0,
        handletextpad=0.4,
    )
    tight(fig, bottom_artist=legend)
    return fig
