"""Method A3 on a table scan: the bound on the azimuth error that the scan's step allows.

Method A3 (eqs. 44-52) needs the LARGEST x-gyro reading over the table angle tau. The x gyro
reads a sinusoid in tau (eq. 44), ``w(tau) = R cos(tau - tau*)`` with ``R = Omega sqrt(X^2 +
Y^2)`` (eq. 45), plus an offset (bias, the z-misalignment term) that is small beside R. A scan
reads it at discrete angles only. The largest sample lies between its two neighbours around the
circle and is the sample nearest tau*, so it is at most ``delta = G / 2`` from tau*, where G is
the larger of the two gaps beside it (the step d of a uniform scan). So

    R cos(delta) <= w_max <= R:  the maximum is low by at most the fraction 1 - cos(delta),

and the true peak lies in ``[w_max, w_max / cos(delta)]``. Eq. 47 turns the peak into psi; to
first order the error is ``R (1 - cos delta) / |dR/dpsi|``, which grows without limit where R
is stationary in psi. :func:`a3_scan_bound_deg` does not linearise: it solves eq. 47 (with the
estimator's own quartic and root selection) for peaks across that interval and returns the
largest change of psi. A gap of 180 deg or more beside the maximum (delta >= 90 deg: the peak
may be anywhere) gives ``inf``; fewer than two scan readings give NaN (no gap to measure).

>>> import numpy as np
>>> peak_gap_deg(np.arange(0.0, 360.0, 30.0), np.cos(np.deg2rad(np.arange(0.0, 360.0, 30.0) - 40))[None, :])
array([30.])
>>> peak_gap_deg(np.array([10.0]), np.array([[1.0]]))
array([nan])
>>> round(float(1 - np.cos(np.deg2rad(30.0) / 2)), 5)  # relative bias of a 30-deg scan's maximum
0.03407
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

import numpy as np
import pandas as pd

from pipeline.generated import north_finding as gen
from pipeline.north_finding.estimators import solve_quartic_psi, wrap_pi

__all__ = [
    "DEFAULT_ACCURACY_DEG",
    "FLAG_EXCEEDS",
    "FLAG_UNKNOWN",
    "peak_gap_deg",
    "a3_scan_bound_deg",
    "flag",
    "accuracy_deg",
    "warnings",
]

#: accuracy option of method A3 (deg) when a scenario or the CLI gives none
DEFAULT_ACCURACY_DEG = 0.1
#: estimates.csv ``flag`` values
FLAG_EXCEEDS = "a3_scan_bound_exceeds_accuracy"
FLAG_UNKNOWN = "a3_scan_bound_unknown"
#: points of the interval of possible true peaks at which eq. 47 is solved again
N_GRID = 9


def peak_gap_deg(tau_deg: np.ndarray, w: np.ndarray) -> np.ndarray:
    """Per trial, the larger of the two circular gaps (deg) beside the largest reading.

    ``tau_deg`` (P,) are the scan's table angles, ``w`` (T, P) its readings; NaN if P < 2.
    """
    tau = np.asarray(tau_deg, dtype=float) % 360.0
    w = np.atleast_2d(np.asarray(w, dtype=float))
    if tau.size < 2:
        return np.full(w.shape[0], np.nan)
    order = np.argsort(tau, kind="stable")
    sorted_tau = tau[order]
    gap_next = (np.roll(sorted_tau, -1) - sorted_tau) % 360.0  # gap after sample i
    k = np.argmax(w[:, order], axis=1)
    return np.maximum(gap_next[k], gap_next[k - 1])


def a3_scan_bound_deg(
    tau_deg: np.ndarray,
    w: np.ndarray,
    omega_ie: float,
    lat: float,
    theta: np.ndarray,
    phi: np.ndarray,
    prior: np.ndarray,
) -> np.ndarray:
    """Bound (deg) on the error of method A3's psi caused by taking the maximum of a scan.

    ``w`` (T, P) are the x-gyro readings of the scan at ``tau_deg`` (P,); theta, phi, prior
    (rad, per trial) are those the estimator uses. See the module docstring.
    """
    w = np.atleast_2d(np.asarray(w, dtype=float))
    n = w.shape[0]
    theta, phi, prior = (
        np.broadcast_to(np.asarray(x, dtype=float), (n,)) for x in (theta, phi, prior)
    )
    delta = np.deg2rad(peak_gap_deg(tau_deg, w)) / 2.0
    w_max = w.max(axis=1)
    reachable = np.isfinite(delta) & (delta < np.pi / 2)
    grow = np.where(reachable, 1.0 / np.cos(np.where(reachable, delta, 0.0)) - 1.0, 0.0)
    with np.errstate(invalid="ignore"):
        psi0 = solve_quartic_psi(gen.a3_eq47_coeffs(w_max, omega_ie, lat, theta, phi), prior)
        bound = np.zeros(n)
        for f in np.linspace(0.0, 1.0, N_GRID)[1:]:
            peak = w_max * (1.0 + f * grow)
            psi = solve_quartic_psi(gen.a3_eq47_coeffs(peak, omega_ie, lat, theta, phi), prior)
            bound = np.fmax(bound, np.abs(wrap_pi(psi - psi0)))
    bound = np.where(np.isfinite(delta), np.where(reachable, bound, np.inf), np.nan)
    return np.rad2deg(bound)


def flag(bound_deg: float, accuracy_deg: float) -> str:
    """The estimates.csv ``flag`` of an A3 estimate with sampling bound ``bound_deg``.

    >>> flag(0.0001, 0.1), flag(8.6, 0.1), flag(float("nan"), 0.1)
    ('', 'a3_scan_bound_exceeds_accuracy', 'a3_scan_bound_unknown')
    """
    if np.isnan(bound_deg):
        return FLAG_UNKNOWN
    return FLAG_EXCEEDS if bound_deg > accuracy_deg else ""


def accuracy_deg(raw: Mapping[str, Any]) -> float:
    """A scenario's accuracy option of method A3 (``a3_accuracy_deg``, deg), or the default.

    >>> accuracy_deg({}), accuracy_deg({"a3_accuracy_deg": 0.5})
    (0.1, 0.5)
    """
    return float(raw.get("a3_accuracy_deg", DEFAULT_ACCURACY_DEG))


def warnings(estimates: pd.DataFrame, accuracy: float | None = None) -> list[str]:
    """One sentence per A3 row of ``estimates`` (estimates.csv rows) flagged for its scan bound
    (the ``flag`` column is ';'-separated; other flags are
    :func:`pipeline.north_finding.readings_checks.flag_notes`'); ``accuracy`` (deg) is named if
    given."""
    limit = "a3_accuracy_deg" if accuracy is None else f"a3_accuracy_deg = {accuracy:g} deg"
    notes = []
    flags = estimates["flag"].astype(object).where(estimates["flag"].notna(), "").astype(str)
    for i, r in estimates.iterrows():
        mine = [f for f in flags[i].split(";") if f in (FLAG_EXCEEDS, FLAG_UNKNOWN)]
        if not mine:
            continue
        if mine[0] == FLAG_EXCEEDS:
            notes.append(
                f"method A3 ({r['sensor']} sensor): the step of the peak scan allows an azimuth "
                f"error of up to {float(r['scan_bound_deg']):.3g} deg, above {limit}; scan the "
                "peak more finely"
            )
        else:
            notes.append(
                f"method A3 ({r['sensor']} sensor): fewer than 2 peak readings, so the error "
                "from not reading at the true maximum cannot be bounded"
            )
    return notes
