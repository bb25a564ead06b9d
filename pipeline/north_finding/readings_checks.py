"""Checks of an estimate from a user's readings: flags for estimates.csv and warning sentences.

A readings run (a ``type: readings`` scenario or ``inertial-repro north-finding estimate``) has
one trial and no truth, so nothing downstream can tell a good estimate from a bad one. These
checks say when an estimate is not to be trusted, computed from the readings themselves:

``a3_peak_unreachable``
    Method A3 (eqs. 44-52) reads the x gyro's largest value over tau and solves eq. 47 for the
    psi whose ideal peak ``R(psi) = Omega sqrt(X^2 + Y^2)`` (eq. 45) equals it. At a given
    latitude, roll and pitch, R(psi) spans ``[R_min, R_max]`` over psi; a peak reading outside
    that range has no solution (the quartic of eq. 50 has no real root in [-1, 1]). A gyro
    bias b adds to every reading, so the peak of a biased gyro is ``R + b``: b > R_max - R(psi)
    already puts it out of reach. The estimator then uses the real parts of the complex roots,
    do not follow the reading: on the paper's attitude (roll 50, pitch 30 deg, latitude 35 deg)
    every peak above 1.3 R_max gives psi = 168.54 deg or 0 deg, whichever the compass is
    nearer, whatever the true azimuth. Method A4 estimates the bias and is not affected.
``compass_disagrees``
    An azimuth estimate farther than the compass tolerance from the coarse compass heading. The
    compass only selects among each method's roots (two for A1, A2, A4, A5; up to four for
    A3); with a compass that far off the other root may be the right one (a compass 176 deg off
    makes A4 pick the mirror root). Readings that do not fit a method's model are caught too:
    a gyro bias of 10 deg/h moves A2 by about 50 deg (A1, A2 and A3 have no bias term; A4 and
    A5 estimate it).
``a4_scale_implausible``
    Method A4's gyro scale S (eq. 60, from the root the compass chose) with ``|S - 1| >``
    :data:`MAX_SCALE_ERROR`: no gyro is that far off its nominal scale, so the compass chose the
    wrong root even though it is near it (the example file's compass at 41 deg instead of 225
    gives A4 psi = 33 deg, S = -0.57). On every A4 row.
numerical trouble (:mod:`pipeline.north_finding.trouble`)
    ``clipped_arcsine``, ``unreachable_root``, ``complex_roots`` (A5), ``non_finite``: the
    method met trouble, its estimate is a clipped or NaN value; the kind is the flag.

>>> r_lo, r_hi = a3_peak_range(7.292115e-5, np.deg2rad(35.0), np.deg2rad(30.0), np.deg2rad(50.0))
>>> round(r_lo * 1e6, 3), round(r_hi * 1e6, 3)  # rad/s * 1e6: R_max is Omega at this attitude
(1.494, 72.921)
>>> compass_flag(305.0, 129.0, 30.0), compass_flag(224.0, 220.0, 30.0)
('compass_disagrees', '')
"""

from __future__ import annotations

import numpy as np
import pandas as pd

from pipeline.generated import north_finding as gen
from pipeline.north_finding.readings import Readings
from pipeline.north_finding.trouble import TROUBLE_KINDS

__all__ = [
    "FLAG_PEAK_UNREACHABLE",
    "FLAG_COMPASS",
    "FLAG_SCALE",
    "MAX_SCALE_ERROR",
    "DEFAULT_COMPASS_TOLERANCE_DEG",
    "a3_peak_range",
    "a3_peak_note",
    "compass_flag",
    "add_flags",
    "flag_notes",
]

FLAG_PEAK_UNREACHABLE = "a3_peak_unreachable"
FLAG_COMPASS = "compass_disagrees"
#: default compass tolerance (deg): a magnetic compass beside a turntable, with the local
#: declination applied, is good to a few degrees; 30 deg is far beyond that yet below the
#: smallest root separation that still lets the compass choose reliably (60 deg apart)
DEFAULT_COMPASS_TOLERANCE_DEG = 30.0
#: psi grid (deg) on which R(psi) of eq. 45 is evaluated for its range
_PSI_GRID_DEG = np.arange(0.0, 360.0, 0.01)
RAD_S_TO_DEG_H = 180.0 / np.pi * 3600.0
FLAG_SCALE = "a4_scale_implausible"
#: the largest |S - 1| of a gyro scale taken as plausible (10 %; tactical and MEMS gyros are
#: specified to well under 1 %)
MAX_SCALE_ERROR = 0.1


def a3_peak_range(omega_ie: float, lat: float, theta: float, phi: float) -> tuple[float, float]:
    """Smallest and largest ideal x-gyro peak ``R(psi)`` (eq. 45, rad/s) over psi, at the given
    latitude, pitch and roll (rad): the readings method A3 can turn into an azimuth."""
    _, r = gen.a3_peak(omega_ie, lat, np.deg2rad(_PSI_GRID_DEG), theta, phi)
    return float(r.min()), float(r.max())


def a3_peak_note(readings: Readings, omega_ie: float, lat: float, theta: float, phi: float) -> str:
    """The warning sentence of an A3 estimate whose peak reading is out of reach (trial 0)."""
    w_max = float(readings.gyro[0, readings.columns("x", "peak")].max())
    r_lo, r_hi = a3_peak_range(omega_ie, lat, theta, phi)
    if w_max > r_hi:
        where = f"above the largest value eq. 45 allows, {r_hi:.6g} rad/s, by"
        excess = w_max - r_hi
    else:
        where = f"below the smallest value eq. 45 allows, {r_lo:.6g} rad/s, by"
        excess = r_lo - w_max
    return (
        f"method A3: the peak gyro reading {w_max:.6g} rad/s is {where} {excess:.3g} rad/s "
        f"({excess * RAD_S_TO_DEG_H:.3g} deg/h) at this latitude, roll and pitch: eq. 47 has no "
        "solution, so its psi does not depend on the readings and is flagged "
        f"{FLAG_PEAK_UNREACHABLE}; a gyro bias of at least that size does this (method A4 "
        "estimates the bias)"
    )


