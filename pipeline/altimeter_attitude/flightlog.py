"""Run the paper's filters on your own flight log.

``inertial-repro flight-log LOG.csv --out attitude.csv [--filters linear_kf,ukf]``

Frames and units: navigation frame N is NED (z down; gravity g^n = (0, 0, 9.80665) m/s^2); body
frame b has x forward, y right, z down; roll phi and pitch theta are those of the 3-2-1
(yaw psi, pitch theta, roll phi) Euler sequence from N to b (pitch positive nose up, roll
positive right wing down; yaw is not estimated). SI units, angles in deg at the edges.

Input CSV (one row per IMU sample, header required, comma separated)::

    t_s            sample time, s, strictly increasing, uniformly spaced (the IMU rate is
                   inferred from the median step and checked: every step within 1 %)
    gyro_x_rad_s   gyro outputs omega_nb^b after Earth-rate compensation (body x forward,
    gyro_y_rad_s   y right, z down), rad/s -- or gyro_x_deg_s, ... in deg/s
    gyro_z_rad_s
    accel_x_m_s2   accelerometer outputs (specific force), m/s^2
    accel_y_m_s2
    accel_z_m_s2
    altimeter_m    barometric altitude (up), m; empty where there is no sample. The
                   altimeter must sample every n-th IMU row (n inferred and checked)

At rest and level the accelerometers read specific force f^b = (0, 0, -g); nose up by
theta, accel_x_m_s2 reads about +g sin(theta). Example (100 Hz IMU, altimeter at 10 Hz)::

    t_s,gyro_x_rad_s,gyro_y_rad_s,gyro_z_rad_s,accel_x_m_s2,accel_y_m_s2,accel_z_m_s2,altimeter_m
    0.00,0.001,-0.002,0.0,0.17,-0.09,-9.80,1000.2
    0.01,0.001,-0.002,0.0,0.17,-0.08,-9.81,

Row k's IMU sample is held over [t_k, t_k+1] (the last row has no interval and is not used
for propagation); an altimeter value in row k is a measurement at t_k. The filters start
at t_0 from accelerometer levelling (eq. 17-b) averaged over ``--level-s`` seconds (the log
should start in unaccelerated flight or at rest) unless ``--roll0-deg/--pitch0-deg`` are
given; V_d starts at 0 and h at the first altimeter value.

Output CSV (``FLIGHTLOG_OUTPUT_COLUMNS``): t_s, filter, roll_deg, pitch_deg, roll_sigma_deg,
pitch_sigma_deg for every state time t_k of every filter asked for (sigma empty for the
complementary filter).
"""

from __future__ import annotations

import argparse
import math
import sys
from pathlib import Path

import numpy as np
import pandas as pd

from pipeline.altimeter_attitude import complementary, euler_filters, linear_kf
from pipeline.altimeter_attitude.columns import FLIGHTLOG_OUTPUT_COLUMNS
from pipeline.altimeter_attitude.estimates import Estimates
from pipeline.altimeter_attitude.sensors import InitialSpec, Inputs, SensorSpec
from pipeline.atomic import write_csv
from pipeline.generated import altimeter_attitude as gen

__all__ = ["FlightLogError", "read_log", "run_log", "main", "FILTERS"]

FILTERS = ("linear_kf", "ukf", "complementary", "gyro_only")
DEG = math.pi / 180.0
STEP_TOLERANCE = 0.01


class FlightLogError(ValueError):
    """A malformed flight log: the message names the file, the column/row and what is allowed."""


def _gyro_columns(frame: pd.DataFrame, path: Path) -> tuple[list[str], float]:
    rad = [f"gyro_{a}_rad_s" for a in "xyz"]
    deg = [f"gyro_{a}_deg_s" for a in "xyz"]
    if all(c in frame for c in rad):
        return rad, 1.0
    if all(c in frame for c in deg):
        return deg, DEG
    raise FlightLogError(
        f"{path}: gyro columns missing: need {rad} (rad/s) or {deg} (deg/s); found {list(frame)}"
    )


def _cell(value: object) -> str:
    """A CSV cell as the user wrote it: an empty cell is named as such, not as ``nan``."""
    if value is None or (isinstance(value, float) and np.isnan(value)):
        return "an empty cell"
    return repr(value.item() if isinstance(value, np.generic) else value)


