"""Run the paper's filters on your own flight log.

``inertial-repro flight-log LOG.csv --out attitude.csv [options]``

Frames and units: navigation frame N is NED (z down; gravity g^n = (0, 0, g) m/s^2); body
frame b has x forward, y right, z down; roll phi and pitch theta are those of the 3-2-1
(yaw psi, pitch theta, roll phi) Euler sequence from N to b (pitch positive nose up, roll
positive right wing down; yaw is not estimated). SI units, angles in deg at the edges. At rest
and level the accelerometers read specific force f^b = (0, 0, -g); nose up by theta,
accel_x_m_s2 reads about +g sin(theta).

Input CSV (one row per IMU sample, header required, comma separated)::

    t_s            sample time, s, strictly increasing, uniformly spaced (the IMU rate is
                   inferred from the median step; every step within --max-jitter of it)
    gyro_x_rad_s   gyro outputs omega_nb^b after Earth-rate compensation (body x forward,
    gyro_y_rad_s   y right, z down), rad/s -- or gyro_x_deg_s, ... in deg/s
    gyro_z_rad_s
    accel_x_m_s2   accelerometer outputs (specific force), m/s^2
    accel_y_m_s2
    accel_z_m_s2
    altimeter_m    barometric altitude (up), m; empty where there is no sample. The
                   altimeter must sample every n-th IMU row (n inferred and checked); a
                   value held on every row until the next sample: --altimeter-held yes

Other names and units: --columns QUANTITY=COLUMN[:UNIT],... with QUANTITY one of t,
gyro_x, gyro_y, gyro_z, accel_x, accel_y, accel_z, altimeter and UNIT s|ms|us (t),
rad/s|deg/s (gyro), m/s^2|g0 (accel; g0 = 9.80665 m/s^2), m|ft (altimeter); without :UNIT
the unit is read from the name's suffix (alt_m -> m, gx_deg_s -> deg/s), else refused.
Example: --columns t=time:ms,gyro_x=gx:deg/s,gyro_y=gy:deg/s,gyro_z=gz:deg/s,
accel_x=ax:m/s^2,accel_y=ay:m/s^2,accel_z=az:m/s^2,altimeter=alt_m
Or --format FILE, YAML/JSON: {columns: {gyro_x: {column: gx, unit: deg/s}, ...}, stamp: end}.

Time stamps (--stamp): 'start' (default) -- row k's IMU sample is the average over
[t_k, t_k+1] (the last row's sample is not used); 'end' -- it is the average over
[t_k-1, t_k] (the first row's sample is not used). An altimeter value in row k is a
measurement at t_k either way. A one-sample lag adds an error that grows with the manoeuvre rates
(say which convention your logger uses).

Gravity: 9.80665 m/s^2 (standard gravity) unless --gravity VALUE, or --latitude-deg LAT
[--height-m H] for WGS-84 normal gravity (Somigliana, NIMA TR8350.2 eq. 4-1, with its
second-order free-air height term, eq. 4-3; H defaults to the mean altimeter reading).
A wrong g biases the linear filter's roll/pitch, its sigma does not show it.

The filters start at t_0 from accelerometer levelling (eq. 17-b) averaged over --level-s
seconds (the log should start in unaccelerated flight or at rest) unless --roll0-deg and
--pitch0-deg are given; V_d starts at --v-d0-m-s (0) and h at --h0-m (the first altimeter
value). The initial roll/pitch sigma (--init-sigma-deg) defaults, after levelling, to
max(0.5 deg, 3 x the standard error of the levelling mean: s_y / (g sqrt n) for roll,
s_x for pitch), and to 2 deg with a given start. Measured on 120 s, 100 Hz simulated logs
(tests/flightlog_sim.py, 8 noise seeds, levelling error about 0.05 deg): the old fixed 2 deg
gave 1.2-1.4x (linear KF) and 1.7-1.9x (UKF) the roll/pitch RMS after 20 s of a matching
sigma and 2.5x too large sigmas; 0.5 deg is within 4 % of the best RMS for levelling errors
up to 0.5 deg and keeps NEES below 2 for errors up to 2 deg (a smaller sigma reaches 6). Defaults of k and of the UKF's alpha/beta/kappa are those of the paper scenario
(config/scenarios/altimeter_attitude/paper.yaml; the paper gives no values).

What was inferred (rates, duration, largest step deviation, columns and units, gravity,
start; |f| over the levelling window must be 0.8-1.2 g, which catches accelerometer unit
mistakes) is printed to stderr before the filters run. Bad input ends with one 'error:' line
and exit status 2 ('data row' n is the n-th line after the header); a filter failure with
one 'error:' line and status 1.

Output CSV (FLIGHTLOG_OUTPUT_COLUMNS): t_s, filter, roll_deg, pitch_deg, roll_sigma_deg,
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
from pipeline.altimeter_attitude.flightlog_format import (
    HELD_MODES,
    STAMPS,
    FlightLog,
    FlightLogError,
    load_format,
    parse_columns,
    read_log,
)
from pipeline.altimeter_attitude.gravity import normal_gravity
from pipeline.altimeter_attitude.sensors import InitialSpec, Inputs, SensorSpec
from pipeline.atomic import write_csv
from pipeline.cli_args import Parser, option, out_problem
from pipeline.generated import altimeter_attitude as gen

__all__ = ["FlightLogError", "FlightLog", "read_log", "run_log", "main", "FILTERS", "DEFAULTS"]

FILTERS = ("linear_kf", "ukf", "complementary", "gyro_only")
DEG = math.pi / 180.0
STANDARD_GRAVITY = 9.80665
#: the paper scenario's filter settings (a test checks them against paper.yaml)
DEFAULTS = {"k_per_s": 1.0, "ukf_alpha": 1.0, "ukf_beta": 2.0, "ukf_kappa": 0.0, "omega_c": 0.05}
MAX_K_DT = 0.5  # as the scenario check: A is frozen over a step
#: initial roll/pitch sigma (deg) when levelling starts the filters: at least this, and at
#: least INIT_SIGMA_SCATTER times the standard error of the levelling mean (its scatter)
INIT_SIGMA_FLOOR_DEG = 0.5
INIT_SIGMA_SCATTER = 3.0
#: initial roll/pitch sigma (deg) with a given start (--roll0-deg, --pitch0-deg): the paper
#: scenario's initial_error
GIVEN_START_SIGMA_DEG = 2.0
LEVEL_LOAD = (0.8, 1.2)  # |f| / g allowed over the levelling window (catches unit mistakes)


def levelling_sigma(accel: np.ndarray, gravity: float) -> tuple[float, float]:
    """Initial sigma (rad) of roll and pitch from accelerometer levelling over ``accel``
    (n, 3) m/s^2: ``max(floor, 3 s_y / (g sqrt n))`` for roll and the same with ``s_x`` for
    pitch, s the samples' standard deviation (eq. 17-b: theta ~ asin(f_x / g), phi ~
    atan(f_y / f_z), so the mean's standard error over g is the angle's); the floor
    :data:`INIT_SIGMA_FLOOR_DEG` covers the steady accelerations the scatter cannot show.

    >>> a = np.tile([0.0, 0.0, -9.80665], (100, 1))
    >>> [round(float(np.degrees(s)), 3) for s in levelling_sigma(a, 9.80665)]
    [0.5, 0.5]
    >>> a[:, 1] += np.tile([-1.0, 1.0], 50)  # 1 m/s^2 of vibration on y
    >>> [round(float(np.degrees(s)), 3) for s in levelling_sigma(a, 9.80665)]
    [1.762, 0.5]
    """
    n = accel.shape[0]
    s = accel.std(axis=0, ddof=1) if n > 1 else np.zeros(3)
    scatter = INIT_SIGMA_SCATTER * s / (gravity * math.sqrt(n))
    floor = INIT_SIGMA_FLOOR_DEG * DEG
    return max(floor, float(scatter[1])), max(floor, float(scatter[0]))


def run_log(
    log: FlightLog,
    filters: tuple[str, ...] = FILTERS,
    *,
    gyro_sigma_deg_s: float = 0.5,
    accel_sigma: float = 0.1,
    altimeter_sigma: float = 2.0,
    k: float = DEFAULTS["k_per_s"],
    roll0_deg: float | None = None,
    pitch0_deg: float | None = None,
    init_sigma_deg: float | None = None,
    v_d0: float = 0.0,
    v_d_sigma: float = 1.0,
    h0: float | None = None,
    h_sigma: float | None = None,
    level_s: float = 1.0,
    gravity: float = STANDARD_GRAVITY,
    stamp: str = "start",
    ukf_params: tuple[float, float, float] = (
        DEFAULTS["ukf_alpha"],
        DEFAULTS["ukf_beta"],
        DEFAULTS["ukf_kappa"],
    ),
    omega_c: float = DEFAULTS["omega_c"],
    report=None,
) -> pd.DataFrame:
    """Filter a checked flight log; returns the FLIGHTLOG_OUTPUT_COLUMNS frame.

    ``report`` (a callable taking a line) receives the start that was inferred.
    """
    unknown = sorted(set(filters) - set(FILTERS))
    if unknown or stamp not in STAMPS:
        raise FlightLogError(f"filters {unknown} / stamp {stamp!r}: allowed {FILTERS}, {STAMPS}")
    t, dt, alt = log.t, log.dt, log.altimeter
    n_level = max(1, min(len(t) - 1, int(round(level_s / dt))))
    f_mean = log.accel[:n_level].mean(axis=0)
    c_a = np.array(gen.accel_third_row(*f_mean), dtype=float)
    phi_a, theta_a = (float(v) for v in gen.euler_from_third_row(*c_a))
    load = float(np.linalg.norm(f_mean)) / gravity
    if (roll0_deg is None or pitch0_deg is None) and not LEVEL_LOAD[0] <= load <= LEVEL_LOAD[1]:
        cols = ", ".join(f"{c}[{u}]" for q, (c, u) in log.columns.items() if q.startswith("accel"))
        raise FlightLogError(
            f"{log.path}: columns {cols}: mean |f| over the first {n_level} rows (--level-s) is "
            f"{load:.3g} g; levelling needs {LEVEL_LOAD[0]:g}-{LEVEL_LOAD[1]:g} g (unaccelerated "
            "start): check the accelerometer unit, or give --roll0-deg and --pitch0-deg"
        )
    phi0 = phi_a if roll0_deg is None else roll0_deg * DEG
    theta0 = theta_a if pitch0_deg is None else pitch0_deg * DEG
    levelled = roll0_deg is None or pitch0_deg is None
    if init_sigma_deg is not None:
        sig_roll = sig_pitch = init_sigma_deg * DEG
        sigma_from = "given"
    elif levelled:
        sig_roll, sig_pitch = levelling_sigma(log.accel[:n_level], gravity)
        sigma_from = f"from the levelling scatter, floor {INIT_SIGMA_FLOOR_DEG:g} deg"
    else:
        sig_roll = sig_pitch = GIVEN_START_SIGMA_DEG * DEG
        sigma_from = "given start"
    altimeter = alt.copy()
    if h0 is None:
        h0 = float(alt[np.isfinite(alt)][0])
        altimeter[np.flatnonzero(np.isfinite(alt))[0]] = np.nan  # used to start h, not again
    h_sigma = altimeter_sigma if h_sigma is None else h_sigma
    if report is not None:
        report(
            f"start: roll {round(phi0 / DEG, 3) + 0.0:.3f} deg, pitch {round(theta0 / DEG, 3) + 0.0:.3f} deg "
            f"({'levelling over ' + str(n_level) + ' rows' if roll0_deg is None else 'given'}; "
            f"|f| = {load:.4f} g there), V_d {v_d0:g} m/s, "
            f"h {h0:.6g} m; gravity {gravity:.8g} m/s^2; stamp {stamp}; initial sigma roll "
            f"{sig_roll / DEG:.3g} deg, pitch {sig_pitch / DEG:.3g} deg ({sigma_from})"
        )
    imu = slice(None, -1) if stamp == "start" else slice(1, None)
    sensors = SensorSpec(gyro_sigma_deg_s * DEG, accel_sigma, altimeter_sigma, 1 / dt, log.every)
    initial = InitialSpec(sig_roll, sig_pitch, v_d_sigma, h_sigma)
    inputs = Inputs(
        dt=dt,
        g=gravity,
        gyro=log.gyro[None, imu],
        accel=log.accel[None, imu],
        altimeter=altimeter[None, :],
        x0_euler=np.array([[phi0, theta0, v_d0, h0]]),
        sigma0=np.array([[initial.roll_sigma, initial.pitch_sigma, v_d_sigma, h_sigma]]),
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
    for e in ests:
        bad = ~(np.isfinite(e.roll[0]) & np.isfinite(e.pitch[0]))
        if bad.any():
            raise FloatingPointError(
                f"{e.filter}: non-finite roll/pitch from t = {t[np.flatnonzero(bad)[0]]:.6g} s "
                "(the filter diverged; check the units and the noise sigmas)"
            )
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


def _parser(prog: str | None = None) -> argparse.ArgumentParser:
    p = Parser(
        prog=prog or "python -m pipeline.altimeter_attitude.flightlog",
        description=__doc__,
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    p.add_argument("log", type=Path, help="flight-log CSV (format above)")
    p.add_argument("--out", type=Path, required=True, help="attitude CSV to write (a file)")
    p.add_argument("--filters", default=",".join(FILTERS), help=f"subset of {','.join(FILTERS)}")
    p.add_argument("--columns", default="", help="QUANTITY=COLUMN[:UNIT],... (see above)")
    p.add_argument("--format", type=Path, help="YAML/JSON file with columns and stamp")
    p.add_argument(
        "--altimeter-held",
        choices=HELD_MODES,
        default="check",
        help="an altimeter value repeated on every row until the next sample: 'check' "
        "(default) refuses a column repeating the value before on half its rows, 'yes' keeps "
        "the first row of each hold, 'no' takes every value as a sample",
    )
    p.add_argument(
        "--stamp",
        choices=STAMPS,
        help="IMU sample stamped at its interval's start (default) or end",
    )
    option(
        p,
        "--max-jitter",
        0,
        0.5,
        "largest |step - median step| / median step allowed "
        "(default 0.01); larger steps are refused as gaps, naming the rows",
        default=0.01,
    )
    g = p.add_mutually_exclusive_group()
    option(g, "--gravity", 9.7, 9.9, "g in m/s^2 (default 9.80665)")
    option(g, "--latitude-deg", -90, 90, "WGS-84 normal gravity at this latitude", False)
    option(
        p,
        "--height-m",
        -1000,
        20000,
        "height for --latitude-deg (default: mean altimeter reading)",
        False,
    )
    option(p, "--gyro-sigma-deg-s", 0, 100, "gyro noise per sample (0.5)", default=0.5)
    option(p, "--accel-sigma-m-s2", 0, 100, "accelerometer noise per sample (0.1)", default=0.1)
    option(p, "--altimeter-sigma-m", 0, 1000, "altimeter noise (2)", default=2.0)
    option(
        p,
        "--k-per-s",
        0,
        1e4,
        f"eq. 14 gain ({DEFAULTS['k_per_s']:g}; k dt <= {MAX_K_DT})",
        False,
        default=DEFAULTS["k_per_s"],
    )
    option(p, "--ukf-alpha", 0, 1, "UKF alpha (1)", default=DEFAULTS["ukf_alpha"])
    option(p, "--ukf-beta", 0, 10, "UKF beta (2)", False, default=DEFAULTS["ukf_beta"])
    option(p, "--ukf-kappa", -4, 100, "UKF kappa (0; > -4)", default=DEFAULTS["ukf_kappa"])
    option(
        p,
        "--omega-c-rad-s",
        0,
        10,
        "complementary filter bandwidth (0.05)",
        default=DEFAULTS["omega_c"],
    )
    option(p, "--roll0-deg", -89, 89, "initial roll (default: levelling)", False)
    option(p, "--pitch0-deg", -89, 89, "initial pitch (default: levelling)", False)
    option(
        p,
        "--init-sigma-deg",
        0,
        90,
        "initial roll and pitch sigma (default: from levelling, see above; with --roll0-deg and "
        f"--pitch0-deg {GIVEN_START_SIGMA_DEG:g})",
    )
    option(p, "--v-d0-m-s", -1000, 1000, "initial V_d, down (0)", False, default=0.0)
    option(p, "--v-d-sigma0-m-s", 0, 1000, "its sigma (1)", default=1.0)
    option(p, "--h0-m", -1000, 30000, "initial h (default: first altimeter value)", False)
    option(p, "--h-sigma0-m", 0, 1000, "its sigma (default: --altimeter-sigma-m)")
    option(p, "--level-s", 0, 600, "levelling window, s (1; at most the log)", default=1.0)
    return p


def main(argv: list[str] | None = None, prog: str | None = None) -> int:
    """The command line; returns 0, 2 (bad input, argument or --out) or 1 (a filter failed).

    Never raises: every failure is one ``error:`` line on stderr.
    """
    parser = _parser(prog)
    try:
        args = parser.parse_args(argv)
        filters = tuple(f.strip() for f in args.filters.split(",") if f.strip())
        if not filters or any(f not in FILTERS for f in filters):
            parser.error(f"--filters = {args.filters!r}: allowed values are {', '.join(FILTERS)}")
        if args.height_m is not None and args.latitude_deg is None:
            parser.error(f"--height-m = {args.height_m:g}: only with --latitude-deg")
    except SystemExit as exc:  # --help (0) or a bad argument (2, one line printed)
        return int(exc.code or 0) if not isinstance(exc.code, str) else 2
    problem = out_problem(args.out, args.log)

    def say(line: str) -> None:
        print(line, file=sys.stderr)

    try:
        if problem:
            raise FlightLogError(problem)
        mapping, stamp = {}, None
        if args.format is not None:
            mapping, stamp = load_format(args.format)
        mapping.update(parse_columns(args.columns))
        stamp = args.stamp or stamp or "start"
        log = read_log(args.log, mapping, args.max_jitter, args.altimeter_held)
        if args.k_per_s * log.dt > MAX_K_DT:
            raise FlightLogError(
                f"--k-per-s = {args.k_per_s:g}: k dt = {args.k_per_s * log.dt:g} at the log's "
                f"{1 / log.dt:.6g} Hz must be <= {MAX_K_DT}"
            )
        if args.level_s > log.duration:
            raise FlightLogError(
                f"--level-s = {args.level_s:g}: longer than the log ({log.duration:.6g} s)"
            )
        gravity = STANDARD_GRAVITY if args.gravity is None else args.gravity
        if args.gravity is None and args.latitude_deg is None:
            say("gravity: standard 9.80665 m/s^2 (--gravity or --latitude-deg to change it)")
        if args.latitude_deg is not None:
            alt = log.altimeter[np.isfinite(log.altimeter)]
            height = float(alt.mean()) if args.height_m is None else args.height_m
            gravity = normal_gravity(args.latitude_deg, height)
            say(f"gravity: WGS-84 normal gravity at {args.latitude_deg:g} deg, {height:.6g} m")
        say(log.summary())
    except (FlightLogError, ValueError) as exc:
        say(f"error: {exc}")
        return 2
    try:
        frame = run_log(
            log,
            filters,
            gyro_sigma_deg_s=args.gyro_sigma_deg_s,
            accel_sigma=args.accel_sigma_m_s2,
            altimeter_sigma=args.altimeter_sigma_m,
            k=args.k_per_s,
            roll0_deg=args.roll0_deg,
            pitch0_deg=args.pitch0_deg,
            init_sigma_deg=args.init_sigma_deg,
            v_d0=args.v_d0_m_s,
            v_d_sigma=args.v_d_sigma0_m_s,
            h0=args.h0_m,
            h_sigma=args.h_sigma0_m,
            level_s=args.level_s,
            gravity=gravity,
            stamp=stamp,
            ukf_params=(args.ukf_alpha, args.ukf_beta, args.ukf_kappa),
            omega_c=args.omega_c_rad_s,
            report=say,
        )
        write_csv(args.out, frame, FLIGHTLOG_OUTPUT_COLUMNS)
    except FlightLogError as exc:  # the levelling check (|f| over the window)
        say(f"error: {exc}")
        return 2
    except (ValueError, ArithmeticError, OSError) as exc:  # NotPositiveDefiniteError: ValueError
        say(f"error: {args.log}: {type(exc).__name__}: {str(exc).splitlines()[0]}")
        return 1
    say(f"{args.out}: {len(frame)} rows ({', '.join(filters)})")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
