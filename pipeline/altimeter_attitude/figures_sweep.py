"""The sweep figure (ours, not in the paper): ``sweep.csv``, one panel per swept parameter, RMS
roll and pitch error of each filter against the parameter's value, the published values of
Sec. 6 as horizontal lines.

:func:`sweep_figure_step` is the workflow's ``sweep_figure`` step.
"""

from __future__ import annotations

from collections.abc import Callable, Mapping
from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from pipeline.altimeter_attitude.columns import ALTIMETER_FILTERS, SWEEP_COLUMNS
from pipeline.altimeter_attitude.figures_style import DPI, FILTER_STYLE, finish, style_axes
from pipeline.altimeter_attitude.published_rms import published_rms, published_value
from pipeline.altimeter_attitude.result_frames import require_columns
from pipeline.figure_files import write_png_svg

__all__ = ["SWEEP_PARAMETERS", "sweep_figure", "write_sweep", "sweep_figure_step"]

SWEEP_PARAMETERS = {
    "imu_rate_hz": "IMU sample rate (Hz)",
    "intensity": "maneuver intensity (x paper amplitudes)",
    "initial_error_deg": "initial roll/pitch error sigma (deg)",
}


def sweep_figure(
    frame: pd.DataFrame, published: Mapping | None = None, subtitle: str = ""
) -> Figure:
    """One panel per swept parameter: RMS roll (solid) and pitch (dashed) per filter vs value."""
    require_columns(frame, SWEEP_COLUMNS, "sweep")
    if frame.empty:
        raise ValueError("sweep: no rows")
    params = [p for p in SWEEP_PARAMETERS if p in set(frame["parameter"])]
    params += sorted(set(frame["parameter"]) - set(SWEEP_PARAMETERS))
    filters = [f for f in ALTIMETER_FILTERS if f in set(frame["filter"])]
    filters += sorted(set(frame["filter"]) - set(ALTIMETER_FILTERS))
    fig = Figure(figsize=(4.4 * len(params), 5.2), dpi=DPI)
    FigureCanvasAgg(fig)
    axes = list(fig.subplots(1, len(params), sharey=True, squeeze=False)[0])
    for ax, param in zip(axes, params, strict=True):
        ax.set_yscale("log")
        rows = frame[frame["parameter"] == param]
        for filt in filters:
            color, label = FILTER_STYLE.get(filt, (None, filt))
            cur = rows[rows["filter"] == filt].sort_values("value", kind="stable")
            if cur.empty:
                continue
            x = cur["value"].to_numpy(float)
            ax.plot(x, cur["roll_rms_deg"], color=color, lw=1.6, marker="o", label=f"{label}: roll")
            ax.plot(
                x,
                cur["pitch_rms_deg"],
                color=color,
                lw=1.6,
                ls="--",
                marker="s",
                label=f"{label}: pitch",
            )
            for angle, ls in (("roll", ":"), ("pitch", "-.")):
                value = published_value(published, filt, f"{angle}_rms_deg")
                if value is not None:
                    ax.axhline(
                        value,
                        color=color,
                        lw=1.2,
                        ls=ls,
                        alpha=0.8,
                        label=f"{label}, published: {angle} {value:g} deg",
                    )
        if param == "imu_rate_hz" and (rows["value"] > 0).all():
            ax.set_xscale("log")
            ticks = np.unique(rows["value"].to_numpy(float))
            ax.set_xticks(ticks, [f"{v:g}" for v in ticks])
            ax.minorticks_off()
            ax.grid(True, which="minor", alpha=0.15, axis="y")
        style_axes(
            ax, "RMS error (deg)" if ax is axes[0] else None, SWEEP_PARAMETERS.get(param, param)
        )
    if not subtitle:
        n = sorted({int(v) for v in frame["n_runs"]})
        runs = f"{n[0]}" if len(n) == 1 else f"{n[0]}-{n[-1]}"
        subtitle = (
            f"One parameter at a time around the paper scenario; {runs} Monte Carlo runs per "
            "point; RMS over runs and over time after the transient. Published values (Sec. 6) "
            "dotted (roll) and dash-dotted (pitch)."
        )
    return finish(
        fig,
        "Sweep (ours, not in the paper) — RMS roll/pitch error vs choices the paper leaves open",
        subtitle,
        ncol=2,
    )


def write_sweep(sweep_csv: Path, out_png: Path, published: dict | None) -> Path:
    """Write the sweep figure of ``sweep.csv`` to ``out_png`` (and its SVG beside it)."""
    return write_png_svg(sweep_figure(pd.read_csv(sweep_csv), published), out_png, DPI)[0]


def sweep_figure_step(inputs: Mapping, outputs: Mapping, params: Mapping, log: Callable) -> None:
    """The ``sweep_figure`` step (:func:`pipeline.steps.run_step`): ``inputs`` sweep and
    published, ``outputs`` png (the SVG goes beside it)."""
    from pipeline.config import load_yaml

    published = published_rms(load_yaml(inputs["published"]))
    write_sweep(Path(inputs["sweep"]), Path(outputs["png"]), published)
