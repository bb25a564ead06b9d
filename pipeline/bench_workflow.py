"""Workflow benchmark (issue 15): CPU seconds per step of the last reproduction, and a no-op.

``python -m pipeline.bench_workflow [--results results] [--baseline DIR] [--noop-repeat 3]
[--full-run]`` (part of ``make bench``). It reads the Snakemake benchmark files of every job,
``<results>/<paper>/benchmarks/<step>[_<scenario>].tsv`` and ``<results>/benchmarks/*.tsv``
(columns ``s`` = wall seconds and ``cpu_time`` = user + system CPU seconds of the job's
processes), and prints per step the jobs, CPU and wall seconds, then the totals against the
issue's targets:

* a full reproduction in <= 60 s of wall time on 2 cores: the jobs' CPU seconds / 2 is the
  least wall time 2 cores need (printed with the span of the jobs' benchmark files, which is
  the run's wall time when every job ran in the same run);
* a no-op ``make reproduce`` in <= 3 s: measured here, ``--noop-repeat`` times (median and
  range of the wall seconds, judged against the target, and of the CPU seconds, user + system
  of make and every process it starts, which a loaded machine inflates less), only when a dry
  run finds nothing to do (otherwise it would be a real run, and it is not started).

``--full-run`` measures the target itself instead of reading the last run's files: the
checkout's files (tracked and untracked, not ignored; so uncommitted edits count) are copied
to a temporary directory, with no results, no Snakemake state and an empty numba cache, as a
fresh clone has; the set-up's numba warm-up (``make warm-kernels``:
:mod:`pipeline.warm_up`, each paper's plug-in warm-up) runs there, timed apart, and then
``make workflow`` (what ``make reproduce`` runs after set-up, the Snakemake report included)
with this checkout's ``.venv`` on 2 cores. It prints the
wall time, the CPU seconds of every process it started, the load average before and after
(the wall time holds only on an idle machine), the per-step table of that run and its no-op
rerun. The jobs ``make reproduce`` runs itself have their exact CPU time in their benchmark
files (``pipeline/exact_benchmark.py``: the kernel's count when the job's shell is reaped); a
job run by an unpatched Snakemake (on a cluster node) has its CPU time sampled every 0.5 s for
its first 15 s, then every 30 s, and not at its end: an under-count, large for a job longer
than 15 s (starred in the table). The total is exact (``getrusage`` of the children).

``--baseline DIR`` adds the same columns for another results directory (e.g. a checkout
before a change) and the difference. The timings are of this machine and this run; they are
not results (nothing here is written under results/ or reports/).
"""

from __future__ import annotations

import argparse
import csv
import os
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

__all__ = [
    "FullRun",
    "StepTime",
    "checkout_files",
    "collect",
    "main",
    "measure_full_run",
    "measure_noop",
    "step_table",
]

#: issue 15's targets, seconds
FULL_RUN_TARGET_S = 60.0
#: an unpatched Snakemake (9.27.1, snakemake/benchmark.py; a cluster node's) samples a job's
#: CPU time every 0.5 s for its first 30 samples, then every 30 s, and not at its end: the CPU a
#: longer job spends after its last sample is missing from its benchmark file
SAMPLED_DENSELY_S = 15.0
NOOP_TARGET_S = 3.0
#: the set-up's numba warm-up (``make warm-kernels``), run in the copy before a full run
WARM_MODULE = "pipeline.warm_up"
CORES = 2


@dataclass(frozen=True)
class StepTime:
    """The jobs of one step (a rule; per-scenario jobs summed): count, CPU and wall seconds."""

    paper: str
    step: str
    jobs: int
    cpu_s: float
    wall_s: float
    #: newest benchmark file's mtime and the earliest start (mtime - wall) of the step's jobs
    end: float
    start: float
    #: the longest wall time of one of its jobs
    longest_s: float = 0.0


def _read_tsv(path: Path) -> tuple[float, float]:
    """(wall s, CPU s) of one Snakemake benchmark file (its first row)."""
    with path.open(encoding="utf-8", newline="") as fh:
        rows = list(csv.DictReader(fh, delimiter="\t"))
    if not rows or "s" not in rows[0] or "cpu_time" not in rows[0]:
        raise ValueError(f"{path}: not a Snakemake benchmark file (columns s, cpu_time)")
    try:
        return float(rows[0]["s"]), float(rows[0]["cpu_time"])
    except ValueError as exc:
        raise ValueError(f"{path}: s or cpu_time is not a number: {exc}") from None


