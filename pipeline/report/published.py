"""Published vs reproduced, from ``verdicts.csv``, grouped by the paper's own table and figure
numbering, and the claims as sentences: the same tables for every paper.

A number is named in the paper's words (its method and quantity, ``names`` of the published
file); the reproduced column says what it holds (ours, or the Monte Carlo median with its
5-95 % band), at the printed precision plus two digits; the tolerance is the one the verdict
applied (its reason below the table); the verdict is a token the renderers show as a word.

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

from pipeline.report.model import FAILURE_WORDS, Block, Paragraph, Section, Table
from pipeline.report.precision import (
    compact_reason,
    compact_tolerance,
    reproduced_header,
    shown_reproduced,
)
from pipeline.report.summary import RowNames
from pipeline.report.vocabulary import cause_word, plain_words
from pipeline.verdicts import published_items

__all__ = [
    "claims_section",
    "group_label",
    "load_published",
    "published_items",
    "published_section",
]


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


def _col(df: pd.DataFrame, name: str) -> pd.Series:
    return df[name].astype(str) if name in df.columns else pd.Series("", index=df.index)


def _cause(row: Mapping[str, Any]) -> str:
    text = str(row.get("cause") or "").strip()
    return f"{text} ({cause_word(str(row.get('cause_kind') or ''))})" if text else ""


def published_section(sid: str, verdicts: pd.DataFrame, published: Path) -> Section:
    """The published numbers, one table per table or figure of the paper (in its numbering)."""
    data = load_published(published)
    names = RowNames(data)
    items = {str(i.get("id")): i for i in published_items(data)}
    numbers = verdicts[verdicts["kind"] != "claim"].copy()
    blocks: list[Block] = [
        Paragraph(
            "Published: the value as the paper prints it; ours: our value at the printed "
            "precision plus two digits, or for a statistical value the median of our Monte "
            "Carlo and its 5-95 % band (MC median [5-95 %]); tolerance: what the verdict allowed "
            "(for a statistical value, the 0.5-99.5 % range of the Monte Carlo); why: how the "
            "verdict was reached (the HTML report adds each row's note). Grouped by the paper's "
            "table or figure."
        )
    ]
    with_cause = bool(_col(numbers, "cause").str.strip().any())
    groups: dict[str, list[int]] = {}
    for i, r in numbers.iterrows():
        groups.setdefault(group_label(items.get(str(r["id"]).split("/")[0])), []).append(i)
    for label in sorted(groups, key=_sort_key):
        rows = numbers.loc[groups[label]]
        cells, reasons, highlight, status, notes = [], [], [], [], []
        for k, (_, r) in enumerate(rows.iterrows()):
            notes.append(str(r["note"]))
            where, what = names.what(r)
            tol, tol_reason = compact_tolerance(str(r.get("tolerance", "")), str(r["published"]))
            if tol_reason and tol_reason not in reasons:
                reasons.append(tol_reason)
            if where != label:  # the item's own label ("Fig. 5 (3)") says more than its group
                what = f"{where}: {what}"
            row = [
                what,
                str(r["published"]),
                shown_reproduced(
                    str(r["kind"]), str(r["published"]), str(r["reproduced"]), str(r["note"])
                ),
                tol,
                str(r["verdict"]),
                compact_reason(str(r.get("reason", ""))),
            ]
            if with_cause:
                row.append(_cause(r))
            cells.append(row)
            status.append(str(r["verdict"]))
            if r["verdict"] in FAILURE_WORDS:
                highlight.append(k)
        # one quantity in the whole table: named in the caption, not in every row
        quantities = {names.words(str(q)) for q in rows["quantity"]}
        caption = f"{label}: published numbers"
        if len(quantities) == 1 and all(
            c[0].endswith(", " + next(iter(quantities))) for c in cells
        ):
            q = next(iter(quantities))
            caption = f"{label}: {q}"
            for c in cells:
                c[0] = c[0][: -len(", " + q)]
        columns = ["item", "published", reproduced_header(list(rows["kind"].astype(str)))]
        columns += ["tolerance", "verdict", "why"] + (["cause"] if with_cause else [])
        blocks.append(Table(columns, cells, caption, highlight, status, notes))
        if reasons:
            blocks.append(Paragraph("Tolerance: " + "; ".join(reasons) + "."))
    return Section(sid, "Published numbers", blocks)


def claims_section(sid: str, verdicts: pd.DataFrame, published: Path) -> Section:
    """The claims: each as the paper's sentence, the evidence, the test and the verdict."""
    names = RowNames(load_published(published))
    claims = verdicts[verdicts["kind"] == "claim"]
    if claims.empty:
        return Section(sid, "Claims", [Paragraph("The published-values file lists no claims.")])
    with_cause = bool(_col(claims, "cause").str.strip().any())
    cells, highlight, status, notes = [], [], [], []
    for k, (_, r) in enumerate(claims.iterrows()):
        notes.append(str(r["note"]))
        row = [
            names.claim(r, whole="/" not in str(r["id"])),
            plain_words(str(r["reproduced"])),
            plain_words(str(r.get("reason", "")) or str(r.get("tolerance", ""))),
            str(r["verdict"]),
        ]
        if with_cause:
            row.append(_cause(r))
        cells.append(row)
        status.append(str(r["verdict"]))
        if r["verdict"] in FAILURE_WORDS:
            highlight.append(k)
    columns = ["claim (where the paper makes it)", "evidence (computed)", "test", "verdict"]
    columns += ["cause"] if with_cause else []
    intro = Paragraph(
        "Each claim is the paper's sentence, judged by a test over our results (the test and "
        "its threshold are named); a claim about several curves is judged on each."
    )
    table = Table(columns, cells, "Claims", highlight, status, notes)
    return Section(sid, "Claims", [intro, table])
