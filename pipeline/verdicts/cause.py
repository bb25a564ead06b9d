"""The root cause of a verdict that is not reproduced or not upheld.

A paper package attaches a :class:`Cause` to what it found (``Found.cause``,
``ClaimResult.cause``) when it knows why a number or a claim fails: the same ``Cause``
object for every row it explains, so the summary counts a root cause once and lists its rows
(one method's wrong formula explains a table row, the next table's row and three claims).
The cause is written only on rows that are not reproduced or not upheld: a cause never
turns a verdict, it explains one.

>>> c = Cause("unpublished", "the paper does not publish the flight trajectory")
>>> c.kind, c.text
('unpublished', 'the paper does not publish the flight trajectory')
>>> Cause("typo", "x")
Traceback (most recent call last):
...
ValueError: cause kind 'typo': allowed: one of ['paper_error', 'unpublished', 'model']
"""

from __future__ import annotations

from dataclasses import dataclass

from pipeline.columns import CAUSE_KINDS

__all__ = ["FAILED", "Cause", "cause_columns"]

#: The verdicts a cause explains.
FAILED = ("not_reproduced", "not_upheld")


@dataclass(frozen=True)
class Cause:
    """``kind``: one of :data:`pipeline.columns.CAUSE_KINDS`; ``text``: one plain sentence."""

    kind: str
    text: str

    def __post_init__(self) -> None:
        if self.kind not in CAUSE_KINDS:
            raise ValueError(f"cause kind {self.kind!r}: allowed: one of {list(CAUSE_KINDS)}")
        if not self.text.strip():
            raise ValueError("cause text: empty; allowed: one plain sentence")


def cause_columns(verdict: str, cause: Cause | None) -> dict[str, str]:
    """The ``cause_kind`` and ``cause`` columns of a row with this verdict.

    >>> cause_columns("reproduced", Cause("model", "x"))
    {'cause_kind': '', 'cause': ''}
    >>> cause_columns("not_upheld", Cause("model", "x"))
    {'cause_kind': 'model', 'cause': 'x'}
    """
    if cause is None or verdict not in FAILED:
        return {"cause_kind": "", "cause": ""}
    return {"cause_kind": cause.kind, "cause": cause.text}
