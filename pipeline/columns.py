"""Column names of the results files (the results contract of DESIGN.md).

Columns every paper shares (the equation audit and the verdicts); each paper's own result
columns live in ``pipeline/<slug>/columns.py``. Every reader and writer of a results CSV
imports its columns from one of them, so a rename happens in one place. Units are carried in the names (``_deg``,
``_ug``, ``_rad_s``, ``_pct``).
"""

from __future__ import annotations

# results/<slug>/equation_audit.csv; ``kind`` (one of DIFFERS_KINDS) is written on ``differs``
# rows only and is blank on the others
AUDIT_COLUMNS = ["equation", "status", "residual", "note", "kind"]
AUDIT_STATUSES = ("match", "differs", "not_checkable")
#: what a ``differs`` is, with the label a report shows for it. The kind follows from what the
#: seed text shows (derivations.discrepancies.DISCREPANCIES, one rule for every paper):
#: paper_error: the printed mathematics, legible and coherent in the seed text, is wrong and
#: would give wrong numbers if used as printed (beyond one mark, or one mark that recurs or is
#: carried into later equations);
#: text_artefact: the seed text is visibly broken there (OCR, layout: stacked lines read as a
#: fraction, a displaced line), and undoing the break gives the right equation;
#: convention: an approximation or a convention the paper chose (small angles, a dropped term,
#: a sign, frame or notation convention), in which the printed form is right;
#: unclear_from_text: one mark, once (a sign, exponent, transpose, subscript, one symbol read as
#: another, a bar's extent), of the kind this OCR misreads: the text cannot tell a slip of the
#: paper from one of the OCR. Only paper_error is shown as a failure.
DIFFERS_KINDS = {
    "paper_error": "error of the paper",
    "text_artefact": "artefact of the text",
    "convention": "approximation or convention",
    "unclear_from_text": "cannot tell from the text",
}

# results/<slug>/verdicts.csv
VERDICT_COLUMNS = ["id", "kind", "quantity", "method", "published", "reproduced", "verdict", "note"]
# written after the contract columns: the tolerance a verdict applied and the reason it follows
# and, for a row that is not reproduced or not upheld, its root cause: ``cause_kind`` (one of
# CAUSE_KINDS), ``cause`` (its title: a short fixed phrase, the same for every row it explains,
# so the summary groups rows by it) and ``cause_detail`` (the full sentence computed from the
# results, with the numbers it rests on)
VERDICT_EXTRA_COLUMNS = ["tolerance", "reason", "cause_kind", "cause", "cause_detail"]
#: paper_error: the paper's own formula, table or text is wrong (shown with the evidence);
#: unpublished: the number depends on what the paper does not publish (trajectory, rates,
#: tuning, metric), so it cannot be reproduced from the paper: not refuted;
#: model: our model or the scenario differs from the paper's in a way the row names.
CAUSE_KINDS = ("paper_error", "unpublished", "model")
VERDICT_FILE_COLUMNS = VERDICT_COLUMNS + VERDICT_EXTRA_COLUMNS
VERDICT_KINDS = ("exact", "approximate", "statistical", "claim")
# exact, approximate -> reproduced | not_reproduced; statistical -> consistent | not_reproduced;
# claim -> upheld | not_upheld; any kind -> not_checkable (pipeline/verdicts/kinds.py, claims.py)
VERDICTS = ("reproduced", "consistent", "not_reproduced", "upheld", "not_upheld", "not_checkable")
