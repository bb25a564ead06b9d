"""The numerical trouble of the altimeter-attitude filters as the report shows it: one sentence
when there was none, else a note and the runs of every filter and kind that met some
(``numerical_trouble.csv``, ``sweep_trouble.csv``; :mod:`pipeline.altimeter_attitude.trouble`,
layout :mod:`pipeline.report.trouble`)."""

from __future__ import annotations

from pathlib import Path

from pipeline.altimeter_attitude.trouble import DIVERGED_DEG
from pipeline.report.model import Block, not_available
from pipeline.report.trouble import read_trouble, trouble_frame_blocks

__all__ = ["filter_trouble_blocks"]

_WORDS = {
    "non_finite": "NaN or infinite roll or pitch estimate",
    "diverged": f"roll or pitch error beyond {DIVERGED_DEG:g} deg at some time",
    "sigma_not_positive": "zero, negative or non-finite filter sigma",
}
_RUNS = {"monte_carlo": "Monte Carlo", "noise_free": "noise-free run", "sweep": "the sweep"}
_AFTER = (
    "These runs are kept in the summaries: a non-finite run makes that filter's RMS "
    "non-finite rather than being left out."
)
_LEVELLING = (
    " Accelerometer levelling has no memory: under acceleration its error is the tilt of the "
    "apparent vertical at that instant, not a divergence."
)


def filter_trouble_blocks(path: Path) -> list[Block]:
    """Blocks for ``path`` (a numerical_trouble.csv or sweep_trouble.csv); ``not available``
    if it is absent."""
    df = read_trouble(path)
    if df is None:
        return [not_available("numerical trouble counts")]
    levelling = (
        (df["method"] == "accel_leveling") & (df["kind"] == "diverged") & (df["n_affected"] > 0)
    ).any()
    after = _AFTER + (_LEVELLING if levelling else "")
    return trouble_frame_blocks(df, _WORDS, _RUNS, unit="runs", after=after)
