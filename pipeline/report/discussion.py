"""What a paper's discussion module (``Paper.discussion``) builds on: its verdicts, audit and
published values read once, counts over them, and the three parts of a discussion (what was
easy, what was hard, what the paper left open) as report blocks. Nothing here names a paper.
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from typing import Any

import pandas as pd

from pipeline.columns import AUDIT_COLUMNS, VERDICT_COLUMNS
from pipeline.report.model import Block, Paragraph, ReportInputs
from pipeline.report.names import RowNames
from pipeline.report.paper_parts import AUDIT_OPTIONAL, VERDICT_OPTIONAL, read_results_csv
from pipeline.report.published import load_published
from pipeline.report.vocabulary import DIFFERS_WORDS, differs_word
from pipeline.verdicts.main_claims import PASSING

__all__ = ["Results", "three_parts"]


@dataclass(frozen=True)
class Results:
    """A paper's verdicts, audit and published values (see :meth:`read`)."""

    verdicts: pd.DataFrame
    audit: pd.DataFrame
    published: Mapping[str, Any]

    @classmethod
    def read(cls, inputs: ReportInputs) -> Results:
        return cls(
            read_results_csv(inputs.results / "verdicts.csv", VERDICT_COLUMNS, VERDICT_OPTIONAL),
            read_results_csv(inputs.results / "equation_audit.csv", AUDIT_COLUMNS, AUDIT_OPTIONAL),
            load_published(inputs.published),
        )

    @property
    def names(self) -> RowNames:
        return RowNames(self.published)

    def rows(self, prefix: str = "", kind: str | None = None) -> pd.DataFrame:
        """The verdict rows whose id starts with ``prefix`` (and of ``kind``)."""
        v = self.verdicts[self.verdicts["id"].astype(str).str.startswith(prefix)]
        return v if kind is None else v[v["kind"] == kind]

    @staticmethod
    def held(rows: pd.DataFrame) -> str:
        """``"k of n"``: how many of ``rows`` are reproduced, consistent or upheld."""
        return f"{int(rows['verdict'].isin(PASSING).sum())} of {len(rows)}"

    def equations(self) -> str:
        """How the printed equations compare, in words ("60 of 92 match the derivation as
        printed and 18 differ (...)")."""
        a = self.audit
        n_match = int((a["status"] == "match").sum())
        differs = a[a["status"] == "differs"]
        kinds = differs["kind"] if "kind" in differs.columns else pd.Series("", index=differs.index)
        parts = [
            f"{int((kinds == k).sum())} {w}" for k, w in DIFFERS_WORDS.items() if (kinds == k).any()
        ]
        unclassified = int((~kinds.isin(list(DIFFERS_WORDS))).sum())
        if unclassified == len(differs):
            parts = ["not classified yet"]
        elif unclassified:
            parts.append(f"{unclassified} {differs_word('')}")
        text = f"{n_match} of {len(a)} match the derivation as printed"
        if len(differs):
            text += f" and {len(differs)} differ ({', '.join(parts)})"
        return text

    def unchecked_claims(self) -> list[str]:
        """The claims that cannot be checked, in the paper's words."""
        names = RowNames(self.published)
        out = []
        for _, r in self.verdicts[
            (self.verdicts["kind"] == "claim") & (self.verdicts["verdict"] == "not_checkable")
        ].iterrows():
            out.append(names.claim(r, whole="/" not in str(r["id"])))
        return out


def three_parts(easy: str, hard: str, left_open: str, extra: Sequence[Block] = ()) -> list[Block]:
    """The discussion of a paper: what was easy, what was hard, what the paper left open."""
    return [
        Paragraph(f"What was easy. {easy}"),
        Paragraph(f"What was hard. {hard}"),
        Paragraph(f"What the paper left open. {left_open}"),
        *extra,
    ]
