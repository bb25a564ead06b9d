"""Sensitivity sweep: how the RMS errors depend on choices the paper leaves open.

One parameter at a time around a base scenario (the paper's): the IMU sample rate (the
sigmas are per-sample values, so the attitude random walk scales with sqrt(dt)), the
maneuver intensity (what the altimeter can observe comes from the vertical-plane
accelerations), and the initial roll/pitch error. Points that share the sample rate are
stacked along the run axis and filtered in one vectorised pass; errors are then computed per
point against that point's own truth, over the flight after the transient and over the
point's own after-bank window (:mod:`pipeline.altimeter_attitude.windows`; NaN where it has
none). Writes ``sweep.csv`` (``SWEEP_COLUMNS``); the workflow step also writes the numerical
trouble of every point and filter to ``sweep_trouble.csv``.
"""

from __future__ import annotations

import argparse
import copy
import math
import sys
from pathlib import Path
from typing import Any

import pandas as pd

from pipeline.altimeter_attitude import metrics, run, windows
from pipeline.altimeter_attitude.columns import SWEEP_COLUMNS, WINDOWS
from pipeline.altimeter_attitude.scenario import Scenario, build_scenario, load_scenario
from pipeline.altimeter_attitude.sensors import simulate_inputs
from pipeline.altimeter_attitude.trouble import estimates_trouble
from pipeline.atomic import write_csv
from pipeline.config import ConfigError

__all__ = ["PARAMETERS", "variant", "run_sweep", "main"]

PARAMETERS = ("imu_rate_hz", "intensity", "initial_error_deg")


def variant(base: Scenario, parameter: str, value: float) -> Scenario:
    """The base scenario with one parameter changed (validated like any scenario file)."""
    raw = copy.deepcopy(base.raw)
    if parameter == "imu_rate_hz":
        raw["sensors"]["imu_rate_hz"] = float(value)
    elif parameter == "intensity":
        raw["trajectory"]["intensity"] = float(value)
    elif parameter == "initial_error_deg":
        raw["initial_error"]["roll_sigma_deg"] = float(value)
        raw["initial_error"]["pitch_sigma_deg"] = float(value)
    else:
        raise ValueError(f"sweep parameter {parameter!r} unknown; allowed: {list(PARAMETERS)}")
    return build_scenario(raw, base.path)


def run_sweep(
    base: Scenario,
    values: dict[str, list[float]],
    n_runs: int,
    filters: tuple[str, ...],
    log=print,
    trouble: list[tuple] | None = None,
) -> pd.DataFrame:
    """Every (parameter, value) point; base-valued points are computed once and reported
    under each parameter. Given ``trouble`` (a list), appends the numerical trouble of every
    point and filter (:func:`pipeline.altimeter_attitude.trouble.estimates_trouble`, run
    ``sweep``, case ``<parameter>=<value>``)."""
    points: list[tuple[str, float, Scenario]] = []
    for parameter, vals in values.items():
        for v in vals:
            points.append((parameter, float(v), variant(base, parameter, v)))
    # group points by sample rate (one vectorised pass per rate)
    groups: dict[float, list[tuple[str, float, Scenario]]] = {}
    for p in points:
        groups.setdefault(p[2].sensors.rate_hz, []).append(p)
    rows: list[dict[str, Any]] = []
    for rate, pts in sorted(groups.items()):
        # identical scenarios (e.g. the base under every parameter) are simulated once
        unique: dict[str, tuple[Scenario, list[tuple[str, float]]]] = {}
        for parameter, v, sc in pts:
            unique.setdefault(sc.config_sha256, (sc, []))[1].append((parameter, v))
        # one point's runs at a time: the compiled filters cost the same per run whatever
        # the batch, and only one point's histories are held (stacking the 7 points of 50 Hz
        # held 140 runs': ~490 MB peak, which this VM charges ~5 ms of system CPU per MB
        # first touched; see chunk_plan.BATCH_RUNS)
        for sc, labels in unique.values():
            part = simulate_inputs(sc.profiles, sc.sensors, sc.initial, n_runs, sc.seed, base.name)
            estimates = run.run_filters(base, part, filters, log=lambda m: None)
            first = int(round(sc.transient * sc.sensors.rate_hz))
            after = windows.scenario_windows(sc)[WINDOWS.index("after_bank")]
            for name, mine in estimates.items():
                row = metrics.summary_row(mine, part.truth, first)
                if after.defined:
                    srow = metrics.summary_row(mine, part.truth, after.first)
                else:
                    srow = {"roll_rms_deg": math.nan, "pitch_rms_deg": math.nan}
                for parameter, v in labels:
                    if trouble is not None:
                        trouble += estimates_trouble(
                            mine, part.truth, "sweep", f"{parameter}={v:g}"
                        )
                    rows.append(
                        {
                            "parameter": parameter,
                            "value": v,
                            "filter": name,
                            "roll_rms_deg": row["roll_rms_deg"],
                            "pitch_rms_deg": row["pitch_rms_deg"],
                            "n_runs": n_runs,
                            "after_bank_roll_rms_deg": srow["roll_rms_deg"],
                            "after_bank_pitch_rms_deg": srow["pitch_rms_deg"],
                            "after_bank_start_s": after.start,
                        }
                    )
        log(f"sweep: {rate:g} Hz, {len(unique)} points x {n_runs} runs done")
    frame = pd.DataFrame(rows, columns=SWEEP_COLUMNS)
    order = {p: i for i, p in enumerate(values)}
    frame["_o"] = frame["parameter"].map(order)
    frame = frame.sort_values(["_o", "value", "filter"], kind="stable").drop(columns="_o")
    return frame.reset_index(drop=True)


def sweep_settings(config: dict[str, Any]) -> dict[str, Any]:
    """The ``altimeter_attitude.sweep`` block of config/config.yaml (validated by its schema)."""
    try:
        block = config["altimeter_attitude"]["sweep"]
    except (KeyError, TypeError):
        raise ConfigError("config: altimeter_attitude.sweep is missing") from None
    return block


def main(argv: list[str] | None = None) -> int:
    from pipeline.config import load_schema, load_yaml, validate

    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--config", type=Path, default=Path("config/config.yaml"))
    parser.add_argument("--out", type=Path, required=True, help="sweep.csv to write")
    args = parser.parse_args(argv)
    try:
        config = load_yaml(args.config)
        validate(config, load_schema("config"), args.config)
        settings = sweep_settings(config)
        base = load_scenario(settings["base_scenario"])
    except (ValueError, OSError) as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    frame = run_sweep(
        base,
        settings["values"],
        settings["n_runs"],
        tuple(settings["filters"]),
        log=lambda m: print(m, file=sys.stderr, flush=True),
    )
    write_csv(args.out, frame, SWEEP_COLUMNS)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
