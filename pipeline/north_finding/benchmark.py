"""Benchmark (issue 15): the north_finding Monte Carlo and its consumers at 1e3, 1e4, 1e5 trials.

``python -m pipeline.north_finding.benchmark [--scenario config/scenarios/north_finding/paper.yaml]
[--sizes 1000,10000,100000] [--steps simulate,infer_n,verdicts,figures,report]`` (part of
``make bench``). For each size, a copy of the scenario with ``monte_carlo.n_trials`` raised to it
(same name, so its seeds are the scenario's: at the scenario's own size the results are its
own) runs every step into a temporary directory, each step in a fresh child process, as the
workflow runs them: ``simulate`` (:func:`pipeline.north_finding.run.run_scenario`), ``infer_n``
(:func:`pipeline.north_finding.run_inference.infer_scenario`), ``verdicts``
(:func:`pipeline.north_finding.verdicts.write_verdicts`, without the equation audit), ``figures``
(:func:`pipeline.north_finding.figures.run`) and ``report`` (the scenario's report section,
:func:`pipeline.north_finding.report_results.scenario_section`). Printed per step: CPU seconds of
the step in the child (``time.process_time``, imports excluded), the child's peak RSS and the
CPU seconds per 1,000 trials (flat when the cost is linear in trials); then the size of the
per-trial files (``mc_trials``, ``mc_trials_judged``: CSV or binary,
:mod:`pipeline.north_finding.trials_file`) and the CPU seconds to read them. CPU time, not wall
time, so a loaded machine inflates the figures less; they are of this machine and run, not
results (nothing is written under results/ or reports/).
"""

from __future__ import annotations

import argparse
import json
import resource
import subprocess
import sys
import tempfile
import time
from collections.abc import Sequence
from pathlib import Path

import yaml

__all__ = ["STEPS", "main", "run_child"]

MODULE = "pipeline.north_finding.benchmark"
PUBLISHED = "config/published/north_finding.yaml"
STEPS = ("simulate", "infer_n", "verdicts", "figures", "report")
#: the per-trial results the steps write and read (file stem)
TRIAL_FILES = ("mc_trials", "mc_trials_judged")


def _step(step: str, scenario: Path, work: Path) -> None:
    """Run one step of the workflow on the scenario copy ``scenario`` into ``work``."""
    d = work / scenario.stem
    if step == "simulate":
        from pipeline.north_finding.run import run_scenario

        run_scenario(scenario, d, log=lambda m: None)
    elif step == "infer_n":
        from pipeline.north_finding.run_inference import infer_scenario

        infer_scenario(scenario, PUBLISHED, d, log=lambda m: None)
    elif step == "verdicts":
        from pipeline.north_finding.verdicts import write_verdicts

        write_verdicts(
            PUBLISHED, d, work / "verdicts.csv", scenario, sensitivity_out=work / "n_sens.csv"
        )
    elif step == "figures":
        from pipeline.north_finding.figures import run

        run(d, PUBLISHED, work / "figures")
    elif step == "report":
        from pipeline.north_finding.report_results import scenario_section

        scenario_section(d)
    elif step == "read":
        from pipeline.north_finding.trials_file import read_trials

        for stem in TRIAL_FILES:
            read_trials(d, stem)
    else:
        raise ValueError(f"step {step!r}: allowed: one of {[*STEPS, 'read']}")


def run_child(step: str, scenario: Path, work: Path) -> dict[str, float]:
    """One step in this process: its CPU seconds (imports excluded) and this process's peak RSS."""
    import pipeline.north_finding.run  # noqa: F401  (the heavy imports, outside the timing)
    import pipeline.north_finding.verdicts  # noqa: F401

    cpu0 = time.process_time()
    _step(step, scenario, work)
    cpu = time.process_time() - cpu0
    rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024  # KiB on Linux
    return {"cpu_s": cpu, "peak_rss_mb": rss}


