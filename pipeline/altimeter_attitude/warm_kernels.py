"""Compile the altimeter_attitude numba kernels into numba's on-disk cache at set-up, so that the
workflow's jobs load them (~0.1 CPU-s each) instead of compiling them (~11 CPU-s in all on an
empty cache, paid by whichever of the simulate, sweep and ukf_tuning jobs comes first while the
others wait, idle, on the cache's lock: :mod:`pipeline.altimeter_attitude.jit`).

``python -m pipeline.altimeter_attitude.warm_kernels [--force]`` (``make warm-kernels``, run by
``make reproduce`` and ``make test`` after the project's install). numba compiles one machine
code per signature, the types of the arguments, array layouts included (C-contiguous or not,
ndim, dtype): a warm-up must pass the very types the workflow's jobs pass. So it runs the
workflow's own entry code with every array the same shape but the run axis: each scenario of
``config/scenarios/altimeter_attitude/`` through :func:`~pipeline.altimeter_attitude.run.run_scenario`
(the simulate step: Monte Carlo blocks and the one-run noise-free pass), the published scenario
through :func:`~pipeline.altimeter_attitude.chunks.simulate_chunk` (the chunk step) and
:func:`~pipeline.altimeter_attitude.ukf_tuning.run_tuning` (its grid), and the sweep of
config/config.yaml through :func:`~pipeline.altimeter_attitude.sweep.run_sweep`, with
:data:`WARM_RUNS` Monte Carlo runs instead of the scenarios' 100 (more than one, as in the real
runs: an axis of size 1 can make numpy call an array C-contiguous that is not otherwise) and
each flight cut to its transient and :data:`WARM_FLIGHT_S` more (still hundreds of steps and
several of the linear KF's 256-step chunks). That costs ~1.5-2 CPU-s besides the compilation. tests/altimeter_attitude/test_warm_kernels_altimeter_attitude.py
runs the workflow's step functions after it, in a fresh process on the same cache, and fails
if they compile anything.

A warm cache costs nothing: after a warm-up, a stamp (``warm_kernels.json`` in numba's cache
base directory, ``.snakemake/numba-cache`` or ``NUMBA_CACHE_DIR``) records the fingerprint of
what it ran (the contents of the altimeter_attitude modules, the generated formulas, the
config and scenario files; the Python, numba and numpy versions), and a later call whose
fingerprint matches, and whose cache directory is still there, prints so and exits (~0.1
CPU-s). ``make clean`` removes the stamp with the cache.

After set-up, a changed source file is handled by numba, not here: a cached function's index
entry keys on the source stamp of the file it is defined in (numba 0.68: the sha256 of the
file's bytes, so a ``touch`` or a fresh checkout changes nothing), so a job that calls a
kernel whose file was edited finds the index stale and compiles it again (correct, as slow as
before this warm-up existed); a changed ``jit.py`` or generated module starts a fresh cache
directory (jit.cache_key). The next ``make reproduce`` or ``make test`` sees the changed
fingerprint and warms the cache again before the workflow (~1.5 CPU-s plus the compilation
of what changed; a change that does not touch the kernels compiles nothing). What it cannot see: a ``CONFIG=`` file's values (types do not depend on
them), and machines other than this one (numba's cache entries are per CPU model: SLURM nodes
of another model compile their own).

A failed warm-up does not stop the set-up: it prints the traceback and a warning (the
workflow's jobs then compile the kernels, and fail with the same error in their own log if
the kernels are broken), writes no stamp, and exits 0.
"""

from __future__ import annotations

import argparse
import hashlib
import json
import math
import os
import resource
import sys
import tempfile
import traceback
import warnings
from dataclasses import dataclass
from importlib.metadata import version
from pathlib import Path

__all__ = [
    "WARM_RUNS",
    "KernelStat",
    "WarmReport",
    "cache_base",
    "fingerprint",
    "kernel_stats",
    "main",
    "warm",
]

