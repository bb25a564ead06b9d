"""The equation audit of a paper in the reports: in the main text, one short statement per
printed equation that differs from the derivation (with its kind: an error of the paper, an
artefact of the text, or an approximation or convention the paper chose); in the appendix,
the :class:`EquationTable` with the printed, derived and residual forms
(``equation_audit.csv``, its optional ``kind`` column, and ``equation_math.json``).

>>> equation_list(["1", "2", "3"]), equation_list(["9", "17"])
('1–3', '9, 17')
>>> short_statement("typo of the paper: the rows drop sin(phi) (-cos t sin th); the product "
...                 "follows")
'typo of the paper: the rows drop sin(phi) (-cos t sin th)'
>>> short_statement("the rows of H must carry g, as in eq. 20. The pipeline uses H")
'the rows of H must carry g, as in eq. 20'
"""

from __future__ import annotations

import json
import re
from collections.abc import Iterator, Mapping, Sequence
from pathlib import Path
from typing import Any

import pandas as pd

from pipeline.report.model import Bullets, EquationRow, EquationTable, Paragraph, Section
from pipeline.report.vocabulary import DIFFERS_WORDS, differs_word

__all__ = [
    "differs_counts",
    "equation_appendix",
    "equation_groups",
    "equation_list",
    "equation_rows",
    "equation_section",
    "formless",
    "read_math",
    "short_statement",
]

#: the longest short statement of a differing equation (the full note is in the appendix)
STATEMENT_CHARS = 240
#: a full stop that ends an abbreviation, not a sentence
_ABBREVIATION = re.compile(r"(?:\b(?:eqs?|Eqs?|Figs?|Sec|Secs|no|cf|vs|approx)|\be\.g|\bi\.e)\.$")


def formless(row: EquationRow) -> bool:
    """An audit row with nothing to typeset (no printed, derived or residual form)."""
    return not (row.printed_srepr or row.derived_srepr or row.residual_srepr) and (
        not row.residual_text or row.status == "match"
    )


def equation_groups(rows: Sequence[EquationRow]) -> Iterator[list[EquationRow]]:
    """The audit rows, consecutive rows with no forms and the same status and note grouped
    (eqs. 1-11 of a paper, all "not in the seed text", become one group)."""
    group: list[EquationRow] = []
    for row in rows:
        if (
            group
            and formless(row)
            and formless(group[-1])
            and (row.status, row.note) == (group[-1].status, group[-1].note)
        ):
            group.append(row)
            continue
        if group:
            yield group
        group = [row]
    if group:
        yield group


def equation_list(names: list[str]) -> str:
    """``1–11`` for a run of consecutive integers, else the names separated by commas."""
    if len(names) > 1 and all(n.isdigit() for n in names):
        nums = [int(n) for n in names]
        if nums == list(range(nums[0], nums[0] + len(nums))):
            return f"{nums[0]}–{nums[-1]}"
    return ", ".join(names)


def read_math(path: Path) -> list[dict[str, Any]]:
    """The typeset forms of the audited equations (``equation_math.json``; optional)."""
    return json.loads(path.read_text(encoding="utf-8")) if path.is_file() else []


def short_statement(note: str, limit: int = STATEMENT_CHARS) -> str:
    """The first clause of an audit note (up to its first ``;`` or sentence end outside
    parentheses), at most ``limit`` characters cut at a word."""
    text = " ".join(str(note).split())
    depth = 0
    for i, c in enumerate(text):
        depth += (c == "(") - (c == ")")
        ends = c == "." and text[i + 1 : i + 2] == " " and not _ABBREVIATION.search(text[: i + 1])
        if depth == 0 and (c == ";" or ends):
            text = text[:i]
            break
    if len(text) > limit:
        text = text[:limit].rsplit(" ", 1)[0].rstrip(",;:") + " …"
    return text


def _plural(n: int, one: str) -> str:
    return f"{n} {one if n == 1 else one + 's'}"


