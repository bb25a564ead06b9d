"""The equation audit in the PDF: every printed equation that differs, with its printed,
derived and residual forms typeset from their SymPy ``srepr``; those that cannot be checked,
one line per run with the same note; those that match, listed by number only (the HTML report
shows their forms).

A matrix is shown by the entries that differ (row, column: printed, derived, residual; at
most :data:`SHOWN_ENTRIES` of them), so a 5 x 5 matrix with one wrong subscript takes one
entry, not twenty-five; a small matrix that differs everywhere is shown whole.
"""

from __future__ import annotations

import re
from collections.abc import Iterable
from typing import Any

from pipeline.report import typst_math as M
from pipeline.report.equations import equation_groups, equation_list
from pipeline.report.model import EquationRow, EquationTable
from pipeline.report.typst_breakable import typst_math_breakable
from pipeline.report.typst_source import escape, raw_block
from pipeline.report.typst_symbols import typst_string
from pipeline.report.vocabulary import differs_word, plain_words, tone, word

__all__ = ["EquationRenderer", "from_srepr"]

#: a matrix with more entries than this is shown by its differing entries only
WHOLE_ENTRIES = 4
#: at most this many differing entries of a matrix are typeset (the HTML report has all)
SHOWN_ENTRIES = 4
_SNIPPETS = re.compile(r"\$([^$]+)\$")


def from_srepr(text: str) -> Any:
    """The SymPy object an srepr string describes (evaluated in SymPy's namespace only)."""
    import sympy as sp

    return eval(text, {"__builtins__": {}}, vars(sp).copy())  # noqa: S307 - our own results


def _status(word_: str, kind: str) -> str:
    return f"#status({typst_string(word_)}, {typst_string(kind)})"


