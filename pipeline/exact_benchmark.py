"""A job's benchmark file with its exact CPU time, measured more cheaply (used by
:mod:`pipeline.run_snakemake` for the Snakemake version it pins).

What Snakemake does (9.27.1, ``snakemake/benchmark.py``): for a ``shell:`` or ``script:`` job
with a ``benchmark:`` file (every rule here has one), ``snakemake.shell`` starts the job's shell
and waits for it inside ``benchmarked(pid, record)``, whose ``BenchmarkTimer`` samples the shell's
process tree from Snakemake's own process, in a new thread per sample: at once, every 0.5 s for 30
samples, then every 30 s. A sample lists the tree with psutil's ``children(recursive=True)``
(which reads ``/proc/<pid>/stat`` of every process on the machine) and reads each process's
``memory_full_info()`` (``/proc/<pid>/smaps_rollup``: the kernel walks the process's page tables,
~5 ms for a 380 MB Python process here), I/O counters and CPU times. The benchmark's ``cpu_time``
is the sum of the CPU times seen at the last sample, not at the job's end: a short job loses what
it spent after its last sample (up to 0.5 s), a job longer than 15 s up to 30 s, and the CPU of a
child that exited between samples is lost. py-spy of Snakemake's process over a full ``make
workflow`` (2 cores): 11.7 CPU-s in all, 5.6 of them in this sampling (3.2 in
``memory_full_info``, 1.2 in ``children``).

What :func:`exact_benchmarks` changes (only the benchmark of a job run through
``snakemake.shell``, i.e. every job of this workflow; ``run:`` jobs, which benchmark Snakemake's
own process, keep Snakemake's timer):

* the job's shell is reaped with ``os.wait4`` instead of ``os.waitpid`` (a ``subprocess.Popen``
  subclass for ``snakemake.shell`` only), which returns its resource usage together with that of
  every descendant it and they waited for: ``cpu_time`` is the exact user + system CPU seconds of
  the job, ``mean_load`` is ``100 * cpu_time / s`` (Snakemake's unit: percent of one core),
  ``io_in``/``io_out`` the MB the job's processes read from and wrote to storage (the counters of
  ``/proc/<pid>/io`` that Snakemake sampled, but totals, exited processes included). Its
  ``ru_maxrss`` is not used: the shell is forked from Snakemake's process, whose RSS (~90 MB)
  the kernel counts in the shell's peak, so it is no bound of the job's;
* one sampling thread per job (not one per sample) reads the tree's size every 0.5 s for its
  first 15 s, then every 2 s (so a long job's peak is no longer sampled every 30 s only):
  ``/proc/<pid>/statm`` of each process (RSS and VMS, ~0.01 ms), the tree listed from
  ``/proc/<pid>/task/<tid>/children`` where the kernel has it (psutil's scan otherwise, as
  before). ``max_rss``/``max_vms`` are the largest sums over the tree, as Snakemake's;
* ``smaps_rollup`` (``max_uss``, ``max_pss``, which nothing in this project reads) is read only
  at the first sample and when the tree's RSS has grown 10 % past its size at the last reading:
  near the RSS peaks, where USS and PSS peak too, a few times per job instead of 30.

The TSV is written by Snakemake's own ``BenchmarkRecord`` (same columns, same formatting). If the
shell was reaped by something else (no resource usage), the record falls back on the sampled
CPU times, as Snakemake's. A process a job leaves running past its end (re-parented to init) is
in neither measurement once it has left the tree.

Measured on a full ``make workflow`` from nothing (2 cores, a loaded machine, the same copy of
the repository before and after, alternately): Snakemake's own process 13.3 -> 8.7 CPU-s, all
processes 221.1 -> 217.5 CPU-s; the jobs' ``cpu_time`` summed 157.2 CPU-s before (64 s of the
jobs' CPU missing: a 40 s job had 5.5 CPU-s of its ~16) and 208.4 after, which with Snakemake's
process is the run's total (217.0 of 217.5 CPU-s). Every file under results/ and reports/
byte-identical (benchmarks, logs and Snakemake's report aside).
"""

from __future__ import annotations

import contextlib
import os
import subprocess
import threading
import time
import types
from collections.abc import Iterator
from typing import Any

