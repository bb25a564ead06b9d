"""HTML of the document model's blocks and sections (:mod:`pipeline.report.model`), shared by
the combined report (:mod:`pipeline.report.reproduction_html`) and the per-paper pages
(:mod:`pipeline.report.page_html`): tables (verdict words coloured), equation audits with
MathML forms, figures as ``data:`` URIs, bulleted lists, links and nested sections.

>>> print(render_block(Paragraph("a < b")), end="")
<p>a &lt; b</p>
"""

from __future__ import annotations

import html.entities
import re
from dataclasses import dataclass, field
from pathlib import Path

from pipeline.report import html as H
from pipeline.report.equations import equation_groups, equation_list
from pipeline.report.model import (
    Block,
    Bullets,
    EquationRow,
    EquationTable,
    Figure,
    Link,
    MainClaims,
    Paragraph,
    Section,
    Table,
)
from pipeline.report.vocabulary import (
    MARK_WORDS,
    TOKENS,
    differs_word,
    plain_words,
    tone,
    word,
)

__all__ = ["Anchors", "render_block", "render_section", "render_sections", "section_numbers"]


def _cell(text: str) -> str:
    """A table cell: a verdict or status token alone is shown as its word, in its colour."""
    token = text.strip()
    if token in TOKENS:
        return f'<span class="{H.css_class(token)} t-{tone(token)}">{H.escape(word(token))}</span>'
    return H.escape(plain_words(text))


def section_numbers(sections: list[Section], appendices: list[Section] = ()) -> dict[str, str]:
    """Section id -> its number ("1", "2.3", "2.3.1"; appendices "A", "A.1"), in document
    order (as in the PDF)."""
    out: dict[str, str] = {}

    def walk(items: list[Section], prefix: str, top: list[str] | None = None) -> None:
        for i, s in enumerate(items, 1):
            num = f"{prefix}{top[i - 1] if top else i}"
            out[s.id] = num
            walk(s.subsections, f"{num}.")

    walk(list(sections), "")
    walk(list(appendices), "", [chr(ord("A") + k) for k in range(len(appendices))])
    return out


_NUM_ATTR = ' class="num"'
_NUMERIC = re.compile(r"^[+-]?(\d+(\.\d*)?|\.\d+)([eE][+-]?\d+)?$")


@dataclass
class Anchors:
    """Row anchors handed out while rendering: an element id for the first row of each published
    item or claim (a table whose first column is ``id``) and each audited equation of a paper;
    ``rows`` maps a paper's item/claim ids to theirs, so the scoreboard can link the ids it
    names (equations are not linked from there: its sentences are full of other numbers)."""

    papers: set[str]
    paper: str = ""
    rows: dict[str, dict[str, str]] = field(default_factory=dict)
    used: set[str] = field(default_factory=set)

    def claim(self, kind: str, key: str) -> str | None:
        """A fresh element id for ``key`` (None outside a paper or if ``key`` has one)."""
        if not self.paper or not key:
            return None
        anchor = f"{kind}-{H.slugify(self.paper)}-{H.slugify(key)}"
        if anchor in self.used:
            return None
        self.used.add(anchor)
        if kind == "row":  # "F5.3.crossover/proposed_simulated" is also "F5.3.crossover"
            table = self.rows.setdefault(self.paper, {})
            table.setdefault(key, anchor)
            table.setdefault(key.split("/")[0], anchor)
        return anchor


def _id_attr(anchor: str | None) -> str:
    return f' id="{H.escape(anchor)}"' if anchor else ""


def _table(t: Table, anchors: Anchors | None = None, status_rows: bool = False) -> str:
    """``status_rows``: each row's class is its status word (``v-<word>``, a page's colours)
    where the table has them; otherwise highlighted rows are ``bad``."""
    hl = set(t.highlight)
    keyed = anchors is not None and bool(t.columns) and t.columns[0] == "id"
    parts = ['<div class="scroll"><table class="data">\n']
    if t.caption:
        parts.append(f"<caption>{H.escape(t.caption)}</caption>\n")
    notes = len(t.notes) == len(t.rows) and any(n.strip() for n in t.notes)
    if any(t.columns):
        head = "".join(f"<th>{_cell(c)}</th>" for c in t.columns)
        head += "<th>note</th>" if notes else ""
        parts.append(f"<thead><tr>{head}</tr></thead>\n")
    parts.append("<tbody>\n")
    for i, row in enumerate(t.rows):
        if status_rows and t.row_status:
            # a row's status word; "differs" (of unknown kind) is amber, not a failure's red
            cls = f' class="{H.css_class(t.row_status[i])}"'
        else:
            cls = ' class="bad"' if i in hl else ""
        if keyed and row:
            cls += _id_attr(anchors.claim("row", row[0].strip()))
        cells = "".join(
            f"<td{_NUM_ATTR if _NUMERIC.match(c.strip()) else ''}>{_cell(c)}</td>" for c in row
        )
        if notes:
            cells += f'<td class="note">{H.escape(plain_words(t.notes[i]))}</td>'
        parts.append(f"<tr{cls}>{cells}</tr>\n")
    parts.append("</tbody>\n</table></div>\n")
    return "".join(parts)


