"""The workflow on a SLURM cluster through Snakemake's executor plugin (profiles/slurm/) gives the
same bytes as the local run (DESIGN.md invariant 4, "across executors").

A copy of the session's reduced repository (``workflow_run``, run locally with ``--cores 2``)
without its outputs runs, through the profile on the cluster, one scenario per paper and each
paper's derivation and equation audit: the derivations and audits of the three papers grouped
into one sbatch job, the altimeter_attitude Monte Carlo in another, the short steps as local
rules on this machine. Every file it writes under results/ and reports/ (benchmarks and job
logs excepted) is compared byte for byte with the local run's.

Without a cluster (``sbatch``, ``squeue``, ``scontrol ping``, the plugin) the test is skipped;
with ``REQUIRE_SLURM=1`` (CI: ``.ci/run`` starts one with ``.ci/slurm up``) it fails instead.
"""

from __future__ import annotations

import importlib.util
import os
import re
import shutil
import subprocess
from datetime import datetime
from pathlib import Path

import pytest
import yaml

from tests.hang_guard import HANG_GUARD_S
from tests.workflow_harness import SLUGS, output_digests, snakemake

pytestmark = [pytest.mark.slow, pytest.mark.workflow]

#: the rules grouped into one sbatch job (all papers': --group-components)
GROUPED = ("derive", "audit")


def cluster_missing() -> str | None:
    """Why no SLURM cluster can take jobs from here, or None."""
    for tool in ("sbatch", "squeue", "scontrol", "scancel"):
        if shutil.which(tool) is None:
            return f"{tool} is not on PATH"
    for module in ("snakemake_executor_plugin_slurm", "snakemake_executor_plugin_slurm_jobstep"):
        if importlib.util.find_spec(module) is None:
            return f"{module} is not installed (environment.lock has it: make venv)"
    ping = subprocess.run(["scontrol", "ping"], capture_output=True, text=True, timeout=60)
    if ping.returncode != 0 or "UP" not in ping.stdout:
        return f"no slurmctld answers: {(ping.stdout + ping.stderr).strip()[:200]}"
    return None


@pytest.fixture(scope="module")
def cluster() -> None:
    why = cluster_missing()
    if why is None:
        return
    if os.environ.get("REQUIRE_SLURM") == "1":
        pytest.fail(f"REQUIRE_SLURM=1 but no SLURM cluster: {why}")
    pytest.skip(f"no SLURM cluster ({why}); `.ci/slurm up` starts a one-node one")


def node_cpus() -> int:
    """The CPUs of the cluster's smallest node (a job asking for more would wait forever)."""
    out = subprocess.run(["sinfo", "-h", "-o", "%c"], capture_output=True, text=True, timeout=60)
    return min(int(c.rstrip("+")) for c in out.stdout.split())


def targets(repo: Path) -> list[str]:
    """Per paper: its equation audit and one scenario's step outputs (the published scenario,
    else the first), through that scenario's provenance file."""
    config = yaml.safe_load((repo / "config" / "config.yaml").read_text(encoding="utf-8"))
    out = []
    for slug in SLUGS:
        names = sorted(p.stem for p in (repo / "config" / "scenarios" / slug).glob("*.yaml"))
        scenario = (config.get(slug) or {}).get("published_scenario", names[0])
        out += [f"results/{slug}/equation_audit.csv", f"results/{slug}/{scenario}/provenance.json"]
    return out


def copy_without_outputs(src: Path, dest: Path) -> None:
    """``src`` without what the workflow wrote (results/, .snakemake/, the rendered reports)."""

    def ignore(directory: str, names: list[str]) -> set[str]:
        d = Path(directory)
        skip = {n for n in names if d == src and n in ("results", ".snakemake")}
        if d == src / "reports":
            skip |= {n for n in names if n.endswith((".html", ".pdf")) or n == "notebooks"}
        return skip

    shutil.copytree(src, dest, symlinks=True, ignore=ignore)


