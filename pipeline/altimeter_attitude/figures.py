"""Figures 2-12 of the altimeter-attitude paper, a comparison of all filters, and the sweep.

One function per figure; each takes DataFrames (the results contract of
``pipeline.columns``) and returns a :class:`matplotlib.figure.Figure`:

* Figs 2-6 (the nominal trajectory and run 0's sensor outputs) from ``truth.csv``;
* Figs 7-12 (Monte Carlo RMS over runs at each output time) from ``timeseries.csv``; Figs 7
  and 12 overlay the RMS values printed in Sec. 6 (``published``, the dict of
  :func:`published_rms`);
* ``fig_compare_filters.png`` (ours): RMS roll/pitch error of every filter, maneuvers shaded;
* ``fig_sweep.png`` (ours): ``sweep.csv``, one panel per swept parameter.

:func:`write_all` writes the PNGs of one scenario directory, :func:`write_sweep` the sweep
figure. PNGs carry no Software stamp and no date, so reruns are byte-identical; files are
written atomically.

CLI::

    python -m pipeline.altimeter_attitude.figures --scenario-dir results/altimeter_attitude/paper \\
        --out-dir results/altimeter_attitude/figures \\
        [--published config/published/altimeter_attitude.yaml] \\
        [--sweep results/altimeter_attitude/sweep.csv] [--figures fig7_lkf_rms_error.png ...]
"""

from __future__ import annotations

import argparse
import json
import math
import sys
import textwrap
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import Any

import matplotlib

matplotlib.use("Agg")
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402
from matplotlib.backends.backend_agg import FigureCanvasAgg  # noqa: E402
from matplotlib.figure import Figure  # noqa: E402
from matplotlib.ticker import (  # noqa: E402
    FuncFormatter,
    LogFormatterSciNotation,
    LogLocator,
    NullFormatter,
)

from pipeline.altimeter_attitude.columns import (  # noqa: E402
    ALTIMETER_FILTERS,
    RMS_SUMMARY_COLUMNS,
    SWEEP_COLUMNS,
    TIMESERIES_COLUMNS,
    TRUTH_COLUMNS,
)
from pipeline.altimeter_attitude.workflow import FIGURES, SWEEP_FIGURE
from pipeline.figure_files import write_png_svg  # noqa: E402

__all__ = [
    "FIGURES",
    "SWEEP_FIGURE",
    "LOAD_DEVIATION",
    "published_rms",
    "maneuver_intervals",
    "fig2_third_row",
    "fig3_specific_force",
    "fig4_vertical_channel",
    "fig5_angular_rates",
    "fig6_roll_pitch",
    "fig7_lkf_rms_error",
    "fig8_lkf_c_rms",
    "fig9_lkf_sigma",
    "fig10_norm_error",
    "fig11_ukf_sigma",
    "fig12_ukf_rms_error",
    "compare_filters",
    "sweep_figure",
    "write_all",
    "write_sweep",
    "main",
]

DPI = 130
WIDTH_IN = 9.0
FS_TITLE = 12.0
FS_SUBTITLE = 9.5
FS_LABEL = 10.0
FS_TICK = 9.0
FS_LEGEND = 9.0
# maneuvers are shaded where the truth load factor |f|/g is off 1 by more than this (the same
# threshold as claim C6 of config/published/altimeter_attitude.yaml)
LOAD_DEVIATION = 0.05

RMS_QUANTITIES = ("roll_rms_deg", "pitch_rms_deg")
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
SWEEP_PARAMETERS = {
    "imu_rate_hz": "IMU sample rate (Hz)",
    "intensity": "maneuver intensity (x paper amplitudes)",
    "initial_error_deg": "initial roll/pitch error sigma (deg)",
}


# ---------------------------------------------------------------------------------------------
# published values


