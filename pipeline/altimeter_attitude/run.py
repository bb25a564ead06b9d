"""Run one altimeter-attitude scenario: Monte Carlo of every filter, and its results files.

Writes, under ``results/altimeter_attitude/<scenario>/``:

* ``rms_summary.csv`` (``RMS_SUMMARY_COLUMNS``, the contract of issue 4): per filter the RMS
  roll/pitch error over runs and over the times after ``metrics.transient_s``, the RMS of the
  filter's own sigma, the mean NEES per angle, and the number of runs;
* ``noise_free.csv`` (``RMS_SUMMARY_COLUMNS``, n_runs = 1): the same for one run with
  noise-free sensors and an exact start (the filters still assume the scenario's noise):
  what each filter's model and update do on perfect data;
* ``run_rms.csv`` (``RUN_RMS_COLUMNS``): per run and filter the RMS over time after the
  transient (for paired comparisons between filters);
* ``window_summary.csv`` (``WINDOW_SUMMARY_COLUMNS``) and ``window_run_rms.csv``
  (``WINDOW_RUN_RMS_COLUMNS``): the same statistics over each averaging window, the flight
  after the transient and the window after the first bank
  (:mod:`pipeline.altimeter_attitude.windows`);
* ``timeseries.csv`` (``TIMESERIES_COLUMNS``): the RMS-over-runs curves of Figs 7-12 at
  ``metrics.output_rate_hz``;
* ``truth.csv`` (``TRUTH_COLUMNS``): the nominal trajectory (Figs 2, 4, 6) and the sensor
  outputs of run 0 (Figs 3, 5);
* ``numerical_trouble.csv`` (:data:`pipeline.trouble.TROUBLE_COLUMNS`): per run kind
  (``monte_carlo``, ``noise_free``) and filter, the runs with a non-finite estimate, a diverged
  error or a non-positive sigma (:mod:`pipeline.altimeter_attitude.trouble`);
* ``provenance.json``: code version, config hash, seeds, package versions, filter settings.

Filters (all fed the same noise, vectorised over runs): ``linear_kf`` (eqs. 26-33),
``linear_kf_no_gamma``, ``gyro_only``, ``ukf``, ``ekf``, ``complementary``, ``accel_leveling``.

Usage::

    python -m pipeline.altimeter_attitude.run --scenario config/scenarios/altimeter_attitude/paper.yaml \
        --out-dir results/altimeter_attitude/paper [--runs 20]
"""

from __future__ import annotations

import argparse
import hashlib
import sys
from collections.abc import Callable, Iterator
from pathlib import Path

import numpy as np
import pandas as pd

from pipeline.altimeter_attitude import complementary, euler_filters, linear_kf, metrics, windows
from pipeline.altimeter_attitude.chunk_plan import BATCH_RUNS
from pipeline.altimeter_attitude.columns import (
    ALTIMETER_FILTERS,
    RMS_SUMMARY_COLUMNS,
    RUN_RMS_COLUMNS,
    TIMESERIES_COLUMNS,
    TRUTH_COLUMNS,
    WINDOW_RUN_RMS_COLUMNS,
    WINDOW_SUMMARY_COLUMNS,
)
from pipeline.altimeter_attitude.estimates import Estimates
from pipeline.altimeter_attitude.mc_sums import BLOCK_RUNS, BlockSums, MonteCarloSums
from pipeline.altimeter_attitude.scenario import ROOT, Scenario, load_scenario
from pipeline.altimeter_attitude.sensors import Inputs, concat_inputs, simulate_inputs
from pipeline.altimeter_attitude.trajectory import load_factor
from pipeline.altimeter_attitude.trouble import trouble_frame
from pipeline.atomic import write_csv, write_json
from pipeline.trouble import TROUBLE_COLUMNS

__all__ = [
    "iter_filters",
    "run_filters",
    "simulate",
    "simulate_sums",
    "new_sums",
    "block_filter_sums",
    "add_noise_free",
    "truth_frame",
    "run_scenario",
    "write_results",
    "main",
]

GENERATED = ROOT / "pipeline" / "generated" / "altimeter_attitude.py"
RAD2DEG = 180.0 / np.pi


