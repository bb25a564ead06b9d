"""Figs 7, 8, 10 and 12 of the altimeter-attitude paper and the filter comparison (ours): Monte
Carlo RMS over runs at each output time, drawn from the scenario's ``timeseries.csv``.

Figs 7 and 12 overlay the RMS values printed in Sec. 6 (``published``, the dict of
:func:`pipeline.altimeter_attitude.published_rms.published_rms`) and, with ``summary``
(rms_summary.csv), this reproduction's one-number RMS in the legend.
"""

from __future__ import annotations

from collections.abc import Mapping

import numpy as np
import pandas as pd
from matplotlib.figure import Figure

from pipeline.altimeter_attitude.figures_style import (
    ANGLE_COLOR,
    C_COLOR,
    FILTER_STYLE,
    finish,
    new_figure,
    positive,
    shade,
    style_axes,
)
from pipeline.altimeter_attitude.maneuvers import Maneuvers
from pipeline.altimeter_attitude.published_rms import published_value
from pipeline.altimeter_attitude.result_frames import (
    filter_curve,
    filters_present,
    require_columns,
    summary_value,
)

__all__ = [
    "fig7_lkf_rms_error",
    "fig8_lkf_c_rms",
    "fig10_norm_error",
    "fig12_ukf_rms_error",
    "compare_filters",
]


def _rms_error_figure(
    ts: pd.DataFrame,
    filt: str,
    number: int,
    name: str,
    published: Mapping | None,
    subtitle: str,
    maneuvers: Maneuvers,
    summary: pd.DataFrame | None,
) -> Figure:
    fig, (ax,) = new_figure(1, 6.0)
    ax.set_yscale("log")
    shade([ax], maneuvers)
    for angle in ("roll", "pitch"):
        t, y = filter_curve(ts, filt, f"{angle}_rms_deg")
        ours = summary_value(summary, filt, f"{angle}_rms_deg")
        extra = f"; summary {ours:.2f} deg" if ours is not None else ""
        label = f"{angle}, ours (RMS over runs){extra}"
        ax.plot(t, positive(y), color=ANGLE_COLOR[angle], lw=1.6, label=label)
    for angle in ("roll", "pitch"):
        value = published_value(published, filt, f"{angle}_rms_deg")
        if value is not None:
            ax.axhline(
                value,
                color=ANGLE_COLOR[angle],
                lw=1.4,
                ls="--",
                label=f"{angle}: published (read from Fig. {number}) {value:g} deg",
            )
    ax.set_xlim(t[0], t[-1])
    style_axes(ax, "RMS error over runs (deg)", "time (s)")
    return finish(fig, f"Fig. {number} — {name}: RMS roll and pitch estimation error", subtitle)


def fig7_lkf_rms_error(
    timeseries: pd.DataFrame,
    published: Mapping | None = None,
    subtitle: str = "",
    maneuvers: Maneuvers = (),
    summary: pd.DataFrame | None = None,
) -> Figure:
    """Fig. 7: linear KF RMS roll/pitch error vs time, published values dashed."""
    return _rms_error_figure(
        timeseries, "linear_kf", 7, "Linear KF", published, subtitle, maneuvers, summary
    )


def fig12_ukf_rms_error(
    timeseries: pd.DataFrame,
    published: Mapping | None = None,
    subtitle: str = "",
    maneuvers: Maneuvers = (),
    summary: pd.DataFrame | None = None,
) -> Figure:
    """Fig. 12: UKF RMS roll/pitch error vs time, published values dashed."""
    return _rms_error_figure(timeseries, "ukf", 12, "UKF", published, subtitle, maneuvers, summary)


def fig8_lkf_c_rms(
    timeseries: pd.DataFrame, subtitle: str = "", maneuvers: Maneuvers = ()
) -> Figure:
    """Fig. 8: linear KF RMS error of c1, c2, c3 vs time."""
    fig, (ax,) = new_figure(1, 5.8)
    ax.set_yscale("log")
    shade([ax], maneuvers)
    for k, color in enumerate(C_COLOR, start=1):
        t, y = filter_curve(timeseries, "linear_kf", f"c{k}_rms")
        ax.plot(t, positive(y), color=color, lw=1.4, label=rf"$c_{k}$")
    ax.set_xlim(t[0], t[-1])
    style_axes(ax, "RMS error over runs (dimensionless)", "time (s)")
    return finish(fig, "Fig. 8 — Linear KF: RMS error of the DCM parameters c1, c2, c3", subtitle)


def fig10_norm_error(
    timeseries: pd.DataFrame, subtitle: str = "", maneuvers: Maneuvers = ()
) -> Figure:
    """Fig. 10: RMS of 1 - c^T c for linear_kf (and linear_kf_no_gamma, gyro_only if present)."""
    fig, (ax,) = new_figure(1, 6.0)
    ax.set_yscale("log")
    shade([ax], maneuvers)
    present = set(timeseries["filter"].unique()) if "filter" in timeseries else set()
    for filt, lw in (("linear_kf", 1.6), ("linear_kf_no_gamma", 1.0), ("gyro_only", 1.2)):
        if filt != "linear_kf" and filt not in present:
            continue
        t, y = filter_curve(timeseries, filt, "norm_error_rms")
        color, label = FILTER_STYLE[filt]
        if filt == "linear_kf_no_gamma":
            label += r" (k$\gamma$ term kept)"
        if np.nanmax(np.abs(y)) < 1e-12:
            label += ": round-off level"
        ax.plot(t, positive(y), color=color, lw=lw, label=label)
    ax.set_xlim(t[0], t[-1])
    style_axes(ax, r"RMS over runs of $1 - c^T c$ (dimensionless)", "time (s)")
    return finish(fig, r"Fig. 10 — Linear KF: RMS normalisation error $1 - c^T c$", subtitle)


def compare_filters(
    timeseries: pd.DataFrame, subtitle: str = "", maneuvers: Maneuvers = ()
) -> Figure:
    """RMS roll and pitch error vs time of every filter in timeseries.csv (two panels)."""
    require_columns(timeseries, ["t_s", "filter"], "timeseries")
    fig, axes = new_figure(2, 8.6)
    for ax in axes:
        ax.set_yscale("log")
    shade(axes, maneuvers)
    for ax, angle in zip(axes, ("roll", "pitch"), strict=True):
        for filt in filters_present(timeseries):
            color, label = FILTER_STYLE.get(filt, (None, filt))
            t, y = filter_curve(timeseries, filt, f"{angle}_rms_deg")
            main = filt in ("linear_kf", "ukf")  # the paper's two filters, drawn on top
            ax.plot(
                t,
                positive(y),
                color=color,
                lw=1.8 if main else 1.1,
                zorder=3 if main else 2,
                label=label,
            )
        style_axes(ax, f"RMS {angle} error (deg)")
    axes[-1].set_xlim(t[0], t[-1])
    style_axes(axes[-1], xlabel="time (s)")
    return finish(
        fig,
        "Comparison (ours, not in the paper) — RMS roll and pitch error of every filter",
        subtitle,
    )
