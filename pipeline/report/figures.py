"""A paper's figures as model blocks, from its ``Paper.figures`` (file, paper number, caption).

A figure of the paper is labelled with its number (``Fig. 7``); one the paper lacks is an
``Extra fig. k`` (numbered in the order of ``Paper.figures``), its caption saying so and
naming its file.
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path

from pipeline.paper import FigureSpec, Paper
from pipeline.report.model import Figure

__all__ = ["figure_blocks"]


def figure_blocks(
    paper: Paper, figures_dir: Path, files: Sequence[str] | None = None
) -> list[Figure]:
    """The figures ``files`` (default: all) of ``paper`` under ``figures_dir``, in the order
    of ``files``; a missing file is rendered as "not available"."""
    extra = {f.file: k for k, f in enumerate((f for f in paper.figures if not f.in_paper), 1)}
    chosen: list[FigureSpec] = (
        list(paper.figures) if files is None else [paper.figure(f) for f in files]
    )
    out = []
    for spec in chosen:
        path = str((figures_dir / spec.file).resolve())
        if spec.in_paper:
            out.append(Figure(path, spec.caption, spec.label))
        else:
            caption = f"(not in the paper): {spec.caption} (figure file {Path(spec.file).stem})"
            out.append(Figure(path, caption, f"Extra fig. {extra[spec.file]}", in_paper=False))
    return out
