"""Numbers as the reports show them: a reproduced value at the printed precision of the
published one plus two digits, and a Monte Carlo value as its median with the 5-95 % band.

verdicts.csv keeps every digit (``reproduced``: 15 significant digits, a statistical row's
median; its ``note`` the band as ``MC 5-95 %: [a, b]``, pipeline.verdicts.kinds); the
reports round them here, so a reader compares like with like.

>>> shown_value("50.0050", "50.0054709908323")
'50.005471'
>>> shown_value("4.85e-8", "4.84813681109501e-08"), shown_value("4.5 km", "4.437 km")
('4.8481e-8', '4.437 km')
>>> shown_value("2400", "never"), shown_value("0 %", "4.26e-14 %")
('never', '0.00 %')
>>> shown_reproduced("statistical", "50.0050", "50.0054709908323",
...                  "MC 5-95 %: [50.00123456, 50.0098761]; noise-free real: 50.005")
'50.005471 [50.001235, 50.009876]'
>>> compact_tolerance("percentile rank in [0.5, 99.5] of 1000 Monte Carlo trials, i.e. any "
...                   "value in [50.0012, 50.0098] (a range 0.0129 % of the published value wide)",
...                   "50.0050")
('[50.001200, 50.009800] (MC 0.5-99.5 %)', '')
>>> compact_tolerance("+-20% of 4.5 km (an 'about' value the authors read off their own plot)", "4.5")
('+-20% of 4.5 km', "an 'about' value the authors read off their own plot")
"""

from __future__ import annotations

import math
import re

from pipeline.report.vocabulary import plain_words

__all__ = [
    "MC_HEADER",
    "compact_reason",
    "compact_tolerance",
    "mc_band",
    "reproduced_header",
    "shown_reproduced",
    "shown_value",
]

#: what the reproduced column of a statistical row holds
MC_HEADER = "MC median [5-95 %]"

_NUMBER = re.compile(r"^\s*([+-]?(?:\d+(?:\.\d*)?|\.\d+))(?:[eE]([+-]?\d+))?(\s*\S*)\s*$")
_BAND = re.compile(r"MC 5-95 %: \[([^,\]]+), ([^\]]+)\]")
_RANK = re.compile(
    r"^percentile rank in \[([\d.]+), ([\d.]+)\] of (\d+) Monte Carlo trials, i\.e\. any value "
    r"in \[([^,\]]+), ([^\]]+)\]"
)


def _parse(text: str) -> tuple[float, int, int | None, str] | None:
    """(value, decimals of the mantissa, exponent or None, unit) of a printed number."""
    m = _NUMBER.match(str(text))
    if m is None:
        return None
    mantissa, exponent, unit = m.group(1), m.group(2), m.group(3).strip()
    try:
        value = float(mantissa) * (10.0 ** int(exponent) if exponent else 1.0)
    except (ValueError, OverflowError):
        return None
    decimals = len(mantissa.partition(".")[2])
    return value, decimals, (int(exponent) if exponent else None), unit


def _format(value: float, printed: tuple[float, int, int | None, str], extra: int = 2) -> str:
    _, decimals, exponent, _ = printed
    if exponent is not None:  # the printed power of ten: the mantissa's digits plus two
        return f"{value / 10.0**exponent:.{decimals + extra}f}e{exponent}"
    return f"{value:.{decimals + extra}f}"


def shown_value(published: str, reproduced: str, extra: int = 2) -> str:
    """``reproduced`` at the printed precision of ``published`` plus ``extra`` digits, with its
    unit; unchanged when either is not a number or their units differ."""
    pub, ours = _parse(published), _parse(reproduced)
    if pub is None or ours is None or pub[3] != ours[3] or not math.isfinite(ours[0]):
        return plain_words(str(reproduced))
    text = _format(ours[0], pub, extra)
    return f"{text} {ours[3]}" if ours[3] else text


def mc_band(note: str) -> tuple[float, float] | None:
    """The 5-95 % band of a statistical row's Monte Carlo (from its note), None if absent."""
    m = _BAND.search(str(note))
    if m is None:
        return None
    try:
        return float(m.group(1)), float(m.group(2))
    except ValueError:
        return None


