"""NEES consistency of one filter and angle: inside the chi-square band, over- or under-confident.

The NEES at a time is the mean over the n runs of e^2 / sigma^2 of one angle; for a consistent
filter n times it is chi-square with n degrees of freedom, so it lies in the two-sided band
chi2(p, n) / n (:func:`pipeline.altimeter_attitude.metrics.nees_bounds`) with probability p.
Above the band the filter's sigma is too small for its errors (over-confident), below it too
large (under-confident). The flight mean uses the same band (the times are correlated, so n
runs is the conservative number of samples).

A filter and angle are consistent when the flight-mean NEES lies in the band and the NEES at
the times after the transient lies outside it for at most ``max_outside`` of them; otherwise
the direction is that of the flight mean when it is outside the band, else that of the larger
share of times outside it.

>>> classify(1.0, 0.02, 0.03, (0.74, 1.3), 0.10)
'consistent'
>>> classify(0.87, 0.0, 0.25, (0.74, 1.3), 0.10), classify(1.2, 0.12, 0.02, (0.74, 1.3), 0.10)
('under-confident', 'over-confident')
>>> classify(1.5, 0.0, 0.0, (0.74, 1.3), 0.10)
'over-confident'
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from pipeline.altimeter_attitude.metrics import nees_bounds

__all__ = ["CONSISTENT", "DIRECTIONS", "NeesCheck", "classify", "nees_check"]

CONSISTENT = "consistent"
#: direction -> what it means for the filter's sigma
DIRECTIONS = {"over-confident": "sigma too small", "under-confident": "sigma too large"}


def classify(
    mean: float, above: float, below: float, band: tuple[float, float], max_outside: float
) -> str:
    """``consistent``, ``over-confident`` or ``under-confident`` (see the module)."""
    lo, hi = band
    if lo <= mean <= hi and above + below <= max_outside:
        return CONSISTENT
    if mean > hi:
        return "over-confident"
    if mean < lo:
        return "under-confident"
    return "over-confident" if above > below else "under-confident"


@dataclass(frozen=True)
class NeesCheck:
    """The NEES of one filter and angle against its band (fractions of the times after the
    transient; ``*_level``: of those outside the band, the share with true |roll| below the
    bank that opens the window after the first bank; ``after_bank_mean``: mean NEES of the window after the first bank
    window, NaN without one)."""

    filter: str
    angle: str
    n_runs: int
    p: float
    band: tuple[float, float]
    mean: float
    above: float
    below: float
    n_times: int
    direction: str
    peak: float
    peak_t: float
    above_level: float
    below_level: float
    after_bank_mean: float

    @property
    def ok(self) -> bool:
        return self.direction == CONSISTENT


def nees_check(res, filt: str, angle: str, p: float, max_outside: float) -> NeesCheck:
    """The :class:`NeesCheck` of a filter and angle on :class:`ScenarioResults` ``res``."""
    n = int(res.summary.loc[filt, "n_runs"])
    band = nees_bounds(n, p=p)
    mean = float(res.summary.loc[filt, f"nees_{angle}"])
    curve = res.curve(filt, f"nees_{angle}")
    curve = curve[curve.index >= res.transient]
    values = curve.to_numpy(float)
    above_mask, below_mask = values > band[1], values < band[0]
    level = np.abs(res.true_roll_deg.reindex(curve.index.round(9)).to_numpy()) < res.bank_deg

    def share(mask: np.ndarray) -> float:
        return float(np.mean(level[mask])) if mask.any() else float("nan")

    i = int(np.nanargmax(values)) if len(values) else 0
    after = res.window(filt, "after_bank")
    above, below = float(np.mean(above_mask)), float(np.mean(below_mask))
    return NeesCheck(
        filter=filt,
        angle=angle,
        n_runs=n,
        p=p,
        band=band,
        mean=mean,
        above=above,
        below=below,
        n_times=len(values),
        direction=classify(mean, above, below, band, max_outside),
        peak=float(values[i]) if len(values) else float("nan"),
        peak_t=float(curve.index[i]) if len(values) else float("nan"),
        above_level=share(above_mask),
        below_level=share(below_mask),
        after_bank_mean=float(after[f"nees_{angle}"]),
    )