def published_rms(data: Any) -> dict[str, dict[str, float]]:
    """The published RMS values ``{filter: {roll_rms_deg: v, pitch_rms_deg: v}}``.

    ``data`` is the parsed ``config/published/altimeter_attitude.yaml`` (the shared format of
    pipeline.verdicts): entries under the top-level ``items:`` list, e.g. ``{id: V1.lkf_roll,
    kind: approximate, quantity: roll_rms_deg, value: "0.16", select: {filter: linear_kf},
    ...}``. Entries of the roll/pitch RMS quantities are kept, others are skipped. A missing
    field, a non-numeric or non-positive value, or a duplicated (filter, quantity) raises
    ValueError naming the entry.
    """
    if not isinstance(data, Mapping) or "items" not in data:
        raise ValueError("published values: no top-level 'items:' list")
    items = data["items"]
    if not isinstance(items, list):
        raise ValueError(f"published values: 'items' is {type(items).__name__}, not a list")
    out: dict[str, dict[str, float]] = {}
    for i, entry in enumerate(items):
        if not isinstance(entry, Mapping):
            raise ValueError(f"published entry items[{i}] is not a mapping: {entry!r}")
        name = f"{entry['id']!r}" if entry.get("id") is not None else f"items[{i}]"
        select = entry.get("select") if isinstance(entry.get("select"), Mapping) else {}
        flat = {**entry, "filter": select.get("filter")}
        missing = [k for k in ("quantity", "value", "filter") if flat.get(k) is None]
        if missing:
            raise ValueError(f"published entry {name}: missing field(s) {missing}")
        if entry["quantity"] not in RMS_QUANTITIES:
            continue
        filt, qty, text = flat["filter"], entry["quantity"], entry["value"]
        if not isinstance(filt, str) or not filt:
            raise ValueError(f"published entry {name}: filter = {filt!r} is not a filter name")
        try:
            value = float(text) if isinstance(text, str) else None
        except ValueError:
            value = None
        if value is None:
            raise ValueError(
                f"published entry {name}: value = {text!r} is not a number string (the printed "
                "digits, e.g. '0.16')"
            )
        if not math.isfinite(value) or value <= 0:
            raise ValueError(f"published entry {name}: value = {text!r} must be finite and > 0")
        if qty in out.get(filt, {}):
            raise ValueError(f"published entry {name}: {filt}.{qty} is given twice")
        out.setdefault(filt, {})[qty] = value
    return out


def _published(published: Mapping | None, filt: str, qty: str) -> float | None:
    """published[filt][qty] as a float, None if the dict or the entry is absent."""
    if published is None:
        return None
    if not isinstance(published, Mapping):
        raise ValueError(
            f"published must be a dict filter -> {{quantity: value}}, got {published!r}"
        )
    entry = published.get(filt)
    if entry is None:
        return None
    if not isinstance(entry, Mapping):
        raise ValueError(f"published[{filt!r}] must be a dict quantity -> value, got {entry!r}")
    value = entry.get(qty)
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
        raise ValueError(f"published[{filt!r}][{qty!r}] = {value!r} is not a finite number")
    return float(value)


# ---------------------------------------------------------------------------------------------
# helpers


def _require(frame: pd.DataFrame, columns: Sequence[str], what: str) -> None:
    missing = [c for c in columns if c not in frame.columns]
    if missing:
        raise ValueError(f"{what}: missing columns {missing}")


def _curve(ts: pd.DataFrame, filt: str, column: str) -> tuple[np.ndarray, np.ndarray]:
    """(t, y) of one filter's column of timeseries.csv, sorted by time."""
    _require(ts, ["t_s", "filter", column], "timeseries")
    rows = ts[ts["filter"] == filt]
    if rows.empty:
        present = sorted(ts["filter"].unique())
        raise ValueError(f"timeseries: no rows for filter {filt!r} (present: {present})")
    rows = rows.sort_values("t_s", kind="stable")
    return rows["t_s"].to_numpy(float), rows[column].to_numpy(float)


def _positive(y: np.ndarray) -> np.ndarray:
    """y with non-positive values as NaN (gaps on a log axis instead of clipped spikes)."""
    y = np.asarray(y, dtype=float)
    return np.where(y > 0, y, np.nan)


