"""reports/reproduction.pdf (pipeline/report/reproduction_pdf.py).

A small document with every block kind and hostile text compiles and reads back verbatim; the
real report, built from results/ (or from a reduced workflow run on a fresh clone), is
byte-identical when rebuilt in another process, renders every page with pdftoppm without an
error, uses only the fonts embedded in the typst package, starts every appendix on a new page,
has the HTML report's numbered section titles in the same order, keeps its main part
within MAIN_PART_PAGES pages, shows the one vocabulary and has no zero-width space in its text.
"""

from __future__ import annotations

import os
import re
import shutil
import subprocess
import sys
import time
from html.parser import HTMLParser
from pathlib import Path

import pytest

from pipeline.report.document import (
    Document,
    EquationRow,
    EquationTable,
    Figure,
    Link,
    Paragraph,
    ScoreRow,
    Section,
    Table,
)
from tests.hang_guard import HANG_GUARD_S
from tests.workflow_harness import NEEDS_RUN

typst = pytest.importorskip("typst")
from pipeline.report import reproduction_pdf as R  # noqa: E402 - needs typst

ROOT = Path(__file__).resolve().parents[2]
POPPLER = {name: shutil.which(name) for name in ("pdftoppm", "pdftotext", "pdfinfo", "pdffonts")}
pytestmark = pytest.mark.skipif(
    POPPLER["pdftoppm"] is None or POPPLER["pdftotext"] is None or POPPLER["pdfinfo"] is None,
    reason="poppler-utils (pdftoppm, pdftotext, pdfinfo) not installed",
)

#: Font families the typst package embeds (system fonts are ignored when compiling).
EMBEDDED_FONTS = ("LibertinusSerif", "NewCM", "DejaVuSansMono")


# ------------------------------------------------------------------------------------------
# helpers
# ------------------------------------------------------------------------------------------
def _run(*cmd: str) -> subprocess.CompletedProcess:
    return subprocess.run(cmd, capture_output=True, text=True, timeout=HANG_GUARD_S)


def page_count(pdf: Path) -> int:
    r = _run(POPPLER["pdfinfo"], str(pdf))
    assert r.returncode == 0, r.stderr
    return int(re.search(r"^Pages:\s+(\d+)", r.stdout, re.M).group(1))


def page_texts(pdf: Path) -> list[str]:
    """Text of every page, whitespace collapsed and typographic quotes made plain."""
    r = _run(POPPLER["pdftotext"], "-enc", "UTF-8", str(pdf), "-")
    assert r.returncode == 0 and not r.stderr.strip(), r.stderr
    pages = r.stdout.split("\f")
    if pages and not pages[-1].strip():
        pages = pages[:-1]
    return [_norm(p) for p in pages]


def _norm(text: str) -> str:
    text = text.replace("\u2019", "'").replace("\u2018", "'")
    text = text.replace("\u201c", '"').replace("\u201d", '"').replace("\u200b", "")
    return " ".join(text.split())


def render_pages(pdf: Path, out: Path) -> subprocess.CompletedProcess:
    out.mkdir(parents=True, exist_ok=True)
    return _run(POPPLER["pdftoppm"], "-r", "50", "-png", str(pdf), str(out / "page"))


class _Headings(HTMLParser):
    """(number, title) of every <h2>..<h6> with a section number, in document order."""

    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.items: list[tuple[str, str]] = []
        self._h: list[str] | None = None
        self._no: list[str] | None = None

    def handle_starttag(self, tag, attrs):
        if re.fullmatch(r"h[2-6]", tag):
            self._h = []
        elif tag == "span" and self._h is not None and ("class", "secno") in attrs:
            self._no = []

    def handle_endtag(self, tag):
        if tag == "span" and self._no is not None:
            self._no_text = "".join(self._no).strip()
            self._no = None
        elif re.fullmatch(r"h[2-6]", tag) and self._h is not None:
            number = getattr(self, "_no_text", "")
            if number:
                title = " ".join("".join(self._h).split())
                self.items.append((number, title[len(number) :].strip()))
            self._h, self._no_text = None, ""

    def handle_data(self, data):
        if self._h is not None:
            self._h.append(data)
        if self._no is not None:
            self._no.append(data)


