"""HTML renderer of the combined reproduction report (``reports/reproduction.html``).

Renders a :class:`pipeline.report.document.Document` as ONE self-contained file: inline
CSS, figures as base64 ``data:`` URIs, mathematics as inline MathML (rendered natively by
the browser), no JavaScript and nothing fetched from a network. The output is
deterministic: the same document gives the same bytes.

Layout: title, abstract, the papers in brief (per paper its status, its main claims marked
[Re] or [¬Re] and three sentences), the counts per paper, a numbered table of contents, then
the numbered sections and the appendices A, B, ... (the PDF uses the same numbers).
"""

from __future__ import annotations

import os
from collections.abc import Sequence
from pathlib import Path

from pipeline.atomic import write_text
from pipeline.report import html as H
from pipeline.report.blocks_html import Anchors, render_block, render_sections, section_numbers
from pipeline.report.model import Document, MainClaims, Paragraph, ScoreRow, Section
from pipeline.report.scoreboard import AUDIT_WORDS, CLAIM_WORDS, NUMBER_WORDS, SELF_CHECK_WORDS
from pipeline.report.vocabulary import tone, word

__all__ = ["CSS", "paper_summaries", "render_html", "section_numbers", "write_html"]

CSS = (
    H.DEFAULT_CSS
    + """
body { max-width: 1400px; }
header.title h1 { font-size: 2em; margin-bottom: 0.1em; }
header.title p.subtitle { font-size: 1.1em; color: #333; margin-top: 0; }
header.title p.generated { color: #666; font-size: 0.9em; }
table.scoreboard { border-collapse: collapse; width: 100%; margin: 0.6em 0 1.4em 0;
                   font-size: 0.95em; }
table.scoreboard caption { text-align: left; font-weight: bold; font-size: 1.15em;
                           padding: 0.3em 0; }
table.scoreboard th, table.scoreboard td { border: 1px solid #bbb; padding: 0.3em 0.5em; }
table.scoreboard thead th { background: #eef0f3; text-align: center; }
table.scoreboard thead tr.groups th { font-size: 1.0em; }
table.scoreboard thead tr.words th { font-weight: normal; font-size: 0.85em; }
table.scoreboard th.paper { text-align: left; vertical-align: bottom; }
table.scoreboard td.paper { font-weight: bold; }
table.scoreboard td.paper a { color: #0b3d91; }
table.scoreboard td.paper span.slug { display: block; font-weight: normal; color: #666;
                                      font-size: 0.85em; font-family: monospace; }
table.scoreboard td.n { text-align: center; font-size: 1.25em; font-weight: bold;
                        font-variant-numeric: tabular-nums; width: 4.2em; }
table.scoreboard td.n.zero { color: #aaa; font-weight: normal; }
table.scoreboard td.good { background: #eaf6ea; color: #1d6b1d; }
table.scoreboard td.bad { background: #fbe3e1; color: #a3261a; }
table.scoreboard td.neutral { background: #f3f3f3; color: #444; }
table.scoreboard td.n.zero { background: #fff; }
table.scoreboard .first { border-left: 2px solid #666; }
table.scoreboard td.partial { background: #fff4d6; color: #8a5a00; }
table.scoreboard span.kinds { display: block; font-size: 0.6em; font-weight: normal; }
strong.status.full { color: #1d6b1d; }
strong.status.partial { color: #8a5a00; }
strong.status.none { color: #a3261a; }
strong.status { font-size: 0.85em; margin-left: 0.5em; }
span.sref { font-size: 0.75em; color: #666; font-weight: normal; margin-left: 0.5em; }
section.summaries h3 { margin-bottom: 0.2em; }
div.paper-summary { border-left: 3px solid #ccd; padding-left: 0.9em; margin: 0.8em 0 1.4em 0; }
h2.appendices { border-bottom: 3px double #999; }
tr:target > td { background: #fff4c2; }
p.legend { font-size: 0.85em; color: #444; }
nav.toc { background: #f7f8fa; border: 1px solid #ddd; padding: 0.4em 1em; margin: 1em 0; }
nav.toc h2 { border: none; margin: 0.3em 0; font-size: 1.2em; }
nav.toc ul { columns: 1; list-style: none; padding-left: 0; margin: 0.2em 0; }
nav.toc ul ul { padding-left: 1.6em; font-size: 0.95em; }
nav.toc > ul > li { margin-top: 0.35em; }
table.data tr.bad td { background: #fbe3e1; }
div.scroll { overflow-x: auto; max-width: 100%; }
table.equations { width: 100%; }
table.equations td { vertical-align: top; }
table.equations td.eq { font-weight: bold; white-space: nowrap; width: 4.5em; }
table.equations td.forms { width: 100%; }
table.equations dl.forms { display: grid; grid-template-columns: max-content minmax(0, 1fr);
  column-gap: 0.8em; row-gap: 0.3em; margin: 0.2em 0; }
table.equations dl.forms dt { color: #555; font-size: 0.85em; padding-top: 0.35em; }
table.equations dl.forms dd { margin: 0; min-width: 0; }
table.equations div.m { max-height: 24em; overflow: auto; padding: 0.15em 0; }
table.equations p.note { margin: 0.2em 0; font-size: 0.9em; color: #333; }
table.equations tr.v-match td { background: #fff; }
table.equations tr.v-differs td { background: #fff8e6; }
table.equations tr.v-differs.t-bad td { background: #fdf0ee; }
table.equations tr.v-not_checkable td { background: #f7f7f7; }
math { font-size: 1.05em; font-family: "STIX Two Math", "Cambria Math", "Latin Modern Math",
                                       "DejaVu Math TeX Gyre", math; }
code.res { font-size: 0.8em; color: #555; display: block; max-width: 30em;
           overflow-wrap: anywhere; }
figure img { max-width: min(100%, 960px); }
figure figcaption strong { margin-right: 0.3em; }
p.link a { font-weight: bold; }
"""
)