def _new_figure(nrows: int, height: float, sharex: bool = True) -> tuple[Figure, list]:
    fig = Figure(figsize=(WIDTH_IN, height), dpi=DPI)
    FigureCanvasAgg(fig)
    axes = fig.subplots(nrows, 1, sharex=sharex, squeeze=False)[:, 0]
    return fig, list(axes)


def _style_axes(ax, ylabel: str | None = None, xlabel: str | None = None) -> None:
    ax.grid(True, which="major", alpha=0.4)
    if ax.get_yscale() == "log":
        ax.grid(True, which="minor", alpha=0.15)
    ax.tick_params(labelsize=FS_TICK)
    if ylabel is not None:
        ax.set_ylabel(ylabel, fontsize=FS_LABEL)
    if xlabel is not None:
        ax.set_xlabel(xlabel, fontsize=FS_LABEL)


def _log_ticks(ax) -> None:
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


def _finish(fig: Figure, title: str, subtitle: str, ncol: int = 3) -> Figure:
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


def maneuver_intervals(
    truth: pd.DataFrame, threshold: float = LOAD_DEVIATION
) -> list[tuple[float, float]]:
    """Time intervals (t_start, t_end) where |load_factor - 1| > threshold."""
    _require(truth, ["t_s", "load_factor"], "truth")
    frame = truth.sort_values("t_s", kind="stable")
    t = frame["t_s"].to_numpy(float)
    flag = np.abs(frame["load_factor"].to_numpy(float) - 1.0) > threshold
    edges = np.diff(np.concatenate([[0], flag.astype(np.int8), [0]]))
    starts, ends = np.flatnonzero(edges == 1), np.flatnonzero(edges == -1) - 1
    return [(float(t[a]), float(t[b])) for a, b in zip(starts, ends, strict=True)]


def _shade(axes, maneuvers: Sequence[tuple[float, float]], label: bool = True) -> None:
    for k, ax in enumerate(axes):
        for j, (a, b) in enumerate(maneuvers):
            lab = (
                f"maneuver (|n - 1| > {LOAD_DEVIATION:g})"
                if (label and k == 0 and j == 0)
                else None
            )
            ax.axvspan(a, b, color="0.88", lw=0, zorder=0, label=lab)


def _truth_col(truth: pd.DataFrame, column: str) -> tuple[np.ndarray, np.ndarray]:
    _require(truth, ["t_s", column], "truth")
    frame = truth.sort_values("t_s", kind="stable")
    return frame["t_s"].to_numpy(float), frame[column].to_numpy(float)


# ---------------------------------------------------------------------------------------------
# Figs 2-6: nominal trajectory and run 0's sensor outputs (truth.csv)


def fig2_third_row(truth: pd.DataFrame, subtitle: str = "", maneuvers=()) -> Figure:
    """Fig. 2: C31, C32, C33 of the nominal trajectory vs time."""
    fig, (ax,) = _new_figure(1, 5.6)
    _shade([ax], maneuvers)
    labels = (
        r"$C_{31} = -\sin\theta$",
        r"$C_{32} = \sin\phi\,\cos\theta$",
        r"$C_{33} = \cos\phi\,\cos\theta$",
    )
    for col, color, label in zip(("c31", "c32", "c33"), C_COLOR, labels, strict=True):
        t, y = _truth_col(truth, col)
        ax.plot(t, y, color=color, lw=1.6, label=label)
    ax.set_xlim(t[0], t[-1])
    _style_axes(ax, "DCM element (dimensionless)", "time (s)")
    return _finish(fig, "Fig. 2 — Third row of the DCM along the nominal trajectory", subtitle)


