"""What each workflow job asks a cluster for: threads, memory and run time from measured peaks.

Every rule writes a Snakemake benchmark file (``results/<slug>/benchmarks/<step>[_<scenario>].tsv``:
wall seconds ``s``, peak resident memory ``max_rss`` in MB, ``cpu_time`` seconds). This module
turns the benchmark files of a run into ``config/job_resources.csv``, one row per job, which the
rules read (``pipeline/rules/common.smk``: ``resources`` and ``localrules``)::

    .venv/bin/python -m pipeline.job_resources results config/job_resources.csv

A job asks for

    mem_mb  = max(MEM_FLOOR_MB,  ceil_to(MEM_FACTOR  * peak RSS,       MEM_STEP_MB))
    runtime = max(RUNTIME_FLOOR_MIN, ceil(RUNTIME_FACTOR * wall / 60))      (minutes)
    threads = max(1, round(cpu_time / wall))  (cores it kept busy; 1 for every step today)

with margins for a slower node or a loaded one (2x memory, 3x wall). A job that needed less
than ``LOCAL_MAX_S`` of CPU is cheaper on the login node than in the queue (one sbatch job
costs about half a minute of overhead): its rule is a local rule when every measured job of the
rule is. CPU time, not wall time, decides it: on a shared machine the wall time of a step is
mostly the load of the others. The sizes are the shipped scenarios'; a user who raises the number of trials
measures again (the command above) or raises ``runtime``/``mem_mb`` in the profile.

>>> r = derive_row("some_paper/simulate_paper", wall_s=20.0, rss_mb=300.0, cpu_s=19.0)
>>> (r.threads, r.mem_mb, r.runtime, r.local)
(1, 600, 5, False)
>>> derive_row("x/y", wall_s=1.0, rss_mb=10.0, cpu_s=0.5).mem_mb
500
>>> r = derive_row("x/y", wall_s=1000.0, rss_mb=10.0, cpu_s=1900.0)
>>> (r.runtime, r.threads, r.local)
(50, 2, False)
"""

from __future__ import annotations

import csv
import io
import math
import re
import sys
from dataclasses import dataclass
from pathlib import Path

from pipeline.atomic import write_text

__all__ = [
    "COLUMNS",
    "JobResources",
    "ResourceTable",
    "derive_row",
    "measure",
    "read_table",
]

MEM_FACTOR = 2.0
MEM_STEP_MB = 100
MEM_FLOOR_MB = 500
RUNTIME_FACTOR = 3.0
RUNTIME_FLOOR_MIN = 5
LOCAL_MAX_S = 10.0
COLUMNS = ["job", "threads", "mem_mb", "runtime", "local", "wall_s", "peak_rss_mb", "cpu_s"]


@dataclass(frozen=True)
class JobResources:
    """One job's request (``job``: its benchmark path below the results directory, without
    ``benchmarks/`` and ``.tsv``, e.g. ``some_paper/simulate_paper``) and what it was from."""

    job: str
    threads: int
    mem_mb: int
    runtime: int
    local: bool
    wall_s: float
    peak_rss_mb: float
    cpu_s: float


def derive_row(job: str, wall_s: float, rss_mb: float, cpu_s: float) -> JobResources:
    """The request of one job from its measured wall time, peak RSS and CPU time."""
    for name, value in (("s", wall_s), ("max_rss", rss_mb), ("cpu_time", cpu_s)):
        if not math.isfinite(value) or value < 0:
            raise ValueError(f"{job}: benchmark field {name!r} is {value!r}; allowed: finite >= 0")
    mem = max(MEM_FLOOR_MB, math.ceil(MEM_FACTOR * rss_mb / MEM_STEP_MB) * MEM_STEP_MB)
    runtime = max(RUNTIME_FLOOR_MIN, math.ceil(RUNTIME_FACTOR * wall_s / 60.0))
    threads = max(1, round(cpu_s / wall_s)) if wall_s > 0 else 1
    return JobResources(job, threads, mem, runtime, cpu_s < LOCAL_MAX_S, wall_s, rss_mb, cpu_s)


def _read_benchmark(path: Path) -> tuple[float, float, float]:
    """(wall s, peak RSS MB, CPU s) of a benchmark file: the largest of its rows (repeats)."""
    rows = list(csv.DictReader(io.StringIO(path.read_text(encoding="utf-8")), delimiter="\t"))
    if not rows:
        raise ValueError(f"{path}: a benchmark file with no measurement row")
    try:
        values = [(float(r["s"]), float(r["max_rss"]), float(r["cpu_time"])) for r in rows]
    except (KeyError, ValueError) as exc:
        raise ValueError(
            f"{path}: benchmark columns s, max_rss, cpu_time must be numbers ({exc})"
        ) from None
    return tuple(max(v[i] for v in values) for i in range(3))  # type: ignore[return-value]


