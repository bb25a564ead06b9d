"""The root causes of a paper's failing verdicts, grouped by their title (verdicts.csv
``cause``), for its summary sentence and its section's list of causes.

One title is one root cause: the rows it explains are counted once and named in the paper's
labels; its full text (``cause_detail``) is listed once per distinct text. Rows without a
cause form the last group, "cause not identified".

>>> v = pd.DataFrame({"id": ["T1.a", "T1.b", "C1/x"], "kind": ["exact", "exact", "claim"],
...     "method": ["M4", "M4", "M4"], "quantity": ["q", "q", "q"],
...     "cause_kind": ["unpublished", "unpublished", ""], "cause": ["run not given"] * 2 + [""],
...     "cause_detail": ["The run is not given (N = 3).", "The run is not given (N = 3).", ""]})
>>> lines = cause_lines(v, RowNames({"items": [{"id": "T1.a", "label": "Table 1"},
...     {"id": "T1.b", "label": "Table 2"}], "names": {"M4": "method 4"}}), list(v["id"]))
>>> [(c.title, c.rows, c.labels, c.details) for c in lines]
[('run not given', 2, 'Tables 1-2, method 4', ('The run is not given (N = 3).',)), ('', 1, 'the claim of the paper', ())]
>>> causes_sentence(lines)
'Causes, by rows explained: (1) run not given (unpublished, 2 rows); (2) cause not identified (1 row).'
"""

from __future__ import annotations

from collections.abc import Sequence

import pandas as pd

from pipeline.report.grouping import rows_phrase
from pipeline.report.model import Block, Bullets, CauseLine, Paragraph
from pipeline.report.names import RowNames
from pipeline.report.vocabulary import cause_short, cause_word

__all__ = ["cause_lines", "causes_blocks", "causes_sentence", "plural"]


def plural(n: int, one: str, many: str | None = None) -> str:
    """``"1 run"``, ``"2 runs"``."""
    return f"{n} {one if n == 1 else (many or one + 's')}"


def _column(frame: pd.DataFrame, name: str) -> pd.Series:
    if name not in frame.columns:
        return pd.Series("", index=frame.index)
    return frame[name].fillna("").astype(str).str.strip()


def cause_lines(failing: pd.DataFrame, names: RowNames, all_ids: Sequence[str]) -> list[CauseLine]:
    """One line per root cause (title and kind) of the ``failing`` rows, most rows first
    (ties in order of first appearance), the rows without a cause last."""
    titles, kinds = _column(failing, "cause"), _column(failing, "cause_kind")
    details = _column(failing, "cause_detail")
    groups: dict[tuple[str, str], list[int]] = {}
    for i in failing.index:
        key = (titles[i], kinds[i]) if titles[i] else ("", "")
        groups.setdefault(key, []).append(i)
    named = sorted(((k, v) for k, v in groups.items() if k[0]), key=lambda kv: -len(kv[1]))
    if ("", "") in groups:
        named.append((("", ""), groups[("", "")]))
    return [
        CauseLine(
            title,
            kind,
            len(rows),
            rows_phrase(failing.loc[rows], names, all_ids),
            tuple(dict.fromkeys(d for d in details[rows] if d)),
        )
        for (title, kind), rows in named
    ]


def causes_sentence(lines: Sequence[CauseLine]) -> str:
    """The third sentence of a paper's summary: the causes by the rows they explain, each
    with its kind in words (numbered as the groups of the second sentence)."""
    if not lines:
        return "Cause: none to give, as nothing checked failed."
    if len(lines) == 1 and not lines[0].title:
        n = lines[0].rows
        return f"Cause: not identified for {'the' if n == 1 else 'any of the'} {plural(n, 'row')}."
    numbered = len(lines) > 1
    parts = []
    for k, c in enumerate(lines, 1):
        head = f"({k}) " if numbered else ""
        if c.title:
            parts.append(f"{head}{c.title} ({cause_short(c.kind)}, {plural(c.rows, 'row')})")
        else:
            parts.append(f"{head}cause not identified ({plural(c.rows, 'row')})")
    lead = "Causes, by rows explained: " if numbered else "Cause: "
    return lead + "; ".join(parts) + "."


def causes_blocks(lines: Sequence[CauseLine]) -> list[Block]:
    """The paper's causes, listed once: title, kind, the rows it explains, its full text."""
    if not lines:
        return []
    items = []
    for c in lines:
        rows = f"{plural(c.rows, 'row')}: {c.labels}"
        if c.title:
            text = " ".join(d.rstrip(".") + "." for d in c.details)
            items.append(f"{c.title[0].upper()}{c.title[1:]} ({cause_word(c.kind)}; {rows})."
                         + (f" {text}" if text else ""))  # fmt: skip
        else:
            items.append(f"Cause not identified ({rows}).")
    return [Paragraph("Causes of the verdicts not reproduced or not upheld, by rows explained:"),
            Bullets(items)]  # fmt: skip
