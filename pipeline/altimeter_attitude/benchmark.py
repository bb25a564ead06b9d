"""Benchmark: the 100-run Monte Carlo of every filter, and filterpy's UKF on the same data.

``python -m pipeline.altimeter_attitude.benchmark [--scenario ...] [--runs 100] [--filterpy-runs 2]``
(or ``make bench``). In one process it times each filter of :mod:`run` over the scenario's
runs, then filterpy's ``UnscentedKalmanFilter`` (same model, sigma points, noise and data) over
the first ``--filterpy-runs`` runs, one run at a time as filterpy works, and prints the
throughput in run-steps per second and the ratio ours / filterpy for the UKF. It also prints
the largest difference between the two UKFs' roll/pitch on the runs both did (they implement
the same algorithm). filterpy is a test/benchmark dependency only.
"""

from __future__ import annotations

import argparse
import time
from pathlib import Path

import numpy as np

from pipeline.altimeter_attitude import euler_filters, run
from pipeline.altimeter_attitude.scenario import load_scenario
from pipeline.altimeter_attitude.sensors import simulate_inputs

__all__ = ["filterpy_ukf", "main"]


def filterpy_ukf(inputs, run_index: int, alpha: float, beta: float, kappa: float) -> np.ndarray:
    """filterpy's UKF on run ``run_index``: the (T + 1, 4) state history."""
    from filterpy.kalman import MerweScaledSigmaPoints, UnscentedKalmanFilter

    dt, g, sens = inputs.dt, inputs.g, inputs.sensors

    def fx(x, dt_, gyro, accel):
        return euler_filters.rk4_step(x, dt_, gyro, accel, g)

    points = MerweScaledSigmaPoints(4, alpha=alpha, beta=beta, kappa=kappa)
    ukf = UnscentedKalmanFilter(4, 1, dt, hx=lambda x: x[3:4], fx=fx, points=points)
    ukf.x = inputs.x0_euler[run_index].copy()
    ukf.P = np.diag(inputs.sigma0[run_index] ** 2)
    ukf.R = np.array([[sens.altimeter_sigma**2]])
    out = np.empty((inputs.n_steps + 1, 4))
    out[0] = ukf.x
    for k in range(inputs.n_steps):
        ukf.Q = euler_filters.process_noise(ukf.x[None], dt, sens.gyro_sigma, sens.accel_sigma)[0]
        ukf.predict(gyro=inputs.gyro[run_index, k], accel=inputs.accel[run_index, k])
        z = inputs.altimeter[run_index, k + 1]
        if not np.isnan(z):
            ukf.update(np.array([z]))
        out[k + 1] = ukf.x
    return out


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument(
        "--scenario", type=Path, default=Path("config/scenarios/altimeter_attitude/paper.yaml")
    )
    parser.add_argument("--runs", type=int, default=100)
    parser.add_argument("--filterpy-runs", type=int, default=2)
    args = parser.parse_args(argv)
    if args.runs < 1 or not 1 <= args.filterpy_runs <= args.runs:
        parser.error("need --runs >= 1 and 1 <= --filterpy-runs <= --runs")
    sc = load_scenario(args.scenario)
    inputs = simulate_inputs(sc.profiles, sc.sensors, sc.initial, args.runs, sc.seed, sc.name)
    steps = inputs.n_steps
    print(f"scenario {sc.name}: {args.runs} runs x {steps} steps ({sc.sensors.rate_hz:g} Hz)")
    rate = {}
    estimates = {}
    for name in ("linear_kf", "linear_kf_no_gamma", "gyro_only", "ukf", "ekf", "complementary"):
        start = time.perf_counter()
        estimates[name] = run.run_filters(sc, inputs, (name,), log=lambda m: None)[name]
        seconds = time.perf_counter() - start
        rate[name] = args.runs * steps / seconds
        print(f"  {name:20s} {seconds:7.2f} s  {rate[name]:12.0f} run-steps/s")
    n = args.filterpy_runs
    start = time.perf_counter()
    ref = [filterpy_ukf(inputs, i, sc.ukf_alpha, sc.ukf_beta, sc.ukf_kappa) for i in range(n)]
    seconds = time.perf_counter() - start
    fp_rate = n * steps / seconds
    print(f"  {'filterpy UKF':20s} {seconds:7.2f} s  {fp_rate:12.0f} run-steps/s ({n} runs)")
    ours = estimates["ukf"]
    diff = max(
        max(
            np.abs(ours.roll[i] - ref[i][:, 0]).max(),
            np.abs(ours.pitch[i] - ref[i][:, 1]).max(),
        )
        for i in range(n)
    )
    print(f"UKF throughput ratio, ours / filterpy: {rate['ukf'] / fp_rate:.1f}")
    print(f"largest roll/pitch difference, ours vs filterpy on {n} runs: {diff:.2e} rad")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