def _scenario_copy(scenario: Path, n_trials: int, directory: Path) -> Path:
    """``scenario`` with ``monte_carlo.n_trials`` = ``n_trials``, same file name (and seeds)."""
    raw = yaml.safe_load(scenario.read_text(encoding="utf-8"))
    raw["monte_carlo"]["n_trials"] = int(n_trials)
    out = directory / scenario.name
    out.write_text(yaml.safe_dump(raw, sort_keys=False), encoding="utf-8")
    return out


def _spawn(step: str, scenario: Path, work: Path) -> dict[str, float]:
    cmd = [sys.executable, "-m", MODULE, "--child", step, "--scenario", str(scenario)]
    res = subprocess.run([*cmd, "--work", str(work)], capture_output=True, text=True)
    if res.returncode != 0:
        raise RuntimeError(f"benchmark child {step} ({scenario}) failed:\n{res.stderr}")
    return json.loads(res.stdout.strip().splitlines()[-1])


def _trial_files(d: Path) -> str:
    """The per-trial files of a scenario folder and their sizes."""
    found = [p for stem in TRIAL_FILES for p in sorted(d.glob(f"{stem}.*"))]
    return ", ".join(f"{p.name} {p.stat().st_size / 1e6:.1f} MB" for p in found) or "none"


def measure(scenario: Path, sizes: Sequence[int], steps: Sequence[str]) -> dict:
    """Every step at every size (fresh child each); prints the table as it goes."""
    print(
        f"north_finding Monte Carlo ({scenario}), every step in a fresh process "
        "(CPU s of the step, peak RSS of its process)"
    )
    print(
        f"   {'trials':>7s} {'step':9s} {'CPU s':>8s} {'peak RSS MB':>12s} {'CPU s/1e3 trials':>17s}"
    )
    table: dict = {}
    for n in sizes:
        with tempfile.TemporaryDirectory(prefix="nf_bench_") as tmp:
            work = Path(tmp)
            copy = _scenario_copy(scenario, n, work)
            for step in [*steps, "read"] if "simulate" in steps else steps:
                m = _spawn(step, copy, work)
                table[n, step] = m
                print(
                    f"   {n:7d} {step:9s} {m['cpu_s']:8.2f} {m['peak_rss_mb']:12.0f} "
                    f"{1e3 * m['cpu_s'] / n:17.3f}",
                    flush=True,
                )
            print(f"   {n:7d} files: {_trial_files(work / copy.stem)}", flush=True)
    for a, b in zip(sizes, sizes[1:], strict=False):
        ratios = ", ".join(
            f"{s} {table[b, s]['cpu_s'] / max(table[a, s]['cpu_s'], 1e-9):.1f}x"
            for s in steps
            if (a, s) in table and (b, s) in table
        )
        print(f"   CPU {b} / {a} trials ({b / a:g}x = linear): {ratios}")
    return table


def main(argv: Sequence[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--scenario", type=Path, default=Path("config/scenarios/north_finding/paper.yaml")
    )
    parser.add_argument("--sizes", default="1000,10000,100000", help="trial counts")
    parser.add_argument("--steps", default=",".join(STEPS), help=f"among {','.join(STEPS)}")
    parser.add_argument("--child", default=None, help=argparse.SUPPRESS)
    parser.add_argument("--work", type=Path, default=None, help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.child is not None:
        print(json.dumps(run_child(args.child, args.scenario, args.work)))
        return 0
    try:
        sizes = [int(s) for s in args.sizes.split(",") if s.strip()]
    except ValueError:
        parser.error(f"--sizes {args.sizes!r}: comma-separated integers >= 2 expected")
    steps = [s for s in args.steps.split(",") if s.strip()]
    bad = [s for s in steps if s not in STEPS]
    if bad or any(n < 2 for n in sizes):
        parser.error(f"--steps among {list(STEPS)} (got {bad}); --sizes >= 2")
    measure(args.scenario, sizes, steps)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
