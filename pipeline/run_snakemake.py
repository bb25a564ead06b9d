"""Snakemake's command line (``python -m pipeline.run_snakemake <snakemake arguments>``), with one
fix to its scheduler loop; what ``make reproduce`` runs.

Snakemake's job scheduler (9.27.1, the version of environment.lock) ends every pass of its loop
by starting a ``threading.Timer`` that wakes the loop again one second later (its job rate
limiter, ``--max-jobs-per-timespan``, 100 jobs per second by default). A pass woken by a finished
job starts one more timer, so the timers multiply: after k finished jobs the loop runs about k
times a second, each pass re-reading the size of every input of every waiting job (on this
workflow about 120 files a pass). Measured on a full run from nothing (2 cores, loaded machine,
the same run side by side): 5,736 timers and 34.6 CPU-s in Snakemake's own process; with at most
one pending timer, 447 timers and 13.5 CPU-s; every output byte-identical.

:func:`one_pending_reevaluation` keeps at most one timer pending: a pass that finds one already
set does not start another. The loop is still woken within the limiter's time span after any
pass, and at once by every finished job (Snakemake releases the loop then itself), so no job is
scheduled later than before. Upstream: snakemake/snakemake pull request 3744 (the loop woken too
often under the rate limiter). The fix is applied only to the Snakemake version it was written
for (:data:`PATCHED_VERSION`); any other version runs unchanged.

A second change, for local runs only: Snakemake imports every installed executor plugin at start
to register its options, and the SLURM plugin (in environment.lock for ``make reproduce-slurm``)
runs ``scontrol show config`` at import, with a 10 s time-out, to word a help text. On a machine
with a SLURM client whose controller does not answer, every Snakemake start waited ~9-10 s for
it, idle (two starts in a full ``make reproduce``: the workflow and its report; ~0.6 CPU-s each
otherwise). :func:`local_run` tells from the command line that no cluster executor can be in
play (no ``--executor``, no profile given or found); then :func:`skip_executor_plugins` leaves
the SLURM plugins out of Snakemake's plugin registry. A run with a profile or an executor
(``make reproduce-slurm``) loads every plugin as before.

A third: each pass of the loop re-read the size of every input of every ready job (with the
code inputs, hundreds of files a pass), though a ready job's inputs no longer change;
:func:`known_input_sizes` reads each file's size once. The sizes only order jobs of equal
priority (the rules' priorities, ``pipeline.job_priority``, come first).

A fourth: the benchmark file of a job (every rule has one) gets the job's exact CPU time, from
the kernel when its shell is reaped (``os.wait4``), and its memory is sampled more cheaply, in
one thread per job instead of one per sample (:func:`pipeline.exact_benchmark.exact_benchmarks`,
whose docstring has what Snakemake does and the numbers). Same TSV columns, written by
Snakemake's own code; it applies to the jobs this process runs (a cluster job's benchmark is
measured by the Snakemake on its node, unpatched).

A fifth, when the command line asks for a report (``--report``): Snakemake's report renders the
caption of each tagged output once per distinct text (:mod:`pipeline.snakemake_captions`:
docutils and Jinja compute the same HTML from the same input; the captions' ``publish_parts``
0.243 -> 0.110 CPU-s, at the end of a run, in series).

A sixth: each input of a finished job is hashed once per version of the file for the jobs'
metadata records, not once per output of every job that reads it
(:func:`pipeline.snakemake_checksums.known_checksums`: ~10,200 hashes, ~0.9 CPU-s of a full
run in Snakemake's process; the records hold the same checksums).

Not changed, measured: a ``script:`` job's preamble unpickles Snakemake's ``snakemake`` object,
which imports ``snakemake.io`` and with it most of Snakemake (asyncio, ssl, ...): 0.11 CPU-s in
a bare interpreter, but only 0.02-0.09 CPU-s more than what a step imports anyway (numpy 0.09,
sympy 0.08, matplotlib 0.08, the notebook kernel's client 0.02; means of 8 alternating starts),
about 3 CPU-s per full run of 40 jobs. Avoiding it needs a preamble of our own with an imitation
of Snakemake's ``Namedlist`` (its ``str``, ``repr``, attribute and index access) for local runs
only, while cluster jobs keep Snakemake's: two objects whose every use by a script must agree
for the outputs to stay byte-identical across executors; not worth ~1.5 s of wall time.

>>> import snakemake
>>> snakemake.__version__ == PATCHED_VERSION
True
"""

from __future__ import annotations

import importlib
import inspect
import os
import pkgutil
import sys
import threading
from collections.abc import Iterable, Mapping
from pathlib import Path
from typing import Any

