"""pipeline.heap_reuse: with glibc's thresholds fixed, a large block freed and allocated
again reuses the same pages (no new page faults); without, glibc hands it back to the system
and the next allocation touches fresh pages (off glibc: skipped). Each case runs in a process of its own (the
setting lasts for the process)."""

from __future__ import annotations

import os
import subprocess
import sys
from pathlib import Path

import pytest

from pipeline.heap_reuse import MMAP_THRESHOLD
from tests.hang_guard import HANG_GUARD_S

ROOT = Path(__file__).resolve().parents[2]
#: allocates and touches 8 MB three times, freeing it in between; prints the minor page
#: faults of the second and third allocations
PROBE = """
import resource, sys
from pipeline.heap_reuse import keep_freed_memory
if sys.argv[1] == "keep" and not keep_freed_memory():
    print("not glibc")
    sys.exit()
MB = 8
def touched():
    return bytearray(MB << 20)  # calloc'ed memory, zeroed: make every page resident
def faults():
    return resource.getrusage(resource.RUSAGE_SELF).ru_minflt
block = touched()
for b in range(0, len(block), 4096):
    block[b] = 1
del block
seen = []
for _ in range(2):
    before = faults()
    block = touched()
    for b in range(0, len(block), 4096):
        block[b] = 1
    seen.append(faults() - before)
    del block
print(max(seen))
"""


def _faults(mode: str) -> int:
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    r = subprocess.run(
        [sys.executable, "-c", PROBE, mode],
        capture_output=True,
        text=True,
        env=env,
        timeout=HANG_GUARD_S,
    )
    assert r.returncode == 0, r.stderr
    if r.stdout.strip() == "not glibc":
        pytest.skip("not glibc: keep_freed_memory changes nothing")
    return int(r.stdout)


def test_a_freed_block_is_reused_without_new_faults():
    pages = (8 << 20) // 4096
    assert _faults("keep") < pages // 8  # reused: a few pages at most
    assert _faults("default") >= pages // 2  # handed back, touched again


def test_threshold_is_glibcs_largest():
    assert MMAP_THRESHOLD == 32 << 20  # a larger value is refused (mallopt returns 0)
