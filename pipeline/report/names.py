"""A verdict row in the paper's words, from its published-values file: the label of the
table, figure or section that prints it, its method and quantity, a claim's sentence.

No internal id is shown: an item is named by its label, method and quantity in the paper's
words (the file's ``names`` of its tokens), a claim by its sentence and where the paper makes
it. Nothing here names a paper.

>>> n = RowNames({"items": [{"id": "T1.a", "label": "Table 1", "select": {"method": "M4"}}],
...               "claims": [{"id": "C1", "label": "Abstract", "text": "It holds."}],
...               "names": {"M4": "method 4", "phi_deg": "roll"}})
>>> n.what({"id": "T1.a", "method": "M4", "quantity": "phi_deg"})
('Table 1', 'method 4, roll')
>>> n.where({"id": "C1/x", "kind": "claim"}), n.claim({"id": "C1/x"}, whole=True)
('Abstract', '“It holds” (Abstract)')
"""

from __future__ import annotations

import re
from collections.abc import Mapping
from typing import Any

__all__ = ["RowNames", "split_id", "the"]


def split_id(row_id: Any) -> tuple[str, str]:
    """(base id, suffix) of a verdict row id ``<base>/<suffix>`` (suffix "" without one)."""
    base, _, suffix = str(row_id).partition("/")
    return base, suffix


class RowNames:
    """Names a verdict row in the paper's words, from its published-values file."""

    def __init__(self, published: Mapping[str, Any]):
        self.items = {str(i["id"]): i for i in published.get("items") or []}
        self.claims = {str(c["id"]): c for c in published.get("claims") or []}
        self.names = {str(k): str(v) for k, v in (published.get("names") or {}).items()}

    def words(self, text: str) -> str:
        """Every token of ``text`` that the file names, in the paper's words."""
        return re.sub(
            r"[A-Za-z0-9_]+",
            lambda m: self.names.get(m.group(0), m.group(0).replace("_", " ")),
            str(text),
        )

    def where(self, row: Mapping[str, Any]) -> str:
        """The paper's label of a row: where it prints the number or makes the claim."""
        base, _ = split_id(row["id"])
        entry = self.claims.get(base) if row.get("kind") == "claim" else self.items.get(base)
        return str((entry or {}).get("label") or "")

    def what(self, row: Mapping[str, Any], variant: bool = True) -> tuple[str, str]:
        """(where the paper prints it, what it is) of a published number's row (``variant``:
        with the words of its id's suffix)."""
        base, suffix = split_id(row["id"])
        item = self.items.get(base, {})
        method = str(row.get("method") or "")
        tokens = set(method.replace(",", " ").split())
        parts = [self.words(method)] if method else []
        for value in (item.get("select") or {}).values():
            v = str(value)
            if v in self.names and v not in tokens:
                parts.append(self.names[v])
                tokens.add(v)
        if variant and suffix and suffix not in tokens:
            parts.append(self.words(suffix))
        parts.append(self.words(str(row.get("quantity") or item.get("quantity") or "")))
        label = str(item.get("label") or "an item the paper does not label")
        return label, ", ".join(p for p in parts if p)

    def claim(self, row: Mapping[str, Any], whole: bool, short: bool = False) -> str:
        """A claim's row: its sentence (``short``: only "the claim of <where>"), where the
        paper makes it and, for one curve of a claim judged on several, the curve."""
        base, variant = split_id(row["id"])
        claim = self.claims.get(base, {})
        text = str(claim.get("text") or row.get("published") or base).strip().rstrip(".")
        where = str(claim.get("label") or "")
        curve = self.words(variant) if variant and not whole else ""
        if short:
            return f"the claim of {the(where or 'the paper')}" + (f", {curve}" if curve else "")
        where = "; ".join(w for w in (where, curve) if w)
        return f"“{text}” ({where})" if where else f"“{text}”"


def the(place: str) -> str:
    """A place the paper names, as a noun phrase: "Abstract" -> "the Abstract" (a numbered
    place, "Sec. 6", stays as it is)."""
    return f"the {place}" if re.match(r"^[A-Z][a-z]+\b(?![.\s]*(\d|[A-Z]\b))", place) else place
