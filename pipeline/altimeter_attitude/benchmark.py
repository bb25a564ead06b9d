"""Benchmark: the altimeter-attitude filters against filterpy, and the Monte Carlo's scaling.

``python -m pipeline.altimeter_attitude.benchmark [--runs 100] [--steps 1000] [--repeats 7]
[--scaling 100,1000,10000] [--max-cpu-s 300] [--full] [--workflow-runs 10000] [--jobs 2]
[--chunk-runs N]`` (or ``make bench``). Times are CPU seconds of this process
(``time.process_time``) or of a child (``resource``), so a loaded machine inflates them less;
part 4 also prints wall time, the only one. Five parts (run in the order 1, 2, 3, 5, 4):

1. each filter's CPU time on the scenario's ``--runs`` runs (one pass; numba compiled, cached);
2. our UKF against filterpy 2.0.0's ``UnscentedKalmanFilter`` on the SAME runs' first
   ``--steps`` steps, same sigma points (Van der Merwe), noise and data, filterpy given a plain
   scalar RK4 of the model (the generated formulas, compiled, called per sigma point: the
   cheapest model filterpy can be handed, so the comparison is fair to it). The two are
   measured alternately ``--repeats`` times in one process; the median per-step costs, their
   spread (min-max), the median of the paired ratios (filterpy per step / ours per step x run)
   and the largest difference between the two UKFs' roll/pitch are printed;
3. the full Monte Carlo of the scenario (every filter, every results file written to a
   temporary directory, as ``run.py`` does) at each ``--scaling`` size, each in a fresh child
   process: CPU seconds, peak RSS, CPU per run-step. A size whose CPU, extrapolated linearly
   from the largest measured one, exceeds ``--max-cpu-s`` is extrapolated (said so) unless
   ``--full``; its peak RSS is the largest size's plus the per-run growth between the two
   largest sizes of at least one block (memory is one block's histories plus per-run rows);
4. ``--workflow-runs`` runs the way the workflow runs them with ``monte_carlo.chunk_runs``
   (:mod:`pipeline.altimeter_attitude.chunks`): one fresh process per chunk of ``--chunk-runs``
   runs (default: the scenario's, else the runs split evenly over ``--jobs``, in whole blocks),
   at most ``--jobs`` at once (Snakemake's ``--cores``), then the merge writing every results
   file. Wall time from the first start to the merge's end, the CPU of every process (the
   chunks' sum is what one core would spend), the largest peak RSS of any one process;
5. the cost against the steps: every filter on the ``--runs`` runs' first 1/8, 1/4, 1/2 and
   all of their steps, in this process with freed memory kept (as the workflow's steps run;
   the filters only: the metrics need the whole flight), the lengths interleaved
   ``--repeats`` times: the median CPU per run-step of each and the ratio of the longest's
   to the shortest's (1 = linear).

The targets of issue 15 are printed against the measured values: UKF >= 100x filterpy per
(step x run); 10,000 runs in <= 5 min and < 4 GB, on one core (part 3: CPU) and as the
workflow runs them on ``--jobs`` cores (part 4: wall, and CPU beside it). filterpy is a
test/benchmark dependency only.

Last measured (issue 15, 2026-12-05, 2-core Intel Xeon 2.6 GHz, idle; `make bench`): UKF
0.690 us per step x run against filterpy's 215.9 us per step, median ratio 309x; the paper
scenario's full Monte Carlo at 10,000 runs in one process 203 CPU-s (2.03 us per run-step),
0.48 GB peak RSS (memory is one batch's histories: flat in the runs); part 4, two chunks of
5,120 and 4,880 runs at once: 106 s wall, 205 CPU-s, <= 0.97 GB together; part 5: 1.86-1.94
us per run-step from 1,250 to 10,000 steps. Every target met. The README's Benchmarks
section keeps the table.
"""

from __future__ import annotations

import argparse
import dataclasses
import json
import resource
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

from pipeline.altimeter_attitude import euler_filters, run
from pipeline.altimeter_attitude.mc_sums import BLOCK_RUNS
from pipeline.altimeter_attitude.scenario import load_scenario
from pipeline.altimeter_attitude.sensors import Inputs, simulate_inputs

__all__ = ["filterpy_ukf", "truncate", "main"]

