"""Verdicts of the platform-drift paper: published numbers and claims vs the error curves.

Reads ``config/published/platform_drift.yaml`` and, for every scenario folder of
``results/platform_drift/`` (``results_dir``), ``errors.csv``, ``errors_long.csv`` (the
24 h run, non-empty for the stationary scenario) and ``errors_diagnostic.csv``, with the
scenario's config (``scenarios_dir/<name>.yaml``: whether its vehicle is at rest decides where
the analytic curves hold); writes ``results/platform_drift/verdicts.csv``.
The rules are the shared engine's (:mod:`pipeline.verdicts`); this module binds the paper's
locator (:mod:`pipeline.platform_drift.quantities`) and claim tests
(:mod:`pipeline.platform_drift.claims`). The ``method`` column names the curve a row is about.
"""

from __future__ import annotations

import argparse
from pathlib import Path

import pandas as pd

from pipeline.platform_drift.claims import CLAIMS
from pipeline.platform_drift.quantities import check_item, locate, read_results
from pipeline.platform_drift.scenario import ROOT
from pipeline.verdicts import engine
from pipeline.verdicts.published import load_published as _load

__all__ = ["load_published", "main", "write_verdicts"]


def load_published(path: str | Path) -> dict:
    """The published file, validated with this paper's selectors and claim tests; in a
    repository layout (``<root>/config/published/``) every item selects one of the scenario
    files of ``<root>/config/scenarios/platform_drift/``."""
    scenarios_dir = Path(path).absolute().parents[1] / "scenarios" / "platform_drift"
    names = sorted(p.stem for p in scenarios_dir.glob("*.yaml")) or None
    return _load(path, claims=CLAIMS, check_item=lambda item: check_item(item, names))


#: the scenario configs
SCENARIOS_DIR = ROOT / "config" / "scenarios" / "platform_drift"


def write_verdicts(
    published_path: str | Path,
    results_dir: str | Path,
    out_path: str | Path,
    scenarios_dir: str | Path = SCENARIOS_DIR,
) -> pd.DataFrame:
    """Judge every published number and claim; write ``out_path`` atomically.

    ``results_dir``: ``results/platform_drift`` (one folder per scenario with errors.csv);
    ``scenarios_dir``: the folder of the scenario configs.
    """
    return engine.write_verdicts(
        published_path,
        out_path,
        locate=locate,
        claims=CLAIMS,
        read_results=lambda: read_results(results_dir, scenarios_dir),
        check_item=check_item,
    )


def main(argv: list[str] | None = None) -> int:
    ap = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    ap.add_argument("--published", default="config/published/platform_drift.yaml")
    ap.add_argument("--results-dir", default="results/platform_drift")
    ap.add_argument("--out", default="results/platform_drift/verdicts.csv")
    ap.add_argument("--scenarios-dir", default="config/scenarios/platform_drift")
    a = ap.parse_args(argv)
    table = write_verdicts(a.published, a.results_dir, a.out, a.scenarios_dir)
    print(table["verdict"].value_counts().to_dict())
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
