"""The look shared by the altimeter_attitude figures: sizes, fonts, colours, the style of each
filter, and the drawing steps every figure uses (a new figure, styled axes, readable log ticks,
shaded maneuvers, the title, subtitle and one legend below the panels).

Figures are built on :class:`matplotlib.figure.Figure` with an Agg canvas (no pyplot state),
so drawing one figure never changes another.
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

DPI = 130
WIDTH_IN = 9.0
FS_TITLE = 12.0
FS_SUBTITLE = 9.5
FS_LABEL = 10.0
FS_TICK = 9.0
FS_LEGEND = 9.0

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
    """A figure of :data:`WIDTH_IN` x ``height`` inches with ``nrows`` stacked axes."""
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


def _log_ticks(ax: Any) -> None:
    """Readable log-axis labels: 0.05, 0.1, 0.2, 0.5, 1, 2 over a few decades, 10^k beyond."""
    lo, hi = ax.get_ylim()
    if lo <= 0 or hi <= lo:
        return
    if math.log10(hi / lo) <= 3.5:
        ax.yaxis.set_major_locator(LogLocator(base=10.0, subs=(1.0, 2.0, 5.0)))
        ax.yaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
    else:
        ax.yaxis.set_major_locator(LogLocator(base=10.0, numticks=12))
        ax.yaxis.set_major_formatter(LogFormatterSciNotation())
    ax.yaxis.set_minor_formatter(NullFormatter())


def finish(fig: Figure, title: str, subtitle: str, ncol: int = 3) -> Figure:
    """Title (``Fig. N — ...``), caption-like subtitle, one legend below the panels, layout.

    The legend collects the labelled artists of every axes (first occurrence of each label),
    so it never hides data.
    """
    for ax in fig.axes:
        if ax.get_yscale() == "log":
            _log_ticks(ax)
    seen: dict[str, Any] = {}
    for ax in fig.axes:
        for handle, label in zip(*ax.get_legend_handles_labels(), strict=True):
            seen.setdefault(label, handle)
    height = fig.get_figheight()
    bottom = 0.0
    if seen:
        # columns that fit the width: handle + ~0.068 in per character at 9 pt
        col_width = 0.75 + 0.068 * max(len(label) for label in seen)
        fit = max(1, int(fig.get_figwidth() // col_width))
        ncol = min(ncol, len(seen), fit)
        fig.legend(
            list(seen.values()),
            list(seen.keys()),
            loc="lower center",
            ncol=ncol,
            fontsize=FS_LEGEND,
            frameon=False,
            borderaxespad=0.3,
        )
        bottom = (0.12 + 0.21 * math.ceil(len(seen) / ncol)) / height
    lines = textwrap.wrap(subtitle, width=int(13.5 * fig.get_figwidth())) if subtitle else []
    fig.suptitle(title, fontsize=FS_TITLE, y=1 - 0.08 / height, va="top").set_in_layout(False)
    if lines:
        fig.text(
            0.5,
            1 - 0.36 / height,
            "\n".join(lines),
            ha="center",
            va="top",
            fontsize=FS_SUBTITLE,
            color="0.25",
        ).set_in_layout(False)
    top = 1 - (0.42 + 0.17 * len(lines)) / height
    fig.tight_layout(rect=(0, bottom, 1, top), h_pad=0.6)
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
