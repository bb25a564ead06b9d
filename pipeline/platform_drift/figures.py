"""Figures 5-8 of the platform-drift paper, panel by panel, from errors.csv.

Panel (1): the trajectory (or, for the stationary vehicle, the no-drift case);
panels (2)-(4): position error against time for the channel-1, channel-3 and combined drift
cases, with the three curves (proposed_analytic, proposed_simulated, strapdown) and the
true-azimuth diagnostic (dashed) that shows which part of the error eqs. 33-36 model.
The values the paper prints for a panel (``config/published/platform_drift.yaml``, by its
``figure: "Fig. N (k)"``) are overlaid: the strapdown error at 2 h as a black diamond, the
crossover time as a dotted vertical line.

``python -m pipeline.platform_drift.figures --results-dir results/platform_drift
--out-dir results/platform_drift/figures``
"""

from __future__ import annotations

import argparse
import re
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402
import pandas as pd  # noqa: E402

from pipeline.figure_files import write_png_svg  # noqa: E402
from pipeline.platform_drift.quantities import FINAL_S  # noqa: E402
from pipeline.platform_drift.scenario import load_scenario  # noqa: E402
from pipeline.verdicts import load_published  # noqa: E402

__all__ = ["FIGURES", "plot_scenario", "run"]

DPI = 130
FIGURES = {
    "stationary": (5, "stationary vehicle"),
    "latitude_change": (6, "large latitude change"),
    "longitude_change": (7, "large longitude change"),
    "lat_lon_change": (8, "large latitude and longitude change"),
}
STYLE = {
    "proposed_analytic": dict(color="tab:blue", lw=1.6, label="proposed, analytic (eqs. 32/36)"),
    "proposed_simulated": dict(color="tab:green", lw=1.6, label="proposed, nonlinear simulation"),
    "strapdown": dict(color="tab:red", lw=1.6, label="strapdown"),
    "proposed_true_azimuth": dict(
        color="0.4", lw=1.2, ls="--", label="proposed, true azimuth rate (diagnostic)"
    ),
}
CASES = {"ch1": "channel-1 drift 0.01 deg/h", "ch3": "channel-3 drift 0.1 deg/h", "ch1_ch3": "both"}


def _panel(ax, frame: pd.DataFrame, case: str, title: str) -> None:
    for scheme, style in STYLE.items():
        cur = frame[(frame["case"] == case) & (frame["scheme"] == scheme)]
        if not cur.empty:
            ax.plot(cur["t_s"], cur["error_m"] / 1000.0, **style)
    ax.set_title(title, fontsize=10)
    ax.set_xlabel("time (s)")
    ax.set_ylabel("position error (km)")
    ax.grid(alpha=0.3)


def _published_marks(ax, items: Sequence[Mapping[str, Any]]) -> None:
    """Overlay the paper's printed values of one panel (km and s, as the axes)."""
    for item in items:
        value = float(item["value"])
        if item["quantity"] == "error_2h_m":
            km = value * (1000.0 if item.get("unit") == "km" else 1.0) / 1000.0
            ax.plot(
                [FINAL_S], [km], "D", color="k", ms=7, mfc="none", mew=1.6, zorder=5,
                label="published 2 h error (paper's text)",
            )  # fmt: skip
        elif item["quantity"] == "crossover_s":
            ax.axvline(value, color="k", ls=":", lw=1.3, label="published crossover (paper's text)")


def _panel_number(item: Mapping[str, Any]) -> tuple[int, int] | None:
    m = re.match(r"Fig\. (\d+) \((\d)\)", str(item.get("label", "")))
    return (int(m.group(1)), int(m.group(2))) if m else None


