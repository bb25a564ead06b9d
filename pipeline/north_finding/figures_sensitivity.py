"""Fig. 6 of this reproduction (not in the paper): the Monte Carlo RMS percent error of the
azimuth estimate against the number of samples averaged per table position (``sensitivity.csv``,
log-log), one line per method, with the scenario's default ``n_avg`` and the published percent
error of each method. The paper does not state ``n_avg``; this figure shows which averaging its
errors imply.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

import matplotlib
import numpy as np
import pandas as pd
from matplotlib.figure import Figure
from matplotlib.lines import Line2D

from pipeline.figure_print import FONT_PT
from pipeline.north_finding.columns import AZIMUTH_METHODS
from pipeline.north_finding.figures_spec import SENSITIVITY_TITLE
from pipeline.north_finding.figures_style import COLUMN, new_figure, tight, title

__all__ = ["plot_sensitivity_figure"]


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
    fig = new_figure((COLUMN, 3.1))
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
            ms=3,
            lw=1.2,
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
                lw=2.5,
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
            fontsize=FONT_PT["label"],
            color="#777",
        )
    if default_n_avg is not None and np.isfinite(default_n_avg) and default_n_avg > 0:
        handles.append(
            ax.axvline(
                default_n_avg,
                color="#555",
                ls="--",
                lw=1.2,
                label=f"default\n$n_\\mathrm{{avg}}$ = {default_n_avg:.3g}",
            )
        )
    handles.append(
        Line2D(
            [],
            [],
            color="#555",
            lw=2.5,
            solid_capstyle="butt",
            label="published\n(ticks at right)",
        )
    )
    ax.set_xlabel(r"samples averaged per table position, $n_\mathrm{avg}$ (-)")
    ax.set_ylabel(r"RMS percent error of $\hat{\psi}$ (%)")
    title(fig, SENSITIVITY_TITLE)
    legend = fig.legend(
        handles=handles,
        loc="lower center",
        ncol=4,
        frameon=False,
        bbox_to_anchor=(0.5, 0.0),
        columnspacing=0.8,
        handlelength=1.5,
    )
    tight(fig, bottom_artist=legend)
    return fig