def _step_name(stem: str, scenarios: set[str]) -> str:
    """``simulate_paper`` -> ``simulate`` when ``paper`` is a scenario of the paper."""
    for scenario in sorted(scenarios, key=len, reverse=True):
        if stem.endswith(f"_{scenario}") and len(stem) > len(scenario) + 1:
            return stem[: -len(scenario) - 1]
    return stem


def collect(results: Path) -> list[StepTime]:
    """Every step's jobs under ``results``, sorted by paper then step."""
    found: dict[tuple[str, str], list[tuple[float, float, float]]] = {}
    for tsv in sorted(results.glob("*/benchmarks/*.tsv")) + sorted(
        results.glob("benchmarks/*.tsv")
    ):
        paper = tsv.parent.parent.name if tsv.parent.parent != results else "(all papers)"
        # a per-scenario job's file is <step>_<scenario>.tsv; scenario dirs carry provenance
        scenarios = {p.parent.name for p in tsv.parent.parent.glob("*/provenance.json")}
        wall, cpu = _read_tsv(tsv)
        key = (paper, _step_name(tsv.stem, scenarios))
        found.setdefault(key, []).append((wall, cpu, tsv.stat().st_mtime))
    return [
        StepTime(
            paper,
            step,
            len(jobs),
            sum(c for _, c, _ in jobs),
            sum(w for w, _, _ in jobs),
            max(m for _, _, m in jobs),
            min(m - w for w, _, m in jobs),
            max(w for w, _, _ in jobs),
        )
        for (paper, step), jobs in sorted(found.items())
    ]


def step_table(steps: list[StepTime], baseline: list[StepTime] | None = None) -> str:
    """The per-step table (CPU and wall seconds; with ``baseline``: before, after, change)."""
    before = {(s.paper, s.step): s for s in baseline or []}
    keys = [(s.paper, s.step) for s in steps]
    keys += [k for k in sorted(before) if k not in keys]
    now = {(s.paper, s.step): s for s in steps}
    head = f"{'paper':<20} {'step':<22} {'jobs':>4} {'CPU s':>8} {'wall s':>8}"
    if baseline is not None:
        head += f" {'CPU s before':>13} {'change':>8}"
    lines = [head, "-" * len(head)]
    for key in keys:
        s, b = now.get(key), before.get(key)
        jobs = f"{s.jobs:>4}" if s else f"{'-':>4}"
        cpu = f"{s.cpu_s:>8.1f}" if s else f"{'-':>8}"
        wall = f"{s.wall_s:>8.1f}" if s else f"{'-':>8}"
        line = f"{key[0]:<20} {key[1]:<22} {jobs} {cpu} {wall}"
        line += " *" if s and s.longest_s > SAMPLED_DENSELY_S else ""
        if baseline is not None:
            old = f"{b.cpu_s:>13.1f}" if b else f"{'-':>13}"
            change = f"{(s.cpu_s if s else 0.0) - (b.cpu_s if b else 0.0):>+8.1f}"
            line += f" {old} {change}"
        lines.append(line)
    total = sum(s.cpu_s for s in steps)
    foot = f"{'total':<20} {'':<22} {sum(s.jobs for s in steps):>4} {total:>8.1f}"
    foot += f" {sum(s.wall_s for s in steps):>8.1f}"
    if baseline is not None:
        old_total = sum(b.cpu_s for b in baseline)
        foot += f" {old_total:>13.1f} {total - old_total:>+8.1f}"
    notes = []
    if any(s.longest_s > SAMPLED_DENSELY_S for s in steps):
        notes.append(
            f"* a job ran longer than {SAMPLED_DENSELY_S:.0f} s of wall: if it ran on a cluster "
            "node, Snakemake there sampled its CPU time every 30 s, so its CPU seconds are a "
            "lower bound (a local run's are exact)"
        )
    return "\n".join(lines + ["-" * len(head), foot, *notes])


def _children_cpu() -> float:
    usage = resource.getrusage(resource.RUSAGE_CHILDREN)
    return usage.ru_utime + usage.ru_stime