__all__ = [
    "PATCHED_VERSION",
    "CLUSTER_PLUGINS",
    "one_pending_reevaluation",
    "known_input_sizes",
    "local_run",
    "skip_executor_plugins",
    "wants_report",
    "main",
]

#: the Snakemake release whose scheduler loop :func:`one_pending_reevaluation` replaces a part of
PATCHED_VERSION = "9.27.1"

#: executor plugin modules a local run does not import (the SLURM one queries the cluster at import)
CLUSTER_PLUGINS = frozenset(
    {"snakemake_executor_plugin_slurm", "snakemake_executor_plugin_slurm_jobstep"}
)

# Snakemake's options that choose an executor or a profile (which may choose one)
_EXECUTOR_OPTIONS = ("--executor", "--profile", "--workflow-profile")


def one_pending_reevaluation(scheduler_class: type) -> bool:
    """Make ``scheduler_class._schedule_reevalutation`` (sic, Snakemake's name) start a timer
    only when none is pending; the timer is a daemon thread, so a finished run exits at once
    rather than waiting for it. Returns whether the class was patched (False: no such method).

    >>> class Loop:
    ...     def __init__(self):
    ...         self._open_jobs = threading.Semaphore(0)
    ...     def _schedule_reevalutation(self, delay):
    ...         raise AssertionError("replaced")
    >>> one_pending_reevaluation(Loop)
    True
    >>> loop = Loop()
    >>> loop._schedule_reevalutation(0.05); loop._schedule_reevalutation(0.05)
    >>> loop._open_jobs.acquire(timeout=5), loop._open_jobs.acquire(timeout=0.2)
    (True, False)
    """
    if not callable(getattr(scheduler_class, "_schedule_reevalutation", None)):
        return False
    guard = threading.Lock()

    def schedule_reevaluation(self, delay: float) -> None:
        with guard:
            if getattr(self, "_reevaluation_pending", False):
                return
            self._reevaluation_pending = True

        def wake() -> None:
            with guard:
                self._reevaluation_pending = False
            self._open_jobs.release()

        timer = threading.Timer(delay, wake)
        timer.daemon = True
        timer.start()

    scheduler_class._schedule_reevalutation = schedule_reevaluation
    return True


def known_input_sizes(scheduler_class: type) -> bool:
    """Make ``scheduler_class.update_input_sizes`` measure only the inputs it has not measured
    yet. Snakemake calls it on every pass of its loop with every ready job, and re-reads the
    size of each input of each of them (an existence check and a stat, each a coroutine);
    but a ready job's inputs are final (the jobs that write them have finished), so a size once
    read stays right. Returns whether the class was patched (False: no such coroutine).

    >>> class Scheduler:
    ...     def __init__(self):
    ...         self._input_sizes, self.read = {}, []
    ...     async def update_input_sizes(self, jobs):
    ...         paths = {f for job in jobs for f in job.input}
    ...         self.read += sorted(paths)
    ...         self._input_sizes.update((f, 1) for f in paths)
    >>> known_input_sizes(Scheduler)
    True
    >>> import asyncio
    >>> job = lambda *files: type("Job", (), {"input": files})
    >>> s = Scheduler()
    >>> asyncio.run(s.update_input_sizes([job("a", "b")]))
    >>> asyncio.run(s.update_input_sizes([job("a", "b"), job("b", "c")]))
    >>> s.read
    ['a', 'b', 'b', 'c']
    """
    update = getattr(scheduler_class, "update_input_sizes", None)
    if not inspect.iscoroutinefunction(update):
        return False

    async def update_input_sizes(self, jobs: Iterable[Any]) -> None:
        jobs = list(jobs)
        known = self._input_sizes
        new = [job for job in jobs if any(f not in known for f in job.input)]
        if new:
            await update(self, new)
        # Snakemake forgets sizes past 10,000 files: then read every job's again
        if any(f not in known for job in jobs for f in job.input):
            await update(self, jobs)

    scheduler_class.update_input_sizes = update_input_sizes
    return True


