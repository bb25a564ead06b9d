"""Figures 5-8 of the platform-drift paper, panel by panel, from errors.csv.

Panel (1): the trajectory (or, for the stationary vehicle, the no-drift case, in µm);
panels (2)-(4): position error (km) against time (s) for the channel-1, channel-3 and
combined drift cases, with the three curves (proposed_analytic, proposed_simulated,
strapdown) and the true-azimuth diagnostic (dotted) that shows which part of the error
eqs. 33-36 model. The simulated proposed curve is drawn last, dashed with open markers, so
that it stays visible where it lies on the strapdown curve (the finding of this
reproduction: with a channel-3 drift the two coincide); a panel below each gives their
difference in metres, on its own axis. In a scenario whose vehicle moves the analytic curve is
labelled as the stationary formula it is. The four panels stand side by side at the text width
(:mod:`pipeline.platform_drift.figures_style`), panel (1) over the height of both rows.
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
import numpy as np
import pandas as pd
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from pipeline.figure_files import write_png_svg
from pipeline.figure_layout import tight_layout
from pipeline.platform_drift.figures_style import DPI, RC, STYLE, WIDTH_IN, legend_below
from pipeline.platform_drift.quantities import FINAL_S
from pipeline.platform_drift.scenario import load_scenario
from pipeline.verdicts import load_published

__all__ = ["DPI", "FIGURES", "STYLE", "plot_scenario", "run"]

FIGURES = {
    "stationary": (5, "stationary vehicle"),
    "latitude_change": (6, "large latitude change"),
    "longitude_change": (7, "large longitude change"),
    "lat_lon_change": (8, "large latitude and longitude change"),
}
ANALYTIC_MOVING = "proposed, analytic eqs. 32/36\n(vehicle at rest, start latitude)"
CASES = {
    "ch1": "channel-1 drift\n0.01 deg/h",
    "ch3": "channel-3 drift\n0.1 deg/h",
    "ch1_ch3": "both drifts\n(channels 1 and 3)",
}
#: figure height (in) and the height of a main panel over its difference panel
HEIGHT_IN = 3.25
HEIGHT_RATIOS = (2.3, 1.0)


def _curve(frame: pd.DataFrame, case: str, scheme: str) -> pd.DataFrame:
    return frame[(frame["case"] == case) & (frame["scheme"] == scheme)].sort_values("t_s")


def _difference_panel(ax, frame: pd.DataFrame, case: str) -> None:
    """Simulated proposed minus strapdown error (m) against time, on its own axis."""
    sim, strap = _curve(frame, case, "proposed_simulated"), _curve(frame, case, "strapdown")
    ax.axhline(0.0, color=STYLE["strapdown"]["color"], lw=1.0, alpha=0.75)
    if not sim.empty and not strap.empty:
        diff = sim["error_m"].to_numpy() - strap.set_index("t_s")["error_m"].reindex(sim["t_s"])
        ax.plot(sim["t_s"], diff.to_numpy(), color=STYLE["proposed_simulated"]["color"], lw=1.0)
    ax.set_title("sim. − strapdown", fontsize=RC["legend.fontsize"], pad=2)
    ax.set_ylabel("difference (m)")
    ax.set_xlabel("time (s)")
    ax.grid(alpha=0.3)


def _panel(
    ax, frame: pd.DataFrame, case: str, title: str, unit: str = "km", moving: bool = False
) -> None:
    scale = {"km": 1000.0, "um": 1e-6}[unit]
    for scheme, style in STYLE.items():
        cur = _curve(frame, case, scheme)
        if not cur.empty:
            style = (
                {**style, "label": ANALYTIC_MOVING}
                if moving and scheme == "proposed_analytic"
                else style
            )
            ax.plot(cur["t_s"], cur["error_m"] / scale, **style)
    ax.set_title(title)
    ax.set_xlabel("time (s)")
    ax.set_ylabel(f"error ({'µm' if unit == 'um' else unit})")  # the title says "position"
    ax.grid(alpha=0.3)


def _published_marks(ax, items: Sequence[Mapping[str, Any]]) -> None:
    """Overlay the paper's printed values of one panel (km and s, as the axes)."""
    for item in items:
        value = float(item["value"])
        if item["quantity"] == "error_2h_m":
            km = value * (1000.0 if item.get("unit") == "km" else 1.0) / 1000.0
            ax.plot(
                [FINAL_S], [km], "D", color="k", ms=5, mfc="none", mew=1.1, zorder=5,
                label="published 2 h error\n(paper's text)",
            )  # fmt: skip
        elif item["quantity"] == "crossover_s":
            ax.axvline(
                value, color="k", ls=":", lw=1.0, label="published crossover\n(paper's text)"
            )


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
    with matplotlib.rc_context(RC):
        return _figure(errors, number, label, scenario_file, published)


