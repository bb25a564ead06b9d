"""The shared document model (pipeline.report.model), a paper's page (page_html) and its
section of the combined report (paper_section), with a paper that is not one of the project's
(its report function lives here): the shared report code needs nothing but the Paper object,
and the page and the paper's section of the combined report follow one template."""

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
from pipeline.report.page_html import build_page, page_sections, render_page
from pipeline.report.paper_parts import load_parts
from pipeline.report.paper_section import (
    MAIN_TITLES,
    further_sections,
    paper_section,
    supporting_section,
)
from tests.shared.test_report_no_ids import html_text

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
            Section("finding", "A finding", [Paragraph("The period grows with amplitude.")]),
            Section("support", "Supporting runs", [Paragraph("Ten runs per length.")]),
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
            "findings": ["finding", "support"],
            "assumptions": ["assumptions"],
        },
    )


def discussion(inputs: ReportInputs) -> list:
    return [Paragraph("Easy: the period. Hard: nothing.")]


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
    discussion=f"{__name__}:discussion",
)

PUBLISHED = """paper: pendulum
items:
  - {id: T1.a, label: Table 1, kind: exact, quantity: period_s, value: "2.01", select: {method: m1}}
  - {id: T1.b, label: Table 1, kind: exact, quantity: period_s, value: "1.4", select: {method: m2}}
claims:
  - {id: C1, label: Sec. 3, text: "The period does not depend on the mass.", predicate: {test: t}}
main_claims:
  - {label: Abstract, text: "The small-angle period formula holds.", rows: [T1.]}
  - {label: Sec. 3, text: "Mass does not matter.", rows: [C1]}
names: {period_s: period, m1: the first pendulum, m2: the second pendulum}
"""


@pytest.fixture
def inputs(tmp_path: Path) -> ReportInputs:
    results = tmp_path / "results" / "pendulum"
    results.mkdir(parents=True)
    pd.DataFrame(
        {"id": ["T1", "T2"], "value": ["2.01", "1.4"], "verdict": ["reproduced", "differs"]}
    ).to_csv(results / "period.csv", index=False)
    pd.DataFrame(
        {
            "equation": ["1", "2"],
            "status": ["match", "differs"],
            "residual": ["0", "x"],
            "note": ["", "typo of the paper: a factor 2 is lost; see the derivation"],
            "kind": ["", "paper_error"],
        }
    ).to_csv(results / "equation_audit.csv", index=False)
    base = {"quantity": "period_s", "note": "", "tolerance": "", "reason": ""}
    pd.DataFrame(
        [
            {
                **base,
                "id": "T1.a",
                "kind": "exact",
                "method": "m1",
                "published": "2.01",
                "reproduced": "2.0063",
                "verdict": "reproduced",
            },
            {
                **base,
                "id": "T1.b",
                "kind": "exact",
                "method": "m2",
                "published": "1.4",
                "reproduced": "1.5123",
                "verdict": "not_reproduced",
            },
            {
                **base,
                "id": "C1",
                "kind": "claim",
                "method": "",
                "quantity": "",
                "published": "The period does not depend on the mass.",
                "reproduced": "no mass effect",
                "verdict": "upheld",
            },
        ]  # fmt: skip
    ).to_csv(results / "verdicts.csv", index=False)
    (tmp_path / "config" / "published").mkdir(parents=True)
    (tmp_path / "config" / "published" / "pendulum.yaml").write_text(PUBLISHED, encoding="utf-8")
    (results / "figures").mkdir()
    from PIL import Image

    Image.new("RGB", (8, 6), (10, 20, 30)).save(results / "figures" / "fig1_period.png")
    return ReportInputs.under("pendulum", tmp_path / "results", tmp_path / "config")


def test_frame_table_formats_and_marks_failures():
    t = frame_table(
        pd.DataFrame({"x": [0.1 + 0.2, float("nan")], "status": ["match", "not_upheld"]}),
        status="status",
        caption="c",
    )
    assert t.rows == [["0.3", "match"], ["", "not_upheld"]]
    assert t.highlight == [1] and t.row_status == ["match", "not_upheld"] and t.caption == "c"
    # a printed equation that differs is no failure by itself (only an error of the paper is)
    assert frame_table(pd.DataFrame({"s": ["differs"]}), status="s").highlight == []
    with pytest.raises(ValueError, match="status column 'verdict'"):
        frame_table(pd.DataFrame({"x": [1]}), status="verdict")


def _text(html: str) -> str:
    """The text of an HTML document (tags and attributes dropped)."""
    body = re.sub(r"<style>.*?</style>", " ", html, flags=re.S)
    return " ".join(re.sub(r"<[^>]+>", " ", body).split())


