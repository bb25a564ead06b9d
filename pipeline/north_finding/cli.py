"""Command line: the paper's estimators on your own turntable readings.

Estimate roll, pitch, azimuth and the sensor calibration from a readings CSV
(format below and in ``pipeline/north_finding/readings_csv.py``; one row per reading)::

    inertial-repro north-finding estimate --readings my_table.csv \\
        --lat-deg 35.7 --g 9.7966 --omega-ie 7.292115e-5 --compass-deg 80 \\
        --level-source L1 --out my_estimates.csv

Write a readings CSV simulated from a scenario (for trying the format)::

    inertial-repro north-finding simulate-readings \\
        --scenario config/scenarios/north_finding/paper.yaml --out example.csv

Frames: N is NED; the table frame T is N turned by the 3-2-1 Euler angles (yaw
psi, pitch theta, roll phi); the sensor block B is T turned by tau about z_T,
right-handed (z_T points down, so positive tau turns x_B from x_T towards y_T:
clockwise seen from above; on a level table x_B points at azimuth psi + tau).
Which positions each method reads (POSITION_NEEDS in scenario.py): L1 x at 0, 90,
180, 270; L3 the same on y; L2/L4 all rows on x/y (>= 3); L5 x at 0, 90, 180 and
one z; A1c1 x at 0, 180; A1c2 x at 90, 270; A2 x at --a2-tau-deg; A3 the largest
gyro reading on x; A4, A5 x at 0, 90, 180; A6 those and one z. A missing position
is an error before any compute.

Output (stdout, and --out as estimates.csv): method, quantity, estimate with the
unit in the quantity's name: phi_deg, theta_deg (roll, pitch of T, deg), psi_deg
(azimuth of x_T from north, clockwise, deg), acc_bias_ug (micro-g), acc_scale
and gyro_scale (S = 1 + scale-factor error), gyro_bias_rad_s (rad/s); and flag,
';'-separated, empty when the estimate passed every check. Each flag also prints
one "warning:" line on stderr:
  a3_scan_bound_exceeds_accuracy / a3_scan_bound_unknown  the step of the A3 peak
      scan allows an error above --a3-accuracy-deg / cannot be bounded (1 reading);
  a3_peak_unreachable  the largest peak reading is outside the range eq. 45 reaches
      at this roll, pitch and latitude (typically a gyro bias): A3's psi does not
      follow the readings (use A4, which estimates the bias);
  compass_disagrees  psi is more than --compass-tolerance-deg from --compass-deg;
  clipped_arcsine, unreachable_root, complex_roots, non_finite  numerical trouble
      (pipeline/north_finding/trouble.py): an argument out of the formula's domain
      was clipped, or the estimate is NaN.

Inputs are validated with the same schema as scenario files; errors name the
option, the value and what is allowed, and nothing is written on error.
"""

from __future__ import annotations

import argparse
import sys
from pathlib import Path

import numpy as np
import pandas as pd

from pipeline.atomic import write_atomic, write_csv
from pipeline.cli_args import Parser, count, number, out_problem
from pipeline.config import ConfigError
from pipeline.north_finding import columns as col
from pipeline.north_finding import readings as rd
from pipeline.north_finding import readings_checks as rc
from pipeline.north_finding.run import _readings, scenario_key
from pipeline.north_finding.scan_bound import DEFAULT_ACCURACY_DEG
from pipeline.north_finding.scenario import build_scenario, load_scenario

__all__ = ["main"]

ALL = ["L1", "L2", "L3", "L4", "L5", "A1c1", "A1c2", "A2", "A3", "A4", "A5", "A6"]
#: the bounds of the scenario schema (config/schemas/north_finding_scenario.schema.json)
G_RANGE = (9.7, 9.9)
MAX_OMEGA_IE = 1e-4
#: the largest --trial (monte_carlo.n_trials is at most this)
MAX_TRIAL = 1_000_000