def equation_rows(
    slug: str, audit: pd.DataFrame, math: Sequence[Mapping[str, Any]]
) -> list[EquationRow]:
    """The audit rows with their forms (``kind``: the audit's column where it has one)."""
    by_eq: dict[str, Mapping[str, Any]] = {}
    for item in math:
        by_eq.setdefault(str(item.get("equation")), item)
    kinds = audit["kind"] if "kind" in audit.columns else pd.Series("", index=audit.index)
    rows = []
    for r, kind in zip(audit.itertuples(index=False), kinds, strict=True):
        m = by_eq.get(str(r.equation), {})
        rows.append(
            EquationRow(
                paper=slug,
                equation=str(r.equation),
                status=str(r.status),
                note=str(r.note),
                residual_text=str(r.residual),
                printed_mathml=m.get("printed_mathml"),
                derived_mathml=m.get("derived_mathml"),
                residual_mathml=m.get("residual_mathml"),
                printed_srepr=m.get("printed_srepr"),
                derived_srepr=m.get("derived_srepr"),
                residual_srepr=m.get("residual_srepr"),
                kind=str(kind or "") if str(r.status) == "differs" else "",
            )
        )
    return rows


def differs_counts(rows: Sequence[EquationRow]) -> dict[str, int]:
    """The differing equations by kind (every kind, zeros included; "" unclassified)."""
    out = {k: 0 for k in DIFFERS_WORDS}
    for r in rows:
        if r.status == "differs":
            out[r.kind] = out.get(r.kind, 0) + 1
    return {k: n for k, n in out.items() if n or k}


def _statement(r: EquationRow) -> str:
    """The short statement of a differing row, without the words of its kind where the note
    opens with them (they stand in the parentheses before it)."""
    opener = f"{differs_word(r.kind)}: "
    note = r.note[len(opener) :] if r.kind and r.note.startswith(opener) else r.note
    return short_statement(note)


def _differs_text(counts: Mapping[str, int]) -> str:
    parts = [f"{n} {differs_word(k)}" for k, n in counts.items() if n]
    return f" ({', '.join(parts)})" if parts else ""


def equation_section(
    slug: str,
    rows: Sequence[EquationRow],
    counts: Mapping[str, int],
    appendix: str = "",
) -> Section:
    """The main text's "Equation audit" of one paper: the counts, then one short statement per
    differing equation; ``appendix`` names where the forms are."""
    differs = [r for r in rows if r.status == "differs"]
    text = (
        f"{_plural(len(rows), 'printed equation')} checked against the SymPy derivation: "
        f"{counts.get('match', 0)} match, {counts.get('differs', 0)} differ"
        f"{_differs_text(differs_counts(rows))}, {counts.get('not_checkable', 0)} not checkable. "
        "Where a printed equation differs, the pipeline uses the derived form."
    )
    if appendix:
        text += f" The printed, derived and residual forms are in {appendix}."
    blocks: list[Any] = [Paragraph(text)]
    if differs:
        blocks.append(
            Bullets(
                [f"Eq. {r.equation} ({differs_word(r.kind)}): {_statement(r)}" for r in differs]
            )
        )
    return Section(f"{slug}-equations", "Equation audit", blocks)


def equation_appendix(
    slug: str, title: str, rows: Sequence[EquationRow], stems: Mapping[str, str]
) -> Section:
    """The appendix of one paper's audit: every row, the forms of the differing ones."""
    text = (
        "Printed: the equation as the paper prints it, transcribed into SymPy; derived: the "
        "same quantity from the derivation; residual: printed minus derived, simplified. "
        "The equations that differ are shown with their forms (a matrix by the entries that "
        "differ); those that match and those that cannot be checked are listed."
    )
    table = EquationTable(
        list(rows), caption=f"Equation audit ({slug}/equation_audit.csv)", stems=dict(stems)
    )
    return Section(f"{slug}-equation-forms", title, [Paragraph(text), table])
