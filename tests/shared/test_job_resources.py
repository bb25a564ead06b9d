"""Each job's cluster request (pipeline/job_resources.py, config/job_resources.csv): computed
from benchmark files, read back strictly, and covering every rule of the workflow."""

from __future__ import annotations

from pathlib import Path

import pytest

from pipeline.job_resources import (
    LOCAL_MAX_S,
    ResourceTable,
    derive_row,
    format_table,
    measure,
    read_table,
)
from tests.workflow_harness import ROOT, snakemake

HEADER = "s\th:m:s\tmax_rss\tmax_vms\tmax_uss\tmax_pss\tio_in\tio_out\tmean_load\tcpu_time\n"


def _bench(path: Path, wall: float, rss: float, cpu: float) -> None:
    path.parent.mkdir(parents=True, exist_ok=True)
    path.write_text(f"{HEADER}{wall}\t0:00:00\t{rss}\t1\t1\t1\t0\t0\t50\t{cpu}\n", encoding="utf-8")


def test_request_from_measured_peaks(tmp_path):
    results = tmp_path / "results"
    _bench(results / "p" / "benchmarks" / "simulate_a.tsv", wall=400.0, rss=1234.0, cpu=390.0)
    _bench(results / "p" / "benchmarks" / "simulate_b.tsv", wall=2.0, rss=100.0, cpu=1.5)
    _bench(results / "benchmarks" / "report.tsv", wall=3.0, rss=90.0, cpu=2.0)
    rows = {r.job: r for r in measure(results)}
    assert sorted(rows) == ["p/simulate_a", "p/simulate_b", "report"]
    a = rows["p/simulate_a"]
    # 2 x 1234 MB rounded up to 100 MB; 3 x 400 s = 20 min; 390 CPU s in 400 s: one core
    assert (a.mem_mb, a.runtime, a.threads, a.local) == (2500, 20, 1, False)
    b = rows["p/simulate_b"]
    assert (b.mem_mb, b.runtime, b.local) == (500, 5, True)  # the floors; < LOCAL_MAX_S CPU
    # written and read back unchanged
    out = tmp_path / "job_resources.csv"
    out.write_text(format_table(list(rows.values())), encoding="utf-8")
    assert read_table(out) == rows
    table = ResourceTable(rows)
    # a rule's template: a scenario of its own, else the largest of the rule's jobs
    assert table.request("p/simulate_{scenario}", {"scenario": "b"}) == b
    new = table.request("p/simulate_{scenario}", {"scenario": "new"})
    assert (new.mem_mb, new.runtime, new.local) == (2500, 20, False)
    assert table.request("q/derive", {}) is None
    assert not table.is_local("p/simulate_{scenario}") and table.is_local("report")
    assert not table.is_local("q/derive")  # unmeasured: submitted


def test_two_busy_cores_are_two_threads():
    r = derive_row("x", wall_s=100.0, rss_mb=10.0, cpu_s=195.0)
    assert r.threads == 2 and not r.local
    assert derive_row("x", wall_s=0.0, rss_mb=0.0, cpu_s=0.0).threads == 1
    assert derive_row("x", wall_s=30.0, rss_mb=10.0, cpu_s=LOCAL_MAX_S - 0.01).local


@pytest.mark.parametrize(
    ("line", "message"),
    [
        ("p/a,0,500,5,0,1,1,1", "must be >= 1"),
        ("p/a,1,500,5,2,1,1,1", "local 0 or 1"),
        ("p/a,1,lots,5,0,1,1,1", "row 2 ('p/a')"),
    ],
)
def test_bad_table_rows_are_named(tmp_path, line, message):
    path = tmp_path / "t.csv"
    path.write_text(
        "job,threads,mem_mb,runtime,local,wall_s,peak_rss_mb,cpu_s\n" + line + "\n",
        encoding="utf-8",
    )
    with pytest.raises(ValueError, match=message.replace("(", r"\(").replace(")", r"\)")):
        read_table(path)


def test_bad_benchmark_is_named(tmp_path):
    path = tmp_path / "r" / "p" / "benchmarks" / "a.tsv"
    _bench(path, wall=float("nan"), rss=1.0, cpu=1.0)
    with pytest.raises(ValueError, match=r"p/a: benchmark field 's' is nan"):
        measure(tmp_path / "r")
    with pytest.raises(ValueError, match="no benchmark files"):
        measure(tmp_path / "empty")


def test_every_workflow_job_has_a_measured_request():
    """Every job of the default workflow (dry run) is in config/job_resources.csv, so that on a
    cluster none falls back to the profile's default resources; the shipped table's local rules
    are the short steps and the expensive ones are submitted."""
    table = read_table(ROOT / "config" / "job_resources.csv")
    r = snakemake("-n", "--forceall", cwd=ROOT)
    assert r.returncode == 0, (r.stdout + r.stderr)[-3000:]
    benchmarks = {
        line.split("benchmark: ", 1)[1].strip()
        for line in (r.stdout + r.stderr).splitlines()
        if line.strip().startswith("benchmark: ")
    }
    jobs = {b.removeprefix("results/").removesuffix(".tsv") for b in benchmarks}
    jobs = {j.replace("benchmarks/", "") for j in jobs}
    assert len(jobs) >= 30
    assert sorted(jobs - set(table)) == []
    assert not table["altimeter_attitude/ukf_tuning"].local
    assert table["north_finding/codegen_check"].local
