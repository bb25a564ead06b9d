"""The Snakemake workflow: dry run in the repository, and a small real run in a copy of it."""

from __future__ import annotations

import os
import re
import shutil
import signal
import subprocess
import sys
from pathlib import Path

import pandas as pd
import pytest
import yaml

from pipeline.columns import (
    AUDIT_COLUMNS,
    ESTIMATE_COLUMNS,
    VERDICT_COLUMNS,
    VERDICT_KINDS,
    VERDICTS,
)

ROOT = Path(__file__).resolve().parents[1]
RULES_FILE = ROOT / "pipeline" / "rules" / "north_finding.smk"

pytestmark = pytest.mark.workflow


def _snakemake(*args: str, cwd: Path, timeout: float = 900) -> subprocess.CompletedProcess:
    """Run snakemake in its own session; on timeout kill the whole group (its jobs too)."""
    env = {**os.environ, "PYTHONPATH": str(cwd)}
    cmd = [sys.executable, "-m", "snakemake", *args]
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


def _job_counts(output: str) -> dict[str, int]:
    """The 'Job stats' table of a snakemake run or dry run: rule -> number of jobs."""
    start = output.index("Job stats:")
    counts = {}
    for line in output[start:].splitlines()[3:]:
        m = re.match(r"^(\w+)\s+(\d+)$", line.strip())
        if not m:
            break
        counts[m.group(1)] = int(m.group(2))
    return counts


def test_dry_run_lists_every_north_finding_rule():
    """``snakemake -n`` in the repository root parses, validates every scenario and plans every
    rule (``--forceall``: results of an earlier run would otherwise hide up-to-date rules)."""
    r = _snakemake("-n", "--cores", "1", "--forceall", "--nolock", cwd=ROOT, timeout=300)
    assert r.returncode == 0, r.stderr[-3000:]
    counts = _job_counts(r.stdout + r.stderr)
    rules = set(re.findall(r"^rule (\w+):", RULES_FILE.read_text(encoding="utf-8"), flags=re.M))
    assert "north_finding_simulate" in rules and len(rules) >= 8
    planned = {name for name, n in counts.items() if n > 0}
    # north_finding_all is a target-only rule (no job of its own); every other rule plans a job
    assert rules - {"north_finding_all"} <= planned, rules - planned
    n_scenarios = len(list((ROOT / "config" / "scenarios" / "north_finding").glob("*.yaml")))
    assert counts["north_finding_simulate"] == n_scenarios


# --------------------------------------------------------------------------------------------
# a real run in a reduced copy of the repository
# --------------------------------------------------------------------------------------------
def _copy_repo(dest: Path) -> None:
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


@pytest.fixture(scope="module")
def workflow_run(tmp_path_factory):
    repo = tmp_path_factory.mktemp("repo")
    _copy_repo(repo)
    scenarios = repo / "config" / "scenarios" / "north_finding"
    for f in scenarios.glob("*.yaml"):
        if f.name not in ("paper.yaml", "example_readings.yaml"):
            f.unlink()
    _reduce_paper(scenarios / "paper.yaml")
    _reduce_altimeter(repo)
    assert not (repo / "results").exists()
    r = _snakemake("--cores", "2", "--quiet", cwd=repo, timeout=600)
    assert r.returncode == 0, (r.stdout + r.stderr)[-5000:]
    return repo


@pytest.mark.slow
def test_verdicts_one_row_per_published_item_and_claim(workflow_run):
    repo = workflow_run
    published = yaml.safe_load(
        (repo / "config" / "published" / "north_finding.yaml").read_text(encoding="utf-8")
    )
    expected_ids = [i["id"] for i in published["items"]] + [
        c["id"] for c in published.get("claims", [])
    ]
    verdicts = pd.read_csv(
        repo / "results" / "north_finding" / "verdicts.csv", dtype=str, keep_default_na=False
    )
    assert list(verdicts.columns) == VERDICT_COLUMNS
    assert sorted(verdicts["id"]) == sorted(expected_ids)
    assert verdicts["id"].is_unique
    assert set(verdicts["kind"]) <= set(VERDICT_KINDS)
    assert set(verdicts["verdict"]) <= set(VERDICTS)
    kinds = {i["id"]: i["kind"] for i in published["items"]}
    kinds.update({c["id"]: "claim" for c in published.get("claims", [])})
    assert dict(zip(verdicts["id"], verdicts["kind"], strict=True)) == kinds


