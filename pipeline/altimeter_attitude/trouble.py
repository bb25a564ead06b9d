"""Numerical trouble of the altimeter-attitude filters, counted per filter and run: never silent.

A filter meets trouble where noise or an extreme trajectory drives it out of its working range.
Its runs still enter the summaries (a NaN run makes the RMS NaN, it is never left out), and the
counts go to ``numerical_trouble.csv`` (and ``sweep_trouble.csv`` for the sweep) in the shared
layout of :mod:`pipeline.trouble`. The kinds, per run:

``non_finite``
    a roll or pitch estimate NaN or infinite at some state time (eq. 17-b divides by |f|, the
    UKF and EKF propagate Euler angles through tan(theta) and 1/cos(theta));
``diverged``
    a finite roll or pitch error beyond :data:`DIVERGED_DEG` at some state time;
``sigma_not_positive``
    for a filter with a covariance, a roll or pitch sigma that is zero, negative or not finite
    at some state time (the NEES divides by it). A covariance the UKF cannot factor (Cholesky)
    is no count: the run stops with the trials named (``NotPositiveDefiniteError``).
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from pipeline.altimeter_attitude.estimates import Estimates
from pipeline.altimeter_attitude.metrics import angle_errors
from pipeline.altimeter_attitude.trajectory import Truth
from pipeline.trouble import TROUBLE_COLUMNS, trouble_rows

__all__ = ["DIVERGED_DEG", "TROUBLE_KINDS", "estimates_trouble", "trouble_frame"]

TROUBLE_KINDS = ("non_finite", "diverged", "sigma_not_positive")
#: an attitude error beyond this is a diverged run (the paper's RMS errors are below 2 deg)
DIVERGED_DEG = 45.0


def estimates_trouble(est: Estimates, truth: Truth, run: str, case: str = "") -> list[tuple]:
    """Rows of :data:`~pipeline.trouble.TROUBLE_COLUMNS`: the runs of ``est`` with each kind."""
    er, ep = angle_errors(est, truth)
    angles = np.concatenate([est.roll, est.pitch], axis=1)
    bad = ~np.isfinite(angles).all(axis=1)
    err = np.abs(np.concatenate([er, ep], axis=1))
    with np.errstate(invalid="ignore"):
        far = (np.where(np.isfinite(err), err, 0.0) > np.deg2rad(DIVERGED_DEG)).any(axis=1)
    sigma = np.concatenate([est.roll_sigma, est.pitch_sigma], axis=1)
    if np.all(np.isnan(sigma)):  # a filter without a covariance
        sig_bad = np.zeros(sigma.shape[0], dtype=bool)
    else:
        with np.errstate(invalid="ignore"):
            sig_bad = ~(np.isfinite(sigma) & (sigma > 0.0)).all(axis=1)
    counts = {
        "non_finite": int(bad.sum()),
        "diverged": int(far.sum()),
        "sigma_not_positive": int(sig_bad.sum()),
    }
    return trouble_rows(run, case, est.filter, est.roll.shape[0], counts)


def trouble_frame(rows: list[tuple]) -> pd.DataFrame:
    """The rows as a frame of :data:`~pipeline.trouble.TROUBLE_COLUMNS`."""
    return pd.DataFrame(rows, columns=TROUBLE_COLUMNS)