def _estimate(args: argparse.Namespace) -> int:
    raw = {
        "description": f"readings from {args.readings}",
        "type": "readings",
        "readings_csv": str(Path(args.readings).resolve()),
        "site": {"lat_deg": args.lat_deg, "g_m_s2": args.g, "omega_ie_rad_s": args.omega_ie},
        "compass": {"heading_deg": args.compass_deg, "tolerance_deg": args.compass_tolerance_deg},
        "level_source": args.level_source,
        "methods": args.methods or ALL,
        "a2_tau_deg": args.a2_tau_deg,
        "a3_accuracy_deg": args.a3_accuracy_deg,
        "decisions": [],
    }
    sc = build_scenario(raw, Path("<command line>"), base=Path("/"))
    frames = _readings(sc, log=lambda m: print(m, file=sys.stderr))
    est = frames["estimates"].drop(columns=["sensor"])
    if args.out:
        write_csv(args.out, frames["estimates"], col.ESTIMATE_COLUMNS)
    print(est[["method", "quantity", "estimate", "flag"]].fillna("").to_string(index=False))
    return 0


def _simulate_readings(args: argparse.Namespace) -> int:
    sc = load_scenario(args.scenario)
    if sc.kind != "simulated":
        raise ConfigError(
            f"{args.scenario}: type = {sc.kind!r}: allowed: 'simulated' (simulate-readings "
            "draws the noise of a simulated scenario)"
        )
    if args.trial >= sc.n_trials:
        raise ConfigError(
            f"--trial = {args.trial}: allowed: 0 <= trial < {sc.n_trials} (monte_carlo.n_trials "
            f"of {args.scenario})"
        )
    tau, axis, _ = rd.simulation_positions(sc)
    normals = rd.standard_normals(sc.seed, scenario_key(sc.name), args.trial + 1, tau.size)[
        args.trial :
    ]
    r = rd.simulate(sc, sc.accel, sc.gyro, normals, sc.n_samples)
    frame = pd.DataFrame(
        {
            "tau_deg": np.round(r.tau_deg, 9),
            "axis": r.axis,
            "role": r.role,
            "accel_m_s2": r.accel[0],
            "gyro_rad_s": r.gyro[0],
            "n_samples": sc.n_samples,
        }
    )
    header = (
        f"# SIMULATED readings (not measured): scenario {sc.name}, trial {args.trial}, "
        f"N = {sc.n_samples} samples per position.\n"
        f"# Columns: {', '.join(rd.READINGS_COLUMNS)} (see pipeline/north_finding/readings_csv.py).\n"
    )

    def write(p: Path) -> None:
        p.write_text(header + frame.to_csv(index=False, float_format="%.17g"), encoding="utf-8")

    write_atomic(args.out, write)
    print(f"wrote {args.out} ({len(frame)} positions)")
    return 0


