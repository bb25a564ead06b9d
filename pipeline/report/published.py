"""Published vs reproduced, grouped from ``verdicts.csv`` by the paper's own table and figure
numbering (for a paper whose report does not lay out its published tables itself).

>>> group_label({"label": "Table 2 (stationary)"}), group_label({"label": "Fig. 7"})
('Table 2', 'Fig. 7')
>>> group_label(None)
'Other published numbers'
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from pathlib import Path
from typing import Any

import pandas as pd
import yaml

from pipeline.report.model import (
    FAILURE_WORDS,
    Block,
    Paragraph,
    Section,
    Table,
)
from pipeline.verdicts import published_items

__all__ = ["group_label", "load_published", "published_items", "published_section"]


def load_published(path: Path) -> Mapping[str, Any]:
    """``config/published/<slug>.yaml`` as a mapping; an absent file is empty."""
    if not path.is_file():
        return {}
    with path.open(encoding="utf-8") as fh:
        published = yaml.safe_load(fh) or {}
    if not isinstance(published, dict):
        raise ValueError(f"{path}: expected a mapping")
    return published


def group_label(item: Mapping[str, Any] | None) -> str:
    """The paper's table or figure an item is printed in (``Table 2``), else a catch-all."""
    if not item:
        return "Other published numbers"
    ref = str(item.get("label") or "").strip()
    if not ref:
        return "Other published numbers"
    return re.split(r"\s*\(", ref)[0]


def _sort_key(label: str) -> tuple[tuple[float, str], str]:
    """By the number in the label (``Table 10`` after ``Table 2``), then the label."""
    rest = re.sub(r"^\D+", "", label)
    m = re.match(r"^\s*(\d+)(.*)$", rest)
    return ((float(m.group(1)), m.group(2)) if m else (float("inf"), rest)), label


def published_section(sid: str, verdicts: pd.DataFrame, published: Path) -> Section:
    """Numbers by the paper's table/figure (in its numbering), then the claims."""
    items = {str(i.get("id")): i for i in published_items(load_published(published))}
    numbers = verdicts[verdicts["kind"] != "claim"]
    claims = verdicts[verdicts["kind"] == "claim"]
    blocks: list[Block] = [
        Paragraph(
            "Published: the value as the paper prints it (config/published); reproduced: "
            "our value; verdict and note: from verdicts.csv. Grouped by the paper's figure "
            "or table."
        )
    ]
    groups: dict[str, list[list[str]]] = {}
    marks: dict[str, list[int]] = {}
    cols = ["id", "quantity", "method", "published", "reproduced", "verdict", "note"]
    cols += [c for c in ("tolerance", "reason") if c in verdicts.columns]  # where recorded
    for r in numbers[cols].itertuples(index=False):
        label = group_label(items.get(str(r.id).split("/")[0]))
        rows = groups.setdefault(label, [])
        if r.verdict in FAILURE_WORDS:
            marks.setdefault(label, []).append(len(rows))
        rows.append(list(r))
    for label in sorted(groups, key=_sort_key):
        blocks.append(
            Table(
                columns=cols,
                rows=groups[label],
                caption=f"{label}: published numbers",
                highlight=marks.get(label, []),
            )
        )
    if len(claims):
        rows, hl = [], []
        why = ["reason"] if "reason" in claims.columns else []
        for r in claims[
            ["id", "method", "published", "reproduced", "verdict", "note", *why]
        ].itertuples(index=False):
            if r.verdict in FAILURE_WORDS:
                hl.append(len(rows))
            rows.append(list(r))
        blocks.append(
            Table(
                columns=[
                    "id",
                    "applies to",
                    "claim",
                    "evidence (computed)",
                    "verdict",
                    "source",
                    *why,
                ],
                rows=rows,
                caption="Claims",
                highlight=hl,
            )
        )
    return Section(sid, "Published vs reproduced", blocks)
