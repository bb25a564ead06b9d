"""The numerical trouble of one scenario's estimators, as the report shows it: one sentence
when there was none, else a note and the counts of every run, method and kind that met some
(``numerical_trouble.csv`` and the N inference's ``n_trouble.csv``,
:mod:`pipeline.north_finding.trouble`; the shared layout is :mod:`pipeline.report.trouble`)."""

from __future__ import annotations

from pathlib import Path

from pipeline.report.model import Block
from pipeline.report.trouble import trouble_blocks as shared_blocks

__all__ = ["trouble_blocks"]

_WORDS = {
    "clipped_arcsine": "arcsine or arccosine argument clipped to [-1, 1]",
    "unreachable_root": "sinusoid equation beyond reach (right side clipped)",
    "complex_roots": "polynomial without a real root (eq. 50: real parts used; eq. 65: none)",
    "non_finite": "NaN or infinite estimate",
}
_RUNS = {
    "noise_free_real": "noise-free real run",
    "monte_carlo": "Monte Carlo",
    "readings": "the readings",
    "sensitivity": "sensitivity Monte Carlo",
    "ranking": "ranking Monte Carlo",
    "n_inference": "N inference Monte Carlo",
    "a2_scan": "method A2 noise-free at every whole-degree table angle",
}
_AFTER = (
    "The estimators returned a value in every trial counted here, from a clipped argument (or "
    "a non-finite one); the summaries include the clipped trials and leave out the non-finite "
    "ones, and their trial counts say how many they used."
)


def trouble_blocks(path: Path) -> list[Block]:
    """Blocks for ``path`` (a numerical_trouble.csv or n_trouble.csv); ``not available`` if
    it is absent."""
    return shared_blocks(path, _WORDS, _RUNS, after=_AFTER)