def read_log(path: str | Path) -> tuple[np.ndarray, np.ndarray, np.ndarray, np.ndarray, float, int]:
    """Parse and check a flight log: (t, gyro rad/s (n, 3), accel (n, 3), altimeter (n,), dt, every)."""
    path = Path(path)
    try:
        frame = pd.read_csv(path)
    except pd.errors.EmptyDataError:
        raise FlightLogError(f"{path}: the file is empty; need a header and IMU rows") from None
    except (OSError, pd.errors.ParserError, UnicodeDecodeError) as exc:
        raise FlightLogError(f"{path}: cannot read as CSV: {exc}") from None
    gyro_cols, scale = _gyro_columns(frame, path)
    needed = ["t_s", *[f"accel_{a}_m_s2" for a in "xyz"], "altimeter_m"]
    missing = [c for c in needed if c not in frame]
    if missing:
        raise FlightLogError(f"{path}: missing columns {missing}; required: {needed} and gyro")
    if len(frame) < 3:
        raise FlightLogError(f"{path}: {len(frame)} rows; need at least 3 IMU samples")
    numeric = {}
    for col in ["t_s", *gyro_cols, *needed[1:4], "altimeter_m"]:
        values = pd.to_numeric(frame[col], errors="coerce").to_numpy(dtype=float)
        bad = np.flatnonzero(~np.isfinite(values) & frame[col].notna().to_numpy())
        if col != "altimeter_m":
            bad = np.flatnonzero(~np.isfinite(values))
        if bad.size:
            raise FlightLogError(
                f"{path}: column {col}, data row {bad[0] + 1}: {_cell(frame[col].iloc[bad[0]])} is not "
                "a finite number"
                + (
                    " (leave altimeter_m empty where there is no sample)"
                    if col == "altimeter_m"
                    else ""
                )
            )
        numeric[col] = values
    t = numeric["t_s"]
    steps = np.diff(t)
    if np.any(steps <= 0):
        row = int(np.flatnonzero(steps <= 0)[0]) + 2
        raise FlightLogError(f"{path}: t_s must increase strictly; data row {row} does not")
    dt = float(np.median(steps))
    off = np.abs(steps - dt) > STEP_TOLERANCE * dt
    if np.any(off):
        row = int(np.flatnonzero(off)[0]) + 2
        raise FlightLogError(
            f"{path}: t_s step before data row {row} is {steps[off][0]:.6g} s; the IMU rate is "
            f"inferred as {1 / dt:.6g} Hz and every step must be within {STEP_TOLERANCE:.0%} of "
            f"{dt:.6g} s"
        )
    alt = numeric["altimeter_m"]
    rows = np.flatnonzero(np.isfinite(alt))
    if rows.size < 2:
        raise FlightLogError(f"{path}: altimeter_m has {rows.size} samples; need at least 2")
    gaps = np.diff(rows)
    every = int(gaps[0])
    if np.any(gaps != every):
        row = int(rows[1:][gaps != every][0]) + 1
        raise FlightLogError(
            f"{path}: altimeter_m must sample every n-th IMU row; inferred n = {every} from the "
            f"first two samples, but data row {row} breaks it"
        )
    gyro = np.stack([numeric[c] for c in gyro_cols], -1) * scale
    accel = np.stack([numeric[f"accel_{a}_m_s2"] for a in "xyz"], -1)
    return t, gyro, accel, alt, dt, every


