"""The paper's labels, compressed for a summary: "Table 1", "Table 2" -> "Tables 1-2".

A label of a published item or claim names where the paper prints it ("Table 1",
"Fig. 5 (3)", "Sec. 6, Fig. 5 (4)", "Sec. 3 (eq. 12) and Sec. 6 (Fig. 3)"). :func:`refs` splits
it into its references, :func:`compress` merges the references that share a prefix word and
a whole number ("Fig. 5 (3)" and "Fig. 6 (4)" are Figs 5-6: a panel or a parenthesis is
finer than a summary needs), and :func:`capped` joins at most a few of them, then "and N
more". Nothing here names a paper.

>>> refs("Sec. 6, Fig. 5 (4)"), refs("Sec. 3 (eq. 12) and Sec. 6 (Fig. 3)")
(['Sec. 6', 'Fig. 5 (4)'], ['Sec. 3 (eq. 12)', 'Sec. 6 (Fig. 3)'])
>>> compress(["Table 1", "Table 2", "Sec. 5-1-1", "Table 9"])
['Tables 1-2 and 9', 'Sec. 5-1-1']
>>> compress(["Fig. 5 (3)", "Fig. 6 (3)", "Fig. 7 (4)", "Fig. 8 (3)", "Fig. 12"])
['Figs 5-8 and 12']
>>> capped(["Table 1", "Sec. 6", "Abstract", "Fig. 3", "Fig. 9"])
'Table 1, Sec. 6, Abstract and 2 more'
>>> join_words(["a"]), join_words(["a", "b"]), join_words(["a", "b", "c"])
('a', 'a and b', 'a, b and c')
"""

from __future__ import annotations

import re
from collections.abc import Iterable, Sequence

__all__ = ["MAX_LABELS", "capped", "compress", "join_words", "number_list", "refs"]

#: the most labels a summary names for one group of rows before "and N more"
MAX_LABELS = 3
_NUMBERED = re.compile(r"^([A-Z][A-Za-z]*\.?)\s+(\d+)(\s*\(.*\))?$")


def join_words(items: Sequence[str]) -> str:
    """``a``, ``a and b``, ``a, b and c``."""
    items = [i for i in items if i]
    if len(items) <= 1:
        return "".join(items)
    return ", ".join(items[:-1]) + " and " + items[-1]


def _split(text: str, sep: str) -> list[str]:
    """``text`` split at ``sep`` outside parentheses."""
    out, depth, start, i = [], 0, 0, 0
    while i < len(text):
        c = text[i]
        depth += c == "("
        depth -= c == ")"
        if depth == 0 and text.startswith(sep, i):
            out.append(text[start:i])
            start = i = i + len(sep)
            continue
        i += 1
    out.append(text[start:])
    return [p.strip() for p in out if p.strip()]


def refs(label: str) -> list[str]:
    """The references of a label: split at ``;``, ``,`` and `` and `` outside parentheses."""
    out: list[str] = []
    for part in _split(str(label), ";"):
        for piece in _split(part, ","):
            out += _split(piece, " and ")
    return out


def _plural(prefix: str) -> str:
    """``Table`` -> ``Tables``, ``Fig.`` -> ``Figs``, ``Sec.`` -> ``Secs``."""
    return prefix.rstrip(".") + "s"


def number_list(numbers: Iterable[int]) -> str:
    """Whole numbers as runs: ``1-2``, ``5-8 and 12``, ``1, 3 and 9``."""
    xs = sorted(set(numbers))
    runs: list[list[int]] = []
    for x in xs:
        if runs and x == runs[-1][-1] + 1:
            runs[-1].append(x)
        else:
            runs.append([x])
    return join_words([f"{r[0]}-{r[-1]}" if len(r) > 1 else str(r[0]) for r in runs])


def compress(labels: Iterable[str]) -> list[str]:
    """Distinct references, those with one prefix word and a whole number merged (in the order
    of the prefix's first appearance; a parenthesis after the number is dropped when merged)."""
    order: list[str] = []
    numbered: dict[str, dict[int, set[str]]] = {}
    for label in (str(x).strip() for x in labels):
        m = _NUMBERED.match(label)
        if m:
            prefix = m.group(1)
            if prefix not in numbered:
                numbered[prefix] = {}
                order.append(f"#{prefix}")
            numbered[prefix].setdefault(int(m.group(2)), set()).add(label)
        elif label and label not in order:
            order.append(label)
    out = []
    for key in order:
        if not key.startswith("#"):
            out.append(key)
            continue
        prefix, by_number = key[1:], numbered[key[1:]]
        if len(by_number) > 1:
            out.append(f"{_plural(prefix)} {number_list(by_number)}")
            continue
        ((number, raw),) = by_number.items()  # one reference: as the label had it, if one
        out.append(next(iter(raw)) if len(raw) == 1 else f"{prefix} {number}")
    return out


def capped(units: Sequence[str], most: int = MAX_LABELS) -> str:
    """At most ``most`` of ``units`` joined, then "and N more"."""
    units = list(dict.fromkeys(u for u in units if u))
    if len(units) <= most:
        return join_words(units)
    return ", ".join(units[:most]) + f" and {len(units) - most} more"
