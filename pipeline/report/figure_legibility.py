"""The printed text of every figure the PDF report places: each text's font size in the saved
figure (its SVG, :func:`pipeline.figure_print.printed_texts`) times the width at which the
Typst source sets it over the width it was drawn (:func:`pipeline.report.typst_blocks.
placed_images`). :func:`small_print` lists what prints below a minimum
(:data:`pipeline.figure_print.MIN_TEXT_PT` by default).
"""

from __future__ import annotations

from dataclasses import dataclass
from pathlib import Path

from pipeline.figure_print import MIN_TEXT_PT, printed_texts
from pipeline.report.typst_blocks import placed_images

__all__ = ["PrintedText", "printed_figure_texts", "small_print"]


@dataclass(frozen=True)
class PrintedText:
    """One text of a placed figure: its file, words and printed size (pt)."""

    file: str
    text: str
    size_pt: float


def printed_figure_texts(source: str, root: Path) -> list[PrintedText]:
    """Every text of every figure ``source`` (a Typst source) places, at its printed size;
    ``root`` is the compile root the image paths are relative to. A placed figure must be an
    SVG (the PDF report takes the SVG beside a PNG)."""
    out = []
    for rel, width_mm in placed_images(source):
        path = root / rel
        if path.suffix != ".svg":
            raise ValueError(f"{rel}: a placed figure without an SVG; its text cannot be read")
        for text, size in printed_texts(path.read_bytes(), width_mm):
            out.append(PrintedText(rel, text, size))
    return out


def small_print(source: str, root: Path, minimum: float = MIN_TEXT_PT) -> list[PrintedText]:
    """The texts of placed figures that print smaller than ``minimum`` pt."""
    return [t for t in printed_figure_texts(source, root) if t.size_pt < minimum]