def run_log(
    path: str | Path,
    filters: tuple[str, ...] = FILTERS,
    gyro_sigma_deg_s: float = 0.5,
    accel_sigma: float = 0.1,
    altimeter_sigma: float = 2.0,
    k: float = 1.0,
    roll0_deg: float | None = None,
    pitch0_deg: float | None = None,
    init_sigma_deg: float = 2.0,
    level_s: float = 1.0,
    gravity: float = 9.80665,
    ukf_params: tuple[float, float, float] = (0.5, 2.0, 0.0),
    omega_c: float = 0.05,
) -> pd.DataFrame:
    """Filter a flight log; returns the FLIGHTLOG_OUTPUT_COLUMNS frame."""
    unknown = sorted(set(filters) - set(FILTERS))
    if unknown:
        raise FlightLogError(f"filters {unknown} unknown; allowed: {list(FILTERS)}")
    t, gyro, accel, alt, dt, every = read_log(path)
    n_level = max(1, min(len(t) - 1, int(round(level_s / dt))))
    f_mean = accel[:n_level].mean(axis=0)
    c_a = np.array(gen.accel_third_row(*f_mean), dtype=float)
    phi_a, theta_a = (float(v) for v in gen.euler_from_third_row(*c_a))
    phi0 = phi_a if roll0_deg is None else roll0_deg * DEG
    theta0 = theta_a if pitch0_deg is None else pitch0_deg * DEG
    first_alt = float(alt[np.isfinite(alt)][0])
    altimeter = alt.copy()
    altimeter[0] = np.nan  # the state at t_0 is initialised from it, not updated with it
    sensors = SensorSpec(gyro_sigma_deg_s * DEG, accel_sigma, altimeter_sigma, 1 / dt, every)
    initial = InitialSpec(init_sigma_deg * DEG, init_sigma_deg * DEG, 1.0, altimeter_sigma)
    inputs = Inputs(
        dt=dt,
        g=gravity,
        gyro=gyro[None, :-1],
        accel=accel[None, :-1],
        altimeter=altimeter[None, :],
        x0_euler=np.array([[phi0, theta0, 0.0, first_alt]]),
        sigma0=np.array([[initial.roll_sigma, initial.pitch_sigma, 1.0, altimeter_sigma]]),
        sensors=sensors,
        initial=initial,
        truth=None,
    )
    ests: list[Estimates] = []
    lkf = tuple(f for f in filters if f in linear_kf.VARIANTS)
    if lkf:
        ests += linear_kf.run_linear_kf(inputs, k, "exact", lkf)
    if "ukf" in filters:
        ests.append(euler_filters.run_ukf(inputs, *ukf_params))
    if "complementary" in filters:
        ests.append(complementary.run_complementary(inputs, omega_c, 1 / math.sqrt(2)))
    frames = [
        pd.DataFrame(
            {
                "t_s": t,
                "filter": e.filter,
                "roll_deg": e.roll[0] / DEG,
                "pitch_deg": e.pitch[0] / DEG,
                "roll_sigma_deg": e.roll_sigma[0] / DEG,
                "pitch_sigma_deg": e.pitch_sigma[0] / DEG,
            }
        )
        for e in sorted(ests, key=lambda e: filters.index(e.filter))
    ]
    return pd.concat(frames, ignore_index=True)[FLIGHTLOG_OUTPUT_COLUMNS]


def _positive(name: str):
    def parse(text: str) -> float:
        try:
            value = float(text)
        except ValueError:
            raise argparse.ArgumentTypeError(f"{name} = {text!r}: must be a number") from None
        if not (value > 0 and math.isfinite(value)):
            raise argparse.ArgumentTypeError(f"{name} = {text!r}: must be a finite number > 0")
        return value

    return parse


def main(argv: list[str] | None = None, prog: str | None = None) -> int:
    parser = argparse.ArgumentParser(
        prog=prog or "python -m pipeline.altimeter_attitude.flightlog",
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    parser.add_argument("log", type=Path, help="flight-log CSV (format above)")
    parser.add_argument("--out", type=Path, required=True, help="attitude CSV to write")
    parser.add_argument(
        "--filters",
        default=",".join(FILTERS),
        help=f"comma-separated subset of {','.join(FILTERS)}",
    )
    parser.add_argument("--gyro-sigma-deg-s", type=_positive("--gyro-sigma-deg-s"), default=0.5)
    parser.add_argument("--accel-sigma-m-s2", type=_positive("--accel-sigma-m-s2"), default=0.1)
    parser.add_argument("--altimeter-sigma-m", type=_positive("--altimeter-sigma-m"), default=2.0)
    parser.add_argument("--k-per-s", type=_positive("--k-per-s"), default=1.0, help="eq. 14 gain")
    parser.add_argument("--roll0-deg", type=float, default=None)
    parser.add_argument("--pitch0-deg", type=float, default=None)
    parser.add_argument("--init-sigma-deg", type=_positive("--init-sigma-deg"), default=2.0)
    parser.add_argument("--level-s", type=_positive("--level-s"), default=1.0)
    args = parser.parse_args(argv)
    filters = tuple(f.strip() for f in args.filters.split(",") if f.strip())
    bad = [f for f in filters if f not in FILTERS]
    if bad or not filters:
        parser.error(f"--filters = {args.filters!r}: allowed values are {', '.join(FILTERS)}")
    for name in ("roll0_deg", "pitch0_deg"):
        v = getattr(args, name)
        if v is not None and not -89.0 <= v <= 89.0:
            parser.error(f"--{name.replace('_', '-')} = {v}: must lie in [-89, 89] deg")
    try:
        frame = run_log(
            args.log,
            filters,
            args.gyro_sigma_deg_s,
            args.accel_sigma_m_s2,
            args.altimeter_sigma_m,
            args.k_per_s,
            args.roll0_deg,
            args.pitch0_deg,
            args.init_sigma_deg,
            args.level_s,
        )
    except FlightLogError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    write_csv(args.out, frame, FLIGHTLOG_OUTPUT_COLUMNS)
    print(f"{args.out}: {len(frame)} rows ({', '.join(filters)})", file=sys.stderr)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
