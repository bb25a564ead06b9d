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
    Paragraph,
    Section,
    Table,
)

__all__ = ["Anchors", "render_block", "render_section"]

#: Words that get a verdict colour wherever a table cell holds exactly that word.
_VERDICT_WORDS = {
    "match",
    "differs",
    "not_checkable",
    "reproduced",
    "consistent",
    "not_reproduced",
    "upheld",
    "not_upheld",
    "missing",
}


def _cell(text: str) -> str:
    word = text.strip()
    if word in _VERDICT_WORDS:
        return f'<span class="{H.css_class(word)}">{H.escape(text)}</span>'
    return H.escape(text)


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
    if any(t.columns):
        parts.append(
            "<thead><tr>"
            + "".join(f"<th>{H.escape(c)}</th>" for c in t.columns)
            + "</tr></thead>\n"
        )
    parts.append("<tbody>\n")
    for i, row in enumerate(t.rows):
        if status_rows and t.row_status:
            cls = f' class="{H.css_class(t.row_status[i])}"'
        else:
            cls = ' class="bad"' if i in hl else ""
        if keyed and row:
            cls += _id_attr(anchors.claim("row", row[0].strip()))
        cells = "".join(
            f"<td{_NUM_ATTR if _NUMERIC.match(c.strip()) else ''}>{_cell(c)}</td>" for c in row
        )
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
    note = f'<p class="note">{H.escape(r.note)}</p>' if r.note else ""
    return (
        f'<tr class="{H.css_class(r.status)}"{row_id}>'
        f'<td class="eq">{spans}{label}({H.escape(number)})</td>'
        f'<td><span class="{H.css_class(r.status)}">{H.escape(_words(r.status))}</span></td>'
        f'<td class="forms">{note}{_forms(r) if len(group) == 1 else ""}</td></tr>\n'
    )


def _words(word: str) -> str:
    return word.replace("_", " ")


def _equation_table(t: EquationTable, anchors: Anchors | None = None) -> str:
    head = "".join(
        f"<th>{c}</th>"
        for c in ("eq.", "status", "note; printed (the paper), derived (SymPy), residual")
    )
    cap = f"<caption>{H.escape(t.caption)}</caption>\n" if t.caption else ""
    rows = "".join(_equation_row(g, anchors) for g in equation_groups(t.rows))
    return (
        f'<div class="scroll"><table class="data equations">\n{cap}'
        f"<thead><tr>{head}</tr></thead>\n<tbody>\n{rows}</tbody>\n</table></div>\n"
    )


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
        return H.paragraph(b.text)
    if isinstance(b, Bullets):
        items = "".join(f"<li>{H.escape(i)}</li>\n" for i in b.items)
        return f"<ul>\n{items}</ul>\n"
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