@pytest.mark.slow
def test_equation_audit_written_with_contract_columns(workflow_run):
    audit = pd.read_csv(
        workflow_run / "results" / "north_finding" / "equation_audit.csv", dtype=str
    )
    assert list(audit.columns) == AUDIT_COLUMNS
    assert len(audit) >= 71
    assert set(audit["status"]) <= {"match", "differs", "not_checkable"}
    assert "47.E" in set(audit["equation"])


@pytest.mark.slow
def test_report_html_has_the_tables(workflow_run):
    html = (workflow_run / "reports" / "north_finding.html").read_text(encoding="utf-8")
    assert "Table 9" in html
    notebook = (workflow_run / "reports" / "notebooks" / "north_finding.html").read_text(
        encoding="utf-8"
    )
    assert "<html" in notebook.lower() and len(notebook) > 10_000


@pytest.mark.slow
def test_estimates_of_both_scenarios(workflow_run):
    results = workflow_run / "results" / "north_finding"
    dirs = sorted(p.name for p in results.iterdir() if (p / "estimates.csv").is_file())
    assert dirs == ["example_readings", "paper"]
    for name in dirs:
        frame = pd.read_csv(results / name / "estimates.csv")
        assert list(frame.columns) == ESTIMATE_COLUMNS
        assert len(frame) > 0 and frame["estimate"].notna().all()
    paper = pd.read_csv(results / "paper" / "estimates.csv")
    assert set(paper["sensor"]) == {"ideal", "real"}
    trials = pd.read_csv(results / "paper" / "mc_trials.csv")
    assert trials["trial"].max() == 39  # the reduced scenario ran, not the repository's


@pytest.mark.slow
def test_bad_scenario_stops_the_workflow_before_any_job(workflow_run):
    repo = workflow_run
    scenarios = repo / "config" / "scenarios" / "north_finding"
    raw = yaml.safe_load((scenarios / "paper.yaml").read_text(encoding="utf-8"))
    raw["site"]["lat_deg"] = 95
    bad = scenarios / "zz_bad_latitude.yaml"
    bad.write_text(yaml.safe_dump(raw), encoding="utf-8")
    before = {p: p.stat().st_mtime_ns for p in (repo / "results").rglob("*") if p.is_file()}
    try:
        r = _snakemake("--cores", "1", "--forceall", cwd=repo, timeout=300)
    finally:
        bad.unlink()
    assert r.returncode != 0
    err = r.stdout + r.stderr
    assert "zz_bad_latitude.yaml" in err and "site.lat_deg" in err
    after = {p: p.stat().st_mtime_ns for p in (repo / "results").rglob("*") if p.is_file()}
    assert after == before  # no job ran


@pytest.mark.slow
def test_altimeter_attitude_outputs(workflow_run):
    from pipeline.altimeter_attitude.workflow import FIGURES, SWEEP_FIGURE
    from pipeline.columns import RMS_SUMMARY_COLUMNS, SWEEP_COLUMNS

    results = workflow_run / "results" / "altimeter_attitude"
    summary = pd.read_csv(results / "paper" / "rms_summary.csv")
    assert list(summary.columns) == RMS_SUMMARY_COLUMNS
    assert (summary["n_runs"] == 10).all()  # the reduced scenario ran
    published = yaml.safe_load(
        (workflow_run / "config" / "published" / "altimeter_attitude.yaml").read_text(
            encoding="utf-8"
        )
    )
    verdicts = pd.read_csv(results / "verdicts.csv", dtype=str, keep_default_na=False)
    assert list(verdicts.columns) == VERDICT_COLUMNS
    ids = [v["id"] for v in published["values"]] + [c["id"] for c in published["claims"]]
    assert sorted(verdicts["id"]) == sorted(ids)
    assert set(verdicts["verdict"]) <= set(VERDICTS)
    sweep = pd.read_csv(results / "sweep.csv")
    assert list(sweep.columns) == SWEEP_COLUMNS and set(sweep["value"]) == {0.5, 1.0}
    for name in [*FIGURES, SWEEP_FIGURE]:
        assert (results / "figures" / name).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n", name
    audit = pd.read_csv(results / "equation_audit.csv", dtype=str)
    assert list(audit.columns) == AUDIT_COLUMNS and "13a" in set(audit["equation"])
    page = (workflow_run / "reports" / "altimeter_attitude.html").read_text(encoding="utf-8")
    assert "rms_summary" in page or "Fig. 7" in page
