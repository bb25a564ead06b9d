"""A fourth paper plugged in with no shared file edited: the synthetic pendulum paper of
``tests/synthetic_paper/`` goes through derive -> audit -> codegen check -> simulate ->
verdicts -> figure -> notebook -> page -> combined report.

This is also the worked example of README "Adding a paper": the files under
``tests/synthetic_paper/`` are laid out as in the repository; installing the paper is copying
them in and adding its slug to ``papers:`` in ``config/config.yaml``.
"""

from __future__ import annotations

import os
import shutil
import subprocess
import sys
from pathlib import Path

import pandas as pd
import pytest
import yaml

from pipeline.columns import AUDIT_COLUMNS
from tests.hang_guard import HANG_GUARD_S
from tests.workflow_harness import ROOT, copy_repo, snakemake

SYNTHETIC = ROOT / "tests" / "synthetic_paper"
SLUG = "pendulum"

pytestmark = [pytest.mark.workflow]


def install(repo: Path, papers: list[str]) -> list[str]:
    """Copy the synthetic paper's files into ``repo`` (each one new: nothing is overwritten)
    and set ``papers:``; returns the files added."""
    added = []
    for src in sorted(p for p in SYNTHETIC.rglob("*") if p.is_file()):
        if "__pycache__" in src.parts:
            continue
        rel = src.relative_to(SYNTHETIC)
        dest = repo / rel
        assert not dest.exists(), f"{rel} exists already: installing a paper edits no file"
        dest.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(src, dest)
        added.append(str(rel))
    config = repo / "config" / "config.yaml"
    raw = yaml.safe_load(config.read_text(encoding="utf-8"))
    raw["papers"] = papers  # the one line of config
    config.write_text(yaml.safe_dump(raw, sort_keys=False), encoding="utf-8")
    return added


def test_the_synthetic_paper_adds_files_only():
    """Its files live where a paper's files live (DESIGN.md), none of them shared."""
    files = [str(p.relative_to(SYNTHETIC)) for p in SYNTHETIC.rglob("*") if p.is_file()]
    allowed = (
        f"derivations/{SLUG}/",
        f"pipeline/{SLUG}/",
        f"pipeline/generated/{SLUG}.py",
        f"config/scenarios/{SLUG}/",
        f"config/published/{SLUG}.yaml",
        f"config/schemas/{SLUG}_",
        f"notebooks/{SLUG}.ipynb",
    )
    outside = [f for f in files if not f.startswith(allowed) and "__pycache__" not in f]
    assert not outside, outside
    assert not (ROOT / "pipeline" / SLUG).exists()


def test_a_fourth_paper_plans_beside_the_others(tmp_path):
    """With the synthetic paper added to the three, the dry run plans its steps and keeps
    every other paper's."""
    copy_repo(tmp_path)
    papers = [*yaml.safe_load((ROOT / "config" / "config.yaml").read_text())["papers"], SLUG]
    install(tmp_path, papers)
    r = snakemake("-n", "--cores", "1", "--forceall", cwd=tmp_path, timeout=HANG_GUARD_S)
    out = r.stdout + r.stderr
    assert r.returncode == 0, out[-3000:]
    for rule in (f"{SLUG}_simulate", f"{SLUG}_verdicts", f"{SLUG}_figures", f"{SLUG}_report"):
        assert f"rule {rule}:" in out, rule
    assert "paper=pendulum" in out and "paper=north_finding" in out


def test_the_synthetic_papers_audit_gives_its_wrong_equation_a_kind(tmp_path):
    """The paper's audit on its own (its command line, no workflow): eq. 4's /8 is a
    ``differs`` of kind paper_error, the other rows carry no kind."""
    copy_repo(tmp_path)
    install(tmp_path, [SLUG])
    out = tmp_path / "equation_audit.csv"
    r = subprocess.run(
        [sys.executable, "-m", f"derivations.{SLUG}.audit", "--out", str(out)],
        cwd=tmp_path,
        env={**os.environ, "PYTHONPATH": str(tmp_path)},
        capture_output=True,
        text=True,
        timeout=HANG_GUARD_S,
    )
    assert r.returncode == 0, r.stderr[-3000:]
    audit = pd.read_csv(out, dtype=str, keep_default_na=False)
    assert list(audit.columns) == AUDIT_COLUMNS
    pairs = zip(audit["status"], audit["kind"], strict=True)
    rows = dict(zip(audit["equation"], pairs, strict=True))
    assert rows == {"1": ("match", ""), "3": ("match", ""), "4": ("differs", "paper_error")}


@pytest.mark.slow
def test_the_synthetic_paper_runs_end_to_end(tmp_path):
    copy_repo(tmp_path)
    install(tmp_path, [SLUG])
    r = snakemake("--cores", "2", cwd=tmp_path, timeout=HANG_GUARD_S)
    assert r.returncode == 0, (r.stdout + r.stderr)[-5000:]
    results = tmp_path / "results" / SLUG

    audit = pd.read_csv(results / "equation_audit.csv", dtype=str, keep_default_na=False)
    statuses = dict(zip(audit["equation"], audit["status"], strict=True))
    assert statuses == {"1": "match", "3": "match", "4": "differs"}  # eq. 4's /8 is wrong
    assert dict(zip(audit["equation"], audit["kind"], strict=True))["4"] == "paper_error"
    assert "is fresh" in (results / "codegen_check.txt").read_text()

    periods = pd.read_csv(results / "paper" / "periods.csv")
    # the integrated period grows with the amplitude as eq. 4's derived form says, to O(a^4)
    small = periods[periods["amplitude_deg"] <= 10]
    rel = (small["period_s"] - small["first_order_s"]).abs() / small["period_s"]
    assert (rel < 1e-5).all(), rel

    verdicts = pd.read_csv(results / "verdicts.csv", dtype=str, keep_default_na=False)
    got = dict(zip(verdicts["id"], verdicts["verdict"], strict=True))
    assert got == {
        "T1.period": "reproduced",
        "F1.period_60": "reproduced",
        "C1.isochronous": "upheld",
    }
    assert (verdicts["tolerance"] != "").all() and (verdicts["reason"] != "").all()

    for name in ("fig1_period.png", "fig1_period.svg"):
        assert (results / "figures" / name).stat().st_size > 1000, name
    page = (tmp_path / "reports" / f"{SLUG}.html").read_text(encoding="utf-8")
    assert "The period of a simple pendulum" in page and "C1.isochronous" in page
    notebook = (tmp_path / "reports" / "notebooks" / f"{SLUG}.html").read_text(encoding="utf-8")
    # eq. 1 as the executed cell shows it: MathML built offline, no LaTeX left for a script
    assert "<math" in notebook and "<mi>sin</mi>" in notebook and "\u03b8" in notebook
    assert "\\sin" not in notebook
    combined = (tmp_path / "reports" / "reproduction.html").read_text(encoding="utf-8")
    assert "The period of a simple pendulum" in combined
    assert (tmp_path / "reports" / "reproduction.pdf").read_bytes()[:5] == b"%PDF-"
