"""The combined reproduction report (HTML and PDF): its :class:`Document`, a reproduction
article built from the papers the config lists (their :class:`~pipeline.paper.Paper`
plug-ins) and their results.

Title page: the abstract and, per paper, three sentences and a mark per main claim. Then the
introduction, one section per paper (one template, :mod:`pipeline.report.paper_section`), the
discussion, the references, and the appendices: the equation audits with their forms, the
assumptions, the provenance. Both renderers (:mod:`pipeline.report.reproduction_html` and the
Typst/PDF renderer :mod:`pipeline.report.reproduction_pdf`) read this one document; neither
reads a CSV. The model lives in :mod:`pipeline.report.model` (re-exported here).
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

import yaml

from pipeline.provenance import git_describe
from pipeline.registry import load_paper
from pipeline.report.article import abstract, discussion, introduction, references
from pipeline.report.equations import equation_groups, equation_list, formless, read_math
from pipeline.report.model import (
    Block,
    Bullets,
    Document,
    EquationRow,
    EquationTable,
    Figure,
    Link,
    MainClaims,
    PaperReport,
    Paragraph,
    ReportInputs,
    ScoreRow,
    Section,
    Table,
)
from pipeline.report.paper_parts import load_parts, read_results_csv
from pipeline.report.paper_section import (
    assumptions_section,
    forms_section,
    paper_section,
    supporting_section,
)
from pipeline.report.provenance_section import ProvenanceInputs, provenance_section
from pipeline.report.scoreboard import AUDIT_WORDS, CLAIM_WORDS, NUMBER_WORDS, counts, score_row

__all__ = [
    "AUDIT_WORDS",
    "CLAIM_WORDS",
    "NUMBER_WORDS",
    "APPENDICES",
    "Block",
    "Bullets",
    "Document",
    "EquationRow",
    "EquationTable",
    "Figure",
    "Link",
    "MainClaims",
    "Paragraph",
    "ScoreRow",
    "Section",
    "Table",
    "build_document",
    "counts",
    "equation_groups",
    "equation_list",
    "formless",
    "paper_report",
    "read_math",
    "read_results_csv",
    "score_row",
]

ROOT = Path(__file__).resolve().parents[2]
#: the appendices of the combined report, in order (numbered A, B, C)
APPENDICES = (
    "Equation audits",
    "Supporting results",
    "Assumptions where the papers are silent",
    "Provenance",
)


def build_document(
    root: Path = ROOT,
    results_dir: str | Path = "results",
    reports_dir: str | Path = "reports",
    config: str | Path = "config",
) -> Document:
    """Build the report's content from the results (nothing typed by hand).

    ``results_dir`` and ``config`` (the config directory) are taken relative to ``root``
    unless absolute; nothing under ``reports_dir`` is read (the per-paper pages are not
    parsed: each paper's section is built from the same parts as its page), it only names
    where the pages and notebooks are for a reader of the PDF.

    Reads ``<config>/config.yaml`` (``papers``, each paper's settings) and, per paper:
    ``equation_audit.csv``, ``equation_math.json``, ``verdicts.csv``, the scenario
    ``provenance.json`` files and ``benchmarks/*.tsv`` under ``results/<slug>/``;
    ``config/scenarios/<slug>/*.yaml`` and ``config/published/<slug>.yaml``; and whatever
    the paper's report and discussion functions read. Raises ``FileNotFoundError`` naming a
    missing required input.
    """
    root = Path(root)
    results = _under(root, results_dir)
    config_dir = _under(root, config)
    cfg = _load_yaml(config_dir / "config.yaml")
    slugs = [str(s) for s in (cfg.get("papers") or [])]
    if not slugs:
        raise ValueError(f"{config_dir / 'config.yaml'}: no 'papers' listed")
    reports = Path(reports_dir).as_posix() if not Path(reports_dir).is_absolute() else "reports"
    papers = [
        load_parts(
            load_paper(slug),
            ReportInputs.under(slug, results, config_dir, cfg.get(slug) or {}, display_root=root),
            reports,
        )
        for slug in slugs
    ]
    described = git_describe(root)
    letters = "ABCDEFGHIJKLMNOPQRSTUVWXYZ"
    forms = [f"Appendix A.{k}" for k in range(1, len(papers) + 1)]
    appendix_names = [f"{letters[i]}: {a.lower()}" for i, a in enumerate(APPENDICES)]
    sections = [introduction(papers, appendix_names)]
    sections += [paper_section(p, forms[k]) for k, p in enumerate(papers)]
    sections += [discussion(papers), references(papers, described)]
    supporting = [s for p in papers if (s := supporting_section(p)) is not None]
    appendices = [
        Section("equation-audits", APPENDICES[0], [], [forms_section(p) for p in papers]),
        Section(
            "supporting",
            APPENDICES[1],
            [
                Paragraph(
                    "Per paper, every verdict row (the main text gives one row per item or claim) and the results its findings rest on."
                )
            ]
            if supporting
            else [Paragraph("No paper lists results beyond its findings.")],
            supporting,
        ),
        Section("assumptions", APPENDICES[2], [], [assumptions_section(p) for p in papers]),
        provenance_section(
            [ProvenanceInputs(p.slug, p.inputs.results, p.inputs.scenarios) for p in papers],
            root,
        ),
    ]
    n = len(papers)
    fixed = _unique_ids(sections + appendices)
    return Document(
        title="Reproducing three inertial-navigation papers"
        if n == 3
        else f"Reproducing {n} inertial-navigation paper{'s' if n != 1 else ''}",
        subtitle=(
            "Every printed equation, published number and claim beside what this project "
            "derived with SymPy and computed: a reproducibility audit"
        ),
        generated_from=described,
        scoreboard=[p.score for p in papers],
        sections=fixed[: len(sections)],
        appendices=fixed[len(sections) :],
        abstract=abstract(papers),
    )


def paper_report(paper: Any, inputs: ReportInputs) -> PaperReport:
    """The sections ``paper`` contributes (its ``report`` function called on ``inputs``)."""
    return paper.report_function()(inputs)


def _under(root: Path, p: str | Path) -> Path:
    p = Path(p)
    return p if p.is_absolute() else root / p


def _load_yaml(path: Path) -> dict[str, Any]:
    if not path.is_file():
        raise FileNotFoundError(f"{path}: required input is missing")
    with path.open(encoding="utf-8") as fh:
        data = yaml.load(fh, Loader=getattr(yaml, "CSafeLoader", yaml.SafeLoader)) or {}
    if not isinstance(data, dict):
        raise ValueError(f"{path}: expected a mapping")
    return data


def _unique_ids(sections: Sequence[Section]) -> list[Section]:
    seen: set[str] = set()

    def fix(s: Section) -> Section:
        sid = s.id
        k = 2
        while sid in seen:
            sid = f"{s.id}-{k}"
            k += 1
        seen.add(sid)
        return Section(sid, s.title, s.blocks, [fix(c) for c in s.subsections])

    return [fix(s) for s in sections]
