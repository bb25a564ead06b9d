"""A paper's summary for the first page: three plain sentences and a mark per main claim.

Computed from ``verdicts.csv`` (verdicts, kinds, root causes), ``equation_audit.csv`` and the
paper's published-values file (its items' and claims' labels, its ``main_claims`` and the
``names`` of its tokens), nothing typed by hand:

1. what was reproduced (counts by kind);
2. what was not, in the paper's own labels ("Table 1, levelling method 4, roll"), grouped by
   root cause (rows with one identical cause text are one cause);
3. the causes, ranked by the rows they explain ("cause not identified" where a row has none).

No internal id appears: an item is named by its label, method and quantity in the paper's
words, a claim by its sentence and where the paper makes it.
"""

from __future__ import annotations

import re
from collections.abc import Mapping, Sequence
from typing import Any

import pandas as pd

from pipeline.report.model import MainClaimLine, PaperSummary
from pipeline.report.vocabulary import cause_word
from pipeline.verdicts.main_claims import FAILING, PASSING, judge_main_claims

__all__ = ["MainClaimLine", "PaperSummary", "RowNames", "paper_summary", "plural", "status_of"]

_KIND_PASS = {
    "exact": "exact ones to the printed digits",
    "approximate": "approximate ones within the stated tolerance",
    "statistical": "statistical ones inside the Monte Carlo distribution",
}


def plural(n: int, one: str, many: str | None = None) -> str:
    """``"1 run"``, ``"2 runs"``."""
    return f"{n} {one if n == 1 else (many or one + 's')}"


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

    def what(self, row: Mapping[str, Any]) -> tuple[str, str]:
        """(where the paper prints it, what it is) of a published number's row."""
        base, _, variant = str(row["id"]).partition("/")
        item = self.items.get(base, {})
        method = str(row.get("method") or "")
        tokens = set(method.replace(",", " ").split())
        parts = [self.words(method)] if method else []
        for value in (item.get("select") or {}).values():
            v = str(value)
            if v in self.names and v not in tokens:
                parts.append(self.names[v])
                tokens.add(v)
        if variant and variant not in tokens:
            parts.append(self.words(variant))
        parts.append(self.words(str(row.get("quantity") or item.get("quantity") or "")))
        label = str(item.get("label") or "an item the paper does not label")
        return label, ", ".join(p for p in parts if p)

    def claim(self, row: Mapping[str, Any], whole: bool, short: bool = False) -> str:
        """A claim's row: its sentence (``short``: only "the claim of <where>"), where the
        paper makes it and, for one curve of a claim judged on several, the curve."""
        base, _, variant = str(row["id"]).partition("/")
        claim = self.claims.get(base, {})
        text = str(claim.get("text") or row.get("published") or base).strip().rstrip(".")
        where = str(claim.get("label") or "")
        curve = self.words(variant) if variant and not whole else ""
        if short:
            place = where or "the paper"
            if re.match(r"^[A-Z][a-z]+\b(?!\.)", place):  # "Abstract": the Abstract
                place = f"the {place}"
            return f"the claim of {place}" + (f", {curve}" if curve else "")
        where = "; ".join(w for w in (where, curve) if w)
        return f"“{text}” ({where})" if where else f"“{text}”"

    def phrases(self, rows: pd.DataFrame, all_ids: Sequence[str], short: bool = False) -> list[str]:
        """The rows in the paper's words: numbers grouped by what they are (one list of labels
        per method and quantity), a claim once when every curve of it is among the rows
        (``short``: a claim by where the paper makes it, not its sentence)."""
        out: list[str] = []
        groups: dict[str, list[str]] = {}
        ids = set(rows["id"].astype(str))
        named_claims: set[str] = set()
        for _, row in rows.iterrows():
            if row["kind"] == "claim":
                base = str(row["id"]).split("/")[0]
                variants = [i for i in all_ids if i.split("/")[0] == base]
                whole = all(v in ids for v in variants)
                if whole and base in named_claims:
                    continue
                named_claims.add(base)
                out.append(self.claim(row, whole, short))
            else:
                label, what = self.what(row)
                if what not in groups:
                    groups[what] = []
                    out.append(what)  # placeholder, replaced below (keeps the order)
                groups[what].append(label)
        shown = []
        for p in out:
            if p in groups:
                labels = list(dict.fromkeys(groups[p]))
                shown.append(
                    f"{labels[0]}, {p}" if len(labels) == 1 else f"{p} in {', '.join(labels)}"
                )
            else:
                shown.append(p)
        return shown


def status_of(marks: Sequence[str], verdicts: Sequence[str]) -> str:
    """Full / Partial / Not reproduced: from the main claims' marks, else from every row."""
    good = [m == "Re" for m in marks] if marks else [v in PASSING for v in verdicts]
    if not good:
        return "Nothing to reproduce"
    if all(good):
        return "Full reproduction"
    if not any(good):
        return "Not reproduced"
    return "Partial reproduction"


