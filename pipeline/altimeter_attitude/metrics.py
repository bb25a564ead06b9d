"""Monte Carlo statistics of the filters (Figs 7-12 and the quoted RMS values).

* RMS over runs at each time: ``sqrt(mean_runs e^2)`` (Figs 7, 8, 10, 12); the filter's
  own sigma likewise as RMS over runs (Figs 9, 11).
* One number per filter and angle (rms_summary.csv): RMS over runs *and* over the times
  after the transient; sigma the same for the filter's sigma; NEES the mean over runs and
  times of e^2 / sigma^2 (1 for a consistent filter, per angle).
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from pipeline.altimeter_attitude.columns import (
    RMS_SUMMARY_COLUMNS,
    RUN_RMS_COLUMNS,
    TIMESERIES_COLUMNS,
)
from pipeline.altimeter_attitude.estimates import Estimates
from pipeline.altimeter_attitude.trajectory import Truth

__all__ = ["angle_errors", "summary_row", "run_rms_frame", "timeseries_frame", "nees_bounds"]

RAD2DEG = 180.0 / np.pi


def _wrap(a: np.ndarray) -> np.ndarray:
    return (a + np.pi) % (2 * np.pi) - np.pi


def angle_errors(est: Estimates, truth: Truth) -> tuple[np.ndarray, np.ndarray]:
    """Roll and pitch errors (N, T + 1) in rad, wrapped to [-pi, pi)."""
    return _wrap(est.roll - truth.roll), _wrap(est.pitch - truth.pitch)


def _rms(a: np.ndarray, axis=None) -> np.ndarray:
    return np.sqrt(np.mean(a**2, axis=axis))


def summary_row(est: Estimates, truth: Truth, first: int) -> dict:
    """One row of rms_summary.csv over state times ``first:`` (after the transient)."""
    er, ep = angle_errors(est, truth)
    sl = np.s_[:, first:]
    has_sigma = not np.all(np.isnan(est.roll_sigma))
    row = {
        "filter": est.filter,
        "roll_rms_deg": RAD2DEG * _rms(er[sl]),
        "pitch_rms_deg": RAD2DEG * _rms(ep[sl]),
        "roll_sigma_deg": RAD2DEG * _rms(est.roll_sigma[sl]) if has_sigma else np.nan,
        "pitch_sigma_deg": RAD2DEG * _rms(est.pitch_sigma[sl]) if has_sigma else np.nan,
        "nees_roll": np.mean((er / est.roll_sigma)[sl] ** 2) if has_sigma else np.nan,
        "nees_pitch": np.mean((ep / est.pitch_sigma)[sl] ** 2) if has_sigma else np.nan,
        "n_runs": est.roll.shape[0],
    }
    return {k: row[k] for k in RMS_SUMMARY_COLUMNS}


def run_rms_frame(est: Estimates, truth: Truth, first: int) -> pd.DataFrame:
    """Per run: RMS over the state times ``first:`` of the roll and pitch errors (deg)."""
    er, ep = angle_errors(est, truth)
    frame = pd.DataFrame(
        {
            "run": np.arange(er.shape[0]),
            "filter": est.filter,
            "roll_rms_deg": RAD2DEG * _rms(er[:, first:], axis=1),
            "pitch_rms_deg": RAD2DEG * _rms(ep[:, first:], axis=1),
        }
    )
    return frame[RUN_RMS_COLUMNS]


def timeseries_frame(est: Estimates, truth: Truth, every: int) -> pd.DataFrame:
    """RMS-over-runs time series of one filter at every ``every``-th state time."""
    er, ep = angle_errors(est, truth)
    idx = np.arange(0, er.shape[1], every)
    c_err = est.c[:, idx] - truth.c[idx][None]
    with np.errstate(invalid="ignore", divide="ignore"):
        nees_r = np.mean((er[:, idx] / est.roll_sigma[:, idx]) ** 2, axis=0)
        nees_p = np.mean((ep[:, idx] / est.pitch_sigma[:, idx]) ** 2, axis=0)
    frame = pd.DataFrame(
        {
            "t_s": truth.t[idx],
            "filter": est.filter,
            "roll_rms_deg": RAD2DEG * _rms(er[:, idx], axis=0),
            "pitch_rms_deg": RAD2DEG * _rms(ep[:, idx], axis=0),
            "roll_sigma_deg": RAD2DEG * _rms(est.roll_sigma[:, idx], axis=0),
            "pitch_sigma_deg": RAD2DEG * _rms(est.pitch_sigma[:, idx], axis=0),
            "c1_rms": _rms(c_err[..., 0], axis=0),
            "c2_rms": _rms(c_err[..., 1], axis=0),
            "c3_rms": _rms(c_err[..., 2], axis=0),
            "norm_error_rms": _rms(est.norm_error[:, idx], axis=0),
            "nees_roll": nees_r,
            "nees_pitch": nees_p,
        }
    )
    return frame[TIMESERIES_COLUMNS]


def nees_bounds(n_runs: int, n_times: int = 1, p: float = 0.95) -> tuple[float, float]:
    """Two-sided chi-square interval of a mean NEES of one angle over n_runs (x n_times)
    independent samples: chi2(p, dof = n) / n. For time averages the samples are correlated,
    so the interval is computed with n = n_runs only (conservative).

    The quantiles are ``2 gammaincinv(n/2, q)``, which is what ``scipy.stats.chi2.ppf(q, n)``
    computes (bit for bit), without importing ``scipy.stats`` (~0.8 CPU-s of the figures step).

    >>> from scipy.stats import chi2
    >>> nees_bounds(100) == tuple(float(v) / 100 for v in chi2.ppf([0.025, 0.975], 100))
    True
    """
    from scipy.special import gammaincinv

    n = n_runs * n_times
    lo, hi = 2 * gammaincinv(n / 2, np.array([(1 - p) / 2, (1 + p) / 2]))
    return float(lo / n), float(hi / n)
