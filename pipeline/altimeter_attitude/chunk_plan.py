"""How a scenario's Monte Carlo is cut into blocks and chunks, and what a chunk job asks a
cluster for: what the workflow needs when it parses the Snakefile (chunk wildcards and
resources), kept apart from :mod:`pipeline.altimeter_attitude.chunks` and the compiled
filters it imports (numba's import alone costs ~0.5 CPU-s in every workflow start).

>>> chunk_bounds(1000, 512, 256)
[(0, 512), (512, 1000)]
>>> chunk_bounds(100, None), chunk_bounds(512, 512)
([], [])
>>> chunk_bounds(1000, 300, 256)
Traceback (most recent call last):
...
ValueError: chunk_runs = 300: must be a positive multiple of the block of 256 runs
"""

from __future__ import annotations

import math

from pipeline.altimeter_attitude.scenario import Scenario
from pipeline.job_resources import JobResources, derive_row

__all__ = ["BATCH_RUNS", "BLOCK_RUNS", "chunk_bounds", "chunk_request"]

#: runs per block: the unit of the Monte Carlo's sums (one :class:`~pipeline.altimeter_attitude.
#: mc_sums.BlockSums` per block and filter, what a chunk file keeps); fixed, so the results do
#: not depend on the machine
BLOCK_RUNS = 256

#: runs per filter call within a block: the histories of one batch (~19 MB per filter at
#: 10,000 steps; the linear-KF variants run stacked, three times that) are all that is held.
#: Fixed too: the linear KF's series length follows its batch's largest rotation (a 1e-17
#: effect per run), the other filters treat each run alone. Memory a process touches for the
#: first time is dear on a VM whose host reclaims the guest's freed pages (here ~5 ms of
#: system CPU per MB, seconds after another process freed it): the paper scenario's 100 runs
#: in one batch of 256 took 4.44 CPU-s (1.4 of them system, peak RSS 529 MB), in batches of
#: 32 4.0, of 16 3.7 (0.4, 300 MB); 512 runs: 18.3 CPU-s in batches of 256 (1,379 MB), 14.5
#: in batches of 32 (378 MB), 15.2 of 16 (medians of paired runs, one process each).
BATCH_RUNS = 32

#: measured (paper scenario, 10,000 steps, 7 filters, batches of BATCH_RUNS, one process:
#: 512 runs 15.6 CPU-s, peak RSS 374 MB; 100 runs 352 MB; 8 runs 215 MB): what a chunk job
#: asks a cluster for, per run-step; memory taken as linear up to a block through the 8- and
#: 100-run peaks (584 MB at 256 runs: above what is measured, so a request is never short)
CPU_S_PER_RUN_STEP = 15.6 / (512 * 10_000)
RSS_MB_PER_RUN_STEP = (352.0 - 215.0) / (92 * 10_000)
RSS_MB_BASE = 215.0 - 8 * 10_000 * RSS_MB_PER_RUN_STEP


def chunk_bounds(
    n_runs: int, chunk_runs: int | None, block: int = BLOCK_RUNS
) -> list[tuple[int, int]]:
    """The runs [start, stop) of each chunk; empty when the Monte Carlo is one job (no
    ``chunk_runs``, or not fewer runs than it)."""
    if chunk_runs is None:
        return []
    if chunk_runs < 1 or chunk_runs % block:
        raise ValueError(
            f"chunk_runs = {chunk_runs}: must be a positive multiple of the block of {block} runs"
        )
    if n_runs <= chunk_runs:
        return []
    return [(s, min(s + chunk_runs, n_runs)) for s in range(0, n_runs, chunk_runs)]


def chunk_request(sc: Scenario, chunk_runs: int | None = None) -> JobResources:
    """A chunk job's threads, memory and run time (the margins of
    :func:`pipeline.job_resources.derive_row`), scaled from the measured cost per run-step:
    memory by one block's runs (above what a block in batches needs), CPU by the chunk's runs."""
    runs = chunk_runs or sc.chunk_runs or sc.n_runs
    steps = int(round(sc.raw["trajectory"]["duration_s"] * sc.sensors.rate_hz))
    cpu = CPU_S_PER_RUN_STEP * runs * steps
    rss = RSS_MB_BASE + RSS_MB_PER_RUN_STEP * min(runs, BLOCK_RUNS) * steps
    return derive_row(f"altimeter_attitude/simulate_chunk_{sc.name}", cpu, math.ceil(rss), cpu)