def html_headings(html: str) -> list[tuple[str, str]]:
    p = _Headings()
    p.feed(html)
    return p.items


# ------------------------------------------------------------------------------------------
# a small document: every block kind, hostile text, the expression fallback
# ------------------------------------------------------------------------------------------
NASTY = r"#set $x$ *bold* _it_ @ref <lab> [b] {c} \back // not a comment = - + 1. ~ ` ^ 50 %"


def _small_document(root: Path) -> Document:
    from PIL import Image

    (root / "figs").mkdir(parents=True, exist_ok=True)
    Image.new("RGB", (260, 180), (40, 90, 160)).save(root / "figs" / "fig1.png")
    rows = [
        EquationRow("p", "1", "not_checkable", "not in the text", "", *([None] * 6)),
        EquationRow("p", "2", "not_checkable", "not in the text", "", *([None] * 6)),
        EquationRow(
            "p",
            "3.a",
            "differs",
            "typo " + NASTY,
            "x - y",
            None,
            None,
            None,
            "Symbol('omega_x')",
            "Mul(Integer(2), Symbol('omega_x'))",
            "Mul(Integer(-1), Symbol('omega_x'))",
        ),
        EquationRow(
            "p",
            "4",
            "match",
            "",
            "0",
            None,
            None,
            None,
            "ImmutableDenseMatrix([[sin(Symbol('theta'))], [Pow(Symbol('x'), Integer(-1))]])",
            "ImmutableDenseMatrix([[sin(Symbol('theta'))], [Pow(Symbol('x'), Integer(-1))]])",
            None,
        ),
        EquationRow(
            "p", "5", "differs", "", "1", None, None, None, "not sympy (", "Integer(1)", None
        ),
        EquationRow("p", "6", "match", "", "0", None, None, None, "Integer(1)", "Integer(1)", None),
    ]
    paper = Section(
        "paper",
        "A paper: " + NASTY,
        [Paragraph("Summary " + NASTY + "\n\nSecond paragraph.")],
        [
            Section("paper-eq", "Equation audit", [EquationTable(rows, caption="Audit")]),
            Section(
                "paper-tab",
                "Numbers",
                [
                    Table(
                        ["id", "verdict", "note"],
                        [["T1.a_b", "not_reproduced", NASTY], ["T2", "reproduced", "x" * 90]],
                        caption="Table 1 " + NASTY,
                        highlight=[0],
                    )
                ],
            ),
            Section(
                "paper-fig",
                "Figures",
                [
                    Figure(str(root / "figs" / "fig1.png"), "A caption " + NASTY, "Fig. 1"),
                    Link("the notebook", "notebooks/p.html"),
                    Link("back to the top", "#paper"),
                    Link("nowhere", "#missing"),
                ],
            ),
        ],
    )
    score = ScoreRow(
        "p",
        "A paper",
        {"match": 2, "differs": 1, "not_checkable": 2},
        {"reproduced": 1, "consistent": 0, "not_reproduced": 1},
        {"upheld": 0, "not_upheld": 0, "not_checkable": 0},
        "Partial reproduction " + NASTY,
        "paper",
    )
    return Document("Title " + NASTY, "Sub " + NASTY, "v0-1-gabc", [score], [paper])


