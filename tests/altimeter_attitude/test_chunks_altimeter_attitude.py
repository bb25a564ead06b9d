"""The chunked Monte Carlo (pipeline/altimeter_attitude/chunks.py): chunk jobs' files merged give
the results files of the run in one process byte for byte; a chunk file of another run is
refused naming the file and the field; chunk_runs is validated by the scenario schema."""

from __future__ import annotations

import subprocess
import sys
from dataclasses import replace
from pathlib import Path

import pytest
import yaml

from pipeline.altimeter_attitude import chunks, run
from pipeline.altimeter_attitude.mc_sums import BLOCK_RUNS
from pipeline.altimeter_attitude.scenario import ROOT, build_scenario, load_scenario
from pipeline.config import ConfigError, load_schema
from tests.hang_guard import HANG_GUARD_S
from tests.workflow_harness import copy_repo, snakemake

PAPER = ROOT / "config" / "scenarios" / "altimeter_attitude" / "paper.yaml"


def short_raw(duration: float = 25.0) -> dict:
    """The paper scenario cut to its first ``duration`` s (pull-up included), transient 5 s."""
    raw = yaml.safe_load(PAPER.read_text(encoding="utf-8"))
    raw["trajectory"]["duration_s"] = duration
    raw["trajectory"]["maneuvers"] = [
        m for m in raw["trajectory"]["maneuvers"] if m["start_s"] + m["duration_s"] <= duration
    ]
    raw["metrics"]["transient_s"] = 5.0
    return raw


@pytest.fixture(scope="module")
def short():
    return build_scenario(short_raw(), PAPER)


def _files(directory: Path) -> dict[str, bytes]:
    return {p.name: p.read_bytes() for p in sorted(directory.iterdir()) if p.is_file()}


def _chunked(sc, n_runs, chunk_runs, block, tmp: Path) -> tuple[list[Path], Path]:
    """Each chunk simulated and written alone, then merged into tmp/merged."""
    sc = replace(sc, **{"n_runs": n_runs, "chunk_runs": chunk_runs})
    bounds = chunks.chunk_bounds(n_runs, chunk_runs, block)
    paths = []
    for c, b in enumerate(bounds):
        parts = chunks.simulate_chunk(sc, b, log=lambda m: None, block=block)
        paths.append(chunks.write_chunk(tmp / "chunks" / f"{c}.mcsums", sc, b, parts, block))
    merged = chunks.merge_chunks(sc, paths, chunk_runs, block=block)
    run.write_results(sc, tmp / "merged", *merged)
    return paths, tmp / "merged"


def test_merged_chunks_are_byte_identical_to_one_process(short, tmp_path):
    """11 runs in blocks of 2, chunks of 4 (three chunks, the last with a short block): every
    results file, provenance.json included, equals the one-process run's bytes."""
    one = tmp_path / "one"
    sc = replace(short, **{"n_runs": 11, "chunk_runs": 4})
    run.run_scenario(sc, one, log=lambda m: None, block=2)
    paths, merged = _chunked(short, 11, 4, 2, tmp_path)
    assert len(paths) == 3
    want, got = _files(one), _files(merged)
    assert sorted(want) == sorted(got) and len(want) == 9
    assert [n for n in want if want[n] != got[n]] == []
    # a chunk file is the same bytes when written again
    again = chunks.simulate_chunk(sc, (4, 8), log=lambda m: None, block=2)
    assert chunks.write_chunk(tmp_path / "again", sc, (4, 8), again, 2).read_bytes() == (
        paths[1].read_bytes()
    )


def test_summing_per_chunk_would_not_be_identical(short, tmp_path):
    """Why the files keep every block's sums: the same 8 runs summed per chunk of 4 and then
    across chunks differ from the block-by-block fold in the last bits of some time sample."""
    import numpy as np

    sc = replace(short, **{"n_runs": 8, "chunk_runs": 4})
    _, mc, _ = run.simulate_sums(sc, log=lambda m: None, block=2)
    halves = []
    for bounds in chunks.chunk_bounds(8, 4, 2):
        part = run.new_sums(sc)[1]
        for _, bs in chunks.simulate_chunk(sc, bounds, log=lambda m: None, block=2):
            part.fold(bs)
        halves.append(part.filters["ukf"].sums["er2"])
    direct = mc.filters["ukf"].sums["er2"]
    assert np.allclose(halves[0] + halves[1], direct, rtol=1e-13)
    assert not np.array_equal(halves[0] + halves[1], direct)


