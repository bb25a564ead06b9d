"""DESIGN.md invariant 4: every file under ``results/`` and ``reports/`` is byte-identical across
runs and core counts. The session's reduced run (``--cores 2``) is rerun from scratch with
``--cores 1`` in a copy and every file is compared (wall-clock benchmark files and job logs
excepted: they hold timings by design)."""

from __future__ import annotations

import shutil

import pytest

from tests.hang_guard import HANG_GUARD_S
from tests.workflow_harness import output_digests, snakemake

pytestmark = [pytest.mark.slow, pytest.mark.workflow]


def test_every_output_identical_on_one_core_and_two(workflow_run, tmp_path):
    repo = tmp_path / "repo"
    shutil.copytree(workflow_run, repo, symlinks=True)
    two_cores = output_digests(repo)
    assert len(two_cores) > 50 and any(p.endswith(".pdf") for p in two_cores)
    r = snakemake("--cores", "1", "--forceall", "--quiet", cwd=repo, timeout=HANG_GUARD_S)
    assert r.returncode == 0, (r.stdout + r.stderr)[-4000:]
    one_core = output_digests(repo)
    differ = sorted(
        p for p in two_cores.keys() | one_core.keys() if two_cores.get(p) != one_core.get(p)
    )
    assert not differ, f"{len(differ)} of {len(two_cores)} files differ: {differ[:20]}"