def fig3_specific_force(truth: pd.DataFrame, subtitle: str = "", maneuvers=()) -> Figure:
    """Fig. 3: measured specific force f_x, f_y, f_z (run 0) and the load factor |f|/g."""
    fig, axes = _new_figure(3, 8.6)
    _shade(axes, maneuvers)
    for col, color, label in (
        ("accel_x_m_s2", C_COLOR[0], r"$f_x$ (forward)"),
        ("accel_y_m_s2", C_COLOR[1], r"$f_y$ (right)"),
    ):
        t, y = _truth_col(truth, col)
        axes[0].plot(t, y, color=color, lw=0.6, label=label)
    t, y = _truth_col(truth, "accel_z_m_s2")
    axes[1].plot(t, y, color=C_COLOR[2], lw=0.6, label=r"$f_z$ (down)")
    t, n = _truth_col(truth, "load_factor")
    axes[2].axhline(1.0, color="k", lw=0.8, ls=":", label="steady flight (n = 1)")
    axes[2].plot(t, n, color="k", lw=1.4, label=r"load factor $n = |f|/g$ (truth)")
    axes[2].set_xlim(t[0], t[-1])
    _style_axes(axes[0], r"$f_x$, $f_y$ (m/s$^2$)")
    _style_axes(axes[1], r"$f_z$ (m/s$^2$)")
    _style_axes(axes[2], "load factor (g)", "time (s)")
    return _finish(
        fig,
        "Fig. 3 — Measured specific force (accelerometer outputs, body axes) and load factor",
        subtitle,
    )


def fig4_vertical_channel(truth: pd.DataFrame, subtitle: str = "", maneuvers=()) -> Figure:
    """Fig. 4: V_d and h vs time; run 0's altimeter samples as faint dots."""
    fig, axes = _new_figure(2, 7.0)
    _shade(axes, maneuvers)
    t, vd = _truth_col(truth, "v_d_m_s")
    axes[0].plot(t, vd, color="tab:blue", lw=1.6, label=r"$V_d$ (truth, positive down)")
    t_alt, alt = _truth_col(truth, "altimeter_m")
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
    t, h = _truth_col(truth, "h_m")
    axes[1].plot(t, h, color="tab:red", lw=1.6, label="h (truth)")
    axes[1].set_xlim(t[0], t[-1])
    _style_axes(axes[0], r"$V_d$ (m/s)")
    _style_axes(axes[1], "altitude h (m)", "time (s)")
    return _finish(fig, "Fig. 4 — Vertical channel: down velocity and altitude", subtitle)


def fig5_angular_rates(truth: pd.DataFrame, subtitle: str = "", maneuvers=()) -> Figure:
    """Fig. 5: measured gyro rates (run 0), one panel per axis."""
    fig, axes = _new_figure(3, 8.6)
    _shade(axes, maneuvers)
    for ax, col, color, name in zip(
        axes,
        ("gyro_x_deg_s", "gyro_y_deg_s", "gyro_z_deg_s"),
        C_COLOR,
        ("x (roll rate p)", "y (pitch rate q)", "z (yaw rate r)"),
        strict=True,
    ):
        t, y = _truth_col(truth, col)
        ax.plot(t, y, color=color, lw=0.6, label=f"gyro {name}")
        _style_axes(ax, f"{name.split()[0]} rate (deg/s)")
    axes[-1].set_xlim(t[0], t[-1])
    _style_axes(axes[-1], xlabel="time (s)")
    return _finish(fig, "Fig. 5 — Measured angular rates (gyro outputs, body axes)", subtitle)


def fig6_roll_pitch(truth: pd.DataFrame, subtitle: str = "", maneuvers=()) -> Figure:
    """Fig. 6: true roll and pitch vs time."""
    fig, (ax,) = _new_figure(1, 5.4)
    _shade([ax], maneuvers)
    for angle in ("roll", "pitch"):
        t, y = _truth_col(truth, f"{angle}_deg")
        ax.plot(t, y, color=ANGLE_COLOR[angle], lw=1.6, label=f"{angle} (truth)")
    ax.set_xlim(t[0], t[-1])
    _style_axes(ax, "angle (deg)", "time (s)")
    return _finish(fig, "Fig. 6 — Roll and pitch angles along the nominal trajectory", subtitle)


