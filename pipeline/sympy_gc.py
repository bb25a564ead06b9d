"""Python's cyclic garbage collector paused while a SymPy job runs: :func:`paused_gc`.

The derive, derive_frames, audit and codegen_check jobs build millions of SymPy objects (the
north-finding audit: ~50 million function calls), almost all short-lived and freed by their
reference counts; the cyclic collector scans them anyway, every 700 allocations for the
youngest generation and, as the heap grows, all of it (importing SymPy and the derivations
alone: ~0.1 CPU-s of ~0.4). Within :func:`paused_gc` the collector does not run; the few
cycles made stay until the process exits (peak memory of the ten jobs +0..26 MB, measured).
At the end everything still alive is frozen (``gc.freeze``: moved to a generation no
collection scans, including the one at the interpreter's exit) and the collector is switched
back on if it was.

The garbage collector frees memory only: what a job computes and writes is the same with it
paused (the jobs' outputs are byte-identical; SymPy defines no ``__del__``).

>>> import gc
>>> with paused_gc():
...     gc.isenabled()
False
>>> gc.isenabled()
True
"""

from __future__ import annotations

import contextlib
import gc
from collections.abc import Iterator

__all__ = ["paused_gc"]


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
