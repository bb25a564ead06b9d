"""Run one north-finding scenario and write its results directory.

Writes, under ``results/north_finding/<scenario>/`` (columns in pipeline/columns.py):

* ``estimates.csv``: the ideal sensor and the real sensor without noise
  (deterministic error propagation), one row per method and quantity;
* ``mc_trials.csv`` and ``mc_summary.csv``: the noisy real sensor, Monte Carlo (above
  :data:`pipeline.north_finding.trials_file.CSV_MAX_TRIALS` trials ``mc_trials.npy``, the
  binary form of :mod:`pipeline.north_finding.trials_file`);
* ``error_budget.csv``: the noise-free error with one error source at a time, and
  the Monte Carlo standard deviation as the 'noise' source;
* ``sensitivity.csv``: Monte Carlo RMS error against the averaging count N;
* ``ranking.csv`` and ``ranking_pairs.csv``: the Monte Carlo at each N of the scenario's
  ``ranking`` block, for the claims that rank methods (:mod:`pipeline.north_finding.ranking`);
* ``a2_scan.csv``: the noise-free real-sensor azimuth of method A2 at every whole-degree
  table angle (the paper does not give its tau);
* ``numerical_trouble.csv``: per run (noise-free real, Monte Carlo, sensitivity and ranking
  at each N, or the readings), method and kind, the trials in which an estimator clipped an
  argument or gave a non-finite value (:mod:`pipeline.north_finding.trouble`);
* ``provenance.json``: code version, config hash, packages, seeds.

The N at which the statistical verdicts are judged is not this scenario's ``n_samples``: the
published scenario's N inference (:mod:`pipeline.north_finding.run_inference`, its own step)
writes ``n_profile.csv``, ``n_rows.csv``, ``n_robustness.csv`` and ``mc_trials_judged.csv``.

Ideal sensor: no misalignment and no noise; the scale factor and bias are those of
the real sensor for the methods that estimate them (L5, A4, A5, A6), and 1 and 0
for the others (the paper's Tables 1, 2, 5 print 0 % for the ideal sensor, and
Tables 6-8 recover the nominal S and b).

Usage: ``python -m pipeline.north_finding.run --scenario config/scenarios/north_finding/paper.yaml
--out-dir results/north_finding/paper``
"""

from __future__ import annotations

import argparse
import hashlib
import sys
from pathlib import Path

import numpy as np
import pandas as pd

from pipeline.atomic import write_csv, write_json
from pipeline.north_finding import columns as col
from pipeline.north_finding import estimators as est
from pipeline.north_finding import readings as rd
from pipeline.north_finding import readings_checks as rc
from pipeline.north_finding import scan_bound as sb
from pipeline.north_finding import trials_file as tf
from pipeline.north_finding.ranking import ranking_frames
from pipeline.north_finding.scenario import ROOT, Scenario, load_scenario
from pipeline.north_finding.trials_file import difference as _difference
from pipeline.north_finding.trials_file import error_pct as _error_pct
from pipeline.north_finding.trials_file import ordered as _ordered
from pipeline.north_finding.trials_file import trials_frame
from pipeline.north_finding.trouble import TROUBLE_COLUMNS, Trouble, n_case

__all__ = ["run_scenario", "truth_values", "estimates_frame", "trials_frame", "main"]

CALIBRATION_METHODS = ("L5", "A4", "A5", "A6")
ALL_SOURCES = ("scale_factor", "misalignment", "bias", "noise")


def scenario_key(name: str) -> int:
    """Stable 32-bit key of a scenario name, mixed into every seed."""
    return int.from_bytes(hashlib.sha256(name.encode()).digest()[:4], "little")


def truth_values(sc: Scenario, off: tuple[str, ...] = ()) -> dict[str, float]:
    """True value of every quantity for the sensor with the error sources ``off`` switched off.

    NaN where unknown (e.g. a readings scenario without a truth block).
    """
    t = sc.truth or {}
    out = {q: np.nan for q in col.QUANTITIES}
    if t:
        out.update(
            phi_deg=np.rad2deg(t["phi"]),
            theta_deg=np.rad2deg(t["theta"]),
            psi_deg=np.rad2deg(t["psi"]) % 360.0,
        )
    if sc.accel is not None:
        acc = sc.accel.without(*off)
        out.update(
            acc_bias_ug=acc.bias / sc.g * 1e6, acc_scale=acc.scale, acc_scale_approx=acc.scale
        )
    if sc.gyro is not None:
        gyr = sc.gyro.without(*off)
        out.update(gyro_bias_rad_s=gyr.bias, gyro_scale=gyr.scale, gyro_scale_approx=gyr.scale)
    return out


