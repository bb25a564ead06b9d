"""Verdict rows grouped for a reader: an item or claim judged on several curves, windows or
averaging counts (row ids ``<base>/<suffix>``) is one entry, its verdict across them in words
and its mark the worst of its rows; a set of rows is named by the paper's labels, compressed.

>>> describe([("N=1", "not_upheld"), ("N=100", "not_upheld"), ("N=1e6", "upheld"),
...           ("noise-free", "upheld")])
'not upheld at N = 1 and 100; upheld at N = 1e6 and noise-free'
>>> describe([("analytic", "upheld"), ("simulated", "not_upheld")])
'upheld for analytic; not upheld for simulated'
>>> describe([("", "reproduced")]), worst(["upheld", "not_checkable", "not_upheld", "upheld"])
('reproduced', 'not_upheld')
>>> suffix_phrase(["N=1e6", "N=1e8", "noise-free"]), suffix_phrase(["roll", "pitch"])
('at N = 1e6, 1e8 and noise-free', 'for roll and pitch')
"""

from __future__ import annotations

import re
from collections.abc import Sequence

import pandas as pd

from pipeline.report.labels import capped, compress, join_words, refs
from pipeline.report.names import RowNames, split_id, the
from pipeline.report.vocabulary import word
from pipeline.verdicts.main_claims import FAILING, PASSING

__all__ = ["describe", "group_rows", "rows_phrase", "severity", "suffix_phrase", "worst"]

_KEYED = re.compile(r"^(\w+)\s*=\s*(.+)$")


def severity(verdict: str) -> int:
    """2 for a verdict that refutes, 0 for one that holds, 1 for any other (not checkable)."""
    return 2 if verdict in FAILING else 0 if verdict in PASSING else 1


def worst(verdicts: Sequence[str]) -> str:
    """The worst of ``verdicts`` (the first of the most severe): a group's mark."""
    return max(verdicts, key=severity) if verdicts else ""


def suffix_phrase(labels: Sequence[str]) -> str:
    """Suffixes in words: ``at N = 1, 100 and 1e4`` for values of one parameter ``N=...``
    (others listed after them), else ``for roll and pitch``."""
    keyed: dict[str, list[str]] = {}
    plain: list[str] = []
    for label in dict.fromkeys(labels):
        m = _KEYED.match(label)
        if m:
            keyed.setdefault(m.group(1), []).append(m.group(2).strip())
        else:
            plain.append(label)
    if not keyed:
        return f"for {join_words(plain)}"
    lone = len(keyed) == 1 and not plain
    parts = [f"{k} = {join_words(v) if lone else ', '.join(v)}" for k, v in keyed.items()]
    return f"at {join_words(parts + plain)}"


def describe(pairs: Sequence[tuple[str, str]]) -> str:
    """The verdict of a group across its rows, from (suffix in words, verdict token) pairs in
    row order: the token itself for one row without a suffix, else each verdict with the
    suffixes it holds for, in the order they first appear."""
    if len(pairs) == 1 and not pairs[0][0]:
        return pairs[0][1]
    by_verdict: dict[str, list[str]] = {}
    for label, verdict in pairs:
        by_verdict.setdefault(verdict, []).append(label)
    return "; ".join(f"{word(v)} {suffix_phrase(labels)}" for v, labels in by_verdict.items())


def group_rows(rows: pd.DataFrame) -> list[pd.DataFrame]:
    """The rows grouped by base id, in the order of each base's first row."""
    bases = [split_id(i)[0] for i in rows["id"]]
    order = list(dict.fromkeys(bases))
    index = pd.Series(bases, index=rows.index)
    return [rows[index == b] for b in order]


def _numbers_phrase(rows: pd.DataFrame, names: RowNames) -> str:
    units = compress(ref for _, r in rows.iterrows() for ref in refs(names.where(r)))
    where = capped(units) or "published numbers"
    methods = {names.words(str(m)) for m in rows["method"]}
    return f"{where}, {methods.pop()}" if len(methods) == 1 and "" not in methods else where


def _claims_phrase(rows: pd.DataFrame, names: RowNames, all_ids: Sequence[str]) -> str:
    groups = group_rows(rows)
    units = compress(ref for g in groups for ref in refs(names.where(g.iloc[0])))
    shown = capped(units)
    head = "the claim" if len(groups) == 1 else f"{len(groups)} claims"
    text = f"{head} of {the(shown) if shown else 'the paper'}"
    # the suffixes the rows fail for, when every claim has the same ones and some other
    suffixes = [tuple(split_id(i)[1] for i in g["id"]) for g in groups]
    bases = [split_id(g["id"].iloc[0])[0] for g in groups]
    variants = [[i for i in all_ids if split_id(i)[0] == b] for b in bases]
    if (
        all(s and all(s) for s in suffixes)
        and len(set(suffixes)) == 1
        and any(len(v) > len(s) for v, s in zip(variants, suffixes, strict=True))
    ):
        text += " " + suffix_phrase([names.words(s) for s in suffixes[0]])
    return text


def rows_phrase(rows: pd.DataFrame, names: RowNames, all_ids: Sequence[str]) -> str:
    """A set of verdict rows in the paper's labels, compressed: its numbers' tables or figures
    (with their method when they share one) and its claims (counted, with where the paper
    makes them and, when they fail for some of their suffixes only, which): at most a few
    labels each, then "and N more"."""
    parts = []
    numbers = rows[rows["kind"] != "claim"]
    claims = rows[rows["kind"] == "claim"]
    if len(numbers):
        parts.append(_numbers_phrase(numbers, names))
    if len(claims):
        parts.append(_claims_phrase(claims, names, all_ids))
    return ", and ".join(parts) if any("," in p for p in parts[:1]) else " and ".join(parts)