_NAMED_ENTITY = re.compile(r"&([A-Za-z][A-Za-z0-9]*);")
_XML_ENTITIES = {"amp", "lt", "gt", "quot", "apos"}


def _numeric_entities(markup: str) -> str:
    """Named character references (``&InvisibleTimes;``) as numeric ones, so every MathML
    fragment is also well-formed XML; unknown names are left as they are."""

    def repl(m: re.Match[str]) -> str:
        name = m.group(1)
        if name in _XML_ENTITIES:
            return m.group(0)
        text = html.entities.html5.get(f"{name};")
        return "".join(f"&#{ord(c)};" for c in text) if text else m.group(0)

    return _NAMED_ENTITY.sub(repl, markup)


def _math(mathml: str | None) -> str:
    """A MathML element in a scroll box (a long expression scrolls instead of widening the
    table); nothing if absent."""
    if mathml and mathml.lstrip().startswith("<math"):
        return f'<div class="m">{_numeric_entities(mathml)}</div>'
    return ""


def _forms(r: EquationRow) -> str:
    """The printed, derived and residual forms of one audited equation, one per line (the
    printed and derived forms once if they are the same expression)."""
    out = []
    if r.printed_mathml and r.printed_srepr and r.printed_srepr == r.derived_srepr:
        out.append(("printed = derived", _math(r.printed_mathml)))
    else:
        out += [("printed", _math(r.printed_mathml)), ("derived", _math(r.derived_mathml))]
    if r.status != "match" and r.residual_mathml:
        out.append(("residual", _math(r.residual_mathml)))
    elif r.residual_text and (r.status != "match" or r.residual_text != "0"):
        out.append(("residual", f'<code class="res">{H.escape(r.residual_text)}</code>'))
    items = "".join(f"<dt>{H.escape(k)}</dt><dd>{v}</dd>" for k, v in out if v)
    return f'<dl class="forms">{items}</dl>' if items else ""


def _status(r: EquationRow) -> str:
    """The status of an audited equation in words, a difference with its kind."""
    text = word(r.status) + (f": {differs_word(r.kind)}" if r.status == "differs" else "")
    kind = f" k-{H.slugify(r.kind or 'unclassified')}" if r.status == "differs" else ""
    return (
        f'<span class="{H.css_class(r.status)} t-{tone(r.status, r.kind)}{kind}">'
        f"{H.escape(text)}</span>"
    )


def _equation_row(group: list[EquationRow], anchors: Anchors | None = None) -> str:
    """One audited equation (or a run of form-less ones with the same status and note):
    number and status, then the note and the forms across the table's width."""
    r = group[0]
    claim = anchors.claim if anchors is not None else (lambda kind, key: None)
    row_id = _id_attr(claim("eq", r.equation))
    # every equation of a run keeps an anchor of its own
    spans = "".join(
        f'<span id="{H.escape(a)}"></span>' for g in group[1:] if (a := claim("eq", g.equation))
    )
    label = "Eqs. " if len(group) > 1 else ""
    number = equation_list([g.equation for g in group])
    note = f'<p class="note">{H.escape(plain_words(r.note))}</p>' if r.note else ""
    return (
        f'<tr class="{H.css_class(r.status)} t-{tone(r.status, r.kind)}"{row_id}>'
        f'<td class="eq">{spans}{label}({H.escape(number)})</td>'
        f"<td>{_status(r)}</td>"
        f'<td class="forms">{note}{_forms(r) if len(group) == 1 else ""}</td></tr>\n'
    )


