"""The shared document model (pipeline.report.model), a paper's page (page_html) and its
section of the combined report (paper_section), with a paper that is not one of the project's
(its report function lives here): the shared report code needs nothing but the Paper object."""

from __future__ import annotations

import re
import shutil
from pathlib import Path

import pandas as pd
import pytest

from pipeline.paper import FigureSpec, Paper
from pipeline.report.document import build_document
from pipeline.report.figures import figure_blocks
from pipeline.report.model import (
    Bullets,
    Figure,
    PaperReport,
    Paragraph,
    ReportInputs,
    Section,
    Table,
    frame_table,
)
from pipeline.report.page_html import build_page, render_page
from pipeline.report.paper_section import PaperParts, paper_section
from pipeline.report.scoreboard import score_row

ROOT = Path(__file__).resolve().parents[2]


def report(inputs: ReportInputs) -> PaperReport:
    """A pendulum paper's sections, read from ``inputs`` (a CSV and the figures)."""
    path = inputs.results / "period.csv"
    if not path.is_file():
        raise FileNotFoundError(f"{path}: required input is missing")
    df = pd.read_csv(path, dtype=str, keep_default_na=False)
    figs = figure_blocks(PENDULUM, inputs.figures)
    return PaperReport(
        [
            Section("summary", "Summary", [Paragraph(f"{len(df)} periods."), Bullets(["a", "b"])]),
            Section("periods", "Periods", [frame_table(df, status="verdict")]),
            Section("figures", "Figures", figs),
            Section(
                "assumptions",
                "Assumptions",
                [],
                [Section("a-1", "Scenario one", [Table(["field", "value"], [["g", "9.81"]])])],
            ),
        ],
        {
            "summary": ["summary"],
            "published": None,
            "figures": ["figures"],
            "findings": [],
            "assumptions": ["assumptions"],
        },
    )


PENDULUM = Paper(
    slug="pendulum",
    title="The period of a pendulum <small>",
    citation="A. Author, Journal 1 (2000)",
    load_scenario=lambda path: None,
    figures=(
        FigureSpec("fig1_period.png", 1, "(paper Fig. 1): period against length."),
        FigureSpec("fig_extra.png", None, "the period against amplitude."),
    ),
    report=f"{__name__}:report",
    math_stems={"thetat": "tilde(theta)"},
)


@pytest.fixture
def inputs(tmp_path: Path) -> ReportInputs:
    results = tmp_path / "results" / "pendulum"
    results.mkdir(parents=True)
    pd.DataFrame(
        {"id": ["T1", "T2"], "value": ["2.01", "1.4"], "verdict": ["reproduced", "differs"]}
    ).to_csv(results / "period.csv", index=False)
    (results / "figures").mkdir()
    from PIL import Image

    Image.new("RGB", (8, 6), (10, 20, 30)).save(results / "figures" / "fig1_period.png")
    return ReportInputs.under("pendulum", tmp_path / "results", tmp_path / "config")


def test_frame_table_formats_and_marks_failures():
    t = frame_table(
        pd.DataFrame({"x": [0.1 + 0.2, float("nan")], "status": ["match", "differs"]}),
        status="status",
        caption="c",
    )
    assert t.rows == [["0.3", "match"], ["", "differs"]]
    assert t.highlight == [1] and t.row_status == ["match", "differs"] and t.caption == "c"
    with pytest.raises(ValueError, match="status column 'verdict'"):
        frame_table(pd.DataFrame({"x": [1]}), status="verdict")


def test_page_renders_the_papers_sections(inputs, tmp_path):
    out = build_page(PENDULUM, inputs, tmp_path / "reports" / "pendulum.html")
    text = out.read_text(encoding="utf-8")
    assert "<h1>Reproduction report: The period of a pendulum &lt;small&gt;</h1>" in text
    toc = re.search(r'<nav class="toc">(.*?)</nav>', text, re.S).group(1)
    assert re.findall(r'href="#([^"]+)"', toc) == ["summary", "periods", "figures", "assumptions"]
    assert '<tr class="v-differs">' in text and '<tr class="v-reproduced">' in text
    assert "<li>a</li>" in text
    assert text.count("data:image/png;base64,") == 1  # the extra figure's file is absent
    assert "Extra fig. 1 (fig_extra.png): not available." in text
    assert "Fig. 1</strong> (paper Fig. 1): period against length." in text
    again = render_page(PENDULUM, report(inputs))
    assert again == text  # the same inputs, the same bytes


def test_missing_input_names_the_file_and_writes_nothing(inputs, tmp_path):
    (inputs.results / "period.csv").unlink()
    out = tmp_path / "reports" / "pendulum.html"
    with pytest.raises(FileNotFoundError, match="period.csv"):
        build_page(PENDULUM, inputs, out)
    assert not out.exists()


