"""Config values, claim predicates and row ids in a reader's words: no JSON, no braces.

A report shows where a scenario file decides something (a mapping, a list of maneuvers) and
the rule a claim is judged by (its predicate); both are data, and the reader gets them as
plain text: ``key = value`` pairs, entries of a list separated by ``;``, the paper's own words
for its tokens (``names`` of the published file). Verdict-row ids (``T9.psi.A3``,
``C2/proposed_simulated``) are for cross-reference with verdicts.csv only: :func:`row_labels`
names rows by the paper's labels instead.

>>> plain_value({"xy": 10.0, "xz": 10.0}), plain_value([1, 2.5]), plain_value(True)
('xy = 10.0, xz = 10.0', '1, 2.5', 'yes')
>>> plain_value([{"channel": "alpha_deg", "start_s": 20.0}, {"channel": "speed_m_s"}])
'channel = alpha_deg, start_s = 20.0; channel = speed_m_s'
>>> plain_value({"mode": "scan", "limits": {"lo": 1, "hi": 2}})
'mode = scan, limits (lo = 1, hi = 2)'
>>> predicate_sentence({"test": "argmax", "methods": ["L1", "L4"], "expect": "L4"},
...                    {"L1": "method 1", "L4": "method 4"})
'test argmax, with methods = method 1, method 4; expect = method 4'
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from typing import Any

__all__ = ["plain_value", "predicate_sentence", "row_labels"]


def _scalar(value: Any, words: Callable[[str], str]) -> str:
    if isinstance(value, bool):
        return "yes" if value else "no"
    if value is None:
        return "none"
    if isinstance(value, str):
        return words(value)
    return str(value)


def plain_value(value: Any, words: Callable[[str], str] = str) -> str:
    """A config value as plain text (``words`` maps a string token to the paper's words)."""
    if isinstance(value, Mapping):
        parts = []
        for k, v in value.items():
            if isinstance(v, Mapping):
                parts.append(f"{k} ({plain_value(v, words)})")
            else:
                parts.append(f"{k} = {plain_value(v, words)}")
        return ", ".join(parts)
    if isinstance(value, (list, tuple)):
        sep = "; " if any(isinstance(v, (Mapping, list, tuple)) for v in value) else ", "
        return sep.join(plain_value(v, words) for v in value)
    return _scalar(value, words)


def predicate_sentence(predicate: Mapping[str, Any], names: Mapping[str, str]) -> str:
    """A claim's predicate as a sentence: its test, then its arguments in the paper's words."""
    words = lambda t: names.get(t, t)  # noqa: E731
    args = [f"{k} = {plain_value(v, words)}" for k, v in predicate.items() if k != "test"]
    test = str(predicate.get("test", ""))
    return f"test {test}" + (f", with {'; '.join(args)}" if args else "")


def row_labels(
    ids: Sequence[str], published: Mapping[str, Any], names: Mapping[str, str] | None = None
) -> list[str]:
    """Rows named by the paper's label and method (``Table 9, azimuth method 1 case 1``),
    from the published file's items; an id the file does not list stays as it is.

    >>> row_labels(["T9.psi.A1"], {"items": [{"id": "T9.psi.A1", "label": "Table 9",
    ...            "select": {"method": "A1"}}], "names": {"A1": "azimuth method 1"}})
    ['Table 9, azimuth method 1']
    """
    words = dict(names if names is not None else published.get("names") or {})
    items = {str(i["id"]): i for i in published.get("items") or []}
    out = []
    for row in ids:
        item = items.get(str(row).split("/", 1)[0])
        if item is None:
            out.append(str(row))
            continue
        method = (item.get("select") or {}).get("method")
        out.append(str(item["label"]) + (f", {words.get(method, method)}" if method else ""))
    return out
