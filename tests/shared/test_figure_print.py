"""Figures print legibly: every text of every figure the PDF report places (tick labels,
legends, insets, titles) prints at MIN_TEXT_PT or more, computed from the saved SVG (its font
sizes) and the Typst source (the width it is set at); figures are set at the width they were
drawn, two abreast only when drawn for a column."""

from __future__ import annotations

from pathlib import Path

import pytest
from matplotlib.backends.backend_agg import FigureCanvasAgg
from matplotlib.figure import Figure as MplFigure

from pipeline.figure_files import write_png_svg
from pipeline.figure_print import (
    COLUMN_WIDTH_IN,
    COLUMN_WIDTH_MM,
    MIN_TEXT_PT,
    TEXT_WIDTH_IN,
    TEXT_WIDTH_MM,
    printed_texts,
    svg_texts,
    svg_width_mm,
)
from pipeline.report.figure_legibility import printed_figure_texts, small_print
from pipeline.report.model import Figure
from pipeline.report.typst_blocks import BlockRenderer, placed_images, walk
from tests.workflow_harness import NEEDS_RUN


def _figure(path: Path, width_in: float, font_pt: float) -> Path:
    """A one-panel figure ``width_in`` wide whose every text is ``font_pt``."""
    fig = MplFigure(figsize=(width_in, 0.7 * width_in), dpi=60)
    FigureCanvasAgg(fig)
    ax = fig.add_subplot()
    ax.plot([0, 1], [1, 0], label="curve")
    ax.set_yscale("log")
    ax.set_title("Fig. 1 title", fontsize=font_pt)
    ax.set_xlabel("time (s)", fontsize=font_pt)
    ax.tick_params(labelsize=font_pt)
    ax.legend(fontsize=font_pt)
    return write_png_svg(fig, path, 60)[1]


def test_svg_text_sizes_are_read_from_the_glyph_scale(tmp_path):
    fig = MplFigure(figsize=(3.0, 2.0), dpi=60)
    FigureCanvasAgg(fig)
    ax = fig.add_subplot()
    ax.plot([1, 10], [1, 100])
    ax.set_yscale("log")  # tick labels 10^k: mathtext with a smaller superscript
    ax.set_title("a title", fontsize=9.0)
    ax.set_ylabel("error (deg)", fontsize=7.25)
    ax.tick_params(labelsize=6.5)
    ax.text(0.5, 0.5, "inset note", fontsize=5.0, rotation=30)
    svg = write_png_svg(fig, tmp_path / "f.png", 60)[1].read_bytes()
    texts = dict(svg_texts(svg))
    assert texts["a title"] == 9.0
    assert texts["error (deg)"] == 7.25
    assert texts["inset note"] == 5.0
    ticks = [size for text, size in svg_texts(svg) if text.startswith("$")]
    assert ticks and set(ticks) == {6.5}
    assert svg_width_mm(svg) == pytest.approx(3.0 * 25.4)
    # set at half its width, every text prints at half its size
    half = dict(printed_texts(svg, 1.5 * 25.4))
    assert half["a title"] == 4.5


def test_a_figure_drawn_for_a_column_goes_beside_another_at_its_size(tmp_path):
    a = _figure(tmp_path / "a.png", COLUMN_WIDTH_IN, 7.5)
    b = _figure(tmp_path / "b.png", COLUMN_WIDTH_IN, 7.5)
    r = BlockRenderer(tmp_path, {})
    source = r.figures([Figure(str(a.with_suffix(".png")), "a", "Fig. 1"),
                        Figure(str(b.with_suffix(".png")), "b", "Fig. 2")])  # fmt: skip
    assert source.startswith("#grid(columns: (1fr, 1fr)")
    assert placed_images(source) == [("a.svg", COLUMN_WIDTH_MM), ("b.svg", COLUMN_WIDTH_MM)]
    assert small_print(source, tmp_path) == []
    assert {t.size_pt for t in printed_figure_texts(source, tmp_path)} == {7.5}


def test_a_wide_figure_goes_alone_and_prints_at_its_size(tmp_path):
    wide = _figure(tmp_path / "w.png", TEXT_WIDTH_IN, 7.0)
    narrow = _figure(tmp_path / "n.png", COLUMN_WIDTH_IN, 8.0)
    r = BlockRenderer(tmp_path, {})
    source = r.figures([Figure(str(wide.with_suffix(".png")), "w", "Fig. 1"),
                        Figure(str(narrow.with_suffix(".png")), "n", "Fig. 2")])  # fmt: skip
    assert "#grid" not in source
    assert placed_images(source) == [("w.svg", TEXT_WIDTH_MM), ("n.svg", COLUMN_WIDTH_MM)]
    assert small_print(source, tmp_path) == []


def test_small_print_is_found_when_a_figure_is_set_smaller_than_drawn(tmp_path):
    """The old layout: a figure drawn 9 in wide with 9 pt text, set two abreast (82 mm),
    prints its text at 9 * 82 / 228.6 = 3.2 pt; one drawn too wide for the page is shrunk."""
    old = _figure(tmp_path / "old.png", 9.0, 9.0)
    source = f'#figure(image("/old.svg", width: {COLUMN_WIDTH_MM}mm))'
    small = small_print(source, tmp_path)
    assert small and {t.file for t in small} == {"old.svg"}
    assert max(t.size_pt for t in small) == pytest.approx(9.0 * 82.0 / (9.0 * 25.4), abs=1e-3)
    # the renderer itself caps it at the text width: still too small (9 * 170 / 228.6 = 6.7)
    placed = BlockRenderer(tmp_path, {}).figures([Figure(str(old.with_suffix(".png")), "", "")])
    assert placed_images(placed) == [("old.svg", TEXT_WIDTH_MM)]
    assert {round(t.size_pt, 2) for t in small_print(placed, tmp_path)} == {6.69}
    # text one hundredth of a point below the minimum is found too
    _figure(tmp_path / "edge.png", COLUMN_WIDTH_IN, MIN_TEXT_PT - 0.01)
    assert small_print(f'image("/edge.svg", width: {COLUMN_WIDTH_MM}mm)', tmp_path)


def test_a_placed_png_without_svg_is_refused(tmp_path):
    (tmp_path / "x.png").write_bytes(b"")
    with pytest.raises(ValueError, match="without an SVG"):
        small_print('image("/x.png", width: 80.0mm)', tmp_path)


@pytest.mark.parametrize("_", [pytest.param(None, marks=NEEDS_RUN)])
def test_every_figure_of_the_report_prints_legibly(results_repo, _):
    """The real report: every figure of the document is placed, and every text of every
    placed figure prints at MIN_TEXT_PT or more."""
    from pipeline.report.document import build_document
    from pipeline.report.reproduction_pdf import render_typst

    doc = build_document(root=results_repo)
    source = render_typst(doc, results_repo)
    placed = placed_images(source)
    figures = [
        Path(b.path).with_suffix(".svg").resolve().relative_to(results_repo.resolve()).as_posix()
        for s in walk([*doc.sections, *doc.appendices])
        for b in s.blocks
        if isinstance(b, Figure) and Path(b.path).is_file()
    ]
    assert figures and sorted(set(figures)) == sorted({p for p, _ in placed})
    texts = printed_figure_texts(source, results_repo)
    assert len(texts) >= 10 * len(placed)  # every figure has its ticks, labels and title
    small = [(t.file.rsplit("/", 1)[-1], t.text[:40], t.size_pt) for t in texts
             if t.size_pt < MIN_TEXT_PT]  # fmt: skip
    assert small == [], f"{len(small)} texts print below {MIN_TEXT_PT} pt: {small[:20]}"
