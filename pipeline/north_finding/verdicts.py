"""Verdicts of the north-finding paper: its published tables and claims vs our results.

Reads ``config/published/north_finding.yaml`` and, in the published scenario's folder
(``results/north_finding/<published_scenario>/``), ``estimates.csv``, ``mc_trials.csv`` and
``error_budget.csv``; writes ``results/north_finding/verdicts.csv``. The rules are the shared
engine's (:mod:`pipeline.verdicts`); this module only binds the paper's locator
(:mod:`pipeline.north_finding.quantities`) and claim tests (:mod:`pipeline.north_finding.claims`).

Command line::

    python -m pipeline.north_finding.verdicts --published config/published/north_finding.yaml \\
        --results-dir results/north_finding/paper --out results/north_finding/verdicts.csv
"""

from __future__ import annotations

import argparse
from collections.abc import Sequence
from pathlib import Path

import pandas as pd

from pipeline.north_finding.claims import CLAIMS
from pipeline.north_finding.quantities import check_item, locate, read_results
from pipeline.verdicts import engine
from pipeline.verdicts.published import load_published as _load

__all__ = ["load_published", "main", "write_verdicts"]


def load_published(path: str | Path) -> dict:
    """The published file, validated with this paper's selectors and claim tests."""
    return _load(path, claims=CLAIMS, check_item=check_item)


def write_verdicts(
    published_path: str | Path, results_dir: str | Path, out_path: str | Path
) -> pd.DataFrame:
    """Judge every published number and claim; write ``out_path`` atomically.

    ``results_dir`` is the published scenario's folder (estimates.csv, mc_trials.csv,
    error_budget.csv). The published file is validated before any results file is read.
    """
    return engine.write_verdicts(
        published_path,
        out_path,
        locate=locate,
        claims=CLAIMS,
        read_results=lambda: read_results(results_dir),
        check_item=check_item,
    )


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m pipeline.north_finding.verdicts",
        description="Give every published number and claim a verdict (writes verdicts.csv).",
    )
    parser.add_argument("--published", default="config/published/north_finding.yaml")
    parser.add_argument("--results-dir", default="results/north_finding/paper")
    parser.add_argument("--out", default="results/north_finding/verdicts.csv")
    args = parser.parse_args(argv)
    table = write_verdicts(args.published, args.results_dir, args.out)
    print(f"{args.out}: {len(table)} verdicts {table['verdict'].value_counts().to_dict()}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
