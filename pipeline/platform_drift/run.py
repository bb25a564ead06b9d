"""Run one platform-drift scenario and write its results directory.

Writes, under ``results/platform_drift/<scenario>/``:

* ``errors.csv`` (``ERRORS_COLUMNS``): position error (m) every ``output_step_s`` from 0 to
  ``duration_s`` for every drift case and three schemes:

  - ``proposed_simulated``: nonlinear simulation of the stable platform and of the paper's
    position-independent algorithm (eqs. 9-16, 25; :mod:`platform`);
  - ``proposed_analytic``: the paper's analysis, eqs. 32 and 36, from the generated code
    (:mod:`analytic`);
  - ``strapdown``: nonlinear NED strapdown INS with the same gyro drifts (:mod:`strapdown`);

* ``errors_diagnostic.csv`` (same columns, scheme ``proposed_true_azimuth``): the platform
  simulation with eq. 16 told the platform's true azimuth rate (r_m = b_g3), i.e. only the
  tilt-induced rate errors that eqs. 33-36 model;
* ``errors_long.csv`` and ``errors_long_diagnostic.csv``: the same over ``long_duration_s``
  when the scenario has one (the stationary 24 h run);
* ``summary.csv`` (``SUMMARY_COLUMNS``): per case and scheme the error at ``duration_s``
  (``error_2h_m``), the largest error, and ``crossover_s``. For the rows of
  ``proposed_simulated`` and ``strapdown`` it is the first output time t >= 300 s at which
  the strapdown error exceeds the proposed_simulated error by more than 1 m (so that two
  coinciding curves do not "cross" on numerical noise); for the rows of
  ``proposed_analytic`` and ``proposed_true_azimuth`` the same with that scheme in place of
  proposed_simulated; NaN if it never does;
* ``numerical_trouble.csv`` (:data:`pipeline.trouble.TROUBLE_COLUMNS`): per run (``main``,
  ``long``), drift case and scheme, how many of the curve's points met each kind of
  :data:`TROUBLE_KINDS`: ``eq36_undefined`` (the analytic channel-3 curve at a start latitude
  of 0, where eq. 36 divides by zero: NaN), ``clipped_arcsine`` (the haversine's argument
  clipped to [0, 1]) and ``non_finite`` (a NaN or infinite error). An integrator failure is
  no count: the step stops with the integrator's message and writes nothing;
* ``provenance.json``: code version, config and generated-module hashes, packages,
  integrator, function-evaluation counts, derived constants and no-drift error floors.
  No wall times (the files are reproducible bit for bit; there are no random numbers).

Usage::

    python -m pipeline.platform_drift.run --scenario config/scenarios/platform_drift/stationary.yaml \
        --out-dir results/platform_drift/stationary
    python -m pipeline.platform_drift.run --all    # every scenario into results/platform_drift/<name>
"""

from __future__ import annotations

import argparse
import hashlib
import sys
import time
from pathlib import Path

import numpy as np
import pandas as pd

from pipeline.atomic import write_csv, write_json
from pipeline.generated import frames
from pipeline.generated import platform_drift as gen
from pipeline.platform_drift import analytic
from pipeline.platform_drift import platform as pf
from pipeline.platform_drift import strapdown as sd
from pipeline.platform_drift.columns import DRIFT_SUMMARY_COLUMNS, ERRORS_COLUMNS
from pipeline.platform_drift.scenario import ROOT, Scenario, load_scenario
from pipeline.platform_drift.trajectory import haversine, haversine_clipped
from pipeline.trouble import TROUBLE_COLUMNS, Trouble

__all__ = [
    "ERRORS_COLUMNS",
    "CROSSOVER_AFTER_S",
    "SUMMARY_COLUMNS",
    "SCHEMES",
    "DIAGNOSTIC_SCHEME",
    "TROUBLE_KINDS",
    "simulate_errors",
    "summary_frame",
    "crossover",
    "run_scenario",
    "main",
]

# column lists: pipeline/columns.py (ERRORS_COLUMNS, DRIFT_SUMMARY_COLUMNS)
SUMMARY_COLUMNS = DRIFT_SUMMARY_COLUMNS
SCHEMES = ("proposed_simulated", "proposed_analytic", "strapdown")
DIAGNOSTIC_SCHEME = "proposed_true_azimuth"
CROSSOVER_AFTER_S = 300.0
SCENARIO_DIR = ROOT / "config" / "scenarios" / "platform_drift"
RESULTS_DIR = ROOT / "results" / "platform_drift"
GENERATED = ROOT / "pipeline" / "generated" / "platform_drift.py"
#: the numerical trouble counted per curve point (see the module docstring)
TROUBLE_KINDS = ("eq36_undefined", "clipped_arcsine", "non_finite")


def _long(t: np.ndarray, curves: dict[tuple[str, str], np.ndarray]) -> pd.DataFrame:
    parts = [
        pd.DataFrame({"t_s": t, "case": case, "scheme": scheme, "error_m": err})
        for (case, scheme), err in curves.items()
    ]
    return pd.concat(parts, ignore_index=True)[ERRORS_COLUMNS]


