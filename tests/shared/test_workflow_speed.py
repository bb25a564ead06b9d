"""Issue 15, workflow speed: the parse cache of the code inputs, the Snakefile's parse path kept
free of scipy, and the workflow benchmark's reading of Snakemake's benchmark files."""

from __future__ import annotations

import json
import os
import shutil
import subprocess
import sys
from pathlib import Path

import pytest

from pipeline import bench_workflow, code_inputs

ROOT = Path(__file__).resolve().parents[2]


def _fresh() -> None:
    """Forget what this process parsed (the caches a new Snakemake process would not have)."""
    code_inputs._direct.cache_clear()
    code_inputs._parse_cache.cache_clear()


def _repo(tmp_path: Path) -> Path:
    (tmp_path / "pipeline").mkdir()
    (tmp_path / ".snakemake").mkdir()
    (tmp_path / "pipeline" / "__init__.py").write_text("")
    (tmp_path / "pipeline" / "a.py").write_text("from pipeline import b\n")
    (tmp_path / "pipeline" / "b.py").write_text("x = 1\n")
    (tmp_path / "pipeline" / "c.py").write_text("y = 2\n")
    return tmp_path


def test_cache_written_and_used(tmp_path: Path) -> None:
    root = _repo(tmp_path)
    _fresh()
    assert code_inputs.module_closure(["pipeline.a"], root) == [
        "pipeline/__init__.py",
        "pipeline/a.py",
        "pipeline/b.py",
    ]
    cache = root / code_inputs.CACHE_FILE
    data = json.loads(cache.read_text())
    entry = data["files"][str(root / "pipeline" / "a.py")]
    assert entry[2] == ["pipeline", "pipeline.b"]
    # an entry whose size and mtime match is believed without parsing the file: the cache is
    # what a new process reads (here it says a.py imports c as well)
    entry[2] = ["pipeline", "pipeline.b", "pipeline.c"]
    cache.write_text(json.dumps(data))
    _fresh()
    assert "pipeline/c.py" in code_inputs.module_closure(["pipeline.a"], root)


def test_edit_invalidates(tmp_path: Path) -> None:
    root = _repo(tmp_path)
    _fresh()
    assert "pipeline/c.py" not in code_inputs.module_closure(["pipeline.a"], root)
    a = root / "pipeline" / "a.py"
    stat = a.stat()
    # the same size, a new mtime: parsed again
    a.write_text("from pipeline import c\n")
    assert a.stat().st_size == stat.st_size
    os.utime(a, ns=(stat.st_atime_ns, stat.st_mtime_ns + 1_000_000))
    _fresh()
    assert code_inputs.module_closure(["pipeline.a"], root) == [
        "pipeline/__init__.py",
        "pipeline/a.py",
        "pipeline/c.py",
    ]
    # a new size with the mtime put back: parsed again too
    a.write_text("from pipeline import b, c\n")
    os.utime(a, ns=(stat.st_atime_ns, stat.st_mtime_ns))
    _fresh()
    assert "pipeline/b.py" in code_inputs.module_closure(["pipeline.a"], root)


def test_bad_cache_ignored(tmp_path: Path) -> None:
    root = _repo(tmp_path)
    (root / code_inputs.CACHE_FILE).write_text("{not json")
    _fresh()
    assert "pipeline/b.py" in code_inputs.module_closure(["pipeline.a"], root)
    assert json.loads((root / code_inputs.CACHE_FILE).read_text())["version"] == 1


def test_no_cache_without_snakemake_dir(tmp_path: Path) -> None:
    root = _repo(tmp_path)
    (root / ".snakemake").rmdir()
    _fresh()
    code_inputs.module_closure(["pipeline.a"], root)
    assert not (root / ".snakemake").exists()


