"""The combined reproduction report (HTML and PDF): its :class:`Document`, built from the
papers the config lists (their :class:`~pipeline.paper.Paper` plug-ins) and their results.

Both renderers (:mod:`pipeline.report.reproduction_html` and the Typst/PDF renderer
:mod:`pipeline.report.reproduction_pdf`) read this one document; neither reads a CSV. Each
paper's section is assembled (:mod:`pipeline.report.paper_section`) from the sections the
paper's report contributes (``Paper.report``), the same objects its page
``reports/<slug>.html`` is rendered from; nothing is parsed back from HTML. The model lives
in :mod:`pipeline.report.model` (re-exported here).
"""

from __future__ import annotations

from collections.abc import Mapping, Sequence
from dataclasses import dataclass
from pathlib import Path
from typing import Any

import pandas as pd
import yaml

from pipeline.columns import AUDIT_COLUMNS, VERDICT_COLUMNS
from pipeline.paper import Paper
from pipeline.provenance import git_describe
from pipeline.registry import load_paper
from pipeline.report.equations import (
    equation_groups,
    equation_list,
    equation_section,
    formless,
    read_math,
)
from pipeline.report.model import (
    VERDICT_EXTRA_COLUMNS,
    Block,
    Bullets,
    Document,
    EquationRow,
    EquationTable,
    Figure,
    Link,
    PaperReport,
    Paragraph,
    ReportInputs,
    ScoreRow,
    Section,
    Table,
)
from pipeline.report.paper_section import PaperParts, paper_section
from pipeline.report.provenance_section import ProvenanceInputs, provenance_section
from pipeline.report.published import published_section
from pipeline.report.scoreboard import (
    AUDIT_WORDS,
    CLAIM_WORDS,
    NUMBER_WORDS,
    counts,
    plural,
    rescience_line,
    score_row,
)

__all__ = [
    "AUDIT_WORDS",
    "CLAIM_WORDS",
    "NUMBER_WORDS",
    "Block",
    "Bullets",
    "Document",
    "EquationRow",
    "EquationTable",
    "Figure",
    "Link",
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
    "read_results_csv",
    "rescience_line",
    "score_row",
]

ROOT = Path(__file__).resolve().parents[2]


def build_document(
    root: Path = ROOT,
    results_dir: str | Path = "results",
    reports_dir: str | Path = "reports",
    config: str | Path = "config",
) -> Document:
    """Build the report's content from the results (nothing typed by hand).

    ``results_dir`` and ``config`` (the config directory) are taken relative to ``root``
    unless absolute; nothing under ``reports_dir`` is read (the per-paper pages are not
    parsed: each paper's section is built from the same sections as its page).

    Reads ``<config>/config.yaml`` (``papers``, each paper's settings) and, per paper:
    ``equation_audit.csv``, ``equation_math.json``, ``verdicts.csv``, the scenario
    ``provenance.json`` files and ``benchmarks/*.tsv`` under ``results/<slug>/``;
    ``config/scenarios/<slug>/*.yaml`` and ``config/published/<slug>.yaml``; and whatever
    the paper's report function reads (its results files and figures, see its
    ``Paper.report``). Raises ``FileNotFoundError`` naming a missing required input.
    """
    root = Path(root)
    results = _under(root, results_dir)
    # reports_dir is not read: the report links to the pages and notebooks beside it by
    # relative href (<slug>.html, notebooks/<slug>.html), wherever it is written
    config_dir = _under(root, config)
    cfg = _load_yaml(config_dir / "config.yaml")
    slugs = [str(s) for s in (cfg.get("papers") or [])]
    if not slugs:
        raise ValueError(f"{config_dir / 'config.yaml'}: no 'papers' listed")
    papers = [_load(load_paper(slug), root, results, config_dir, cfg) for slug in slugs]
    sections = [_how_to_read(papers)]
    sections += [paper_section(p.parts) for p in papers]
    sections.append(
        provenance_section(
            [ProvenanceInputs(p.slug, p.inputs.results, p.inputs.scenarios) for p in papers],
            root,
        )
    )
    n = len(papers)
    return Document(
        title=f"Reproducing {n} inertial-navigation paper{'s' if n != 1 else ''}"
        if n != 3
        else "Reproducing three inertial-navigation papers",
        subtitle=(
            "Every printed equation, published number and claim beside what this project "
            "derived with SymPy and computed: a reproducibility audit"
        ),
        generated_from=git_describe(root),
        scoreboard=[p.parts.score for p in papers],
        sections=_unique_ids(sections),
    )


def paper_report(paper: Paper, inputs: ReportInputs) -> PaperReport:
    """The sections ``paper`` contributes (its ``report`` function called on ``inputs``)."""
    return paper.report_function()(inputs)


# --------------------------------------------------------------------------- reading