import psutil

__all__ = ["RusagePopen", "exact_benchmarks", "tree_sampler"]

#: pid -> resource usage at its reaping (None before) of the job shells being benchmarked
_RUSAGE: dict[int, Any] = {}
_MB = 1024 * 1024
#: the sampling interval for a job's first DENSE_S seconds, and after
DENSE_INTERVAL_S, DENSE_S, SPARSE_INTERVAL_S = 0.5, 15.0, 2.0
#: growth of the tree's RSS since the last smaps_rollup reading that calls for another
SMAPS_GROWTH = 1.10
_PAGE = os.sysconf("SC_PAGE_SIZE")
_TICK = os.sysconf("SC_CLK_TCK")
_HAS_CHILDREN_FILE = os.path.exists(f"/proc/self/task/{threading.get_native_id()}/children")


class RusagePopen(subprocess.Popen):
    """``subprocess.Popen`` that reaps a process being benchmarked (its pid in ``_RUSAGE``) with
    ``os.wait4`` and keeps the resource usage; any other process as ``Popen`` does."""

    def _try_wait(self, wait_flags: int) -> tuple[int, int]:
        if self.pid not in _RUSAGE:
            return super()._try_wait(wait_flags)
        try:
            pid, status, usage = os.wait4(self.pid, wait_flags)
        except ChildProcessError:  # as Popen: reaped elsewhere, the status is lost
            return self.pid, 0
        if pid == self.pid:
            _RUSAGE[pid] = usage
        return pid, status


def _children(pid: int) -> list[int]:
    found = []
    try:
        tids = os.listdir(f"/proc/{pid}/task")
    except OSError:
        return found
    for tid in tids:
        try:
            with open(f"/proc/{pid}/task/{tid}/children", "rb") as fh:
                found.extend(int(c) for c in fh.read().split())
        except OSError:
            pass
    return found


def _tree(pid: int) -> list[int]:
    """``pid`` and its descendants alive now."""
    if not _HAS_CHILDREN_FILE:
        try:
            return [pid, *(p.pid for p in psutil.Process(pid).children(recursive=True))]
        except psutil.Error:
            return [pid]
    out, i = [pid], 0
    while i < len(out):
        out.extend(_children(out[i]))
        i += 1
    return out


def _statm(pid: int) -> tuple[int, int] | None:
    """(RSS, VMS) in bytes, as psutil's ``memory_info``; None for a process that is gone."""
    try:
        with open(f"/proc/{pid}/statm", "rb") as fh:
            vms, rss = fh.read().split()[:2]
    except (OSError, ValueError):
        return None
    return int(rss) * _PAGE, int(vms) * _PAGE


def _cpu_seconds(pid: int) -> float | None:
    """user + system CPU seconds of a process (``/proc/<pid>/stat``, as psutil's cpu_times)."""
    try:
        with open(f"/proc/{pid}/stat", "rb") as fh:
            fields = fh.read().rpartition(b")")[2].split()
        return (int(fields[11]) + int(fields[12])) / _TICK
    except (OSError, ValueError, IndexError):
        return None


