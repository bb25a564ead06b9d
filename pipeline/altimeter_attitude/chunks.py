"""The Monte Carlo of one scenario as chunks of runs that a cluster can spread, merged into the
same bytes as the run in one process (:func:`pipeline.altimeter_attitude.run.run_scenario`).

A scenario with ``monte_carlo.chunk_runs`` (a whole number of blocks of
:data:`~pipeline.altimeter_attitude.mc_sums.BLOCK_RUNS` runs) and more runs than that is run by
the workflow as one job per chunk (rule ``altimeter_attitude_simulate_chunk``, wildcard
``{chunk}``), each writing ``results/altimeter_attitude/<scenario>/chunks/<chunk>.mcsums``, and a
merge (rule ``altimeter_attitude_simulate``) writing the results files. Chunk ``c`` holds runs

    [c * chunk_runs, min((c + 1) * chunk_runs, n_runs))

in blocks of BLOCK_RUNS runs from its first run, each run through the filters in batches of
:data:`~pipeline.altimeter_attitude.chunk_plan.BATCH_RUNS` runs, so its blocks and batches are
exactly the in-process loop's (estimates depend on the batch they are run in: the linear KF's
series length follows the batch's largest rotation). The file keeps each block's
:class:`~pipeline.altimeter_attitude.mc_sums.BlockSums` per filter, not their sum: the merge
folds them in run order, the very additions of the in-process loop,

    S = (((b_0 + b_1) + b_2) + ...) + b_{B-1}        (per filter, state time and square)

so the results are bit-identical (floating-point addition is not associative: a sum of
per-chunk sums would differ in the last bits). Seeds are per run (``seed_scheme`` in
provenance.json), so a chunk draws its runs alone. Size: 10 x (T + 1) doubles per block and
filter (5.6 MB per 256 runs of the paper scenario's 10,000 steps and 7 filters).

File format (deterministic bytes): the line ``MAGIC``, one line of JSON (sorted keys: the
scenario, its config hash, runs, block, chunk bounds, and per part its filter, first run and
runs), then per part four arrays in ``.npy`` format (``numpy.lib.format``, version 1.0):
squares, run_ms, counts, any_sigma.

The chunks' bounds and a chunk job's request are in :mod:`pipeline.altimeter_attitude.chunk_plan`
(the Snakefile's parse reads them without importing the filters).
"""

from __future__ import annotations

import io
import json
from collections.abc import Sequence
from pathlib import Path

import numpy as np

from pipeline.altimeter_attitude.chunk_plan import BLOCK_RUNS, chunk_bounds, chunk_request
from pipeline.altimeter_attitude.columns import ALTIMETER_FILTERS
from pipeline.altimeter_attitude.mc_sums import BlockSums, MonteCarloSums
from pipeline.altimeter_attitude.scenario import Scenario
from pipeline.altimeter_attitude.sensors import Inputs, simulate_inputs
from pipeline.atomic import write_bytes

__all__ = [
    "MAGIC",
    "chunk_bounds",
    "chunk_request",
    "merge_chunks",
    "read_chunk",
    "simulate_chunk",
    "write_chunk",
]

MAGIC = b"inertial-repro altimeter_attitude Monte Carlo chunk, format 1\n"
_ARRAYS = ("squares", "run_ms", "counts", "any_sigma")


def _header(sc: Scenario, block: int, bounds: tuple[int, int], parts: list[dict]) -> dict:
    return {
        "scenario": sc.name,
        "config_sha256": sc.config_sha256,
        "n_runs": sc.n_runs,
        "block": block,
        "runs": list(bounds),
        "parts": parts,
    }


def simulate_chunk(
    sc: Scenario,
    bounds: tuple[int, int],
    filters: tuple[str, ...] = ALTIMETER_FILTERS,
    log=print,
    block: int = BLOCK_RUNS,
) -> list[tuple[int, BlockSums]]:
    """(first run, sums) of every block and filter of runs [start, stop), in the order the
    in-process loop folds them."""
    from pipeline.altimeter_attitude.run import block_filter_sums, new_sums

    start, stop = bounds
    if start % block:
        raise ValueError(f"chunk runs {start}-{stop - 1}: must start on a block of {block} runs")
    _, mc, _ = new_sums(sc, filters)
    out: list[tuple[int, BlockSums]] = []
    for first in range(start, stop, block):
        last = min(stop, first + block)
        log(f"{sc.name}: runs {first}-{last - 1} of {sc.n_runs}")
        out += [(first, s) for s in block_filter_sums(sc, mc, first, last, filters)[1]]
    return out


