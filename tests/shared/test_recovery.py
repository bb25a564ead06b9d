"""`make reproduce` recovers by itself after a kill: a real run is killed with SIGKILL while a job
is running (Snakemake's lock and the job's incomplete marker are left behind), and the next
`make reproduce` completes and writes the same bytes as the uninterrupted run."""

from __future__ import annotations

import hashlib
import os
import shutil
import signal
import subprocess
import time
from pathlib import Path

import pytest

from tests.hang_guard import HANG_GUARD_S
from tests.workflow_harness import ROOT, output_digests, snakemake

pytestmark = [pytest.mark.slow, pytest.mark.workflow]

#: the job killed mid-way, and the outputs compared byte for byte after the recovery
TARGET = "results/platform_drift/stationary/errors.csv"
COMPARED = ("results/platform_drift", "reports/platform_drift.html")


def _digests(repo: Path) -> dict[str, str]:
    out = {}
    for top in COMPARED:
        path = repo / top
        files = [path] if path.is_file() else sorted(p for p in path.rglob("*") if p.is_file())
        for f in files:
            rel = f.relative_to(repo).as_posix()
            if "/benchmarks/" in rel or "/logs/" in rel:  # wall-clock timings and job logs
                continue
            out[rel] = hashlib.sha256(f.read_bytes()).hexdigest()
    return out


def _make(repo: Path, *args: str, **kw) -> subprocess.Popen:
    env = {**os.environ, "PYTHONPATH": str(repo)}
    return subprocess.Popen(
        ["make", "--no-print-directory", *args],
        cwd=repo,
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.STDOUT,
        text=True,
        start_new_session=True,
        **kw,
    )


def _incomplete(repo: Path) -> bool:
    marks = repo / ".snakemake" / "incomplete"
    return marks.is_dir() and any(marks.iterdir())


@pytest.mark.skipif(not (ROOT / ".venv" / "bin" / "snakemake").exists(), reason="needs .venv")
def test_make_reproduce_recovers_after_kill_9(workflow_run, tmp_path):
    repo = tmp_path / "repo"
    shutil.copytree(workflow_run, repo, symlinks=True)
    (repo / ".venv").unlink(missing_ok=True)
    (repo / ".venv").symlink_to(ROOT / ".venv")
    before = _digests(repo)
    assert TARGET in before

    # the paper's outputs removed (a missing intermediate file alone is not rerun while what
    # depends on it is up to date); the run is killed while its first job runs
    shutil.rmtree(repo / "results" / "platform_drift")
    (repo / "reports" / "platform_drift.html").unlink()
    proc = _make(repo, "reproduce", "CORES=1")
    deadline = time.monotonic() + HANG_GUARD_S  # a bound on a hung run, not a speed limit
    while not _incomplete(repo) and proc.poll() is None and time.monotonic() < deadline:
        time.sleep(0.02)
    killed = proc.poll() is None
    if killed:
        os.killpg(proc.pid, signal.SIGKILL)
    out, _ = proc.communicate()
    if not killed:
        pytest.fail(f"the run ended before a job had started: nothing was killed:\n{out[-3000:]}")
    assert (repo / ".snakemake" / "locks").is_dir() and any(
        (repo / ".snakemake" / "locks").iterdir()
    )

    # a plain Snakemake call now refuses (locked): what the user met before the fix
    locked = snakemake("--cores", "1", cwd=repo, timeout=HANG_GUARD_S)  # a dry run takes no lock
    assert locked.returncode != 0 and "lock" in (locked.stdout + locked.stderr).lower()

    again = _make(repo, "reproduce", "CORES=1")
    out, _ = again.communicate(timeout=HANG_GUARD_S)
    assert again.returncode == 0, out[-4000:]
    assert "releasing it" in out
    assert _digests(repo) == before
    # Snakemake's report was missing before the run: the run wrote it at its end (in its own
    # process, --report-after-run), through a temporary file it renamed
    assert "--report-after-run" in out and "Report created" in out
    assert "snakemake.html is up to date" in out
    assert (repo / "reports" / "snakemake.html").stat().st_size > 0
    assert not list((repo / "reports").glob(".snakemake-report.*"))


def test_a_second_make_reproduce_in_the_same_checkout_is_refused(tmp_path):
    """The make-level lock: while one `make reproduce` holds it, another one says so and stops
    (it never releases the first run's Snakemake lock)."""
    repo = tmp_path / "repo"
    repo.mkdir()
    shutil.copy2(ROOT / "Makefile", repo / "Makefile")
    (repo / ".snakemake").mkdir()
    (repo / ".venv").mkdir()
    (repo / "environment.lock").write_text("", encoding="utf-8")
    (repo / "pyproject.toml").write_text("", encoding="utf-8")
    time.sleep(0.01)
    (repo / ".venv" / ".stamp").write_text("", encoding="utf-8")
    time.sleep(0.01)
    (repo / ".venv" / ".project-stamp").write_text("", encoding="utf-8")
    holder = subprocess.Popen(
        ["flock", str(repo / ".snakemake" / "make-reproduce.lock"), "sleep", "60"],
        start_new_session=True,
    )
    try:
        for _ in range(500):  # until the holder has the lock
            probe = subprocess.run(
                ["flock", "-n", str(repo / ".snakemake" / "make-reproduce.lock"), "true"],
                check=False,
            )
            if probe.returncode != 0:
                break
            time.sleep(0.01)
        second = _make(repo, "reproduce")
        out, _ = second.communicate(timeout=HANG_GUARD_S)
        assert second.returncode != 0 and "another 'make reproduce' is running" in out, out
    finally:
        os.killpg(holder.pid, signal.SIGKILL)
        holder.wait()


def test_a_failing_step_keeps_the_previous_outputs(workflow_run, tmp_path):
    """A step that fails (here: every reader of a results file that was replaced by garbage)
    leaves its previous outputs in place, byte for byte, and says so in one line per job;
    nothing else under results/ or reports/ changes."""
    repo = tmp_path / "repo"
    shutil.copytree(workflow_run, repo, symlinks=True)
    broken = repo / "results" / "north_finding" / "paper" / "estimates.csv"
    before = output_digests(repo, logs=False)  # the failing jobs' logs say why they failed
    broken.write_text("this is not,the estimates\n\x00\n", encoding="utf-8")
    before[broken.relative_to(repo).as_posix()] = hashlib.sha256(broken.read_bytes()).hexdigest()
    r = snakemake("--cores", "1", "--keep-going", cwd=repo, timeout=HANG_GUARD_S)
    out = r.stdout + r.stderr
    assert r.returncode != 0, out[-3000:]
    assert "Restored previous version of results/north_finding/verdicts.csv" in out, out[-4000:]
    assert "Traceback" not in out, out[-4000:]
    assert output_digests(repo, logs=False) == before
