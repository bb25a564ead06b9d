"""The Snakemake workflow: dry run in the repository, and a small real run in a copy of it."""

from __future__ import annotations

import json
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pandas as pd
import pytest
import yaml

from pipeline.columns import AUDIT_COLUMNS, VERDICT_FILE_COLUMNS, VERDICT_KINDS, VERDICTS
from pipeline.north_finding.columns import ESTIMATE_COLUMNS
from tests.hang_guard import HANG_GUARD_S
from tests.workflow_harness import ROOT, snakemake

pytestmark = pytest.mark.workflow


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
    assert list(verdicts.columns) == VERDICT_FILE_COLUMNS
    # one row per item and claim, or one per curve or averaging count (<id>/<suffix>)
    assert sorted(set(verdicts["id"].str.split("/").str[0])) == sorted(expected_ids)
    assert verdicts["id"].is_unique
    assert set(verdicts["kind"]) <= set(VERDICT_KINDS)
    assert set(verdicts["verdict"]) <= set(VERDICTS)
    assert (verdicts["tolerance"] != "").all() and (verdicts["reason"] != "").all()
    kinds = {i["id"]: i["kind"] for i in published["items"]}
    kinds.update({c["id"]: "claim" for c in published.get("claims", [])})
    base = verdicts["id"].str.split("/").str[0]
    assert dict(zip(base, verdicts["kind"], strict=True)) == kinds


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
def test_bad_scenario_stops_the_workflow_before_any_job(workflow_run, tmp_path):
    repo = tmp_path / "repo"  # a copy: other workers read workflow_run meanwhile
    shutil.copytree(workflow_run, repo, symlinks=True)
    scenarios = repo / "config" / "scenarios" / "north_finding"
    raw = yaml.safe_load((scenarios / "paper.yaml").read_text(encoding="utf-8"))
    raw["site"]["lat_deg"] = 95
    bad = scenarios / "zz_bad_latitude.yaml"
    bad.write_text(yaml.safe_dump(raw), encoding="utf-8")
    before = {p: p.stat().st_mtime_ns for p in (repo / "results").rglob("*") if p.is_file()}
    try:
        r = snakemake("--cores", "1", "--forceall", cwd=repo, timeout=HANG_GUARD_S)
    finally:
        bad.unlink()
    assert r.returncode != 0
    err = r.stdout + r.stderr
    assert "zz_bad_latitude.yaml" in err and "site.lat_deg" in err
    after = {p: p.stat().st_mtime_ns for p in (repo / "results").rglob("*") if p.is_file()}
    assert after == before  # no job ran


@pytest.mark.slow
def test_altimeter_attitude_outputs(workflow_run):
    from pipeline.altimeter_attitude.columns import RMS_SUMMARY_COLUMNS, SWEEP_COLUMNS
    from pipeline.altimeter_attitude.workflow import FIGURES, SWEEP_FIGURE

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
    assert list(verdicts.columns) == VERDICT_FILE_COLUMNS
    ids = [v["id"] for v in published["items"]] + [c["id"] for c in published["claims"]]
    # one row per item and claim, or one per curve or window (<id>/<suffix>)
    assert sorted(set(verdicts["id"].str.split("/").str[0])) == sorted(ids)
    assert set(verdicts["verdict"]) <= set(VERDICTS)
    sweep = pd.read_csv(results / "sweep.csv")
    assert list(sweep.columns) == SWEEP_COLUMNS and set(sweep["value"]) == {0.5, 1.0}
    for name in [*FIGURES, SWEEP_FIGURE]:
        assert (results / "figures" / name).read_bytes()[:8] == b"\x89PNG\r\n\x1a\n", name
    audit = pd.read_csv(results / "equation_audit.csv", dtype=str)
    assert list(audit.columns) == AUDIT_COLUMNS and "13a" in set(audit["equation"])
    page = (workflow_run / "reports" / "altimeter_attitude.html").read_text(encoding="utf-8")
    assert "rms_summary" in page or "Fig. 7" in page


# --------------------------------------------------------------------------------------------
# Snakemake ecosystem: lint, snakefmt, --report, the conda environment of the rules
# --------------------------------------------------------------------------------------------
def test_snakemake_lint_is_clean():
    r = snakemake("--lint", cwd=ROOT, timeout=HANG_GUARD_S)
    out = r.stdout + r.stderr
    assert r.returncode == 0, out[-3000:]
    assert "Lints for" not in out and "good condition" in out, out[-3000:]


