"""The look shared by the altimeter_attitude figures: sizes, fonts, colours, the style of each
filter, and the drawing steps every figure uses (a new figure, styled axes, readable log ticks,
shaded maneuvers, the title, subtitle and one legend below the panels).

Figures are built on :class:`matplotlib.figure.Figure` with an Agg canvas (no pyplot state),
so drawing one figure never changes another.

:func:`finish` sets the figure to the size the PDF report prints it (:mod:`pipeline.figure_print`):
a column wide (set beside another figure) when its panels are stacked, the text width when they
stand side by side; its height follows from the wrapped title and subtitle, the rows of panels
and the measured legend. Fonts are the print sizes of :data:`pipeline.figure_print.FONT_PT`, and
lines drawn with the widths of a 9-in canvas are thinned (:data:`LINE_SCALE`) to the print size.
"""

from __future__ import annotations

import math
import textwrap
from collections.abc import Sequence
from typing import Any

import numpy as np
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure
from matplotlib.ticker import (
    FuncFormatter,
    LogFormatterSciNotation,
    LogLocator,
    NullFormatter,
)

from pipeline.altimeter_attitude.maneuvers import LOAD_DEVIATION
from pipeline.figure_layout import tight_layout
from pipeline.figure_print import COLUMN_WIDTH_IN, FONT_PT, TEXT_WIDTH_IN

__all__ = [
    "DPI",
    "WIDTH_IN",
    "ANGLE_COLOR",
    "C_COLOR",
    "FILTER_STYLE",
    "positive",
    "new_figure",
    "style_axes",
    "finish",
    "shade",
]

#: PNG resolution (the HTML pages): a column-wide figure is ~650 px wide
DPI = 200
#: the drawing width before :func:`finish` sets the print size
WIDTH_IN = COLUMN_WIDTH_IN
FS_TITLE = FONT_PT["title"]
FS_SUBTITLE = FONT_PT["note"]
FS_LABEL = FONT_PT["label"]
FS_TICK = FONT_PT["tick"]
FS_LEGEND = FONT_PT["legend"]
#: height (in) of one row of panels: alone, stacked, side by side at the text width
PANEL_IN = {"single": 1.3, "stacked": 0.85, "wide": 1.8}
#: the bottom axis' tick labels and label below the rows (in)
XAXIS_IN = 0.3
#: line widths and marker sizes are given for a 9-in canvas; at the print width they are
#: drawn this much thinner
LINE_SCALE = 0.65

ANGLE_COLOR = {"roll": "tab:blue", "pitch": "tab:green"}
C_COLOR = ("tab:blue", "tab:orange", "tab:green")
FILTER_STYLE = {
    "linear_kf": ("tab:blue", "linear KF on c (eqs. 26-33)"),
    "linear_kf_no_gamma": ("tab:cyan", r"linear KF without $\Gamma(Q\otimes P)\Gamma^T$"),
    "ukf": ("tab:orange", "UKF on Euler angles (Sec. 6)"),
    "ekf": ("tab:brown", "EKF on Euler angles"),
    "complementary": ("tab:purple", "PI complementary filter (Fig. 1)"),
    "gyro_only": ("0.45", "gyro only (eq. 14, no update)"),
    "accel_leveling": ("tab:red", "accelerometer leveling (eq. 17-b)"),
}


def positive(y: np.ndarray) -> np.ndarray:
    """y with non-positive values as NaN (gaps on a log axis instead of clipped spikes)."""
    y = np.asarray(y, dtype=float)
    return np.where(y > 0, y, np.nan)


def new_figure(nrows: int, height: float, sharex: bool = True) -> tuple[Figure, list]:
    """A figure of :data:`WIDTH_IN` x ``height`` inches with ``nrows`` stacked axes (the
    height is provisional: :func:`finish` sets the printed size from the rows)."""
    fig = Figure(figsize=(WIDTH_IN, height), dpi=DPI)
    FigureCanvasAgg(fig)
    axes = fig.subplots(nrows, 1, sharex=sharex, squeeze=False)[:, 0]
    return fig, list(axes)


def style_axes(ax: Any, ylabel: str | None = None, xlabel: str | None = None) -> None:
    """Grid (minor too on a log axis), tick font, axis labels."""
    ax.grid(True, which="major", alpha=0.4)
    if ax.get_yscale() == "log":
        ax.grid(True, which="minor", alpha=0.15)
    ax.tick_params(labelsize=FS_TICK)
    if ylabel is not None:
        ax.set_ylabel(ylabel, fontsize=FS_LABEL)
    if xlabel is not None:
        ax.set_xlabel(xlabel, fontsize=FS_LABEL)


def _log_ticks(ax: Any, height_in: float) -> None:
    """Readable log-axis labels for a panel ``height_in`` tall: 0.05, 0.1, 0.2, 0.5, 1, 2 over a
    few decades, the decades alone where those would crowd (over ~4 labels an inch), 10^k
    beyond."""
    lo, hi = ax.get_ylim()
    if lo <= 0 or hi <= lo:
        return
    decades = math.log10(hi / lo)
    if decades <= 3.5:
        subs = (1.0, 2.0, 5.0) if 3 * decades <= 4 * height_in else (1.0,)
        ax.yaxis.set_major_locator(LogLocator(base=10.0, subs=subs))
        ax.yaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
    else:
        ax.yaxis.set_major_locator(LogLocator(base=10.0, numticks=max(3, int(4 * height_in))))
        ax.yaxis.set_major_formatter(LogFormatterSciNotation())
    ax.yaxis.set_minor_formatter(NullFormatter())