def plot_scenario(
    name: str,
    scenario_dir: Path,
    scenario_file: Path | None,
    published: Sequence[Mapping[str, Any]] = (),
):
    """The four-panel figure of one scenario; ``published``: the items of the published-values
    file (those whose ``label`` names this figure's number are overlaid on their panel)."""
    errors = pd.read_csv(scenario_dir / "errors.csv")
    diag_path = scenario_dir / "errors_diagnostic.csv"
    if diag_path.is_file():
        errors = pd.concat([errors, pd.read_csv(diag_path)], ignore_index=True)
    number, label = FIGURES.get(name, (None, name))
    fig, axes = plt.subplots(2, 2, figsize=(11, 7.5))
    ax1 = axes[0, 0]
    moving = False
    if scenario_file is not None and scenario_file.is_file():
        traj = load_scenario(scenario_file).trajectory()
        t = np.linspace(0.0, float(errors["t_s"].max()), 400)
        lat, lon = traj.latlon(t)
        moving = float(np.ptp(lat)) > 0 or float(np.ptp(lon)) > 0
        if moving:
            ax1.plot(np.rad2deg(lon), np.rad2deg(lat), color="k")
            ax1.plot(np.rad2deg(lon[0]), np.rad2deg(lat[0]), "o", color="tab:green", label="start")
            ax1.plot(np.rad2deg(lon[-1]), np.rad2deg(lat[-1]), "s", color="tab:red", label="end")
            ax1.set_xlabel("longitude (deg)")
            ax1.set_ylabel("latitude (deg)")
            ax1.set_title("(1) trajectory", fontsize=10)
            ax1.grid(alpha=0.3)
            ax1.legend(fontsize=8)
    if not moving:
        _panel(ax1, errors, "none", "(1) no error source")
    for ax, (case, text), k in zip(axes.flat[1:], CASES.items(), (2, 3, 4), strict=True):
        _panel(ax, errors, case, f"({k}) {text}")
        _published_marks(ax, [i for i in published if _panel_number(i) == (number, k)])
    legend: dict[str, Any] = {}
    for ax in axes.flat[1:]:
        for handle, text in zip(*ax.get_legend_handles_labels(), strict=True):
            legend.setdefault(text, handle)
    fig.legend(
        list(legend.values()), list(legend), loc="lower center", ncol=3, fontsize=9, frameon=False
    )
    head = f"Fig. {number}" if number else "Figure"
    fig.suptitle(f"{head}: position error, proposed scheme vs strapdown, {label}", fontsize=12)
    fig.tight_layout(rect=(0, 0.08, 1, 0.96))
    return fig


def _write(fig, png_path: Path) -> list[Path]:
    try:
        return write_png_svg(fig, png_path, DPI)
    finally:
        plt.close(fig)


def run(
    results_dir: str | Path,
    scenarios_dir: str | Path,
    out_dir: str | Path,
    published: str | Path | None = None,
) -> list[Path]:
    """Write fig<N>_<scenario>.png (and .svg) for every scenario directory with errors.csv,
    with the published values of ``published`` (the platform-drift published-values file)
    overlaid; returns the PNG paths."""
    results_dir, scenarios_dir, out_dir = Path(results_dir), Path(scenarios_dir), Path(out_dir)
    items = load_published(published)["items"] if published is not None else []
    written = []
    for d in sorted(p for p in results_dir.iterdir() if (p / "errors.csv").is_file()):
        number, _ = FIGURES.get(d.name, (0, d.name))
        fig = plot_scenario(d.name, d, scenarios_dir / f"{d.name}.yaml", items)
        written.append(_write(fig, out_dir / f"fig{number}_{d.name}.png")[0])
    return written


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--results-dir", default="results/platform_drift")
    ap.add_argument("--scenarios-dir", default="config/scenarios/platform_drift")
    ap.add_argument("--out-dir", default="results/platform_drift/figures")
    ap.add_argument("--published", default="config/published/platform_drift.yaml")
    a = ap.parse_args(argv)
    for p in run(a.results_dir, a.scenarios_dir, a.out_dir, a.published):
        print(p)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