def test_small_document_compiles_and_reads_back(tmp_path):
    doc = _small_document(tmp_path)
    build = R.compile_pdf(doc, tmp_path)
    assert build.warnings == () and build.fallbacks == frozenset()
    pdf = tmp_path / "small.pdf"
    pdf.write_bytes(build.data)
    r = render_pages(pdf, tmp_path / "png")
    assert r.returncode == 0 and r.stderr == "", r.stderr
    pages = page_texts(pdf)
    text = " ".join(pages)
    nasty = _norm(NASTY)
    assert text.count(nasty) >= 5, text  # title, subtitle, heading, paragraph, table ...
    # the title matter and the contents, then the first section on a page of its own
    assert pages[1].startswith("1 A paper: " + nasty)
    assert "Eqs. 1–2 not checkable" in text  # formless rows with the same note: one line
    assert "Fig. 1. A caption" in text
    assert "not sympy (" in text  # an unreadable srepr is shown as text
    assert "printed" in text and "derived" in text
    assert "2 printed equations match the derivation" in text and "eqs. 4, 6." in text
    # one vocabulary; a link to a file beside the report says where the file is
    assert "not_reproduced" not in text and "not reproduced" in text
    assert "the notebook: the file notebooks/p.html of the repository" in text


def test_expression_that_does_not_typeset_falls_back_to_text(tmp_path, monkeypatch, capsys):
    from pipeline.report import typst_math as M

    doc = _small_document(tmp_path)
    real = M.typst_math

    def broken(expr, **kw):
        out = real(expr, **kw)
        return out + " #" if "omega" in out else out  # "#" is invalid in math

    monkeypatch.setattr(M, "typst_math", broken)
    build = R.compile_pdf(doc, tmp_path)
    assert build.fallbacks and all("omega" in s for s in build.fallbacks)
    assert "did not typeset" in capsys.readouterr().err
    pdf = tmp_path / "fallback.pdf"
    pdf.write_bytes(build.data)
    assert "2*omega_x" in " ".join(page_texts(pdf))


def test_escape_and_breakable():
    assert R.escape("a_b *c* #d $e$") == r"a\_b \*c\* \#d \$e\$"
    assert R.escape("one\n two") == "one two"
    assert R.breakable("filters.linear_kf.p0_radius").startswith("#box[filters\\.]#box[")
    assert R.breakable("50.0054709908323") == R.escape("50.0054709908323")  # numbers whole
    assert "\u200b" not in R.breakable("a" * 40 + "/b_c")


def test_identifiers_copy_out_whole(tmp_path):
    """A long identifier in a narrow column breaks between boxes, not at a zero-width space:
    the PDF's text has no ZWSP, and the identifier's characters come out in order."""
    ident = "filters.linear_kf.p0_radius_of_the_initial_covariance"
    table = Table(["name", "a much wider column of ordinary words"],
                  [[ident, "word " * 40], ["T1.phi.L1.ideal", "short"]])  # fmt: skip
    doc = Document("t", "", "", [], [Section("s", "S", [table])])
    pdf = tmp_path / "ids.pdf"
    pdf.write_bytes(R.compile_pdf(doc, tmp_path).data)
    r = _run(POPPLER["pdftotext"], "-enc", "UTF-8", str(pdf), "-")
    assert "\u200b" not in r.stdout
    assert "T1.phi.L1.ideal" in r.stdout  # on one line: copied as it is
    assert ident in "".join(r.stdout.split())  # across lines: the same characters in order


# ------------------------------------------------------------------------------------------
# the real report
# ------------------------------------------------------------------------------------------
BUILD_SCRIPT = """
import sys
from pathlib import Path
from pipeline.report.document import build_document
from pipeline.report.reproduction_pdf import write_pdf
root = Path(sys.argv[1])
write_pdf(build_document(root=root), sys.argv[2], root=root)
"""


@pytest.fixture(scope="module")
def report(results_repo, tmp_path_factory):
    """(document, PDF path, build seconds, repo) of the real report."""
    from pipeline.report.document import build_document

    out = tmp_path_factory.mktemp("pdf") / "reproduction.pdf"
    t0 = time.perf_counter()
    doc = build_document(root=results_repo)
    build = R.compile_pdf(doc, results_repo)
    seconds = time.perf_counter() - t0
    out.write_bytes(build.data)
    print(f"reproduction.pdf: {len(build.data)} bytes, built in {seconds:.1f} s")
    return doc, out, build, results_repo