def shown_reproduced(kind: str, published: str, reproduced: str, note: str = "") -> str:
    """The reproduced cell of a verdict row: our value (exact, approximate), or the Monte Carlo
    median with its 5-95 % band (statistical), at the printed precision plus two digits."""
    value = shown_value(published, reproduced)
    if kind != "statistical":
        return value
    band, pub = mc_band(note), _parse(published)
    if band is None or pub is None or _parse(reproduced) is None:
        return value
    lo, hi = (_format(b, pub) for b in band)
    return f"{value} [{lo}, {hi}]"


def reproduced_header(kinds: list[str]) -> str:
    """The reproduced column's header for rows of these kinds: it says what the cells are."""
    stat = [k == "statistical" for k in kinds]
    if stat and all(stat):
        return MC_HEADER
    if any(stat):
        return f"ours, or {MC_HEADER}"
    return "ours"


def compact_tolerance(tolerance: str, published: str) -> tuple[str, str]:
    """(the tolerance as a table shows it, its reason) of a verdict row: a statistical row's
    band as ``MC 0.5-99.5 % of n trials: [lo, hi]`` at the printed precision plus two digits; a
    trailing parenthesis of more than a few words is the reason, returned apart."""
    text = plain_words(" ".join(str(tolerance).split()))
    m = _RANK.match(text)
    pub = _parse(published)
    if m and pub is not None:
        try:
            lo, hi = (_format(float(m.group(k)), pub) for k in (4, 5))
        except ValueError:
            return text, ""
        return f"[{lo}, {hi}] (MC {m.group(1)}-{m.group(2)} %)", ""
    head, reason = _trailing_parenthesis(text)
    if len(reason) >= 30:
        return compact_reason(head), reason
    return compact_reason(text), ""


def _trailing_parenthesis(text: str) -> tuple[str, str]:
    """(text before, inside) of a balanced parenthesis that ends ``text``; else (text, "")."""
    if not text.endswith(")"):
        return text, ""
    depth = 0
    for i in range(len(text) - 1, -1, -1):
        depth += (text[i] == ")") - (text[i] == "(")
        if depth == 0:
            if i == 0 or text[i - 1] != " ":
                return text, ""
            return text[:i].rstrip(), text[i + 1 : -1]
    return text, ""


_RANK_REASON = re.compile(
    r"^published value at percentile rank ([\d.]+) of (\d+) Monte Carlo trials \((inside|outside)"
)


#: the engine's wordings (pipeline.verdicts.kinds) and their short forms in a table
_SHORT = (
    (re.compile(r"\|ours - printed\| = "), "|ours - printed| "),
    (re.compile(r"^value: ours \S+ (rounded|truncated) to the printed \S+$"), r"\1 to the printed digits"),
    (re.compile(r"^value: the printed digits of (\S+) \(rounding: \+-(\S+); truncation: .*\)\)$"),
     r"the digits of \1 (+-\2 rounded, or truncated)"),
)  # fmt: skip


def compact_reason(reason: str) -> str:
    """A verdict's reason (or an exact tolerance) as a table shows it: a statistical row's as
    its percentile rank, an exact one's in fewer words.

    >>> compact_reason("published value at percentile rank 41.9 of 1000 Monte Carlo trials "
    ...                "(inside [0.5, 99.5])")
    'percentile rank 41.9 (inside)'
    >>> compact_reason("value: ours 88 rounded to the printed 88")
    'rounded to the printed digits'
    >>> compact_reason("value: the printed digits of 88 (rounding: +-0.5; truncation: [88, +1))")
    'the digits of 88 (+-0.5 rounded, or truncated)'
    """
    text = plain_words(" ".join(str(reason).split()))
    m = _RANK_REASON.match(text)
    if m:
        return f"percentile rank {m.group(1)} ({m.group(3)})"
    for pattern, short in _SHORT:
        text = pattern.sub(short, text)
    return text