def test_parse_path_has_no_scipy() -> None:
    """What the Snakefile runs when it is parsed (a no-op `make reproduce` included) does not
    import scipy.stats (~1 s of CPU): the steps that need it import it when they run."""
    code = (
        "import sys, yaml\n"
        "from pathlib import Path\n"
        "from pipeline.registry import check_workflow\n"
        "cfg = Path('config/config.yaml')\n"
        "check_workflow(yaml.safe_load(cfg.read_text()), [str(cfg)], Path('.').resolve())\n"
        "print(sorted(m for m in ('scipy.stats', 'scipy.special', 'sympy') if m in sys.modules))\n"
    )
    out = subprocess.run(
        [sys.executable, "-c", code],
        cwd=ROOT,
        env=dict(os.environ, PYTHONPATH=str(ROOT)),
        capture_output=True,
        text=True,
        check=True,
    )
    assert out.stdout.strip() == "[]"


def _tsv(path: Path, wall: float, cpu: float) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(
        "s\th:m:s\tmax_rss\tmax_vms\tmax_uss\tmax_pss\tio_in\tio_out\tmean_load\tcpu_time\n"
        f"{wall}\t0:00:01\t1\t1\t1\t1\t0\t0\t50\t{cpu}\n"
    )


def test_bench_collect_groups_scenarios(tmp_path: Path) -> None:
    res = tmp_path / "results"
    for scenario in ("paper", "high_latitude"):
        (res / "nf" / scenario).mkdir(parents=True)
        (res / "nf" / scenario / "provenance.json").write_text("{}")
    _tsv(res / "nf" / "benchmarks" / "simulate_paper.tsv", 2.0, 1.5)
    _tsv(res / "nf" / "benchmarks" / "simulate_high_latitude.tsv", 3.0, 2.5)
    _tsv(res / "nf" / "benchmarks" / "verdicts.tsv", 1.0, 0.75)
    _tsv(res / "benchmarks" / "reproduction.tsv", 4.0, 3.0)
    steps = {(s.paper, s.step): s for s in bench_workflow.collect(res)}
    assert sorted(steps) == [
        ("(all papers)", "reproduction"),
        ("nf", "simulate"),
        ("nf", "verdicts"),
    ]
    assert steps["nf", "simulate"].jobs == 2
    assert steps["nf", "simulate"].cpu_s == pytest.approx(4.0)
    assert steps["nf", "simulate"].wall_s == pytest.approx(5.0)
    table = bench_workflow.step_table(list(steps.values()), [steps["nf", "verdicts"]])
    total = table.splitlines()[-1].split()
    # jobs, CPU, wall, CPU before, change
    assert total[1:] == ["4", "7.8", "10.0", "0.8", "+7.0"]
    assert "*" not in table
    # a job longer than Snakemake's dense sampling: its CPU seconds are flagged a lower bound
    _tsv(res / "nf" / "benchmarks" / "simulate_paper.tsv", 16.0, 1.5)
    steps = {(s.paper, s.step): s for s in bench_workflow.collect(res)}
    lines = bench_workflow.step_table(list(steps.values())).splitlines()
    flagged = [line.split()[1] for line in lines if line.endswith(" *")]
    assert flagged == ["simulate"]
    assert lines[-1].startswith("* a job ran longer than 15 s") and "lower bound" in lines[-1]


def test_bench_bad_tsv(tmp_path: Path, capsys: pytest.CaptureFixture[str]) -> None:
    res = tmp_path / "results"
    (res / "nf" / "benchmarks").mkdir(parents=True)
    (res / "nf" / "benchmarks" / "audit.tsv").write_text("s\tcpu_time\n1.0\tabc\n")
    assert bench_workflow.main(["--results", str(res), "--noop-repeat", "0"]) == 2
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error: ") and "audit.tsv" in err[0]
    assert "cpu_time" in err[0]


def _git_repo(tmp_path: Path) -> Path:
    repo = tmp_path / "src"
    (repo / "pipeline").mkdir(parents=True)
    (repo / ".gitignore").write_text("results/\n.venv/\n")
    (repo / "pipeline" / "a.py").write_text("x = 1\n")
    (repo / "results").mkdir()
    (repo / "results" / "old.csv").write_text("stale\n")
    subprocess.run(["git", "init", "-q"], cwd=repo, check=True)
    subprocess.run(["git", "add", "."], cwd=repo, check=True)
    (repo / "pipeline" / "new.py").write_text("y = 2\n")  # untracked, not ignored: an edit
    return repo


