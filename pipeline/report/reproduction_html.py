"""HTML renderer of the combined reproduction report (``reports/reproduction.html``).

Renders a :class:`pipeline.report.document.Document` as ONE self-contained file: inline
CSS, figures as base64 ``data:`` URIs, mathematics as inline MathML (rendered natively by
the browser), no JavaScript and nothing fetched from a network. The output is
deterministic: the same document gives the same bytes.

Layout: title, the scoreboard (one row per paper plus its ReScience-style line, linking to
the paper's section), a numbered table of contents, then the numbered sections (the PDF
uses the same numbers).
"""

from __future__ import annotations

import os
import re
from collections.abc import Sequence
from pathlib import Path

from pipeline.atomic import write_text
from pipeline.report import html as H
from pipeline.report.blocks_html import Anchors, render_section
from pipeline.report.model import Document, ScoreRow, Section

__all__ = ["CSS", "render_html", "section_numbers", "write_html"]

CSS = (
    H.DEFAULT_CSS
    + """
body { max-width: 1400px; }
header.title h1 { font-size: 2em; margin-bottom: 0.1em; }
header.title p.subtitle { font-size: 1.1em; color: #333; margin-top: 0; }
header.title p.generated { color: #666; font-size: 0.9em; }
h2 a, h3 a, h4 a, h5 a { color: inherit; text-decoration: none; }
span.secno { color: #666; margin-right: 0.4em; font-variant-numeric: tabular-nums; }
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
table.scoreboard tr.line td { font-size: 0.9em; color: #222; background: #fafafa;
                              border-bottom: 2px solid #666; }
table.scoreboard tr.line td strong.full { color: #1d6b1d; }
table.scoreboard tr.line td strong.partial { color: #8a5a00; }
table.scoreboard tr.line td strong.none { color: #a3261a; }
table.scoreboard ul.reasons { margin: 0.15em 0 0.1em 0; padding-left: 1.3em; }
table.scoreboard ul.reasons li { margin: 0.05em 0; }
table.scoreboard a.ref { font-family: ui-monospace, monospace; font-size: 0.92em; }
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
table.equations tr.v-differs td { background: #fdf0ee; }
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


# --------------------------------------------------------------------------- numbering


def section_numbers(sections: Sequence[Section]) -> dict[str, str]:
    """Section id -> its number ("1", "2.3", "2.3.1"), in document order (as in the PDF)."""
    out: dict[str, str] = {}

    def walk(items: Sequence[Section], prefix: str) -> None:
        for i, s in enumerate(items, 1):
            num = f"{prefix}{i}"
            out[s.id] = num
            walk(s.subsections, f"{num}.")

    walk(sections, "")
    return out


# --------------------------------------------------------------------------- front matter

_GROUPS = (
    ("Equations audited", "audit", ("match", "differs", "not_checkable")),
    ("Published numbers", "numbers", ("reproduced", "consistent", "not_reproduced")),
    ("Claims", "claims", ("upheld", "not_upheld", "not_checkable")),
)
_TONE = {
    "match": "good",
    "reproduced": "good",
    "consistent": "good",
    "upheld": "good",
    "differs": "bad",
    "not_reproduced": "bad",
    "not_upheld": "bad",
    "not_checkable": "neutral",
}
_SHORT = {"not_checkable": "not checkable", "not_reproduced": "not reproduced"}


_TOKEN = re.compile(r"[A-Za-z0-9_./]+")  # ids, with a "/variant" suffix


def _linked(text: str, targets: dict[str, str]) -> str:
    """``text`` escaped, each whole word that is a key of ``targets`` linked to its anchor."""
    out, pos = [], 0
    for m in _TOKEN.finditer(text):
        word = m.group(0).rstrip(".")
        anchor = targets.get(word)
        if anchor is None:
            continue
        out.append(H.escape(text[pos : m.start()]))
        out.append(f'<a class="ref" href="#{H.escape(anchor)}">{H.escape(word)}</a>')
        pos = m.start() + len(word)
    out.append(H.escape(text[pos:]))
    return "".join(out)


def _scoreboard(
    rows: Sequence[ScoreRow],
    numbers: dict[str, str] | None = None,
    anchors: Anchors | None = None,
) -> str:
    n_cols = 1 + sum(len(w) for _, _, w in _GROUPS)
    groups = "".join(
        f'<th colspan="{len(words)}" class="first">{H.escape(name)}</th>'
        for name, _, words in _GROUPS
    )
    words = "".join(
        f'<th class="{"first" if i == 0 else ""}">{H.escape(_SHORT.get(w, w.replace("_", " ")))}</th>'
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
                cls = ["n", _TONE.get(w, "neutral")]
                if n == 0:
                    cls.append("zero")
                if i == 0:
                    cls.append("first")
                cells.append(
                    f'<td class="{" ".join(cls)}" data-group="{attr}" data-word="{w}">{n}</td>'
                )
        extra = [
            f"{w}: {n}"
            for _, attr, ws in _GROUPS
            for w, n in getattr(r, attr).items()
            if w not in ws
        ]
        totals = " · ".join(
            f"{sum(getattr(r, attr).values())} {noun}"
            for attr, noun in (("audit", "equations"), ("numbers", "numbers"), ("claims", "claims"))
        )
        body.append(
            f'<tr class="counts" id="score-{H.escape(r.slug)}">'
            f'<td class="paper"><a href="#{H.escape(r.anchor)}">{H.escape(r.title)}</a>'
            f'<span class="slug">{H.escape(r.slug)}: {totals}</span></td>{"".join(cells)}</tr>\n'
        )
        status, _, rest = r.line.partition(":")
        tone = (
            "full"
            if status.lower().startswith("full")
            else "none"
            if status.lower().startswith("not")
            else "partial"
        )
        warn = f" (unexpected words: {H.escape(', '.join(extra))})" if extra else ""
        # one reason per line: the line's sentences end with ". " (ids have no spaces)
        reasons = [x.strip() for x in re.split(r"(?<=\.)\s+", rest.strip()) if x.strip()]
        targets = anchors.rows.get(r.slug, {}) if anchors is not None else {}
        items = "".join(f"<li>{_linked(x, targets)}</li>" for x in reasons)
        body.append(
            f'<tr class="line"><td colspan="{n_cols}"><strong class="{tone}">'
            f"{H.escape(status)}</strong>{warn} "
            f'<a href="#{H.escape(r.anchor)}">see section '
            f"{H.escape((numbers or {}).get(r.anchor, r.anchor))}</a>"
            f'<ul class="reasons">{items}</ul></td></tr>\n'
        )
    return (
        '<table class="scoreboard" id="scoreboard">\n'
        "<caption>Scoreboard</caption>\n"
        f'<thead><tr class="groups"><th rowspan="2" class="paper">Paper</th>{groups}</tr>\n'
        f'<tr class="words">{words}</tr></thead>\n'
        f"<tbody>\n{''.join(body)}</tbody>\n</table>\n"
    )


def _toc(sections: Sequence[Section], numbers: dict[str, str], depth: int = 2) -> str:
    def items(secs: Sequence[Section], level: int) -> str:
        out = []
        for s in secs:
            sub = items(s.subsections, level + 1) if level < depth and s.subsections else ""
            out.append(
                f'<li><a href="#{H.escape(s.id)}"><span class="secno">{numbers[s.id]}</span>'
                f"{H.escape(s.title)}</a>{sub}</li>\n"
            )
        return "<ul>\n" + "".join(out) + "</ul>\n"

    return f'<nav class="toc" id="contents">\n<h2>Contents</h2>\n{items(sections, 1)}</nav>\n'


def render_html(doc: Document) -> str:
    """The whole report as one self-contained HTML document (a ``str``)."""
    numbers = section_numbers(doc.sections)
    # the sections first: they hand out the row anchors the scoreboard links to
    anchors = Anchors(papers={r.slug for r in doc.scoreboard})
    sections = "".join(render_section(s, numbers, 2, anchors) for s in doc.sections)
    body = (
        '<header class="title">\n'
        f"<h1>{H.escape(doc.title)}</h1>\n"
        f'<p class="subtitle">{H.escape(doc.subtitle)}</p>\n'
        f'<p class="generated">Generated from the workflow\'s results at git describe '
        f"<code>{H.escape(doc.generated_from)}</code>.</p>\n</header>\n"
    )
    body += _scoreboard(doc.scoreboard, numbers, anchors)
    body += (
        '<p class="legend">Each number counts rows of the paper\'s equation_audit.csv or '
        "verdicts.csv. Green: the paper and this reproduction agree (a printed equation matches "
        "the derivation; a published number is reproduced exactly or is consistent with the "
        "Monte Carlo spread; a claim holds). Red: they disagree (a printed equation differs, "
        "usually a typo, and the derived form is used; a number or claim is not reproduced). "
        "Grey: not checkable. "
        'Each paper\'s name links to its section; <a href="#how-to-read">how to read '
        "this report</a>.</p>\n"
    )
    body += _toc(doc.sections, numbers)
    body += sections
    return H.page(doc.title, body, css=CSS)


def write_html(doc: Document, path: str | os.PathLike[str]) -> Path:
    """Render ``doc`` and write it atomically to ``path`` (pipeline.atomic)."""
    return write_text(path, render_html(doc))
