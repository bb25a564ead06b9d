"""Verdicts of the altimeter-attitude paper: published numbers and claims vs our Monte Carlo.

Reads ``config/published/altimeter_attitude.yaml``, the published scenario's YAML (its
transient and the bank that opens its after-bank window), in its results folder
``rms_summary.csv``, ``noise_free.csv``, ``run_rms.csv``, ``window_summary.csv``,
``window_run_rms.csv``, ``timeseries.csv``, ``truth.csv`` and ``ukf_tuning.csv``, and
``sweep.csv`` (the last two: evidence of the causes); writes ``results/altimeter_attitude/verdicts.csv``. The
rules are the shared engine's (:mod:`pipeline.verdicts`); this module binds the paper's locator
(:mod:`pipeline.altimeter_attitude.quantities`) and claim tests
(:mod:`pipeline.altimeter_attitude.claims`). ``method`` is the filter a verdict is about.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import pandas as pd

from pipeline.altimeter_attitude.claims import CLAIMS
from pipeline.altimeter_attitude.quantities import ScenarioResults, check_item, locate
from pipeline.verdicts import engine
from pipeline.verdicts.published import load_published as _load

__all__ = ["load_published", "main", "write_verdicts"]


def load_published(path: str | Path) -> dict:
    """The published file, validated with this paper's selectors and claim tests."""
    return _load(path, claims=CLAIMS, check_item=check_item)


def write_verdicts(
    published_path: str | Path,
    scenario_path: str | Path,
    results_dir: str | Path,
    out_path: str | Path,
    sweep_path: str | Path | None = None,
    tuning_path: str | Path | None = None,
) -> pd.DataFrame:
    """Judge every published number and claim; write ``out_path`` atomically.

    ``scenario_path``: the published scenario's YAML; ``results_dir``: its results folder;
    ``sweep_path``: sweep.csv and ``tuning_path``: ukf_tuning.csv (without them the causes
    carry no sweep or tuning evidence).
    """
    import math

    from pipeline.altimeter_attitude.scenario import load_scenario

    def read() -> ScenarioResults:
        sc = load_scenario(scenario_path)
        return ScenarioResults(
            results_dir,
            sc.transient,
            bank_deg=math.degrees(sc.after_bank),
            sweep=sweep_path,
            published=load_published(published_path),
            tuning=tuning_path,
        )

    return engine.write_verdicts(
        published_path,
        out_path,
        locate=locate,
        claims=CLAIMS,
        read_results=read,
        check_item=check_item,
    )


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--published", type=Path, default=Path("config/published/altimeter_attitude.yaml")
    )
    parser.add_argument(
        "--scenario", type=Path, required=True, help="the published scenario's YAML"
    )
    parser.add_argument("--results", type=Path, required=True, help="its results directory")
    parser.add_argument("--sweep", type=Path, default=None, help="sweep.csv (evidence of causes)")
    parser.add_argument(
        "--tuning", type=Path, default=None, help="ukf_tuning.csv (evidence of causes)"
    )
    parser.add_argument("--out", type=Path, required=True, help="verdicts.csv to write")
    args = parser.parse_args(argv)
    try:
        frame = write_verdicts(
            args.published, args.scenario, args.results, args.out, args.sweep, args.tuning
        )
    except (ValueError, OSError) as exc:
        print(f"error: {exc}")
        return 2
    print(frame["verdict"].value_counts().to_dict())
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