def iter_filters(
    sc: Scenario, inputs: Inputs, filters: tuple[str, ...] = ALTIMETER_FILTERS, log=print
) -> Iterator[Estimates]:
    """Run the named filters on the same inputs, yielding each one's estimates as it is done
    (the linear-KF variants share one pass); the caller may drop each before the next."""
    unknown = sorted(set(filters) - set(ALTIMETER_FILTERS))
    if unknown:
        raise ValueError(f"filters {unknown} unknown; allowed: {list(ALTIMETER_FILTERS)}")
    lkf = tuple(f for f in filters if f in linear_kf.VARIANTS)
    jobs: list[tuple[str, Callable[[], list[Estimates]]]] = []
    if lkf:
        jobs.append(
            (
                "+".join(lkf),
                lambda: linear_kf.run_linear_kf(inputs, sc.k, sc.input_matrix, lkf, sc.p0_radial),
            )
        )
    if "ukf" in filters:
        jobs.append(
            (
                "ukf",
                lambda: [euler_filters.run_ukf(inputs, sc.ukf_alpha, sc.ukf_beta, sc.ukf_kappa)],
            )
        )
    if "ekf" in filters:
        jobs.append(("ekf", lambda: [euler_filters.run_ekf(inputs)]))
    if "complementary" in filters:
        jobs.append(
            ("complementary", lambda: [complementary.run_complementary(inputs, sc.omega_c, sc.xi)])
        )
    if "accel_leveling" in filters:
        jobs.append(("accel_leveling", lambda: [complementary.run_accel_leveling(inputs)]))
    for label, job in jobs:
        done = job()
        log(f"{sc.name}: {label}: {inputs.n_runs} runs x {inputs.n_steps} steps done")
        yield from done
        del done


def run_filters(
    sc: Scenario, inputs: Inputs, filters: tuple[str, ...] = ALTIMETER_FILTERS, log=print
) -> dict[str, Estimates]:
    """Run the named filters on the same inputs; returns their estimates by name."""
    out = {est.filter: est for est in iter_filters(sc, inputs, filters, log)}
    return {f: out[f] for f in filters}


def _split(est: Estimates, sl: slice) -> Estimates:
    return Estimates(
        est.filter,
        est.roll[sl],
        est.pitch[sl],
        est.roll_sigma[sl],
        est.pitch_sigma[sl],
        est.c[sl],
        est.norm_error[sl],
    )


def simulate(
    sc: Scenario, n_runs: int | None = None, filters: tuple[str, ...] = ALTIMETER_FILTERS, log=print
) -> tuple[Inputs, dict[str, Estimates], dict[str, Estimates]]:
    """Monte Carlo of ``n_runs`` runs (default: the scenario's) through every filter, plus one
    noise-free run with an exact start (sensor noise and initial errors scaled to zero; the
    filters still assume the scenario's noise). That run is stacked onto the Monte Carlo
    batch, so it costs almost nothing. Returns (inputs, estimates, noise-free estimates)."""
    n = n_runs or sc.n_runs
    inputs = simulate_inputs(sc.profiles, sc.sensors, sc.initial, n, sc.seed, sc.name)
    clean = simulate_inputs(sc.profiles, sc.sensors, sc.initial, 1, sc.seed, sc.name, 0.0)
    both = run_filters(sc, concat_inputs([inputs, clean]), filters, log)
    mc = {k: _split(e, slice(0, n)) for k, e in both.items()}
    nf = {k: _split(e, slice(n, n + 1)) for k, e in both.items()}
    return inputs, mc, nf


def new_sums(
    sc: Scenario, filters: tuple[str, ...] = ALTIMETER_FILTERS
) -> tuple[Inputs, MonteCarloSums, MonteCarloSums]:
    """The noise-free run's inputs and the empty Monte Carlo and noise-free sums of ``sc``."""
    first = int(round(sc.transient * sc.sensors.rate_hz))
    wins = windows.scenario_windows(sc)
    clean = simulate_inputs(sc.profiles, sc.sensors, sc.initial, 1, sc.seed, sc.name, 0.0)
    mc = MonteCarloSums(clean.truth, first, wins, "monte_carlo", filters)
    nf = MonteCarloSums(clean.truth, first, wins, "noise_free", filters)
    return clean, mc, nf


