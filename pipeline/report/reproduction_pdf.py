"""The combined reproduction report as a printable PDF, typeset with Typst (no TeX).

``render_typst(doc)`` turns the shared content model (:mod:`pipeline.report.document`) into one
Typst source: A4, a title page with the abstract and each paper's summary and main claims
(:mod:`pipeline.report.typst_front`), a table of contents, the numbered sections of the main
part, flowing from one to the next (:mod:`pipeline.report.typst_blocks`), then the appendices
numbered A, B, ..., each on a new page, with the equation audits typeset as mathematics from
the SymPy ``srepr`` fields (:mod:`pipeline.report.typst_equations`,
:mod:`pipeline.report.typst_math`).

``write_pdf(doc, path)`` compiles it with the ``typst`` package from PyPI. The output depends on
nothing but the document and the image files: only the fonts embedded in the typst package are
used (system fonts are ignored), the document carries no date, and no package is downloaded, so
rebuilding from the same results gives the same bytes.
"""

from __future__ import annotations

import os
from collections.abc import Iterable, Iterator
from dataclasses import dataclass, field
from pathlib import Path

from pipeline.atomic import write_bytes
from pipeline.report.model import Document, Section
from pipeline.report.typst_blocks import BlockRenderer, walk
from pipeline.report.typst_front import title_page
from pipeline.report.typst_source import FONTS, PREAMBLE, breakable, escape, label_name
from pipeline.report.typst_symbols import typst_string

__all__ = [
    "APPENDIX_HEADING",
    "FONTS",
    "PdfBuild",
    "Rendered",
    "breakable",
    "compile_pdf",
    "escape",
    "render_typst",
    "section_titles",
    "write_pdf",
]

#: the heading before the appendices (unnumbered, in the contents)
APPENDIX_HEADING = "Appendices"


@dataclass
class Rendered:
    """Typst source plus the math snippets it contains (``bad``: snippets shown as raw text)."""

    source: str
    snippets: list[str] = field(default_factory=list)
    bad: frozenset[str] = frozenset()


def _render(doc: Document, root: Path, bad: frozenset[str]) -> Rendered:
    labels = {s.id: label_name(s.id) for s in walk([*doc.sections, *doc.appendices])}
    r = BlockRenderer(root, labels, bad)
    preamble = PREAMBLE.replace("TITLE", typst_string(doc.title))
    for key, name in FONTS.items():
        preamble = preamble.replace(f"FONT_{key.upper()}", name)
    parts = [preamble, title_page(r, doc), "#counter(page).update(1)"]
    for sec in doc.sections:  # the main part flows: a section starts below the one before
        parts.extend(r.section(sec, 1))
    if doc.appendices:
        parts.append("#pagebreak(weak: true)")
        parts.append("#counter(heading).update(0)")
        parts.append('#set heading(numbering: "A.1")')
        parts.append(
            f"#heading(level: 1, numbering: none)[{escape(APPENDIX_HEADING)}] <appendices>"
        )
        for k, sec in enumerate(doc.appendices):
            if k:
                parts.append("#pagebreak(weak: true)")
            parts.extend(r.section(sec, 1))
    return Rendered("\n\n".join(parts) + "\n", r.equations.snippets, bad)


def render_typst(doc: Document, root: str | os.PathLike[str] = ".", bad: Iterable[str] = ()) -> str:
    """The complete Typst source of the report. Image paths are written relative to ``root``
    (the compile root, which must contain them); ``bad``: math snippets to show as raw text."""
    return _render(doc, Path(root), frozenset(bad)).source


def _numbered(
    sections: Iterable[Section], prefix: str = "", top: list[str] | None = None
) -> Iterator[tuple[str, str, int]]:
    for i, s in enumerate(sections, 1):
        num = f"{prefix}{top[i - 1] if top else i}"
        yield num, s.title, num.count(".") + 1
        yield from _numbered(s.subsections, num + ".")


def section_titles(doc: Document) -> list[tuple[str, str, int]]:
    """(number, title, level) of every section, numbered as in the PDF (``1``, ``1.2`` ...,
    the appendices ``A``, ``A.1`` ...)."""
    letters = [chr(ord("A") + k) for k in range(len(doc.appendices))]
    return list(_numbered(doc.sections)) + list(_numbered(doc.appendices, "", letters))


def _typst_compile(source: str, root: Path) -> tuple[bytes, list[str]]:
    """(PDF bytes, warning messages) of a Typst source; raises typst.TypstError."""
    import typst

    data, warnings = typst.compile_with_warnings(
        source.encode("utf-8"),
        format="pdf",
        root=str(root),
        font_paths=[],
        ignore_system_fonts=True,
        # untagged: poppler (pdftoppm 22.12) reports the MarkInfo of typst's tagged PDFs as a
        # syntax error ("Suspects object is wrong type"); tags also add a third to the size
        pdf_tags=False,
    )
    return data, [w.message for w in warnings]


def _failing_snippets(snippets: list[str], root: Path) -> set[str]:
    """The math snippets that do not compile on their own."""
    import typst

    bad = set()
    for s in dict.fromkeys(snippets):
        try:
            typst.compile(
                f"$ {s} $".encode(), format="pdf", root=str(root), ignore_system_fonts=True
            )
        except typst.TypstError:
            bad.add(s)
    return bad


@dataclass(frozen=True)
class PdfBuild:
    """A compiled report: the PDF bytes, the Typst source, the math snippets shown as text
    because they did not typeset (normally none), and Typst's warnings."""

    data: bytes
    source: str
    fallbacks: frozenset[str]
    warnings: tuple[str, ...]


def compile_pdf(doc: Document, root: str | os.PathLike[str] = ".") -> PdfBuild:
    """Compile the report. If some expression does not typeset, the expressions are checked
    one by one and the failing ones are shown as text (and named on stderr)."""
    import sys

    import typst

    root = Path(root).resolve()
    rendered = _render(doc, root, frozenset())
    try:
        data, warnings = _typst_compile(rendered.source, root)
    except typst.TypstError as exc:
        bad = frozenset(_failing_snippets(rendered.snippets, root))
        if not bad:
            raise
        print(
            f"reproduction_pdf: {len(bad)} expression(s) did not typeset ({exc.message}); "
            "shown as text:\n  " + "\n  ".join(sorted(bad)),
            file=sys.stderr,
        )
        rendered = _render(doc, root, bad)
        data, warnings = _typst_compile(rendered.source, root)
    for w in warnings:
        print(f"reproduction_pdf: typst warning: {w}", file=sys.stderr)
    return PdfBuild(data, rendered.source, rendered.bad, tuple(warnings))


def write_pdf(
    doc: Document, path: str | os.PathLike[str], root: str | os.PathLike[str] | None = None
) -> Path:
    """Compile the report and write it atomically to ``path``. ``root`` (default: the
    repository root of :mod:`pipeline.report.document`) is the compile root: it must
    contain every figure."""
    from pipeline.report.document import ROOT  # the repository root

    build = compile_pdf(doc, ROOT if root is None else root)
    out = write_bytes(path, build.data)
    print(f"reproduction_pdf: {path}: {len(build.data)} bytes")
    return out
