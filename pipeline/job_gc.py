"""Python's cyclic garbage collector in the workflow's jobs: paused while a SymPy job runs
(:func:`paused_gc`), and kept away from the heap the interpreter leaves at exit
(:func:`frozen_at_exit`).

The derive, derive_frames, audit and codegen_check jobs build millions of SymPy objects (the
north-finding audit: ~50 million function calls), almost all short-lived and freed by their
reference counts; the cyclic collector scans them anyway, every 700 allocations for the
youngest generation and, as the heap grows, all of it (importing SymPy and the derivations
alone: ~0.1 CPU-s of ~0.4). Within :func:`paused_gc` the collector does not run; the few
cycles made stay until the process exits (peak memory of the ten jobs +0..26 MB, measured).
At the end everything still alive is frozen (``gc.freeze``: moved to a generation no
collection scans) and the collector is switched back on if it was.

The combined report's job (pipeline/scripts/reproduction.py) runs paused too: it builds no
Matplotlib figure, and its ~390 collections (pandas, SymPy, the document) took 0.17-0.21 of
its ~4.5 CPU-s while its minor page faults and peak memory stayed the same without them
(461-472 MB of pages touched, ~420 MB peak, measured).

The other jobs (simulations, figures, verdicts, pages) keep the collector on while they run: Matplotlib's figures are cycles, and with the collector paused
the figure jobs' peak memory grew by 20-57 MB (measured), which this machine pays in system
CPU. But when a job's script ends, the interpreter's exit still collects, several times over
the whole heap (NumPy, pandas, Matplotlib, the results): 0.1-0.4 s between a job's last
statement and its process ending, 5.5 s over the 40 jobs of a full run (measured from the
script's end to Snakemake reaping the process), time in which a core runs no job. With the
heap frozen first (:func:`frozen_at_exit`, and the end of :func:`paused_gc`) those
collections have nothing to scan: 1.0 s over the 40 jobs.

The garbage collector frees memory only: what a job computes and writes is the same with it
paused or frozen (the jobs' outputs are byte-identical; SymPy defines no ``__del__``).

>>> import gc
>>> with paused_gc():
...     gc.isenabled()
False
>>> gc.isenabled()
True
>>> with frozen_at_exit():
...     gc.isenabled()
True
"""

from __future__ import annotations

import contextlib
import gc
from collections.abc import Iterator

__all__ = ["frozen_at_exit", "paused_gc"]


@contextlib.contextmanager
def paused_gc() -> Iterator[None]:
    """The cyclic garbage collector off while the block runs; then what is alive frozen
    (never scanned again) and the collector back on if it was on before."""
    enabled = gc.isenabled()
    gc.disable()
    try:
        yield
    finally:
        gc.freeze()
        if enabled:
            gc.enable()


@contextlib.contextmanager
def frozen_at_exit() -> Iterator[None]:
    """The block runs with the collector as it is; then what is alive is frozen, so the
    collections of the interpreter's exit that follows the job's script do not scan it."""
    try:
        yield
    finally:
        gc.freeze()