MODULE = "pipeline.altimeter_attitude.benchmark"
RATIO_TARGET = 100.0
MC_RUNS_TARGET, MC_CPU_TARGET_S, MC_RSS_TARGET_GB = 10_000, 300.0, 4.0


def truncate(inputs: Inputs, steps: int) -> Inputs:
    """The first ``steps`` steps of every run (the filters only; the truth is dropped)."""
    return dataclasses.replace(
        inputs,
        gyro=inputs.gyro[:, :steps],
        accel=inputs.accel[:, :steps],
        altimeter=inputs.altimeter[:, : steps + 1],
        truth=None,
    )


def filterpy_ukf(inputs: Inputs, run_index: int, alpha: float, beta: float, kappa: float):
    """filterpy's UKF on run ``run_index``: the (T + 1, 4) state history.

    Its model is a plain scalar RK4 over the compiled generated right-hand side (one call
    per stage and sigma point, ~1 us), and Q the compiled generated process noise."""
    from filterpy.kalman import MerweScaledSigmaPoints, UnscentedKalmanFilter

    from pipeline.altimeter_attitude import jit

    dt, g, sens = inputs.dt, inputs.g, inputs.sensors
    rhs = jit.euler_model_rhs
    gyro_var, accel_var = sens.gyro_sigma**2, sens.accel_sigma**2
    floor = euler_filters.Q_FLOOR * np.eye(4)

    def fx(x, dt_, gyro, accel):
        w0, w1, w2 = gyro
        f0, f1, f2 = accel
        k1 = np.array(rhs(x[0], x[1], x[2], x[3], w0, w1, w2, f0, f1, f2, g))
        y = x + 0.5 * dt_ * k1
        k2 = np.array(rhs(y[0], y[1], y[2], y[3], w0, w1, w2, f0, f1, f2, g))
        y = x + 0.5 * dt_ * k2
        k3 = np.array(rhs(y[0], y[1], y[2], y[3], w0, w1, w2, f0, f1, f2, g))
        y = x + dt_ * k3
        k4 = np.array(rhs(y[0], y[1], y[2], y[3], w0, w1, w2, f0, f1, f2, g))
        return x + dt_ / 6.0 * (k1 + 2 * k2 + 2 * k3 + k4)

    points = MerweScaledSigmaPoints(4, alpha=alpha, beta=beta, kappa=kappa)
    ukf = UnscentedKalmanFilter(4, 1, dt, hx=lambda x: x[3:4], fx=fx, points=points)
    ukf.x = inputs.x0_euler[run_index].copy()
    ukf.P = np.diag(inputs.sigma0[run_index] ** 2)
    ukf.R = np.array([[sens.altimeter_sigma**2]])
    gyro, accel, alt = inputs.gyro[run_index], inputs.accel[run_index], inputs.altimeter[run_index]
    out = np.empty((inputs.n_steps + 1, 4))
    out[0] = ukf.x
    for k in range(inputs.n_steps):
        q = jit.euler_process_noise(ukf.x[0], ukf.x[1], dt, gyro_var, accel_var)
        ukf.Q = np.array(q).reshape(4, 4) + floor
        ukf.predict(gyro=gyro[k], accel=accel[k])
        if not np.isnan(alt[k + 1]):
            ukf.update(np.array([alt[k + 1]]))
        out[k + 1] = ukf.x
    return out


def _cpu(fn):
    start = time.process_time()
    value = fn()
    return time.process_time() - start, value


def filter_costs(sc, inputs: Inputs) -> None:
    steps, n = inputs.n_steps, inputs.n_runs
    print(f"1. each filter, {n} runs x {steps} steps (CPU s; us per step x run)")
    run.run_filters(sc, truncate(inputs, 2), log=lambda m: None)  # compile / load the kernels
    for name in ("linear_kf", "linear_kf_no_gamma", "gyro_only", "ukf", "ekf", "complementary"):
        sec, _ = _cpu(lambda name=name: run.run_filters(sc, inputs, (name,), log=lambda m: None))
        print(f"   {name:20s} {sec:7.2f} s  {1e6 * sec / (n * steps):8.3f} us")