def _reproduced(verdicts: pd.DataFrame, audit: pd.DataFrame) -> str:
    numbers = verdicts[verdicts["kind"] != "claim"]
    claims = verdicts[verdicts["kind"] == "claim"]
    parts = []
    if len(numbers):
        good = numbers["verdict"].isin(PASSING)
        by_kind = [
            f"{int(good[numbers['kind'] == k].sum())} of {int((numbers['kind'] == k).sum())} {why}"
            for k, why in _KIND_PASS.items()
            if (numbers["kind"] == k).any()
        ]
        parts.append(
            f"{int(good.sum())} of {plural(len(numbers), 'published number')} "
            f"({'; '.join(by_kind)})"
        )
    if len(claims):
        parts.append(
            f"{int((claims['verdict'] == 'upheld').sum())} of "
            f"{plural(len(claims), 'claim verdict')} upheld"
        )
    text = "Reproduced: " + (" and ".join(parts) if parts else "nothing was published to check")
    if len(audit):
        n_match = int((audit["status"] == "match").sum())
        text += f"; {n_match} of {plural(len(audit), 'printed equation')} match the derivation"
    return text + "."


def _cause_groups(failing: pd.DataFrame) -> list[tuple[str, str, pd.DataFrame]]:
    """(cause text, cause kind, rows) per root cause, most rows first; the rows without a
    cause last (text and kind blank)."""
    causes = failing.get("cause", pd.Series("", index=failing.index)).fillna("").astype(str)
    kinds = failing.get("cause_kind", pd.Series("", index=failing.index)).fillna("").astype(str)
    groups: dict[str, list[int]] = {}
    for i, c in zip(failing.index, causes, strict=True):
        groups.setdefault(c.strip(), []).append(i)
    named = [(c, rows) for c, rows in groups.items() if c]
    named.sort(key=lambda cr: -len(cr[1]))  # stable: ties keep the order of first appearance
    out = [(c, str(kinds[rows[0]]), failing.loc[rows]) for c, rows in named]
    if "" in groups:
        out.append(("", "", failing.loc[groups[""]]))
    return out


def _not_reproduced(
    groups: list[tuple[str, str, pd.DataFrame]],
    unchecked: pd.DataFrame,
    audit: pd.DataFrame,
    names: RowNames,
    all_ids: Sequence[str],
) -> str:
    numbered = len(groups) > 1
    parts = []
    for k, (_, _, rows) in enumerate(groups, 1):
        listed = "; ".join(names.phrases(rows, all_ids))
        parts.append(f"({k}) {listed}" if numbered else listed)
    n = sum(len(r) for _, _, r in groups)
    text = (
        f"Not reproduced or not upheld ({plural(n, 'verdict')}): " + "; ".join(parts)
        if parts
        else "Nothing checked was refuted"
    )
    if len(unchecked):
        text += "; not checkable: " + "; ".join(names.phrases(unchecked, all_ids))
    if "kind" in audit.columns:
        errors = audit[(audit["status"] == "differs") & (audit["kind"] == "paper_error")]
        if len(errors):
            text += "; printed equations with an error of the paper: " + ", ".join(
                f"eq. {e}" for e in errors["equation"]
            )
    return text + "."


def _causes(groups: list[tuple[str, str, pd.DataFrame]]) -> str:
    if not groups:
        return "Cause: none to give, as nothing checked failed."
    if len(groups) == 1 and not groups[0][0]:
        n = len(groups[0][2])
        return f"Cause: not identified for {'the' if n == 1 else 'any of the'} {plural(n, 'row')}."
    numbered = len(groups) > 1
    parts = []
    for k, (text, kind, rows) in enumerate(groups, 1):
        head = f"({k}) " if numbered else ""
        if text:
            parts.append(
                f"{head}{text.rstrip('.')} [{cause_word(kind)}; {plural(len(rows), 'row')}]"
            )
        else:
            parts.append(f"{head}cause not identified [{plural(len(rows), 'row')}]")
    lead = "Causes, by the rows they explain: " if numbered else "Cause: "
    return lead + "; ".join(parts) + "."


def _basis(result: Any, verdicts: pd.DataFrame, names: RowNames, all_ids: Sequence[str]) -> str:
    rows = verdicts.set_index(verdicts["id"].astype(str), drop=False)
    n = len(result.rows)
    if result.mark == "Re":
        return "the verdict on it holds" if n == 1 else f"all {n} verdicts on it hold"
    if result.mark == "not_Re":
        failing = rows.loc[list(result.failing)]
        head = "it fails" if n == 1 else f"{len(result.failing)} of {n} verdicts on it fail"
        return f"{head}: " + "; ".join(names.phrases(failing, all_ids, short=True))
    unchecked = rows.loc[list(result.unchecked)]
    return "not checkable: " + "; ".join(names.phrases(unchecked, all_ids, short=True))


def paper_summary(
    verdicts: pd.DataFrame, audit: pd.DataFrame, published: Mapping[str, Any], source: str
) -> PaperSummary:
    """The summary of one paper (see the module docstring); ``source`` names the published
    file in errors (a main claim naming no verdict row)."""
    names = RowNames(published)
    all_ids = [str(i) for i in verdicts["id"]]
    failing = verdicts[verdicts["verdict"].isin(FAILING)]
    unchecked = verdicts[~verdicts["verdict"].isin(FAILING) & ~verdicts["verdict"].isin(PASSING)]
    groups = _cause_groups(failing)
    results = judge_main_claims(
        published.get("main_claims") or [], all_ids, [str(v) for v in verdicts["verdict"]], source
    )
    lines = tuple(
        MainClaimLine(r.mark, r.label, r.text, _basis(r, verdicts, names, all_ids)) for r in results
    )
    status = status_of([r.mark for r in results], [str(v) for v in verdicts["verdict"]])
    sentences = (
        _reproduced(verdicts, audit),
        _not_reproduced(groups, unchecked, audit, names, all_ids),
        _causes(groups),
    )
    return PaperSummary(status, sentences, lines)
