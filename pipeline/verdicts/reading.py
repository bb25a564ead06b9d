"""The tolerance of an approximate number, from how the paper printed it (one rule, every paper).

An approximate item states ``printed_as``, never a free tolerance:

``about``
    The text prints the value as "about X" ("approximately", Persian "حدود", "به طور تقریبی").
    A number printed to some digits is the value rounded to its last significant digit (+- half
    a unit); "about" says the rounding itself is loose, so the neighbouring values X +- one unit
    of that digit are still "about X". A number printed with many digits ("about 22") still
    reads, in common usage, as a round figure within about a tenth of itself, so the tolerance
    has a floor: **max(one unit of the last significant digit, 10 % of |X|)**
    (:data:`ABOUT_FLOOR`). Trailing zeros of an integer are not significant ("about 2400" is 24
    hundreds: unit 100).
``plot``
    The value is a point of a plotted curve, read off the figure (by the authors, who print it
    without "about", or by us). A curve cannot be read finer than its axis: the tolerance is
    **max(half a tick of the axis it is read on, one unit of the last printed digit)**. The
    axis (range, tick, unit) is stated once per figure in the published file (``figures``), and
    the item names it (``figure: {label: ..., axis: x|y}``).

Plus, for both, two standard errors of ours when ours is a Monte Carlo estimate
(:mod:`pipeline.verdicts.kinds`).

>>> significant_unit("22"), significant_unit("2400"), significant_unit("0.07"), significant_unit("4.5")
(1.0, 100.0, 0.01, 0.1)
>>> limit({"printed_as": "about", "value": "22"})[0]  # 10 % floor above one unit (1)
2.2
>>> limit({"printed_as": "about", "value": "2000"})[0]  # one unit of the 2 (thousands)
1000.0
>>> limit({"printed_as": "plot", "value": "4.5", "axis": {"tick": 1.0, "unit": "km"}})[0]
0.5
"""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from pipeline.verdicts.printed import unit

__all__ = [
    "ABOUT_FLOOR",
    "PRINTED_AS",
    "check_reading",
    "fmt_limit",
    "limit",
    "significant_unit",
    "with_axis",
]

#: the printed forms of an approximate number
PRINTED_AS = ("about", "plot")
#: the smallest tolerance of "about X", as a share of |X|
ABOUT_FLOOR = 0.1


def significant_unit(printed: str) -> float:
    """One unit of the last significant digit of a printed number: the unit of its last printed
    digit, except that trailing zeros of an integer mantissa are not significant."""
    text = printed.strip().lower()
    mantissa, _, exponent = text.partition("e")
    digits = mantissa.lstrip("-")
    if "." in digits or set(digits) <= {"0"}:
        return unit(printed)
    zeros = len(digits) - len(digits.rstrip("0"))
    return float(10**zeros) * 10.0 ** (int(exponent) if exponent else 0)


def fmt_limit(x: float) -> str:
    """A tolerance in 3 significant digits, without an exponent from 1000 to 1e6.

    >>> fmt_limit(1000.0), fmt_limit(0.016), fmt_limit(2.2)
    ('1000', '0.016', '2.2')
    """
    return f"{x:.0f}" if 1e3 <= abs(x) < 1e6 else f"{x:.3g}"


_g = fmt_limit


def limit(item: Mapping[str, Any]) -> tuple[float, str]:
    """(|ours - published| allowed before any Monte Carlo error, the rule in words) of an
    approximate item; a ``plot`` item carries its figure's axis (``axis``, :func:`with_axis`)."""
    printed = str(item["value"])
    one = significant_unit(printed)
    if item["printed_as"] == "about":
        floor = ABOUT_FLOOR * abs(float(printed))
        return max(one, floor), (
            f"printed as 'about {printed}': one unit of its last significant digit "
            f"({_g(one)}) or {ABOUT_FLOOR:.0%} of it ({_g(floor)}), the larger"
        )
    axis = item["axis"]
    half = 0.5 * float(axis["tick"])
    where = (
        f"{item['figure']['label']}, {item['figure']['axis']} axis" if "figure" in item else "plot"
    )
    return max(half, unit(printed)), (
        f"read off {where} (tick {_g(float(axis['tick']))} {axis['unit']}): half a tick "
        f"({_g(half)}) or one unit of the printed digit ({_g(unit(printed))}), the larger"
    )


def with_axis(item: Mapping[str, Any], figures: Mapping[str, Any] | None) -> Mapping[str, Any]:
    """The item, with the axis its ``figure`` names resolved from the file's ``figures`` (a
    ``plot`` item); any other item unchanged."""
    if item.get("printed_as") != "plot" or not figures:
        return item
    ref = item["figure"]
    return {**item, "axis": figures[ref["label"]][ref["axis"]]}


def check_reading(
    item: Mapping[str, Any], figures: Mapping[str, Any] | None
) -> list[tuple[str, Any, str]]:
    """(field, bad value, allowed) of every problem of an approximate item's printed form that
    the schema cannot find: a ``plot`` item without a figure axis stated in ``figures``."""
    if item.get("kind") != "approximate" or item.get("printed_as") != "plot":
        return []
    ref = item.get("figure")
    if not isinstance(ref, Mapping):
        return [("figure", None, "for printed_as 'plot': {label: <a key of figures>, axis: x|y}")]
    known = sorted(figures or {})
    if ref.get("label") not in known:
        return [("figure.label", ref.get("label"), f"a figure stated under 'figures': {known}")]
    axes = sorted((figures or {})[ref["label"]])
    if ref.get("axis") not in axes:
        return [("figure.axis", ref.get("axis"), f"an axis {ref['label']!r} states: {axes}")]
    return []
