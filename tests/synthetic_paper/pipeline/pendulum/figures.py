"""Fig. 1 of the synthetic paper: the period against the amplitude."""

from __future__ import annotations

from pathlib import Path

import pandas as pd
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from pipeline.figure_files import write_png_svg

__all__ = ["write_period_figure"]


def write_period_figure(periods_csv: str | Path, png: str | Path) -> list[Path]:
    frame = pd.read_csv(periods_csv)
    fig = Figure(figsize=(6, 4), dpi=100)
    FigureCanvasAgg(fig)
    ax = fig.add_subplot()
    ax.plot(frame["amplitude_deg"], frame["period_s"], "o-", label="eq. 1 integrated")
    ax.plot(frame["amplitude_deg"], frame["small_angle_s"], "--", label="eq. 3 (small angle)")
    ax.plot(frame["amplitude_deg"], frame["first_order_s"], ":", label="eq. 4 (derived form)")
    ax.set_xlabel("amplitude (deg)")
    ax.set_ylabel("period (s)")
    ax.set_title("Fig. 1: pendulum period against amplitude")
    ax.legend()
    return write_png_svg(fig, Path(png), dpi=100)