def test_paper_section_is_assembled_from_the_papers_parts(inputs):
    rep = report(inputs)
    audit = pd.DataFrame(
        {"equation": ["1"], "status": ["match"], "residual": ["0"], "note": [""], "kind": [""]}
    )
    verdicts = pd.DataFrame(
        {
            "id": ["T1"],
            "kind": ["exact"],
            "quantity": ["T"],
            "method": [""],
            "published": ["2.01"],
            "reproduced": ["2.01"],
            "verdict": ["reproduced"],
            "note": [""],
        }
    )
    score = score_row("pendulum", PENDULUM.title, audit, verdicts)
    eq = Section("pendulum-equations", "Equation audit", [])
    pub = Section("pendulum-published", "Published vs reproduced", [])
    sec = paper_section(
        PaperParts("pendulum", PENDULUM.title, PENDULUM.citation, score, rep, eq, pub)
    )
    assert sec.id == "pendulum"
    assert [s.title for s in sec.subsections] == [
        "Summary",
        "Equation audit",
        "Published vs reproduced",
        "Figures",
        "Assumptions",
        "Findings beyond the paper",
        "Notebook",
    ]
    summary, _, _, figures, assumptions, findings, _ = sec.subsections
    assert summary.blocks[0] == Paragraph(score.line)
    assert Paragraph("2 periods.") in summary.blocks
    # the paper's figure stays under Figures; the one not in the paper goes to the findings
    assert [b.label for b in figures.blocks if isinstance(b, Figure)] == ["Fig. 1"]
    (extra,) = [b for b in findings.blocks if isinstance(b, Figure)]
    assert extra.label == "Extra fig. 1" and not extra.in_paper
    assert (
        extra.caption == "(not in the paper): the period against amplitude. (figure file fig_extra)"
    )
    # a subsection holding one table becomes that table, captioned with its title
    assert [b.caption for b in assumptions.blocks if isinstance(b, Table)] == ["Scenario one"]
    assert not assumptions.subsections

    bad = PaperReport(rep.sections, {**rep.parts, "findings": ["no-such-section"]})
    with pytest.raises(ValueError, match="no-such-section"):
        paper_section(PaperParts("pendulum", "t", "", score, bad, eq, pub))


def test_combined_report_names_a_missing_results_file(tmp_path):
    shutil.copytree(ROOT / "config", tmp_path / "config")
    with pytest.raises(FileNotFoundError, match="equation_audit.csv"):
        build_document(tmp_path)


def test_the_papers_math_stems_reach_the_pdf():
    from pipeline.report.document import Document
    from pipeline.report.equations import equation_section
    from pipeline.report.reproduction_pdf import render_typst

    audit = pd.DataFrame(
        {"equation": ["1"], "status": ["match"], "residual": ["0"], "note": [""], "kind": [""]}
    )
    forms = [{"equation": "1", "printed_srepr": "Symbol('thetat_1')"}]
    counts = {"match": 1, "differs": 0, "not_checkable": 0}
    sec = equation_section("pendulum", audit, forms, counts, PENDULUM.math_stems)
    assert sec.blocks[1].stems == {"thetat": "tilde(theta)"}
    doc = Document("t", "s", "v0", [], [Section("pendulum", "P", [], [sec])])
    assert "tilde(theta)_1" in render_typst(doc)
    plain = Section("pendulum", "P", [], [equation_section("pendulum", audit, forms, counts, {})])
    assert "tilde(theta)" not in render_typst(Document("t", "s", "v0", [], [plain]))


def test_published_tables_show_tolerance_and_reason_where_recorded(tmp_path):
    from pipeline.report.published import published_section

    published = tmp_path / "p.yaml"
    published.write_text(
        "items:\n  - {id: T1, label: Table 2 (x)}\n  - {id: F1, label: Fig. 10}\n"
        "  - {id: T3, label: Table 10}\n",
        encoding="utf-8",
    )
    base = {"quantity": "q", "method": "m", "published": "1", "reproduced": "1", "note": ""}
    verdicts = pd.DataFrame(
        [
            {**base, "id": "T3", "kind": "exact", "verdict": "reproduced"},
            {**base, "id": "F1", "kind": "approximate", "verdict": "not_reproduced"},
            {**base, "id": "T1", "kind": "exact", "verdict": "reproduced"},
            {**base, "id": "C1", "kind": "claim", "verdict": "upheld"},
        ]
    )
    sec = published_section("p-published", verdicts, published)
    tables = [b for b in sec.blocks if isinstance(b, Table)]
    # by the number in the paper's table or figure label (10 after 2), then the claims
    assert [t.caption for t in tables] == [
        "Table 2: published numbers",
        "Fig. 10: published numbers",
        "Table 10: published numbers",
        "Claims",
    ]
    assert tables[1].highlight == [0] and tables[0].highlight == []
    assert "tolerance" not in tables[0].columns
    verdicts = verdicts.assign(tolerance="0.5 %", reason="within the tolerance")
    tables = [b for b in published_section("p", verdicts, published).blocks if isinstance(b, Table)]
    assert tables[0].columns[-2:] == ["tolerance", "reason"]
    assert tables[0].rows[0][-2:] == ["0.5 %", "within the tolerance"]
    assert tables[-1].columns[-1] == "reason" and tables[-1].rows[0][-1] == "within the tolerance"
