"""Running the Snakemake workflow from tests: ``snakemake(...)`` in its own process group, and
``reduced_run(dest)``, a real run of the whole default workflow in a reduced copy of the
repository (fewer trials and scenarios) that the workflow, report and PDF tests share through
the session fixtures ``workflow_run`` and ``results_repo`` of ``tests/conftest.py``.
"""

from __future__ import annotations

import fcntl
import hashlib
import os
import re
import shutil
import signal
import subprocess
import sys
from pathlib import Path

import pytest
import yaml

from tests.hang_guard import HANG_GUARD_S

ROOT = Path(__file__).resolve().parents[1]
SLUGS = tuple(
    yaml.safe_load((ROOT / "config" / "config.yaml").read_text(encoding="utf-8"))["papers"]
)


def have_results(root: Path = ROOT) -> bool:
    """Whether the workflow has run in ``root``: each paper's audit, equation forms, verdicts,
    page and executed notebook (what the combined-report tests read) are there."""
    need = []
    for slug in SLUGS:
        r = root / "results" / slug
        need += [r / "equation_audit.csv", r / "verdicts.csv", r / "equation_math.json"]
        need += [root / "reports" / f"{slug}.html", root / "reports" / "notebooks" / f"{slug}.html"]
    return all(p.is_file() for p in need)


#: Marks of a test that reads workflow results: on a fresh clone they come from the reduced
#: run (``workflow_run``), which makes the test slow.
NEEDS_RUN = [] if have_results(ROOT) else [pytest.mark.slow, pytest.mark.workflow]


def snakemake(*args: str, cwd: Path, timeout: float = HANG_GUARD_S) -> subprocess.CompletedProcess:
    """Run snakemake in its own session, as ``make reproduce`` runs it (pipeline.run_snakemake);
    on timeout kill the whole group (its jobs too)."""
    env = {**os.environ, "PYTHONPATH": str(cwd)}
    cmd = [sys.executable, "-m", "pipeline.run_snakemake", *args]
    proc = subprocess.Popen(
        cmd,
        cwd=cwd,
        env=env,
        stdout=subprocess.PIPE,
        stderr=subprocess.PIPE,
        text=True,
        start_new_session=True,
    )
    try:
        out, err = proc.communicate(timeout=timeout)
    except subprocess.TimeoutExpired:
        os.killpg(proc.pid, signal.SIGKILL)
        out, err = proc.communicate()
        pytest.fail(
            f"snakemake {' '.join(args)} did not finish in {timeout} s:\n{(out + err)[-3000:]}"
        )
    return subprocess.CompletedProcess(cmd, proc.returncode, out, err)


def copy_repo(dest: Path) -> None:
    files = subprocess.run(
        ["git", "ls-files", "-co", "--exclude-standard", "-z"],
        cwd=ROOT,
        capture_output=True,
        text=True,
        check=True,
    ).stdout.split("\0")
    for name in filter(None, files):
        src = ROOT / name
        if not src.is_file():  # deleted in the working tree
            continue
        target = dest / name
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(src, target)


def _reduce_paper(path: Path) -> None:
    """Fewer trials, keeping the file's comments (the report shows the scenario and decisions)."""
    text = path.read_text(encoding="utf-8")
    new, n1 = re.subn(r"(?m)^(monte_carlo:\n  n_trials:) \d+", r"\1 40", text)
    new, n2 = re.subn(
        r"(?m)^(sensitivity:\n  n_avg:) \[[^\]]*\]\n  n_trials: \d+",
        r"\1 [10000, 1000000]\n  n_trials: 10",
        new,
    )
    assert n1 == 1 and n2 == 1, "paper.yaml layout changed: update _reduce_paper"
    path.write_text(new, encoding="utf-8")
    raw = yaml.safe_load(new)
    assert raw["monte_carlo"]["n_trials"] == 40 and raw["sensitivity"] == {
        "n_avg": [10000, 1000000],
        "n_trials": 10,
    }


def _reduce_altimeter(repo: Path) -> None:
    """altimeter_attitude: the paper scenario only, 10 runs; a two-point sweep of 3 runs."""
    scenarios = repo / "config" / "scenarios" / "altimeter_attitude"
    for f in scenarios.glob("*.yaml"):
        if f.name != "paper.yaml":
            f.unlink()
    paper = scenarios / "paper.yaml"
    text, n = re.subn(r"(?m)^(  n_runs:) \d+", r"\1 10", paper.read_text(encoding="utf-8"))
    assert n == 1, "altimeter_attitude paper.yaml layout changed: update _reduce_altimeter"
    paper.write_text(text, encoding="utf-8")
    config = repo / "config" / "config.yaml"
    raw = yaml.safe_load(config.read_text(encoding="utf-8"))
    raw["altimeter_attitude"]["sweep"]["n_runs"] = 3
    raw["altimeter_attitude"]["sweep"]["values"] = {"intensity": [0.5, 1.0]}
    config.write_text(yaml.safe_dump(raw, sort_keys=False), encoding="utf-8")


def reduced_run(repo: Path) -> Path:
    """Copy the repository (tracked and untracked, not ignored files) to ``repo``, reduce it and
    run the default workflow there (every rule, reports included); returns ``repo``."""
    copy_repo(repo)
    scenarios = repo / "config" / "scenarios" / "north_finding"
    for f in scenarios.glob("*.yaml"):
        if f.name not in ("paper.yaml", "example_readings.yaml"):
            f.unlink()
    _reduce_paper(scenarios / "paper.yaml")
    _reduce_altimeter(repo)
    assert not (repo / "results").exists()
    r = snakemake("--cores", "2", "--quiet", cwd=repo, timeout=HANG_GUARD_S)
    assert r.returncode == 0, (r.stdout + r.stderr)[-5000:]
    return repo


def once_across_workers(dest: Path, build) -> Path:
    """``build(dest)`` run by exactly one of the pytest-xdist workers that call this with the same
    ``dest``; the others block on a file lock until it is done and get ``dest``. A build that
    failed fails every caller with its message (it is not retried)."""
    dest.parent.mkdir(parents=True, exist_ok=True)
    done, failed = dest.with_name(dest.name + ".done"), dest.with_name(dest.name + ".failed")
    with open(dest.with_name(dest.name + ".lock"), "w") as lock:
        fcntl.flock(lock, fcntl.LOCK_EX)
        if not done.exists() and not failed.exists():
            try:
                dest.mkdir()
                build(dest)
            except BaseException as exc:
                failed.write_text(f"{type(exc).__name__}: {exc}"[-5000:], encoding="utf-8")
                raise
            done.write_text("", encoding="utf-8")
    if failed.exists():
        pytest.fail(f"the shared build of {dest} failed in another worker:\n{failed.read_text()}")
    return dest


def output_digests(repo: Path, logs: bool = True) -> dict[str, str]:
    """sha256 of every file under results/ and reports/ (benchmark files, which hold wall-clock
    timings by design, excepted; the job logs included unless ``logs`` is false: they print no
    timings), by path relative to ``repo``."""
    out = {}
    for top in ("results", "reports"):
        for f in sorted(p for p in (repo / top).rglob("*") if p.is_file()):
            rel = f.relative_to(repo).as_posix()
            if "/benchmarks/" in rel or (not logs and "/logs/" in rel):  # wall-clock timings
                continue
            out[rel] = hashlib.sha256(f.read_bytes()).hexdigest()
    return out
