"""What every filter returns: roll/pitch estimates and (where it has one) their sigma."""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

__all__ = ["Estimates"]


@dataclass(frozen=True)
class Estimates:
    """Estimates at the state times t_k, k = 0..T, for N runs (arrays (N, T + 1)).

    ``roll_sigma``/``pitch_sigma`` are NaN for a filter without a covariance; ``c`` (N, T+1, 3)
    is the estimated third DCM row (for the c-based filters; else computed from the angles);
    ``norm_error`` is 1 - c^T c of the filter's own c (0 for the angle-based filters).
    """

    filter: str
    roll: np.ndarray
    pitch: np.ndarray
    roll_sigma: np.ndarray
    pitch_sigma: np.ndarray
    c: np.ndarray
    norm_error: np.ndarray