def test_snakefiles_are_snakefmt_formatted():
    files = ["Snakefile", *sorted(str(p) for p in (ROOT / "pipeline" / "rules").glob("*.smk"))]
    r = subprocess.run(
        [sys.executable, "-m", "snakefmt", "--check", "--diff", *files],
        cwd=ROOT,
        capture_output=True,
        text=True,
        timeout=HANG_GUARD_S,
    )
    assert r.returncode == 0, (r.stdout + r.stderr)[-3000:]


def _report_categories(html: str, names) -> dict[str, dict[str, list[str]]]:
    """The category -> subcategory -> files tables embedded in a Snakemake report."""
    decoder = json.JSONDecoder()
    found = {}
    for name in names:
        m = re.search(rf'"{name}": (\{{"[^"]+": \[)', html)
        assert m, f"category {name} not in the report"
        found[name], _ = decoder.raw_decode(html, m.start(1))
    return found


@pytest.mark.slow
def test_snakemake_report_has_a_category_per_paper(workflow_run, tmp_path):
    """``snakemake --report`` builds; every paper is a category holding its figures (labelled
    with the paper's figure numbers), audit, verdicts and pages; the combined reports too."""
    out = tmp_path / "snakemake.html"
    r = snakemake("--report", str(out), cwd=workflow_run, timeout=HANG_GUARD_S)
    assert r.returncode == 0, (r.stdout + r.stderr)[-3000:]
    html = out.read_text(encoding="utf-8")
    papers = yaml.safe_load((workflow_run / "config" / "config.yaml").read_text())["papers"]
    cats = _report_categories(html, [*papers, "reproduction"])
    for slug in papers:
        sub = cats[slug]
        assert sub["Equation audit"] == [f"results/{slug}/equation_audit.csv"], sub
        assert sub["Verdicts"] == [f"results/{slug}/verdicts.csv"], sub
        assert f"reports/{slug}.html" in sub["Pages"], sub
        figures = sorted(Path(f).name for f in sub["Figures"])
        on_disk = sorted(
            p.name for p in (workflow_run / "results" / slug / "figures").glob("*.png")
        )
        assert figures == on_disk
    assert sorted(cats["reproduction"]["Reports"]) == [
        "reports/reproduction.html",
        "reports/reproduction.pdf",
    ]
    # the figure labels come from the file names and each rule's paper figure numbers
    labels = dict(re.findall(r'"filename": "([^"]+\.png)", "labels": \{"figure": "([^"]+)"', html))
    assert labels["fig7_lkf_rms_error.png"] == "Fig. 7"
    assert labels["fig5_stationary.png"] == "Fig. 5"
    assert labels["fig1_roll.png"] == "Fig. 1"
    assert labels["fig6_sensitivity.png"] == "not in the paper"
    assert labels["fig9_latitude.png"] == "not in the paper"
    assert labels["fig_sweep.png"] == "not in the paper"
    # the captions are rendered (Jinja: the paper's slug from the rule name)
    assert 'Figure of <tt class=\\"docutils literal\\">platform_drift</tt>' in html


def _lock_versions() -> dict[str, str]:
    text = (ROOT / "environment.lock").read_text(encoding="utf-8")
    return {m[0].lower(): m[1] for m in re.findall(r"(?m)^([A-Za-z0-9_.-]+)==(\S+)", text)}


def test_conda_env_pins_match_the_lock():
    """The rules' conda environment (``snakemake --sdm conda``) pins the lock's versions of every
    runtime top-level requirement; the workflow's rules all name it."""
    env = yaml.safe_load((ROOT / "pipeline" / "envs" / "inertial-repro.yaml").read_text())
    pip = next(d["pip"] for d in env["dependencies"] if isinstance(d, dict))
    pins = dict(p.lower().split("==") for p in pip)
    lock = _lock_versions()
    assert {k: lock.get(k) for k in pins} == pins
    assert "python=3.11" in env["dependencies"]
    runtime = {"numpy", "scipy", "sympy", "pandas", "matplotlib", "jupyter", "nbconvert",
               "nbclient", "ipykernel", "typst", "snakemake", "pyyaml", "jsonschema"}  # fmt: skip
    assert runtime <= set(pins)
    for smk in (ROOT / "pipeline" / "rules").glob("*.smk"):
        text = smk.read_text(encoding="utf-8")
        n_conda = len(re.findall(r"\n\s+conda:\n\s+ENV\n", text))
        assert text.count("    script:") == n_conda, smk.name