def simulate_errors(
    sc: Scenario,
    duration: float,
    log=print,
    trouble: list[pd.DataFrame] | None = None,
    run: str = "main",
    case_prefix: str = "",
    ground_speed: bool = True,
) -> tuple[pd.DataFrame, pd.DataFrame, dict]:
    """Errors of every case and scheme over ``duration``; (errors, diagnostic, info). Given
    ``trouble`` (a list), appends the numerical trouble of every curve (rows of
    :data:`~pipeline.trouble.TROUBLE_COLUMNS`, run ``run``, case ``case_prefix + case``).
    ``ground_speed=False`` leaves ``max_ground_speed_m_s`` out of ``info`` (it samples the
    trajectory 720 times; a caller that discards ``info`` need not)."""
    traj = sc.trajectory()
    t = sc.times(duration)
    lat_true, lon_true = traj.latlon(t)
    radius = sc.earth.radius
    p_drift = np.array([sc.platform_drift(c) for c in sc.cases])
    s_drift = np.array([sc.strapdown_drift(c) for c in sc.cases])

    plat = pf.simulate(traj, p_drift, t, sc.initial_level, sc.rtol)
    strap = sd.simulate(traj, s_drift, t, sc.rtol)
    log(
        f"{sc.name}: {duration:g} s, {len(sc.cases)} cases: platform "
        f"{int(plat['nfev'])} evaluations, strapdown {int(strap['nfev'])} evaluations"
    )

    curves, diag = {}, {}
    counts = Trouble(TROUBLE_KINDS)
    for i, case in enumerate(sc.cases):
        pos = {
            "proposed_simulated": (plat["lat"][i], plat["lon"][i]),
            "strapdown": (strap["lat"][i], strap["lon"][i]),
            DIAGNOSTIC_SCHEME: (plat["lat_diag"][i], plat["lon_diag"][i]),
        }
        err = {}
        for scheme, (lat, lon) in pos.items():
            err[scheme] = radius * haversine(lat_true, lon_true, lat, lon)
            clipped = haversine_clipped(lat_true, lon_true, lat, lon)
            counts.mark(f"{case}/{scheme}", "clipped_arcsine", clipped)
        curves[case, "proposed_simulated"] = err["proposed_simulated"]
        curves[case, "proposed_analytic"] = analytic.error_m(sc, case, t)
        curves[case, "strapdown"] = err["strapdown"]
        diag[case, DIAGNOSTIC_SCHEME] = err[DIAGNOSTIC_SCHEME]
        undefined = bool(analytic.eq36_undefined(sc)) and sc.platform_drift(case)[2] != 0.0
        counts.mark(f"{case}/proposed_analytic", "eq36_undefined", np.full(t.shape, undefined))
    if trouble is not None:
        trouble.append(_trouble_frame(counts, {**curves, **diag}, run, case_prefix))
    info = {"nfev_platform": int(plat["nfev"]), "nfev_strapdown": int(strap["nfev"])}
    if "none" in sc.cases:
        info["no_drift_floor_m"] = {
            "proposed_simulated": float(curves["none", "proposed_simulated"].max()),
            "strapdown": float(curves["none", "strapdown"].max()),
        }
    if ground_speed:
        ground = [traj.at(float(x)) for x in t[:: max(1, len(t) // 720)]]
        # eq. 8: the Earth-relative velocity v_i - omega_ie x r
        w_ie = frames.earth_rate_e(sc.earth.omega_e)
        info["max_ground_speed_m_s"] = float(
            max(np.linalg.norm(gen.ground_velocity(*g.v_i, *g.r_i, *w_ie)) for g in ground)
        )
    return _long(t, curves), _long(t, diag), info


def _trouble_frame(
    counts: Trouble, curves: dict[tuple[str, str], np.ndarray], run: str, case_prefix: str
) -> pd.DataFrame:
    """The trouble rows of every curve: case and scheme, in the order of errors.csv."""
    flat = counts.frame({f"{c}/{s}": v for (c, s), v in curves.items()}, run)
    case_scheme = flat["method"].str.split("/", n=1, expand=True)
    flat["case"] = case_prefix + case_scheme[0]
    flat["method"] = case_scheme[1]
    return flat[TROUBLE_COLUMNS]


def crossover(t: np.ndarray, strap: np.ndarray, other: np.ndarray) -> float:
    """The crossover of ``strap`` above ``other``: the one rule of the verdicts
    (:func:`pipeline.platform_drift.curves.crossover`), so the summary and the verdicts agree."""
    from pipeline.platform_drift.curves import crossover as cross

    return cross(pd.Series(strap, index=t), pd.Series(other, index=t), CROSSOVER_AFTER_S)


def summary_frame(errors: pd.DataFrame, diagnostic: pd.DataFrame) -> pd.DataFrame:
    """One row per case and scheme (SUMMARY_COLUMNS); see the module docstring."""
    both = pd.concat([errors, diagnostic], ignore_index=True)
    rows = []
    for case in dict.fromkeys(both["case"]):
        sub = both[both["case"] == case]
        curve = {s: g.sort_values("t_s") for s, g in sub.groupby("scheme", sort=False)}
        t = curve["strapdown"]["t_s"].to_numpy()
        strap = curve["strapdown"]["error_m"].to_numpy()
        prop = curve["proposed_simulated"]["error_m"].to_numpy()
        for scheme in (*SCHEMES, DIAGNOSTIC_SCHEME):
            err = curve[scheme]["error_m"].to_numpy()
            ref = prop if scheme == "strapdown" else err
            rows.append(
                {
                    "case": case,
                    "scheme": scheme,
                    "error_2h_m": float(err[-1]),
                    "error_max_m": float(err.max()),
                    "crossover_s": crossover(t, strap, ref),
                }
            )
    return pd.DataFrame(rows, columns=SUMMARY_COLUMNS)


def _sha256_file(path: Path) -> str:
    return hashlib.sha256(path.read_bytes()).hexdigest() if path.is_file() else "missing"


def _relative(path: Path) -> str:
    try:
        return str(path.resolve().relative_to(ROOT))
    except ValueError:
        return str(path)


def run_scenario(
    scenario: Scenario | str | Path, out_dir: str | Path, log=print
) -> dict[str, Path]:
    """Run a scenario (validated first) and write its results atomically into ``out_dir``."""
    from pipeline.provenance import provenance

    sc = scenario if isinstance(scenario, Scenario) else load_scenario(scenario)
    out_dir = Path(out_dir)
    trouble: list[pd.DataFrame] = []
    errors, diag, info = simulate_errors(sc, sc.duration, log, trouble, "main")
    written = {
        "errors": write_csv(out_dir / "errors.csv", errors, ERRORS_COLUMNS),
        "errors_diagnostic": write_csv(out_dir / "errors_diagnostic.csv", diag, ERRORS_COLUMNS),
        "summary": write_csv(out_dir / "summary.csv", summary_frame(errors, diag), SUMMARY_COLUMNS),
    }
    runs = {"main": {"duration_s": sc.duration, **info}}
    if sc.long_duration is not None:
        errors_l, diag_l, info_l = simulate_errors(sc, sc.long_duration, log, trouble, "long")
        written["errors_long"] = write_csv(out_dir / "errors_long.csv", errors_l, ERRORS_COLUMNS)
        written["errors_long_diagnostic"] = write_csv(
            out_dir / "errors_long_diagnostic.csv", diag_l, ERRORS_COLUMNS
        )
        runs["long"] = {"duration_s": sc.long_duration, **info_l}
    else:  # no long run: header-only files, so every scenario has the same outputs
        empty = pd.DataFrame(columns=ERRORS_COLUMNS)
        written["errors_long"] = write_csv(out_dir / "errors_long.csv", empty, ERRORS_COLUMNS)
        written["errors_long_diagnostic"] = write_csv(
            out_dir / "errors_long_diagnostic.csv", empty, ERRORS_COLUMNS
        )
    written["numerical_trouble"] = write_csv(
        out_dir / "numerical_trouble.csv", pd.concat(trouble, ignore_index=True), TROUBLE_COLUMNS
    )
    prov = provenance(
        scenario=sc.name,
        scenario_file=_relative(sc.path),
        config_sha256=sc.config_sha256,
        generated_module=_relative(GENERATED),
        generated_sha256=_sha256_file(GENERATED),
        seeds=None,
        seed_scheme="none: deterministic simulation, no random numbers",
        integrator={
            "method": "DOP853",
            "rtol": sc.rtol,
            "library": "pipeline.platform_drift.dop853 (scipy.integrate.solve_ivp DOP853, bit for bit)",
        },
        constants=analytic.constants(sc),
        runs=runs,
    )
    written["provenance"] = write_json(out_dir / "provenance.json", prov)
    return written


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    group = parser.add_mutually_exclusive_group(required=True)
    group.add_argument("--scenario", type=Path, help="scenario YAML file")
    group.add_argument(
        "--all", action="store_true", help=f"run every scenario in {_relative(SCENARIO_DIR)}"
    )
    parser.add_argument("--out-dir", type=Path, help="results directory (with --scenario)")
    parser.add_argument(
        "--results-dir",
        type=Path,
        default=RESULTS_DIR,
        help="parent of the per-scenario directories (with --all)",
    )
    args = parser.parse_args(argv)
    if args.scenario is not None and args.out_dir is None:
        parser.error("--out-dir is required with --scenario")

    def log(message: str) -> None:
        print(message, file=sys.stderr, flush=True)

    paths = [args.scenario] if args.scenario else sorted(SCENARIO_DIR.glob("*.yaml"))
    try:  # validate every file before any compute starts
        scenarios = [load_scenario(p) for p in paths]
    except ValueError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    start = time.perf_counter()
    for sc in scenarios:
        out = args.out_dir if args.scenario else args.results_dir / sc.name
        run_scenario(sc, out, log=log)
        log(f"{sc.name}: written to {out} ({time.perf_counter() - start:.1f} s elapsed)")
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