@pytest.mark.parametrize("_", [pytest.param(None, marks=NEEDS_RUN)])
def test_every_expression_typeset_no_warnings(report, _):
    _, _, build, _ = report
    assert build.fallbacks == frozenset()
    assert build.warnings == ()


@pytest.mark.parametrize("_", [pytest.param(None, marks=NEEDS_RUN)])
def test_rebuild_in_another_process_is_byte_identical(report, tmp_path, _):
    _, pdf, _, repo = report
    again = tmp_path / "again.pdf"
    env = {**os.environ, "PYTHONPATH": str(ROOT), "PYTHONHASHSEED": "12345"}
    r = subprocess.run(
        [sys.executable, "-c", BUILD_SCRIPT, str(repo), str(again)],
        capture_output=True,
        text=True,
        env=env,
        timeout=HANG_GUARD_S,
    )
    assert r.returncode == 0, r.stderr[-3000:]
    assert again.read_bytes() == pdf.read_bytes()
    assert b"CreationDate" not in pdf.read_bytes()  # no timestamp in the file


@pytest.mark.parametrize("_", [pytest.param(None, marks=NEEDS_RUN)])
def test_every_page_renders(report, tmp_path, _):
    _, pdf, _, _ = report
    n = page_count(pdf)
    r = render_pages(pdf, tmp_path / "png")
    assert r.returncode == 0, r.stderr
    assert r.stderr == "", r.stderr  # poppler reports any syntax problem on stderr
    pngs = sorted((tmp_path / "png").glob("page-*.png"))
    assert len(pngs) == n
    assert all(p.stat().st_size > 1000 for p in pngs)


@pytest.mark.parametrize("_", [pytest.param(None, marks=NEEDS_RUN)])
def test_only_embedded_fonts(report, _):
    if POPPLER["pdffonts"] is None:
        pytest.skip("pdffonts not installed")
    _, pdf, _, _ = report
    r = _run(POPPLER["pdffonts"], str(pdf))
    assert r.returncode == 0 and not r.stderr.strip(), r.stderr
    fonts = [line.split() for line in r.stdout.splitlines()[2:] if line.strip()]
    assert fonts
    for f in fonts:
        name = f[0].split("+")[-1]
        assert name.startswith(EMBEDDED_FONTS), name
        assert "yes" in f[-5:-2], f  # embedded (emb column)


#: the most pages the main part (everything before the first appendix) may take
MAIN_PART_PAGES = 25


def _first_page_with(pages: list[str], start: int, title: str) -> int:
    """The index of the first page from ``start`` on whose text starts with ``title``
    (compared without whitespace)."""
    key = title.replace(" ", "")
    for i in range(start, len(pages)):
        if pages[i].replace(" ", "").startswith(key):
            return i
    raise AssertionError(f"no page starts with {title!r}")


@pytest.mark.parametrize("_", [pytest.param(None, marks=NEEDS_RUN)])
def test_section_titles_and_pages_match_the_html(report, _):
    from pipeline.report.reproduction_html import render_html

    doc, pdf, _, _ = report
    expected = html_headings(render_html(doc))
    # the HTML, the model and the PDF number the same sections the same way
    assert expected == [(num, _norm(title)) for num, title, _ in R.section_titles(doc)]
    assert len(expected) >= 3 * 6  # every paper has its summary, audit, numbers ... sections

    pages = page_texts(pdf)
    n = page_count(pdf)
    assert len(pages) == n
    # the title matter (abstract, the papers in brief, the contents), then the body
    assert pages[0].startswith(_norm(doc.title)) and "Abstract." in pages[0]
    first = f"{expected[0][0]} {expected[0][1]}"
    body_start = _first_page_with(pages, 1, first)
    assert any("Contents" in p for p in pages[:body_start])
    body = pages[body_start:]
    # every numbered title is in the body, in the HTML's order (compared without whitespace:
    # a long title may break after a slash)
    text, pos = "".join(body).replace(" ", ""), 0
    for num, title in expected:
        found = text.find(f"{num}{title}".replace(" ", ""), pos)
        assert found >= 0, f"section {num} {title!r} not found in the PDF after offset {pos}"
        pos = found + 1
    # the main part flows; each appendix starts a page, but the first: it follows the heading
    # "Appendices", which starts one
    top = [f"{num} {title}" for num, title in expected if "." not in num]
    appendices = top[len(doc.sections) + 1 :]
    starts = [
        t for t in top if any(p.replace(" ", "").startswith(t.replace(" ", "")) for p in body)
    ]
    assert set(appendices) <= set(starts), set(appendices) - set(starts)
    assert any(p.startswith(R.APPENDIX_HEADING) for p in body)
    # the footer of the last page numbers the body pages ("k / k")
    body_pages = n - body_start
    assert pages[-1].endswith(f"{body_pages} / {body_pages}")


