"""The numerical trouble of one scenario's estimators, as the report shows it: one sentence
when there was none, else the counts of every method and kind that met some
(``numerical_trouble.csv``, :mod:`pipeline.north_finding.trouble`)."""

from __future__ import annotations

from pathlib import Path

import pandas as pd

from pipeline.north_finding.trouble import TROUBLE_COLUMNS
from pipeline.report.model import Block, Paragraph, frame_table, not_available

__all__ = ["trouble_blocks"]

_WORDS = {
    "clipped_arcsine": "arcsine or arccosine argument clipped to [-1, 1]",
    "unreachable_root": "sinusoid equation beyond reach, right side clipped",
    "complex_roots": "quartic of eq. 50 without a real root, real parts used",
    "non_finite": "estimate NaN or infinite",
}
_RUNS = {
    "noise_free_real": "noise-free real run",
    "monte_carlo": "Monte Carlo",
    "readings": "the readings",
}


def trouble_blocks(path: Path) -> list[Block]:
    """Blocks for ``path`` (a numerical_trouble.csv); ``not available`` if it is absent."""
    if not path.is_file():
        return [not_available(path.name)]
    df = pd.read_csv(path)
    missing = [c for c in TROUBLE_COLUMNS if c not in df.columns]
    if missing:
        raise ValueError(f"{path}: missing columns {missing} (has {list(df.columns)})")
    runs = ", ".join(
        f"{_RUNS.get(r, r)} ({int(g['n_trials'].max())} trials)"
        for r, g in df.groupby("run", sort=False)
    )
    hit = df[df["n_affected"] > 0]
    if hit.empty:
        return [
            Paragraph(f"No numerical trouble in {runs}: no " + "; no ".join(_WORDS.values()) + ".")
        ]
    table = pd.DataFrame(
        {
            "run": hit["run"].map(lambda r: _RUNS.get(r, r)),
            "method": hit["method"],
            "trouble": hit["kind"].map(lambda k: _WORDS.get(k, k)),
            "trials affected": [
                f"{a} of {n}" for a, n in zip(hit["n_affected"], hit["n_trials"], strict=True)
            ],
        }
    )
    return [
        Paragraph(
            f"Numerical trouble in {runs}: the estimators returned a value in every trial below, "
            "but from a clipped argument (or a non-finite one); the Monte Carlo summaries "
            "include these trials."
        ),
        frame_table(table.reset_index(drop=True)),
    ]
