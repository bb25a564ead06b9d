"""Issue 15: ``python -m pipeline.run_snakemake`` (what ``make reproduce`` runs) is Snakemake's
command line with at most one pending scheduler wake-up timer."""

from __future__ import annotations

import hashlib
import json
import os
import subprocess
import sys
import threading
from pathlib import Path

import snakemake
from snakemake.io import _IOFile
from snakemake.scheduling.job_scheduler import JobScheduler

from pipeline import run_snakemake
from pipeline.snakemake_checksums import known_checksums

ROOT = Path(__file__).resolve().parents[2]


def test_pinned_snakemake_is_the_patched_one() -> None:
    """The lock's Snakemake is the version the fix was written for, and it still has the method
    the fix replaces (an upgrade that renames it makes this fail, not the fix silently vanish)."""
    assert snakemake.__version__ == run_snakemake.PATCHED_VERSION
    subclass = type("Scheduler", (JobScheduler,), {})
    assert run_snakemake.one_pending_reevaluation(subclass)
    assert subclass._schedule_reevalutation is not JobScheduler._schedule_reevalutation
    assert run_snakemake.known_input_sizes(subclass)
    assert subclass.update_input_sizes is not JobScheduler.update_input_sizes
    io_subclass = type("IOFile", (_IOFile,), {})
    assert known_checksums(io_subclass)
    assert io_subclass.checksum is not _IOFile.checksum


def test_many_requests_one_timer() -> None:
    """Ten requests while one timer is pending wake the loop once; a request after it fired sets
    a new timer (the loop is never left without a wake-up)."""

    class Loop:
        def __init__(self) -> None:
            self._open_jobs = threading.Semaphore(0)

        def _schedule_reevalutation(self, delay: float) -> None:
            raise AssertionError("not patched")

    assert run_snakemake.one_pending_reevaluation(Loop)
    loop = Loop()
    for _ in range(10):
        loop._schedule_reevalutation(0.05)
    assert loop._open_jobs.acquire(timeout=10)
    assert not loop._open_jobs.acquire(timeout=0.3)
    loop._schedule_reevalutation(0.05)
    assert loop._open_jobs.acquire(timeout=10)


def test_no_method_no_patch() -> None:
    assert not run_snakemake.one_pending_reevaluation(type("Other", (), {}))


def _run(workdir: Path, *args: str) -> subprocess.CompletedProcess:
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    return subprocess.run(
        [sys.executable, "-m", "pipeline.run_snakemake", "--cores", "2", *args],
        cwd=workdir,
        env=env,
        capture_output=True,
        text=True,
        check=False,
    )


def test_runs_a_workflow_and_reports_failure(tmp_path: Path) -> None:
    """Jobs that wait for cores (the timer's case) all run; a failing job gives exit status 1."""
    (tmp_path / "Snakefile").write_text(
        "rule all:\n"
        "    input: expand('out/{i}.txt', i=range(5))\n"
        "rule one:\n"
        "    output: 'out/{i}.txt'\n"
        "    shell: 'sleep 0.2; echo {wildcards.i} > {output}'\n"
    )
    done = _run(tmp_path)
    assert done.returncode == 0, done.stderr
    assert [(tmp_path / f"out/{i}.txt").read_text() for i in range(5)] == [
        f"{i}\n" for i in range(5)
    ]
    (tmp_path / "Snakefile").write_text("rule bad:\n    output: 'bad.txt'\n    shell: 'exit 3'\n")
    failed = _run(tmp_path)
    assert failed.returncode == 1
    assert "Error in rule bad" in failed.stderr


def test_metadata_records_hold_each_inputs_checksum(tmp_path: Path) -> None:
    """Jobs of two outputs each, reading the same inputs (one rewritten between the runs): each
    output's metadata record holds the SHA-256 of the input versions it was made from."""
    (tmp_path / "a.txt").write_text("a\n")
    (tmp_path / "b.txt").write_text("b\n")
    (tmp_path / "Snakefile").write_text(
        "rule all:\n"
        "    input: expand('out/{i}.{x}', i=range(3), x=('p', 'q'))\n"
        "rule one:\n"
        "    input: 'a.txt', 'b.txt'\n"
        "    output: 'out/{i}.p', 'out/{i}.q'\n"
        "    shell: 'cat {input} > {output[0]}; cat {input} > {output[1]}'\n"
    )

    def recorded() -> set[tuple[str, str]]:
        pairs = set()
        for record in (tmp_path / ".snakemake" / "metadata").iterdir():
            pairs |= set(json.loads(record.read_text())["input_checksums"].items())
        return pairs

    def sha(name: str) -> str:
        return "sha256:" + hashlib.sha256((tmp_path / name).read_bytes()).hexdigest()

    done = _run(tmp_path)
    assert done.returncode == 0, done.stderr
    assert recorded() == {("a.txt", sha("a.txt")), ("b.txt", sha("b.txt"))}
    old_b = sha("b.txt")
    (tmp_path / "b.txt").write_text("b, changed\n")
    again = _run(tmp_path, "--forcerun", "one", "--rerun-triggers", "mtime")
    assert again.returncode == 0, again.stderr
    assert sha("b.txt") != old_b
    assert recorded() == {("a.txt", sha("a.txt")), ("b.txt", sha("b.txt"))}


def test_local_runs_leave_the_slurm_plugin_out(tmp_path: Path) -> None:
    """A run with no executor and no profile does not import the SLURM plugin (its import runs
    `scontrol show config`, which waits up to 10 s for an unanswering controller); a run with a
    profile imports every installed plugin, as Snakemake does."""
    (tmp_path / "Snakefile").write_text(
        "import sys\n"
        "print('SLURM_PLUGIN', 'snakemake_executor_plugin_slurm' in sys.modules)\n"
        "rule all:\n"
        "    output: 'x.txt'\n"
        "    shell: 'echo x > {output}'\n"
    )
    local = _run(tmp_path, "--dry-run")
    assert local.returncode == 0, local.stderr
    assert "SLURM_PLUGIN False" in local.stdout + local.stderr
    (tmp_path / "profile").mkdir()
    (tmp_path / "profile" / "config.yaml").write_text("printshellcmds: true\n")
    profiled = _run(tmp_path, "--dry-run", "--profile", "profile")
    assert profiled.returncode == 0, profiled.stderr
    assert "SLURM_PLUGIN True" in profiled.stdout + profiled.stderr


def test_local_run_doubts_answer_false(tmp_path: Path) -> None:
    """Every way Snakemake can be told to use an executor or a profile keeps the plugins."""
    for argv in (
        ["--executor", "slurm"],
        ["--executor=slurm"],
        ["--exec", "slurm"],
        ["-e", "slurm"],
        ["-eslurm"],
        ["--profile=p"],
        ["--workflow-profile", "p"],
    ):
        assert not run_snakemake.local_run(argv, {}, tmp_path), argv
    assert not run_snakemake.local_run([], {"SNAKEMAKE_PROFILE": "p"}, tmp_path)
    assert run_snakemake.local_run(["--cores", "2", "-n", "-p"], {}, tmp_path)
    (tmp_path / "profiles" / "default").mkdir(parents=True)
    assert not run_snakemake.local_run(["--cores", "2"], {}, tmp_path)