@pytest.mark.parametrize("_", [pytest.param(None, marks=NEEDS_RUN)])
def test_main_part_fits_the_page_budget(report, _):
    """The main part (title matter, introduction, papers, discussion, references) takes at
    most MAIN_PART_PAGES pages: the equation forms and the other appendices follow it."""
    doc, pdf, _, _ = report
    pages = page_texts(pdf)
    first = _first_page_with(pages, 1, R.APPENDIX_HEADING)
    print(f"main part: {first} pages of {len(pages)}")
    assert first <= MAIN_PART_PAGES, f"the main part takes {first} pages"
    assert f"A {doc.appendices[0].title}" in pages[first]


@pytest.mark.parametrize("_", [pytest.param(None, marks=NEEDS_RUN)])
def test_pdf_text_has_one_vocabulary_and_no_zero_width_space(report, _):
    _, pdf, _, _ = report
    r = _run(POPPLER["pdftotext"], "-enc", "UTF-8", str(pdf), "-")
    assert "\u200b" not in r.stdout
    for token in ("not_reproduced", "not_upheld", "not_checkable"):
        assert token not in r.stdout, token
    # a file beside the report is named by its place in the repository
    assert "reports/notebooks/" in "".join(r.stdout.split())


@pytest.mark.parametrize("_", [pytest.param(None, marks=NEEDS_RUN)])
def test_nothing_runs_off_the_text_area(report, tmp_path, _):
    """Every word of every page (pdftotext -bbox) stays inside the page less 15 mm per side:
    tables, wide equations and their line-broken forms fit (the margins are 20 mm)."""
    _, pdf, _, _ = report
    out = tmp_path / "bbox.html"
    r = _run(POPPLER["pdftotext"], "-bbox", str(pdf), str(out))
    assert r.returncode == 0, r.stderr
    inset = 15 / 25.4 * 72
    off = []
    for n, page in enumerate(out.read_text(encoding="utf-8").split("<page ")[1:], 1):
        width = float(re.search(r'width="([\d.]+)"', page).group(1))
        for m in re.finditer(r'xMin="([\d.]+)" yMin="[\d.]+" xMax="([\d.]+)"[^>]*>([^<]*)<', page):
            if float(m.group(1)) < inset or float(m.group(2)) > width - inset:
                off.append((n, m.group(3)))
    assert off == [], off[:10]


def test_breakable_text_keeps_its_spaces_and_compiles(tmp_path):
    """A long token followed by ' (' stays markup: the space survives (else Typst reads the
    token's last box as a function called with the parenthesis, "expected comma")."""
    import typst

    from pipeline.report.typst_source import breakable

    text = "over the sweep of imu_rate_hz, intensity, initial_error_deg (20 runs a point) [x]"
    src = breakable(text)
    assert "#box[deg] (20" in src and "intensity, #box" in src
    page = tmp_path / "a.typ"
    page.write_text(f"#table(columns: 1, [{src}])", encoding="utf-8")
    assert typst.compile(str(page))[:4] == b"%PDF"