def estimates_frame(
    estimates: est.Estimates,
    truth: dict[str, float],
    sensor: str,
    bounds: dict[str, np.ndarray] | None = None,
    accuracy_deg: float = sb.DEFAULT_ACCURACY_DEG,
) -> pd.DataFrame:
    """One row per (method, quantity) of a single-trial run; A3's psi carries its scan bound
    (``bounds``, deg) and the flag against ``accuracy_deg``."""
    rows = []
    for m, q in _ordered(estimates):
        value = float(estimates[m, q][0])
        bound = float(bounds[m][0]) if bounds and m in bounds and q == "psi_deg" else np.nan
        rows.append(
            {
                "sensor": sensor,
                "method": m,
                "quantity": q,
                "truth": truth[q],
                "estimate": value,
                "error_pct": float(_error_pct(value, truth[q], q)),
                "scan_bound_deg": bound,
                "flag": sb.flag(bound, accuracy_deg) if m == "A3" and bounds is not None else "",
            }
        )
    return pd.DataFrame(rows, columns=col.ESTIMATE_COLUMNS)


def summary_frame(trials: pd.DataFrame) -> pd.DataFrame:
    """Mean, std and 5/50/95 % quantiles of every estimate over its finite trials; ``n_trials``
    is how many those are (NaN trials are skipped, counted in numerical_trouble.csv)."""
    grouped = trials.groupby(["method", "quantity"], sort=False)["estimate"]
    out = pd.DataFrame(
        {
            "truth": trials.groupby(["method", "quantity"], sort=False)["truth"].first(),
            "mean": grouped.mean(),
            "std": grouped.std(ddof=1),
            "p05": grouped.quantile(0.05),
            "p50": grouped.quantile(0.50),
            "p95": grouped.quantile(0.95),
            "n_trials": grouped.count(),  # the trials used: NaN ones are skipped
        }
    ).reset_index()
    return out[col.MC_SUMMARY_COLUMNS]


class _Runner:
    """Runs the estimators on simulated readings with chosen error sources."""

    def __init__(self, sc: Scenario):
        self.sc = sc
        self.site = est.Site(sc.lat, sc.g, sc.omega_ie)
        t = sc.truth
        self.truth_level = (t["theta"], t["phi"])
        self.psi = t["psi"]

    def run(
        self,
        off: tuple[str, ...],
        normals: np.ndarray | None,
        n_samples: int,
        methods=None,
        trouble: Trouble | None = None,
        bounds: dict[str, np.ndarray] | None = None,
    ):
        sc = self.sc
        methods = methods or sc.methods
        readings = rd.simulate(
            sc, sc.accel.without(*off), sc.gyro.without(*off), normals, n_samples
        )
        prior = np.full(readings.n_trials, self.psi + sc.compass_offset)
        return est.estimate_all(
            readings,
            self.site,
            methods,
            sc.level_source,
            self.truth_level,
            prior,
            sc.table["a2_tau_deg"],
            trouble,
            bounds,
        )