def block_filter_sums(
    sc: Scenario,
    mc: MonteCarloSums,
    start: int,
    stop: int,
    filters: tuple[str, ...] = ALTIMETER_FILTERS,
    batch: int = BATCH_RUNS,
) -> tuple[Inputs, list[BlockSums]]:
    """The sums of the block of runs ``start``..``stop - 1``, one :class:`BlockSums` per filter
    (in :func:`iter_filters`' order), the filters run ``batch`` runs at a time: a batch's
    histories are all that is held. Each filter's sums are continued batch after batch in run
    order (:func:`~pipeline.altimeter_attitude.mc_sums.block_sums`), the same additions as over
    the whole block at once. Returns (the first batch's inputs, the sums)."""
    if batch < 1:
        raise ValueError(f"batch = {batch}: must be >= 1")
    sums: dict[str, BlockSums] = {}
    first_inputs: Inputs | None = None
    for first in range(start, stop, batch):
        part = simulate_inputs(
            sc.profiles, sc.sensors, sc.initial, min(batch, stop - first), sc.seed, sc.name,
            first_run=first,
        )  # fmt: skip
        for est in iter_filters(sc, part, filters, lambda message: None):
            sums[est.filter] = mc.block_sums(est, into=sums.get(est.filter))
            del est
        first_inputs = first_inputs or part
        del part
    assert first_inputs is not None, f"runs {start}-{stop - 1}: an empty block"
    return first_inputs, list(sums.values())


def simulate_sums(
    sc: Scenario,
    n_runs: int | None = None,
    filters: tuple[str, ...] = ALTIMETER_FILTERS,
    log=print,
    block: int = BLOCK_RUNS,
    batch: int = BATCH_RUNS,
) -> tuple[Inputs, MonteCarloSums, MonteCarloSums]:
    """The Monte Carlo of :func:`simulate` in blocks of ``block`` runs, each run through the
    filters in batches of ``batch`` runs whose estimates are folded into the block's sums as
    soon as they are made, so memory is bounded by one batch whatever ``n_runs``; then the
    noise-free run alone (the compiled filters treat each run alone; the linear KF's series
    length follows a batch's largest rotation, a 1e-17 effect). Returns (the first batch's
    inputs, for truth.csv; the Monte Carlo sums; the noise-free sums)."""
    if block < 1:
        raise ValueError(f"block = {block}: must be >= 1")
    n = n_runs or sc.n_runs
    clean, mc, nf = new_sums(sc, filters)
    first_inputs: Inputs | None = None
    for start in range(0, n, block):
        stop = min(n, start + block)
        part, sums = block_filter_sums(sc, mc, start, stop, filters, batch)
        for s in sums:
            mc.fold(s)
        first_inputs = first_inputs or part
        log(f"{sc.name}: runs {start}-{stop - 1} of {n}: {', '.join(s.filter for s in sums)} done")
        del part, sums
    add_noise_free(sc, clean, nf, filters)
    assert first_inputs is not None
    return first_inputs, mc, nf


def add_noise_free(
    sc: Scenario, clean: Inputs, nf: MonteCarloSums, filters: tuple[str, ...] = ALTIMETER_FILTERS
) -> None:
    """The noise-free run through every filter, folded into ``nf``."""
    for est in iter_filters(sc, clean, filters, lambda m: None):
        nf.add(est)


def truth_frame(inputs: Inputs) -> pd.DataFrame:
    """truth.csv: the trajectory at the state times, and run 0's sensor outputs."""
    tr = inputs.truth
    pad = np.full((1, 3), np.nan)  # IMU sample k belongs to [t_k, t_k+1]: none at t_end
    gyro = np.concatenate([inputs.gyro[0], pad]) * RAD2DEG
    accel = np.concatenate([inputs.accel[0], pad])
    frame = pd.DataFrame(
        {
            "t_s": tr.t,
            "c31": tr.c[:, 0],
            "c32": tr.c[:, 1],
            "c33": tr.c[:, 2],
            "roll_deg": tr.roll * RAD2DEG,
            "pitch_deg": tr.pitch * RAD2DEG,
            "yaw_deg": tr.yaw * RAD2DEG,
            "v_d_m_s": tr.v_d,
            "h_m": tr.h,
            "load_factor": load_factor(tr),
            "gyro_x_deg_s": gyro[:, 0],
            "gyro_y_deg_s": gyro[:, 1],
            "gyro_z_deg_s": gyro[:, 2],
            "accel_x_m_s2": accel[:, 0],
            "accel_y_m_s2": accel[:, 1],
            "accel_z_m_s2": accel[:, 2],
            "altimeter_m": inputs.altimeter[0],
        }
    )
    return frame[TRUTH_COLUMNS]


