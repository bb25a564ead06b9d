"""A figure the paper lacks: position error at 2 h against latitude, per scheme and drift case.

The stationary scenario is rerun at latitudes 0-80 deg (everything else as in its file); the
2 h error of each curve goes to ``results/platform_drift/latitude_sweep.csv``
(``lat_deg,case,scheme,error_2h_m``) and ``figures/fig9_latitude.png``, the numerical trouble
of every curve to ``latitude_sweep_trouble.csv`` (:data:`pipeline.trouble.TROUBLE_COLUMNS`;
at latitude 0 eq. 36 is undefined, so the analytic channel-3 value is empty there).

``python -m pipeline.platform_drift.sweep``
"""

from __future__ import annotations

import argparse
import dataclasses
from pathlib import Path

import matplotlib
import numpy as np
import pandas as pd
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure

from pipeline.atomic import write_csv
from pipeline.figure_files import write_png_svg
from pipeline.figure_layout import tight_layout
from pipeline.platform_drift.figures_style import DPI, RC, STYLE, WIDTH_IN, legend_below
from pipeline.platform_drift.run import simulate_errors
from pipeline.platform_drift.scenario import load_scenario

__all__ = ["SWEEP_COLUMNS", "LATITUDES_DEG", "sweep", "plot", "main"]

SWEEP_COLUMNS = ["lat_deg", "case", "scheme", "error_2h_m"]
LATITUDES_DEG = (0.0, 10.0, 20.0, 30.0, 40.0, 50.0, 60.0, 70.0, 80.0)
CASES = ("ch1", "ch3")


def sweep(
    scenario: str | Path,
    latitudes=LATITUDES_DEG,
    log=print,
    trouble: list[pd.DataFrame] | None = None,
) -> pd.DataFrame:
    """2 h error of every scheme for the stationary scenario moved to each latitude; given
    ``trouble`` (a list), appends the numerical trouble of every curve (run ``sweep``, case
    ``latitude <lat> deg, <drift case>``)."""
    sc = load_scenario(scenario)
    sc = dataclasses.replace(sc, cases=CASES)
    rows = []
    for lat in latitudes:
        moved = dataclasses.replace(sc, route=dataclasses.replace(sc.route, lat0=np.deg2rad(lat)))
        errors, diag, _ = simulate_errors(
            moved,
            7200.0,
            lambda m: None,
            trouble,
            "sweep",
            f"latitude {lat:g} deg, ",
            ground_speed=False,
        )
        both = pd.concat([errors, diag], ignore_index=True)
        final = both[both["t_s"] == both["t_s"].max()]
        for r in final.itertuples(index=False):
            rows.append(
                {"lat_deg": lat, "case": r.case, "scheme": r.scheme, "error_2h_m": r.error_m}
            )
        log(f"latitude sweep: {lat:g} deg done")
    return pd.DataFrame(rows, columns=SWEEP_COLUMNS)


def plot(frame: pd.DataFrame, png_path: str | Path) -> list[Path]:
    """Fig. 9 (not in the paper) of the latitude sweep, written to ``png_path`` and the SVG
    beside it; returns both paths."""
    with matplotlib.rc_context(RC):
        # an Agg canvas of its own (no pyplot: its import and figure state are not needed)
        fig = Figure(figsize=(WIDTH_IN, 2.6))
        FigureCanvasAgg(fig)
        axes = fig.subplots(1, 2)
        titles = {"ch1": "channel-1 drift 0.01 deg/h", "ch3": "channel-3 drift 0.1 deg/h"}
        for ax, case in zip(axes, CASES, strict=True):
            for scheme, style in STYLE.items():
                cur = frame[(frame["case"] == case) & (frame["scheme"] == scheme)]
                if not cur.empty:
                    # one point per latitude: every point marked (the curves' own markevery
                    # is for 2 h time series)
                    points = {"marker": "o", "ms": 2.5, **style, "markevery": None}
                    ax.plot(cur["lat_deg"], cur["error_2h_m"] / 1000.0, **points)
            ax.set_title(titles[case])
            ax.set_xlabel("latitude (deg)")
            ax.set_ylabel("position error at 2 h (km)")
            ax.grid(alpha=0.3)
        legend = legend_below(fig, axes[1:], ncol=2)
        fig.suptitle("Fig. 9 (not in the paper): error at 2 h against latitude, vehicle at rest")
        bottom = legend.get_window_extent(fig.canvas.get_renderer()).height / fig.bbox.height
        tight_layout(fig, rect=(0, bottom + 0.01, 1, 0.95), pad=0.3)
    return write_png_svg(fig, png_path, DPI)


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(description=__doc__)
    ap.add_argument("--scenario", default="config/scenarios/platform_drift/stationary.yaml")
    ap.add_argument("--out-csv", default="results/platform_drift/latitude_sweep.csv")
    ap.add_argument("--out-png", default="results/platform_drift/figures/fig9_latitude.png")
    a = ap.parse_args(argv)
    frame = sweep(a.scenario)
    write_csv(a.out_csv, frame, SWEEP_COLUMNS)
    plot(frame, a.out_png)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
