"""The front matter of the PDF report: the title page (title, abstract, and per paper its
status, its main claims marked [Re] or [¬Re] and its three sentences, then the counts per
paper) and the table of contents.
"""

from __future__ import annotations

from pipeline.report.model import Document, MainClaims, ScoreRow
from pipeline.report.scoreboard import AUDIT_WORDS, CLAIM_WORDS, NUMBER_WORDS, SELF_CHECK_WORDS
from pipeline.report.typst_blocks import BlockRenderer
from pipeline.report.typst_source import breakable, escape
from pipeline.report.vocabulary import word

__all__ = ["contents", "title_page"]

# the scoreboard's words, in its order (one list for the HTML, the PDF and the counts)
_AUDIT, _NUMBERS, _CLAIMS, _CHECKS = AUDIT_WORDS, NUMBER_WORDS, CLAIM_WORDS, SELF_CHECK_WORDS


def _tone(status: str) -> str:
    s = status.lower()
    return "good" if s.startswith("full") else "bad" if s.startswith("not") else "partial"


def _paper(r: BlockRenderer, row: ScoreRow) -> list[str]:
    s = row.summary
    if s is None:
        return []
    out = [
        f"#block(above: 0.9em, below: 0.4em, sticky: true)[*{r.anchor_link(row.anchor, row.title)}* "
        f'#h(0.4em) #text(weight: "bold", fill: {_tone(s.status)}, hyphenate: false)'
        f"[{escape(s.status)}]]"
    ]
    if s.main_claims:
        out.append(r.main_claims(MainClaims(list(s.main_claims))))
    out += [f"#par[{r.text(t)}]" for t in s.sentences]
    return out


def _counts(r: BlockRenderer, rows: list[ScoreRow]) -> str:
    head1 = (
        "table.cell(rowspan: 2, align: left + bottom)[Paper], "
        f"table.cell(colspan: {len(_AUDIT)})[Equations audited], "
        f"table.cell(colspan: {len(_NUMBERS)})[Published numbers], "
        f"table.cell(colspan: {len(_CLAIMS)})[Claims], "
        f"table.cell(colspan: {len(_CHECKS)})[Self-checks]"
    )
    words = (*_AUDIT, *_NUMBERS, *_CLAIMS, *_CHECKS)
    differs = words.index("differs")
    failing = {i for i, w in enumerate(words) if w in ("not_reproduced", "not_upheld")}
    sub = [word(w) for w in words]
    head2 = ", ".join("[" + escape(s).replace(" ", " \\ ") + "]" for s in sub)
    body = []
    for row in rows:
        cells = [str(row.audit.get(k, 0)) for k in _AUDIT]
        cells += [str(row.numbers.get(k, 0)) for k in _NUMBERS]
        cells += [str(row.claims.get(k, 0)) for k in _CLAIMS]
        cells += [str(row.self_checks.get(k, 0)) for k in _CHECKS]
        errors = int(row.differs.get("paper_error", 0))
        classified = any(n for k, n in row.differs.items() if k)
        shown = []
        for i, c in enumerate(cells):
            if i == differs and c != "0":  # a difference is red only as an error of the paper
                colour = "bad" if errors else "partial"
                note = (
                    f"{errors} {'error' if errors == 1 else 'errors'} of the paper"
                    if classified
                    else "not classified"
                )
                shown.append(
                    f'[#text(fill: {colour}, weight: "bold")[{c}] \\ #text(size: 6.5pt)[{note}]]'
                )
            elif i in failing and c != "0":
                shown.append(f'text(fill: bad, weight: "bold")[{c}]')
            else:
                shown.append(f"[{c}]")
        body.append(f"[{r.anchor_link(row.anchor, row.title)}], " + ", ".join(shown))
    return (
        "#text(size: 8pt, table(\n"
        # the paper's title gets a fixed share; the counts split the rest (with four groups,
        # auto-width counts would squeeze the title to a word a line)
        f"  columns: (3.6cm,) + (1fr,) * {len(words)},\n"
        "  align: (x, y) => if x == 0 { left } else { center },\n"
        "  fill: (x, y) => if y < 2 { headfill },\n"
        f"  table.header({head1}, {head2}),\n  " + ",\n  ".join(body) + ",\n))"
    )


def title_page(r: BlockRenderer, doc: Document) -> str:
    """The title page (it flows onto a second page if the papers' summaries need one)."""
    out = [
        "#page(numbering: none)[",
        "#set par(justify: false)",
        "#set text(size: 8.6pt)",
        "#set par(spacing: 0.6em)",
        f'#align(center, text(size: 16pt, weight: "bold")[{escape(doc.title)}])',
        "#v(1mm)",
    ]
    if doc.subtitle:
        out.append(f"#align(center, text(size: 11pt)[{escape(doc.subtitle)}])")
    out.append("#v(2mm)")
    if doc.abstract:
        out.append(f"#block(inset: (x: 6mm))[*Abstract.* {r.text(doc.abstract)}]")
    for row in doc.scoreboard:
        out += _paper(r, row)
    if doc.scoreboard:
        out.append("#v(2mm)")
        out.append(_counts(r, doc.scoreboard))
    if doc.generated_from:
        out.append(
            f"#text(size: 8pt, fill: neutral)[Generated from git describe "
            f"{breakable(doc.generated_from)}.]"
        )
    out.append(contents())
    out.append("]")
    return "\n".join(out)


def contents() -> str:
    """The table of contents (top-level sections and appendices), after the title matter on
    its last page, then a page break: the body's pages are numbered from 1."""
    return (
        "#block(above: 6mm, text(size: 9pt, outline(title: [Contents], depth: 1, indent: auto)))\n"
        "#pagebreak()"
    )