# ---------------------------------------------------------------------------------------------
# Figs 7-12: Monte Carlo statistics (timeseries.csv)


def _summary_value(summary: pd.DataFrame | None, filt: str, column: str) -> float | None:
    if summary is None or column not in summary.columns:
        return None
    rows = summary[summary["filter"] == filt]
    if rows.empty or not np.isfinite(rows[column].iloc[0]):
        return None
    return float(rows[column].iloc[0])


def _rms_error_figure(
    ts: pd.DataFrame,
    filt: str,
    number: int,
    name: str,
    published: Mapping | None,
    subtitle: str,
    maneuvers,
    summary: pd.DataFrame | None,
) -> Figure:
    fig, (ax,) = _new_figure(1, 6.0)
    ax.set_yscale("log")
    _shade([ax], maneuvers)
    for angle in ("roll", "pitch"):
        t, y = _curve(ts, filt, f"{angle}_rms_deg")
        ours = _summary_value(summary, filt, f"{angle}_rms_deg")
        extra = f"; summary {ours:.2f} deg" if ours is not None else ""
        label = f"{angle}, ours (RMS over runs){extra}"
        ax.plot(t, _positive(y), color=ANGLE_COLOR[angle], lw=1.6, label=label)
    for angle in ("roll", "pitch"):
        value = _published(published, filt, f"{angle}_rms_deg")
        if value is not None:
            ax.axhline(
                value,
                color=ANGLE_COLOR[angle],
                lw=1.4,
                ls="--",
                label=f"{angle}: published (read from Fig. {number}) {value:g} deg",
            )
    ax.set_xlim(t[0], t[-1])
    _style_axes(ax, "RMS error over runs (deg)", "time (s)")
    return _finish(fig, f"Fig. {number} — {name}: RMS roll and pitch estimation error", subtitle)


def fig7_lkf_rms_error(
    timeseries: pd.DataFrame,
    published: Mapping | None = None,
    subtitle: str = "",
    maneuvers=(),
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
    maneuvers=(),
    summary: pd.DataFrame | None = None,
) -> Figure:
    """Fig. 12: UKF RMS roll/pitch error vs time, published values dashed."""
    return _rms_error_figure(timeseries, "ukf", 12, "UKF", published, subtitle, maneuvers, summary)


def fig8_lkf_c_rms(timeseries: pd.DataFrame, subtitle: str = "", maneuvers=()) -> Figure:
    """Fig. 8: linear KF RMS error of c1, c2, c3 vs time."""
    fig, (ax,) = _new_figure(1, 5.8)
    ax.set_yscale("log")
    _shade([ax], maneuvers)
    for k, color in enumerate(C_COLOR, start=1):
        t, y = _curve(timeseries, "linear_kf", f"c{k}_rms")
        ax.plot(t, _positive(y), color=color, lw=1.4, label=rf"$c_{k}$")
    ax.set_xlim(t[0], t[-1])
    _style_axes(ax, "RMS error over runs (dimensionless)", "time (s)")
    return _finish(fig, "Fig. 8 — Linear KF: RMS error of the DCM parameters c1, c2, c3", subtitle)


