"""What one paper's part of a report is built from, read once from its results: the same
:class:`PaperParts` feed its page ``reports/<slug>.html`` and its section of the combined
report (:mod:`pipeline.report.paper_section`), so both follow one template.

Reads ``results/<slug>/equation_audit.csv`` (its optional ``kind`` column),
``equation_math.json`` (optional), ``verdicts.csv``, ``config/published/<slug>.yaml`` and
whatever the paper's report and discussion functions read (``Paper.report``,
``Paper.discussion``).
"""

from __future__ import annotations

from collections.abc import Sequence
from dataclasses import dataclass
from pathlib import Path

import pandas as pd

from pipeline.columns import AUDIT_COLUMNS, VERDICT_COLUMNS
from pipeline.paper import Paper
from pipeline.report.equations import equation_rows, read_math
from pipeline.report.model import Block, EquationRow, PaperReport, ReportInputs, ScoreRow, Section
from pipeline.report.published import (
    claim_rows_section,
    claims_section,
    load_published,
    published_rows_section,
    published_section,
)
from pipeline.report.scoreboard import score_row
from pipeline.verdicts.published import load_published as load_checked

__all__ = ["AUDIT_OPTIONAL", "VERDICT_OPTIONAL", "PaperParts", "load_parts", "read_results_csv"]

#: the columns the reports read where a results file has them
AUDIT_OPTIONAL = ("kind",)
VERDICT_OPTIONAL = ("tolerance", "reason", "cause_kind", "cause", "cause_detail")


def read_results_csv(
    path: Path, columns: Sequence[str], optional: Sequence[str] = ()
) -> pd.DataFrame:
    """A required results CSV with every cell as printed (strings): ``columns`` (required)
    and the ``optional`` ones the file has, selected by name (other columns are ignored);
    FileNotFoundError / ValueError naming the file."""
    if not path.is_file():
        raise FileNotFoundError(f"{path}: required input is missing")
    df = pd.read_csv(path, dtype=str, keep_default_na=False)
    missing = [c for c in columns if c not in df.columns]
    if missing:
        raise ValueError(f"{path}: missing columns {missing} (has {list(df.columns)})")
    extra = [c for c in optional if c in df.columns and c not in columns]
    return df[[*columns, *extra]]


@dataclass(frozen=True)
class PaperParts:
    """One paper's results as the report template needs them."""

    slug: str
    title: str
    citation: str
    inputs: ReportInputs
    score: ScoreRow
    report: PaperReport
    equations: list[EquationRow]
    #: the main text's published numbers and claims (one row per item or claim)
    published: Section
    claims: Section
    discussion: list[Block]
    stems: dict[str, str]
    #: the repository folder of the reports (its pages and notebooks), e.g. ``reports``
    reports: str = "reports"
    #: every verdict row of the published numbers and of the claims (the appendix)
    published_rows: Section | None = None
    claim_rows: Section | None = None

    @property
    def page(self) -> str:
        """The paper's page, relative to the report folder."""
        return f"{self.slug}.html"

    @property
    def notebook(self) -> str:
        return f"notebooks/{self.slug}.html"


def load_parts(paper: Paper, inputs: ReportInputs, reports: str = "reports") -> PaperParts:
    """Read a paper's results and call its report and discussion functions (FileNotFoundError
    naming a missing required input)."""
    audit = read_results_csv(inputs.results / "equation_audit.csv", AUDIT_COLUMNS, AUDIT_OPTIONAL)
    verdicts = read_results_csv(inputs.results / "verdicts.csv", VERDICT_COLUMNS, VERDICT_OPTIONAL)
    published = (
        load_checked(inputs.published)
        if inputs.published.is_file()
        else load_published(inputs.published)
    )
    score = score_row(
        paper.slug, paper.title, audit, verdicts, published, inputs.shown(inputs.published)
    )
    rows = equation_rows(paper.slug, audit, read_math(inputs.results / "equation_math.json"))
    return PaperParts(
        slug=paper.slug,
        title=paper.title,
        citation=paper.citation,
        inputs=inputs,
        score=score,
        report=paper.report_function()(inputs),
        equations=rows,
        published=published_section(f"{paper.slug}-published", verdicts, inputs.published),
        claims=claims_section(f"{paper.slug}-claims", verdicts, inputs.published),
        published_rows=published_rows_section(
            f"{paper.slug}-published-rows", verdicts, inputs.published
        ),
        claim_rows=claim_rows_section(f"{paper.slug}-claim-rows", verdicts, inputs.published),
        discussion=list(paper.discussion_function()(inputs)),
        stems=dict(paper.math_stems),
        reports=reports,
    )
