"""How the sensor errors propagate into the north_finding estimates, from its results: which
published real-sensor values the noise-free propagation of the sensor errors reproduces, and
the azimuth error budget of each method (one error source at a time). The page's "Findings
beyond the paper" are written from these.
"""

from __future__ import annotations

import pandas as pd

from pipeline.north_finding.columns import AZIMUTH_METHODS

__all__ = ["azimuth_error_budget", "noise_free_agreement"]


def noise_free_agreement(verdicts: pd.DataFrame) -> tuple[list[str], int]:
    """``(ids, n)``: the statistical verdicts whose note says the noise-free real-sensor value
    equals the published one (to its last printed digit), and how many statistical verdicts
    there are."""
    from pipeline.verdicts import NOISE_FREE_AGREES

    stat = verdicts[verdicts["kind"] == "statistical"]
    agree = stat[stat["note"].str.contains(NOISE_FREE_AGREES, regex=False)]
    return list(agree["id"]), len(stat)


def azimuth_error_budget(budget: pd.DataFrame) -> pd.DataFrame:
    """Azimuth error (deg) per azimuth method (rows, in method order) and error source
    (columns) from ``error_budget.csv``."""
    psi = budget[budget["quantity"] == "psi_deg"].pivot_table(
        index="method", columns="source", values="error", aggfunc="first"
    )
    return psi.reindex([m for m in AZIMUTH_METHODS if m in psi.index])
