"""One template for a paper, in the combined report and on its own page: the same sections in
the same order, built from its :class:`~pipeline.report.paper_parts.PaperParts`.

Main text: Summary (the same blocks for every paper: the status, on the paper's page the main
claims with their marks and the three sentences, the root causes listed once in full, the
links; the paper's own summary section is kept among its own sections on its page), Equation audit (a statement per differing
equation), Published numbers and Claims (one row per item or claim, its verdict across the
curves or averaging counts it is judged on), Figures (the paper's, in its numbering),
Findings beyond the paper (with the figures the paper lacks). Discussion: the paper's part of
it. Appendices: the equation forms, the supporting results (every verdict row first), the
assumptions, and on the page the paper's further sections.

The paper's page sections are reused as they are, their ids prefixed with the paper's slug
(its own page drops the prefix again);
a subsection holding one table becomes that table, and nesting deeper than two levels is
merged into its parent (the PDF's heading depth stays at three).
"""

from __future__ import annotations

from collections.abc import Sequence

from pipeline.report.causes import causes_blocks, plural
from pipeline.report.equations import equation_appendix, equation_section
from pipeline.report.model import (
    Block,
    Figure,
    Link,
    MainClaims,
    Paragraph,
    Section,
    Table,
)
from pipeline.report.paper_parts import PaperParts

__all__ = [
    "MAIN_TITLES",
    "OVERVIEW",
    "assumptions_section",
    "discussion_section",
    "forms_section",
    "further_sections",
    "paper_section",
    "supporting_section",
    "prefixed",
]

#: the title of the paper's own summary section among its own sections (on its page)
OVERVIEW = "Overview, as the paper's page counts it"

#: the main-text sections of every paper, in order
MAIN_TITLES = (
    "Summary",
    "Equation audit",
    "Published numbers",
    "Claims",
    "Figures",
    "Findings beyond the paper",
)


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


def _used(p: PaperParts) -> set[str]:
    return {sid for ids in p.report.parts.values() for sid in (ids or [])}


def _part(p: PaperParts, key: str, first: bool = False) -> tuple[list[Block], list[Section]]:
    """Blocks and subsections of the page sections the paper lists for ``key``: the first
    section's blocks and subsections, the others as subsections (``first``: the first only)."""
    blocks: list[Block] = []
    subs: list[Section] = []
    ids = list(p.report.parts.get(key) or [])
    for i, sid in enumerate(ids[:1] if first else ids):
        sec = p.report.section(sid)
        if sec is None:
            raise ValueError(
                f"paper {p.slug}: report part {key!r} names section {sid!r}, which its report "
                f"does not have (sections: {[s.id for s in p.report.sections]})"
            )
        # the first section's subsections are the part's; the others' one level deeper
        sec = _flatten_deep(_inline_single_tables(prefixed(sec, p.slug)), depth=1 if i == 0 else 2)
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


def _links(p: PaperParts, page: bool) -> list[Block]:
    out: list[Block] = []
    if not page:
        out.append(
            Link(
                "The paper's page, with every table of its results", p.page, f"{p.reports}/{p.page}"
            )
        )
    out.append(
        Link(
            "The executed notebook, stepping through the SymPy derivations",
            p.notebook,
            f"{p.reports}/{p.notebook}",
        )
    )
    return out


def _summary(p: PaperParts, page: bool) -> Section:
    """The paper's status, its main claims and three sentences (on its page; the combined
    report has them on its first page and points there), then the paper's own summary."""
    s = p.score.summary
    blocks: list[Block] = []
    if s is not None and page:
        blocks.append(Paragraph(f"{s.status}."))
        if s.main_claims:
            blocks.append(MainClaims(list(s.main_claims)))
        blocks += [Paragraph(t) for t in s.sentences]
        blocks += causes_blocks(s.causes)
    elif s is not None:
        marks = [m.mark for m in s.main_claims]
        held = f"; {marks.count('Re')} of {len(marks)} main claims [Re]" if marks else ""
        blocks.append(
            Paragraph(
                f"{s.status}{held}. The main claims with their marks and what was and was not "
                "reproduced are in the papers in brief, at the front of this report."
            )
        )
        blocks += causes_blocks(s.causes)
    # the same blocks for every paper: the paper's own summary section (its page's counts and
    # overview, which differ by paper) is not repeated here; its page keeps it, among the
    # paper's own sections (further_sections)
    return Section(f"{p.slug}-summary", "Summary", blocks + _links(p, page), [])