def _simulated(sc: Scenario, log) -> dict[str, pd.DataFrame]:
    truth = truth_values(sc)
    runner = _Runner(sc)
    calib = tuple(m for m in sc.methods if m in CALIBRATION_METHODS)
    attitude = tuple(m for m in sc.methods if m not in CALIBRATION_METHODS)
    # ideal: perfect sensor for attitude methods, nominal S and b for calibration methods
    ideal: est.Estimates = {}
    b_ideal: dict[str, np.ndarray] = {}
    b_real: dict[str, np.ndarray] = {}
    if attitude:
        ideal.update(runner.run(ALL_SOURCES, None, 1, attitude, bounds=b_ideal))
    if calib:
        ideal.update(runner.run(("misalignment", "noise"), None, 1, calib))
    # truth of the ideal runs: the attitude is the same; S and b are the nominal ones
    trouble0 = Trouble()
    real0 = runner.run(("noise",), None, 1, trouble=trouble0, bounds=b_real)
    if sc.table["max_search"]["mode"] == "analytic" and "A3" in b_real:
        b_ideal["A3"] = b_real["A3"] = np.zeros(1)  # read at the true tau*: no sampling error
    accuracy = sb.accuracy_deg(sc.raw)
    estimates = pd.concat(
        [
            estimates_frame(ideal, truth, "ideal", b_ideal, accuracy),
            estimates_frame(real0, truth, "real", b_real, accuracy),
        ],
        ignore_index=True,
    )
    for note in sb.warnings(estimates, accuracy):
        log(f"warning: {sc.name}: {note}")
    log(f"{sc.name}: ideal and noise-free real runs done")

    n_pos = rd.simulation_positions(sc)[0].size
    key = scenario_key(sc.name)
    normals = rd.standard_normals(sc.seed, key, sc.n_trials, n_pos)
    trouble_mc = Trouble()
    mc = runner.run((), normals, sc.n_samples, trouble=trouble_mc)
    trials = trials_frame(mc, truth)
    summary = summary_frame(trials)
    log(f"{sc.name}: Monte Carlo {sc.n_trials} trials done")

    budget_rows = []
    for source in ("scale_factor", "misalignment", "bias"):
        others = tuple(s for s in ALL_SOURCES if s != source)
        one = runner.run(others, None, 1)
        truth_one = truth_values(sc, others)
        for (m, q), v in one.items():
            budget_rows.append((m, q, source, float(_difference(v[0], truth_one[q], q))))
    for (m, q), v in real0.items():
        budget_rows.append((m, q, "all_deterministic", float(_difference(v[0], truth[q], q))))
    for (m, q), v in mc.items():
        budget_rows.append((m, q, "noise", float(np.std(v, ddof=1))))
    budget = pd.DataFrame(budget_rows, columns=["method", "quantity", "source", "error"])
    budget["error_pct"] = 100.0 * budget["error"] / budget["quantity"].map(truth).abs()

    sens_rows = []
    trouble_frames = [trouble0.frame(real0, "noise_free_real"), trouble_mc.frame(mc, "monte_carlo")]
    if sc.sensitivity:
        n_sens = sc.sensitivity["n_trials"]
        z = rd.standard_normals(sc.seed, key, n_sens, n_pos)
        for i, n_avg in enumerate(sc.sensitivity["n_avg"]):
            t_sens = Trouble()
            out = runner.run((), z, int(n_avg), trouble=t_sens)
            trouble_frames.append(t_sens.frame(out, "sensitivity", n_case(n_avg)))
            for (m, q), v in out.items():
                err = _error_pct(v, truth[q], q)
                diff = _difference(v, truth[q], q)
                sens_rows.append(
                    {
                        "n_avg": int(n_avg),
                        "method": m,
                        "quantity": q,
                        "truth": truth[q],
                        "rms_error": float(np.sqrt(np.mean(diff**2))),
                        "rms_error_pct": float(np.sqrt(np.mean(err**2))),
                        "n_trials": n_sens,
                    }
                )
            log(f"{sc.name}: sensitivity {i + 1}/{len(sc.sensitivity['n_avg'])} (N = {n_avg})")
    sensitivity = pd.DataFrame(sens_rows, columns=col.SENSITIVITY_COLUMNS)
    ranking, pairs = _ranking(sc, runner, truth, normals, key, n_pos, trouble_frames)
    if sc.ranking:
        log(f"{sc.name}: ranking Monte Carlo at N = {sc.ranking['n_avg']}")
    return {
        "estimates": estimates,
        "mc_trials": {None: mc},  # written by trials_file (CSV or binary)
        "truth": truth,
        "mc_summary": summary,
        "error_budget": budget,
        "sensitivity": sensitivity,
        "ranking": ranking,
        "ranking_pairs": pairs,
        "a2_scan": _a2_scan(sc, runner, trouble_frames),  # before the trouble is gathered
        "numerical_trouble": pd.concat(trouble_frames, ignore_index=True),
    }


