"""The published values of the north-finding paper as DataFrames: the items of
``config/published/north_finding.yaml`` flattened into one row each (table, quantity, method,
sensor, the printed value and percent error), and its claims.

>>> canonical_quantity("phi"), canonical_quantity("gyro_bias"), canonical_quantity("other")
('phi_deg', 'gyro_bias_rad_s', 'other')
>>> _table_number("Table 12"), _table_number("T3")
(12.0, 3.0)
"""

from __future__ import annotations

import re
from pathlib import Path

import pandas as pd

from pipeline.north_finding.columns import QUANTITIES
from pipeline.verdicts import published as verdicts_published

__all__ = ["PUBLISHED_ITEM_FIELDS", "canonical_quantity", "load_published"]

PUBLISHED_ITEM_FIELDS = (
    "id",
    "table",
    "quantity",
    "method",
    "sensor",
    "value",
    "error_pct",
    "unit",
    "kind",
)


def canonical_quantity(name: object) -> str:
    """Map a quantity name to the results-contract name (``phi`` -> ``phi_deg``,
    ``gyro_bias`` -> ``gyro_bias_rad_s``); unknown names are returned unchanged."""
    q = str(name).strip()
    if q in QUANTITIES:
        return q
    hits = [c for c in QUANTITIES if c.startswith(q + "_") and not c.endswith("_approx")]
    return hits[0] if len(hits) == 1 else q


def _table_number(value: object) -> float:
    """``1``, ``"1"``, ``"T1"``, ``"Table 1"`` -> 1.0; anything else -> NaN."""
    if value is None:
        return float("nan")
    m = re.search(r"\d+", str(value))
    return float(m.group()) if m else float("nan")


def load_published(path: str | Path) -> tuple[pd.DataFrame, pd.DataFrame]:
    """Read ``config/published/<slug>.yaml`` -> ``(items, claims)``.

    The file is read and checked by :func:`pipeline.verdicts.load_published` (the shared
    format); the items are flattened into the columns :data:`PUBLISHED_ITEM_FIELDS` (values as
    printed, strings; ``table`` is the item's ``label``, ``method`` and ``sensor`` its
    selectors) plus ``table_no`` (float, NaN if no table) and ``error_pct_value`` (float, NaN
    if the paper prints none); ``quantity`` is canonicalised with :func:`canonical_quantity`.
    ``claims`` has ``id, text, source, predicate``.
    """
    data = verdicts_published.load_published(path)
    raw_items = []
    for i in data["items"]:
        select = i.get("select") or {}
        raw_items.append(
            {
                **{k: v for k, v in i.items() if k not in ("select", "label")},
                "table": i["label"],
                "method": select.get("method"),
                "sensor": select.get("sensor"),
            }
        )
    items = pd.DataFrame(raw_items)
    for field in PUBLISHED_ITEM_FIELDS:
        if field not in items.columns:
            items[field] = None
    items = items.astype({f: object for f in PUBLISHED_ITEM_FIELDS})
    items["quantity"] = items["quantity"].map(canonical_quantity)
    items["method"] = items["method"].map(lambda m: None if m is None else str(m))
    items["sensor"] = items["sensor"].map(lambda s: None if s is None else str(s).lower())
    items["table_no"] = items["table"].map(_table_number).astype(float)
    items["error_pct_value"] = pd.to_numeric(items["error_pct"], errors="coerce").astype(float)
    claims = pd.DataFrame([dict(c) for c in data["claims"]], columns=None)
    for field in ("id", "text", "source", "predicate"):
        if field not in claims.columns:
            claims[field] = None
    return items, claims
