"""The equation audit of a paper in the combined report: one :class:`EquationTable` with the
printed, derived and residual forms of every audited equation (``equation_audit.csv`` and
``equation_math.json``), and the grouping the renderers share.

>>> equation_list(["1", "2", "3"]), equation_list(["9", "17"])
('1–3', '9, 17')
"""

from __future__ import annotations

import json
from collections.abc import Iterator, Mapping, Sequence
from pathlib import Path
from typing import Any

import pandas as pd

from pipeline.report.model import EquationRow, EquationTable, Paragraph, Section

__all__ = ["equation_groups", "equation_list", "equation_section", "formless", "read_math"]


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


def _plural(n: int, one: str) -> str:
    return f"{n} {one if n == 1 else one + 's'}"


def equation_section(
    slug: str,
    audit: pd.DataFrame,
    math: Sequence[Mapping[str, Any]],
    counts: Mapping[str, int],
    stems: Mapping[str, str],
) -> Section:
    """The "Equation audit" section of one paper: a summary sentence and the table."""
    by_eq: dict[str, Mapping[str, Any]] = {}
    for item in math:
        by_eq.setdefault(str(item.get("equation")), item)
    rows = []
    for r in audit.itertuples(index=False):
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
            )
        )
    differs = [r.equation for r in rows if r.status == "differs"]
    text = (
        f"{_plural(len(rows), 'printed equation')} checked against the derivation: "
        f"{counts['match']} match, {counts['differs']} differ, {counts['not_checkable']} not "
        "checkable. Printed: the equation as the paper prints it, transcribed into SymPy; "
        "derived: the same quantity from the derivation; residual: printed minus derived, "
        "simplified, shown where they differ."
    )
    if differs:
        text += (
            " Equations that differ (the pipeline uses the derived form): "
            + ", ".join(differs)
            + "."
        )
    no_math = sum(1 for r in rows if r.printed_mathml is None and r.derived_mathml is None)
    if no_math:
        text += (
            f" {_plural(no_math, 'row')} without a typeset form: the audit had no SymPy "
            "expression to compare (see the note)."
        )
    table = EquationTable(
        rows, caption=f"Equation audit ({slug}/equation_audit.csv)", stems=dict(stems)
    )
    return Section(f"{slug}-equations", "Equation audit", [Paragraph(text), table])
