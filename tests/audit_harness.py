"""Shared check of the per-paper audit tests: the kind of every differing equation follows the
one rule (``derivations.discrepancies``), and its note opens with the kind's evidence."""

from __future__ import annotations

from collections.abc import Sequence

import pandas as pd

from derivations.discrepancies import inconsistencies

# the words a judgement opens with, by kind: the evidence for the kind comes first
OPENERS = {
    "paper_error": ("error of the paper: ",),
    "text_artefact": ("artefact of the text: ",),
    "unclear_from_text": ("cannot tell from the text: ",),
    "convention": ("approximation of the paper: ", "notation of ", "sign convention "),
}


def assert_kinds_follow_the_rule(frame: pd.DataFrame, records: Sequence[dict]) -> None:
    """One rule for every paper: the kind of a difference is the one its discrepancy gives,
    the same discrepancy never has two kinds, and the note opens with the kind's evidence."""
    differs = frame[frame["status"] == "differs"]
    by_eq = {r["equation"]: r for r in records if r["status"] == "differs"}
    assert set(by_eq) == set(differs["equation"])
    rows = [
        (e, by_eq[e]["discrepancy"], k)
        for e, k in zip(differs["equation"], differs["kind"], strict=True)
    ]
    assert inconsistencies(rows) == []
    for _, row in differs.iterrows():
        assert row["note"].startswith(OPENERS[row["kind"]]), row["equation"]
