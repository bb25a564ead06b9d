"""Flight logs with a known truth for the flight-log tests: the project's own truth and sensor
simulation (trajectory.py, sensors.py) written out as CSV files shaped like real logs.

A 120 s flight at 100 Hz with two coordinated turns (banks up to ~34 deg), a pull-up and
push-over and a speed change; altimeter every 5th row (20 Hz). ``g`` sets the truth's
gravity; ``noise_scale=0`` gives noise-free sensors (the errors are then the filter's own
model and discretisation errors plus whatever a wrong option adds).
"""

from __future__ import annotations

import math
from functools import cache
from pathlib import Path

import numpy as np
import pandas as pd

from pipeline.altimeter_attitude import flightlog
from pipeline.altimeter_attitude.scenario import build_scenario, load_scenario
from pipeline.altimeter_attitude.sensors import Inputs, simulate_inputs

RATE_HZ = 100.0
DURATION_S = 120.0
ALT_EVERY = 5
TRANSIENT_S = 20.0  # errors are compared after it (as the scenarios' metrics.transient_s)
MANEUVERS = [
    {"channel": "heading_deg", "start_s": 15.0, "duration_s": 30.0, "amplitude": 60.0},
    {"channel": "flight_path_deg", "start_s": 50.0, "duration_s": 4.0, "amplitude": 15.0},
    {"channel": "flight_path_deg", "start_s": 60.0, "duration_s": 4.0, "amplitude": -15.0},
    {"channel": "heading_deg", "start_s": 70.0, "duration_s": 30.0, "amplitude": -60.0},
    {"channel": "speed_m_s", "start_s": 100.0, "duration_s": 10.0, "amplitude": 20.0},
]


@cache
def simulate(g: float = 9.80665, noise_scale: float = 1.0, seed: int = 7) -> Inputs:
    """One run of the test flight (truth at the state times, IMU interval averages)."""
    base = load_scenario("config/scenarios/altimeter_attitude/paper.yaml")
    raw = {
        **base.raw,
        "trajectory": {
            **base.raw["trajectory"],
            "duration_s": DURATION_S,
            "gravity_m_s2": g,
            "maneuvers": MANEUVERS,
        },
        "sensors": {**base.raw["sensors"], "imu_rate_hz": RATE_HZ, "altimeter_every": ALT_EVERY},
    }
    sc = build_scenario(raw, base.path)
    return simulate_inputs(sc.profiles, sc.sensors, sc.initial, 1, seed, sc.name, noise_scale)


def log_frame(inp: Inputs, stamp: str = "start") -> pd.DataFrame:
    """The run as a log with the project's column names (gyro in rad/s).

    ``start``: row k holds the sample over [t_k, t_k+1] (the last row repeats the one before);
    ``end``: row k holds the sample over [t_k-1, t_k] (the first row repeats the one after).
    """
    frame = pd.DataFrame({"t_s": inp.truth.t})
    for i, a in enumerate("xyz"):
        for name, data in ((f"gyro_{a}_rad_s", inp.gyro), (f"accel_{a}_m_s2", inp.accel)):
            s = data[0, :, i]
            frame[name] = np.r_[s, s[-1]] if stamp == "start" else np.r_[s[0], s]
    alt = inp.altimeter[0].copy()
    alt[0] = inp.truth.h[0] + (alt[ALT_EVERY] - inp.truth.h[ALT_EVERY])  # a noisy first reading
    frame["altimeter_m"] = alt
    return frame


def write(frame: pd.DataFrame, path: Path) -> Path:
    frame.to_csv(path, index=False)
    return path


def errors(out: Path, inp: Inputs, name: str) -> dict[str, float]:
    """RMS (deg) after TRANSIENT_S of the roll/pitch errors against the truth and of the sigmas."""
    res = pd.read_csv(out)
    res = res[res["filter"] == name]
    assert len(res) == len(inp.truth.t)
    np.testing.assert_allclose(res["t_s"].to_numpy(), inp.truth.t, rtol=0, atol=5e-4)  # jitter
    keep = inp.truth.t >= TRANSIENT_S
    out_ = {}
    for angle in ("roll", "pitch"):
        err = res[f"{angle}_deg"].to_numpy() - np.degrees(getattr(inp.truth, angle))
        out_[angle] = math.sqrt(np.mean(err[keep] ** 2))
        out_[f"{angle}_sigma"] = math.sqrt(np.mean(res[f"{angle}_sigma_deg"].to_numpy()[keep] ** 2))
    return out_


def run(log: Path, out: Path, *args: str) -> int:
    return flightlog.main([str(log), "--out", str(out), *args])
