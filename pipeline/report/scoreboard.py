"""The scoreboard: one row per paper, counted from its ``equation_audit.csv`` and
``verdicts.csv``, with its first-page summary (:mod:`pipeline.report.summary`).

>>> counts(["match", "differs", "match"], ("match", "differs", "not_checkable"))
{'match': 2, 'differs': 1, 'not_checkable': 0}
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import pandas as pd

from pipeline.report.model import ScoreRow
from pipeline.report.summary import paper_summary, plural, self_checks
from pipeline.report.vocabulary import DIFFERS_WORDS

__all__ = [
    "AUDIT_WORDS",
    "CLAIM_WORDS",
    "NUMBER_WORDS",
    "SELF_CHECK_WORDS",
    "counts",
    "differs_by_kind",
    "plural",
    "score_row",
]

#: Status and verdict words counted on the scoreboard (every word shown, zeros included).
AUDIT_WORDS = ("match", "differs", "not_checkable")
NUMBER_WORDS = ("reproduced", "consistent", "not_reproduced", "not_checkable")
CLAIM_WORDS = ("upheld", "not_upheld", "not_checkable")
#: the verdicts of self-checks (rows the published file marks ``self_check``), counted apart
SELF_CHECK_WORDS = ("reproduced", "not_reproduced")


def counts(values: Sequence[str] | pd.Series, words: Sequence[str]) -> dict[str, int]:
    """How often each of ``words`` occurs in ``values`` (zeros included, in that order);
    any other word found is appended (a producer bug, shown rather than hidden)."""
    out = {w: 0 for w in words}
    for v in values:
        out[str(v)] = out.get(str(v), 0) + 1
    return out


def differs_by_kind(audit: pd.DataFrame) -> dict[str, int]:
    """The differing equations by their ``kind`` (every known kind, zeros included; ``""``:
    not classified, also when the audit has no ``kind`` column)."""
    differs = audit[audit["status"] == "differs"]
    kinds = (
        differs["kind"].astype(str)
        if "kind" in differs.columns
        else pd.Series("", index=differs.index)
    )
    out = {k: 0 for k in DIFFERS_WORDS} | {"": 0}
    for k in kinds:
        out[k.strip()] = out.get(k.strip(), 0) + 1
    return out


def score_row(
    slug: str,
    title: str,
    audit: pd.DataFrame,
    verdicts: pd.DataFrame,
    published: Mapping[str, Any] | None = None,
    source: str = "",
) -> ScoreRow:
    """The scoreboard row of one paper, counted from its audit and verdict tables, with its
    summary (``published``: its published-values file, parsed; ``source`` names it)."""
    checks = self_checks(verdicts, published or {})
    numbers = verdicts[(verdicts["kind"] != "claim") & ~checks]
    claims = verdicts[verdicts["kind"] == "claim"]
    summary = paper_summary(verdicts, audit, published or {}, source or f"{slug} published values")
    return ScoreRow(
        slug=slug,
        title=title,
        audit=counts(audit["status"], AUDIT_WORDS),
        numbers=counts(numbers["verdict"], NUMBER_WORDS),
        claims=counts(claims["verdict"], CLAIM_WORDS),
        self_checks=counts(verdicts[checks]["verdict"], SELF_CHECK_WORDS),
        line=f"{summary.status}: {summary.sentences[0]}",
        anchor=slug,
        summary=summary,
        differs=differs_by_kind(audit),
    )