def _equation_table(t: EquationTable, anchors: Anchors | None = None) -> str:
    """The differing and not checkable equations in a table; those that match in a
    collapsed ``<details>`` below it (their forms shown when opened)."""
    head = "".join(
        f"<th>{c}</th>"
        for c in ("eq.", "status", "note; printed (the paper), derived (SymPy), residual")
    )
    cap = f"<caption>{H.escape(t.caption)}</caption>\n" if t.caption else ""
    shown = [r for r in t.rows if r.status != "match"]
    matching = [r for r in t.rows if r.status == "match"]
    rows = "".join(_equation_row(g, anchors) for g in equation_groups(shown))
    out = (
        f'<div class="scroll"><table class="data equations">\n{cap}'
        f"<thead><tr>{head}</tr></thead>\n<tbody>\n{rows}</tbody>\n</table></div>\n"
    )
    if matching:
        names = equation_list([r.equation for r in matching])
        inner = "".join(_equation_row([r], anchors) for r in matching)
        out += (
            f'<details class="matching"><summary>{len(matching)} printed equations match the '
            f"derivation (eqs. {H.escape(names)}): show their forms</summary>\n"
            f'<div class="scroll"><table class="data equations">\n'
            f"<thead><tr>{head}</tr></thead>\n<tbody>\n{inner}</tbody>\n</table></div>\n"
            "</details>\n"
        )
    return out


def _main_claims(b: MainClaims) -> str:
    items = "".join(
        f'<li><span class="mark m-{H.slugify(m.mark)}">{H.escape(MARK_WORDS.get(m.mark, m.mark))}'
        f'</span> {H.escape(m.text)} <span class="where">({H.escape(m.label)})</span>'
        f'<br><span class="basis">{H.escape(plain_words(m.basis))}</span></li>\n'
        for m in b.lines
    )
    return f'<ul class="marks">\n{items}</ul>\n'


def _figure(f: Figure) -> str:
    anchor = "fig-" + H.slugify(f"{Path(f.path).parent.parent.name}-{Path(f.path).stem}")
    cap = f"<figcaption><strong>{H.escape(f.label)}</strong> {H.escape(f.caption)}</figcaption>\n"
    if not Path(f.path).is_file():
        missing = H.escape(f"{f.label} ({Path(f.path).name}): not available.")
        return f'<figure id="{anchor}">\n<p class="na">{missing}</p>\n{cap}</figure>\n'
    return (
        f'<figure id="{anchor}">\n<img src="{H.png_data_uri(f.path)}" '
        f'alt="{H.escape(f.label)}">\n{cap}</figure>\n'
    )


def render_block(b: Block, anchors: Anchors | None = None, status_rows: bool = False) -> str:
    """One block as HTML (see :func:`render_section`)."""
    if isinstance(b, Paragraph):
        return H.paragraph(plain_words(b.text))
    if isinstance(b, Bullets):
        items = "".join(f"<li>{H.escape(plain_words(i))}</li>\n" for i in b.items)
        return f"<ul>\n{items}</ul>\n"
    if isinstance(b, MainClaims):
        return _main_claims(b)
    if isinstance(b, Table):
        return _table(b, anchors, status_rows)
    if isinstance(b, Figure):
        return _figure(b)
    if isinstance(b, EquationTable):
        return _equation_table(b, anchors)
    if isinstance(b, Link):
        return f'<p class="link"><a href="{H.escape(b.target)}">{H.escape(b.text)}</a></p>\n'
    raise TypeError(f"unknown block type {type(b).__name__}")


def render_section(
    s: Section,
    numbers: dict[str, str],
    level: int,
    anchors: Anchors | None = None,
    status_rows: bool = False,
) -> str:
    """A section (heading ``h{level}``, numbered from ``numbers`` where it has a number) with
    its blocks and subsections. ``anchors``: hand out row anchors (the combined report);
    ``status_rows``: colour table rows by their status words (a per-paper page)."""
    h = min(level, 6)
    num = numbers.get(s.id, "")
    if anchors is not None and level == 2:  # a top-level section: a paper's, or not
        anchors.paper = s.id if s.id in anchors.papers else ""
    body = "".join(render_block(b, anchors, status_rows) for b in s.blocks)
    body += "".join(
        render_section(c, numbers, level + 1, anchors, status_rows) for c in s.subsections
    )
    secno = f'<span class="secno">{num}</span>' if num else ""
    return (
        f'<section id="{H.escape(s.id)}">\n'
        f'<h{h}><a href="#{H.escape(s.id)}">{secno}'
        f"{H.escape(s.title)}</a></h{h}>\n{body}</section>\n"
    )


def render_sections(
    sections: list[Section],
    appendices: list[Section],
    numbers: dict[str, str],
    anchors: Anchors | None = None,
    status_rows: bool = False,
) -> str:
    """The numbered sections, then the appendices under a heading of their own."""
    body = "".join(render_section(s, numbers, 2, anchors, status_rows) for s in sections)
    if appendices:
        body += '<h2 class="appendices" id="appendices">Appendices</h2>\n'
        body += "".join(render_section(s, numbers, 2, anchors, status_rows) for s in appendices)
    return body
