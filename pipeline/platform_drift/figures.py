"""Figures 5-8 of the platform-drift paper, panel by panel, from errors.csv.

Panel (1): the trajectory (or, for the stationary vehicle, the no-drift case, in µm);
panels (2)-(4): position error (km) against time (s) for the channel-1, channel-3 and
combined drift cases, with the three curves (proposed_analytic, proposed_simulated,
strapdown) and the true-azimuth diagnostic (dotted) that shows which part of the error
eqs. 33-36 model. The simulated proposed curve is drawn last, dashed with open markers, so
that it stays visible where it lies on the strapdown curve (the finding of this
reproduction: with a channel-3 drift the two coincide); an inset gives their difference in
metres. In a scenario whose vehicle moves the analytic curve is labelled as the stationary
formula it is.
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
#: drawing order: the simulated proposed curve last, on top of the strapdown one
STYLE = {
    "proposed_analytic": dict(color="tab:blue", lw=1.6, label="proposed, analytic (eqs. 32/36)"),
    "proposed_true_azimuth": dict(
        color="0.45", lw=1.3, ls=":", label="proposed, true azimuth rate (diagnostic)"
    ),
    "strapdown": dict(color="tab:red", lw=2.6, alpha=0.8, label="strapdown"),
    "proposed_simulated": dict(
        color="tab:purple", lw=1.4, ls="--", marker="o", mfc="none", ms=4.5, markevery=36,
        label="proposed, nonlinear simulation", zorder=4,
    ),
}  # fmt: skip
ANALYTIC_MOVING = "proposed, analytic eqs. 32/36 (for a vehicle at rest; start latitude)"
CASES = {"ch1": "channel-1 drift 0.01 deg/h", "ch3": "channel-3 drift 0.1 deg/h", "ch1_ch3": "both"}


def _curve(frame: pd.DataFrame, case: str, scheme: str) -> pd.DataFrame:
    return frame[(frame["case"] == case) & (frame["scheme"] == scheme)].sort_values("t_s")


#: inset boxes (axes fraction: x, y, width, height), tried in turn: upper left, lower right
INSET_BOXES = ((0.1, 0.56, 0.4, 0.3), (0.55, 0.1, 0.4, 0.3))


def _inset_box(ax) -> tuple[float, float, float, float]:
    """The first inset box no drawn curve passes through (else the least crossed one)."""
    ax.autoscale_view()
    to_axes = ax.transData + ax.transAxes.inverted()
    points = np.vstack([to_axes.transform(line.get_xydata()) for line in ax.lines])

    def crossed(box):
        x, y, w, h = box
        inside = (points[:, 0] >= x) & (points[:, 0] <= x + w)
        return int(np.sum(inside & (points[:, 1] >= y - 0.03) & (points[:, 1] <= y + h + 0.08)))

    return min(INSET_BOXES, key=crossed)


def _difference_inset(ax, frame: pd.DataFrame, case: str) -> None:
    """Inset: simulated proposed minus strapdown error (m), where the two are drawn."""
    sim, strap = _curve(frame, case, "proposed_simulated"), _curve(frame, case, "strapdown")
    if sim.empty or strap.empty:
        return
    diff = sim["error_m"].to_numpy() - strap.set_index("t_s")["error_m"].reindex(sim["t_s"])
    ins = ax.inset_axes(_inset_box(ax), zorder=6)
    white = {"facecolor": "white", "edgecolor": "none", "pad": 1.0}
    ins.axhline(0.0, color="tab:red", lw=1.0, alpha=0.8)
    ins.plot(sim["t_s"], diff.to_numpy(), color=STYLE["proposed_simulated"]["color"], lw=1.2)
    ins.set_title(
        "proposed simulated - strapdown (m)",
        fontsize=7,
        pad=2,
        bbox=white,
    )
    ins.set_xlabel("time (s)", fontsize=6, labelpad=1, bbox=white)
    ins.tick_params(labelsize=6, pad=1)
    ins.grid(alpha=0.3)


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
    ax.set_title(title, fontsize=10)
    ax.set_xlabel("time (s)")
    ax.set_ylabel(f"position error ({'µm' if unit == 'um' else unit})")
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
        _panel(ax1, errors, "none", "(1) no error source (integration floor)", unit="um")
    for ax, (case, text), k in zip(axes.flat[1:], CASES.items(), (2, 3, 4), strict=True):
        _panel(ax, errors, case, f"({k}) {text}", moving=moving)
        _published_marks(ax, [i for i in published if _panel_number(i) == (number, k)])
        _difference_inset(ax, errors, case)
    legend: dict[str, Any] = {}
    for ax in axes.flat[1:]:
        for handle, text in zip(*ax.get_legend_handles_labels(), strict=True):
            legend.setdefault(text, handle)
    fig.legend(
        list(legend.values()), list(legend), loc="lower center", ncol=3, fontsize=9, frameon=False
    )
    head = f"Fig. {number} (reproduced)" if number else "Figure"
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
