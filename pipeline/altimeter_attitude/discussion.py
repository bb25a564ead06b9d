"""The altimeter_attitude part of the report's discussion: what was easy (the linear model and
its filter), what was hard (the RMS values and the filters' consistency on a flight the paper
does not publish), what the paper left open. Every number is read from the results
(verdicts.csv, equation_audit.csv and the published scenario's rms_summary.csv)."""

from __future__ import annotations

import pandas as pd

from pipeline.altimeter_attitude.columns import RMS_SUMMARY_COLUMNS
from pipeline.report.discussion import Results, three_parts
from pipeline.report.model import Block, ReportInputs
from pipeline.report.vocabulary import word

__all__ = ["discussion"]


def _verdict(r: Results, prefix: str) -> str:
    rows = r.rows(prefix, "claim")
    return word(str(rows["verdict"].iloc[0])) if len(rows) else "not judged"


def _rms(inputs: ReportInputs, r: Results) -> str:
    """Ours against the published RMS values, per filter and angle."""
    scenario = str(inputs.settings.get("published_scenario", "paper"))
    path = inputs.results / scenario / "rms_summary.csv"
    if not path.is_file():
        return ""
    s = pd.read_csv(path)
    if not set(RMS_SUMMARY_COLUMNS) <= set(s.columns):
        return ""
    s = s.set_index("filter")
    parts, seen = [], set()
    for _, row in r.rows(kind="approximate").iterrows():
        f, q = str(row["method"]), str(row["quantity"])
        if (f, q) in seen:  # a value judged over several windows: once, over the flight
            continue
        seen.add((f, q))
        if f in s.index and q in s.columns:
            what = f"{r.names.words(q)} of the {r.names.words(f)}"
            parts.append(f"{what} {s.loc[f, q]:.2f} deg against {row['published']} deg")
    if not parts:
        return ""
    runs = int(s["n_runs"].max())
    return (
        f"Over the whole flight of our scenario ({runs} Monte Carlo runs) the RMS errors are "
        + "; ".join(parts)
        + ". "
    )


def discussion(inputs: ReportInputs) -> list[Block]:
    r = Results.read(inputs)
    easy = (
        "The linear model: with the third row of the DCM in the state, the attitude kinematics "
        "and the vertical channel are linear in the state, and the filter of eq. 31 with the "
        f"multiplicative-noise term follows from Appendix A; of the printed equations, "
        f"{r.equations()}. The normalisation claim is {_verdict(r, 'C5.')}, and accelerometer "
        f"levelling failing under acceleration is {_verdict(r, 'C6.')}."
    )
    hard = (
        _rms(inputs, r)
        + "The paper does not say how a curve is reduced to its number, nor over which part of "
        "the flight; roll becomes observable through the altimeter only when the vehicle banks, "
        "so the flight the paper does not publish decides the value. The comparison of the "
        f"filters is {_verdict(r, 'C1.')}, and their consistency with their own standard "
        f"deviations is {_verdict(r, 'C2.')} for the linear filter and {_verdict(r, 'C3.')} for "
        "the UKF."
    )
    left_open = (
        "The trajectory and its duration, the sample rates of the IMU and the altimeter, the "
        "gain k of the normalisation term, the initial state error and covariance, the tuning "
        "beyond the sensor sigmas, the UKF's parameters and noise handling, and how an RMS curve "
        "becomes one number; each is decided in a scenario file (the assumptions appendix)."
    )
    return three_parts(easy, hard, left_open)