def _sigma_figure(
    ts: pd.DataFrame,
    filt: str,
    number: int,
    name: str,
    compare_with: int,
    subtitle: str,
    maneuvers,
    n_runs: int | None,
) -> Figure:
    fig, axes = _new_figure(3, 9.2)
    for ax in axes[:2]:
        ax.set_yscale("log")
    _shade(axes, maneuvers)
    for ax, angle in zip(axes[:2], ("roll", "pitch"), strict=True):
        color = ANGLE_COLOR[angle]
        t, sig = _curve(ts, filt, f"{angle}_sigma_deg")
        _, err = _curve(ts, filt, f"{angle}_rms_deg")
        ax.plot(
            t, _positive(sig), color=color, lw=1.8, label=f"{angle}: filter sigma (RMS over runs)"
        )
        ax.plot(
            t,
            _positive(err),
            color="k",
            lw=1.1,
            ls="--",
            label=f"{angle}: actual RMS error (Fig. {compare_with})",
        )
        _style_axes(ax, f"{angle} sigma, error (deg)")
    ax = axes[2]
    if n_runs is not None and n_runs >= 1:
        from scipy.stats import chi2

        lo, hi = chi2.ppf([0.025, 0.975], n_runs) / n_runs
        ax.axhspan(lo, hi, color="tab:olive", alpha=0.18, lw=0, label=f"95 % band, {n_runs} runs")
    ax.axhline(1.0, color="k", lw=0.8, ls=":")
    for angle in ("roll", "pitch"):
        t, nees = _curve(ts, filt, f"nees_{angle}")
        ax.plot(t, nees, color=ANGLE_COLOR[angle], lw=1.1, label=f"NEES {angle}")
    ax.set_xlim(t[0], t[-1])
    _style_axes(ax, r"NEES, mean $e^2/\sigma^2$ (-)", "time (s)")
    return _finish(
        fig,
        f"Fig. {number} — {name}: filter-estimated sigma of roll and pitch vs actual RMS error",
        subtitle,
    )


def fig9_lkf_sigma(
    timeseries: pd.DataFrame, subtitle: str = "", maneuvers=(), n_runs: int | None = None
) -> Figure:
    """Fig. 9: linear KF sigma (RMS over runs) with the Fig. 7 RMS error dashed, and NEES."""
    return _sigma_figure(timeseries, "linear_kf", 9, "Linear KF", 7, subtitle, maneuvers, n_runs)


def fig11_ukf_sigma(
    timeseries: pd.DataFrame, subtitle: str = "", maneuvers=(), n_runs: int | None = None
) -> Figure:
    """Fig. 11: UKF sigma (RMS over runs) with the Fig. 12 RMS error dashed, and NEES."""
    return _sigma_figure(timeseries, "ukf", 11, "UKF", 12, subtitle, maneuvers, n_runs)


def fig10_norm_error(timeseries: pd.DataFrame, subtitle: str = "", maneuvers=()) -> Figure:
    """Fig. 10: RMS of 1 - c^T c for linear_kf (and linear_kf_no_gamma, gyro_only if present)."""
    fig, (ax,) = _new_figure(1, 6.0)
    ax.set_yscale("log")
    _shade([ax], maneuvers)
    present = set(timeseries["filter"].unique()) if "filter" in timeseries else set()
    for filt, lw in (("linear_kf", 1.6), ("linear_kf_no_gamma", 1.0), ("gyro_only", 1.2)):
        if filt != "linear_kf" and filt not in present:
            continue
        t, y = _curve(timeseries, filt, "norm_error_rms")
        color, label = FILTER_STYLE[filt]
        if filt == "linear_kf_no_gamma":
            label += r" (k$\gamma$ term kept)"
        if np.nanmax(np.abs(y)) < 1e-12:
            label += ": round-off level"
        ax.plot(t, _positive(y), color=color, lw=lw, label=label)
    ax.set_xlim(t[0], t[-1])
    _style_axes(ax, r"RMS over runs of $1 - c^T c$ (dimensionless)", "time (s)")
    return _finish(fig, r"Fig. 10 — Linear KF: RMS normalisation error $1 - c^T c$", subtitle)


# ---------------------------------------------------------------------------------------------
# our additions


def _filters_present(ts: pd.DataFrame) -> list[str]:
    present = list(dict.fromkeys(ts["filter"]))
    return [f for f in ALTIMETER_FILTERS if f in present] + sorted(
        f for f in present if f not in ALTIMETER_FILTERS
    )


