"""Figs 2-6 of the altimeter-attitude paper: the nominal trajectory and run 0's sensor outputs,
drawn from the scenario's ``truth.csv`` (one :class:`matplotlib.figure.Figure` each).

``maneuvers`` are the windows of :func:`pipeline.altimeter_attitude.maneuvers.maneuver_intervals`,
shaded; ``subtitle`` says what is drawn (scenario, which run).
"""

from __future__ import annotations

import numpy as np
import pandas as pd
from matplotlib.figure import Figure

from pipeline.altimeter_attitude.figures_style import (
    ANGLE_COLOR,
    C_COLOR,
    finish,
    new_figure,
    shade,
    style_axes,
)
from pipeline.altimeter_attitude.maneuvers import Maneuvers
from pipeline.altimeter_attitude.result_frames import truth_column

__all__ = [
    "fig2_third_row",
    "fig3_specific_force",
    "fig4_vertical_channel",
    "fig5_angular_rates",
    "fig6_roll_pitch",
]


def fig2_third_row(truth: pd.DataFrame, subtitle: str = "", maneuvers: Maneuvers = ()) -> Figure:
    """Fig. 2: C31, C32, C33 of the nominal trajectory vs time."""
    fig, (ax,) = new_figure(1, 5.6)
    shade([ax], maneuvers)
    labels = (
        r"$C_{31} = -\sin\theta$",
        r"$C_{32} = \sin\phi\,\cos\theta$",
        r"$C_{33} = \cos\phi\,\cos\theta$",
    )
    for col, color, label in zip(("c31", "c32", "c33"), C_COLOR, labels, strict=True):
        t, y = truth_column(truth, col)
        ax.plot(t, y, color=color, lw=1.6, label=label)
    ax.set_xlim(t[0], t[-1])
    style_axes(ax, "DCM element (dimensionless)", "time (s)")
    return finish(fig, "Fig. 2 — Third row of the DCM along the nominal trajectory", subtitle)


def fig3_specific_force(
    truth: pd.DataFrame, subtitle: str = "", maneuvers: Maneuvers = ()
) -> Figure:
    """Fig. 3: measured specific force f_x, f_y, f_z (run 0) and the load factor |f|/g."""
    fig, axes = new_figure(3, 8.6)
    shade(axes, maneuvers)
    for col, color, label in (
        ("accel_x_m_s2", C_COLOR[0], r"$f_x$ (forward)"),
        ("accel_y_m_s2", C_COLOR[1], r"$f_y$ (right)"),
    ):
        t, y = truth_column(truth, col)
        axes[0].plot(t, y, color=color, lw=0.6, label=label)
    t, y = truth_column(truth, "accel_z_m_s2")
    axes[1].plot(t, y, color=C_COLOR[2], lw=0.6, label=r"$f_z$ (down)")
    t, n = truth_column(truth, "load_factor")
    axes[2].axhline(1.0, color="k", lw=0.8, ls=":", label="steady flight (n = 1)")
    axes[2].plot(t, n, color="k", lw=1.4, label=r"load factor $n = |f|/g$ (truth)")
    axes[2].set_xlim(t[0], t[-1])
    style_axes(axes[0], r"$f_x$, $f_y$ (m/s$^2$)")
    style_axes(axes[1], r"$f_z$ (m/s$^2$)")
    style_axes(axes[2], "load factor (g)", "time (s)")
    return finish(
        fig,
        "Fig. 3 — Measured specific force (accelerometer outputs, body axes) and load factor",
        subtitle,
    )


def fig4_vertical_channel(
    truth: pd.DataFrame, subtitle: str = "", maneuvers: Maneuvers = ()
) -> Figure:
    """Fig. 4: V_d and h vs time; run 0's altimeter samples as faint dots."""
    fig, axes = new_figure(2, 7.0)
    shade(axes, maneuvers)
    t, vd = truth_column(truth, "v_d_m_s")
    axes[0].plot(t, vd, color="tab:blue", lw=1.6, label=r"$V_d$ (truth, positive down)")
    t_alt, alt = truth_column(truth, "altimeter_m")
    ok = np.isfinite(alt)
    axes[1].plot(
        t_alt[ok],
        alt[ok],
        ls="none",
        marker=".",
        ms=1.5,
        color="0.5",
        alpha=0.35,
        label="altimeter samples (run 0)",
    )
    t, h = truth_column(truth, "h_m")
    axes[1].plot(t, h, color="tab:red", lw=1.6, label="h (truth)")
    axes[1].set_xlim(t[0], t[-1])
    style_axes(axes[0], r"$V_d$ (m/s)")
    style_axes(axes[1], "altitude h (m)", "time (s)")
    return finish(fig, "Fig. 4 — Vertical channel: down velocity and altitude", subtitle)


def fig5_angular_rates(
    truth: pd.DataFrame, subtitle: str = "", maneuvers: Maneuvers = ()
) -> Figure:
    """Fig. 5: measured gyro rates (run 0), one panel per axis."""
    fig, axes = new_figure(3, 8.6)
    shade(axes, maneuvers)
    for ax, col, color, name in zip(
        axes,
        ("gyro_x_deg_s", "gyro_y_deg_s", "gyro_z_deg_s"),
        C_COLOR,
        ("x (roll rate p)", "y (pitch rate q)", "z (yaw rate r)"),
        strict=True,
    ):
        t, y = truth_column(truth, col)
        ax.plot(t, y, color=color, lw=0.6, label=f"gyro {name}")
        style_axes(ax, f"{name.split()[0]} rate (deg/s)")
    axes[-1].set_xlim(t[0], t[-1])
    style_axes(axes[-1], xlabel="time (s)")
    return finish(fig, "Fig. 5 — Measured angular rates (gyro outputs, body axes)", subtitle)


def fig6_roll_pitch(truth: pd.DataFrame, subtitle: str = "", maneuvers: Maneuvers = ()) -> Figure:
    """Fig. 6: true roll and pitch vs time."""
    fig, (ax,) = new_figure(1, 5.4)
    shade([ax], maneuvers)
    for angle in ("roll", "pitch"):
        t, y = truth_column(truth, f"{angle}_deg")
        ax.plot(t, y, color=ANGLE_COLOR[angle], lw=1.6, label=f"{angle} (truth)")
    ax.set_xlim(t[0], t[-1])
    style_axes(ax, "angle (deg)", "time (s)")
    return finish(fig, "Fig. 6 — Roll and pitch angles along the nominal trajectory", subtitle)
