"""The figures step of the north-finding paper: Figs 1-5 (percent errors per method) and the
sensitivity figure (Fig. 6, not in the paper) of one scenario directory, each as PNG and SVG.

The figures are drawn by :mod:`pipeline.north_finding.figures_errors` (Figs 1-5, panels in
:mod:`pipeline.north_finding.figures_spec`) and :mod:`pipeline.north_finding.figures_sensitivity`
(Fig. 6), from the statistics of :mod:`pipeline.north_finding.percent_errors` and the published
values read by :mod:`pipeline.north_finding.published_items`.

Inputs (one scenario directory, the results contract of DESIGN.md):
``mc_trials.csv`` (or ``mc_trials.npy``, :mod:`pipeline.north_finding.trials_file`), ``estimates.csv``, ``sensitivity.csv`` (optional),
``provenance.json`` (optional key ``n_avg``), and the published values
``config/published/north_finding.yaml``.

CLI::

    python -m pipeline.north_finding.figures --scenario-dir results/north_finding/paper \\
        --published config/published/north_finding.yaml --out-dir results/north_finding/figures

Output is deterministic: PNG at 150 dpi without a Software stamp, SVG with a
fixed ``svg.hashsalt`` and no date, so reruns are byte-identical. Files are
written atomically.
"""

from __future__ import annotations

import argparse
import json
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import Any

import matplotlib
import pandas as pd
from matplotlib.figure import Figure

from pipeline import figure_files
from pipeline.north_finding.columns import ESTIMATE_COLUMNS, SENSITIVITY_COLUMNS
from pipeline.north_finding.figures_errors import plot_error_figure
from pipeline.north_finding.figures_sensitivity import plot_sensitivity_figure
from pipeline.north_finding.figures_spec import FIGURES, SENSITIVITY_STEM
from pipeline.north_finding.figures_style import DPI, RC
from pipeline.north_finding.percent_errors import (
    abs_error_quantiles,
    published_error_pct,
    real_abs_error_pct,
)
from pipeline.north_finding.published_items import load_published
from pipeline.north_finding.trials_file import read_trials

__all__ = ["read_provenance", "run", "figures_step", "main"]


def _read_csv(path: Path, columns: Sequence[str], optional: bool = False) -> pd.DataFrame:
    if not path.is_file():
        if optional:
            return pd.DataFrame(columns=list(columns))
        raise FileNotFoundError(f"{path}: required input is missing")
    df = pd.read_csv(path)
    missing = [c for c in columns if c not in df.columns]
    if missing:
        raise ValueError(f"{path}: missing columns {missing} (has {list(df.columns)})")
    return df


def read_provenance(scenario_dir: str | Path) -> dict[str, Any]:
    """``provenance.json`` of a scenario, or ``{}`` if absent."""
    p = Path(scenario_dir) / "provenance.json"
    return json.loads(p.read_text(encoding="utf-8")) if p.is_file() else {}


def _write(fig: Figure, out_dir: Path, stem: str) -> list[Path]:
    return figure_files.write_png_svg(fig, out_dir / f"{stem}.png", DPI)


def run(
    scenario_dir: str | Path,
    published: str | Path,
    out_dir: str | Path,
) -> list[Path]:
    """Write fig1..fig6 (``.png`` and ``.svg``) for one scenario into ``out_dir``.

    ``mc_trials.csv`` and ``estimates.csv`` are required; ``sensitivity.csv``
    and ``provenance.json`` are optional (Fig. 6 then says "not available" /
    omits the default-n_avg line). Returns the written paths.
    """
    scenario_dir, out_dir = Path(scenario_dir), Path(out_dir)
    items, _ = load_published(published)
    pub = published_error_pct(items, "real")
    trials = read_trials(scenario_dir, "mc_trials")
    if trials is None:
        raise FileNotFoundError(f"{scenario_dir / 'mc_trials.csv'}: required input is missing")
    estimates = _read_csv(scenario_dir / "estimates.csv", ESTIMATE_COLUMNS)
    sensitivity = _read_csv(scenario_dir / "sensitivity.csv", SENSITIVITY_COLUMNS, optional=True)
    n_avg = read_provenance(scenario_dir).get("n_avg")
    mc = abs_error_quantiles(trials)
    real = real_abs_error_pct(estimates, "real")
    written: list[Path] = []
    with matplotlib.rc_context(RC):
        for spec in FIGURES:
            written += _write(plot_error_figure(spec, mc, real, pub), out_dir, spec.stem)
        fig6 = plot_sensitivity_figure(
            sensitivity, pub, float(n_avg) if n_avg is not None else None
        )
        written += _write(fig6, out_dir, SENSITIVITY_STEM)
    return written


def figures_step(inputs: Mapping, outputs: Mapping, params: Mapping, log: Callable) -> None:
    """The ``figures`` step (:func:`pipeline.steps.run_step`): Figs. 1-5 of the paper and the
    sensitivity figure of the published scenario, exactly the declared PNG and SVG outputs."""
    out_dir = Path(outputs["png"][0]).parent
    written = run(Path(inputs["mc_trials"]).parent, inputs["published"], out_dir)
    got = sorted(str(p) for p in written)
    expected = sorted([*outputs["png"], *outputs["svg"]])
    if got != expected:
        raise ValueError(f"wrote {got}, but the rule declares {expected}")


def main(argv: Sequence[str] | None = None) -> int:
    """The command line (see the module docstring); returns the exit status."""
    ap = argparse.ArgumentParser(
        prog="python -m pipeline.north_finding.figures", description=__doc__.split("\n\n")[0]
    )
    ap.add_argument("--scenario-dir", default="results/north_finding/paper", type=Path)
    ap.add_argument("--published", default="config/published/north_finding.yaml", type=Path)
    ap.add_argument("--out-dir", default="results/north_finding/figures", type=Path)
    args = ap.parse_args(argv)
    for p in run(args.scenario_dir, args.published, args.out_dir):
        print(p)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