def _grid(fig: Figure) -> tuple[int, int]:
    """(rows, columns) of the panel grid of ``fig``."""
    shapes = [ax.get_subplotspec().get_gridspec().get_geometry() for ax in fig.axes]
    return max(r for r, _ in shapes), max(c for _, c in shapes)


def _chars(width_in: float, size_pt: float) -> int:
    """Characters of ``size_pt`` text to a line ``width_in`` wide (about 0.56 em each)."""
    return int(width_in * 72 / (0.56 * size_pt))


def _wrap(text: str, chars: int) -> list[str]:
    """``text`` in lines of at most ``chars`` characters, never breaking inside ``$...$``."""
    parts = text.split("$")
    kept = "$".join(p.replace(" ", "\u00a0") if k % 2 else p for k, p in enumerate(parts))
    lines = textwrap.wrap(kept, chars, break_long_words=False, break_on_hyphens=False)
    return [line.replace("\u00a0", " ") for line in lines]


def _fit_ylabels(fig: Figure, panel_in: float) -> None:
    """An axis label longer than its panel is tall goes on as many lines as it needs."""
    chars = _chars(0.95 * panel_in, FS_LABEL)
    for ax in fig.axes:
        label = ax.get_ylabel()
        if label and "\n" not in label and len(label) > chars:
            ax.set_ylabel("\n".join(_wrap(label, chars)))


def _legend(fig: Figure, entries: dict[str, Any], ncol: int) -> float:
    """The one legend below the panels, with the most columns (at most ``ncol``) that fit the
    width; returns its height in inches (measured)."""
    if not entries:
        return 0.0
    renderer = fig.canvas.get_renderer()
    for n in range(min(ncol, len(entries)), 0, -1):
        legend = fig.legend(
            list(entries.values()),
            list(entries.keys()),
            loc="lower center",
            ncol=n,
            fontsize=FS_LEGEND,
            frameon=False,
            borderaxespad=0.3,
            handlelength=1.6,
            columnspacing=1.0,
        )
        box = legend.get_window_extent(renderer)
        if box.width <= 0.98 * fig.bbox.width or n == 1:
            return box.height / fig.dpi + 0.08
        legend.remove()
    raise AssertionError("unreachable")


def finish(fig: Figure, title: str, subtitle: str, ncol: int = 3) -> Figure:
    """Print size, title (``Fig. N — ...``), caption-like subtitle, one legend below the
    panels, layout.

    The legend collects the labelled artists of every axes (first occurrence of each label),
    so it never hides data.
    """
    rows, cols = _grid(fig)
    width = TEXT_WIDTH_IN if cols > 1 else COLUMN_WIDTH_IN
    panel = PANEL_IN["wide" if cols > 1 else "single" if rows == 1 else "stacked"]
    fig.set_size_inches(width, rows * panel + 2.0)
    for ax in fig.axes:
        if ax.get_yscale() == "log":
            _log_ticks(ax, panel)
        ax.tick_params(labelsize=FS_TICK, width=0.6, length=3.0)
        for line in ax.get_lines():
            line.set_linewidth(line.get_linewidth() * LINE_SCALE)
            line.set_markersize(line.get_markersize() * LINE_SCALE)
    seen: dict[str, Any] = {}
    for ax in fig.axes:
        for handle, label in zip(*ax.get_legend_handles_labels(), strict=True):
            seen.setdefault(label, handle)
    bottom_in = _legend(fig, seen, ncol)
    _fit_ylabels(fig, panel)
    title_lines = _wrap(title, _chars(width, FS_TITLE))
    lines = _wrap(subtitle, _chars(width, FS_SUBTITLE)) if subtitle else []
    title_in = 0.05 + 1.2 * FS_TITLE / 72 * len(title_lines)
    head_in = title_in + 0.04 + 1.2 * FS_SUBTITLE / 72 * len(lines) + 0.06
    height = head_in + rows * panel + XAXIS_IN + bottom_in
    fig.set_size_inches(width, height)
    fig.suptitle(
        "\n".join(title_lines), fontsize=FS_TITLE, y=1 - 0.05 / height, va="top"
    ).set_in_layout(False)
    if lines:
        fig.text(
            0.5,
            1 - (title_in + 0.04) / height,
            "\n".join(lines),
            ha="center",
            va="top",
            fontsize=FS_SUBTITLE,
            color="0.25",
        ).set_in_layout(False)
    tight_layout(fig, rect=(0, bottom_in / height, 1, 1 - head_in / height), h_pad=0.4, pad=0.3)
    return fig


def shade(
    axes: Sequence[Any], maneuvers: Sequence[tuple[float, float]], label: bool = True
) -> None:
    """Shade the maneuver windows on every axes (labelled once, on the first)."""
    for k, ax in enumerate(axes):
        for j, (a, b) in enumerate(maneuvers):
            lab = (
                f"maneuver (|n - 1| > {LOAD_DEVIATION:g})"
                if (label and k == 0 and j == 0)
                else None
            )
            ax.axvspan(a, b, color="0.88", lw=0, zorder=0, label=lab)
