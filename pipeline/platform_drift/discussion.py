"""The platform_drift part of the report's discussion: what was easy (the level-gyro case and
the strapdown errors), what was hard (the azimuth-gyro case: eq. 36 against the full
simulation, and the crossover times of the moving scenarios), what the paper left open.
Every number is read from the results (verdicts.csv, equation_audit.csv and each scenario's
summary.csv)."""

from __future__ import annotations

import math

import pandas as pd

from pipeline.platform_drift.columns import DRIFT_SUMMARY_COLUMNS
from pipeline.report.discussion import Results, three_parts
from pipeline.report.model import Block, ReportInputs

__all__ = ["discussion"]


def _number(text: object) -> float | None:
    try:
        return float(str(text).split()[0])
    except (ValueError, IndexError):
        return None


def _ratios(rows: pd.DataFrame) -> str:
    """``lo-hi``: ours over published across rows where both are numbers."""
    ratios = []
    for pub, ours in zip(rows["published"], rows["reproduced"], strict=True):
        a, b = _number(pub), _number(ours)
        if a and b is not None and math.isfinite(b):
            ratios.append(b / a)
    if not ratios:
        return "no comparable values"
    return f"{min(ratios):.2f}-{max(ratios):.2f} times the printed values"


def _azimuth_case(inputs: ReportInputs) -> str:
    """The stationary azimuth-drift case from its summary.csv."""
    path = inputs.results / "stationary" / "summary.csv"
    if not path.is_file():
        return ""
    s = pd.read_csv(path)
    if not set(DRIFT_SUMMARY_COLUMNS) <= set(s.columns):
        return ""
    ch3 = s[s["case"] == "ch3"].set_index("scheme")
    need = {"proposed_analytic", "proposed_simulated", "strapdown"}
    if not need <= set(ch3.index):
        return ""
    bound = float(ch3.loc["proposed_analytic", "error_max_m"])
    simulated = float(ch3.loc["proposed_simulated", "error_2h_m"])
    strapdown = float(ch3.loc["strapdown", "error_2h_m"])
    return (
        f"On the stationary vehicle with an azimuth-gyro drift, eq. 36 keeps the proposed "
        f"scheme's error below {bound:.0f} m, but the full simulation of the same algorithm "
        f"reaches {simulated:.0f} m at 2 h, {simulated / strapdown:.2f} times the strapdown "
        f"error of {strapdown:.0f} m: the bound holds for the tilt-induced part eq. 36 models, "
        "not for the azimuth error the algorithm integrates. "
    )


def discussion(inputs: ReportInputs) -> list[Block]:
    r = Results.read(inputs)
    finals = r.verdicts[r.verdicts["quantity"] == "error_2h_m"]
    crossings = r.verdicts[r.verdicts["quantity"] == "crossover_s"]
    easy = (
        f"The level-gyro case: with a channel-1 drift {r.held(r.rows('C1.', 'claim'))} curves "
        "follow eq. 32 within the claim's tolerance, the same for both schemes; and "
        f"{r.held(finals)} strapdown errors at 2 h of Figs 5-8 are within the tolerance of a "
        f"value read off a plot ({_ratios(finals)}). Of the printed equations, {r.equations()}."
    )
    hard = (
        _azimuth_case(inputs)
        + f"The crossover times: {r.held(crossings)} printed crossovers are reproduced; "
        "on the moving vehicles the analytic curve of eq. 36 is a stationary result, and the "
        "simulated curves depend on trajectories the paper does not give."
    )
    left_open = (
        "The trajectories of the moving scenarios (only the total changes of latitude and "
        "longitude are given), the latitude of the stationary case, the loop gains of the "
        "platform, the strapdown comparator and its error metric, whether the azimuth error of "
        "the proposed algorithm counts, and the undefined drift of Table 2 no. 5; each is "
        "decided in a scenario file (the assumptions appendix)."
    )
    return three_parts(easy, hard, left_open)
