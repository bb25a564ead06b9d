"""A user's own config file (``make reproduce CONFIG=FILE``), checked by pipeline.check_config
before Snakemake reads it: every bad file is one ``error:`` line naming the file, the field or
place, the value and what is allowed; exit status 2; no traceback."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from pipeline.check_config import main

ROOT = Path(__file__).resolve().parents[2]

CASES = [  # id, file bytes, what the message must name (besides the file)
    ("binary", b"\xff\xfe\x00papers", ["byte 0", "not UTF-8"]),
    ("bad_yaml", b"papers: [north_finding\n  x: : :\n", ["line 2", "not valid YAML"]),
    ("python_tag", b"papers: !!python/object:os.system x\n", ["python/object", "not allowed"]),
    ("duplicate_key", b"papers: [north_finding]\npapers: [platform_drift]\n", ["line 2", "once"]),
    ("nan", b"results_dir: .nan\n", ["results_dir", "nan", "finite"]),
    ("unknown_key", b"report_dir: r\n", ["report_dir", "unknown key", "allowed keys"]),
    ("unknown_nested", b"north_finding:\n  bogus: 1\n", ["north_finding", "bogus", "allowed"]),
    ("escaping_results", b"results_dir: ../out\n", ["results_dir", "'../out'", "inside it"]),
    ("unknown_paper", b"papers: [nope]\n", ["'nope'", "north_finding"]),
    ("list_top_level", b"- papers\n", ["top level", "a list", "a mapping"]),
    ("empty", b"", ["top level", "empty", "a mapping"]),
]


@pytest.mark.parametrize(("case", "data", "named"), CASES, ids=[c[0] for c in CASES])
def test_a_bad_user_config_is_refused_in_one_line(tmp_path, capsys, case, data, named):
    path = tmp_path / f"{case}.yaml"
    path.write_bytes(data)
    assert main([str(path)]) == 2
    out = capsys.readouterr()
    lines = out.err.strip().splitlines()
    assert len(lines) == 1 and lines[0].startswith("error: ") and not out.out, out
    assert str(path) in lines[0]
    for text in named:
        assert text in lines[0], (text, lines[0])


@pytest.mark.parametrize("what", ["missing", "directory"])
def test_a_config_that_is_not_a_file_is_refused(tmp_path, capsys, what):
    path = tmp_path / "my.yaml"
    if what == "directory":
        path.mkdir()
    assert main([str(path)]) == 2
    err = capsys.readouterr().err
    assert (
        err.startswith(f"error: {path}: ") and ("not found" if what == "missing" else what) in err
    )


def test_a_good_user_config_is_merged_over_the_repository_config(tmp_path, capsys):
    """A nested setting is merged (the other papers' settings stay), and the workflow's own
    parse-time checks run on the result: only north_finding is listed."""
    path = tmp_path / "my.yaml"
    path.write_text("papers: [north_finding]\nnorth_finding:\n  published_scenario: paper\n")
    assert main([str(path)]) == 0
    assert "papers: north_finding" in capsys.readouterr().out


def test_make_reproduce_checks_config_before_snakemake_reads_it(tmp_path):
    """`make reproduce CONFIG=FILE` runs the check first and passes --configfile FILE after."""
    path = tmp_path / "my.yaml"
    path.write_text("papers: [north_finding]\n")
    plan = subprocess.run(
        ["make", "-n", "--no-print-directory", "workflow", f"CONFIG={path}"],
        cwd=ROOT, capture_output=True, text=True, check=True,
    ).stdout  # fmt: skip
    check = plan.index(f"-m pipeline.check_config {path}")
    run = plan.index(f"--configfile {path}")
    assert check < run, plan


def test_the_command_line_reports_without_a_traceback(tmp_path):
    path = tmp_path / "bin.yaml"
    path.write_bytes(b"\x00\xff")
    r = subprocess.run(
        [sys.executable, "-m", "pipeline.check_config", str(path)],
        cwd=ROOT, capture_output=True, text=True,
    )  # fmt: skip
    assert r.returncode == 2 and "Traceback" not in r.stderr and str(path) in r.stderr