def ukf_vs_filterpy(sc, inputs: Inputs, repeats: int) -> float:
    """Interleaved measurements; returns the median paired ratio."""
    n, steps = inputs.n_runs, inputs.n_steps
    args = (sc.ukf_alpha, sc.ukf_beta, sc.ukf_kappa)
    euler_filters.run_ukf(truncate(inputs, 2), *args)  # compile / load the kernels first
    filterpy_ukf(truncate(inputs, 20), 0, *args)  # and filterpy's imports, the model's dispatch
    ours_us, fp_us, ratios, diff = [], [], [], 0.0
    for r in range(repeats):
        sec, ours = _cpu(lambda: euler_filters.run_ukf(inputs, *args))
        ours_us.append(1e6 * sec / (n * steps))
        i = r % n
        sec, ref = _cpu(lambda i=i: filterpy_ukf(inputs, i, *args))
        fp_us.append(1e6 * sec / steps)
        ratios.append(fp_us[-1] / ours_us[-1])
        diff = max(
            diff, np.abs(ours.roll[i] - ref[:, 0]).max(), np.abs(ours.pitch[i] - ref[:, 1]).max()
        )
    print(
        f"2. UKF vs filterpy's UnscentedKalmanFilter, {steps} steps, {repeats} interleaved "
        f"repeats (ours on {n} runs, filterpy on one run each time; CPU)"
    )
    for label, v in (("ours, per step x run", ours_us), ("filterpy, per step", fp_us)):
        print(
            f"   {label:22s} median {statistics.median(v):9.3f} us  "
            f"(min {min(v):.3f}, max {max(v):.3f})"
        )
    ratio = statistics.median(ratios)
    print(
        f"   ratio filterpy / ours per (step x run): median {ratio:.0f}x (min {min(ratios):.0f}x,"
        f" max {max(ratios):.0f}x); target >= {RATIO_TARGET:.0f}x: "
        f"{'met' if ratio >= RATIO_TARGET else 'NOT met'}"
    )
    print(f"   largest roll/pitch difference, ours vs filterpy: {diff:.2e} rad")
    return ratio


def child(scenario: Path, n_runs: int) -> int:
    """One full Monte Carlo (run_scenario into a temporary directory); prints JSON."""
    from pipeline.altimeter_attitude.heap import keep_freed_memory

    keep_freed_memory()  # as the workflow's steps do
    cpu0, wall0 = time.process_time(), time.perf_counter()
    with tempfile.TemporaryDirectory() as tmp:
        run.run_scenario(scenario, tmp, n_runs, log=lambda m: None)
    usage = resource.getrusage(resource.RUSAGE_SELF)
    out = {
        "cpu_s": time.process_time() - cpu0,
        "wall_s": time.perf_counter() - wall0,
        "peak_rss_gb": usage.ru_maxrss / 1024**2,  # ru_maxrss is in KiB on Linux
    }
    print(json.dumps(out))
    return 0


