"""The document model shared by every report: the per-paper pages (``reports/<slug>.html``)
and the combined report (``reports/reproduction.html`` and ``.pdf``) are rendered from it.

The model is plain data: text fields are plain text (no HTML), except the ``*_mathml``
fields of :class:`EquationRow`, which hold complete ``<math>`` elements (or ``None``). A
paper contributes its sections through its :class:`~pipeline.paper.Paper` plug-in: a
function of :class:`ReportInputs` that returns a :class:`PaperReport`.

>>> t = frame_table(pd.DataFrame({"id": ["a"], "x": [0.1 + 0.2], "verdict": ["not_upheld"]}),
...                 status="verdict")
>>> t.rows, t.highlight, t.row_status
([['a', '0.3', 'not_upheld']], [0], ['not_upheld'])
>>> frame_table(pd.DataFrame({"x": []}), caption="sweep.csv")
Paragraph(text='sweep.csv: no rows.')
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

import pandas as pd

from pipeline.report.html import format_value
from pipeline.report.vocabulary import ROW_ID

__all__ = [
    "FAILURE_WORDS",
    "VERDICT_EXTRA_COLUMNS",
    "Block",
    "Bullets",
    "CauseLine",
    "Document",
    "EquationRow",
    "EquationTable",
    "Figure",
    "Link",
    "MainClaimLine",
    "MainClaims",
    "PaperReport",
    "PaperSummary",
    "Paragraph",
    "ReportInputs",
    "ScoreRow",
    "Section",
    "Table",
    "frame_table",
    "not_available",
    "walk",
]

#: Verdict/status words that mark a table row as a failure (``Table.highlight``). A printed
#: equation that differs is not one by itself: only an error of the paper is (its kind, which
#: the equation audit renders; pipeline.report.vocabulary.tone)
FAILURE_WORDS = ("not_reproduced", "not_upheld", "missing")
#: verdicts.csv columns after the contract's (pipeline.columns.VERDICT_COLUMNS) that the
#: reports show where a file has them, selected by name
VERDICT_EXTRA_COLUMNS = ("tolerance", "reason")


@dataclass(frozen=True)
class Paragraph:
    """One paragraph of plain text."""

    text: str


@dataclass(frozen=True)
class Bullets:
    """A bulleted list of plain-text items."""

    items: list[str]


@dataclass(frozen=True)
class Table:
    """A table of plain-text cells. ``highlight`` lists the row indices to emphasise (rows
    whose verdict or status is a failure); ``row_status`` (empty, or one word per row) is the
    verdict or status word of each row, which a page colours its row by; ``notes`` (empty, or
    one text per row) the detail of each row that the HTML shows in a last column and the
    PDF leaves to it (the PDF's main part has a page budget)."""

    columns: list[str]
    rows: list[list[str]]
    caption: str = ""
    highlight: list[int] = field(default_factory=list)
    row_status: list[str] = field(default_factory=list)
    notes: list[str] = field(default_factory=list)


@dataclass(frozen=True)
class Figure:
    """A PNG figure (its SVG twin beside it). ``label`` is the paper's numbering (``"Fig. 7"``;
    ``"Extra fig. 1"`` for a figure the paper does not have, ``in_paper`` False); ``caption``
    does not repeat the label, so renderers show ``label`` then ``caption``."""

    path: str
    caption: str
    label: str
    in_paper: bool = True


@dataclass(frozen=True)
class EquationRow:
    """One row of an equation audit, with the printed/derived/residual forms as
    MathML (complete ``<math>`` elements) and SymPy ``srepr`` strings (None where absent)."""

    paper: str
    equation: str
    status: str
    note: str
    residual_text: str
    printed_mathml: str | None
    derived_mathml: str | None
    residual_mathml: str | None
    printed_srepr: str | None
    derived_srepr: str | None
    residual_srepr: str | None
    #: a differing row's kind (pipeline.columns.DIFFERS_KINDS: paper_error, text_artefact,
    #: convention, unclear_from_text); blank: not classified (or the row does not differ)
    kind: str = ""


@dataclass(frozen=True)
class EquationTable:
    """A paper's audited equations; ``stems`` maps symbol stems to their Typst rendering
    (the paper's :attr:`~pipeline.paper.Paper.math_stems`)."""

    rows: list[EquationRow]
    caption: str = ""
    stems: Mapping[str, str] = field(default_factory=dict)


@dataclass(frozen=True)
class Link:
    """A link; ``target`` is an href relative to the report (e.g. ``notebooks/x.html``) or an
    anchor (``#id``); ``path``: where the target is in the repository
    (``reports/notebooks/x.html``), which a PDF that travels alone names instead of linking."""

    text: str
    target: str
    path: str = ""


@dataclass(frozen=True)
class MainClaimLine:
    """One main claim of a paper: its ``mark`` (pipeline.verdicts.main_claims.MARKS: Re,
    not_Re, not_checkable), where the paper states it, the claim as a sentence, and the basis
    of the mark in the paper's labels."""

    mark: str
    label: str
    text: str
    basis: str


@dataclass(frozen=True)
class MainClaims:
    """A paper's main claims with their marks (a [Re]/[¬Re] line each)."""

    lines: list[MainClaimLine]


Block = Paragraph | Bullets | Table | Figure | EquationTable | Link | MainClaims


@dataclass(frozen=True)
class CauseLine:
    """One root cause of a paper's failing verdicts: its ``title`` (verdicts.csv ``cause``;
    blank: not identified), its ``kind`` (pipeline.columns.CAUSE_KINDS), how many ``rows`` it
    explains, those rows in the paper's labels (``labels``) and its full texts (the distinct
    ``cause_detail`` of its rows, in row order)."""

    title: str
    kind: str
    rows: int
    labels: str
    details: tuple[str, ...] = ()


@dataclass(frozen=True)
class PaperSummary:
    """A paper on the first page: ``status`` (Full / Partial / Not reproduced), three plain
    sentences (what was reproduced, what was not, the cause), its main claims, and the root
    causes of its failing verdicts (most rows first; the paper's section lists them)."""

    status: str
    sentences: tuple[str, str, str]
    main_claims: tuple[MainClaimLine, ...]
    causes: tuple[CauseLine, ...] = ()


@dataclass(frozen=True)
class Section:
    id: str
    title: str
    blocks: list[Block]
    subsections: list[Section] = field(default_factory=list)


@dataclass(frozen=True)
class ScoreRow:
    """One paper's line of the scoreboard; every count is computed from the CSVs.

    ``audit``: match / differs / not_checkable; ``numbers``: reproduced /
    consistent / not_reproduced (self-checks excluded); ``claims``: upheld / not_upheld /
    not_checkable; ``self_checks``: reproduced / not_reproduced of the rows the published file
    marks ``self_check`` (counted apart from the published numbers);
    ``line``: the ReScience-style one-line verdict; ``anchor``: the section id;
    ``summary``: the paper on the first page; ``differs``: the differing equations by kind
    (paper_error, text_artefact, convention, unclear_from_text, and "" for unclassified).
    """

    slug: str
    title: str
    audit: dict[str, int]
    numbers: dict[str, int]
    claims: dict[str, int]
    line: str
    anchor: str
    summary: PaperSummary | None = None
    differs: dict[str, int] = field(default_factory=dict)
    self_checks: dict[str, int] = field(default_factory=dict)


@dataclass(frozen=True)
class Document:
    """A reproduction article: title page (``abstract``, then each paper's summary from its
    ``scoreboard`` row), the numbered ``sections`` (introduction, papers, discussion,
    references) and the ``appendices`` (numbered A, B, ...)."""

    title: str
    subtitle: str
    generated_from: str
    scoreboard: list[ScoreRow]
    sections: list[Section]
    appendices: list[Section] = field(default_factory=list)
    abstract: str = ""


@dataclass(frozen=True)
class ReportInputs:
    """What a paper's report sections read: ``results`` (``results/<slug>``), ``scenarios``
    (``config/scenarios/<slug>``), ``published`` (``config/published/<slug>.yaml``),
    ``figures`` (``results/<slug>/figures``) and the paper's settings in the config
    (``config[<slug>]``)."""

    results: Path
    scenarios: Path
    published: Path
    figures: Path
    settings: Mapping[str, Any] = field(default_factory=dict)
    #: paths shown on a page are relative to this folder (the repository root) where they
    #: are inside it, so the page does not depend on where the repository is
    display_root: Path | None = None

    @classmethod
    def from_context(cls, ctx: Any) -> ReportInputs:
        """The inputs of a :class:`~pipeline.paper.Context` (the registry's view of a paper
        under the current config).

        >>> from pipeline.paper import Context
        >>> ctx = Context("x", "results", "reports", ("paper",), {"published_scenario": "paper"})
        >>> i = ReportInputs.from_context(ctx)
        >>> i.results.as_posix(), i.figures.as_posix(), i.published.as_posix(), dict(i.settings)
        ('results/x', 'results/x/figures', 'config/published/x.yaml', {'published_scenario': 'paper'})
        """
        return cls(
            results=Path(ctx.results),
            scenarios=Path(ctx.scenarios_dir),
            published=Path(ctx.published),
            figures=Path(ctx.figure("-")).parent,
            settings=dict(ctx.settings),
        )

    def shown(self, path: Path) -> str:
        """``path`` as a page shows it.

        >>> ReportInputs.under("x", "/r/results", "/r/config", display_root=Path("/r")).shown(
        ...     Path("/r/results/x/figures"))
        'results/x/figures'
        """
        if self.display_root is not None:
            try:
                return path.relative_to(self.display_root).as_posix()
            except ValueError:
                pass
        return path.as_posix()

    @classmethod
    def under(
        cls,
        slug: str,
        results_dir: str | Path,
        config_dir: str | Path = "config",
        settings: Mapping[str, Any] | None = None,
        display_root: Path | None = None,
    ) -> ReportInputs:
        """The inputs at their conventional places under ``results_dir`` and ``config_dir``."""
        results = Path(results_dir) / slug
        return cls(
            results=results,
            scenarios=Path(config_dir) / "scenarios" / slug,
            published=Path(config_dir) / "published" / f"{slug}.yaml",
            figures=results / "figures",
            settings=dict(settings or {}),
            display_root=display_root,
        )


#: The parts of a paper's section in the combined report, fed from page sections.
PARTS = ("summary", "published", "figures", "findings", "assumptions")


@dataclass(frozen=True)
class PaperReport:
    """What one paper contributes: its page ``sections`` (in page order, ids unprefixed) and,
    per part of its section in the combined report (:data:`PARTS`), the ids of the page
    sections that feed it. ``published`` None: the combined report groups the published
    numbers itself from verdicts.csv by the paper's table and figure numbering."""

    sections: list[Section]
    parts: Mapping[str, Sequence[str] | None]

    def section(self, sid: str) -> Section | None:
        return next((s for s in self.sections if s.id == sid), None)


#: ``report(inputs)``: a paper's report function (``Paper.report`` names it).
ReportFunction = Callable[[ReportInputs], PaperReport]


def not_available(what: str) -> Paragraph:
    """A uniform 'X: not available.' note."""
    return Paragraph(f"{what}: not available.")


def frame_table(
    df: pd.DataFrame,
    *,
    status: str | None = None,
    caption: str = "",
    formatters: Mapping[str, Callable[[Any], str]] | None = None,
    sig: int = 9,
    empty_text: str = "no rows",
) -> Table | Paragraph:
    """A DataFrame as a :class:`Table` of text cells (``formatters`` per column, else
    :func:`~pipeline.report.html.format_value` with ``sig`` digits; a column ``id`` of
    verdict-row ids is headed :data:`~pipeline.report.vocabulary.ROW_ID`). ``status`` names the
    column holding each row's verdict or status word (``row_status``, ``highlight``). An
    empty frame is a paragraph saying so."""
    if df.empty:
        return Paragraph(f"{caption + ': ' if caption else ''}{empty_text}.")
    if status is not None and status not in df.columns:
        raise ValueError(f"status column {status!r} not in columns {list(df.columns)}")
    fmts = dict(formatters or {})
    rows = [
        [
            fmts[c](v) if c in fmts else format_value(v, sig)
            for c, v in zip(df.columns, row, strict=True)
        ]
        for row in df.itertuples(index=False, name=None)
    ]
    words = [str(w) for w in df[status]] if status is not None else []
    return Table(
        columns=[ROW_ID if str(c) == "id" else str(c) for c in df.columns],
        rows=rows,
        caption=caption,
        highlight=[i for i, w in enumerate(words) if w in FAILURE_WORDS],
        row_status=words,
    )


def walk(sections: Sequence[Section]) -> list[Section]:
    """Every section, depth first, in document order."""
    out: list[Section] = []
    for s in sections:
        out.append(s)
        out += walk(s.subsections)
    return out