def measure(results: Path) -> list[JobResources]:
    """One row per benchmark file under ``results`` (``<slug>/benchmarks/*.tsv`` and the
    combined report's ``benchmarks/*.tsv``), sorted by job."""
    rows = []
    for path in sorted(results.glob("**/benchmarks/*.tsv")):
        rel = path.relative_to(results).with_suffix("").as_posix()
        job = rel.replace("benchmarks/", "")
        rows.append(derive_row(job, *_read_benchmark(path)))
    if not rows:
        raise ValueError(f"{results}: no benchmark files (run the workflow first)")
    return sorted(rows, key=lambda r: r.job)


def format_table(rows: list[JobResources]) -> str:
    out = io.StringIO()
    out.write(
        "# threads, mem_mb, runtime (minutes) and local of each workflow job, from measured\n"
        "# peaks (wall_s, peak_rss_mb, cpu_s): python -m pipeline.job_resources (its docstring)\n"
    )
    w = csv.writer(out, lineterminator="\n")
    w.writerow(COLUMNS)
    for r in rows:
        w.writerow([r.job, r.threads, r.mem_mb, r.runtime, int(r.local), r.wall_s,
                    r.peak_rss_mb, r.cpu_s])  # fmt: skip
    return out.getvalue()


def read_table(path: Path) -> dict[str, JobResources]:
    """``config/job_resources.csv`` by job; a malformed row is an error naming it."""
    lines = [ln for ln in path.read_text(encoding="utf-8").splitlines() if not ln.startswith("#")]
    reader = csv.DictReader(lines)
    if reader.fieldnames != COLUMNS:
        raise ValueError(f"{path}: columns {reader.fieldnames}; expected {COLUMNS}")
    table = {}
    for n, row in enumerate(reader, start=2):
        try:
            r = JobResources(
                row["job"], int(row["threads"]), int(row["mem_mb"]), int(row["runtime"]),
                row["local"] == "1", float(row["wall_s"]), float(row["peak_rss_mb"]),
                float(row["cpu_s"]),
            )  # fmt: skip
        except (TypeError, ValueError) as exc:
            raise ValueError(f"{path}: row {n} ({row.get('job')!r}): {exc}") from None
        if min(r.threads, r.mem_mb, r.runtime) < 1 or row["local"] not in ("0", "1"):
            raise ValueError(
                f"{path}: row {n} ({r.job!r}): threads, mem_mb, runtime must be >= 1 and "
                f"local 0 or 1"
            )
        table[r.job] = r
    return table


class ResourceTable:
    """The rules' view of the table: the request of a job named by its benchmark template
    (``{paper}/derive``, ``some_paper/simulate_{scenario}``) and its wildcards."""

    def __init__(self, table: dict[str, JobResources]) -> None:
        self.table = table

    @classmethod
    def load(cls, path: Path) -> ResourceTable:
        return cls(read_table(path) if path.is_file() else {})

    def matching(self, template: str) -> list[JobResources]:
        """The measured jobs a template stands for (every value of its wildcards)."""
        pattern = re.sub(r"\\\{[A-Za-z_]+\\\}", "[^/]+", re.escape(template))
        return [r for job, r in self.table.items() if re.fullmatch(pattern, job)]

    def request(self, template: str, wildcards: dict[str, str]) -> JobResources | None:
        """The job's own row; else the largest request among the rule's measured jobs (a new
        scenario of a measured step); else None (the profile's default resources)."""
        job = template.format(**wildcards)
        if job in self.table:
            return self.table[job]
        rows = self.matching(template)
        if not rows:
            return None
        return JobResources(
            job, max(r.threads for r in rows), max(r.mem_mb for r in rows),
            max(r.runtime for r in rows), all(r.local for r in rows),
            max(r.wall_s for r in rows), max(r.peak_rss_mb for r in rows),
            max(r.cpu_s for r in rows),
        )  # fmt: skip

    def is_local(self, template: str) -> bool:
        """Whether a rule runs on the login node: it was measured and every job of it needed
        less than LOCAL_MAX_S of CPU."""
        rows = self.matching(template)
        return bool(rows) and all(r.local for r in rows)


def main(argv: list[str]) -> int:
    if len(argv) != 2:
        sys.stderr.write("usage: python -m pipeline.job_resources RESULTS_DIR OUT_CSV\n")
        return 2
    try:
        rows = measure(Path(argv[0]))
    except ValueError as exc:
        sys.stderr.write(f"error: {exc}\n")
        return 1
    write_text(argv[1], format_table(rows))
    print(f"{argv[1]}: {len(rows)} jobs, {sum(r.local for r in rows)} under {LOCAL_MAX_S} CPU s")
    return 0


if __name__ == "__main__":
    raise SystemExit(main(sys.argv[1:]))
