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
and gyro_scale (S = 1 + scale-factor error), gyro_bias_rad_s (rad/s).

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
from pipeline.config import ConfigError
from pipeline.north_finding import columns as col
from pipeline.north_finding import readings as rd
from pipeline.north_finding.run import _readings, scenario_key
from pipeline.north_finding.scan_bound import DEFAULT_ACCURACY_DEG
from pipeline.north_finding.scenario import build_scenario, load_scenario

__all__ = ["main"]

ALL = ["L1", "L2", "L3", "L4", "L5", "A1c1", "A1c2", "A2", "A3", "A4", "A5", "A6"]


def _estimate(args: argparse.Namespace) -> int:
    raw = {
        "description": f"readings from {args.readings}",
        "type": "readings",
        "readings_csv": str(Path(args.readings).resolve()),
        "site": {"lat_deg": args.lat_deg, "g_m_s2": args.g, "omega_ie_rad_s": args.omega_ie},
        "compass": {"heading_deg": args.compass_deg},
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
    print(est[["method", "quantity", "estimate"]].to_string(index=False))
    return 0


def _simulate_readings(args: argparse.Namespace) -> int:
    sc = load_scenario(args.scenario)
    if sc.kind != "simulated":
        raise ConfigError(f"{args.scenario}: type must be 'simulated' to simulate readings")
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


def main(argv: list[str] | None = None, prog: str | None = None) -> int:
    parser = argparse.ArgumentParser(
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
    e.add_argument("--lat-deg", required=True, type=float, help="geodetic latitude, deg (-90, 90)")
    e.add_argument("--g", required=True, type=float, help="local gravity, m/s^2 (> 0)")
    e.add_argument("--omega-ie", type=float, default=7.292115e-5, help="Earth rate, rad/s")
    e.add_argument("--compass-deg", required=True, type=float, help="coarse heading, deg")
    e.add_argument(
        "--level-source",
        default="L1",
        choices=["L1", "L2", "L3", "L4"],
        help="levelling method whose roll and pitch feed the azimuth methods",
    )
    e.add_argument(
        "--a2-tau-deg", type=float, default=45.0, help="table angle of azimuth method 2, deg"
    )
    e.add_argument(
        "--a3-accuracy-deg",
        type=float,
        default=DEFAULT_ACCURACY_DEG,
        help="accuracy option of azimuth method A3, deg: warn when the step of the peak scan "
        "allows a larger azimuth error (default %(default)s)",
    )
    e.add_argument("--methods", nargs="+", choices=ALL, help="methods to run (default: all)")
    e.add_argument("--out", help="write estimates.csv here")
    s = sub.add_parser("simulate-readings", help="write a simulated readings CSV from a scenario")
    s.add_argument("--scenario", required=True, help="simulated scenario YAML")
    s.add_argument("--trial", type=int, default=0, help="Monte Carlo trial whose noise to use")
    s.add_argument("--out", required=True, help="CSV to write")
    args = parser.parse_args(argv)
    try:
        if args.command == "estimate":
            if args.level_source not in (args.methods or ALL):
                args.methods = [args.level_source, *(args.methods or [])]
            return _estimate(args)
        return _simulate_readings(args)
    except ValueError as exc:  # ConfigError is a ValueError
        print(f"error: {exc}", file=sys.stderr)
        return 2


if __name__ == "__main__":
    raise SystemExit(main())