def _under(root: Path, p: str | Path) -> Path:
    p = Path(p)
    return p if p.is_absolute() else root / p


def _load_yaml(path: Path) -> dict[str, Any]:
    if not path.is_file():
        raise FileNotFoundError(f"{path}: required input is missing")
    with path.open(encoding="utf-8") as fh:
        data = yaml.safe_load(fh) or {}
    if not isinstance(data, dict):
        raise ValueError(f"{path}: expected a mapping")
    return data


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
class _Loaded:
    slug: str
    inputs: ReportInputs
    audit: pd.DataFrame
    verdicts: pd.DataFrame
    parts: PaperParts


def _load(
    paper: Paper, root: Path, results: Path, config_dir: Path, cfg: Mapping[str, Any]
) -> _Loaded:
    inputs = ReportInputs.under(
        paper.slug, results, config_dir, cfg.get(paper.slug) or {}, display_root=root
    )
    audit = read_results_csv(inputs.results / "equation_audit.csv", AUDIT_COLUMNS)
    verdicts = read_results_csv(
        inputs.results / "verdicts.csv", VERDICT_COLUMNS, VERDICT_EXTRA_COLUMNS
    )
    score = score_row(paper.slug, paper.title, audit, verdicts)
    report = paper_report(paper, inputs)
    equations = equation_section(
        paper.slug,
        audit,
        read_math(inputs.results / "equation_math.json"),
        score.audit,
        paper.math_stems,
    )
    published = (
        published_section(f"{paper.slug}-published", verdicts, inputs.published)
        if report.parts.get("published") is None
        else None
    )
    parts = PaperParts(paper.slug, paper.title, paper.citation, score, report, equations, published)
    return _Loaded(paper.slug, inputs, audit, verdicts, parts)


# --------------------------------------------------------------------------- sections


def _how_to_read(papers: Sequence[_Loaded]) -> Section:
    n_eq = sum(len(p.audit) for p in papers)
    n_num = sum(int((p.verdicts["kind"] != "claim").sum()) for p in papers)
    n_claim = sum(int((p.verdicts["kind"] == "claim").sum()) for p in papers)
    blocks: list[Block] = [
        Paragraph(
            f"This report audits {plural(len(papers), 'paper')}: {n_eq} printed equations, "
            f"{n_num} published numbers and {n_claim} claim verdicts in all. Each paper's "
            "equations were transcribed as printed and compared with a SymPy derivation from "
            "first principles; its numbers and claims were recomputed by simulation from the "
            "derived equations and compared with the published values by a rule that fits "
            "their kind. Every count and verdict here is read from the result files "
            "(equation_audit.csv, verdicts.csv) the workflow wrote; none is typed by hand."
        ),
        Paragraph(
            "The scoreboard has one row per paper. Equations: printed equations that match "
            "the derivation, differ from it (a typo of the paper or an artefact of the text; "
            "the pipeline then uses the derived form) or cannot be checked (not checkable: "
            "definitions, numeric statements, text). Published numbers: reproduced (an exact, "
            "ideal-sensor value equal to the printed precision or within the stated "
            "tolerance), consistent (a noise-dependent value inside the Monte Carlo "
            "distribution) or not reproduced. Claims: a predicate over the results, upheld, "
            "not upheld or not checkable; where a paper's claim is judged on two variants "
            "(e.g. analytic and simulated curves) each variant counts once."
        ),
        Paragraph(
            "The line under each paper follows ReScience C: full reproduction when every "
            "published number is reproduced or consistent and every claim is upheld, not "
            "reproduced when none is, partial otherwise; it names the numbers and claims that "
            "fail. Each paper's section gives its summary, the equation audit with the printed "
            "and derived forms typeset, the published tables in the paper's own numbering "
            "beside ours, the figures, the assumptions made where the paper is silent, the "
            "findings that go beyond the paper and a link to the executed notebook. The last "
            "section records the provenance of the results."
        ),
        Table(
            columns=["word", "applies to", "meaning"],
            rows=[
                ["match", "equation", "printed form equals the derivation (residual 0)"],
                ["differs", "equation", "printed form differs; residual shown, derived form used"],
                ["not_checkable", "equation, claim", "cannot be decided from the paper's data"],
                ["reproduced", "exact number", "equal to the printed precision or tolerance"],
                ["consistent", "statistical number", "inside the Monte Carlo distribution"],
                ["not_reproduced", "number", "outside the precision, tolerance or distribution"],
                ["upheld", "claim", "the claim's predicate holds on our results"],
                ["not_upheld", "claim", "the predicate fails; the evidence is in the table"],
            ],
            caption="Verdict and status words",
            highlight=[1, 5, 7],
        ),
    ]
    return Section(id="how-to-read", title="How to read this report", blocks=blocks)


def _unique_ids(sections: list[Section]) -> list[Section]:
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