ROOT = Path(__file__).resolve().parents[2]
#: Monte Carlo runs of each warm-up run (> 1: see the module docstring)
WARM_RUNS = 2
#: seconds of flight after the scenario's transient that each warm-up run keeps
WARM_FLIGHT_S = 10.0
STAMP_NAME = "warm_kernels.json"


@dataclass(frozen=True)
class WarmReport:
    """What a warm-up did: the kernels it called, the signatures numba compiled and those it
    loaded from the cache, the cache directory and the CPU seconds it took."""

    kernels: int
    compiled: int
    loaded: int
    cache_dir: str
    cpu_s: float


def cache_base() -> Path:
    """numba's cache base directory as :mod:`pipeline.altimeter_attitude.jit` chooses it
    (without importing numba): ``NUMBA_CACHE_DIR``, else the checkout's
    ``.snakemake/numba-cache``; jit adds the key directory below it."""
    return Path(os.environ.get("NUMBA_CACHE_DIR") or ROOT / ".snakemake" / "numba-cache")


def _watched(root: Path) -> list[Path]:
    """The files whose change may change what the workflow compiles or how."""
    return sorted(
        [
            *(root / "pipeline" / "altimeter_attitude").glob("*.py"),
            root / "pipeline" / "generated" / "altimeter_attitude.py",
            root / "config" / "config.yaml",
            *(root / "config" / "scenarios" / "altimeter_attitude").glob("*.yaml"),
        ]
    )


def fingerprint(root: Path = ROOT) -> str:
    """A hash of the watched files' paths and contents and of the versions that decide
    numba's cache (Python, numba, numpy)."""
    digest = hashlib.sha256(f"{sys.version}|{version('numba')}|{version('numpy')}".encode())
    for path in _watched(root):
        digest.update(f"|{path}|".encode())
        digest.update(hashlib.sha256(path.read_bytes()).digest())
    return digest.hexdigest()


@dataclass(frozen=True)
class KernelStat:
    """One kernel's signatures numba compiled and those it loaded from the cache, in this
    process (numba's dispatcher statistics)."""

    name: str
    compiled: tuple[str, ...]
    loaded: tuple[str, ...]


def kernel_stats() -> list[KernelStat]:
    """A :class:`KernelStat` per :func:`pipeline.altimeter_attitude.jit.kernel` called in this
    process, of the altimeter_attitude modules imported (sorted by name)."""
    from numba.core.dispatcher import Dispatcher

    seen: dict[int, tuple[str, Dispatcher]] = {}
    for name, module in list(sys.modules.items()):
        if not name.startswith("pipeline.altimeter_attitude.") or module is None:
            continue
        for value in vars(module).values():
            disp = getattr(value, "dispatcher", None)
            if isinstance(disp, Dispatcher) and disp.signatures:
                seen[id(disp)] = (f"{disp.py_func.__module__}.{disp.py_func.__name__}", disp)
    stats = [
        KernelStat(
            name,
            tuple(str(sig) for sig in disp.stats.cache_misses),
            tuple(str(sig) for sig in disp.stats.cache_hits),
        )
        for name, disp in seen.values()
    ]
    return sorted(stats, key=lambda k: k.name)


def _cpu_s() -> float:
    usage = resource.getrusage(resource.RUSAGE_SELF)
    return usage.ru_utime + usage.ru_stime


def _quiet(message: str) -> None:
    pass


