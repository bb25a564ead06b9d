"""The set-up's numba warm-up (pipeline/altimeter_attitude/warm_kernels.py): after it, the
workflow's altimeter_attitude steps compile nothing; its stamp skips a warm cache; a failure is
a warning."""

from __future__ import annotations

import json
import os
import re
import subprocess
import sys
from pathlib import Path

from pipeline.altimeter_attitude import warm_kernels
from pipeline.altimeter_attitude.scenario import ROOT
from tests.hang_guard import HANG_GUARD_S

#: the kernels the workflow's Monte Carlo steps call (jit.kernel)
KERNELS = {
    "pipeline.altimeter_attitude.kernels_c.complementary_runs",
    "pipeline.altimeter_attitude.kernels_c.linear_kf_chunk",
    "pipeline.altimeter_attitude.kernels_euler.ekf_runs",
    "pipeline.altimeter_attitude.kernels_euler.ukf_runs",
    "pipeline.altimeter_attitude.mc_sums._accumulate",
}

# The workflow's step functions, called as pipeline.steps.run_step calls them, on the published
# scenario with 3 runs and a 40 s flight (sizes the warm-up, 2 runs and 30 s, does not use), and
# the chunk step's Monte Carlo (its step function chunks only scenarios of > 256 runs); prints
# every called kernel's compiled and loaded signatures.
STEPS = r"""
import json, sys
from dataclasses import asdict
from pathlib import Path
import yaml
from pipeline.altimeter_attitude import chunks, steps, ukf_tuning, warm_kernels
from pipeline.altimeter_attitude.scenario import load_scenario
from pipeline.config import load_yaml

root, tmp = Path(sys.argv[1]), Path(sys.argv[2])
settings = load_yaml(root / "config" / "config.yaml")["altimeter_attitude"]
name = settings["published_scenario"]
raw = load_yaml(root / "config" / "scenarios" / "altimeter_attitude" / f"{name}.yaml")
raw["monte_carlo"]["n_runs"] = 3
tr = raw["trajectory"]
tr["duration_s"] = 40.0
tr["maneuvers"] = [m for m in tr["maneuvers"] if m["start_s"] + m["duration_s"] <= 40.0]
scenario = tmp / f"{name}.yaml"
scenario.write_text(yaml.safe_dump(raw, sort_keys=False))
inp = {"scenario": str(scenario)}
out = tmp / "results"
log = lambda message: None
steps.simulate({**inp, "chunks": []}, {"rms_summary": str(out / "s" / "x.csv")}, {}, log)
chunks.simulate_chunk(load_scenario(scenario), (0, 3), log=log)
sweep = {**settings["sweep"], "n_runs": 3}
outs = {"sweep": str(out / "sweep.csv"), "trouble": str(out / "sweep_trouble.csv")}
steps.sweep(inp, outs, {"sweep": sweep}, log)
grid = {**settings["ukf_tuning"], "n_runs": 3}
ukf_tuning.tuning_step(inp, {"ukf_tuning": str(out / "t.csv")}, {"ukf_tuning": grid}, log)
print(json.dumps([asdict(k) for k in warm_kernels.kernel_stats()]))
"""


def _run(args: list[str], cache: Path) -> subprocess.CompletedProcess:
    env = {**os.environ, "NUMBA_CACHE_DIR": str(cache), "PYTHONPATH": str(ROOT)}
    return subprocess.run(
        [sys.executable, *args], cwd=ROOT, env=env, capture_output=True, text=True,
        timeout=HANG_GUARD_S,
    )  # fmt: skip


