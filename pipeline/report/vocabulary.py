"""One vocabulary for every report: the words a reader sees for the tokens of the result files.

The CSVs keep their tokens (``not_reproduced``, ``differs``, ``paper_error``); the HTML and
the PDF show the words below, in one colour scheme (``tone``): green for what agrees, red
for what fails (a printed equation is red only when it is an error of the paper), amber for
a difference that is no error of the paper, grey for what cannot be checked (and for a
difference the seed text cannot tell to be the paper's or the OCR's).

>>> word("not_reproduced"), word("upheld"), differs_word("text_artefact"), differs_word("")
('not reproduced', 'upheld', 'artefact of the text', 'unclassified')
>>> tone("differs", "paper_error"), tone("differs", "convention"), tone("not_upheld")
('bad', 'partial', 'bad')
>>> tone("differs", "unclear_from_text"), differs_word("unclear_from_text")
('neutral', 'cannot tell from the text')
>>> plain_words("rank 100 (not_reproduced); not_checkable: no value")
'rank 100 (not reproduced); not checkable: no value'
"""

from __future__ import annotations

import re

__all__ = [
    "ROW_ID",
    "CAUSE_SHORT_WORDS",
    "CAUSE_WORDS",
    "DIFFERS_WORDS",
    "MARK_WORDS",
    "NEUTRAL_DIFFERS",
    "TOKENS",
    "WORDS",
    "cause_short",
    "cause_word",
    "differs_word",
    "plain_words",
    "tone",
    "word",
]

#: the one column header under which a report shows verdict-row ids (``T9.psi.A3``,
#: ``C2/proposed_simulated``), for cross-reference with verdicts.csv; nowhere else
ROW_ID = "row id"

#: verdict and status tokens -> the words shown
WORDS = {
    "match": "match",
    "differs": "differs",
    "not_checkable": "not checkable",
    "reproduced": "reproduced",
    "consistent": "consistent",
    "not_reproduced": "not reproduced",
    "upheld": "upheld",
    "not_upheld": "not upheld",
    "missing": "missing",
}
#: every token a report cell may hold alone (shown as its word, in its colour)
TOKENS = frozenset(WORDS)
#: the ``kind`` of a ``differs`` row of equation_audit.csv (pipeline.columns.DIFFERS_KINDS);
#: blank or absent: not classified yet
DIFFERS_WORDS = {
    "paper_error": "error of the paper",
    "text_artefact": "artefact of the text",
    "convention": "approximation or convention",
    "unclear_from_text": "cannot tell from the text",
}
#: the kinds of a difference shown neutral (grey), neither an error nor a judged non-error
NEUTRAL_DIFFERS = frozenset({"unclear_from_text"})
#: the ``cause_kind`` of a failing verdict row (pipeline.columns.CAUSE_KINDS)
CAUSE_WORDS = {
    "paper_error": "error of the paper",
    "unpublished": "cannot be reproduced from what the paper publishes (not refuted)",
    "model": "our model or scenario differs from the paper's",
}
#: the same kinds in a word or two, where a summary names many causes in one sentence (the
#: introduction gives each its full words)
CAUSE_SHORT_WORDS = {
    "paper_error": "error of the paper",
    "unpublished": "unpublished",
    "model": "our model",
}
#: main-claim marks (pipeline.verdicts.main_claims.MARKS) -> the words shown
MARK_WORDS = {"Re": "[Re]", "not_Re": "[¬Re]", "not_checkable": "not checkable"}

_GOOD = {"match", "reproduced", "consistent", "upheld", "Re"}
_BAD = {"not_reproduced", "not_upheld", "not_Re"}
_RAW = re.compile(r"\b(not_reproduced|not_upheld|not_checkable)\b")


def word(token: str) -> str:
    """The word shown for a verdict or status token (any other text unchanged)."""
    return WORDS.get(token.strip(), token)


def differs_word(kind: str) -> str:
    """The words for the kind of a printed equation that differs."""
    return DIFFERS_WORDS.get(kind.strip(), "unclassified" if not kind.strip() else kind)


def cause_word(kind: str) -> str:
    """The words for the kind of a root cause; blank: not identified."""
    return CAUSE_WORDS.get(kind.strip(), "cause not identified" if not kind.strip() else kind)


def cause_short(kind: str) -> str:
    """The short words for the kind of a root cause; blank: not identified."""
    return CAUSE_SHORT_WORDS.get(kind.strip(), cause_word(kind))


def tone(token: str, differs_kind: str = "") -> str:
    """``good``, ``bad``, ``partial`` or ``neutral``: the colour of a token. A ``differs`` is
    bad only as an error of the paper; one the seed text cannot decide is neutral (grey); another
    difference is partial (amber)."""
    token = token.strip()
    if token == "differs":
        if differs_kind.strip() in NEUTRAL_DIFFERS:
            return "neutral"
        return "bad" if differs_kind.strip() == "paper_error" else "partial"
    if token in _GOOD:
        return "good"
    if token in _BAD:
        return "bad"
    return "neutral"


def plain_words(text: str) -> str:
    """``text`` with every raw verdict token inside it replaced by its word."""
    return _RAW.sub(lambda m: WORDS[m.group(1)], text)
