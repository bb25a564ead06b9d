"""Which ready job the scheduler starts first: the one with the most measured work still below it.

Snakemake's local scheduler picks among the jobs that are ready by ``priority``, then (all
priorities equal, its default) by the size of their input files. Input size says nothing of
how long a step takes here: a run on two cores started the three-second steps first and left a
nine-second notebook for last, alone on one core while the other idled. List scheduling does
better with each job's *bottom level* (HEFT's upward rank): its own cost plus the costliest
chain of jobs that wait on it, down to the last target::

    level(job) = cost(job) + max(level(d) for d in dependents(job))   (0 if it has none)

Costs are the CPU seconds measured for each job (``config/job_resources.csv``, column
``cpu_s``; ``pipeline.job_resources``). A job that was never measured (a new paper's step)
costs ``UNMEASURED_COST_S``; a target (no benchmark) costs nothing. The priorities decide only
the order of jobs, never what a job writes: every output stays byte-identical.

>>> dependents = {"derive": ["audit", "simulate"], "simulate": ["figures"], "audit": [],
...               "figures": []}
>>> cost = {"derive": 6.0, "audit": 11.5, "simulate": 3.0, "figures": 4.0}
>>> levels = bottom_levels(dependents, cost)
>>> [levels[job] for job in ("derive", "audit", "simulate", "figures")]
[17.5, 11.5, 7.0, 4.0]
"""

from __future__ import annotations

from collections.abc import Callable, Hashable, Iterable, Mapping
from typing import TypeVar

__all__ = ["UNMEASURED_COST_S", "bottom_levels", "dag_bottom_levels"]

# the cost of a job with no measured row: about the median step of the shipped papers
UNMEASURED_COST_S = 1.0

Job = TypeVar("Job", bound=Hashable)


def bottom_levels(
    dependents: Mapping[Job, Iterable[Job]], cost: Mapping[Job, float]
) -> dict[Job, float]:
    """Each job's cost plus the largest bottom level among the jobs that depend on it.

    ``dependents`` maps every job to the jobs that wait on it (jobs outside the mapping are
    ignored); ``cost`` gives each job's cost (missing: 0). Raises ``ValueError`` on a cycle.

    >>> bottom_levels({"a": ["b"], "b": ["a"]}, {})
    Traceback (most recent call last):
    ...
    ValueError: the job graph has a cycle through 'a'
    """
    levels: dict[Job, float] = {}
    on_path: set[Job] = set()
    for root in dependents:
        if root in levels:
            continue
        # iterative depth-first search: (job, its dependents still to visit)
        stack = [(root, iter(dependents[root]))]
        on_path.add(root)
        while stack:
            job, pending = stack[-1]
            child = next((d for d in pending if d in dependents and d not in levels), None)
            if child is None:
                below = [levels[d] for d in dependents[job] if d in dependents]
                levels[job] = float(cost.get(job, 0.0)) + max(below, default=0.0)
                on_path.discard(job)
                stack.pop()
            elif child in on_path:
                raise ValueError(f"the job graph has a cycle through {child!r}")
            else:
                on_path.add(child)
                stack.append((child, iter(dependents[child])))
    return levels


def dag_bottom_levels(
    jobs: Iterable[Job],
    dependents_of: Callable[[Job], Iterable[Job]],
    cost_of: Callable[[Job], float],
) -> dict[Job, float]:
    """:func:`bottom_levels` over the jobs of a workflow run (Snakemake's ``needrun`` jobs),
    with ``dependents_of`` and ``cost_of`` read off its DAG; costs rounded to 0.1 s so that
    the order does not hang on float noise.

    >>> after = {1: [2, 3], 2: [], 3: []}
    >>> dag_bottom_levels(after, after.__getitem__, {1: 1.04, 2: 2.0, 3: 0.5}.__getitem__)
    {1: 3.0, 2: 2.0, 3: 0.5}
    """
    jobs = list(jobs)
    members = set(jobs)
    dependents = {job: [d for d in dependents_of(job) if d in members] for job in jobs}
    levels = bottom_levels(dependents, {job: round(cost_of(job), 1) for job in jobs})
    return {job: round(levels[job], 1) for job in jobs}
