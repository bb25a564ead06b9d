"""A paper's summary for the first page: three plain sentences and a mark per main claim.

Computed from ``verdicts.csv`` (verdicts, kinds, root causes), ``equation_audit.csv`` and the
paper's published-values file (its items' and claims' labels, its ``main_claims`` and the
``names`` of its tokens), nothing typed by hand:

1. what was reproduced (counts by kind, and of the claims' verdicts);
2. what was not, grouped by root cause (one group per cause title), each group named by the
   paper's labels compressed ("Tables 1-2, levelling method 4, and 4 claims of Sec. 5-1-1": at
   most a few labels, then "and N more"), never row by row;
3. the causes, their titles ranked by the rows they explain, each with its kind in words and
   its number of rows ("cause not identified" where a row has none).

Each main claim's basis is as short: its counts and the failing rows' labels, compressed. No
internal id appears: an item is named by its label and method in the paper's words, a claim
by where the paper makes it (:mod:`pipeline.report.names`).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from typing import Any

import pandas as pd

from pipeline.report.causes import cause_lines, causes_sentence, plural
from pipeline.report.grouping import rows_phrase
from pipeline.report.model import CauseLine, MainClaimLine, PaperSummary
from pipeline.report.names import RowNames
from pipeline.verdicts.main_claims import FAILING, PASSING, judge_main_claims

__all__ = [
    "SELF_CHECK_MEANING",
    "SENTENCE_WORDS",
    "MainClaimLine",
    "PaperSummary",
    "RowNames",
    "paper_summary",
    "plural",
    "self_checks",
    "status_of",
]

#: the most words a sentence of a paper's summary may have (tests/shared hold the reports
#: to it; most are well under)
SENTENCE_WORDS = 80

#: the kinds of a published number, in the order the summary counts them (the introduction
#: says what each means)
_NUMBER_KINDS = ("exact", "approximate", "statistical")


def self_checks(verdicts: pd.DataFrame, published: Mapping[str, Any]) -> pd.Series:
    """Which verdict rows are self-checks: rows of an item the published file marks
    ``self_check`` (it checks our code and derivation, not a number the paper measured, e.g.
    an ideal-sensor column); they are counted apart from the published numbers.

    >>> v = pd.DataFrame({"id": ["T1.ideal", "T1", "T2.ideal/a"]})
    >>> self_checks(v, {"items": [{"id": "T1.ideal", "self_check": "r"},
    ...                           {"id": "T2.ideal", "self_check": "r"}]}).tolist()
    [True, False, True]
    """
    ids = {str(i["id"]) for i in published.get("items") or [] if i.get("self_check")}
    return pd.Series(
        [str(r).split("/", 1)[0] in ids for r in verdicts["id"]], index=verdicts.index, dtype=bool
    )


#: what a self-check is, in the summary's words
SELF_CHECK_MEANING = "they check our code and derivation, not a number the paper measured"


def _self_check_text(checks: pd.DataFrame) -> str:
    passed = int(checks["verdict"].isin(PASSING).sum())
    return f"{passed} of {plural(len(checks), 'self-check')} passed"


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


def _reproduced(verdicts: pd.DataFrame, audit: pd.DataFrame, checks: pd.Series) -> str:
    numbers = verdicts[(verdicts["kind"] != "claim") & ~checks]
    claims = verdicts[verdicts["kind"] == "claim"]
    parts = []
    if len(numbers):
        good = numbers["verdict"].isin(PASSING)
        kinds = [k for k in _NUMBER_KINDS if (numbers["kind"] == k).any()]
        by_kind = [
            f"{int(good[numbers['kind'] == k].sum())} of {int((numbers['kind'] == k).sum())} {k}"
            for k in kinds
        ]
        parts.append(
            f"{int(good.sum())} of {plural(len(numbers), 'published number')} "
            + (f"(all {kinds[0]})" if len(kinds) == 1 else f"({', '.join(by_kind)})")
        )
    if len(claims):
        parts.append(
            f"{int((claims['verdict'] == 'upheld').sum())} of "
            f"{plural(len(claims), 'claim verdict')} upheld"
        )
    text = "Reproduced: " + (" and ".join(parts) if parts else "nothing was published to check")
    if checks.any():
        text += f"; counted apart, {_self_check_text(verdicts[checks])} ({SELF_CHECK_MEANING})"
    if len(audit):
        n_match = int((audit["status"] == "match").sum())
        text += f"; {n_match} of {plural(len(audit), 'printed equation')} match the derivation"
        if "kind" in audit.columns:
            errors = int(((audit["status"] == "differs") & (audit["kind"] == "paper_error")).sum())
            are = "is an error" if errors == 1 else "are errors"
            text += f" ({errors} of the others {are} of the paper)" if errors else ""
    return text + "."


def _not_reproduced(lines: Sequence[CauseLine], unchecked: pd.DataFrame) -> str:
    numbered = len(lines) > 1
    parts = [f"({k}) {c.labels}" if numbered else c.labels for k, c in enumerate(lines, 1)]
    n = sum(c.rows for c in lines)
    text = (
        f"Not reproduced or not upheld ({plural(n, 'verdict')}): " + "; ".join(parts)
        if parts
        else "Nothing checked was refuted"
    )
    if len(unchecked):
        text += f"; {plural(len(unchecked), 'verdict')} not checkable"
    return text + "."


def _basis(
    result: Any, verdicts: pd.DataFrame, names: RowNames, all_ids: Sequence[str], checks: set[str]
) -> str:
    rows = verdicts.set_index(verdicts["id"].astype(str), drop=False)
    n = len(result.rows)
    if result.rows and all(r in checks for r in result.rows):
        done = _self_check_text(rows.loc[list(result.rows)])
        return f"it rests on self-checks only ({SELF_CHECK_MEANING}): {done}"
    if result.mark == "Re":
        return "the verdict on it holds" if n == 1 else f"all {n} verdicts on it hold"
    if result.mark == "not_Re":
        failing = rows.loc[list(result.failing)]
        head = "it fails" if n == 1 else f"{len(result.failing)} of {n} verdicts on it fail"
        return f"{head}: {rows_phrase(failing, names, all_ids)}"
    unchecked = rows.loc[list(result.unchecked)]
    return f"not checkable: {rows_phrase(unchecked, names, all_ids)}"


def paper_summary(
    verdicts: pd.DataFrame, audit: pd.DataFrame, published: Mapping[str, Any], source: str
) -> PaperSummary:
    """The summary of one paper (see the module docstring); ``source`` names the published
    file in errors (a main claim naming no verdict row)."""
    names = RowNames(published)
    all_ids = [str(i) for i in verdicts["id"]]
    failing = verdicts[verdicts["verdict"].isin(FAILING)]
    unchecked = verdicts[~verdicts["verdict"].isin(FAILING) & ~verdicts["verdict"].isin(PASSING)]
    lines = cause_lines(failing, names, all_ids)
    results = judge_main_claims(
        published.get("main_claims") or [], all_ids, [str(v) for v in verdicts["verdict"]], source
    )
    checks = self_checks(verdicts, published)
    check_ids = set(verdicts["id"].astype(str)[checks])
    marks = tuple(
        MainClaimLine(r.mark, r.label, r.text, _basis(r, verdicts, names, all_ids, check_ids))
        for r in results
    )
    status = status_of([r.mark for r in results], [str(v) for v in verdicts["verdict"]])
    sentences = (
        _reproduced(verdicts, audit, checks),
        _not_reproduced(lines, unchecked),
        causes_sentence(lines),
    )
    return PaperSummary(status, sentences, marks, tuple(lines))