def write_chunk(
    path: str | Path,
    sc: Scenario,
    bounds: tuple[int, int],
    parts: Sequence[tuple[int, BlockSums]],
    block: int = BLOCK_RUNS,
) -> Path:
    """One chunk's block sums as a file (atomically; the same bytes for the same sums)."""
    meta = [{"filter": p.filter, "first_run": first, "n_runs": p.n_runs} for first, p in parts]
    head = json.dumps(_header(sc, block, bounds, meta), sort_keys=True, separators=(",", ":"))
    out = io.BytesIO()
    out.write(MAGIC + head.encode("utf-8") + b"\n")
    for _, p in parts:
        for name in _ARRAYS:
            np.lib.format.write_array(out, np.ascontiguousarray(getattr(p, name)), (1, 0))
    return write_bytes(path, out.getvalue())


def read_chunk(
    path: str | Path,
    sc: Scenario,
    bounds: tuple[int, int],
    firsts: tuple[int, ...],
    filters: tuple[str, ...] = ALTIMETER_FILTERS,
    block: int = BLOCK_RUNS,
) -> list[tuple[int, BlockSums]]:
    """A chunk file's block sums; ValueError naming the file and the field when it is not the
    chunk ``bounds`` of this scenario (another scenario, an edited one, other bounds), or its
    blocks are not every filter's blocks of those runs in run order."""
    path = Path(path)
    with path.open("rb") as fh:
        if fh.readline() != MAGIC:
            raise ValueError(f"{path}: not a Monte Carlo chunk file (first line is not {MAGIC!r})")
        head = json.loads(fh.readline())
        want = _header(sc, block, bounds, head.get("parts", []))
        for key, value in want.items():
            if head.get(key) != value:
                raise ValueError(
                    f"{path}: {key} = {head.get(key)!r}, expected {value!r} (a chunk of another "
                    "run: delete it and rerun the workflow)"
                )
        start, stop = bounds
        blocks = [(f, min(block, stop - f)) for f in range(start, stop, block)]
        got = [(m["first_run"], m["n_runs"]) for m in head["parts"]]
        named = [m["filter"] for m in head["parts"]]
        each = [sorted(named[i : i + len(filters)]) for i in range(0, len(named), len(filters))]
        if got != [b for b in blocks for _ in filters] or each != [sorted(filters)] * len(blocks):
            raise ValueError(
                f"{path}: parts (first run, runs) {got} of filters {named}: expected the blocks "
                f"{blocks} of every filter {list(filters)}, in run order"
            )
        parts = []
        for meta in head["parts"]:
            arrays = [np.lib.format.read_array(fh, allow_pickle=False) for _ in _ARRAYS]
            parts.append((meta["first_run"], BlockSums(meta["filter"], firsts, *arrays)))
        if fh.read(1):
            raise ValueError(f"{path}: bytes after its {len(parts)} parts")
    return parts


def merge_chunks(
    sc: Scenario,
    paths: Sequence[str | Path],
    chunk_runs: int | None = None,
    filters: tuple[str, ...] = ALTIMETER_FILTERS,
    block: int = BLOCK_RUNS,
) -> tuple[Inputs, MonteCarloSums, MonteCarloSums]:
    """What :func:`~pipeline.altimeter_attitude.run.simulate_sums` returns, from the chunk
    files of ``sc`` (in chunk order) and the noise-free run."""
    from pipeline.altimeter_attitude.run import add_noise_free, new_sums

    bounds = chunk_bounds(sc.n_runs, chunk_runs or sc.chunk_runs, block)
    if len(paths) != len(bounds):
        raise ValueError(
            f"{sc.name}: {len(paths)} chunk files for {len(bounds)} chunks of "
            f"{chunk_runs or sc.chunk_runs} runs ({sc.n_runs} runs)"
        )
    clean, mc, nf = new_sums(sc, filters)
    for path, chunk in zip(paths, bounds, strict=True):
        for _, part in read_chunk(path, sc, chunk, mc.firsts, filters, block):
            mc.fold(part)
    add_noise_free(sc, clean, nf, filters)
    size = min(block, sc.n_runs)
    first_inputs = simulate_inputs(sc.profiles, sc.sensors, sc.initial, size, sc.seed, sc.name)
    return first_inputs, mc, nf