def _parser(prog: str | None) -> tuple[argparse.ArgumentParser, dict[str, argparse.ArgumentParser]]:
    parser = Parser(
        prog=prog or "python -m pipeline.north_finding.cli",
        description=f"{__doc__}\n{rd.format_help()}",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    sub = parser.add_subparsers(dest="command", required=True)
    e = sub.add_parser(
        "estimate",
        help="run the estimators on a readings CSV",
        description=f"{__doc__}\n{rd.format_help()}",
        formatter_class=argparse.RawDescriptionHelpFormatter,
    )
    e.add_argument("--readings", required=True, help="readings CSV")
    e.add_argument(
        "--lat-deg",
        required=True,
        type=number("--lat-deg", -90, 90, True, True),
        help="geodetic latitude, deg (-90, 90)",
    )
    e.add_argument(
        "--g",
        required=True,
        type=number("--g", *G_RANGE),
        help=f"local gravity, m/s^2 [{G_RANGE[0]:g}, {G_RANGE[1]:g}]",
    )
    e.add_argument(
        "--omega-ie",
        type=number("--omega-ie", 0, MAX_OMEGA_IE, True),
        default=7.292115e-5,
        help=f"Earth rate, rad/s (0, {MAX_OMEGA_IE:g}] (default %(default)s)",
    )
    e.add_argument(
        "--compass-deg",
        required=True,
        type=number("--compass-deg", -180, 360),
        help="coarse heading, deg [-180, 360]",
    )
    e.add_argument(
        "--compass-tolerance-deg",
        type=number("--compass-tolerance-deg", 0, 180, True),
        default=rc.DEFAULT_COMPASS_TOLERANCE_DEG,
        help="stated accuracy of --compass-deg, deg (0, 180]: an azimuth estimate farther than "
        "this from it is flagged compass_disagrees with a warning (the compass only picks among "
        "each method's roots; beyond its accuracy the other root may be right) (default "
        "%(default)s)",
    )
    e.add_argument(
        "--level-source",
        default="L1",
        choices=["L1", "L2", "L3", "L4"],
        help="levelling method whose roll and pitch feed the azimuth methods",
    )
    e.add_argument(
        "--a2-tau-deg",
        type=number("--a2-tau-deg", 0, 360, hi_open=True),
        default=45.0,
        help="table angle of azimuth method 2, deg [0, 360)",
    )
    e.add_argument(
        "--a3-accuracy-deg",
        type=number("--a3-accuracy-deg", 0, 90, True),
        default=DEFAULT_ACCURACY_DEG,
        help="accuracy option of azimuth method A3, deg (0, 90]: warn when the step of the peak "
        "scan allows a larger azimuth error (default %(default)s)",
    )
    e.add_argument("--methods", nargs="+", choices=ALL, help="methods to run (default: all)")
    e.add_argument("--out", type=Path, help="write estimates.csv here")
    s = sub.add_parser("simulate-readings", help="write a simulated readings CSV from a scenario")
    s.add_argument("--scenario", type=Path, required=True, help="simulated scenario YAML")
    s.add_argument(
        "--trial",
        type=count("--trial", 0, MAX_TRIAL),
        default=0,
        help="Monte Carlo trial whose noise to use, 0 <= trial < the scenario's n_trials",
    )
    s.add_argument("--out", type=Path, required=True, help="CSV to write")
    return parser, {"estimate": e, "simulate-readings": s}


def main(argv: list[str] | None = None, prog: str | None = None) -> int:
    """The command line; returns 0, or 2 with one ``error:`` line on stderr (bad input,
    argument or --out, refused before any compute)."""
    parser, subparsers = _parser(prog)
    try:
        args, extra = parser.parse_known_args(argv)
        if extra:
            subparsers[args.command].error(f"unrecognized arguments: {' '.join(extra)}")
    except SystemExit as exc:  # --help (0) or a bad argument (2, one line printed)
        return int(exc.code or 0) if not isinstance(exc.code, str) else 2
    try:
        if args.command == "estimate":
            if not Path(args.readings).is_file():
                raise ConfigError(
                    f"--readings = {args.readings}: not found or not a file; allowed: a "
                    "readings CSV file"
                )
            if args.out is not None:
                problem = out_problem(args.out, Path(args.readings), "the readings file")
                if problem:
                    raise ConfigError(problem)
            if args.level_source not in (args.methods or ALL):
                args.methods = [args.level_source, *(args.methods or [])]
            return _estimate(args)
        if not args.scenario.is_file():
            raise ConfigError(
                f"--scenario = {args.scenario}: not found or not a file; allowed: a simulated "
                "scenario YAML file"
            )
        problem = out_problem(args.out, args.scenario, "the scenario file")
        if problem:
            raise ConfigError(problem)
        return _simulate_readings(args)
    except ValueError as exc:  # ConfigError is a ValueError
        print(f"error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    raise SystemExit(main())
