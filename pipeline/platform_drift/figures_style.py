"""The look shared by the platform-drift figures (Figs 5-8 and the latitude sweep): the print
size, fonts, line styles and the one legend below the panels.

A figure is drawn at the width the PDF report prints it alone, the text width
(:data:`pipeline.figure_print.TEXT_WIDTH_IN`), with the print font sizes of
:data:`pipeline.figure_print.FONT_PT` (:data:`RC`, applied with ``matplotlib.rc_context``), so
its text prints at the sizes given here.
"""

from __future__ import annotations

from collections.abc import Sequence
from typing import Any

from matplotlib.figure import Figure

from pipeline.figure_print import FONT_RC, TEXT_WIDTH_IN

__all__ = ["DPI", "RC", "STYLE", "WIDTH_IN", "legend_below"]

#: PNG resolution (the HTML pages): a text-wide figure is ~1000 px wide
DPI = 150
WIDTH_IN = TEXT_WIDTH_IN
RC = {
    **FONT_RC,
    "axes.linewidth": 0.6,
    "xtick.major.width": 0.6,
    "ytick.major.width": 0.6,
    "xtick.major.size": 3.0,
    "ytick.major.size": 3.0,
    "grid.linewidth": 0.5,
}
#: drawing order: the simulated proposed curve last, on top of the strapdown one
STYLE = {
    "proposed_analytic": dict(color="tab:blue", lw=1.1, label="proposed, analytic (eqs. 32/36)"),
    "proposed_true_azimuth": dict(
        color="0.45", lw=0.9, ls=":", label="proposed, true azimuth rate (diagnostic)"
    ),
    "strapdown": dict(color="tab:red", lw=2.0, alpha=0.75, label="strapdown"),
    "proposed_simulated": dict(
        color="tab:purple", lw=0.9, ls="--", marker="o", mfc="none", ms=3.0, markevery=48,
        mew=0.8, label="proposed, nonlinear simulation", zorder=4,
    ),
}  # fmt: skip


def legend_below(fig: Figure, axes: Sequence[Any], ncol: int) -> Any:
    """One legend at the bottom of ``fig`` with the labelled artists of ``axes`` (first
    occurrence of each label)."""
    entries: dict[str, Any] = {}
    for ax in axes:
        for handle, text in zip(*ax.get_legend_handles_labels(), strict=True):
            entries.setdefault(text, handle)
    return fig.legend(
        list(entries.values()),
        list(entries),
        loc="lower center",
        ncol=ncol,
        frameon=False,
        handlelength=2.2,
        columnspacing=1.2,
        borderaxespad=0.2,
    )
