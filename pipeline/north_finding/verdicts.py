"""Verdicts of the north-finding paper: its published tables and claims vs our results.

Reads ``config/published/north_finding.yaml`` and, in the published scenario's folder
(``results/north_finding/<published_scenario>/``), ``estimates.csv``, ``mc_trials.csv``,
``error_budget.csv``, ``ranking.csv``, ``ranking_pairs.csv``, ``a2_scan.csv`` and
``provenance.json``, with the scenario file and the equation audit (which the causes of
failing rows cite); writes ``results/north_finding/verdicts.csv``. The rules are the shared
engine's (:mod:`pipeline.verdicts`); this module only binds the paper's locator
(:mod:`pipeline.north_finding.quantities`) and claim tests (:mod:`pipeline.north_finding.claims`).

Command line::

    python -m pipeline.north_finding.verdicts --published config/published/north_finding.yaml \\
        --results-dir results/north_finding/paper --out results/north_finding/verdicts.csv \\
        --scenario config/scenarios/north_finding/paper.yaml \\
        --audit results/north_finding/equation_audit.csv
"""

from __future__ import annotations

import argparse
from collections.abc import Sequence
from pathlib import Path

import pandas as pd

from pipeline.atomic import write_csv
from pipeline.north_finding.claims import CLAIMS
from pipeline.north_finding.columns import N_SENSITIVITY_COLUMNS
from pipeline.north_finding.quantities import check_item, locate, read_results
from pipeline.verdicts import engine
from pipeline.verdicts.published import load_published as _load

__all__ = ["load_published", "main", "write_verdicts"]


def load_published(path: str | Path) -> dict:
    """The published file, validated with this paper's selectors and claim tests."""
    return _load(path, claims=CLAIMS, check_item=check_item)


def write_verdicts(
    published_path: str | Path,
    results_dir: str | Path,
    out_path: str | Path,
    scenario: str | Path | None = None,
    audit: str | Path | None = None,
    sensitivity_out: str | Path | None = None,
) -> pd.DataFrame:
    """Judge every published number and claim; write ``out_path`` atomically.

    ``results_dir`` is the published scenario's folder (estimates.csv, mc_trials.csv,
    error_budget.csv, and the ranking files where present); ``scenario`` its scenario file and
    ``audit`` the equation audit, cited by the causes of failing rows (optional). The published
    file is validated before any results file is read. With ``sensitivity_out``, the verdicts
    judged again on reweighted N likelihoods (:mod:`pipeline.north_finding.n_sensitivity`) are
    written there (no rows where the results hold no N inference).
    """
    read_once: dict = {}

    def read() -> dict:
        from pipeline.north_finding.scenario import load_scenario

        read_once["results"] = read_results(
            results_dir,
            scenario=load_scenario(scenario) if scenario is not None else None,
            audit=audit,
            published=load_published(published_path),
        )
        return read_once["results"]

    table = engine.write_verdicts(
        published_path,
        out_path,
        locate=locate,
        claims=CLAIMS,
        read_results=read,
        check_item=check_item,
    )
    if sensitivity_out is not None:
        frame = _sensitivity(read_once["results"], table)
        write_csv(sensitivity_out, frame, N_SENSITIVITY_COLUMNS)
    return table


def _sensitivity(results: dict, judged: pd.DataFrame) -> pd.DataFrame:
    """The N-sensitivity table; ``judged``: the verdict table of ``results`` as written (the
    variant "as judged", not judged a second time)."""
    from pipeline.north_finding.causes import for_item
    from pipeline.north_finding.n_sensitivity import sensitivity

    if results["n_rows"].empty:
        return pd.DataFrame(columns=N_SENSITIVITY_COLUMNS)
    published = results["published"]
    return sensitivity(
        results,
        lambda r: engine.verdict_table(published, locate, CLAIMS, r),
        lambda item: for_item(item, results) is not None,
        judged,
    )


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog="python -m pipeline.north_finding.verdicts",
        description="Give every published number and claim a verdict (writes verdicts.csv).",
    )
    parser.add_argument("--published", default="config/published/north_finding.yaml")
    parser.add_argument("--results-dir", default="results/north_finding/paper")
    parser.add_argument("--out", default="results/north_finding/verdicts.csv")
    parser.add_argument("--scenario", default=None, help="the published scenario's file")
    parser.add_argument("--audit", default=None, help="equation_audit.csv")
    parser.add_argument("--sensitivity-out", default=None, help="n_sensitivity.csv")
    args = parser.parse_args(argv)
    table = write_verdicts(
        args.published, args.results_dir, args.out, args.scenario, args.audit,
        args.sensitivity_out,
    )  # fmt: skip
    print(f"{args.out}: {len(table)} verdicts {table['verdict'].value_counts().to_dict()}")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
