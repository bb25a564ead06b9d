"""Run the N inference of the published scenario (:mod:`pipeline.north_finding.n_inference`).

The Monte Carlo runs at every N of the scenario's ``n_inference.n_avg`` on the main Monte
Carlo's standard normals (trial k seeded by ``SeedSequence([seed, scenario_key, k])``, as in
:mod:`pipeline.north_finding.run`), so the grid point equal to ``averaging.n_samples``
reproduces ``mc_trials.csv`` trial for trial. Writes ``n_profile.csv``, ``n_rows.csv`` and
``mc_trials_judged.csv`` (``.npy`` above :data:`pipeline.north_finding.trials_file.CSV_MAX_TRIALS`
trials: :mod:`pipeline.north_finding.trials_file`) into the scenario's results folder,
``n_robustness.csv``: the
inference rerun at every ``contamination_check`` and on the grid's powers of ten alone, and
``n_trouble.csv``: the numerical trouble of the estimators at every grid N (run
``n_inference``, case ``N=<n>``; :mod:`pipeline.north_finding.trouble`).

Usage: ``python -m pipeline.north_finding.run_inference --scenario
config/scenarios/north_finding/paper.yaml --published config/published/north_finding.yaml
--out-dir results/north_finding/paper``
"""

from __future__ import annotations

import argparse
import math
import sys
from functools import cache
from pathlib import Path

import pandas as pd

from pipeline.atomic import write_csv
from pipeline.config import ConfigError
from pipeline.north_finding import readings as rd
from pipeline.north_finding import trials_file as tf
from pipeline.north_finding.columns import (
    N_PROFILE_COLUMNS,
    N_ROBUSTNESS_COLUMNS,
    N_ROW_COLUMNS,
)
from pipeline.north_finding.judged_n import mixture_rank_of
from pipeline.north_finding.n_inference import fmt_grid, infer_frames
from pipeline.north_finding.run import _Runner, scenario_key, truth_values
from pipeline.north_finding.scenario import Scenario, load_scenario
from pipeline.north_finding.trouble import TROUBLE_COLUMNS, Trouble, n_case
from pipeline.verdicts.kinds import RANK_BAND

__all__ = ["OUTPUTS", "infer_scenario", "main"]

#: output key -> (file name, columns); mc_trials_judged (columns MC_JUDGED_COLUMNS) is written
#: by :func:`pipeline.north_finding.trials_file.write_trials`, as CSV or binary
OUTPUTS = {
    "n_profile": ("n_profile.csv", N_PROFILE_COLUMNS),
    "n_rows": ("n_rows.csv", N_ROW_COLUMNS),
    "n_robustness": ("n_robustness.csv", N_ROBUSTNESS_COLUMNS),
    "n_trouble": ("n_trouble.csv", TROUBLE_COLUMNS),
}


def infer_scenario(
    scenario: Scenario | str | Path, published: str | Path, out_dir: str | Path, log=print
) -> dict[str, Path]:
    """Infer N for the scenario's statistical rows of ``published``; write :data:`OUTPUTS`."""
    from pipeline.north_finding.verdicts import load_published

    sc = scenario if isinstance(scenario, Scenario) else load_scenario(scenario)
    if sc.kind != "simulated" or sc.n_inference is None:
        raise ConfigError(
            f"{sc.path}: n_inference: the N inference needs a simulated scenario with an "
            "n_inference block (n_avg, contamination)"
        )
    items = [i for i in load_published(published)["items"] if i["kind"] == "statistical"]
    runner, truth = _Runner(sc), truth_values(sc)
    n_pos = rd.simulation_positions(sc)[0].size
    z = rd.standard_normals(sc.seed, scenario_key(sc.name), sc.n_trials, n_pos)
    troubles: dict[int, pd.DataFrame] = {}

    @cache  # every grid N once, for every rerun
    def run(n: int):
        t = Trouble()
        out = runner.run((), z, n, trouble=t)
        troubles[n] = t.frame(out, "n_inference", n_case(n))
        return out

    def infer(grid: list[int], eps: float) -> dict:
        return infer_frames(run, None, items, grid, eps)  # the trials: written once below

    grid, eps = list(sc.n_inference["n_avg"]), float(sc.n_inference["contamination"])
    frames = infer(grid, eps)
    decades = [n for n in grid if 10 ** round(math.log10(n)) == n]
    checks = [eps, *sc.n_inference.get("contamination_check", [])]
    robust = [
        (name, e, frames if (name, e) == ("grid", eps) else infer(g, e))
        for name, g in (("grid", grid), ("decades", decades))
        if len(g) >= 2
        for e in checks
    ]
    frames["n_robustness"] = pd.DataFrame(
        [(name, e, *_failing(f)) for name, e, f in robust], columns=N_ROBUSTNESS_COLUMNS
    )
    frames["n_trouble"] = pd.concat([troubles[n] for n in sorted(troubles)], ignore_index=True)
    best = frames["n_profile"].loc[frames["n_profile"]["inferred"], "n_avg"]
    weighted = sorted(grid)  # mc_trials_judged holds every grid N
    log(
        f"{sc.name}: N inferred from {len(items)} statistical rows: "
        f"{', '.join(fmt_grid(int(n)) for n in best)}; rows judged on mixtures over "
        f"{', '.join(fmt_grid(int(n)) for n in weighted)}"
    )
    out_dir = Path(out_dir)
    written = {
        key: write_csv(out_dir / name, frames[key], columns)
        for key, (name, columns) in OUTPUTS.items()
    }
    fmt = tf.trials_format(sc.n_trials, sc.trials_file)
    written["mc_trials_judged"] = tf.write_trials(
        out_dir, "mc_trials_judged", {n: run(n) for n in grid}, truth, fmt
    )
    return written


def _failing(frames: dict) -> tuple[int, int, str]:
    """(N inferred from all rows, count and ids of the rows outside the band in their
    leave-one-out mixture)."""
    prof, rows = frames["n_profile"], frames["n_rows"]
    lo, hi = RANK_BAND
    rank = {i: mixture_rank_of(r) for i, r in rows.groupby("id", sort=False)}
    bad = [i for i, r in rank.items() if not lo <= r <= hi]
    return int(prof.loc[prof["inferred"], "n_avg"].iloc[0]), len(bad), ";".join(bad)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--scenario", required=True, type=Path, help="scenario YAML file")
    parser.add_argument("--published", required=True, type=Path, help="published values YAML")
    parser.add_argument("--out-dir", required=True, type=Path, help="results directory to write")
    args = parser.parse_args(argv)
    try:
        infer_scenario(
            args.scenario,
            args.published,
            args.out_dir,
            log=lambda m: print(m, file=sys.stderr, flush=True),
        )
    except ValueError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
