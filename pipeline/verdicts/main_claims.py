"""The main claims of a paper and their ReScience mark: ``[Re]``, ``[¬Re]`` or not checkable.

ReScience C judges a reproduction by the paper's main claims, not by every cell. A paper's
published-values file lists them (``main_claims``: label, the claim as a plain sentence, and
the verdict rows that bear on it); the mark is computed from those rows of ``verdicts.csv``:

* ``[Re]`` when every matched row is reproduced, consistent or upheld;
* ``[¬Re]`` when any matched row is not reproduced or not upheld;
* not checkable otherwise (a row not checkable, and none fails).

A claim judged on several curves or averaging counts has one row per variant
(``<id>/<variant>``); it holds only if it holds on every variant that bears on it. So a main
claim that holds where its rows can be resolved but is unresolved on another variant of the
same claim is not checkable, never ``[Re]``: the unresolved siblings of every matched variant
row are judged with it (:func:`bearing_rows`), even when ``rows`` names one variant only.

A ``rows`` entry is either an id of the file (an item or claim id, which matches its row and
the rows of its variants ``<id>/<curve>``), an id with a variant (``C2.x/proposed_simulated``:
that row only) or a prefix ending with ``.`` (``T9.``: every row whose id starts with it).

>>> entry_matches("T1.phi.L1", "T1.phi.L1"), entry_matches("T1.phi.L1", "T1.phi.L1.ideal")
(True, False)
>>> entry_matches("T9.", "T9.psi.A2"), entry_matches("C2", "C2/proposed_analytic")
(True, True)
>>> mark(["reproduced", "upheld"]), mark(["reproduced", "not_upheld"]), mark(["not_checkable"])
('Re', 'not_Re', 'not_checkable')
>>> mark(["upheld", "upheld", "not_checkable"])  # holds where resolved, unresolved elsewhere
'not_checkable'
>>> ids = ["C7/N=1", "C7/N=1e6", "T1"]
>>> bearing_rows(["C7/N=1e6"], ids, {"C7/N=1": "not_checkable", "C7/N=1e6": "upheld"})
['C7/N=1', 'C7/N=1e6']
"""

from __future__ import annotations

from collections.abc import Iterable, Mapping, Sequence
from dataclasses import dataclass
from typing import Any

__all__ = [
    "FAILING",
    "MARKS",
    "PASSING",
    "MainClaimResult",
    "bearing_rows",
    "check_main_claims",
    "entry_matches",
    "judge_main_claims",
    "mark",
    "matched_rows",
]

#: verdicts that hold / that refute
PASSING = ("reproduced", "consistent", "upheld")
FAILING = ("not_reproduced", "not_upheld")
#: the marks, as tokens (the report shows "[Re]", "[¬Re]", "not checkable")
MARKS = ("Re", "not_Re", "not_checkable")


def entry_matches(entry: str, row_id: str) -> bool:
    """Whether a ``rows`` entry names the verdict row ``row_id`` (see the module docstring)."""
    if entry.endswith("."):
        return row_id.startswith(entry)
    return row_id == entry or row_id.startswith(entry + "/")


def matched_rows(entries: Sequence[str], row_ids: Iterable[str]) -> list[str]:
    """The row ids (in their order) that any of ``entries`` names."""
    return [r for r in row_ids if any(entry_matches(e, r) for e in entries)]


def _base(row_id: str) -> str:
    return row_id.split("/", 1)[0]


def bearing_rows(
    entries: Sequence[str], row_ids: Sequence[str], verdict_of: Mapping[str, str]
) -> list[str]:
    """The rows a main claim is judged on, in file order: those ``entries`` name, and every
    not-checkable sibling ``<id>/<other variant>`` of a matched variant row (a claim that is
    unresolved on one of its variants is unresolved, whichever variant ``rows`` names)."""
    named = set(matched_rows(entries, row_ids))
    bases = {_base(r) for r in named if "/" in r}
    return [
        r
        for r in row_ids
        if r in named
        or ("/" in r and _base(r) in bases and verdict_of.get(r) not in (*PASSING, *FAILING))
    ]


def mark(verdicts: Sequence[str]) -> str:
    """The mark of a main claim from the verdicts of its rows (:data:`MARKS`)."""
    if not verdicts:
        return "not_checkable"
    if any(v in FAILING for v in verdicts):
        return "not_Re"
    if all(v in PASSING for v in verdicts):
        return "Re"
    return "not_checkable"


def _known(entry: str, ids: Sequence[str]) -> bool:
    """Whether ``entry`` can name a row of a file with item/claim ``ids`` (checked before any
    result: a variant's suffix is known only once the verdicts are written)."""
    if entry.endswith("."):
        return any(i.startswith(entry) for i in ids)
    return entry in ids or entry.split("/", 1)[0] in ids


def check_main_claims(data: Mapping[str, Any]) -> list[tuple[str, str, Any, str]]:
    """(where, field, bad value, allowed) of every problem of a file's ``main_claims`` that a
    schema cannot find: an entry of ``rows`` that names no item or claim of the file."""
    ids = [str(e.get("id")) for s in ("items", "claims") for e in data.get(s) or []]
    problems = []
    for k, claim in enumerate(data.get("main_claims") or []):
        where = f"main claim {claim.get('label')!r} (main_claims[{k}])"
        for j, entry in enumerate(claim["rows"]):
            if not _known(entry, ids):
                problems.append(
                    (
                        where,
                        f"rows[{j}]",
                        entry,
                        "an item or claim id of this file, '<id>/<variant>', or an id prefix "
                        "ending with '.' that some id starts with",
                    )
                )
    return problems


@dataclass(frozen=True)
class MainClaimResult:
    """One main claim judged: its ``label`` and ``text`` (from the file), the ``mark``, and the
    verdict rows it was judged on (``rows``: their ids; ``verdicts``: theirs, same order)."""

    label: str
    text: str
    mark: str
    rows: tuple[str, ...]
    verdicts: tuple[str, ...]

    @property
    def failing(self) -> tuple[str, ...]:
        return tuple(r for r, v in zip(self.rows, self.verdicts, strict=True) if v in FAILING)

    @property
    def unchecked(self) -> tuple[str, ...]:
        return tuple(
            r
            for r, v in zip(self.rows, self.verdicts, strict=True)
            if v not in FAILING and v not in PASSING
        )


def judge_main_claims(
    main_claims: Sequence[Mapping[str, Any]],
    row_ids: Sequence[str],
    row_verdicts: Sequence[str],
    source: str,
) -> list[MainClaimResult]:
    """Every main claim with its mark, from the verdict rows (``row_ids``, ``row_verdicts``:
    the ``id`` and ``verdict`` columns of verdicts.csv). An entry that names no row is an
    error (``ValueError`` naming ``source``, the claim, the field and the value)."""
    verdict_of = dict(zip(row_ids, row_verdicts, strict=True))
    out = []
    for k, claim in enumerate(main_claims):
        for j, entry in enumerate(claim["rows"]):
            if not matched_rows([entry], row_ids):
                raise ValueError(
                    f"{source}: main claim {claim['label']!r} (main_claims[{k}]), field "
                    f"'rows[{j}]': bad value {entry!r}; allowed: a verdict row id of "
                    "verdicts.csv or an id prefix ending with '.' (no row matches)"
                )
        rows = bearing_rows(claim["rows"], row_ids, verdict_of)
        verdicts = tuple(verdict_of[r] for r in rows)
        out.append(
            MainClaimResult(
                str(claim["label"]), str(claim["text"]), mark(verdicts), tuple(rows), verdicts
            )
        )
    return out