def test_chunk_of_another_run_is_refused(short, tmp_path):
    paths, _ = _chunked(short, 6, 4, 2, tmp_path)
    sc = replace(short, **{"n_runs": 6, "chunk_runs": 4})
    firsts = run.new_sums(sc)[1].firsts
    with pytest.raises(ValueError, match=r"0\.mcsums: runs = \[0, 4\], expected \[4, 6\]"):
        chunks.read_chunk(paths[0], sc, (4, 6), firsts, block=2)
    other = replace(sc, raw={**sc.raw, "x": 1})
    with pytest.raises(ValueError, match="config_sha256 = "):
        chunks.read_chunk(paths[0], other, (0, 4), firsts, block=2)
    with pytest.raises(ValueError, match="block = 2, expected 4"):
        chunks.read_chunk(paths[0], sc, (0, 4), firsts, block=4)
    bad = tmp_path / "bad.mcsums"
    bad.write_bytes(b"not a chunk\n")
    with pytest.raises(ValueError, match="bad.mcsums: not a Monte Carlo chunk file"):
        chunks.read_chunk(bad, sc, (0, 4), firsts, block=2)
    with pytest.raises(ValueError, match="1 chunk files for 2 chunks"):
        chunks.merge_chunks(sc, paths[:1], 4, block=2)


def test_chunk_runs_in_the_schema_is_a_whole_number_of_blocks(tmp_path):
    prop = load_schema("altimeter_attitude_scenario")["properties"]["monte_carlo"]["properties"]
    assert prop["chunk_runs"]["multipleOf"] == BLOCK_RUNS == prop["chunk_runs"]["minimum"]
    raw = short_raw()
    raw["monte_carlo"]["chunk_runs"] = 300
    with pytest.raises(
        ConfigError, match=r"x.yaml: monte_carlo.chunk_runs = 300: .*multiple of 256"
    ):
        build_scenario(raw, tmp_path / "x.yaml")
    raw["monte_carlo"]["chunk_runs"] = 512
    assert build_scenario(raw, tmp_path / "x.yaml").chunk_runs == 512
    assert load_scenario(PAPER).chunk_runs is None  # the papers' sizes: one job


def test_chunk_request_scales_with_runs_and_steps():
    """A chunk job asks for the memory of one block and the run time of its runs (paper
    scenario: 10,000 steps)."""
    from pipeline.altimeter_attitude import chunk_plan as plan

    sc = load_scenario(PAPER)
    one = chunks.chunk_request(sc, BLOCK_RUNS)
    ten = chunks.chunk_request(sc, 10 * BLOCK_RUNS)
    block_mb = plan.RSS_MB_BASE + plan.RSS_MB_PER_RUN_STEP * BLOCK_RUNS * 10_000
    assert block_mb >= 374  # the peak RSS measured for 512 runs in batches of BATCH_RUNS
    assert one.mem_mb == ten.mem_mb >= 2 * block_mb
    ten_cpu_s = plan.CPU_S_PER_RUN_STEP * 10 * BLOCK_RUNS * 10_000
    assert ten.runtime >= 3 * ten_cpu_s / 60 and one.runtime == 5


@pytest.mark.slow
@pytest.mark.workflow
def test_workflow_chunk_jobs_merge_to_the_one_process_bytes(tmp_path):
    """In a copy of the repository, a scenario of 600 runs with chunk_runs 256 runs as three
    chunk jobs and a merge; its results files equal, byte for byte, those of the one-process
    command (python -m pipeline.altimeter_attitude.run) on the same file."""
    repo = tmp_path / "repo"
    copy_repo(repo)
    raw = short_raw()
    raw["monte_carlo"].update(n_runs=600, chunk_runs=256)
    scenario = "config/scenarios/altimeter_attitude/chunked.yaml"
    (repo / scenario).write_text(yaml.safe_dump(raw, sort_keys=False), encoding="utf-8")
    target = "results/altimeter_attitude/chunked/provenance.json"
    r = snakemake(target, "--cores", "2", cwd=repo, timeout=HANG_GUARD_S)
    log = r.stdout + r.stderr
    assert r.returncode == 0, log[-5000:]
    chunk_files = sorted((repo / "results/altimeter_attitude/chunked/chunks").iterdir())
    assert [p.name for p in chunk_files] == ["0.mcsums", "1.mcsums", "2.mcsums"]
    assert log.count("rule altimeter_attitude_simulate_chunk:") == 3, log[-3000:]
    one = tmp_path / "one"
    cmd = [sys.executable, "-m", "pipeline.altimeter_attitude.run", "--scenario", scenario]
    done = subprocess.run(
        [*cmd, "--out-dir", str(one)],
        cwd=repo,
        env={"PYTHONPATH": str(repo), "PATH": "/usr/bin:/bin"},
        capture_output=True,
        text=True,
        timeout=HANG_GUARD_S,
    )
    assert done.returncode == 0, done.stderr[-3000:]
    want = _files(one)
    got = {n: b for n, b in _files(repo / "results/altimeter_attitude/chunked").items()}
    assert sorted(want) == sorted(got) and len(want) == 9
    assert [n for n in want if want[n] != got[n]] == []