# --------------------------------------------------------------------------- front matter

_GROUPS = (
    ("Equations audited", "audit", AUDIT_WORDS),
    ("Published numbers", "numbers", NUMBER_WORDS),
    ("Claims", "claims", CLAIM_WORDS),
    ("Self-checks", "self_checks", SELF_CHECK_WORDS),
)
_STATUS_TONE = {"full": "full", "not": "none"}


def _status_class(status: str) -> str:
    return _STATUS_TONE.get(status.lower().split(" ")[0], "partial")


def paper_summaries(rows: Sequence[ScoreRow], numbers: dict[str, str]) -> str:
    """The first page's part per paper: its title and status, its main claims with their
    marks, and its three sentences."""
    out = ['<section class="summaries" id="summaries">\n<h2>The papers in brief</h2>\n']
    for r in rows:
        s = r.summary
        if s is None:
            continue
        out.append(
            f'<div class="paper-summary" id="summary-{H.escape(r.slug)}">\n'
            f'<h3><a href="#{H.escape(r.anchor)}">{H.escape(r.title)}</a> '
            f'<strong class="status {_status_class(s.status)}">{H.escape(s.status)}</strong> '
            f'<span class="sref">section {H.escape(numbers.get(r.anchor, ""))}</span></h3>\n'
        )
        if s.main_claims:
            out.append(render_block(MainClaims(list(s.main_claims))))
        out += [render_block(Paragraph(t)) for t in s.sentences]
        out.append("</div>\n")
    out.append("</section>\n")
    return "".join(out)


