"""The scoreboard: one row per paper, counted from its ``equation_audit.csv`` and
``verdicts.csv``, with a ReScience-style one-line verdict.

>>> counts(["match", "differs", "match"], ("match", "differs", "not_checkable"))
{'match': 2, 'differs': 1, 'not_checkable': 0}
"""

from __future__ import annotations

import math
import re
from collections.abc import Sequence

import pandas as pd

from pipeline.report.model import ScoreRow

__all__ = [
    "AUDIT_WORDS",
    "CLAIM_WORDS",
    "NUMBER_WORDS",
    "counts",
    "plural",
    "rescience_line",
    "score_row",
]

#: Status and verdict words counted on the scoreboard (every word shown, zeros included).
AUDIT_WORDS = ("match", "differs", "not_checkable")
NUMBER_WORDS = ("reproduced", "consistent", "not_reproduced")
CLAIM_WORDS = ("upheld", "not_upheld", "not_checkable")


def counts(values: Sequence[str] | pd.Series, words: Sequence[str]) -> dict[str, int]:
    """How often each of ``words`` occurs in ``values`` (zeros included, in that order);
    any other word found is appended (a producer bug, shown rather than hidden)."""
    out = {w: 0 for w in words}
    for v in values:
        out[str(v)] = out.get(str(v), 0) + 1
    return out


def plural(n: int, one: str, many: str | None = None) -> str:
    """``"1 run"``, ``"2 runs"``."""
    return f"{n} {one if n == 1 else (many or one + 's')}"


def _words(word: str) -> str:
    return word.replace("_", " ")


def _compact_ids(ids: Sequence[str], all_ids: Sequence[str] = (), limit: int = 5) -> str:
    """The ids in ``ids``, at most ``limit`` shown. An id with variants (``F5.3.crossover/
    proposed_simulated``: one published item judged on several curves) is named by its base
    when every variant of it in ``all_ids`` is in ``ids``, else by the variants in ``ids``."""
    chosen = list(dict.fromkeys(str(i) for i in ids))
    variants: dict[str, list[str]] = {}
    for i in dict.fromkeys(str(i) for i in [*all_ids, *chosen]):
        variants.setdefault(i.split("/")[0], []).append(i)
    names: list[str] = []
    for i in chosen:
        base = i.split("/")[0]
        whole = all(v in chosen for v in variants[base])
        name = base if whole else i
        if name not in names:
            names.append(name)
    shown = ", ".join(names[:limit])
    if len(names) > limit:
        shown += f" and {len(names) - limit} more"
    return shown


_NOT_REPRODUCED_WHY = {
    "exact": "beyond the printed precision or stated tolerance",
    "approximate": "outside the stated tolerance of a value read off a plot or printed as about",
    "statistical": "outside the Monte Carlo tolerance",
}


_LEADING_NUMBER = re.compile(r"^\s*([+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?)(\s*\S*)\s*$")


def _number(text: object) -> tuple[float, str] | None:
    """``(value, unit)`` of a cell such as ``"0.16"`` or ``"2400 s"`` (one unit word at most)."""
    m = _LEADING_NUMBER.match(str(text))
    if m is None:
        return None
    value = float(m.group(1))
    return (value, m.group(2).strip()) if math.isfinite(value) else None


def _ratio_range(rows: pd.DataFrame) -> str:
    """How far ours is from the published value over rows where both are numbers (published
    non-zero): ``"2.7\u20136.7x"`` when every ratio is at least 2 or at most 1/2, else the
    relative difference, ``"+0.01 to +0.5 % off"``; ``""`` if no row has two numbers."""
    ratios = []
    for pub, ours in zip(rows["published"], rows["reproduced"], strict=True):
        a, b = _number(pub), _number(ours)
        if a is not None and b is not None and a[0] != 0 and a[1] == b[1]:  # same unit
            ratios.append(b[0] / a[0])
    if not ratios:
        return ""
    lo, hi = min(ratios), max(ratios)
    if lo >= 2 or hi <= 0.5:
        span = f"{lo:.2g}" if f"{lo:.2g}" == f"{hi:.2g}" else f"{lo:.2g}\u2013{hi:.2g}"
        return f"ours {span}x the published"
    d_lo, d_hi = 100 * (lo - 1), 100 * (hi - 1)
    span = f"{d_lo:+.2g}" if f"{d_lo:+.2g}" == f"{d_hi:+.2g}" else f"{d_lo:+.2g} to {d_hi:+.2g}"
    return f"ours {span} % off the published"


