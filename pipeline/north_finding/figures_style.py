"""The look shared by the north-finding figures: resolution, fonts and grid (:data:`RC`, applied
by the figures step with ``matplotlib.rc_context``), a new figure with a renderer, and the one
layout pass.
"""

from __future__ import annotations

from typing import Any

from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

__all__ = ["DPI", "RC", "new_figure", "tight"]

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


def new_figure(size: tuple[float, float]) -> Figure:
    """A figure of ``size`` inches at :data:`DPI` with an Agg canvas (no pyplot state)."""
    fig = Figure(figsize=size, dpi=DPI)
    FigureCanvasAgg(fig)  # a renderer for measuring text before the layout is fixed
    return fig


def tight(fig: Figure, bottom_artist: Any | None = None) -> None:
    """Fix the layout once with ``tight_layout`` (plain arithmetic on text
    extents). Constrained layout is avoided on purpose: its solver result
    varies in the last bits with PYTHONHASHSEED, which changes SVG clip ids."""
    bottom = 0.0
    if bottom_artist is not None:
        renderer = fig.canvas.get_renderer()
        bottom = bottom_artist.get_window_extent(renderer).height / fig.bbox.height + 0.01
    fig.tight_layout(rect=(0.0, bottom, 1.0, 1.0), pad=0.6, w_pad=1.2)