def summary_frame(sc: Scenario, inputs: Inputs, estimates: dict[str, Estimates]) -> pd.DataFrame:
    first = int(round(sc.transient * sc.sensors.rate_hz))
    rows = [metrics.summary_row(est, inputs.truth, first) for est in estimates.values()]
    return pd.DataFrame(rows, columns=RMS_SUMMARY_COLUMNS)


def _sha256_file(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest() if path.is_file() else "missing"


def _relative(path: Path) -> str:
    try:
        return str(path.resolve().relative_to(ROOT))
    except ValueError:
        return str(path)


def run_scenario(
    scenario: Scenario | str | Path,
    out_dir: str | Path,
    n_runs: int | None = None,
    log=print,
    block: int = BLOCK_RUNS,
) -> dict[str, Path]:
    """Run a scenario (validated first) in one process and write its results atomically into
    ``out_dir`` (the workflow's chunked form, :mod:`pipeline.altimeter_attitude.chunks`,
    writes the same bytes)."""
    sc = scenario if isinstance(scenario, Scenario) else load_scenario(scenario)
    inputs, mc, nf = simulate_sums(sc, n_runs, log=log, block=block)
    return write_results(sc, out_dir, inputs, mc, nf)


def write_results(
    sc: Scenario, out_dir: str | Path, inputs: Inputs, mc: MonteCarloSums, nf: MonteCarloSums
) -> dict[str, Path]:
    """The results files of a scenario from its sums (``inputs``: the first block's)."""
    from pipeline.provenance import provenance

    out_dir = Path(out_dir)
    written = {
        "rms_summary": write_csv(
            out_dir / "rms_summary.csv", mc.summary_frame(), RMS_SUMMARY_COLUMNS
        ),
        "noise_free": write_csv(
            out_dir / "noise_free.csv", nf.summary_frame(), RMS_SUMMARY_COLUMNS
        ),
        "run_rms": write_csv(out_dir / "run_rms.csv", mc.run_rms_frame(), RUN_RMS_COLUMNS),
        "window_summary": write_csv(
            out_dir / "window_summary.csv", mc.window_summary_frame(), WINDOW_SUMMARY_COLUMNS
        ),
        "window_run_rms": write_csv(
            out_dir / "window_run_rms.csv", mc.window_run_frame(), WINDOW_RUN_RMS_COLUMNS
        ),
        "timeseries": write_csv(
            out_dir / "timeseries.csv", mc.timeseries_frame(sc.output_every), TIMESERIES_COLUMNS
        ),
        "truth": write_csv(out_dir / "truth.csv", truth_frame(inputs), TRUTH_COLUMNS),
        "numerical_trouble": write_csv(
            out_dir / "numerical_trouble.csv",
            trouble_frame(mc.trouble_rows() + nf.trouble_rows()),
            TROUBLE_COLUMNS,
        ),
    }
    estimates = mc.filters
    n_total = next(iter(mc.filters.values())).n_runs
    prov = provenance(
        scenario=sc.name,
        scenario_file=_relative(sc.path),
        config_sha256=sc.config_sha256,
        generated_module=_relative(GENERATED),
        generated_sha256=_sha256_file(GENERATED),
        seeds={"seed": sc.seed, "n_runs": n_total},
        seed_scheme="run i: numpy default_rng(SeedSequence([seed, sha256(scenario name)[:8], i]))",
        steps={"imu_rate_hz": sc.sensors.rate_hz, "n_steps": inputs.n_steps},
        filters=list(estimates),
    )
    written["provenance"] = write_json(out_dir / "provenance.json", prov)
    return written


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--scenario", type=Path, required=True, help="scenario YAML file")
    parser.add_argument("--out-dir", type=Path, required=True, help="results directory")
    parser.add_argument(
        "--runs", type=int, default=None, help="Monte Carlo runs (default: scenario)"
    )
    args = parser.parse_args(argv)
    if args.runs is not None and args.runs < 2:
        parser.error(f"--runs = {args.runs}: must be an integer >= 2")
    try:
        sc = load_scenario(args.scenario)
    except (ValueError, OSError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2

    def log(message: str) -> None:
        print(message, file=sys.stderr, flush=True)

    from pipeline.altimeter_attitude.heap import keep_freed_memory

    keep_freed_memory()  # as the workflow's step does
    run_scenario(sc, args.out_dir, args.runs, log=log)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