def rescience_line(audit: pd.DataFrame, verdicts: pd.DataFrame) -> str:
    """The ReScience-style one-line verdict of a paper, filled from the CSVs.

    Full reproduction: every published number reproduced or consistent and every claim
    upheld; not reproduced: none of them; partial otherwise. The reasons name the
    numbers not reproduced (by kind, with the range of ours / published), the claims not
    upheld or not checkable, and the printed equations that differ from the derivation.
    """
    numbers = verdicts[verdicts["kind"] != "claim"]
    claims = verdicts[verdicts["kind"] == "claim"]
    nc = counts(numbers["verdict"], NUMBER_WORDS)
    cc = counts(claims["verdict"], CLAIM_WORDS)
    ac = counts(audit["status"], AUDIT_WORDS)
    n_good = nc["reproduced"] + nc["consistent"]
    n_bad = len(numbers) - n_good
    c_good = cc["upheld"]
    c_bad = len(claims) - c_good
    if len(numbers) + len(claims) == 0:
        status = "Nothing to reproduce"
    elif n_bad == 0 and c_bad == 0:
        status = "Full reproduction"
    elif n_good == 0 and c_good == 0:
        status = "Not reproduced"
    else:
        status = "Partial reproduction"
    parts: list[str] = []
    if len(numbers):
        text = f"{n_good} of {plural(len(numbers), 'published number')} reproduced or consistent"
        bad = numbers[numbers["verdict"] != "reproduced"]
        bad = bad[bad["verdict"] != "consistent"]
        if len(bad):
            groups = []
            for kind, g in bad.groupby("kind", sort=False):
                why = _NOT_REPRODUCED_WHY.get(str(kind), f"{kind} values")
                spread = _ratio_range(g)
                if spread:
                    why += f"; {spread}"
                groups.append(f"{_compact_ids(list(g['id']), list(numbers['id']))} ({why})")
            text += "; not reproduced: " + "; ".join(groups)
        parts.append(text)
    if len(claims):
        text = f"{c_good} of {plural(len(claims), 'claim')} upheld"
        for word in ("not_upheld", "not_checkable"):
            ids = list(claims.loc[claims["verdict"] == word, "id"])
            if ids:
                text += f"; {_words(word)}: {_compact_ids(ids, list(claims['id']))}"
        other = claims[~claims["verdict"].isin(CLAIM_WORDS)]
        if len(other):
            text += f"; other verdicts: {_compact_ids(list(other['id']), list(claims['id']))}"
        parts.append(text)
    if len(audit):
        text = (
            f"{ac['differs']} of {plural(len(audit), 'printed equation')} differ from the "
            "derivation"
        )
        if ac["differs"]:
            text += " (the derived forms are used)"
        if ac["not_checkable"]:
            text += f", {ac['not_checkable']} not checkable"
        parts.append(text)
    return f"{status}: " + ". ".join(parts) + "."


def score_row(slug: str, title: str, audit: pd.DataFrame, verdicts: pd.DataFrame) -> ScoreRow:
    """The scoreboard row of one paper, counted from its audit and verdict tables."""
    numbers = verdicts[verdicts["kind"] != "claim"]
    claims = verdicts[verdicts["kind"] == "claim"]
    return ScoreRow(
        slug=slug,
        title=title,
        audit=counts(audit["status"], AUDIT_WORDS),
        numbers=counts(numbers["verdict"], NUMBER_WORDS),
        claims=counts(claims["verdict"], CLAIM_WORDS),
        line=rescience_line(audit, verdicts),
        anchor=slug,
    )
