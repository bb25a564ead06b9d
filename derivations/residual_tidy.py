"""The residual of a ``differs`` row made readable (presentation only: the status is decided
before, numerically, in :mod:`derivations.checks`).

``tidy`` runs ``trigsimp``, then ``simplify`` on a small residual or, on a large one, the shorter of
simplify's first two candidates (:func:`_tidy_large`), under a CPU-time guard.

Each residual is tidied from SymPy's random generator freshly seeded (:data:`derivations.SYMPY_SEED`):
SymPy's polynomial factoring (Wang's algorithm, inside ``trigsimp`` and ``simplify``) draws random
evaluation points, so without the reseed the random state at a residual, hence the work its tidy
does (not its result: a factorisation is unique), depended on every check tidied before it in the
process. With it, a residual costs the same whatever the audit ran first, in the audit job, a test
or a notebook.
"""

from __future__ import annotations

import sympy as sp
import sympy.core.random as _sympy_random

from derivations import SYMPY_SEED

__all__ = ["LARGE_OPS", "SIMPLIFY_SECONDS", "tidy"]

# CPU seconds (not wall-clock) that ``simplify`` gets per residual: a guard against a runaway
# simplify, not a budget that shapes the output. The slowest residual of the three papers takes
# about 9 s of CPU on an idle machine; a budget of 30 s was exceeded on a loaded one (eq. 57 of
# the north-finding paper came out unsimplified in one run of two), so the guard sits far above any
# observed need. Hash randomisation is off in the workflow's jobs (PYTHONHASHSEED=0 in
# pipeline/rules/common.smk), so SymPy's term order, hence simplify's result, is the same in
# every run.
SIMPLIFY_SECONDS = 600

# A residual of more than LARGE_OPS operations after ``trigsimp`` is not passed to ``simplify``:
# it gets the shorter of two of simplify's own candidates (:func:`_tidy_large`). simplify's further
# passes over such a residual (trigsimp again, now of the residual combined into one fraction,
# whose numerator SymPy factors by Wang's algorithm) took seconds each (eq. 57 of the
# north-finding paper ~4 CPU-s, half its audit's simplify time) and, on every residual of the
# three papers above 40 operations, gave nothing other than the shorter of these two candidates
# (equation_audit.csv and equation_math.json of the three papers byte-identical with and without
# this shortcut; tests/shared/test_checks.py compares the two on a large residual).
LARGE_OPS = 40


class _Timeout(Exception):
    pass


def _tidy_large(trigsimped: sp.Expr) -> sp.Expr:
    """The shorter (``count_ops``, the first on a tie) of simplify's first two candidates for a
    large residual already through ``trigsimp``: the residual with its signs and absolute values
    normalised as simplify starts (``collect_abs(signsimp(.))``), and that cancelled into one
    fraction with its common factors pulled out (simplify's ``cancel`` and
    ``factor_terms(sign=False)``). Both are the residual rewritten, so equal to it."""
    from sympy.simplify.simplify import collect_abs, signsimp

    start = collect_abs(signsimp(trigsimped))
    return min((start, sp.factor_terms(sp.cancel(start), sign=False)), key=sp.count_ops)


def _simplified(residual: sp.Expr) -> sp.Expr:
    """``trigsimp``, then ``simplify`` (a small residual) or :func:`_tidy_large` (a large one)."""
    trigsimped = sp.trigsimp(residual)
    if sp.count_ops(trigsimped) > LARGE_OPS:
        return _tidy_large(trigsimped)
    return sp.simplify(trigsimped)


def tidy(residual: sp.Expr) -> sp.Expr:
    """A readable residual. The status is already decided numerically, so this is presentation.

    ``simplify`` usually takes well under a second here, but its run time varies with SymPy's
    term order from process to process and has exceeded minutes; it gets SIMPLIFY_SECONDS of
    the process's CPU time (in the main thread, via ITIMER_PROF and SIGPROF), after which the
    residual is shown with common factors pulled out instead. CPU time, not wall-clock time:
    on a loaded machine a wall-clock budget cut the same residual short in one run and not in
    the next, so the text of equation_audit.csv depended on the load.
    """
    import signal
    import threading

    if threading.current_thread() is not threading.main_thread():
        return sp.factor_terms(residual)

    def _raise(signum, frame):
        raise _Timeout

    previous = signal.signal(signal.SIGPROF, _raise)
    signal.setitimer(signal.ITIMER_PROF, SIMPLIFY_SECONDS)
    try:
        _sympy_random.seed(SYMPY_SEED)  # the same random draws whatever ran before
        return _simplified(residual)
    except _Timeout:
        import sys

        print(
            f"equation audit: simplify exceeded {SIMPLIFY_SECONDS} s of CPU; residual shown "
            "with common factors pulled out instead",
            file=sys.stderr,
        )
        return sp.factor_terms(residual)
    finally:
        signal.setitimer(signal.ITIMER_PROF, 0)
        signal.signal(signal.SIGPROF, previous)
