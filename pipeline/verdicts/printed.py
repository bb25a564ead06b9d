"""Printed numbers: their precision, and whether a computed value equals one to that precision.

A published number is kept as the string the paper prints (``"50.0050"``, ``"88"``,
``"4.85e-8"``), so its precision is known: the unit of its last printed digit. A computed value
*equals the printed value to the printed precision* when rounding it to the printed digits, or
truncating it to them, gives the printed number (papers do both; north-finding Table 8 prints
1.0000199 for 1.00001999999).

>>> unit("50.0050"), unit("88"), unit("4.85e-8")
(0.0001, 1.0, 1e-10)
>>> equals_printed(1.0000199999907, "1.0000199")  # truncated
(True, 'truncated')
>>> equals_printed(50.00504, "50.0050")  # rounded
(True, 'rounded')
>>> equals_printed(50.00516, "50.0050")
(False, '')
"""

from __future__ import annotations

import math

__all__ = [
    "REL_SLACK",
    "decimals",
    "equals_printed",
    "fmt_full",
    "fmt_printed_plus",
    "half_unit",
    "unit",
]

#: Relative floating-point slack added to every printed-precision comparison.
REL_SLACK = 1e-12


def _parts(printed: str) -> tuple[int, int]:
    """(number of decimals of the mantissa, exponent) of a printed number string."""
    text = printed.strip().lower()
    mantissa, _, exponent = text.partition("e")
    return len(mantissa.partition(".")[2]), int(exponent) if exponent else 0


def decimals(printed: str) -> int:
    """Decimal places of the last printed digit (negative above the units).

    >>> decimals("50.0050"), decimals("88"), decimals("4.85e-8")
    (4, 0, 10)
    """
    places, power = _parts(printed)
    return places - power


def unit(printed: str) -> float:
    """The unit of the last printed digit: ``"22.3"`` -> 0.1, ``"4.85e-8"`` -> 1e-10.

    >>> unit("22.3")
    0.1
    """
    places, power = _parts(printed)
    return float(f"1e{power - places}")


def half_unit(printed: str) -> float:
    """Half a unit of the last printed digit: ``"88"`` -> 0.5, ``"0.000003614"`` -> 5e-10.

    >>> half_unit("88"), half_unit("0")
    (0.5, 0.5)
    """
    return 0.5 * unit(printed)


def equals_printed(ours: float, printed: str) -> tuple[bool, str]:
    """Whether ``ours`` rounded or truncated (toward zero) to the printed digits is ``printed``.

    Returns ``(True, "rounded")``, ``(True, "truncated")`` or ``(False, "")``. A floating-point
    slack of :data:`REL_SLACK` x max(|ours|, |printed|) is allowed at every edge.

    >>> equals_printed(88.4, "88"), equals_printed(88.6, "88"), equals_printed(88.99, "88")
    ((True, 'rounded'), (True, 'truncated'), (True, 'truncated'))
    >>> equals_printed(89.0, "88"), equals_printed(-2.57, "-2.5"), equals_printed(-2.45, "-2.5")
    ((False, ''), (True, 'truncated'), (True, 'rounded'))
    >>> equals_printed(float("nan"), "1")
    (False, '')
    """
    if not math.isfinite(ours):
        return False, ""
    value = float(printed)
    step = unit(printed)
    slack = REL_SLACK * max(abs(ours), abs(value))
    if abs(ours - value) <= 0.5 * step + slack:
        return True, "rounded"
    # truncation toward zero: |value| <= |ours| < |value| + step, same sign (or a printed 0)
    same_side = value == 0 or (ours > 0) == (value > 0)
    if same_side and abs(value) - slack <= abs(ours) < abs(value) + step - slack:
        return True, "truncated"
    return False, ""


def fmt_full(x: float) -> str:
    """A reproduced value with 15 significant digits (shows any sub-digit difference).

    >>> fmt_full(1.0000199999907), fmt_full(88.0)
    ('1.0000199999907', '88')
    """
    return f"{x:.15g}"


def fmt_printed_plus(x: float, printed: str, extra: int = 2) -> str:
    """``x`` with the printed number's decimals plus ``extra`` digits (at least 0 decimals).

    >>> fmt_printed_plus(0.895123, "0.16"), fmt_printed_plus(2248.38, "2400")
    ('0.8951', '2248.38')
    >>> fmt_printed_plus(float("nan"), "1")
    'nan'
    """
    if not math.isfinite(x):
        return f"{x}"
    return f"{x:.{max(0, decimals(printed) + extra)}f}"