def cancel_jobs_in(repo: Path) -> None:
    """scancel the queue's jobs whose working directory is ``repo`` (a run that was killed)."""
    q = subprocess.run(["squeue", "-h", "-o", "%i %Z"], capture_output=True, text=True, timeout=60)
    ids = [f[0] for f in (ln.split() for ln in q.stdout.splitlines()) if f[1:] == [str(repo)]]
    if ids:
        subprocess.run(["scancel", *ids], timeout=60, check=False)


_STAMP = re.compile(r"^\[(\w{3} \w{3} +\d+ \d\d:\d\d:\d\d \d{4})\]")
_SUBMIT = re.compile(r"^Job \S+ has been submitted with SLURM jobid (\d+)", re.M)
_JOBID = re.compile(r"^jobid: (\d+)$")
_DONE = re.compile(r"^Finished jobid: (\d+) ")


def sbatch_spans(log: str) -> dict[str, float]:
    """Seconds from each sbatch submission to the moment Snakemake saw the last of its jobs
    finished, per SLURM job id, from the timestamped lines of Snakemake's output (a group job
    lists its jobs' ids before it is submitted)."""
    now, pending, members, start, end = None, [], {}, {}, {}
    for line in (raw.strip() for raw in log.splitlines()):
        if m := _STAMP.match(line):
            now = datetime.strptime(m[1], "%a %b %d %H:%M:%S %Y")
        if "Group job" in line or line.startswith(("rule ", "localrule ")):
            pending = []  # the jobs of the next submission follow
        elif m := _JOBID.match(line):
            pending.append(m[1])
        elif m := _SUBMIT.match(line):
            members[m[1]], start[m[1]], pending = set(pending), now, []
        elif (m := _DONE.match(line)) and now:
            for slurm_id, jobs in members.items():
                if m[1] in jobs:
                    end[slurm_id] = now
    return {k: (end[k] - start[k]).total_seconds() for k in end if start[k]}


def test_cluster_run_identical_to_local(cluster, workflow_run, tmp_path):
    repo = tmp_path / "repo"
    copy_without_outputs(workflow_run, repo)
    sources = set(output_digests(repo))  # the committed files under reports/ (captions)
    wanted = targets(repo)
    groups = [f"{rule}=derivation" for rule in GROUPED]
    # targets before the options that take lists (--groups, --default-resources in the profile)
    args = [*wanted, "--profile", "profiles/slurm", "--groups", *groups]
    # a group job asks for the cores its jobs use in parallel, at most --cores: one node's
    args += ["--group-components", f"derivation={len(SLUGS)}", "--cores", str(node_cpus())]
    args += ["--latency-wait", "10"]
    # first status check after 10 s, not 40 (squeue: MinJobAge 300 >= 3 x 10); no account
    args += ["--slurm-init-seconds-before-status-checks", "10", "--slurm-no-account"]
    try:
        r = snakemake(*args, cwd=repo, timeout=HANG_GUARD_S)
    finally:
        cancel_jobs_in(repo)
    log = r.stdout + r.stderr
    assert r.returncode == 0, log[-5000:]
    submitted = _SUBMIT.findall("\n".join(ln.strip() for ln in log.splitlines()))
    # at least the altimeter Monte Carlo is submitted; the grouped derivations and audits are
    # too when config/job_resources.csv measured them above LOCAL_MAX_S (they sit near it)
    assert len(submitted) >= 1, log[-3000:]
    assert "localrule " in log, "no step ran as a local rule"
    for target in wanted:
        assert (repo / target).is_file(), target

    cluster_files = {p: h for p, h in output_digests(repo).items() if p not in sources}
    local_files = output_digests(workflow_run)
    assert len(cluster_files) >= 3 * len(SLUGS)
    differ = sorted(p for p in cluster_files if cluster_files[p] != local_files.get(p))
    assert not differ, (
        f"{len(differ)} of {len(cluster_files)} files differ from the local run: {differ}"
    )
    spans = sbatch_spans(log)
    print(
        f"\n{len(cluster_files)} files byte-identical; sbatch jobs (s, submit to seen done): {spans}"
    )