def scaling(scenario: Path, sizes: list[int], steps: int, max_cpu_s: float, full: bool) -> None:
    print("3. full Monte Carlo of the scenario (every filter and results file), fresh process each")
    print(f"   {'runs':>7s} {'CPU s':>9s} {'peak RSS GB':>12s} {'us/run-step':>12s}")
    done: list[tuple[int, dict]] = []
    for n in sizes:
        if done and not full:
            n0, m0 = done[-1]
            guess = m0["cpu_s"] * n / n0
            if guess > max_cpu_s:
                rss = m0["peak_rss_gb"]
                # the histories are one block's (BLOCK_RUNS runs): past it only the per-run
                # rows grow; that slope from the last two sizes of at least a block
                full_blocks = [(k, v) for k, v in done if k >= BLOCK_RUNS]
                if len(full_blocks) > 1:
                    (n1, m1), (n2, m2) = full_blocks[-2:]
                    rss += max(0.0, m2["peak_rss_gb"] - m1["peak_rss_gb"]) * (n - n2) / (n2 - n1)
                print(
                    f"   {n:7d} {guess:9.1f} {rss:12.2f} {1e6 * guess / (n * steps):12.3f}  "
                    f"EXTRAPOLATED from {n0} runs (over --max-cpu-s {max_cpu_s:g}; --full runs it)"
                )
                done.append((n, {"cpu_s": guess, "peak_rss_gb": rss, "extrapolated": True}))
                continue
        cmd = [sys.executable, "-m", MODULE, "--scenario", str(scenario), "--child-runs", str(n)]
        res = subprocess.run(cmd, capture_output=True, text=True)
        if res.returncode != 0:
            raise RuntimeError(f"benchmark child for {n} runs failed:\n{res.stderr}")
        m = json.loads(res.stdout.strip().splitlines()[-1])
        print(
            f"   {n:7d} {m['cpu_s']:9.1f} {m['peak_rss_gb']:12.2f} "
            f"{1e6 * m['cpu_s'] / (n * steps):12.3f}"
        )
        done.append((n, m))
    big = [m for n, m in done if n == MC_RUNS_TARGET]
    if big:
        m = big[0]
        how = "extrapolated" if m.get("extrapolated") else "measured"
        print(
            f"   target {MC_RUNS_TARGET} runs <= {MC_CPU_TARGET_S:g} s and < {MC_RSS_TARGET_GB:g} GB:"
            f" {m['cpu_s']:.0f} CPU-s ({'met' if m['cpu_s'] <= MC_CPU_TARGET_S else 'NOT met'}),"
            f" {m['peak_rss_gb']:.2f} GB ({'met' if m['peak_rss_gb'] < MC_RSS_TARGET_GB else 'NOT met'})"
            f" [{how}]"
        )
        per = 1e6 * m["cpu_s"] / (MC_RUNS_TARGET * steps)
        need = 1e6 * MC_CPU_TARGET_S / (MC_RUNS_TARGET * steps)
        print(
            f"   i.e. {per:.2f} us per run-step, all filters and results files (target <= "
            f"{need:.2f}: {'met' if per <= need else 'NOT met'}) [{how}]"
        )