def measure_noop(
    root: Path, repeat: int, venv: Path | None = None
) -> list[tuple[float, float]] | str:
    """(CPU, wall) seconds of ``repeat`` no-op ``make reproduce`` runs in ``root``, or why not
    run (``venv``: another checkout's environment, run through ``make workflow``)."""
    env = dict(os.environ, PYTHONPATH=str(root))
    snakemake = (venv or root / ".venv") / "bin" / "snakemake"
    dry = subprocess.run(
        [str(snakemake), "--dry-run", "--cores", str(CORES), "--rerun-triggers", "mtime"]
        + ["params", "input", "code", "software-env"],
        cwd=root,
        env=env,
        capture_output=True,
        text=True,
    )
    if dry.returncode != 0:
        return f"not measured: the dry run failed ({dry.stderr.strip().splitlines()[-1:]})"
    if "Nothing to be done" not in dry.stdout + dry.stderr:
        return "not measured: the workflow is not up to date (run `make reproduce` first)"
    times = []
    for _ in range(repeat):
        before, start = _children_cpu(), time.perf_counter()
        target = ["workflow", f"VENV={venv}"] if venv else ["reproduce"]
        done = subprocess.run(
            ["make", "--no-print-directory", *target], cwd=root, capture_output=True
        )
        if done.returncode != 0:
            return f"not measured: make reproduce failed with status {done.returncode}"
        times.append((_children_cpu() - before, time.perf_counter() - start))
    return times


@dataclass(frozen=True)
class FullRun:
    """One ``make workflow`` from nothing: wall and CPU seconds, load average around it."""

    wall_s: float
    cpu_s: float
    load_before: float
    load_after: float
    returncode: int
    copy: Path
    #: CPU seconds of the set-up's numba warm-up before the run (None: the copy has none)
    warm_cpu_s: float | None = None


def checkout_files(root: Path) -> list[str]:
    """The checkout's files as a fresh clone with this checkout's edits would have them:
    tracked and untracked, without the ignored ones (results, .venv, caches)."""
    out = subprocess.run(
        ["git", "ls-files", "-z", "--cached", "--others", "--exclude-standard"],
        cwd=root,
        capture_output=True,
        check=True,
    ).stdout
    return sorted({f for f in out.decode().split("\0") if f and (root / f).is_file()})


def measure_full_run(root: Path, work: Path, cores: int = CORES) -> FullRun:
    """Copy ``root``'s files to ``work``/repo and run ``make workflow`` there (see the
    module docstring); the copy is left for the per-step table and the no-op."""
    copy = work / "repo"
    for rel in checkout_files(root):
        dest = copy / rel
        dest.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(root / rel, dest)
    venv = (root / ".venv").resolve()
    env = {k: v for k, v in os.environ.items() if k != "NUMBA_CACHE_DIR"}
    warm_cpu = None
    if (copy / WARM_MODULE.replace(".", "/")).with_suffix(".py").is_file():
        # the module, not `make warm-kernels`, which would install the copy into this
        # checkout's venv if its pyproject.toml were newer than the venv's stamp
        before = _children_cpu()
        subprocess.run(
            [str(venv / "bin" / "python"), "-m", WARM_MODULE],
            cwd=copy,
            env={**env, "PYTHONPATH": str(copy)},
            stdout=subprocess.DEVNULL,
            check=False,
        )
        warm_cpu = _children_cpu() - before
    load_before = os.getloadavg()[0]
    cpu_before = _children_cpu()
    start = time.monotonic()
    done = subprocess.run(
        ["make", "--no-print-directory", "workflow", f"VENV={venv}", f"CORES={cores}"],
        cwd=copy,
        env=env,
        stdout=subprocess.DEVNULL,
        stderr=subprocess.PIPE,
    )
    wall = time.monotonic() - start
    return FullRun(
        wall,
        _children_cpu() - cpu_before,
        load_before,
        os.getloadavg()[0],
        done.returncode,
        copy,
        warm_cpu,
    )