def compass_flag(estimate_deg: float, compass_deg: float, tolerance_deg: float) -> str:
    """``compass_disagrees`` when ``estimate_deg`` is farther than ``tolerance_deg`` from the
    compass heading (circular distance), else ''; NaN estimates are not flagged here (they are
    counted as ``non_finite``)."""
    d = abs((float(estimate_deg) - float(compass_deg) + 180.0) % 360.0 - 180.0)
    return FLAG_COMPASS if np.isfinite(d) and d > tolerance_deg else ""


def _join(*flags: str) -> str:
    return ";".join(dict.fromkeys(f for part in flags for f in part.split(";") if f))


def add_flags(
    estimates: pd.DataFrame,
    trouble: pd.DataFrame,
    compass_deg: float,
    tolerance_deg: float,
) -> pd.DataFrame:
    """``estimates`` (estimates.csv rows of one run) with the checks' flags joined into the
    ``flag`` column (';'-separated): the numerical trouble of each method (``trouble``, rows of
    numerical_trouble.csv; A3's complex roots as ``a3_peak_unreachable``) on every row of that
    method, and ``compass_disagrees`` on the psi rows."""
    out = estimates.copy()
    hit = trouble[trouble["n_affected"] > 0]
    by_method: dict[str, list[str]] = {}
    for m, kind in zip(hit["method"], hit["kind"], strict=True):
        name = FLAG_PEAK_UNREACHABLE if (m, kind) == ("A3", "complex_roots") else kind
        by_method.setdefault(m, []).append(name)
    a4_scale = out.loc[(out["method"] == "A4") & (out["quantity"] == "gyro_scale"), "estimate"]
    if a4_scale.size and abs(float(a4_scale.iloc[0]) - 1.0) > MAX_SCALE_ERROR:
        by_method.setdefault("A4", []).append(FLAG_SCALE)
    flags = []
    for m, q, value, old in zip(
        out["method"], out["quantity"], out["estimate"], out["flag"].fillna(""), strict=True
    ):
        extra = by_method.get(m, [])
        compass = compass_flag(value, compass_deg, tolerance_deg) if q == "psi_deg" else ""
        flags.append(_join(str(old), *extra, compass))
    out["flag"] = flags
    return out


_KIND_WORDS = {
    "clipped_arcsine": "an arcsine or arccosine argument outside [-1, 1] was clipped (the angle "
    "is exactly +-90 or 0/180 deg): a reading larger than the model allows (|f| > g, or a gyro "
    "difference above Earth rate)",
    "unreachable_root": "a sin(psi) + b cos(psi) = c had |c| > sqrt(a^2 + b^2); c was clipped to "
    "the reachable range (the double root is used)",
    "complex_roots": "its quadratic (eq. 65) has no real root: scale and azimuth are NaN",
    "non_finite": "an estimate is NaN or infinite",
}
assert set(_KIND_WORDS) == set(TROUBLE_KINDS)


def flag_notes(
    estimates: pd.DataFrame, compass_deg: float | None = None, tolerance_deg: float | None = None
) -> list[str]:
    """One sentence per (method, flag) of ``estimates`` for the checks' flags (the scan-bound
    flags have their own sentences, :func:`pipeline.north_finding.scan_bound.warnings`); the
    compass heading and tolerance (deg) are named if given (the report has neither)."""
    notes = []
    seen: set[tuple[str, str]] = set()
    for m, q, value, flags in zip(
        estimates["method"],
        estimates["quantity"],
        estimates["estimate"],
        estimates["flag"].astype(object).where(estimates["flag"].notna(), ""),
        strict=True,
    ):
        for f in str(flags).split(";"):
            if (m, f) in seen or not f:
                continue
            seen.add((m, f))
            if f == FLAG_COMPASS and q == "psi_deg":
                far = "the compass tolerance" if tolerance_deg is None else f"{tolerance_deg:g} deg"
                heading = "" if compass_deg is None else f" {compass_deg:g} deg"
                notes.append(
                    f"method {m}: psi = {float(value):.4g} deg is more than {far} from the "
                    f"compass heading{heading} (flagged {FLAG_COMPASS}): either the compass "
                    "is that far off and chose the wrong root (check the heading and the "
                    "tolerance), or the readings do not fit the method's model (a gyro bias "
                    "moves A1, A2 and A3; A4 and A5 estimate it)"
                )
            elif f == FLAG_SCALE:
                scale = estimates.loc[
                    (estimates["method"] == "A4") & (estimates["quantity"] == "gyro_scale"),
                    "estimate",
                ]
                notes.append(
                    f"method A4: its gyro scale S = {float(scale.iloc[0]):.4g} is more than "
                    f"{MAX_SCALE_ERROR:g} from 1 (flagged {FLAG_SCALE}): the compass most likely "
                    "chose the wrong root of eq. 59 (check the heading)"
                )
            elif f in _KIND_WORDS:
                notes.append(f"method {m}: numerical trouble {f}: {_KIND_WORDS[f]}")
            elif f == FLAG_PEAK_UNREACHABLE:
                notes.append(
                    f"method A3: the peak reading is outside the range eq. 45 reaches (flagged "
                    f"{FLAG_PEAK_UNREACHABLE}): its psi does not depend on the readings"
                )
    return notes