def _figures_section(p: PaperParts) -> tuple[Section, list[Block], list[Section]]:
    """The paper's figures; those it lacks (and subsections holding only such) go apart."""
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
    section = Section(f"{p.slug}-figures", "Figures", [intro, *non_fig, *figs], keep_subs)
    return section, extra, extra_subs


def paper_section(p: PaperParts, appendix: str = "", page: bool = False) -> Section:
    """The paper's main-text section: its reference, then :data:`MAIN_TITLES` in order
    (``appendix``: where its equation forms are; ``page``: on the paper's own page)."""
    figures, extra, extra_subs = _figures_section(p)
    blocks, subs = _part(p, "findings", first=True)
    findings = Section(
        f"{p.slug}-findings", "Findings beyond the paper", [*blocks, *extra], subs + extra_subs
    )
    if not findings.blocks and not findings.subsections:
        findings = Section(findings.id, findings.title, [Paragraph("None beyond the paper's.")])
    intro: Sequence[Block] = (
        [Paragraph(f"Reproduced paper: {p.citation}.".replace("..", "."))] if p.citation else []
    )
    return Section(
        p.slug,
        p.title,
        list(intro),
        [
            _summary(p, page),
            equation_section(p.slug, p.equations, p.score.audit, appendix),
            p.published,
            p.claims,
            figures,
            findings,
        ],
    )


def discussion_section(p: PaperParts, sid: str | None = None, title: str | None = None) -> Section:
    """The paper's part of the discussion (its ``Paper.discussion`` blocks)."""
    blocks = p.discussion or [Paragraph("The paper package contributes no discussion.")]
    return Section(sid or f"{p.slug}-discussion", title or p.title, list(blocks))


def forms_section(p: PaperParts, title: str | None = None) -> Section:
    """The appendix of the paper's equation audit (the forms)."""
    return equation_appendix(p.slug, title or p.title, p.equations, p.stems)


def assumptions_section(p: PaperParts, title: str | None = None) -> Section:
    """The decisions the scenario files take where the paper is silent."""
    blocks, subs = _part(p, "assumptions")
    if not any(isinstance(b, Paragraph) for b in blocks):
        blocks.insert(
            0,
            Paragraph(
                "Where the paper is silent, each scenario file decides; the value shown is read "
                "from the file at the named field."
            ),
        )
    return Section(f"{p.slug}-assumptions", title or p.title, blocks, subs)


def _every_row(p: PaperParts) -> Section | None:
    """Every verdict row of the paper (published numbers and claims), after its causes in
    full: the per-row view of the main text's one row per item or claim."""
    parts = [s for s in (p.published_rows, p.claim_rows) if s is not None]
    if not parts:
        return None
    blocks: list[Block] = []
    if p.score.summary is not None:
        blocks += causes_blocks(p.score.summary.causes)
    for s in parts:
        blocks += s.blocks
    return Section(f"{p.slug}-rows", "Every verdict row", blocks)


def supporting_section(
    p: PaperParts, title: str | None = None, flatten: bool = True
) -> Section | None:
    """The results that support the main text: every verdict row, then the sections the
    paper lists for its findings after the first (an appendix; each keeps its id and title;
    ``flatten``: their subsections merged into them, as the PDF's heading depth needs), None
    if there are none."""
    subs = [s for s in (_every_row(p),) if s is not None]
    for sid in list(p.report.parts.get("findings") or [])[1:]:
        sec = p.report.section(sid)
        if sec is None:
            raise ValueError(
                f"paper {p.slug}: report part 'findings' names section {sid!r}, which its "
                f"report does not have (sections: {[s.id for s in p.report.sections]})"
            )
        sec = prefixed(sec, p.slug)
        subs.append(_flatten_deep(_inline_single_tables(sec), depth=2) if flatten else sec)
    if not subs:
        return None
    return Section(f"{p.slug}-supporting", title or p.title, [], subs)


def further_sections(p: PaperParts) -> list[Section]:
    """The paper's page sections that feed no part of the template, and its own published
    tables (with every note of theirs): the page's last appendix."""
    own = set(p.report.parts.get("summary") or [])  # not in the shared Summary: kept here
    used = _used(p) - set(p.report.parts.get("published") or []) - own
    out = []
    for s in p.report.sections:
        if s.id in own:  # its id and title apart from the shared Summary's
            s = Section(f"{s.id}-overview", OVERVIEW, s.blocks, s.subsections)
        if s.id not in used:
            out.append(prefixed(s, p.slug))
    return out