def _figure(
    errors: pd.DataFrame,
    number: int | None,
    label: str,
    scenario_file: Path | None,
    published: Sequence[Mapping[str, Any]],
) -> Figure:
    fig = Figure(figsize=(WIDTH_IN, HEIGHT_IN), dpi=DPI)
    FigureCanvasAgg(fig)
    grid = fig.add_gridspec(2, 4, height_ratios=HEIGHT_RATIOS)
    ax1 = fig.add_subplot(grid[:, 0])
    moving = False
    if scenario_file is not None and scenario_file.is_file():
        traj = load_scenario(scenario_file).trajectory()
        t = np.linspace(0.0, float(errors["t_s"].max()), 400)
        lat, lon = traj.latlon(t)
        moving = float(np.ptp(lat)) > 0 or float(np.ptp(lon)) > 0
        if moving:
            ax1.plot(np.rad2deg(lon), np.rad2deg(lat), color="k", lw=1.0)
            ax1.plot(np.rad2deg(lon[0]), np.rad2deg(lat[0]), "o", color="tab:green", ms=4,
                     label="start")  # fmt: skip
            ax1.plot(np.rad2deg(lon[-1]), np.rad2deg(lat[-1]), "s", color="tab:red", ms=4,
                     label="end")  # fmt: skip
            ax1.set_xlabel("longitude (deg)")
            ax1.set_ylabel("latitude (deg)")
            ax1.set_title("(1) trajectory")
            ax1.grid(alpha=0.3)
            ax1.legend(loc="best", handletextpad=0.3)
    if not moving:
        _panel(ax1, errors, "none", "(1) no error source\n(integration floor)", unit="um")
    mains = [fig.add_subplot(grid[0, col]) for col in (1, 2, 3)]  # fig.axes[1:4]
    for ax, (case, text), k in zip(mains, CASES.items(), (2, 3, 4), strict=True):
        _panel(ax, errors, case, f"({k}) {text}", moving=moving)
        _published_marks(ax, [i for i in published if _panel_number(i) == (number, k)])
    for col, (ax, case) in enumerate(zip(mains, CASES, strict=True), 1):  # fig.axes[4:7]
        _difference_panel(fig.add_subplot(grid[1, col], sharex=ax), errors, case)
        ax.tick_params(labelbottom=False)  # the time axis is the difference panel's
        ax.set_xlabel("")
        ax.set_xticks([0, 3600, 7200])
    head = f"Fig. {number} (redrawn from our runs)" if number else "Figure"
    fig.suptitle(f"{head}: position error, proposed scheme vs strapdown, {label}")
    legend = legend_below(fig, mains, ncol=3)
    renderer = fig.canvas.get_renderer()
    bottom = legend.get_window_extent(renderer).height / fig.bbox.height + 0.01
    tight_layout(fig, rect=(0, bottom, 1, 1 - 0.2 / HEIGHT_IN), pad=0.3, w_pad=0.6, h_pad=0.3)
    return fig


def _write(fig: Figure, png_path: Path) -> list[Path]:
    return write_png_svg(fig, png_path, DPI)


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
