"""Published vs reproduced, from ``verdicts.csv``, grouped by the paper's own table and figure
numbering, and the claims as sentences: the same tables for every paper.

The main text has one row per published item or claim: one judged on several curves, windows
or averaging counts (rows ``<id>/<suffix>``) is one row, its verdict across them in words
("not upheld at N = 1 and 100; upheld at N = 1e6") and its mark the worst of its rows
(:mod:`pipeline.report.grouping`); the columns are what it is, the published value, ours, the
tolerance, the verdict and the cause's title. The per-row tables (:func:`published_rows_section`,
:func:`claim_rows_section`: every row, how its verdict was reached, its note and the cause's
full text) are for the appendix.

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

import copy
import re
from collections.abc import Mapping
from functools import cache
from pathlib import Path
from typing import Any

import pandas as pd
import yaml

from pipeline.report.grouping import describe, group_rows, worst
from pipeline.report.model import FAILURE_WORDS, Block, Paragraph, Section, Table
from pipeline.report.names import RowNames, split_id
from pipeline.report.precision import (
    compact_reason,
    compact_tolerance,
    reproduced_header,
    shown_reproduced,
)
from pipeline.report.vocabulary import ROW_ID, plain_words
from pipeline.verdicts import published_items

__all__ = [
    "claim_rows_section",
    "claims_section",
    "group_label",
    "load_published",
    "published_items",
    "published_rows_section",
    "published_section",
]


#: YAML's safe loader, libyaml's C parser when PyYAML has it (the same documents, faster)
SAFE_LOADER = getattr(yaml, "CSafeLoader", yaml.SafeLoader)


def load_published(path: Path) -> Mapping[str, Any]:
    """``config/published/<slug>.yaml`` as a mapping; an absent file is empty. A text is parsed
    once per process (a report reads the file for every section): a fresh copy each call."""
    if not path.is_file():
        return {}
    published = _parsed(path.read_text(encoding="utf-8"))
    if not isinstance(published, dict):
        raise ValueError(f"{path}: expected a mapping")
    return copy.deepcopy(published)


@cache
def _parsed(text: str) -> Any:
    return yaml.load(text, Loader=SAFE_LOADER) or {}


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


def _titles(rows: pd.DataFrame) -> str:
    """The distinct cause titles of the failing rows."""
    failing = rows[rows["verdict"].isin(FAILURE_WORDS)]
    return "; ".join(dict.fromkeys(t for t in _col(failing, "cause").str.strip() if t))


def _note(row: pd.Series) -> str:
    """A row's note and, for a failing row, its cause's full text (the HTML's last column)."""
    detail = str(row.get("cause_detail") or "").strip()
    return "; ".join(p for p in (str(row["note"]), f"cause: {detail}" if detail else "") if p)


def _per_suffix(
    rows: pd.DataFrame, values: list[str], names: RowNames, partial: bool = False
) -> str:
    """One value for the rows that have one, or each with its suffix in words when they
    differ (a row without a value, e.g. not checkable, is left out; ``partial``: named by
    its suffix also when it is the only one of several with a value)."""
    kept = [(split_id(i)[1], v) for i, v in zip(rows["id"], values, strict=True) if v.strip()]
    named = partial and len(rows) > 1 and len(kept) < len(rows)
    if len({v for _, v in kept}) <= 1 and not named:
        return kept[0][1] if kept else ""
    return "; ".join(f"{names.words(sfx)}: {v}" for sfx, v in kept)


class _Numbers:
    """The published numbers of one paper, grouped by its tables and figures."""

    def __init__(self, verdicts: pd.DataFrame, published: Path):
        data = load_published(published)
        self.names = RowNames(data)
        items = {str(i.get("id")): i for i in published_items(data)}
        self.numbers = verdicts[verdicts["kind"] != "claim"].copy()
        self.groups: dict[str, list[int]] = {}
        for i, r in self.numbers.iterrows():
            label = group_label(items.get(split_id(r["id"])[0]))
            self.groups.setdefault(label, []).append(i)

    def tables(self) -> list[tuple[str, pd.DataFrame]]:
        return [(label, self.numbers.loc[self.groups[label]]) for label in sorted(self.groups, key=_sort_key)]  # fmt: skip

    def what(self, row: pd.Series, label: str, variant: bool) -> str:
        """What a row is (``variant``: with its suffix); one of a group whose rows differ in
        method is named by what its item selects."""
        where, what = self.names.what(row, variant=variant)
        # the item's own label ("Fig. 5 (3)") says more than its group's
        return f"{where}: {what}" if where != label else what

    @staticmethod
    def ours(r: pd.Series) -> str:
        return shown_reproduced(
            str(r["kind"]), str(r["published"]), str(r["reproduced"]), str(r["note"])
        )

    def caption(self, label: str, rows: pd.DataFrame, cells: list[list[str]]) -> str:
        """``<label>: <quantity>`` when the table has one quantity (cut from its rows)."""
        quantities = {self.names.words(str(q)) for q in rows["quantity"]}
        if len(quantities) == 1 and all(
            c[0].endswith(", " + next(iter(quantities))) for c in cells
        ):
            q = next(iter(quantities))
            for c in cells:
                c[0] = c[0][: -len(", " + q)]
            return f"{label}: {q}"
        return f"{label}: published numbers"


def published_section(sid: str, verdicts: pd.DataFrame, published: Path) -> Section:
    """The published numbers, one table per table or figure of the paper (in its numbering),
    one row per item (its rows across curves or windows in one)."""
    n = _Numbers(verdicts, published)
    blocks: list[Block] = [
        Paragraph(
            "Published: the value as the paper prints it; ours: our value at the printed "
            "precision plus two digits, or for a statistical value the median of our Monte "
            "Carlo and its 5-95 % band (MC median [5-95 %]); tolerance: what the verdict allowed "
            "(for a statistical value, the 0.5-99.5 % range of the Monte Carlo); cause: the root "
            "cause of a failing verdict (each listed in full in the Summary). An item judged on "
            "several curves or windows is one row, its verdict given for each; every row, with "
            "how its verdict was reached, is in the supporting results (appendix). Grouped by "
            "the paper's table or figure."
        )
    ]
    said: set[str] = set()  # a tolerance's reason once, below the first table it applies to
    for label, rows in n.tables():
        with_cause = bool(_col(rows, "cause").str.strip().any())  # a cause column where one fails
        cells, reasons, highlight, status = [], [], [], []
        for k, g in enumerate(group_rows(rows)):
            first = g.iloc[0].copy()
            if g["method"].nunique() > 1:  # the method is the suffix's: named per suffix
                first["method"] = ""
            tols = []
            for _, r in g.iterrows():
                tol, why = compact_tolerance(str(r.get("tolerance", "")), str(r["published"]))
                judged = str(r["reproduced"]).strip() != ""  # a tolerance that was applied
                tols.append(tol if judged else "")
                if why and judged and why not in reasons and why not in said:
                    reasons.append(why)
            verdicts_ = [str(v) for v in g["verdict"]]
            pairs = [(n.names.words(split_id(i)[1]), v) for i, v in zip(g["id"], verdicts_, strict=True)]  # fmt: skip
            row = [
                n.what(first, label, variant=len(g) == 1),
                _per_suffix(g, [str(v) for v in g["published"]], n.names),
                _per_suffix(g, [n.ours(r) for _, r in g.iterrows()], n.names, partial=True),
                _per_suffix(g, tols, n.names),
                describe(pairs),
            ]
            cells.append(row + ([_titles(g)] if with_cause else []))
            status.append(worst(verdicts_))
            if status[-1] in FAILURE_WORDS:
                highlight.append(k)
        columns = ["item", "published", reproduced_header(list(rows["kind"].astype(str)))]
        columns += ["tolerance", "verdict"] + (["cause"] if with_cause else [])
        caption = n.caption(label, rows, cells)
        blocks.append(Table(columns, cells, caption, highlight, status))
        if reasons:
            blocks.append(Paragraph("Tolerance: " + "; ".join(reasons) + "."))
            said.update(reasons)
    return Section(sid, "Published numbers", blocks)


def published_rows_section(sid: str, verdicts: pd.DataFrame, published: Path) -> Section:
    """Every published number's row: ours, the tolerance, the verdict, how it was reached and
    the cause's title (the HTML's last column: the row's note and the cause's full text)."""
    n = _Numbers(verdicts, published)
    blocks: list[Block] = [
        Paragraph(
            "Every verdict row of the published numbers: why says how the verdict was reached; "
            "cause is the root cause's title (its full text is listed above; the HTML report "
            "adds each row's note)."
        )
    ]
    for label, rows in n.tables():
        with_cause = bool(_col(rows, "cause").str.strip().any())  # a cause column where one fails
        cells, highlight, status, notes = [], [], [], []
        for k, (_, r) in enumerate(rows.iterrows()):
            tol, _ = compact_tolerance(str(r.get("tolerance", "")), str(r["published"]))
            row = [
                n.what(r, label, variant=True),
                str(r["published"]),
                n.ours(r),
                tol,
                str(r["verdict"]),
                compact_reason(str(r.get("reason", ""))),
            ]
            cells.append(row + ([str(r.get("cause") or "")] if with_cause else []) + [str(r["id"])])
            notes.append(_note(r))
            status.append(str(r["verdict"]))
            if r["verdict"] in FAILURE_WORDS:
                highlight.append(k)
        columns = ["item", "published", reproduced_header(list(rows["kind"].astype(str)))]
        columns += ["tolerance", "verdict", "why"] + (["cause"] if with_cause else [])
        columns += [ROW_ID]
        caption = n.caption(label, rows, cells)
        blocks.append(Table(columns, cells, caption, highlight, status, notes))
    return Section(sid, "Published numbers, every row", blocks)


def claims_section(sid: str, verdicts: pd.DataFrame, published: Path) -> Section:
    """The claims: each as the paper's sentence, its verdict (across the curves or averaging
    counts it is judged on) and the cause's title."""
    names = RowNames(load_published(published))
    claims = verdicts[verdicts["kind"] == "claim"]
    if claims.empty:
        return Section(sid, "Claims", [Paragraph("The published-values file lists no claims.")])
    with_cause = bool(_col(claims, "cause").str.strip().any())
    cells, highlight, status = [], [], []
    for k, g in enumerate(group_rows(claims)):
        verdicts_ = [str(v) for v in g["verdict"]]
        pairs = [(names.words(split_id(i)[1]), v) for i, v in zip(g["id"], verdicts_, strict=True)]
        row = [names.claim(g.iloc[0], whole=True), describe(pairs)]
        cells.append(row + ([_titles(g)] if with_cause else []))
        status.append(worst(verdicts_))
        if status[-1] in FAILURE_WORDS:
            highlight.append(k)
    columns = ["claim (where the paper makes it)", "verdict"] + (["cause"] if with_cause else [])
    intro = Paragraph(
        "Each claim is the paper's sentence, judged by a named test over our results; a claim "
        "about several curves, windows or averaging counts is judged on each, and its verdict "
        "is given for each. The evidence and the test of every row are in the supporting "
        "results (appendix)."
    )
    return Section(sid, "Claims", [intro, Table(columns, cells, "Claims", highlight, status)])


def claim_rows_section(sid: str, verdicts: pd.DataFrame, published: Path) -> Section:
    """Every claim's row: the evidence, the test, the verdict and the cause's title (the HTML's
    last column: the row's note and the cause's full text)."""
    names = RowNames(load_published(published))
    claims = verdicts[verdicts["kind"] == "claim"]
    if claims.empty:
        return Section(sid, "Claims, every row", [Paragraph("No claims.")])
    with_cause = bool(_col(claims, "cause").str.strip().any())
    cells, highlight, status, notes = [], [], [], []
    for k, (_, r) in enumerate(claims.iterrows()):
        row = [
            names.claim(r, whole="/" not in str(r["id"])),
            plain_words(str(r["reproduced"])),
            plain_words(str(r.get("reason", "")) or str(r.get("tolerance", ""))),
            str(r["verdict"]),
        ]
        cells.append(row + ([str(r.get("cause") or "")] if with_cause else []) + [str(r["id"])])
        notes.append(_note(r))
        status.append(str(r["verdict"]))
        if r["verdict"] in FAILURE_WORDS:
            highlight.append(k)
    columns = ["claim (where the paper makes it)", "evidence (computed)", "test", "verdict"]
    columns += (["cause"] if with_cause else []) + [ROW_ID]
    table = Table(columns, cells, "Claims, every row", highlight, status, notes)
    return Section(sid, "Claims, every row", [table])