def test_full_run_copies_a_fresh_clone_with_the_edits(tmp_path: Path) -> None:
    """The full-run benchmark starts from what a fresh clone with this checkout's edits has:
    tracked and untracked files, nothing ignored (no results, no venv, no caches)."""
    repo = _git_repo(tmp_path)
    assert bench_workflow.checkout_files(repo) == [".gitignore", "pipeline/a.py", "pipeline/new.py"]


def test_full_run_reports_make_failure(tmp_path: Path, monkeypatch, capsys) -> None:
    """A failing ``make workflow`` in the copy is reported, not timed as a run."""
    repo = _git_repo(tmp_path)
    (repo / "Makefile").write_text("workflow:\n\t@echo boom >&2; exit 3\n")
    (repo / ".venv").mkdir()
    monkeypatch.chdir(repo)
    assert bench_workflow.main(["--full-run", "--noop-repeat", "0"]) == 1
    out = capsys.readouterr().out
    assert "make workflow failed in the copy (status 2)" in out


def test_full_run_needs_no_results_here(tmp_path: Path, monkeypatch, capsys) -> None:
    """A fresh clone has no results/: the full run (`make bench`) starts all the same (it
    reads the copy's results), where reading the last run's would be refused."""
    repo = _git_repo(tmp_path)
    shutil.rmtree(repo / "results")
    (repo / "Makefile").write_text("workflow:\n\t@exit 3\n")
    (repo / ".venv").mkdir()
    monkeypatch.chdir(repo)
    assert bench_workflow.main(["--noop-repeat", "0"]) == 2
    assert "--results results: not a directory" in capsys.readouterr().err
    assert bench_workflow.main(["--full-run", "--noop-repeat", "0"]) == 1
    assert "make workflow failed in the copy" in capsys.readouterr().out


NESTED = """
import a0
class C:
    import a1
    def f(self):
        try:
            import a2
        except ImportError:
            from a3 import x
        else:
            import a4
        finally:
            import a5
        while True:
            import a6
        else:
            import a7
        with open("f") as h:
            for i in h:
                import a8
        match self:
            case 1:
                import a9
async def g():
    async with x:
        import b0
    async for y in z:
        import b1
try:
    pass
except* ValueError:
    import b2
if x:
    pass
else:
    import b3
lambda: __import__("not_counted")
"""


def test_statement_walk_finds_every_import() -> None:
    """The statement-only walk of the parse finds exactly the imports a walk of every node
    finds: in every kind of block (NESTED) and in each of the repository's own modules."""
    import ast

    modules = sorted(p for pkg in code_inputs.PACKAGES for p in (ROOT / pkg).rglob("*.py"))
    assert len(modules) > 100
    for source in [NESTED] + [p.read_text(encoding="utf-8") for p in modules]:
        _same_imports(ast, source)
    assert len(_same_imports(ast, NESTED)) == 14


def _same_imports(ast, source: str) -> list:
    tree = ast.parse(source)
    every = [n for n in ast.walk(tree) if isinstance(n, ast.Import | ast.ImportFrom)]
    found = [n for n in code_inputs._statements(tree) if isinstance(n, ast.Import | ast.ImportFrom)]
    assert sorted(map(ast.dump, found)) == sorted(map(ast.dump, every))
    return found


def test_noop_judged_by_its_wall_time(capsys: pytest.CaptureFixture[str]) -> None:
    """The no-op target (<= 3 s) is judged on the median wall time; CPU is printed beside."""
    bench_workflow._print_noop([(1.0, 2.0), (1.2, 4.0), (1.1, 2.5)])
    out = capsys.readouterr().out
    assert "median 2.50 s wall, 1.10 CPU-s" in out and out.rstrip().endswith("meets it")
    bench_workflow._print_noop([(1.0, 3.5), (1.2, 4.0), (1.1, 2.5)])
    assert capsys.readouterr().out.rstrip().endswith("misses it")
