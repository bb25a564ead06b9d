"""What the seed text shows where a printed equation differs, and the kind that follows.

The rule of :mod:`derivations.checks` as a table: an audit check names its ``discrepancy``
(a key of :data:`DISCREPANCIES`) and :func:`kind_of` gives its ``kind`` (one of
``pipeline.columns.DIFFERS_KINDS``), so the same discrepancy has the same kind in every
paper. "One mark of the kind this OCR misreads" rests on what the seed texts show elsewhere:
a subscript read as a denominator (the north-finding paper's eq. 58: omega_2 as '2'), two-line numerators
read as fractions or sums (eqs. 52, 57), a symbol read as another (the platform-drift paper's eqs. 30,
34: 'a' for alpha; 28: 'k_l' for k_I), a dot lost (eq. 35) and a subscript lost
(the altimeter-attitude paper's eq. 12a: x for x_k). A slip of one mark is the paper's only when the
seed text repeats it or later equations carry it on; a missing or wrong term, factor or
operator is the paper's when the seed text renders it legibly.

>>> [kind_of(d) for d in DISCREPANCIES]  # doctest: +NORMALIZE_WHITESPACE
['convention', 'convention', 'paper_error', 'paper_error', 'text_artefact',
 'unclear_from_text']
"""

from __future__ import annotations

from collections.abc import Iterable

__all__ = ["DISCREPANCIES", "kind_of", "inconsistencies"]

#: what the seed text shows where a printed equation differs -> (its kind, the test). The order
#: is the order of precedence: a row with several discrepancies takes the first that applies.
DISCREPANCIES: dict[str, tuple[str, str]] = {
    "approximation": (
        "convention",
        "the paper drops or lumps terms on purpose (small angles, a higher-order term) and "
        "uses the approximate form consistently",
    ),
    "notation": (
        "convention",
        "a sign, frame or notation convention of the paper or of its source, in which the "
        "printed form is right",
    ),
    "wrong_term": (
        "paper_error",
        "a term, factor, operator or function is missing, extra or wrong (more than one mark) "
        "in an equation the seed text renders legibly and coherently",
    ),
    "repeated_slip": (
        "paper_error",
        "a one-mark slip that the seed text renders coherently in two or more places (both "
        "rows, both arguments, two equations) or that later equations carry on",
    ),
    "visible_garble": (
        "text_artefact",
        "the seed text is visibly broken where it differs (stacked lines read as a fraction "
        "or a sum, a line displaced to another block) and undoing the break gives the "
        "derived form",
    ),
    "one_mark": (
        "unclear_from_text",
        "one mark, once, in a coherent rendering: a sign, an exponent, a transpose, a "
        "subscript, one symbol read as another, or the extent of one fraction bar or root, "
        "which this OCR is seen to misread; the text cannot tell the paper's slip from the "
        "OCR's",
    ),
}


def kind_of(discrepancy: str) -> str:
    """The kind of a ``differs`` from what the seed text shows (:data:`DISCREPANCIES`).

    >>> kind_of("one_mark"), kind_of("repeated_slip"), kind_of("visible_garble")
    ('unclear_from_text', 'paper_error', 'text_artefact')
    >>> kind_of("typo")  # doctest: +ELLIPSIS
    Traceback (most recent call last):
    ...
    ValueError: discrepancy 'typo' is not one of approximation, notation, wrong_term, ...
    """
    if discrepancy not in DISCREPANCIES:
        raise ValueError(f"discrepancy {discrepancy!r} is not one of {', '.join(DISCREPANCIES)}")
    return DISCREPANCIES[discrepancy][0]


def inconsistencies(rows: Iterable[tuple[str, str, str]]) -> list[str]:
    """The breaches of the rule among ``(equation, discrepancy, kind)`` of differing rows (of
    one paper or of several): a row without a known discrepancy, a kind that is not the one
    its discrepancy gives, and one discrepancy given two kinds.

    >>> rows = [("58", "one_mark", "unclear_from_text"), ("67", "one_mark", "paper_error")]
    >>> for line in inconsistencies(rows):
    ...     print(line)
    eq. 67: one_mark gives unclear_from_text, the row says paper_error
    one_mark has two kinds: paper_error (67), unclear_from_text (58)
    >>> inconsistencies([("23", "visible_garble", "text_artefact"), ("9", "typo", "paper_error")])
    ["eq. 9: no known discrepancy ('typo')"]
    """
    out: list[str] = []
    kinds: dict[str, dict[str, list[str]]] = {}
    for equation, discrepancy, kind in rows:
        if discrepancy not in DISCREPANCIES:
            out.append(f"eq. {equation}: no known discrepancy ({discrepancy!r})")
            continue
        if kind != kind_of(discrepancy):
            out.append(
                f"eq. {equation}: {discrepancy} gives {kind_of(discrepancy)}, the row says {kind}"
            )
        kinds.setdefault(discrepancy, {}).setdefault(kind, []).append(equation)
    for discrepancy, by_kind in kinds.items():
        if len(by_kind) > 1:
            parts = ", ".join(f"{k} ({', '.join(eqs)})" for k, eqs in sorted(by_kind.items()))
            out.append(f"{discrepancy} has two kinds: {parts}")
    return out
