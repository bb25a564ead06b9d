"""The look shared by the north-finding figures: resolution, fonts and grid (:data:`RC`, applied
by the figures step with ``matplotlib.rc_context``), the widths they are drawn at, a new figure
with a renderer, the title wrapped to the width, and the one layout pass.

A figure is drawn at the width the PDF report prints it (:mod:`pipeline.figure_print`):
:data:`COLUMN` for one set beside another, :data:`FULL` for one alone at the text width; the
fonts are the print sizes of :data:`pipeline.figure_print.FONT_PT` (7.5-9 pt).
"""

from __future__ import annotations

import textwrap
from typing import Any

from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from pipeline.figure_layout import tight_layout
from pipeline.figure_print import COLUMN_WIDTH_IN, FONT_PT, FONT_RC, TEXT_WIDTH_IN

__all__ = ["COLUMN", "DPI", "FULL", "RC", "new_figure", "tight", "title"]

#: drawn widths (inches): beside another figure, alone at the text width
COLUMN = COLUMN_WIDTH_IN
FULL = TEXT_WIDTH_IN
#: raster resolution of the PNG (the HTML pages): a column-wide figure is ~650 px wide
DPI = 200
RC = {
    **FONT_RC,
    "lines.linewidth": 1.2,
    "axes.linewidth": 0.6,
    "xtick.major.width": 0.6,
    "ytick.major.width": 0.6,
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


def title(fig: Figure, text: str) -> None:
    """The figure's title, wrapped to its width (about 0.52 em per character)."""
    chars = int(fig.get_figwidth() * 72 / (0.52 * FONT_PT["title"]))
    fig.suptitle("\n".join(textwrap.wrap(text, chars)))


def tight(fig: Figure, bottom_artist: Any | None = None) -> None:
    """Fix the layout once with ``tight_layout`` (plain arithmetic on text
    extents). Constrained layout is avoided on purpose: its solver result
    varies in the last bits with PYTHONHASHSEED, which changes SVG clip ids."""
    bottom = 0.0
    if bottom_artist is not None:
        renderer = fig.canvas.get_renderer()
        bottom = bottom_artist.get_window_extent(renderer).height / fig.bbox.height + 0.01
    tight_layout(fig, rect=(0.0, bottom, 1.0, 1.0), pad=0.4, w_pad=0.8)