def _ranking(
    sc: Scenario, runner: _Runner, truth, normals, key: int, n_pos: int, trouble_frames: list
):
    """ranking.csv and ranking_pairs.csv: the Monte Carlo at every N of ``sc.ranking``, on the
    main Monte Carlo's normals when the trial counts agree (so its N reproduces mc_trials);
    the numerical trouble of each N is appended to ``trouble_frames``."""
    if not sc.ranking:
        return _empty("ranking"), _empty("ranking_pairs")
    n_trials = int(sc.ranking["n_trials"])
    z = normals if n_trials == sc.n_trials else rd.standard_normals(sc.seed, key, n_trials, n_pos)

    def run(n: int) -> est.Estimates:
        t = Trouble()
        out = runner.run((), z, n, trouble=t)
        trouble_frames.append(t.frame(out, "ranking", n_case(n)))
        return out

    return ranking_frames(
        run,
        lambda v, q: _error_pct(v, truth[q], q),
        sc.ranking["n_avg"],
    )


#: The table angles of the method-2 scan (deg).
A2_SCAN_TAU_DEG = np.arange(0.0, 360.0, 1.0)


def _a2_scan(sc: Scenario, runner: _Runner, trouble_frames: list) -> pd.DataFrame:
    """Noise-free real-sensor azimuth of method A2 at every tau of :data:`A2_SCAN_TAU_DEG`;
    its numerical trouble (one 'trial' per tau: run ``a2_scan``) is appended to
    ``trouble_frames``."""
    if "A2" not in sc.methods:
        return _empty("a2_scan")
    tau = A2_SCAN_TAU_DEG
    w = rd.noise_free_gyro(sc, sc.gyro.without("noise"), tau, "x")
    theta, phi = runner.truth_level
    prior = np.full(tau.size, runner.psi + sc.compass_offset)
    t = Trouble()
    with np.errstate(invalid="ignore"):  # NaN angles: counted as non_finite
        psi = est.a2_psi(w, np.deg2rad(tau), sc.omega_ie, sc.lat, theta, phi, prior, t)
    trouble_frames.append(t.frame({("A2", "psi_deg"): psi}, "a2_scan"))
    psi_deg = np.rad2deg(psi) % 360.0
    return pd.DataFrame(
        {
            "tau_deg": tau,
            "psi_deg": psi_deg,
            "error_deg": _difference(psi_deg, np.rad2deg(runner.psi) % 360.0, "psi_deg"),
        }
    )[col.A2_SCAN_COLUMNS]


def _readings(sc: Scenario, log) -> dict[str, pd.DataFrame]:
    truth = truth_values(sc)
    readings = rd.load_readings_csv(sc.readings_csv)
    a2_tau = sc.raw.get("a2_tau_deg")
    rd.check_needs(readings, sc.methods, a2_tau)
    site = est.Site(sc.lat, sc.g, sc.omega_ie)
    level = (sc.truth["theta"], sc.truth["phi"]) if sc.truth else None
    trouble = Trouble()
    bounds: dict[str, np.ndarray] = {}
    out = est.estimate_all(
        readings,
        site,
        sc.methods,
        sc.level_source,
        level,
        np.array([sc.compass_heading]),
        a2_tau,
        trouble,
        bounds,
    )
    log(f"{sc.name}: estimated from {sc.readings_csv.name} ({readings.tau_deg.size} positions)")
    frames: dict = {k: _empty(k) for k in OUTPUTS}
    frames |= {"mc_trials": {}, "truth": truth}  # no Monte Carlo: an empty mc_trials.csv
    frames["numerical_trouble"] = trouble.frame(out, "readings")
    compass_deg = float(np.rad2deg(sc.compass_heading))
    tolerance = float(sc.raw["compass"].get("tolerance_deg", rc.DEFAULT_COMPASS_TOLERANCE_DEG))
    frames["estimates"] = rc.add_flags(
        estimates_frame(out, truth, "real", bounds, sb.accuracy_deg(sc.raw)),
        frames["numerical_trouble"],
        compass_deg,
        tolerance,
    )
    name = sc.readings_csv.name
    for note in sb.warnings(frames["estimates"], sb.accuracy_deg(sc.raw)):
        log(f"warning: {name}: {note}")
    for note in rc.flag_notes(frames["estimates"], compass_deg, tolerance):
        if note.startswith("method A3: the peak reading"):  # the numbers, from the readings
            theta, phi = _level(readings, site, sc, level)
            note = rc.a3_peak_note(readings, sc.omega_ie, sc.lat, theta, phi)
        log(f"warning: {name}: {note}")
    return frames


