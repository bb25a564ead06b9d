"""The verdict engine: every published number and claim of a paper gets one or more rows.

The engine names no paper. A paper package gives it

* ``locate(item, results) -> [Found, ...]``: what its results hold for a published item (one
  :class:`~pipeline.verdicts.kinds.Found` per row: one row, or one per curve);
* a :class:`~pipeline.verdicts.claims.ClaimRegistry` of its claim predicates;
* optionally ``check_item(item) -> [problem, ...]``: its check of an item's selectors;
* ``read_results() -> results``: called only after the published file has been validated.

:func:`verdict_table` judges every item with its kind's rule (:mod:`pipeline.verdicts.kinds`)
and every claim with its registered test, and :func:`write_verdicts` writes
``results/<slug>/verdicts.csv`` atomically with :data:`VERDICT_FILE_COLUMNS` (the contract
columns, then ``tolerance``, ``reason``, ``cause_kind``, ``cause`` (the cause's title) and
``cause_detail`` (its full text)).

>>> from pipeline.verdicts.claims import ClaimRegistry
>>> pub = {"items": [{"id": "A", "label": "Table 1", "kind": "exact", "quantity": "x_m",
...                   "value": "2.50"}], "claims": []}
>>> table = verdict_table(pub, lambda item, res: [Found(value=res)], ClaimRegistry(), 2.504)
>>> table[["id", "verdict", "reason"]].to_dict("records")
[{'id': 'A', 'verdict': 'reproduced', 'reason': 'value: ours 2.504 rounded to the printed 2.50'}]
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import Any

import pandas as pd

from pipeline.atomic import write_csv
from pipeline.columns import VERDICT_FILE_COLUMNS, VERDICT_KINDS, VERDICTS
from pipeline.verdicts.cause import cause_columns
from pipeline.verdicts.claims import ClaimRegistry, ClaimResult
from pipeline.verdicts.kinds import Found, consistency_note, judge, shown_unit
from pipeline.verdicts.published import ItemCheck, load_published
from pipeline.verdicts.reading import with_axis

__all__ = ["Locate", "claim_rows", "item_rows", "verdict_table", "write_verdicts"]

#: A paper's locator: what its results hold for one published item, one Found per row.
Locate = Callable[[Mapping[str, Any], Any], Sequence[Found]]


def _published_text(item: Mapping[str, Any]) -> str:
    if item.get("value") is not None:
        return str(item["value"]) + shown_unit(item)
    return f"{item['error_pct']} %"


def _join(parts: Sequence[str | None]) -> str:
    return "; ".join(p for p in parts if p)


def item_rows(item: Mapping[str, Any], found: Sequence[Found]) -> list[dict[str, str]]:
    """The verdict rows of one published item."""
    if not found:
        found = [Found(missing="the paper package found nothing for this item")]
    rows = []
    for f in found:
        judged = judge(item, f)
        notes = [
            *judged.notes,
            *f.notes,
            consistency_note(item, f.truth) if not f.missing else None,
            item.get("note"),
            item.get("source"),
        ]
        rows.append(
            {
                "id": item["id"] + (f"/{f.suffix}" if f.suffix else ""),
                "kind": item["kind"],
                "quantity": item["quantity"],
                "method": f.method,
                "published": _published_text(item),
                "reproduced": judged.reproduced,
                "verdict": judged.verdict,
                "note": _join(notes),
                "tolerance": judged.tolerance,
                "reason": judged.reason,
                **cause_columns(judged.verdict, f.cause),
            }
        )
    return rows


def claim_rows(claim: Mapping[str, Any], results: Sequence[ClaimResult]) -> list[dict[str, str]]:
    """The verdict rows of one claim (one per curve it was judged on)."""
    test = claim["predicate"]["test"]
    where = claim.get("source") or claim["label"]
    return [
        {
            "id": claim["id"] + (f"/{r.suffix}" if r.suffix else ""),
            "kind": "claim",
            "quantity": r.quantity,
            "method": r.method,
            "published": r.published if r.published is not None else claim["text"],
            "reproduced": r.reproduced,
            "verdict": r.verdict,
            "note": _join([f"claim: {claim['text']} [{where}]", claim.get("note"), *r.notes]),
            "tolerance": r.tolerance,
            "reason": f"test {test}: {r.reason}",
            **cause_columns(r.verdict, r.cause),
        }
        for r in results
    ]


def verdict_table(
    published: Mapping[str, Any], locate: Locate, claims: ClaimRegistry, results: Any
) -> pd.DataFrame:
    """Every verdict row of a validated published file: items first, then claims."""
    rows: list[dict[str, str]] = []
    for item in published["items"]:
        rows += item_rows(with_axis(item, published.get("figures")), locate(item, results))
    for claim in published["claims"]:
        rows += claim_rows(claim, claims.evaluate(claim["predicate"], results))
    table = pd.DataFrame(rows, columns=VERDICT_FILE_COLUMNS)
    bad = table[~table["verdict"].isin(VERDICTS) | ~table["kind"].isin(VERDICT_KINDS)]
    if not bad.empty:  # pragma: no cover (guarded by the rules themselves)
        raise AssertionError(f"verdict rows outside the vocabulary: {bad.to_dict('records')}")
    duplicated = table["id"][table["id"].duplicated()].tolist()
    if duplicated:
        raise ValueError(f"verdict row ids are not unique: {duplicated}")
    return table


def write_verdicts(
    published_path: str | Path,
    out_path: str | Path,
    *,
    locate: Locate,
    claims: ClaimRegistry,
    read_results: Callable[[], Any],
    check_item: ItemCheck | None = None,
) -> pd.DataFrame:
    """Validate the published file (before any compute), read the results, judge, write.

    Writes ``out_path`` atomically and returns the table.
    """
    published = load_published(published_path, claims=claims, check_item=check_item)
    table = verdict_table(published, locate, claims, read_results())
    write_csv(out_path, table, VERDICT_FILE_COLUMNS)
    return table