class tree_sampler:  # noqa: N801 - used like a function: with tree_sampler(pid, record): ...
    """Sample the process tree of ``pid`` into Snakemake's ``BenchmarkRecord`` ``record`` in a
    thread while the block runs; at its end, put ``_RUSAGE[pid]`` (if the shell was reaped with
    it) into the record."""

    def __init__(self, pid: int, record: Any) -> None:
        self.pid, self.record = pid, record
        self.rss = self.vms = 0
        self.uss = self.pss = 0
        self.rss_at_smaps = 0
        self.cpu: dict[int, float] = {}  # pid -> CPU s at its last sample (if no rusage)
        self.samples = 0
        self.stop = threading.Event()
        self.thread = threading.Thread(target=self._run, daemon=True, name=f"benchmark {pid}")

    def sample(self) -> None:
        rss = vms = 0
        sizes = []
        for pid in _tree(self.pid):
            size = _statm(pid)
            if size is None:
                continue
            sizes.append(pid)
            rss, vms = rss + size[0], vms + size[1]
            cpu = _cpu_seconds(pid)
            if cpu is not None:
                self.cpu[pid] = cpu
        if not sizes:
            return
        self.samples += 1
        self.rss, self.vms = max(self.rss, rss), max(self.vms, vms)
        if rss > SMAPS_GROWTH * self.rss_at_smaps:
            self.rss_at_smaps = rss
            uss = pss = 0
            for pid in sizes:
                try:
                    full = psutil.Process(pid).memory_full_info()
                except psutil.Error:
                    continue
                uss, pss = uss + full.uss, pss + getattr(full, "pss", 0)
            self.uss, self.pss = max(self.uss, uss), max(self.pss, pss)

    def _run(self) -> None:
        start = time.monotonic()
        while True:
            self.sample()
            dense = time.monotonic() - start < DENSE_S
            if self.stop.wait(DENSE_INTERVAL_S if dense else SPARSE_INTERVAL_S):
                return

    def __enter__(self) -> tree_sampler:
        _RUSAGE[self.pid] = None
        self.thread.start()
        return self

    def __exit__(self, *exc: object) -> None:
        self.stop.set()
        self.thread.join()
        self.finish(_RUSAGE.pop(self.pid, None))

    def finish(self, usage: Any) -> None:
        """Write the measurements into the record (``usage``: ``os.wait4``'s, or None)."""
        rec = self.record
        if usage is None and not self.samples:
            rec.process_gone = True  # Snakemake's "exited before a sample": NA, no warning
            return
        rec.data_collected = True
        if usage is not None:
            cpu = usage.ru_utime + usage.ru_stime
            rec.io_in, rec.io_out = usage.ru_inblock * 512 / _MB, usage.ru_oublock * 512 / _MB
        else:
            cpu = sum(self.cpu.values())
            rec.io_in = rec.io_out = None  # Snakemake's value when it cannot count I/O
        rec.max_rss, rec.max_vms = self.rss / _MB, self.vms / _MB
        rec.max_uss, rec.max_pss = self.uss / _MB, self.pss / _MB
        rec.cpu_time = cpu
        rec.cpu_usage = 100.0 * cpu  # mean_load = cpu_usage / s: percent of one core


def exact_benchmarks(benchmark_module: types.ModuleType, shell_module: types.ModuleType) -> bool:
    """Make ``benchmark_module.benchmarked`` (``snakemake.benchmark``) measure a job's process
    (a pid given) with :class:`tree_sampler`, and ``shell_module`` (``snakemake.shell``) start
    its processes with :class:`RusagePopen`. Returns whether both were patched (False: one of
    them lacks what is replaced; then neither is).

    >>> import snakemake.benchmark, snakemake.shell
    >>> bench = types.ModuleType("b"); bench.__dict__.update(vars(snakemake.benchmark))
    >>> shell = types.ModuleType("s"); shell.sp = subprocess
    >>> exact_benchmarks(bench, shell)
    True
    >>> shell.sp.Popen is RusagePopen, subprocess.Popen is RusagePopen
    (True, False)
    >>> exact_benchmarks(types.ModuleType("empty"), shell)
    False
    """
    original = getattr(benchmark_module, "benchmarked", None)
    record_class = getattr(benchmark_module, "BenchmarkRecord", None)
    sp = getattr(shell_module, "sp", None)
    if not callable(original) or record_class is None or getattr(sp, "Popen", None) is None:
        return False

    @contextlib.contextmanager
    def benchmarked(
        pid: Any = None, benchmark_record: Any = None, *args: Any, **kwargs: Any
    ) -> Iterator:
        if not pid:  # None: Snakemake's own process (a run: job); False: no benchmark
            with original(pid, benchmark_record, *args, **kwargs) as record:
                yield record
            return
        record = benchmark_record or record_class()
        start = time.time()
        try:
            with tree_sampler(int(pid), record):
                yield record
        finally:
            record.running_time = time.time() - start

    rusage_sp = types.ModuleType(sp.__name__, sp.__doc__)
    rusage_sp.__dict__.update(vars(sp))
    rusage_sp.Popen = RusagePopen
    benchmark_module.benchmarked = benchmarked
    shell_module.sp = rusage_sp
    return True
