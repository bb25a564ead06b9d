"""The document model's blocks and sections as Typst (the PDF report's body).

Tables fit the text width (small type, column widths from the content, rows break across
pages with a repeated header); a verdict or status token is shown as its word in its colour;
figures are set at the width they were drawn, two abreast when both fit a column (the vector SVG
beside a PNG when there is one); a link to
a file beside the report names where the file is in the repository, as the PDF may travel
alone; the equation audit is rendered by :mod:`pipeline.report.typst_equations`.
"""

from __future__ import annotations

import re
from collections.abc import Iterator
from pathlib import Path
from typing import Any

from pipeline.figure_print import COLUMN_WIDTH_MM, GUTTER_MM, MM_PER_IN, svg_width_mm
from pipeline.report.model import (
    Bullets,
    EquationTable,
    Figure,
    Link,
    MainClaims,
    Paragraph,
    Section,
    Table,
)
from pipeline.report.typst_equations import EquationRenderer
from pipeline.report.typst_source import (
    TEXT_WIDTH_MM,
    breakable,
    column_widths,
    escape,
    image_size,
    is_number,
    png_dpi,
    typst_array,
)
from pipeline.report.typst_symbols import typst_string
from pipeline.report.vocabulary import MARK_WORDS, TOKENS, plain_words, tone, word

__all__ = ["BlockRenderer", "drawn_width_mm", "placed_images", "walk"]

#: a figure drawn this much wider than a column (rounding of inches to mm) still goes beside
#: another, at the column width
WIDTH_SLACK_MM = 0.5


def walk(sections: list[Section]) -> Iterator[Section]:
    for s in sections:
        yield s
        yield from walk(s.subsections)