def _full_run_report(args: argparse.Namespace) -> int:
    with tempfile.TemporaryDirectory(prefix="bench-workflow-") as tmp:
        print(
            "full run from nothing (a copy of this checkout, its set-up's numba warm-up, "
            "make workflow, 2 cores) ..."
        )
        run = measure_full_run(Path.cwd(), Path(tmp))
        if run.returncode != 0:
            print(f"error: make workflow failed in the copy (status {run.returncode})")
            return 1
        steps = collect(run.copy / "results")
        print(step_table(steps, collect(args.baseline) if args.baseline else None))
        verdict = "meets it" if run.wall_s <= FULL_RUN_TARGET_S else "misses it"
        print()
        print(
            f"full run: {run.wall_s:.1f} s wall, {run.cpu_s:.1f} CPU-s in all (make, Snakemake, "
            f"jobs, Snakemake's report); target {FULL_RUN_TARGET_S:.0f} s wall: {verdict}"
        )
        print(
            f"          {run.cpu_s / CORES:.1f} s is the least wall time 2 cores need for that "
            f"CPU; load average {run.load_before:.2f} before, {run.load_after:.2f} after "
            "(the wall time holds for an idle machine only)"
        )
        if run.warm_cpu_s is not None:
            print(
                f"          the set-up's numba warm-up before it: {run.warm_cpu_s:.1f} CPU-s "
                "(not in the run's)"
            )
        if args.noop_repeat:
            _print_noop(measure_noop(run.copy, args.noop_repeat, (Path.cwd() / ".venv").resolve()))
    return 0


def _print_noop(noop: list[tuple[float, float]] | str) -> None:
    if isinstance(noop, str):
        print(f"no-op make reproduce: {noop}")
        return
    cpu, wall = [c for c, _ in noop], [w for _, w in noop]
    med = statistics.median(wall)
    print(
        f"no-op make reproduce: median {med:.2f} s wall, {statistics.median(cpu):.2f} CPU-s, "
        f"of {len(noop)} (wall {min(wall):.2f}-{max(wall):.2f}, CPU {min(cpu):.2f}-{max(cpu):.2f};"
        f" target {NOOP_TARGET_S:.0f} s): " + ("meets it" if med <= NOOP_TARGET_S else "misses it")
    )


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--results", type=Path, default=Path("results"))
    parser.add_argument("--baseline", type=Path, default=None, help="results dir to compare")
    parser.add_argument("--noop-repeat", type=int, default=3, help="0 skips the no-op run")
    parser.add_argument(
        "--full-run",
        action="store_true",
        help="run the whole workflow from nothing in a copy of this checkout and time it",
    )
    args = parser.parse_args(argv)
    # --full-run reads the copy's results, not this checkout's (a fresh clone has none)
    checked = (
        (("--baseline", args.baseline),)
        if args.full_run
        else (("--results", args.results), ("--baseline", args.baseline))
    )
    for name, path in checked:
        if path is not None and not path.is_dir():
            print(f"error: {name} {path}: not a directory (a workflow's results)", file=sys.stderr)
            return 2
    if args.noop_repeat < 0:
        print(f"error: --noop-repeat {args.noop_repeat}: must be >= 0", file=sys.stderr)
        return 2
    if args.full_run:
        return _full_run_report(args)
    try:
        steps = collect(args.results)
        baseline = collect(args.baseline) if args.baseline else None
    except ValueError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    if not steps:
        print(f"error: {args.results}: no benchmarks/*.tsv (run `make reproduce`)", file=sys.stderr)
        return 2
    print(f"Workflow steps of the last reproduction ({args.results}), CPU = user + system")
    print(step_table(steps, baseline))
    cpu = sum(s.cpu_s for s in steps)
    wall = sum(s.wall_s for s in steps)
    span = max(s.end for s in steps) - min(s.start for s in steps)
    print()
    print(
        f"full run: {cpu:.1f} CPU-s in jobs -> at least {cpu / CORES:.1f} s of wall on {CORES} "
        f"cores (target {FULL_RUN_TARGET_S:.0f} s): "
        + ("meets it" if cpu / CORES <= FULL_RUN_TARGET_S else "misses it")
    )
    if span <= wall:
        print(f"          the jobs' files span {span:.1f} s of wall (one run; load included)")
    else:
        print("          the jobs ran in more than one run: no single run's wall time")
    if args.noop_repeat:
        _print_noop(measure_noop(Path.cwd(), args.noop_repeat))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
