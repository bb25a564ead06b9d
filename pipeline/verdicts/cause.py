"""The root cause of a verdict that is not reproduced or not upheld.

A paper package attaches a :class:`Cause` to what it found (``Found.cause``,
``ClaimResult.cause``) when it knows why a number or a claim fails: the same ``Cause``
object for every row it explains, so the summary counts a root cause once and lists its rows
(one method's wrong formula explains a table row, the next table's row and three claims).
The cause is written only on rows that are not reproduced or not upheld: a cause never
turns a verdict, it explains one.

A cause has a ``title``, a fixed short phrase naming the root cause (the summary's grouping
key, what a reader scans: at most :data:`TITLE_WORDS` words), and a ``text``, the full
sentence computed from the results with the numbers it rests on.

>>> c = Cause("unpublished", "the flight trajectory is not published",
...           "the paper does not publish the flight trajectory (ours: 3 banks)")
>>> c.kind, c.title
('unpublished', 'the flight trajectory is not published')
>>> Cause("typo", "x", "x")
Traceback (most recent call last):
...
ValueError: cause kind 'typo': allowed: one of ['paper_error', 'unpublished', 'model']
>>> Cause("model", "a title that goes on and on for far more words than a reader scans", "x")
Traceback (most recent call last):
...
ValueError: cause title 'a title that goes on and on for far more words than a reader scans': 15 words; allowed: a phrase of 1 to 12 words
"""

from __future__ import annotations

from dataclasses import dataclass

from pipeline.columns import CAUSE_KINDS

__all__ = ["FAILED", "TITLE_WORDS", "Cause", "cause_columns"]

#: The verdicts a cause explains.
FAILED = ("not_reproduced", "not_upheld")
#: The most words a cause's title may have.
TITLE_WORDS = 12


@dataclass(frozen=True)
class Cause:
    """``kind``: one of :data:`pipeline.columns.CAUSE_KINDS`; ``title``: a short fixed phrase
    (at most :data:`TITLE_WORDS` words, no final full stop); ``text``: one plain sentence."""

    kind: str
    title: str
    text: str

    def __post_init__(self) -> None:
        if self.kind not in CAUSE_KINDS:
            raise ValueError(f"cause kind {self.kind!r}: allowed: one of {list(CAUSE_KINDS)}")
        words = len(self.title.split())
        if not 1 <= words <= TITLE_WORDS or self.title.rstrip().endswith("."):
            raise ValueError(
                f"cause title {self.title!r}: {words} words; allowed: a phrase of 1 to "
                f"{TITLE_WORDS} words"
                + (" without a final full stop" if self.title.rstrip().endswith(".") else "")
            )
        if not self.text.strip():
            raise ValueError("cause text: empty; allowed: one plain sentence")


def cause_columns(verdict: str, cause: Cause | None) -> dict[str, str]:
    """The ``cause_kind``, ``cause`` (the title) and ``cause_detail`` (the text) columns of a
    row with this verdict.

    >>> cause_columns("reproduced", Cause("model", "t", "x"))
    {'cause_kind': '', 'cause': '', 'cause_detail': ''}
    >>> cause_columns("not_upheld", Cause("model", "t", "x"))
    {'cause_kind': 'model', 'cause': 't', 'cause_detail': 'x'}
    """
    if cause is None or verdict not in FAILED:
        return {"cause_kind": "", "cause": "", "cause_detail": ""}
    return {"cause_kind": cause.kind, "cause": cause.title, "cause_detail": cause.text}
