"""Memory a job frees kept for its next allocations (glibc ``mallopt``), not handed back to the
system and touched again.

Every page a process touches first costs the kernel a zeroed page: on this project's 2-core
VM ~0.7-4.5 ms of system CPU per MB (the more, the busier the machine; measured from the minor
faults and the system time of the same job run again and again). glibc's ``malloc`` serves a
block of 128 kB or more with its own ``mmap`` and unmaps it when it is freed, and it hands the
free top of its heap back to the system once more than 128 kB of it is free (both thresholds
grow, up to 32 MB, as large blocks are freed). A job that builds a large string, frees it and
then builds another therefore touches fresh pages for each.

:func:`keep_freed_memory` fixes both thresholds: blocks under :data:`MMAP_THRESHOLD` come from
the heap, and the heap's free top is never handed back, so the next allocations reuse it. The
combined report's job (reproduction.py: pandas, SymPy, an HTML string of ~5 MB with its
figures in base64, then Typst, which grows by ~270 MB) touched 464 MB of pages; with the
thresholds fixed, 376-380 MB (minor faults, medians of 7 alternating runs; its peak resident
memory is unchanged, ~420 MB: what is kept is reused). Python's own small-object arenas are
mapped apart and are not affected; nor is memory freed by one thread and wanted by another,
which glibc serves from another arena (Typst compiling in a thread of its own reused little of
it: 417 MB touched, peak 462 MB).

What a job computes does not depend on where its memory comes from: its outputs are the same
bytes (checked: cmp of the job's outputs). On a C library other than glibc nothing is changed.
"""

from __future__ import annotations

import ctypes
import ctypes.util
import sys

__all__ = ["MMAP_THRESHOLD", "TRIM_THRESHOLD", "keep_freed_memory"]

#: blocks below this size come from the heap (glibc's largest mmap threshold: 32 MB)
MMAP_THRESHOLD = 32 * 1024 * 1024
#: the heap's free top is handed back only beyond this (never, in practice)
TRIM_THRESHOLD = 2**31 - 1

# glibc's mallopt parameters (malloc.h)
_M_TRIM_THRESHOLD = -1
_M_MMAP_THRESHOLD = -3


def keep_freed_memory() -> bool:
    """Fix glibc's mmap and trim thresholds for the rest of the process (see the module
    docstring); True if both were set, False (nothing changed) off glibc."""
    if not sys.platform.startswith("linux"):
        return False
    try:
        libc = ctypes.CDLL(ctypes.util.find_library("c") or "libc.so.6")
        mallopt = libc.mallopt
    except (OSError, AttributeError):  # not glibc (musl has no mallopt)
        return False
    mallopt.argtypes = (ctypes.c_int, ctypes.c_int)
    mallopt.restype = ctypes.c_int
    ok = mallopt(_M_MMAP_THRESHOLD, MMAP_THRESHOLD) == 1
    return mallopt(_M_TRIM_THRESHOLD, TRIM_THRESHOLD) == 1 and ok
