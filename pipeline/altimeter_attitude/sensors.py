"""Sensor outputs and initial estimates of the Monte Carlo runs (common random numbers).

Time grid: states at ``t_k = k dt`` (k = 0..T); IMU sample k is held over [t_k, t_k+1]
and taken at the interval midpoint ``t_k + dt/2`` (to O(dt^2) the interval average a real
IMU delivers as increments); the altimeter reads h(t_k) at k = every, 2 every, ...

Noise (Sec. 6): white, zero-mean Gaussian, no bias, per sample: gyros sigma_g, accelerometers
sigma_a, altimeter sigma_h. Sensor model omega_tilde = omega_nb^b + n_w, f_tilde = f^b + n_a.

Run ``i`` of scenario ``name`` draws from ``default_rng(SeedSequence([seed, key(name), i]))``,
so results are reproducible bit for bit, a run's noise does not depend on how many runs are
made, and every filter sees the same realisations.
"""

from __future__ import annotations

import functools
import hashlib
from dataclasses import dataclass, fields

import numpy as np

from pipeline.altimeter_attitude.profiles import Profiles
from pipeline.altimeter_attitude.trajectory import Truth, truth

__all__ = [
    "SensorSpec",
    "InitialSpec",
    "Inputs",
    "scenario_key",
    "simulate_inputs",
    "concat_inputs",
]


@dataclass(frozen=True)
class SensorSpec:
    gyro_sigma: float  # rad/s per sample
    accel_sigma: float  # m/s^2 per sample
    altimeter_sigma: float  # m
    rate_hz: float  # IMU rate
    altimeter_every: int  # altimeter update every n IMU steps


@dataclass(frozen=True)
class InitialSpec:
    roll_sigma: float  # rad
    pitch_sigma: float  # rad
    v_d_sigma: float  # m/s
    h_sigma: float  # m


@dataclass(frozen=True)
class Inputs:
    """Everything the filters see, plus the truth at the state times."""

    dt: float
    g: float
    gyro: np.ndarray  # (N, T, 3) rad/s
    accel: np.ndarray  # (N, T, 3) m/s^2
    altimeter: np.ndarray  # (N, T + 1) m; NaN where no altimeter sample
    x0_euler: np.ndarray  # (N, 4) initial estimate [phi, theta, V_d, h]
    sigma0: np.ndarray  # (N, 4) its sigmas [phi, theta, V_d, h] (rad, rad, m/s, m)
    sensors: SensorSpec
    initial: InitialSpec
    truth: Truth | None  # at the state times t_k (T + 1); None for a flight log

    @property
    def n_runs(self) -> int:
        return self.gyro.shape[0]

    @property
    def n_steps(self) -> int:
        return self.gyro.shape[1]


def scenario_key(name: str) -> int:
    """A stable 32-bit integer from the scenario name (part of every run's seed)."""
    return int(hashlib.sha256(name.encode()).hexdigest()[:8], 16)


@functools.lru_cache(maxsize=4)
def _truths(profiles: Profiles, n_steps: int, dt: float) -> tuple[Truth, Truth]:
    """The truth at the state times t_k = k dt (k = 0..n_steps) and at the IMU samples'
    midpoints, computed once per trajectory and rate: a Monte Carlo run in batches
    (run.BATCH_RUNS runs) asks for the same trajectory in every batch (~43 ms each). Every
    batch shares these arrays, so they are read-only."""
    t_state = np.arange(n_steps + 1) * dt
    out = truth(profiles, t_state), truth(profiles, t_state[:-1] + dt / 2)
    for tr in out:
        for f in fields(tr):
            value = getattr(tr, f.name)
            if isinstance(value, np.ndarray):
                value.setflags(write=False)
    return out


def simulate_inputs(
    profiles: Profiles,
    sensors: SensorSpec,
    initial: InitialSpec,
    n_runs: int,
    seed: int,
    name: str,
    noise_scale: float = 1.0,
    first_run: int = 0,
) -> Inputs:
    """Truth, sensor outputs and initial estimates of runs ``first_run .. first_run +
    n_runs - 1`` (a block of a larger Monte Carlo: run i's draws depend on i alone).

    ``noise_scale=0`` gives noise-free sensors and exact initial estimates (tests use it).
    """
    if first_run < 0:
        raise ValueError(f"first_run = {first_run}: must be >= 0")
    dt = 1.0 / sensors.rate_hz
    n_steps = int(round(profiles.duration * sensors.rate_hz))
    tr_state, tr_mid = _truths(profiles, n_steps, dt)
    gyro = np.empty((n_runs, n_steps, 3))
    accel = np.empty((n_runs, n_steps, 3))
    alt = np.full((n_runs, n_steps + 1), np.nan)
    x0 = np.empty((n_runs, 4))
    every = sensors.altimeter_every
    has_alt = (np.arange(n_steps + 1) % every == 0) & (np.arange(n_steps + 1) > 0)
    key = scenario_key(name)
    for i in range(n_runs):
        rng = np.random.default_rng(np.random.SeedSequence([seed, key, first_run + i]))
        gyro[i] = tr_mid.rate_b + noise_scale * sensors.gyro_sigma * rng.standard_normal(
            (n_steps, 3)
        )
        accel[i] = tr_mid.force_b + noise_scale * sensors.accel_sigma * rng.standard_normal(
            (n_steps, 3)
        )
        alt[i, has_alt] = tr_state.h[has_alt] + noise_scale * sensors.altimeter_sigma * (
            rng.standard_normal(int(has_alt.sum()))
        )
        err = rng.standard_normal(4) * noise_scale
        x0[i] = [
            tr_state.roll[0] + initial.roll_sigma * err[0],
            tr_state.pitch[0] + initial.pitch_sigma * err[1],
            tr_state.v_d[0] + initial.v_d_sigma * err[2],
            tr_state.h[0] + initial.h_sigma * err[3],
        ]
    sigma0 = np.broadcast_to(
        [initial.roll_sigma, initial.pitch_sigma, initial.v_d_sigma, initial.h_sigma], (n_runs, 4)
    ).copy()
    return Inputs(dt, profiles.gravity, gyro, accel, alt, x0, sigma0, sensors, initial, tr_state)


def concat_inputs(parts: list[Inputs]) -> Inputs:
    """Stack the runs of several Inputs with the same dt, g, sensors and length (the UKF
    tuning stacks the noise-free run onto its Monte Carlo).

    The filters only see sensor outputs and initial estimates, so runs of different
    trajectories or initial sigmas can share one vectorised pass; ``truth`` is the first
    part's, so errors must be computed per part by the caller.
    """
    first = parts[0]
    for p in parts[1:]:
        if (p.dt, p.g, p.n_steps, p.sensors) != (first.dt, first.g, first.n_steps, first.sensors):
            raise ValueError("concat_inputs: parts differ in dt, g, length or sensors")
    return Inputs(
        first.dt,
        first.g,
        np.concatenate([p.gyro for p in parts]),
        np.concatenate([p.accel for p in parts]),
        np.concatenate([p.altimeter for p in parts]),
        np.concatenate([p.x0_euler for p in parts]),
        np.concatenate([p.sigma0 for p in parts]),
        first.sensors,
        first.initial,
        first.truth,
    )