def step_scaling(
    sc, inputs: Inputs, parts: tuple[int, ...] = (8, 4, 2, 1), repeats: int = 3
) -> list[float]:
    """Part 5: every filter on the same runs' first ``T = steps / k`` steps (``k`` in
    ``parts``), in this process, the lengths interleaved ``repeats`` times: CPU per run-step
    flat in T means the cost is linear in the steps (part 3 shows it in the runs). Returns the
    median us per run-step, shortest first."""
    n, steps = inputs.n_runs, inputs.n_steps
    print(
        f"5. cost against steps: every filter on the same {n} runs, their first T steps "
        f"(CPU, this process, median of {repeats} interleaved; part 3 varies the runs)"
    )
    from pipeline.altimeter_attitude.heap import keep_freed_memory

    keep_freed_memory()  # as the workflow's Monte Carlo steps run (from here on: after parts 1-2)
    lengths = [steps // k for k in parts]
    us: dict[int, list[float]] = {t: [] for t in lengths}
    for _ in range(repeats):
        for t in lengths:
            sec, _ = _cpu(lambda t=t: run.run_filters(sc, truncate(inputs, t), log=lambda m: None))
            us[t].append(1e6 * sec / (n * t))
    print(f"   {'steps':>7s} {'us/run-step':>12s}  (min-max)")
    per = [statistics.median(us[t]) for t in lengths]
    for t, med in zip(lengths, per, strict=True):
        print(f"   {t:7d} {med:12.3f}  ({min(us[t]):.3f}-{max(us[t]):.3f})")
    print(
        f"   us per run-step at {steps} steps / at {steps // parts[0]}: {per[-1] / per[0]:.2f} "
        "(1.00 = linear in the steps)"
    )
    return per


def workflow_part(scenario: Path, n_runs: int, jobs: int, chunk_runs: int | None, steps: int):
    """Part 4: the Monte Carlo in chunk processes, ``jobs`` at once, and the merge."""
    from pipeline.altimeter_attitude.bench_chunks import workflow_run

    wall, chunks, merge = workflow_run(scenario, n_runs, jobs, chunk_runs)
    cpu = sum(c.cpu_s for c in chunks) + merge.cpu_s
    rss = max(c.peak_rss_gb for c in [*chunks, merge])
    together = sum(sorted((c.peak_rss_gb for c in chunks), reverse=True)[:jobs])
    print(
        f"4. {n_runs} runs as the workflow runs them: {len(chunks)} chunk processes, {jobs} at "
        "once, then the merge (fresh processes, compiled kernels from the cache)"
    )
    for c in [*chunks, merge]:
        print(f"   {c.label:10s} {c.cpu_s:8.1f} CPU-s {c.peak_rss_gb:6.2f} GB peak RSS")
    print(
        f"   wall {wall:.1f} s; CPU {cpu:.1f} s in all ({1e6 * cpu / (n_runs * steps):.2f} us per "
        f"run-step, the one-core figure); peak RSS {rss:.2f} GB per process, <= {together:.2f} GB"
        f" for the {jobs} largest chunks at once"
    )
    if n_runs == MC_RUNS_TARGET:
        ok = "met" if wall <= MC_CPU_TARGET_S else "NOT met"
        mem = "met" if together < MC_RSS_TARGET_GB else "NOT met"
        print(
            f"   target {MC_RUNS_TARGET} runs <= {MC_CPU_TARGET_S:g} s and < {MC_RSS_TARGET_GB:g} GB"
            f" on {jobs} cores: wall {wall:.0f} s ({ok}), {together:.2f} GB ({mem}); on one core"
            f" {cpu:.0f} CPU-s ({'met' if cpu <= MC_CPU_TARGET_S else 'NOT met'}) [measured]"
        )


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--scenario", type=Path, default=Path("config/scenarios/altimeter_attitude/paper.yaml")
    )
    parser.add_argument("--runs", type=int, default=100, help="runs of parts 1 and 2")
    parser.add_argument("--steps", type=int, default=1000, help="steps of part 2")
    parser.add_argument("--repeats", type=int, default=7, help="interleaved repeats of part 2")
    parser.add_argument("--scaling", default="100,1000,10000", help="run counts of part 3")
    parser.add_argument("--max-cpu-s", type=float, default=300.0)
    parser.add_argument("--full", action="store_true", help="measure every size of part 3")
    parser.add_argument(
        "--workflow-runs", type=int, default=MC_RUNS_TARGET, help="runs of part 4 (0: skip it)"
    )
    parser.add_argument("--jobs", type=int, default=2, help="chunk processes at once (part 4)")
    parser.add_argument("--chunk-runs", type=int, default=None, help="runs per chunk (part 4)")
    parser.add_argument("--parts", default="1,2,3,5,4", help="which parts to run")
    parser.add_argument("--child-runs", type=int, default=None, help=argparse.SUPPRESS)
    args = parser.parse_args(argv)
    if args.child_runs is not None:
        return child(args.scenario, args.child_runs)
    try:
        sizes = [int(s) for s in args.scaling.split(",") if s.strip()]
    except ValueError:
        parser.error(f"--scaling {args.scaling!r}: comma-separated integers >= 2 expected")
    if args.runs < 1 or args.steps < 1 or args.repeats < 1 or any(s < 2 for s in sizes):
        parser.error("need --runs, --steps, --repeats >= 1 and --scaling sizes >= 2")
    if args.jobs < 1 or args.workflow_runs < 0:
        parser.error("need --jobs >= 1 and --workflow-runs >= 0")
    parts = {p.strip() for p in args.parts.split(",")}
    sc = load_scenario(args.scenario)
    inputs = simulate_inputs(sc.profiles, sc.sensors, sc.initial, args.runs, sc.seed, sc.name)
    print(
        f"scenario {sc.name}: {args.runs} runs x {inputs.n_steps} steps ({sc.sensors.rate_hz:g} Hz)"
    )
    run.run_filters(sc, truncate(inputs, 2), log=lambda m: None)  # the kernels compiled, cached
    if "1" in parts:
        filter_costs(sc, inputs)
    if "2" in parts:
        ukf_vs_filterpy(sc, truncate(inputs, min(args.steps, inputs.n_steps)), args.repeats)
    if "3" in parts:
        scaling(args.scenario, sorted(sizes), inputs.n_steps, args.max_cpu_s, args.full)
    if "5" in parts:
        step_scaling(sc, inputs, repeats=args.repeats)
    if "4" in parts and args.workflow_runs:
        workflow_part(args.scenario, args.workflow_runs, args.jobs, args.chunk_runs, inputs.n_steps)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
