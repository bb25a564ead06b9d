"""The maneuver windows of a scenario: where the truth load factor ``n = |f|/g`` is off 1 by
more than :data:`LOAD_DEVIATION` (accelerometer levelling assumes n = 1).

>>> import pandas as pd
>>> truth = pd.DataFrame({"t_s": [0.0, 1.0, 2.0, 3.0, 4.0], "load_factor": [1, 1.2, 1.3, 1, 0.9]})
>>> maneuver_intervals(truth)
[(1.0, 2.0), (4.0, 4.0)]
"""

from __future__ import annotations

from collections.abc import Sequence

import numpy as np
import pandas as pd

from pipeline.altimeter_attitude.result_frames import require_columns

__all__ = ["LOAD_DEVIATION", "Maneuvers", "maneuver_intervals"]

# maneuvers are where the truth load factor |f|/g is off 1 by more than this (the same
# threshold as claim C6 of config/published/altimeter_attitude.yaml)
LOAD_DEVIATION = 0.05
#: maneuver windows (t_start, t_end) in s, as the figures shade them
Maneuvers = Sequence[tuple[float, float]]


def maneuver_intervals(
    truth: pd.DataFrame, threshold: float = LOAD_DEVIATION
) -> list[tuple[float, float]]:
    """Time intervals (t_start, t_end) where |load_factor - 1| > threshold."""
    require_columns(truth, ["t_s", "load_factor"], "truth")
    frame = truth.sort_values("t_s", kind="stable")
    t = frame["t_s"].to_numpy(float)
    flag = np.abs(frame["load_factor"].to_numpy(float) - 1.0) > threshold
    edges = np.diff(np.concatenate([[0], flag.astype(np.int8), [0]]))
    starts, ends = np.flatnonzero(edges == 1), np.flatnonzero(edges == -1) - 1
    return [(float(t[a]), float(t[b])) for a, b in zip(starts, ends, strict=True)]