def _scoreboard(rows: Sequence[ScoreRow], numbers: dict[str, str] | None = None) -> str:
    """The counts per paper (every count from the CSVs; a difference is red only as an error
    of the paper)."""
    groups = "".join(
        f'<th colspan="{len(words)}" class="first">{H.escape(name)}</th>'
        for name, _, words in _GROUPS
    )
    words = "".join(
        f'<th class="{"first" if i == 0 else ""}">{H.escape(word(w))}</th>'
        for _, _, ws in _GROUPS
        for i, w in enumerate(ws)
    )
    body = []
    for r in rows:
        cells = []
        for _, attr, ws in _GROUPS:
            counts = getattr(r, attr)
            for i, w in enumerate(ws):
                n = int(counts.get(w, 0))
                t = tone(w, "paper_error" if r.differs.get("paper_error") else "")
                cls = ["n", t] + (["zero"] if n == 0 else []) + (["first"] if i == 0 else [])
                extra = ""
                if w == "differs" and n:
                    errors = int(r.differs.get("paper_error", 0))
                    words = f"{errors} {'error' if errors == 1 else 'errors'} of the paper"
                    if not any(k and m for k, m in r.differs.items()):
                        words = "not classified"
                    extra = f'<span class="kinds">{words}</span>'
                cells.append(
                    f'<td class="{" ".join(cls)}" data-group="{attr}" data-word="{w}">{n}{extra}</td>'
                )
        body.append(
            f'<tr class="counts" id="score-{H.escape(r.slug)}">'
            f'<td class="paper"><a href="#{H.escape(r.anchor)}">{H.escape(r.title)}</a>'
            f'<span class="slug">section {H.escape((numbers or {}).get(r.anchor, ""))}</span>'
            f"</td>{''.join(cells)}</tr>\n"
        )
    return (
        '<table class="scoreboard" id="scoreboard">\n'
        "<caption>Counts per paper</caption>\n"
        f'<thead><tr class="groups"><th rowspan="2" class="paper">Paper</th>{groups}</tr>\n'
        f'<tr class="words">{words}</tr></thead>\n'
        f"<tbody>\n{''.join(body)}</tbody>\n</table>\n"
    )


def _toc(
    sections: Sequence[Section],
    appendices: Sequence[Section],
    numbers: dict[str, str],
    depth: int = 2,
) -> str:
    def items(secs: Sequence[Section], level: int) -> str:
        out = []
        for s in secs:
            sub = items(s.subsections, level + 1) if level < depth and s.subsections else ""
            out.append(
                f'<li><a href="#{H.escape(s.id)}"><span class="secno">{numbers[s.id]}</span>'
                f"{H.escape(s.title)}</a>{sub}</li>\n"
            )
        return "<ul>\n" + "".join(out) + "</ul>\n"

    apps = f"<h3>Appendices</h3>\n{items(appendices, 1)}" if appendices else ""
    return f'<nav class="toc" id="contents">\n<h2>Contents</h2>\n{items(sections, 1)}{apps}</nav>\n'


def render_html(doc: Document) -> str:
    """The whole report as one self-contained HTML document (a ``str``)."""
    numbers = section_numbers(doc.sections, doc.appendices)
    anchors = Anchors(papers={r.slug for r in doc.scoreboard})
    sections = render_sections(doc.sections, doc.appendices, numbers, anchors)
    body = (
        '<header class="title">\n'
        f"<h1>{H.escape(doc.title)}</h1>\n"
        f'<p class="subtitle">{H.escape(doc.subtitle)}</p>\n'
        f'<p class="generated">Generated from the workflow\'s results at git describe '
        f"<code>{H.escape(doc.generated_from)}</code>.</p>\n</header>\n"
    )
    if doc.abstract:
        body += f'<section class="abstract" id="abstract">\n<h2>Abstract</h2>\n{H.paragraph(doc.abstract)}</section>\n'
    body += paper_summaries(doc.scoreboard, numbers)
    body += _scoreboard(doc.scoreboard, numbers)
    body += (
        '<p class="legend">Each number counts rows of the paper\'s equation_audit.csv or '
        "verdicts.csv. Green: the paper and this reproduction agree. Red: they disagree (a "
        "number or claim is not reproduced; a printed equation is an error of the paper). "
        "Amber: a printed equation differs as an artefact of the text or a convention. Grey: "
        "not checkable, or a printed equation differs where the seed text cannot tell whether "
        'the paper or the OCR slipped. See <a href="#introduction">the introduction</a> for the words.</p>\n'
    )
    body += _toc(doc.sections, doc.appendices, numbers)
    body += sections
    return H.page(doc.title, body, css=CSS)


def write_html(doc: Document, path: str | os.PathLike[str]) -> Path:
    """Render ``doc`` and write it atomically to ``path`` (pipeline.atomic)."""
    return write_text(path, render_html(doc))