class BlockRenderer:
    """Renders sections and blocks; ``labels`` maps section ids to Typst labels (for links),
    ``root`` is the compile root figures are read from."""

    def __init__(self, root: Path, labels: dict[str, str], bad: frozenset[str] = frozenset()):
        self.root = root
        self.labels = labels
        self.equations = EquationRenderer(bad)

    # ---- text -----------------------------------------------------------------------------
    def text(self, text: str) -> str:
        return escape(plain_words(text))

    def link(self, link: Link) -> str:
        target = link.target
        if target.startswith("#") and target[1:] in self.labels:
            return f"#link(<{self.labels[target[1:]]}>)[{escape(link.text)}]"
        if target.startswith("#"):
            return escape(link.text)
        if re.match(r"^[a-z][a-z0-9+.-]*://", target):
            return f"#link({typst_string(target)})[{escape(link.text)}]"
        # a file beside the report: the PDF may travel alone, so say where the file is
        where = link.path or target
        return f"{escape(link.text)}: the file {breakable(where)} of the repository."

    def status(self, token: str, differs_kind: str = "") -> str:
        return f"#status({typst_string(word(token))}, {typst_string(tone(token, differs_kind))})"

    def anchor_link(self, anchor: str, text: str) -> str:
        if anchor in self.labels:
            return f"#link(<{self.labels[anchor]}>)[{escape(text)}]"
        return escape(text)

    # ---- sections -------------------------------------------------------------------------
    def section(self, sec: Section, level: int) -> Iterator[str]:
        yield f"{'=' * level} {escape(sec.title)} <{self.labels[sec.id]}>"
        run: list[Figure] = []
        for block in [*sec.blocks, None]:
            if isinstance(block, Figure):
                run.append(block)
                continue
            if run:  # consecutive figures: two abreast
                yield self.figures(run)
                run = []
            if block is not None:
                yield self.block(block)
        for sub in sec.subsections:
            yield from self.section(sub, min(level + 1, 6))

    def block(self, block: Any) -> str:
        if isinstance(block, Paragraph):
            return "\n\n".join(self.text(p) for p in re.split(r"\n\s*\n", block.text) if p.strip())
        if isinstance(block, Bullets):
            items = "".join(f"[{self.text(item)}], " for item in block.items)
            return f"#list(spacing: 0.6em, {items})" if block.items else ""
        if isinstance(block, Table):
            return self.table(block)
        if isinstance(block, Figure):
            return self.figure(block)
        if isinstance(block, EquationTable):
            return self.equations.table(block)
        if isinstance(block, Link):
            return self.link(block)
        if isinstance(block, MainClaims):
            return self.main_claims(block)
        raise TypeError(f"unknown block {type(block).__name__}")

    def main_claims(self, block: MainClaims) -> str:
        lines = []
        for m in block.lines:
            mark = MARK_WORDS.get(m.mark, m.mark)
            body = f"[{escape(m.text)} #text(fill: neutral)[({escape(m.label)})]]"
            lines.append(
                f"claimline({typst_string(mark)}, {typst_string(tone(m.mark))}, {body}, "
                f"[{self.text(m.basis)}])"
            )
        return (
            "#block(above: 0.6em, below: 0.7em, stack(spacing: 0.45em, " + ", ".join(lines) + "))"
            if lines
            else ""
        )

    # ---- tables ---------------------------------------------------------------------------
    def table(self, table: Table) -> str:
        ncol = len(table.columns)
        budget = 120 if ncol <= 6 else 135  # characters across the text width at that size
        shown = [
            [word(c) if c.strip() in TOKENS else plain_words(c) for c in r] for r in table.rows
        ]
        widths = column_widths([plain_words(c) for c in table.columns], shown, budget)
        numeric = [
            all(is_number(r[j]) for r in table.rows if j < len(r) and r[j].strip())
            and any(j < len(r) and r[j].strip() for r in table.rows)
            for j in range(ncol)
        ]
        size = "8pt" if ncol <= 6 else "7.2pt"
        highlight = sorted(set(table.highlight))
        lines = []
        if table.caption:
            lines.append(
                "#block(sticky: true, above: 1.1em, below: 0.5em, "
                f"text(size: 9pt)[*{self.text(table.caption)}*])"
            )
        header = ", ".join(
            f"[{self.status(c) if c.strip() in TOKENS else breakable(plain_words(c))}]"
            for c in table.columns
        )
        cells = []
        for row in table.rows:
            row = list(row) + [""] * (ncol - len(row))
            for value in row[:ncol]:
                if value.strip() in TOKENS:  # a verdict word, in colour
                    cells.append(f"[{self.status(value.strip())}]")
                else:
                    cells.append(f"[{breakable(plain_words(value))}]")
        aligns = ", ".join("right" if n else "left" for n in numeric)
        fill = (
            f"fill: (x, y) => if y == 0 {{ headfill }} else if (y - 1) in {typst_array(highlight)} "
            "{ badfill },"
        )
        lines.append(
            f"#text(size: {size}, table(\n"
            f"  columns: {widths},\n"
            f"  align: ({aligns},),\n"
            f"  {fill}\n"
            f"  table.header({header}),\n  " + ", ".join(cells) + ",\n))"
        )
        return "\n".join(lines)

    # ---- figures --------------------------------------------------------------------------
    def figures(self, figs: list[Figure]) -> str:
        """Figures at the width they were drawn (:func:`drawn_width_mm`), at most the text
        width: two drawn no wider than a column (:data:`COLUMN_WIDTH_MM`) side by side, a
        wider one alone, and so is one left without a partner."""
        out: list[str] = []
        pair: list[Figure] = []

        def flush() -> None:
            if len(pair) == 1:
                out.append(self.figure(pair[0]))
            elif pair:
                cells = ", ".join(f"[{self.figure(f, COLUMN_WIDTH_MM)}]" for f in pair)
                out.append(
                    f"#grid(columns: (1fr, 1fr), column-gutter: {GUTTER_MM:g}mm, "
                    f"align: center + top, {cells})"
                )
            pair.clear()

        for f in figs:
            if self._drawn(f) > COLUMN_WIDTH_MM + WIDTH_SLACK_MM:
                flush()
                out.append(self.figure(f))
                continue
            pair.append(f)
            if len(pair) == 2:
                flush()
        flush()
        return "\n".join(out)

    def _path(self, fig: Figure) -> Path:
        path = Path(fig.path)
        return path if path.is_absolute() else self.root / path

    def _drawn(self, fig: Figure) -> float:
        return drawn_width_mm(self._path(fig))

    def figure(self, fig: Figure, max_width: float = TEXT_WIDTH_MM) -> str:
        path = self._path(fig)
        svg = path.with_suffix(".svg")
        shown = svg if svg.is_file() else path
        width = min(max_width, self._drawn(fig))
        try:
            rel = "/" + shown.resolve().relative_to(self.root.resolve()).as_posix()
        except ValueError:
            raise ValueError(f"figure {shown} is outside the compile root {self.root}") from None
        caption = (
            f"*{escape(fig.label)}.* {self.text(fig.caption)}"
            if fig.label
            else self.text(fig.caption)
        )
        return (
            f"#figure(image({typst_string(rel)}, width: {width:.1f}mm), numbering: none, "
            f"caption: [{caption}])"
        )


#: ``image("<path>", width: <w>mm)`` as :meth:`BlockRenderer.figure` writes it
_IMAGE = re.compile(r'image\("(/[^"]+)", width: ([\d.]+)mm\)')


def placed_images(source: str) -> list[tuple[str, float]]:
    """(path relative to the compile root, width in mm) of every image a Typst source of
    :class:`BlockRenderer` places, in order."""
    return [(m.group(1).lstrip("/"), float(m.group(2))) for m in _IMAGE.finditer(source)]


def drawn_width_mm(path: Path) -> float:
    """The width a figure was drawn at, in mm: its SVG's (the file or the one beside it), else
    a PNG's pixels over its resolution (pHYs), else the text width."""
    svg = path.with_suffix(".svg")
    if svg.is_file():
        return svg_width_mm(svg.read_bytes())
    size, dpi = image_size(path), png_dpi(path)
    if size is None or dpi is None:
        return TEXT_WIDTH_MM
    return size[0] / dpi * MM_PER_IN
