"""Figures at print size: the widths at which the PDF report sets a figure, the smallest text
it may print, the font sizes a figure drawn for those widths uses, and the printed text size of
a saved figure.

The PDF report sets a figure at the width it was drawn (its SVG's ``width``), at most the
text width: a figure drawn :data:`COLUMN_WIDTH_IN` wide is set beside another, one drawn wider
alone. A figure drawn at its print width therefore prints its text at the font size it was
given; :data:`FONT_PT` are those sizes, all at least :data:`MIN_TEXT_PT`.

The printed size of a text is measured, not assumed: :func:`svg_texts` reads the font size of
every text of an SVG written by :mod:`pipeline.figure_files` (text drawn as paths: Matplotlib
scales each text's glyphs by ``font size / 100``), and :func:`printed_texts` scales it by
``placed width / drawn width``.

>>> from matplotlib.figure import Figure
>>> from pipeline.figure_files import render
>>> fig = Figure(figsize=(2, 1)); ax = fig.add_subplot(); _ = ax.set_title("t", fontsize=8)
>>> svg = render(fig, dpi=50)["svg"]
>>> svg_width_mm(svg) == 2 * MM_PER_IN, ("t", 8.0) in svg_texts(svg)
(True, True)
>>> ("t", 4.0) in printed_texts(svg, placed_width_mm=MM_PER_IN)
True
"""

from __future__ import annotations

import re
import xml.etree.ElementTree as ET

__all__ = [
    "COLUMN_WIDTH_IN",
    "FONT_PT",
    "FONT_RC",
    "MIN_TEXT_PT",
    "MM_PER_IN",
    "TEXT_WIDTH_IN",
    "printed_texts",
    "svg_texts",
    "svg_width_mm",
]

MM_PER_IN = 25.4
#: the text width of the PDF report (A4, 20 mm margins)
TEXT_WIDTH_MM = 170.0
#: the gap between two figures set side by side
GUTTER_MM = 5.0
#: a figure set beside another: half the text width less half the gutter (rounded down)
COLUMN_WIDTH_MM = 82.0
TEXT_WIDTH_IN = TEXT_WIDTH_MM / MM_PER_IN
COLUMN_WIDTH_IN = COLUMN_WIDTH_MM / MM_PER_IN
#: the smallest printed text of a figure (tick labels, legends, insets, titles), in pt
MIN_TEXT_PT = 7.0
#: font sizes (pt) of a figure drawn at its print width
FONT_PT = {
    "tick": 7.5,
    "label": 8.0,
    "legend": 7.5,
    "note": 7.5,
    "panel_title": 8.0,
    "title": 9.0,
}
#: the same sizes as Matplotlib rc settings, for ``matplotlib.rc_context``
FONT_RC = {
    "font.size": FONT_PT["label"],
    "axes.titlesize": FONT_PT["panel_title"],
    "axes.labelsize": FONT_PT["label"],
    "xtick.labelsize": FONT_PT["tick"],
    "ytick.labelsize": FONT_PT["tick"],
    "legend.fontsize": FONT_PT["legend"],
    "figure.titlesize": FONT_PT["title"],
}
SVG_NS = "{http://www.w3.org/2000/svg}"
_SCALE = re.compile(r"scale\(([-\d.e]+)")
_LENGTH = re.compile(r"^([\d.]+)(pt|px|in|mm)?$")
_UNIT_MM = {"pt": MM_PER_IN / 72.0, None: MM_PER_IN / 72.0, "px": MM_PER_IN / 72.0}
_UNIT_MM |= {"in": MM_PER_IN, "mm": 1.0}


def _root(svg: bytes | str) -> ET.Element:
    data = svg.encode("utf-8") if isinstance(svg, str) else svg
    parser = ET.XMLParser(target=ET.TreeBuilder(insert_comments=True))
    return ET.fromstring(data, parser=parser)


def _root_start(svg: bytes | str) -> ET.Element:
    """The root element of an SVG with its attributes, parsed no further than its start tag
    (a figure's SVG is ~1 MB)."""
    data = svg.encode("utf-8") if isinstance(svg, str) else svg
    parser = ET.XMLPullParser(events=("start",))
    for at in range(0, max(len(data), 1), 8192):
        parser.feed(data[at : at + 8192])
        for _event, element in parser.read_events():
            return element
    parser.close()  # raises the parse error of a file without a root element
    raise ValueError("SVG without a root element")


def svg_width_mm(svg: bytes | str) -> float:
    """The width of an SVG (its ``width`` attribute) in mm."""
    width = _root_start(svg).get("width", "")
    m = _LENGTH.match(width.strip())
    if m is None:
        raise ValueError(f"SVG width {width!r} is not a length")
    return float(m.group(1)) * _UNIT_MM[m.group(2)]


def svg_texts(svg: bytes | str) -> list[tuple[str, float]]:
    """(text, font size in pt at the SVG's own size) of every text of a Matplotlib SVG whose
    text is drawn as paths (``<g id="text_N">``, the text in a comment, the glyph group scaled
    by font size / 100). A sub- or superscript inside a text is drawn smaller; the text's size
    is its font size."""
    out = []
    for group in _root(svg).iter(f"{SVG_NS}g"):
        if not group.get("id", "").startswith("text_"):
            continue
        label = next(
            (c.text.strip() for c in group if c.tag is ET.Comment and c.text), group.get("id")
        )
        scales = [
            abs(float(m.group(1)))
            for g in group.iter(f"{SVG_NS}g")
            if (m := _SCALE.search(g.get("transform", "")))
        ]
        if not scales:
            raise ValueError(f"SVG text {label!r} has no glyph scale: is it drawn as paths?")
        out.append((label, round(scales[0] * 100.0, 3)))
    return out


def printed_texts(svg: bytes | str, placed_width_mm: float) -> list[tuple[str, float]]:
    """(text, printed size in pt) of every text of ``svg`` set ``placed_width_mm`` wide."""
    factor = placed_width_mm / svg_width_mm(svg)
    return [(label, round(size * factor, 3)) for label, size in svg_texts(svg)]