def _level(
    readings: rd.Readings, site: est.Site, sc: Scenario, level: tuple[float, float] | None
) -> tuple[float, float]:
    """The pitch and roll (rad) the azimuth methods of a readings run used: (theta, phi)."""
    if sc.level_source == "truth" and level is not None:
        return level
    out = est.levelling(readings, site, (sc.level_source,))
    return (
        float(np.deg2rad(out[sc.level_source, "theta_deg"][0])),
        float(np.deg2rad(out[sc.level_source, "phi_deg"][0])),
    )


OUTPUTS = {
    "estimates": ("estimates.csv", col.ESTIMATE_COLUMNS),
    "mc_trials": ("mc_trials.csv", col.MC_TRIAL_COLUMNS),  # or .npy: trials_file
    "mc_summary": ("mc_summary.csv", col.MC_SUMMARY_COLUMNS),
    "error_budget": ("error_budget.csv", col.ERROR_BUDGET_COLUMNS),
    "sensitivity": ("sensitivity.csv", col.SENSITIVITY_COLUMNS),
    "ranking": ("ranking.csv", col.RANKING_COLUMNS),
    "ranking_pairs": ("ranking_pairs.csv", col.RANKING_PAIR_COLUMNS),
    "a2_scan": ("a2_scan.csv", col.A2_SCAN_COLUMNS),
    "numerical_trouble": ("numerical_trouble.csv", TROUBLE_COLUMNS),
}


def _empty(key: str) -> pd.DataFrame:
    return pd.DataFrame(columns=OUTPUTS[key][1])


def run_scenario(
    scenario: Scenario | str | Path, out_dir: str | Path, log=print
) -> dict[str, Path]:
    """Run a scenario (validated first) and write its results atomically into ``out_dir``."""
    from pipeline.provenance import provenance

    sc = scenario if isinstance(scenario, Scenario) else load_scenario(scenario)
    if sc.kind == "simulated":
        # every method's table positions exist by construction; check anyway before compute
        rd.check_needs(rd.layout(sc), sc.methods, sc.table["a2_tau_deg"])
    frames = _simulated(sc, log) if sc.kind == "simulated" else _readings(sc, log)
    out_dir = Path(out_dir)
    written = {}
    for key, (name, columns) in OUTPUTS.items():
        if key != "mc_trials":  # below, in its form
            written[key] = write_csv(out_dir / name, frames[key], columns)
    fmt = tf.trials_format(sc.n_trials, sc.trials_file) if sc.kind == "simulated" else "csv"
    written["mc_trials"] = tf.write_trials(
        out_dir, "mc_trials", frames["mc_trials"], frames["truth"], fmt
    )
    prov = provenance(
        scenario=sc.name,
        scenario_file=_relative(sc.path),
        config_sha256=sc.config_sha256,
        seed=sc.seed,
        seed_scheme="SeedSequence([seed, scenario_key, trial])",
        scenario_key=scenario_key(sc.name),
        n_avg=sc.n_samples,
        n_trials=sc.n_trials,
    )
    written["provenance"] = write_json(out_dir / "provenance.json", prov)
    return written


def _relative(path: Path) -> str:
    try:
        return str(path.resolve().relative_to(ROOT))
    except ValueError:
        return str(path)


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(
        description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter
    )
    parser.add_argument("--scenario", required=True, type=Path, help="scenario YAML file")
    parser.add_argument("--out-dir", required=True, type=Path, help="results directory to write")
    args = parser.parse_args(argv)
    try:
        sc = load_scenario(args.scenario)
    except ValueError as exc:
        print(f"error: {exc}", file=sys.stderr)
        return 2
    run_scenario(sc, args.out_dir, log=lambda m: print(m, file=sys.stderr, flush=True))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