def compare_filters(timeseries: pd.DataFrame, subtitle: str = "", maneuvers=()) -> Figure:
    """RMS roll and pitch error vs time of every filter in timeseries.csv (two panels)."""
    _require(timeseries, ["t_s", "filter"], "timeseries")
    fig, axes = _new_figure(2, 8.6)
    for ax in axes:
        ax.set_yscale("log")
    _shade(axes, maneuvers)
    for ax, angle in zip(axes, ("roll", "pitch"), strict=True):
        for filt in _filters_present(timeseries):
            color, label = FILTER_STYLE.get(filt, (None, filt))
            t, y = _curve(timeseries, filt, f"{angle}_rms_deg")
            main = filt in ("linear_kf", "ukf")  # the paper's two filters, drawn on top
            ax.plot(
                t,
                _positive(y),
                color=color,
                lw=1.8 if main else 1.1,
                zorder=3 if main else 2,
                label=label,
            )
        _style_axes(ax, f"RMS {angle} error (deg)")
    axes[-1].set_xlim(t[0], t[-1])
    _style_axes(axes[-1], xlabel="time (s)")
    return _finish(
        fig,
        "Comparison (ours, not in the paper) — RMS roll and pitch error of every filter",
        subtitle,
    )


def sweep_figure(
    frame: pd.DataFrame, published: Mapping | None = None, subtitle: str = ""
) -> Figure:
    """One panel per swept parameter: RMS roll (solid) and pitch (dashed) per filter vs value."""
    _require(frame, SWEEP_COLUMNS, "sweep")
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
                value = _published(published, filt, f"{angle}_rms_deg")
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
        _style_axes(
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
    return _finish(
        fig,
        "Sweep (ours, not in the paper) — RMS roll/pitch error vs choices the paper leaves open",
        subtitle,
        ncol=2,
    )


# ---------------------------------------------------------------------------------------------
# writing


def _read_optional_summary(scenario_dir: Path) -> pd.DataFrame | None:
    path = scenario_dir / "rms_summary.csv"
    if not path.is_file():
        return None
    summary = pd.read_csv(path)
    _require(summary, RMS_SUMMARY_COLUMNS, str(path))
    return summary


def _context(scenario_dir: Path, summary: pd.DataFrame | None) -> tuple[str, int | None]:
    """Scenario name and number of Monte Carlo runs (provenance.json / rms_summary.csv)."""
    name, n_runs = scenario_dir.name, None
    prov = scenario_dir / "provenance.json"
    if prov.is_file():
        data = json.loads(prov.read_text(encoding="utf-8"))
        name = str(data.get("scenario", name))
        n_runs = data.get("seeds", {}).get("n_runs")
    if summary is not None and not summary.empty:
        n_runs = int(summary["n_runs"].max())
    return name, (int(n_runs) if n_runs is not None else None)


def _figure_makers(
    truth: pd.DataFrame,
    ts: pd.DataFrame,
    published: Mapping | None,
    summary: pd.DataFrame | None,
    scenario: str,
    n_runs: int | None,
) -> dict[str, Callable[[], Figure]]:
    man = maneuver_intervals(truth)
    t = np.sort(ts["t_s"].unique())
    rate = f"{1.0 / float(np.median(np.diff(t))):g} Hz" if len(t) > 1 else "one time"
    runs = f"{n_runs} Monte Carlo runs" if n_runs is not None else "Monte Carlo runs"
    shade = f"shaded: maneuvers, |n - 1| > {LOAD_DEVIATION:g}"
    nominal = f"Scenario '{scenario}': nominal trajectory (truth); {shade}."
    sensors = f"Scenario '{scenario}': sensor outputs of run 0 (noisy, one realisation); {shade}."
    stats = f"Scenario '{scenario}', {runs}: RMS over runs at each output time ({rate}); {shade}."
    rms_note = " 'summary': RMS over runs and over time after the transient (rms_summary.csv)."
    rms_stats = stats + (rms_note if summary is not None else "")
    return {
        "fig2_third_row.png": lambda: fig2_third_row(truth, nominal, man),
        "fig3_specific_force.png": lambda: fig3_specific_force(truth, sensors, man),
        "fig4_vertical_channel.png": lambda: fig4_vertical_channel(
            truth, nominal.replace("(truth)", "(truth) and run 0's altimeter"), man
        ),
        "fig5_angular_rates.png": lambda: fig5_angular_rates(truth, sensors, man),
        "fig6_roll_pitch.png": lambda: fig6_roll_pitch(truth, nominal, man),
        "fig7_lkf_rms_error.png": lambda: fig7_lkf_rms_error(
            ts, published, rms_stats, man, summary
        ),
        "fig8_lkf_c_rms.png": lambda: fig8_lkf_c_rms(ts, stats, man),
        "fig9_lkf_sigma.png": lambda: fig9_lkf_sigma(ts, stats, man, n_runs),
        "fig10_norm_error.png": lambda: fig10_norm_error(ts, stats, man),
        "fig11_ukf_sigma.png": lambda: fig11_ukf_sigma(ts, stats, man, n_runs),
        "fig12_ukf_rms_error.png": lambda: fig12_ukf_rms_error(
            ts, published, rms_stats, man, summary
        ),
        "fig_compare_filters.png": lambda: compare_filters(ts, stats, man),
    }


def write_all(
    scenario_dir: Path,
    out_dir: Path,
    published: dict | None,
    names: Sequence[str] | None = None,
) -> list[Path]:
    """Write the scenario figures (``names``, PNG file names, default all of FIGURES) into
    ``out_dir``, each as PNG and SVG; returns the paths written (PNG, SVG per figure).

    Reads ``truth.csv`` and ``timeseries.csv`` of ``scenario_dir`` (and, when present,
    ``rms_summary.csv`` for the summary RMS in the legends of Figs 7/12 and
    ``provenance.json`` for the scenario name and number of runs).
    """
    scenario_dir, out_dir = Path(scenario_dir), Path(out_dir)
    names = list(FIGURES if names is None else names)
    unknown = [n for n in names if n not in FIGURES]
    if unknown:
        raise ValueError(f"unknown figure name(s) {unknown}; known: {FIGURES}")
    truth = pd.read_csv(scenario_dir / "truth.csv")
    ts = pd.read_csv(scenario_dir / "timeseries.csv")
    _require(truth, TRUTH_COLUMNS, str(scenario_dir / "truth.csv"))
    _require(ts, TIMESERIES_COLUMNS, str(scenario_dir / "timeseries.csv"))
    summary = _read_optional_summary(scenario_dir)
    scenario, n_runs = _context(scenario_dir, summary)
    makers = _figure_makers(truth, ts, published, summary, scenario, n_runs)
    return [p for name in names for p in write_png_svg(makers[name](), out_dir / name, DPI)]


def write_sweep(sweep_csv: Path, out_png: Path, published: dict | None) -> Path:
    """Write the sweep figure of ``sweep.csv`` to ``out_png`` (and its SVG beside it)."""
    return write_png_svg(sweep_figure(pd.read_csv(sweep_csv), published), out_png, DPI)[0]


def main(argv: list[str] | None = None) -> int:
    from pipeline.config import load_yaml

    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument("--scenario-dir", type=Path, required=True, help="results of one scenario")
    ap.add_argument("--out-dir", type=Path, required=True, help="where the PNGs go")
    ap.add_argument("--published", type=Path, default=None, help="published-values YAML")
    ap.add_argument("--sweep", type=Path, default=None, help="sweep.csv (adds fig_sweep.png)")
    ap.add_argument(
        "--figures", nargs="+", default=None, metavar="NAME", help=f"subset of {FIGURES}"
    )
    a = ap.parse_args(argv)
    try:
        published = published_rms(load_yaml(a.published)) if a.published is not None else None
        written = write_all(a.scenario_dir, a.out_dir, published, a.figures)
        if a.sweep is not None:
            written.append(write_sweep(a.sweep, a.out_dir / SWEEP_FIGURE, published))
    except (ValueError, OSError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    for p in written:
        print(p)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
