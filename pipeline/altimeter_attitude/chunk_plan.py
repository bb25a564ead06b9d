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

__all__ = ["BLOCK_RUNS", "chunk_bounds", "chunk_request"]

#: runs per block: the histories of one block (~150 MB per filter at 10,000 steps) are all
#: that is held; fixed, so the results do not depend on the machine
BLOCK_RUNS = 256

#: measured (paper scenario, one block of 256 runs x 10,000 steps, 7 filters: 24.4 CPU s,
#: peak RSS 1,143 MB; 100 runs: 523 MB): what a chunk job asks a cluster for, per run-step
CPU_S_PER_RUN_STEP = 24.4 / (256 * 10_000)
RSS_MB_PER_RUN_STEP = (1143.0 - 523.0) / (156 * 10_000)
RSS_MB_BASE = 523.0 - 100 * 10_000 * RSS_MB_PER_RUN_STEP


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
    memory by one block, CPU by the chunk's runs."""
    runs = chunk_runs or sc.chunk_runs or sc.n_runs
    steps = int(round(sc.raw["trajectory"]["duration_s"] * sc.sensors.rate_hz))
    cpu = CPU_S_PER_RUN_STEP * runs * steps
    rss = RSS_MB_BASE + RSS_MB_PER_RUN_STEP * min(runs, BLOCK_RUNS) * steps
    return derive_row(f"altimeter_attitude/simulate_chunk_{sc.name}", cpu, math.ceil(rss), cpu)