def local_run(argv: Iterable[str], environ: Mapping[str, str], cwd: Path) -> bool:
    """Whether a Snakemake command line runs its jobs here for certain: no executor chosen
    (``--executor``/``-e``), no profile given (``--profile``, ``$SNAKEMAKE_PROFILE``,
    ``--workflow-profile`` other than ``none``) and no default workflow profile Snakemake would
    pick up (``profiles/default`` or ``default`` in ``cwd``). Any doubt answers False.

    >>> local_run(["--cores", "2", "--report", "r.html"], {}, Path("/nonexistent"))
    True
    >>> local_run(["--profile", "profiles/slurm"], {}, Path("/nonexistent"))
    False
    >>> local_run(["-e", "slurm"], {}, Path("/nonexistent")), local_run(["-npe", "x"], {}, Path("/"))
    (False, False)
    >>> local_run(["--workflow-profile", "none"], {}, Path("/nonexistent"))
    True
    >>> local_run([], {"SNAKEMAKE_PROFILE": "p"}, Path("/nonexistent"))
    False
    """
    args = list(argv)
    for i, arg in enumerate(args):
        name = arg.split("=", 1)[0]
        if name in _EXECUTOR_OPTIONS or any(
            option.startswith(name) and len(name) > 3 for option in _EXECUTOR_OPTIONS
        ):
            value = arg.split("=", 1)[1] if "=" in arg else next(iter(args[i + 1 :]), "")
            if not (name.startswith("--w") and value == "none"):
                return False
        elif arg.startswith("-") and not arg.startswith("--") and "e" in arg[1:]:
            return False
    if environ.get("SNAKEMAKE_PROFILE"):
        return False
    return not any((cwd / place).exists() for place in ("profiles/default", "default"))


def skip_executor_plugins(registry_class: type, skipped: frozenset[str]) -> bool:
    """Make ``registry_class.collect_plugins`` (Snakemake's executor plugin registry) run as
    before but blind to the installed modules named in ``skipped``: while it runs,
    ``pkgutil.iter_modules`` (where it finds the installed plugins) leaves them out, so they are
    not imported. Returns whether the class was patched (False: it has no such method).

    >>> class Registry:
    ...     def collect_plugins(self):
    ...         self.found = {m.name for m in pkgutil.iter_modules()} & {"pkgutil", "doctest"}
    >>> skip_executor_plugins(Registry, frozenset({"doctest"}))
    True
    >>> registry = Registry(); registry.collect_plugins(); registry.found
    {'pkgutil'}
    >>> "doctest" in {m.name for m in pkgutil.iter_modules()}
    True
    """
    collect = getattr(registry_class, "collect_plugins", None)
    if not callable(collect):
        return False

    def collect_plugins(self) -> None:
        iter_modules = pkgutil.iter_modules

        def iter_kept(path=None, prefix=""):
            return (info for info in iter_modules(path, prefix) if info.name not in skipped)

        pkgutil.iter_modules = iter_kept
        try:
            collect(self)
        finally:
            pkgutil.iter_modules = iter_modules

    registry_class.collect_plugins = collect_plugins
    return True


def wants_report(argv: Iterable[str]) -> bool:
    """Whether a Snakemake command line writes its report (``--report``, with or without
    ``=``; an abbreviation of it is ambiguous to Snakemake's parser, which has
    ``--report-after-run`` and others beside it).

    >>> wants_report(["--cores", "2", "--report", "r.html", "--report-after-run"])
    True
    >>> wants_report(["--report=r.html"]), wants_report(["--cores", "2"])
    (True, False)
    >>> wants_report(["--report-stylesheet", "s.css"])
    False
    """
    return any(arg.split("=", 1)[0] == "--report" for arg in argv)


def main(argv: list[str] | None = None) -> None:
    """Run Snakemake's command line with ``argv`` (default: this process's arguments)."""
    import snakemake

    args = sys.argv[1:] if argv is None else argv
    if snakemake.__version__ == PATCHED_VERSION:
        # before anything instantiates the registry (importing the scheduler does)
        from snakemake_interface_executor_plugins.registry import ExecutorPluginRegistry

        if local_run(args, os.environ, Path.cwd()):
            skip_executor_plugins(ExecutorPluginRegistry, CLUSTER_PLUGINS)
        from snakemake.scheduling.job_scheduler import JobScheduler

        one_pending_reevaluation(JobScheduler)
        known_input_sizes(JobScheduler)
        from snakemake.io import _IOFile

        from pipeline.snakemake_checksums import known_checksums

        known_checksums(_IOFile)
        from pipeline.exact_benchmark import exact_benchmarks

        # the modules (the package's attribute ``shell`` is the class of that name)
        exact_benchmarks(
            importlib.import_module("snakemake.benchmark"),
            importlib.import_module("snakemake.shell"),
        )
        if wants_report(args):
            from pipeline.snakemake_captions import cheaper_captions

            cheaper_captions(importlib.import_module("snakemake.report"))
    from snakemake.cli import main as snakemake_main

    snakemake_main(args)


if __name__ == "__main__":
    main()
