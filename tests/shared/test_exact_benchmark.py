"""Issue 15: the benchmark file of a job run by ``python -m pipeline.run_snakemake`` has the
job's exact CPU time (from the kernel when its shell is reaped) in Snakemake's own TSV format,
and its process tree is sampled in one thread (``pipeline/exact_benchmark.py``)."""

from __future__ import annotations

import csv
import os
import subprocess
import sys
import time
from pathlib import Path
from types import SimpleNamespace

from snakemake.benchmark import BenchmarkRecord

from pipeline import exact_benchmark

ROOT = Path(__file__).resolve().parents[2]

# a script that runs a child, which burns 1.2 s of CPU and then starts and leaves a grandchild
# that burns 0.4 s; each writes its own CPU seconds (time.process_time) at its end
BURN = """\
import subprocess, sys, time

def burn(seconds):
    start = time.process_time()
    while time.process_time() - start < seconds:
        pass

role, out = sys.argv[1], sys.argv[2]
if role == "script":
    subprocess.run([sys.executable, __file__, "child", out + ".child"], check=True)
elif role == "child":
    burn(1.2)
    subprocess.run([sys.executable, __file__, "grandchild", out + ".grand"], check=True)
else:
    burn(0.4)
with open(out, "w") as fh:
    fh.write(f"{time.process_time()}\\n")
"""


def _cpu_written(out: Path) -> float:
    return sum(
        float(p.read_text()) for p in (out, Path(f"{out}.child"), Path(f"{out}.child.grand"))
    )


def test_a_job_benchmark_has_its_exact_cpu_time_in_snakemakes_format(tmp_path: Path) -> None:
    """The CPU seconds of a job whose CPU is burnt in a child and a grandchild, the last 0.4 s
    just before they exit (Snakemake's sampler, every 0.5 s and not at the end, misses part of
    them): within 0.5 s above what its three processes counted themselves (bash and Python's
    start-ups), never below; the file's header and columns are Snakemake's."""
    (tmp_path / "burn.py").write_text(BURN)
    (tmp_path / "Snakefile").write_text(
        "rule all:\n"
        "    input: 'out.txt'\n"
        "rule burn:\n"
        "    output: 'out.txt'\n"
        "    benchmark: 'bench.tsv'\n"
        f"    shell: '{sys.executable} burn.py script {{output}}'\n"
    )
    env = {**os.environ, "PYTHONPATH": str(ROOT)}
    run = subprocess.run(
        [sys.executable, "-m", "pipeline.run_snakemake", "--cores", "1", "--quiet"],
        cwd=tmp_path,
        env=env,
        capture_output=True,
        text=True,
        check=False,
    )
    assert run.returncode == 0, run.stderr
    text = (tmp_path / "bench.tsv").read_text()
    assert text.splitlines()[0] == "\t".join(BenchmarkRecord.get_header())
    (row,) = list(csv.DictReader(text.splitlines(), delimiter="\t"))
    numbers = {k: float(v) for k, v in row.items() if k != "h:m:s"}
    truth = _cpu_written(tmp_path / "out.txt")
    assert truth - 0.02 <= numbers["cpu_time"] <= truth + 0.5, (numbers, truth)
    assert abs(numbers["mean_load"] - 100 * numbers["cpu_time"] / numbers["s"]) < 1.0
    assert 0 < numbers["max_uss"] <= numbers["max_rss"] <= numbers["max_vms"]


def test_sampler_and_rusage_without_snakemake(tmp_path: Path) -> None:
    """In-process: the record of a shell reaped by RusagePopen inside tree_sampler."""
    record = BenchmarkRecord()
    (tmp_path / "burn.py").write_text(BURN)
    out = tmp_path / "out.txt"
    proc = exact_benchmark.RusagePopen(
        f"{sys.executable} {tmp_path / 'burn.py'} script {out}; true", shell=True
    )
    with exact_benchmark.tree_sampler(proc.pid, record) as sampler:
        assert proc.wait() == 0
    assert sampler.samples >= 2 and not sampler.thread.is_alive()
    assert proc.pid not in exact_benchmark._RUSAGE
    truth = _cpu_written(out)
    assert truth - 0.02 <= record.cpu_time <= truth + 0.5
    assert record.data_collected and record.max_rss > 5 and record.max_uss > 1
    record.running_time = 2.0
    fields = record.to_tsv(False).split("\t")
    assert len(fields) == len(BenchmarkRecord.get_header())


def test_a_process_reaped_elsewhere_falls_back_on_the_samples() -> None:
    """No resource usage (the shell was reaped by another waiter): the sampled CPU seconds;
    no sample either: Snakemake's NA."""
    proc = subprocess.Popen([sys.executable, "-c", "import time; time.sleep(0.8)"])
    record = BenchmarkRecord()
    with exact_benchmark.tree_sampler(proc.pid, record):
        proc.wait()  # a plain Popen: os.waitpid, no rusage
    assert record.data_collected and record.io_in is None and record.cpu_time >= 0
    gone = BenchmarkRecord()
    exact_benchmark.tree_sampler(2**22 + 1, gone).finish(None)
    assert not gone.data_collected and gone.process_gone


def test_exact_benchmarks_patches_the_pinned_snakemake() -> None:
    """The pinned Snakemake's modules have what the patch replaces (an upgrade that renames
    them makes this fail); a pid of None (a run: job) keeps Snakemake's own timer."""
    import importlib

    import snakemake.benchmark

    shell = importlib.import_module("snakemake.shell")
    bench = SimpleNamespace(**vars(snakemake.benchmark))
    shell_copy = SimpleNamespace(sp=shell.sp)
    assert exact_benchmark.exact_benchmarks(bench, shell_copy)  # type: ignore[arg-type]
    assert shell_copy.sp.Popen is exact_benchmark.RusagePopen
    with bench.benchmarked(None) as record:
        time.sleep(0.1)
    assert record.running_time >= 0.1
