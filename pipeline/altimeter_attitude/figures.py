"""The figures step of the altimeter-attitude paper: Figs 2-12 and the comparison of all filters
(ours) for one scenario directory, each as PNG and SVG.

The figures themselves are drawn by :mod:`~pipeline.altimeter_attitude.figures_truth` (Figs 2-6,
``truth.csv``), :mod:`~pipeline.altimeter_attitude.figures_rms` (Figs 7, 8, 10, 12 and the
comparison, ``timeseries.csv``), :mod:`~pipeline.altimeter_attitude.figures_sigma` (Figs 9, 11)
and :mod:`~pipeline.altimeter_attitude.figures_sweep` (``fig_sweep.png``, ``sweep.csv``).
:func:`write_all` writes the figures of one scenario directory with the subtitles that say
what is drawn; :func:`figures_step` is the workflow's ``figures`` step. PNGs carry no Software
stamp and no date, so reruns are byte-identical; files are written atomically.

CLI::

    python -m pipeline.altimeter_attitude.figures --scenario-dir results/altimeter_attitude/paper \\
        --out-dir results/altimeter_attitude/figures \\
        [--published config/published/altimeter_attitude.yaml] \\
        [--sweep results/altimeter_attitude/sweep.csv] [--figures fig7_lkf_rms_error.png ...]
"""

from __future__ import annotations

import argparse
import json
import sys
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path

import numpy as np
import pandas as pd
from matplotlib.figure import Figure

from pipeline.altimeter_attitude.columns import (
    RMS_SUMMARY_COLUMNS,
    TIMESERIES_COLUMNS,
    TRUTH_COLUMNS,
)
from pipeline.altimeter_attitude.figures_rms import (
    compare_filters,
    fig7_lkf_rms_error,
    fig8_lkf_c_rms,
    fig10_norm_error,
    fig12_ukf_rms_error,
)
from pipeline.altimeter_attitude.figures_sigma import fig9_lkf_sigma, fig11_ukf_sigma
from pipeline.altimeter_attitude.figures_style import DPI
from pipeline.altimeter_attitude.figures_sweep import write_sweep
from pipeline.altimeter_attitude.figures_truth import (
    fig2_third_row,
    fig3_specific_force,
    fig4_vertical_channel,
    fig5_angular_rates,
    fig6_roll_pitch,
)
from pipeline.altimeter_attitude.maneuvers import LOAD_DEVIATION, maneuver_intervals
from pipeline.altimeter_attitude.published_rms import published_rms
from pipeline.altimeter_attitude.result_frames import require_columns
from pipeline.altimeter_attitude.workflow import FIGURES, SWEEP_FIGURE
from pipeline.figure_files import write_png_svg

__all__ = ["write_all", "figures_step", "main"]


def _read_optional_summary(scenario_dir: Path) -> pd.DataFrame | None:
    path = scenario_dir / "rms_summary.csv"
    if not path.is_file():
        return None
    summary = pd.read_csv(path)
    require_columns(summary, RMS_SUMMARY_COLUMNS, str(path))
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
    require_columns(truth, TRUTH_COLUMNS, str(scenario_dir / "truth.csv"))
    require_columns(ts, TIMESERIES_COLUMNS, str(scenario_dir / "timeseries.csv"))
    summary = _read_optional_summary(scenario_dir)
    scenario, n_runs = _context(scenario_dir, summary)
    makers = _figure_makers(truth, ts, published, summary, scenario, n_runs)
    return [p for name in names for p in write_png_svg(makers[name](), out_dir / name, DPI)]


def figures_step(inputs: Mapping, outputs: Mapping, params: Mapping, log: Callable) -> None:
    """The ``figures`` step (:func:`pipeline.steps.run_step`): Figs. 2-12 of the paper and the
    filter comparison of the published scenario, exactly the declared PNG and SVG outputs."""
    from pipeline.config import load_yaml

    published = published_rms(load_yaml(inputs["published"]))
    pngs = [Path(p).name for p in outputs["png"]]
    out_dir = Path(outputs["png"][0]).parent
    written = write_all(Path(inputs["truth"]).parent, out_dir, published, names=pngs)
    expected = sorted([*outputs["png"], *outputs["svg"]])
    if sorted(map(str, written)) != expected:
        raise ValueError(f"wrote {sorted(map(str, written))}, declared {expected}")


def main(argv: list[str] | None = None) -> int:
    """The command line (see the module docstring); returns the exit status."""
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
