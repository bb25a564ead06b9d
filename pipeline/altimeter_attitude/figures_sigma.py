"""Figs 9 and 11 of the altimeter-attitude paper: the filter's own roll and pitch sigma (RMS over
runs) against the actual RMS error, and the NEES with its 95 % band over the Monte Carlo runs,
drawn from the scenario's ``timeseries.csv``.
"""

from __future__ import annotations

import pandas as pd
from matplotlib.figure import Figure

from pipeline.altimeter_attitude.figures_style import (
    ANGLE_COLOR,
    finish,
    new_figure,
    positive,
    shade,
    style_axes,
)
from pipeline.altimeter_attitude.maneuvers import Maneuvers
from pipeline.altimeter_attitude.metrics import nees_bounds
from pipeline.altimeter_attitude.result_frames import filter_curve

__all__ = ["fig9_lkf_sigma", "fig11_ukf_sigma"]


def _sigma_figure(
    ts: pd.DataFrame,
    filt: str,
    number: int,
    name: str,
    compare_with: int,
    subtitle: str,
    maneuvers: Maneuvers,
    n_runs: int | None,
) -> Figure:
    fig, axes = new_figure(3, 9.2)
    for ax in axes[:2]:
        ax.set_yscale("log")
    shade(axes, maneuvers)
    for ax, angle in zip(axes[:2], ("roll", "pitch"), strict=True):
        color = ANGLE_COLOR[angle]
        t, sig = filter_curve(ts, filt, f"{angle}_sigma_deg")
        _, err = filter_curve(ts, filt, f"{angle}_rms_deg")
        ax.plot(
            t, positive(sig), color=color, lw=1.8, label=f"{angle}: filter sigma (RMS over runs)"
        )
        ax.plot(
            t,
            positive(err),
            color="k",
            lw=1.1,
            ls="--",
            label=f"{angle}: actual RMS error (Fig. {compare_with})",
        )
        style_axes(ax, f"{angle} sigma, error (deg)")
    ax = axes[2]
    if n_runs is not None and n_runs >= 1:
        lo, hi = nees_bounds(n_runs, p=0.95)
        ax.axhspan(lo, hi, color="tab:olive", alpha=0.18, lw=0, label=f"95 % band, {n_runs} runs")
    ax.axhline(1.0, color="k", lw=0.8, ls=":")
    for angle in ("roll", "pitch"):
        t, nees = filter_curve(ts, filt, f"nees_{angle}")
        ax.plot(t, nees, color=ANGLE_COLOR[angle], lw=1.1, label=f"NEES {angle}")
    ax.set_xlim(t[0], t[-1])
    style_axes(ax, r"NEES, mean $e^2/\sigma^2$ (-)", "time (s)")
    return finish(
        fig,
        f"Fig. {number} — {name}: filter-estimated sigma of roll and pitch vs actual RMS error",
        subtitle,
    )


def fig9_lkf_sigma(
    timeseries: pd.DataFrame,
    subtitle: str = "",
    maneuvers: Maneuvers = (),
    n_runs: int | None = None,
) -> Figure:
    """Fig. 9: linear KF sigma (RMS over runs) with the Fig. 7 RMS error dashed, and NEES."""
    return _sigma_figure(timeseries, "linear_kf", 9, "Linear KF", 7, subtitle, maneuvers, n_runs)


def fig11_ukf_sigma(
    timeseries: pd.DataFrame,
    subtitle: str = "",
    maneuvers: Maneuvers = (),
    n_runs: int | None = None,
) -> Figure:
    """Fig. 11: UKF sigma (RMS over runs) with the Fig. 12 RMS error dashed, and NEES."""
    return _sigma_figure(timeseries, "ukf", 11, "UKF", 12, subtitle, maneuvers, n_runs)