def test_workflow_steps_compile_nothing_after_the_warm_up(tmp_path):
    """On an empty numba cache (this test's own) the warm-up compiles every kernel; then the
    workflow's steps (simulate, a chunk's Monte Carlo, the sweep, the UKF tuning), in a fresh
    process on that cache, call every kernel and load each from the cache: no signature
    compiled, none the warm-up missed."""
    cache = tmp_path / "numba"
    warm = _run(["-m", "pipeline.altimeter_attitude.warm_kernels"], cache)
    assert warm.returncode == 0, warm.stderr
    line = re.fullmatch(
        r"numba kernels: (\d+) signatures compiled, 0 loaded from the cache, (\d+) kernels, .*",
        warm.stdout.strip(),
    )
    assert line, warm.stdout + warm.stderr
    assert int(line[1]) >= len(KERNELS) and int(line[2]) == len(KERNELS)
    assert "warning" not in warm.stderr, warm.stderr

    work = tmp_path / "steps"
    work.mkdir()
    done = _run(["-c", STEPS, str(ROOT), str(work)], cache)
    assert done.returncode == 0, done.stderr[-3000:]
    stats = json.loads(done.stdout.strip().splitlines()[-1])
    assert {k["name"] for k in stats} == KERNELS
    compiled = {k["name"]: k["compiled"] for k in stats if k["compiled"]}
    assert not compiled, f"compiled by the workflow's steps, missed by the warm-up: {compiled}"
    assert all(k["loaded"] for k in stats)  # each from the cache (so a compile would count)


def _stamp(tmp_path: Path, fingerprint: str, cache_dir: Path) -> Path:
    stamp = tmp_path / warm_kernels.STAMP_NAME
    stamp.write_text(json.dumps({"fingerprint": fingerprint, "cache_dir": str(cache_dir)}))
    return stamp


def test_stamp_skips_a_warm_cache_and_a_failure_is_a_warning(tmp_path, monkeypatch, capsys):
    """No stamp, a stale one, or one whose cache directory is gone: the warm-up runs (here a
    stub that fails: a warning naming the error, exit status 0, no stamp written); a stamp of
    the current fingerprint with its cache directory: nothing runs."""
    monkeypatch.setenv("NUMBA_CACHE_DIR", str(tmp_path))
    calls: list[int] = []

    def broken() -> warm_kernels.WarmReport:
        calls.append(1)
        raise RuntimeError("kernel exploded")

    monkeypatch.setattr(warm_kernels, "warm", broken)
    assert warm_kernels.main([]) == 0
    err = capsys.readouterr().err
    assert "RuntimeError: kernel exploded" in err
    assert "warning: numba kernels: the warm-up failed" in err
    assert not (tmp_path / warm_kernels.STAMP_NAME).exists() and calls == [1]

    key = tmp_path / "0123456789abcdef"
    key.mkdir()
    _stamp(tmp_path, warm_kernels.fingerprint(), key)
    assert warm_kernels.main([]) == 0
    assert "cache warm" in capsys.readouterr().out and calls == [1]
    assert warm_kernels.main(["--force"]) == 0 and calls == [1, 1]

    _stamp(tmp_path, "0" * 64, key)  # a source changed since
    assert warm_kernels.main([]) == 0 and len(calls) == 3
    _stamp(tmp_path, warm_kernels.fingerprint(), tmp_path / "gone")  # make clean, or by hand
    assert warm_kernels.main([]) == 0 and len(calls) == 4


def test_fingerprint_follows_the_watched_files(tmp_path):
    """An edited kernel module or scenario file changes the fingerprint; a ``touch`` (numba's
    cache keys on a file's bytes too) or a file the kernels do not depend on (another
    paper's) does not."""
    files = {
        "pipeline/altimeter_attitude/kernels_c.py": "x = 1\n",
        "pipeline/generated/altimeter_attitude.py": "y = 2\n",
        "pipeline/north_finding/run.py": "z = 3\n",
        "config/config.yaml": "a: 1\n",
        "config/scenarios/altimeter_attitude/paper.yaml": "b: 2\n",
    }
    for rel, text in files.items():
        (tmp_path / rel).parent.mkdir(parents=True, exist_ok=True)
        (tmp_path / rel).write_text(text)
    first = warm_kernels.fingerprint(tmp_path)
    assert warm_kernels.fingerprint(tmp_path) == first
    (tmp_path / "pipeline/north_finding/run.py").write_text("z = 33\n")
    kernel = tmp_path / "pipeline/altimeter_attitude/kernels_c.py"
    st = kernel.stat()
    os.utime(kernel, ns=(st.st_atime_ns, st.st_mtime_ns + 1_000_000_000))
    assert warm_kernels.fingerprint(tmp_path) == first
    kernel.write_text("x = 2\n")  # same size, other bytes
    second = warm_kernels.fingerprint(tmp_path)
    assert second != first
    (tmp_path / "config/scenarios/altimeter_attitude/paper.yaml").write_text("b: 22\n")
    assert warm_kernels.fingerprint(tmp_path) not in (first, second)