def test_page_follows_the_template(inputs, tmp_path):
    out = build_page(PENDULUM, inputs, tmp_path / "reports" / "pendulum.html")
    text = out.read_text(encoding="utf-8")
    assert "<h1>Reproduction report: The period of a pendulum &lt;small&gt;</h1>" in text
    parts = load_parts(PENDULUM, inputs)
    sections, appendices = page_sections(parts)
    # the template's sections, in its order, then the discussion; then the appendices
    assert [s.title for s in sections] == [*MAIN_TITLES, "Discussion"]
    assert [s.title for s in appendices] == [
        "Equation audit: the forms",
        "Supporting results",
        "Assumptions where the paper is silent",
        "The paper's own sections",
    ]
    toc = re.search(r'<nav class="toc">(.*?)</nav>', text, re.S).group(1)
    # on its own page a paper's ids need no prefix
    assert re.findall(r'href="#([^"]+)"', toc)[:2] == ["summary", "equations"]
    assert [s.id for s in sections][:2] == ["summary", "equations"]
    # the main claims, marked from the verdict rows; the three sentences in the paper's words
    assert '<span class="mark m-not-re">[¬Re]</span> The small-angle period formula holds.' in text
    assert '<span class="mark m-re">[Re]</span> Mass does not matter.' in text
    assert "Not reproduced or not upheld (1 verdict): Table 1, the second pendulum." in text
    # no internal id, but in the row-id column of the per-row tables (cross-reference)
    assert "T1.b" in _text(text) and "T1.b" not in html_text(out)
    assert "Easy: the period. Hard: nothing." in text  # the paper's discussion
    assert "Ten runs per length." in text  # its supporting results, in an appendix
    assert text.count("data:image/png;base64,") == 1  # the extra figure's file is absent
    assert "Extra fig. 1 (fig_extra.png): not available." in text
    assert "Fig. 1</strong> (paper Fig. 1): period against length." in text
    # only an error of the paper is red
    assert '<span class="v-differs t-bad k-paper-error">differs: error of the paper</span>' in text
    for token in ("not_reproduced", "not_upheld", "not_checkable"):
        assert token not in _text(text)
    again = render_page(PENDULUM, load_parts(PENDULUM, inputs))
    assert again == text  # the same inputs, the same bytes


def test_missing_input_names_the_file_and_writes_nothing(inputs, tmp_path):
    (inputs.results / "period.csv").unlink()
    out = tmp_path / "reports" / "pendulum.html"
    with pytest.raises(FileNotFoundError, match="period.csv"):
        build_page(PENDULUM, inputs, out)
    assert not out.exists()


def test_paper_section_is_assembled_from_the_papers_parts(inputs):
    parts = load_parts(PENDULUM, inputs)
    sec = paper_section(parts, "Appendix A.1")
    assert sec.id == "pendulum"
    assert tuple(s.title for s in sec.subsections) == MAIN_TITLES
    summary, audit, published, claims, figures, findings = sec.subsections
    # one set of blocks for every paper: the paper's own summary section is not repeated in
    # the shared Summary (its page keeps it among the paper's own sections)
    assert Paragraph("2 periods.") not in summary.blocks
    assert [type(b).__name__ for b in summary.blocks[-2:]] == ["Link", "Link"]
    own = [s for s in further_sections(parts) if s.id == "pendulum-summary-overview"]
    assert own and Paragraph("2 periods.") in own[0].blocks
    # the combined report has the marks and sentences at its front; its page in the summary
    assert summary.blocks[0].text.startswith("Partial reproduction; 1 of 2 main claims [Re].")
    page_summary = paper_section(parts, page=True).subsections[0]
    (marks,) = [b for b in page_summary.blocks if type(b).__name__ == "MainClaims"]
    assert [m.mark for m in marks.lines] == ["not_Re", "Re"]
    assert "forms are in Appendix A.1" in audit.blocks[0].text
    assert audit.blocks[1].items == [
        "Eq. 2 (error of the paper): typo of the paper: a factor 2 is lost"
    ]
    # the paper's figure stays under Figures; the one not in the paper goes to the findings
    assert [b.label for b in figures.blocks if isinstance(b, Figure)] == ["Fig. 1"]
    (extra,) = [b for b in findings.blocks if isinstance(b, Figure)]
    assert extra.label == "Extra fig. 1" and not extra.in_paper
    assert (
        extra.caption == "(not in the paper): the period against amplitude. (figure file fig_extra)"
    )
    # the first findings section is the finding; the others support it (an appendix)
    assert Paragraph("The period grows with amplitude.") in findings.blocks
    assert Paragraph("Ten runs per length.") not in findings.blocks
    every, support = supporting_section(parts).subsections
    assert (
        support.title == "Supporting runs" and Paragraph("Ten runs per length.") in support.blocks
    )
    # every verdict row, with how its verdict was reached, is in the appendix
    assert every.title == "Every verdict row"
    row_tables = [b for b in every.blocks if isinstance(b, Table)]
    assert [t.columns[-2:] for t in row_tables] == [["why", "row id"], ["verdict", "row id"]]
    assert [r[0] for t in row_tables for r in t.rows] == [
        "the first pendulum",
        "the second pendulum",
        "“The period does not depend on the mass” (Sec. 3)",
    ]
    # the published numbers by the paper's table, in its words, at printed precision + 2
    (table,) = [b for b in published.blocks if isinstance(b, Table)]
    assert table.caption == "Table 1: period"
    assert [r[:3] for r in table.rows] == [["the first pendulum", "2.01", "2.0063"],
                                           ["the second pendulum", "1.4", "1.512"]]  # fmt: skip
    assert table.columns[2] == "ours" and table.highlight == [1]
    (ctable,) = [b for b in claims.blocks if isinstance(b, Table)]
    assert ctable.rows[0][0] == "“The period does not depend on the mass” (Sec. 3)"

    bad = PaperReport(parts.report.sections, {**parts.report.parts, "findings": ["nope"]})
    from dataclasses import replace

    with pytest.raises(ValueError, match="nope"):
        paper_section(replace(parts, report=bad))


