"""One paper's section of the combined report, assembled from the sections the paper's
report contributes (:class:`~pipeline.report.model.PaperReport`): summary, equation audit,
published vs reproduced, figures, assumptions, findings beyond the paper, notebook.

The page sections are reused as they are, their ids prefixed with the paper's slug; a
subsection holding one table becomes that table, and nesting deeper than two levels is
merged into its parent (the PDF's heading depth stays at three).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass

from pipeline.report.model import (
    Block,
    Figure,
    Link,
    PaperReport,
    Paragraph,
    ScoreRow,
    Section,
    Table,
)
from pipeline.report.scoreboard import plural

__all__ = ["PaperParts", "paper_section", "prefixed"]


@dataclass(frozen=True)
class PaperParts:
    """What a paper's section is built from (all read or computed from its results)."""

    slug: str
    title: str
    citation: str
    score: ScoreRow
    report: PaperReport
    equations: Section
    published: Section | None  # None: the report's own published sections are used


def prefixed(section: Section, prefix: str) -> Section:
    """``section`` and its subsections with ids ``<prefix>-<id>``."""
    return Section(
        f"{prefix}-{section.id}",
        section.title,
        section.blocks,
        [prefixed(s, prefix) for s in section.subsections],
    )


def _inline_single_tables(section: Section) -> Section:
    """A subsection holding one table and nothing else becomes that table, captioned
    with the subsection's title (keeps the PDF's heading depth at three)."""
    blocks: list[Block] = list(section.blocks)
    subs: list[Section] = []
    for sub in section.subsections:
        sub = _inline_single_tables(sub)
        if not sub.subsections and len(sub.blocks) == 1 and isinstance(sub.blocks[0], Table):
            t = sub.blocks[0]
            cap = sub.title if not t.caption else f"{sub.title}: {t.caption}"
            blocks.append(Table(t.columns, t.rows, cap, t.highlight, t.row_status))
        else:
            subs.append(sub)
    return Section(section.id, section.title, blocks, subs)


def _flatten_deep(section: Section, depth: int, max_depth: int = 2) -> Section:
    """Sections nested deeper than ``max_depth`` (counted from a page section at ``depth``
    1) are merged into their parent: their title captions their first uncaptioned table,
    or opens a paragraph."""
    if depth < max_depth:
        return Section(
            section.id,
            section.title,
            section.blocks,
            [_flatten_deep(s, depth + 1, max_depth) for s in section.subsections],
        )
    blocks: list[Block] = list(section.blocks)
    for sub in section.subsections:
        sub = _flatten_deep(sub, depth + 1, max_depth)
        inner = list(sub.blocks)
        k = next((i for i, b in enumerate(inner) if isinstance(b, Table) and not b.caption), None)
        if k is None:
            inner.insert(0, Paragraph(f"{sub.title}:"))
        else:
            t = inner[k]
            assert isinstance(t, Table)
            inner[k] = Table(t.columns, t.rows, sub.title, t.highlight, t.row_status)
        blocks += inner
    return Section(section.id, section.title, blocks, [])


def _part(p: PaperParts, key: str) -> tuple[list[Block], list[Section]]:
    """Blocks and subsections of the page sections the paper lists for ``key``: the first
    section's blocks and subsections, the others as subsections."""
    blocks: list[Block] = []
    subs: list[Section] = []
    for i, sid in enumerate(p.report.parts.get(key) or []):
        sec = p.report.section(sid)
        if sec is None:
            raise ValueError(
                f"paper {p.slug}: report part {key!r} names section {sid!r}, which its report "
                f"does not have (sections: {[s.id for s in p.report.sections]})"
            )
        sec = _flatten_deep(_inline_single_tables(prefixed(sec, p.slug)), depth=1)
        if i == 0:
            blocks += sec.blocks
            subs += sec.subsections
        else:
            subs.append(sec)
    return blocks, subs


def _figures(section: Section) -> list[Figure]:
    out = [b for b in section.blocks if isinstance(b, Figure)]
    for s in section.subsections:
        out += _figures(s)
    return out


def _extra(block: Block) -> bool:
    return isinstance(block, Figure) and not block.in_paper


def paper_section(p: PaperParts) -> Section:
    """The paper's section: its reference, then the parts in the documented order."""
    blocks, subs = _part(p, "summary")
    summary = Section(
        f"{p.slug}-summary",
        "Summary",
        [
            Paragraph(p.score.line),
            *blocks,
            Link(f"The per-paper page with every detail: {p.slug}.html", f"{p.slug}.html"),
        ],
        subs,
    )
    if p.published is not None:
        published = p.published
    else:
        blocks, subs = _part(p, "published")
        subs = [s if s.title else Section(s.id, "Claims", s.blocks, s.subsections) for s in subs]
        published = Section(f"{p.slug}-published", "Published vs reproduced", blocks, subs)
    # the paper's figures; figures not in the paper (and subsections holding only such
    # figures) go to the findings
    blocks, subs = _part(p, "figures")
    extra = [b for b in blocks if _extra(b)]
    keep = [b for b in blocks if not _extra(b)]
    keep_subs: list[Section] = []
    extra_subs: list[Section] = []
    for s in subs:
        figs = _figures(s)
        (extra_subs if figs and all(not f.in_paper for f in figs) else keep_subs).append(s)
    figs = [b for b in keep if isinstance(b, Figure)]
    intro = Paragraph(
        f"{plural(len(figs), 'figure')} in the paper's numbering, redrawn from our results"
        "; where the paper prints a value, it is overlaid. Figures that are not in the paper "
        "are under Findings beyond the paper."
    )
    non_fig = [b for b in keep if not isinstance(b, Figure)]
    figures = Section(f"{p.slug}-figures", "Figures", [intro, *non_fig, *figs], keep_subs)
    blocks, subs = _part(p, "assumptions")
    if not any(isinstance(b, Paragraph) for b in blocks):
        blocks.insert(
            0,
            Paragraph(
                "Where the paper is silent, each scenario file decides; the value shown is read "
                "from the file at the named field."
            ),
        )
    assumptions = Section(f"{p.slug}-assumptions", "Assumptions", blocks, subs)
    blocks, subs = _part(p, "findings")
    findings = Section(
        f"{p.slug}-findings", "Findings beyond the paper", [*blocks, *extra], subs + extra_subs
    )
    notebook = Section(
        f"{p.slug}-notebook",
        "Notebook",
        [
            Paragraph(
                "The notebook steps through the SymPy derivations of this paper and the "
                "equation audit; the workflow executed it and exported it to HTML beside this "
                "report."
            ),
            Link(f"Executed notebook: notebooks/{p.slug}.html", f"notebooks/{p.slug}.html"),
        ],
    )
    # the heading is the paper's title: the intro gives only the reference
    intro_blocks: Sequence[Block] = (
        [Paragraph(f"Reproduced paper: {p.citation}.".replace("..", "."))] if p.citation else []
    )
    return Section(
        p.slug,
        p.title,
        list(intro_blocks),
        [summary, p.equations, published, figures, assumptions, findings, notebook],
    )
