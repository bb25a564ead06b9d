"""Part 4 of :mod:`pipeline.altimeter_attitude.benchmark`: a large Monte Carlo run the way the
workflow runs a scenario with ``monte_carlo.chunk_runs`` (:mod:`pipeline.altimeter_attitude.chunks`).

One fresh process per chunk of runs (what rule ``altimeter_attitude_simulate_chunk`` runs:
:func:`~pipeline.altimeter_attitude.chunks.simulate_chunk` and its ``.mcsums`` file), at most
``jobs`` at once (Snakemake's ``--cores``), then one process for the merge (rule
``altimeter_attitude_simulate``: :func:`~pipeline.altimeter_attitude.chunks.merge_chunks`, the
noise-free run and every results file). Measured per process with ``os.wait4``: CPU (user +
system) and peak RSS; and the wall time from the first start to the merge's end, the one
figure a second core shortens:

    wall ~ CPU_chunks / jobs + CPU_merge     (chunks of equal size, idle cores)

The scenario is the given one with ``monte_carlo.n_runs`` and ``chunk_runs`` replaced (validated
as any scenario file); the default chunk is the runs split evenly over ``jobs`` in whole blocks
of :data:`~pipeline.altimeter_attitude.chunk_plan.BLOCK_RUNS` runs.

>>> default_chunk_runs(10_000, 2), default_chunk_runs(100, 2), default_chunk_runs(10_000, 3)
(5120, 256, 3584)
"""

from __future__ import annotations

import copy
import math
import os
import subprocess
import sys
import tempfile
import time
from dataclasses import dataclass
from pathlib import Path

from pipeline.altimeter_attitude.chunk_plan import BLOCK_RUNS, chunk_bounds
from pipeline.altimeter_attitude.scenario import Scenario, build_scenario, load_scenario

__all__ = ["ProcessCost", "default_chunk_runs", "sized_scenario", "workflow_run", "main"]

MODULE = "pipeline.altimeter_attitude.bench_chunks"


def default_chunk_runs(n_runs: int, jobs: int, block: int = BLOCK_RUNS) -> int:
    """``n_runs`` split evenly over ``jobs`` chunks, rounded up to whole blocks."""
    return max(1, math.ceil(n_runs / (jobs * block))) * block


def sized_scenario(path: str | Path, n_runs: int, chunk_runs: int) -> Scenario:
    """The scenario file ``path`` with ``n_runs`` runs in chunks of ``chunk_runs``."""
    base = load_scenario(path)
    raw = copy.deepcopy(base.raw)
    raw["monte_carlo"]["n_runs"] = int(n_runs)
    raw["monte_carlo"]["chunk_runs"] = int(chunk_runs)
    return build_scenario(raw, base.path)


@dataclass(frozen=True)
class ProcessCost:
    """One child process: its label, CPU seconds (user + system) and peak RSS (GB)."""

    label: str
    cpu_s: float
    peak_rss_gb: float


def _wait(proc: subprocess.Popen, label: str, err_path: Path) -> ProcessCost:
    _, status, usage = os.wait4(proc.pid, 0)
    proc.returncode = os.waitstatus_to_exitcode(status)
    if proc.returncode != 0:
        raise RuntimeError(f"benchmark {label} failed:\n{err_path.read_text()[-4000:]}")
    # ru_maxrss is in KiB on Linux
    return ProcessCost(label, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024**2)


def workflow_run(
    scenario: str | Path, n_runs: int, jobs: int, chunk_runs: int | None = None
) -> tuple[float, list[ProcessCost], ProcessCost]:
    """Run the chunk processes (``jobs`` at a time) and the merge into a temporary directory:
    (wall seconds, the chunks' costs in chunk order, the merge's cost)."""
    chunk_runs = chunk_runs or load_scenario(scenario).chunk_runs
    chunk_runs = chunk_runs or default_chunk_runs(n_runs, jobs)
    n_chunks = len(chunk_bounds(n_runs, chunk_runs)) or 1
    if n_chunks == 1:
        raise ValueError(f"{n_runs} runs in chunks of {chunk_runs}: one chunk, nothing to spread")
    args = [str(scenario), str(n_runs), str(chunk_runs)]
    with tempfile.TemporaryDirectory() as tmp:
        tmp_dir = Path(tmp)
        paths = [tmp_dir / f"{c}.mcsums" for c in range(n_chunks)]
        costs: dict[int, ProcessCost] = {}
        running: dict[int, tuple[subprocess.Popen, Path]] = {}
        todo = list(range(n_chunks))
        wall0 = time.perf_counter()
        while todo or running:
            while todo and len(running) < jobs:
                c = todo.pop(0)
                err = tmp_dir / f"{c}.err"
                cmd = [sys.executable, "-m", MODULE, "chunk", *args, str(c), str(paths[c])]
                with err.open("w") as fh:
                    running[c] = (subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=fh), err)
            # the first child to end (left to os.wait4 to reap, with its usage)
            pid = os.waitid(os.P_ALL, 0, os.WEXITED | os.WNOWAIT).si_pid
            done = next(c for c, (p, _) in running.items() if p.pid == pid)
            proc, err = running.pop(done)
            costs[done] = _wait(proc, f"chunk {done}", err)
        err = tmp_dir / "merge.err"
        cmd = [sys.executable, "-m", MODULE, "merge", *args, str(tmp_dir / "out"), *map(str, paths)]
        with err.open("w") as fh:
            merge = _wait(subprocess.Popen(cmd, stdout=subprocess.DEVNULL, stderr=fh), "merge", err)
        wall = time.perf_counter() - wall0
    return wall, [costs[c] for c in range(n_chunks)], merge


def main(argv: list[str] | None = None) -> int:
    """The child processes: ``chunk <scenario> <runs> <chunk_runs> <index> <file>`` and
    ``merge <scenario> <runs> <chunk_runs> <out_dir> <file>...``."""
    from pipeline.altimeter_attitude import chunks
    from pipeline.altimeter_attitude.heap import keep_freed_memory
    from pipeline.altimeter_attitude.run import write_results

    keep_freed_memory()  # as the workflow's steps do (pipeline/altimeter_attitude/steps.py)
    mode, path, n_runs, chunk_runs, *rest = argv if argv is not None else sys.argv[1:]
    sc = sized_scenario(path, int(n_runs), int(chunk_runs))
    if mode == "chunk":
        index, out = int(rest[0]), rest[1]
        bounds = chunk_bounds(sc.n_runs, sc.chunk_runs)[index]
        chunks.write_chunk(out, sc, bounds, chunks.simulate_chunk(sc, bounds, log=lambda m: None))
    elif mode == "merge":
        write_results(sc, rest[0], *chunks.merge_chunks(sc, rest[1:]))
    else:
        raise SystemExit(f"{MODULE}: mode {mode!r}: 'chunk' or 'merge'")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