def test_combined_report_names_a_missing_results_file(tmp_path):
    shutil.copytree(ROOT / "config", tmp_path / "config")
    with pytest.raises(FileNotFoundError, match="equation_audit.csv"):
        build_document(tmp_path)


def test_the_papers_math_stems_reach_the_pdf():
    from pipeline.report.document import Document
    from pipeline.report.equations import equation_appendix, equation_rows
    from pipeline.report.reproduction_pdf import render_typst

    audit = pd.DataFrame(
        {"equation": ["1"], "status": ["differs"], "residual": ["x"], "note": [""]}
    )
    forms = [
        {
            "equation": "1",
            "printed_srepr": "Symbol('thetat_1')",
            "derived_srepr": "Integer(0)",
            "residual_srepr": "Symbol('thetat_1')",
        }
    ]
    rows = equation_rows("pendulum", audit, forms)
    sec = equation_appendix("pendulum", "P", rows, PENDULUM.math_stems)
    assert sec.blocks[1].stems == {"thetat": "tilde(theta)"}
    doc = Document("t", "s", "v0", [], [Section("pendulum", "P", [], [sec])])
    assert "tilde(theta)_1" in render_typst(doc)
    plain = equation_appendix("pendulum", "P", rows, {})
    assert "tilde(theta)" not in render_typst(Document("t", "s", "v0", [], [plain]))


def test_published_tables_show_tolerance_and_cause(tmp_path):
    from pipeline.report.published import published_rows_section, published_section

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
    # by the number in the paper's table or figure label (10 after 2); one quantity: captioned
    assert [t.caption for t in tables] == ["Table 2: q", "Fig. 10: q", "Table 10: q"]
    assert tables[1].highlight == [0] and tables[0].highlight == []
    # the main text: no 'why' column (it is in the per-row tables of the appendix)
    assert tables[0].columns == ["item", "published", "ours", "tolerance", "verdict"]
    verdicts = verdicts.assign(
        tolerance="+-20% of 1 (an 'about' value the authors read off their own plot)",
        reason="within the tolerance",
        cause_kind=["", "unpublished", "", ""],
        cause=["", "the trajectory is not published", "", ""],
        cause_detail=["", "The paper does not publish the trajectory (3 banks in ours).", "", ""],
    )
    sec = published_section("p", verdicts, published)
    tables = [b for b in sec.blocks if isinstance(b, Table)]
    # a cause column only in a table where a row fails with a cause
    assert [t.columns[-1] for t in tables] == ["verdict", "cause", "verdict"]
    # the cause's title only: its full text is listed once, with the paper's causes
    assert tables[1].rows[0][3:] == ["+-20% of 1", "not_reproduced", "the trajectory is not published"]  # fmt: skip
    assert (
        Paragraph("Tolerance: an 'about' value the authors read off their own plot.") in sec.blocks
    )
    every = published_rows_section("p", verdicts, published)
    (_, row, _) = [t for t in every.blocks if isinstance(t, Table)]
    assert row.columns[-3:] == ["why", "cause", "row id"]
    assert row.rows[0][3:] == ["+-20% of 1", "not_reproduced", "within the tolerance", "the trajectory is not published", "F1"]  # fmt: skip
    # the HTML's last column: the row's note and the cause's full text
    assert row.notes == ["cause: The paper does not publish the trajectory (3 banks in ours)."]


def test_a_differing_equation_is_stated_without_repeating_its_kind():
    """The statement after "Eq. N (kind):" drops the kind's words where the note opens with
    them; another opening stays."""
    from pipeline.report.equations import equation_section
    from pipeline.report.model import EquationRow

    def row(eq: str, kind: str, note: str) -> EquationRow:
        return EquationRow("p", eq, "differs", note, "x", *([None] * 6), kind=kind)

    rows = [
        row("1", "paper_error", "error of the paper: a factor l is missing; details"),
        row("2", "unclear_from_text", "cannot tell from the text: one exponent, once"),
        row("3", "convention", "approximation of the paper: small angles"),
    ]
    (_, bullets) = equation_section("p", rows, {"differs": 3}).blocks
    assert bullets.items == [
        "Eq. 1 (error of the paper): a factor l is missing",
        "Eq. 2 (cannot tell from the text): one exponent, once",
        "Eq. 3 (approximation or convention): approximation of the paper: small angles",
    ]
