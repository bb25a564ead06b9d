"""The order of ready jobs (pipeline/job_priority.py; `priority:` of every rule, common.smk):
each job's bottom level, its measured CPU seconds plus the costliest chain waiting on it."""

from __future__ import annotations

import itertools
import random

import pytest

from pipeline.job_priority import bottom_levels, dag_bottom_levels
from pipeline.job_resources import read_table
from tests.workflow_harness import ROOT, snakemake


def _longest_chain(dependents: dict[int, list[int]], cost: dict[int, float], job: int) -> float:
    """Brute force: the costliest path from ``job`` to a sink, every path enumerated."""
    paths = [[job]]
    best = 0.0
    while paths:
        path = paths.pop()
        after = dependents[path[-1]]
        if not after:
            best = max(best, sum(cost[j] for j in path))
        paths += [path + [d] for d in after]
    return best


@pytest.mark.parametrize("seed", range(20))
def test_bottom_level_is_the_costliest_chain(seed: int) -> None:
    rng = random.Random(seed)
    n = rng.randint(1, 12)
    # edges only from a lower to a higher number: acyclic
    dependents = {j: sorted(d for d in range(j + 1, n) if rng.random() < 0.3) for j in range(n)}
    cost = {j: rng.choice([0.0, 0.5, 1.0, 4.0, 11.5]) for j in range(n)}
    levels = bottom_levels(dependents, cost)
    assert levels == {j: _longest_chain(dependents, cost, j) for j in range(n)}


def test_jobs_outside_the_run_are_ignored_and_cycles_named() -> None:
    after = {"a": ["b", "done"], "b": []}
    assert dag_bottom_levels(["a", "b"], after.__getitem__, {"a": 1, "b": 2}.get) == {
        "a": 3.0,
        "b": 2.0,
    }
    with pytest.raises(ValueError, match="cycle through"):
        bottom_levels({"a": ["b"], "b": ["c"], "c": ["a"]}, {})


def _dry_run_priorities() -> dict[str, float]:
    """{benchmark job name: priority} of every job of a dry run of the whole workflow."""
    r = snakemake("-n", "--forceall", cwd=ROOT)
    assert r.returncode == 0, (r.stdout + r.stderr)[-3000:]
    found: dict[str, float] = {}
    job = None
    for line in (r.stdout + r.stderr).splitlines():
        line = line.strip()
        if line.startswith("benchmark: "):
            bench = line.split(": ", 1)[1].removeprefix("results/").removesuffix(".tsv")
            job = bench.replace("benchmarks/", "")
        elif line.startswith("priority: ") and job:
            found[job] = float(line.split(": ", 1)[1])
            job = None
    return found


def test_workflow_jobs_start_by_bottom_level() -> None:
    """In the workflow, every measured job's priority is its CPU seconds plus the chain below:
    a derive step ranks above each step that reads its artefact by at least its own cost, and
    the combined report's steps, which nothing waits on, rank by their own cost alone."""
    table = read_table(ROOT / "config" / "job_resources.csv")
    priorities = _dry_run_priorities()
    assert len(priorities) >= 30
    cost = {job: round(table[job].cpu_s, 1) for job in priorities}
    for job, priority in priorities.items():
        assert priority >= cost[job] - 1e-9, job
    assert priorities["reproduction"] == pytest.approx(cost["reproduction"])
    papers = {job.split("/")[0] for job in priorities if job.endswith("/derive")}
    assert len(papers) == 3
    for paper, step in itertools.product(papers, ("audit", "codegen_check", "notebook")):
        derive = priorities[f"{paper}/derive"]
        assert derive >= priorities[f"{paper}/{step}"] + cost[f"{paper}/derive"] - 0.11
        # the paper's page waits on the audit: the chain continues below it
        assert priorities[f"{paper}/audit"] > cost[f"{paper}/audit"]