def warm(runs: int = WARM_RUNS, root: Path = ROOT) -> WarmReport:
    """Run the workflow's kernel-calling entry code on ``runs`` Monte Carlo runs (see the
    module docstring); returns what numba compiled and loaded."""
    if runs < 2:
        raise ValueError(f"runs = {runs}: must be >= 2 (a run axis of 1 may type differently)")
    start = _cpu_s()
    from pipeline.altimeter_attitude import jit  # sets NUMBA_CACHE_DIR to the key directory
    from pipeline.altimeter_attitude.chunks import simulate_chunk
    from pipeline.altimeter_attitude.run import run_scenario
    from pipeline.altimeter_attitude.scenario import Scenario, build_scenario, load_scenario
    from pipeline.altimeter_attitude.sweep import run_sweep
    from pipeline.altimeter_attitude.ukf_tuning import run_tuning
    from pipeline.config import load_yaml

    def small(sc: Scenario) -> Scenario:
        raw = {**sc.raw, "monte_carlo": {**sc.raw["monte_carlo"], "n_runs": runs}}
        tr, every = raw["trajectory"], 1.0 / sc.output_rate
        cut = math.ceil((sc.transient + WARM_FLIGHT_S) / every) * every
        if cut < tr["duration_s"]:
            kept = [m for m in tr["maneuvers"] if m["start_s"] + m["duration_s"] <= cut]
            raw["trajectory"] = {**tr, "duration_s": cut, "maneuvers": kept}
        return build_scenario(raw, sc.path)

    settings = load_yaml(root / "config" / "config.yaml")["altimeter_attitude"]
    directory = root / "config" / "scenarios" / "altimeter_attitude"
    published = small(load_scenario(directory / f"{settings['published_scenario']}.yaml"))
    with warnings.catch_warnings(), tempfile.TemporaryDirectory(prefix="warm-kernels-") as tmp:
        warnings.simplefilter("ignore")  # (statistics of 2 runs: empty windows, NaN means)
        for path in sorted(directory.glob("*.yaml")):
            sc = small(load_scenario(path))
            run_scenario(sc, Path(tmp) / sc.name, log=_quiet)
        simulate_chunk(published, (0, runs), log=_quiet)
        sweep = settings["sweep"]
        run_sweep(
            small(load_scenario(root / sweep["base_scenario"])),
            dict(sweep["values"]),
            runs,
            tuple(sweep["filters"]),
            log=_quiet,
        )
        grid = settings["ukf_tuning"]
        run_tuning(published, list(grid["alpha"]), list(grid["kappa"]), runs, log=_quiet)
    stats = kernel_stats()
    return WarmReport(
        len(stats),
        sum(len(k.compiled) for k in stats),
        sum(len(k.loaded) for k in stats),
        str(jit.jit_lock_path().parent),
        _cpu_s() - start,
    )


def _relative(path: str | Path) -> str:
    try:
        return str(Path(path).resolve().relative_to(Path.cwd().resolve()))
    except ValueError:
        return str(path)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--force", action="store_true", help="run even if the stamp says the cache is warm"
    )
    args = parser.parse_args(argv)
    stamp = cache_base() / STAMP_NAME
    fp = fingerprint()
    if not args.force:
        try:
            seen = json.loads(stamp.read_text())
        except (OSError, ValueError):
            seen = {}
        if seen.get("fingerprint") == fp and Path(seen.get("cache_dir", "")).is_dir():
            print(
                f"numba kernels: cache warm ({_relative(seen['cache_dir'])}, unchanged sources), "
                "nothing to compile"
            )
            return 0
    try:
        report = warm()
    except Exception:  # noqa: BLE001  (an optimisation: the workflow compiles what is missing)
        traceback.print_exc()
        print(
            "warning: numba kernels: the warm-up failed (traceback above); the workflow's jobs "
            "will compile the kernels themselves",
            file=sys.stderr,
        )
        return 0
    print(
        f"numba kernels: {report.compiled} signatures compiled, {report.loaded} loaded from the "
        f"cache, {report.kernels} kernels, {report.cpu_s:.1f} CPU-s "
        f"({_relative(report.cache_dir)})"
    )
    try:
        stamp.write_text(json.dumps({"fingerprint": fp, "cache_dir": report.cache_dir}) + "\n")
    except OSError as exc:  # a read-only cache: the next call warms again (loads, ~2 CPU-s)
        print(f"warning: numba kernels: stamp not written: {exc}", file=sys.stderr)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
