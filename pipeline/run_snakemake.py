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

>>> import snakemake
>>> snakemake.__version__ == PATCHED_VERSION
True
"""

from __future__ import annotations

import sys
import threading

__all__ = ["PATCHED_VERSION", "one_pending_reevaluation", "main"]

#: the Snakemake release whose scheduler loop :func:`one_pending_reevaluation` replaces a part of
PATCHED_VERSION = "9.27.1"


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


def main(argv: list[str] | None = None) -> None:
    """Run Snakemake's command line with ``argv`` (default: this process's arguments)."""
    import snakemake
    from snakemake.cli import main as snakemake_main

    if snakemake.__version__ == PATCHED_VERSION:
        from snakemake.scheduling.job_scheduler import JobScheduler

        one_pending_reevaluation(JobScheduler)
    snakemake_main(sys.argv[1:] if argv is None else argv)


if __name__ == "__main__":
    main()
