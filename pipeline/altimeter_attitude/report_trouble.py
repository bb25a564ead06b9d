"""The numerical trouble of the altimeter-attitude filters as the report shows it: one sentence
when there was none, else a note and the runs of every filter and kind that met some
(``numerical_trouble.csv``, ``sweep_trouble.csv``; :mod:`pipeline.altimeter_attitude.trouble`,
layout :mod:`pipeline.report.trouble`)."""

from __future__ import annotations

from pathlib import Path

from pipeline.altimeter_attitude.trouble import DIVERGED_DEG
from pipeline.report.model import Block
from pipeline.report.trouble import trouble_blocks

__all__ = ["filter_trouble_blocks"]

_WORDS = {
    "non_finite": "roll or pitch estimate NaN or infinite",
    "diverged": f"attitude error beyond {DIVERGED_DEG:g} deg",
    "sigma_not_positive": "filter sigma zero, negative or not finite",
}
_RUNS = {"monte_carlo": "Monte Carlo", "noise_free": "noise-free run", "sweep": "the sweep"}
_AFTER = (
    "These runs are kept in the summaries: a non-finite run makes that filter's RMS "
    "non-finite rather than being left out."
)


def filter_trouble_blocks(path: Path) -> list[Block]:
    """Blocks for ``path`` (a numerical_trouble.csv or sweep_trouble.csv)."""
    return trouble_blocks(path, _WORDS, _RUNS, unit="runs", after=_AFTER)