class EquationRenderer:
    """Renders :class:`EquationTable` blocks; collects the math snippets it emits (so the
    compiler can find one that does not typeset) and shows those in ``bad`` as text."""

    def __init__(self, bad: frozenset[str] = frozenset()):
        self.bad = bad
        self.snippets: list[str] = []
        self.stems: dict[str, str] = {}
        # one memo per paper's stems (the printed text depends on them)
        self._memos: dict[tuple[tuple[str, str], ...], M.PrintMemo] = {}
        self.memo = M.PrintMemo()

    # ---- the table ------------------------------------------------------------------------
    def table(self, eqt: EquationTable) -> str:
        self.stems = dict(eqt.stems)  # the paper's own symbol stems, for its forms
        self.memo = self._memos.setdefault(tuple(sorted(self.stems.items())), M.PrintMemo())
        out = []
        if eqt.caption:
            out.append(
                "#block(sticky: true, above: 1.1em, below: 0.5em, "
                f"text(size: 9pt)[*{escape(eqt.caption)}*])"
            )
        out.append("#[#set text(size: 9.5pt)")
        shown = [r for r in eqt.rows if r.status != "match"]
        for group in equation_groups(shown):
            if len(group) == 1 and group[0].status == "differs":
                out.append(self.row(group[0]))
            else:  # rows that cannot be checked: one line per run with the same note
                r = group[0]
                label = "Eqs." if len(group) > 1 else "Eq."
                head = f"[*{label} {escape(equation_list([g.equation for g in group]))}* #h(0.5em) "
                head += _status(word(r.status), tone(r.status))
                head += f" #h(0.5em) {escape(plain_words(r.note))}]" if r.note else "]"
                out.append(f"#eqrow({head})")
        matching = [r.equation for r in eqt.rows if r.status == "match"]
        if matching:
            out.append(
                f"#block(above: 1em)[*{len(matching)} printed equations match the derivation* "
                f"(residual 0; their forms are in the HTML report): eqs. "
                f"{escape(equation_list(matching))}.]"
            )
        out.append("]")
        return "\n".join(out)

    def row(self, row: EquationRow) -> str:
        status = f"{word(row.status)}: {differs_word(row.kind)}"
        head = f"[*Eq. {escape(row.equation)}* #h(0.5em) "
        head += _status(status, tone(row.status, row.kind))
        head += f" #h(0.5em) {escape(plain_words(row.note))}]" if row.note else "]"
        cells = self.forms(row)
        if not cells:
            return f"#eqrow({head})"
        return f"#eqrow({head}, " + ", ".join(cells) + ")"

    # ---- the forms of one differing equation -------------------------------------------------
    def forms(self, row: EquationRow) -> list[str]:
        """Grid cells (label, form) of a differing equation."""
        try:
            printed = from_srepr(row.printed_srepr) if row.printed_srepr else None
            derived = from_srepr(row.derived_srepr) if row.derived_srepr else None
            residual = from_srepr(row.residual_srepr) if row.residual_srepr else None
        except Exception:  # noqa: BLE001 - an unreadable form is shown as text
            cells = [
                f"[{label}], [{raw_block(text)}]"
                for label, text in (("printed", row.printed_srepr), ("derived", row.derived_srepr))
                if text
            ]
            return cells + self._residual_text(row)
        entries = _differing_entries(printed, derived, residual)
        if entries is not None:
            n, k = entries[0], len(entries[1])
            more = (
                f" The first {SHOWN_ENTRIES} are shown; the HTML report has every form."
                if k > SHOWN_ENTRIES
                else ""
            )
            others = "the others match." if k < n else "every entry differs."
            cells = [f"[], [#text(fill: neutral)[{k} of {n} entries differ; {others}{more}]]"]
            for where, p, d, r in entries[1][:SHOWN_ENTRIES]:
                cells += [
                    f"[printed {where}], [{self.math(p)}]",
                    f"[derived {where}], [{self.math(d)}]",
                ]
                cells.append(f"[residual {where}], [{self.math(r)}]")
            return cells
        cells = [
            f"[{label}], [{self.math(e)}]"
            for label, e in (("printed", printed), ("derived", derived))
            if e is not None
        ]
        if residual is not None:
            cells.append(f"[residual], [{self.math(residual)}]")
        return cells + ([] if residual is not None else self._residual_text(row))

    def _residual_text(self, row: EquationRow) -> list[str]:
        if row.residual_text and row.residual_text.strip() not in ("", "0"):
            return [f"[residual], [{raw_block(row.residual_text)}]"]
        return []

    def math(self, expr: Any) -> str:
        """One form typeset (raw text if it does not print or does not typeset)."""
        try:
            full = M.typst_math(expr, memo=self.memo, stems=self.stems)
            alt = self._alt(expr)
        except Exception:  # noqa: BLE001 - any printing failure falls back to the raw form
            return raw_block(_plain(expr))
        snippets = [full, *_SNIPPETS.findall(alt)]
        if any(s in self.bad for s in snippets):
            return raw_block(_plain(expr))
        self.snippets += snippets
        return f"#fitmath($ {full} $, [{alt}])"

    def _alt(self, expr: Any) -> str:
        """The expression as inline math that breaks across lines (a small matrix by entry)."""
        import sympy as sp

        if isinstance(expr, sp.MatrixBase):
            r, c = expr.shape
            cells = []
            for i in range(r):
                for j in range(c):
                    idx = f"({i + 1})" if c == 1 else f"({i + 1}, {j + 1})"
                    text = typst_math_breakable(expr[i, j], memo=self.memo, stems=self.stems)
                    cells.append(f"#text(size: 8.5pt, fill: neutral)[{idx}] ${text}$")
            return " #linebreak() ".join(cells)
        return f"${typst_math_breakable(expr, memo=self.memo, stems=self.stems)}$"


def _plain(expr: Any) -> str:
    import sympy as sp

    return sp.sstr(expr)


def _flat(m: Any) -> list[Any]:
    return [m[i, j] for i in range(m.rows) for j in range(m.cols)]


def _differing_entries(
    printed: Any, derived: Any, residual: Any
) -> tuple[int, list[tuple[str, Any, Any, Any]]] | None:
    """(entries, [(where, printed, derived, residual)]) of the entries of a printed and a
    derived matrix where the residual is not zero, or None when the equation is to be shown
    whole (not a matrix, a residual of another size, or a small matrix differing everywhere)."""
    import sympy as sp

    mats = [printed, derived, residual]
    if not all(isinstance(m, sp.MatrixBase) for m in mats):
        return None
    if printed.shape != derived.shape or len(residual) != len(printed):
        return None
    res = _flat(residual)
    cols = printed.cols
    out = []
    for k, (p, d, r) in enumerate(zip(_flat(printed), _flat(derived), res, strict=True)):
        if r != 0:
            where = f"({k // cols + 1}, {k % cols + 1})" if cols > 1 else f"({k + 1})"
            out.append((where, p, d, r))
    if len(printed) <= WHOLE_ENTRIES and len(out) == len(printed):
        return None
    return len(printed), out


def snippets_of(rendered: Iterable[str]) -> list[str]:
    """The math snippets (between ``$``) of rendered Typst."""
    return [s for text in rendered for s in _SNIPPETS.findall(text)]
