"""The UKF's sigma-point tuning, which the paper does not give: ``ukf_tuning.csv``.

The paper names its UKF (Julier/Uhlmann, Wan/van der Merwe; Sec. 6) but prints none of its
parameters. Every (alpha, kappa) of a grid (``altimeter_attitude.ukf_tuning`` of
config/config.yaml; beta of the scenario) runs the UKF on the published scenario: the
scenario's Monte Carlo and, stacked onto it, the noise-free run with an exact start of
``noise_free.csv`` (:func:`pipeline.altimeter_attitude.run.simulate`), both on the same
inputs as the scenario's own results. One row per setting (``UKF_TUNING_COLUMNS``), RMS over
runs and over the flight after the transient, with the centre weights of the mean (``wm0``)
and of the covariance (``wc0``), whether every weight is >= 0 (then the unscented covariance
is a non-negative sum of outer products, positive semi-definite by construction) and whether
the setting is the scenario's own (``chosen``). A setting whose covariance stops being
positive definite keeps its row with NaN statistics and ``status`` naming the failure.
"""

from __future__ import annotations

import math
from collections.abc import Sequence
from typing import Any

import numpy as np
import pandas as pd

from pipeline.altimeter_attitude import euler_filters, metrics
from pipeline.altimeter_attitude.columns import UKF_TUNING_COLUMNS
from pipeline.altimeter_attitude.scenario import Scenario
from pipeline.altimeter_attitude.sensors import simulate_inputs
from pipeline.altimeter_attitude.ukf import MerweWeights, NotPositiveDefiniteError

__all__ = ["N_STATE", "nonnegative_weights", "run_tuning", "spread", "tuning_step"]

N_STATE = 4  # [roll, pitch, V_d, h]


def nonnegative_weights(alpha: float, beta: float, kappa: float, n: int = N_STATE) -> bool:
    """Whether every mean and covariance weight of the Merwe sigma points is >= 0.

    ``Wm[0] = lam / (n + lam)`` with ``lam = alpha**2 (n + kappa) - n`` is >= 0 only when
    ``alpha**2 (n + kappa) >= n``; with ``alpha <= 1`` that needs ``kappa >= 0`` and, for
    kappa = 0, ``alpha = 1``.

    >>> nonnegative_weights(1.0, 2.0, 0.0), nonnegative_weights(0.5, 2.0, 0.0)
    (True, False)
    >>> nonnegative_weights(1.0, 2.0, 3.0 - 4)  # Julier's kappa = 3 - n for n = 4
    False
    """
    w = MerweWeights(n=n, alpha=alpha, beta=beta, kappa=kappa)
    return bool(np.all(w.Wm >= 0.0) and np.all(w.Wc >= 0.0))


def run_tuning(
    sc: Scenario,
    alphas: Sequence[float],
    kappas: Sequence[float],
    n_runs: int | None = None,
    log=print,
) -> pd.DataFrame:
    """One row per (alpha, kappa), alpha-major in the given order (``UKF_TUNING_COLUMNS``)."""
    n = n_runs or sc.n_runs
    inputs = simulate_inputs(sc.profiles, sc.sensors, sc.initial, n, sc.seed, sc.name)
    clean = simulate_inputs(sc.profiles, sc.sensors, sc.initial, 1, sc.seed, sc.name, 0.0)
    first = int(round(sc.transient * sc.sensors.rate_hz))
    rows: list[dict[str, Any]] = []
    for alpha in alphas:
        for kappa in kappas:
            w = MerweWeights(n=N_STATE, alpha=float(alpha), beta=sc.ukf_beta, kappa=float(kappa))
            row: dict[str, Any] = {
                "alpha": float(alpha),
                "kappa": float(kappa),
                "beta": sc.ukf_beta,
                "wm0": float(w.Wm[0]),
                "wc0": float(w.Wc[0]),
                "nonnegative_weights": nonnegative_weights(alpha, sc.ukf_beta, kappa),
                "chosen": (float(alpha), float(kappa)) == (sc.ukf_alpha, sc.ukf_kappa),
                "n_runs": n,
            }
            # the Monte Carlo and the noise-free run apart (the UKF treats each run alone: the
            # same numbers as stacked), so no stacked copy of the inputs is made (~56 MB)
            try:
                est, est_nf = (
                    euler_filters.run_ukf(
                        part, float(alpha), sc.ukf_beta, float(kappa), third_row=False
                    )
                    for part in (inputs, clean)
                )
            except NotPositiveDefiniteError as err:
                row["status"] = f"covariance not positive definite ({err.where})"
                rows.append(row)
                continue
            mc = metrics.summary_row(est, inputs.truth, first)
            nf = metrics.summary_row(est_nf, clean.truth, first)
            del est, est_nf
            row.update(
                {
                    "roll_rms_deg": mc["roll_rms_deg"],
                    "pitch_rms_deg": mc["pitch_rms_deg"],
                    "nees_roll": mc["nees_roll"],
                    "nees_pitch": mc["nees_pitch"],
                    "noise_free_roll_rms_deg": nf["roll_rms_deg"],
                    "noise_free_pitch_rms_deg": nf["pitch_rms_deg"],
                    "status": "ok",
                }
            )
            rows.append(row)
            log(f"ukf tuning: alpha {alpha:g}, kappa {kappa:g}: done")
    frame = pd.DataFrame(rows, columns=UKF_TUNING_COLUMNS)
    for col in UKF_TUNING_COLUMNS:
        if col.endswith("_deg") or col.startswith("nees"):
            frame[col] = frame[col].astype(float)
    return frame


def spread(frame: pd.DataFrame, column: str) -> tuple[float, float]:
    """(min, max) of a column over the settings that ran (NaN, NaN if none).

    >>> spread(pd.DataFrame({"x": [0.5, float("nan"), 0.2]}), "x")
    (0.2, 0.5)
    """
    vals = frame[column].dropna()
    if not len(vals):
        return math.nan, math.nan
    return float(vals.min()), float(vals.max())


def tuning_step(inputs: Any, outputs: Any, params: Any, log: Any) -> None:
    """Workflow step: the grid of ``params["ukf_tuning"]`` on ``inputs["scenario"]``."""
    from pipeline.altimeter_attitude.heap import keep_freed_memory
    from pipeline.altimeter_attitude.scenario import load_scenario
    from pipeline.atomic import write_csv

    keep_freed_memory()
    grid = params["ukf_tuning"]
    frame = run_tuning(
        load_scenario(inputs["scenario"]),
        list(grid["alpha"]),
        list(grid["kappa"]),
        grid.get("n_runs"),
        log=log,
    )
    write_csv(outputs["ukf_tuning"], frame, UKF_TUNING_COLUMNS)
