"""Figure files: one Matplotlib figure written as PNG (raster, shown inline by the HTML pages)
and as SVG beside it (vector, typeset by the PDF report, which takes the SVG of a PNG when there
is one, so printed figures are sharp at any size).

Both are byte-identical across runs: no date or software stamp, a fixed ``svg.hashsalt`` for
the SVG element ids, text drawn as paths (no font needed to show the SVG). Files are written
atomically (:mod:`pipeline.atomic`).

A figure laid out once with ``fig.tight_layout()`` keeps a do-nothing placeholder layout engine,
and ``savefig`` draws a figure that has a layout engine twice (once, not rendered, to run the
engine; once for the file). :func:`render` sets the placeholder aside while it saves, so each
file is drawn once: the same bytes (every figure of the reference run compared), about a third
less CPU per file. Each draw runs inside :func:`pipeline.figure_layout.measured_once` (an
axis' ticks and tick-label extents computed once per draw, not three and two times).

>>> from matplotlib.figure import Figure
>>> fig = Figure(figsize=(2, 1)); _ = fig.add_subplot().plot([0, 1], [1, 0])
>>> a, b = render(fig, dpi=50), render(fig, dpi=50)
>>> a == b, a["png"][:4] == b"\\x89PNG", b"<svg" in a["svg"]
(True, True, True)
>>> fig.tight_layout(); engine = fig.get_layout_engine()
>>> render(fig, dpi=50) == render(fig, dpi=50), fig.get_layout_engine() is engine
(True, True)
"""

from __future__ import annotations

import io
from pathlib import Path

import matplotlib
from matplotlib.layout_engine import PlaceHolderLayoutEngine

from pipeline.atomic import write_bytes
from pipeline.figure_layout import measured_once

__all__ = ["METADATA", "SVG_HASHSALT", "render", "write_png_svg"]

#: Fixed salt for the ids of SVG elements (Matplotlib draws them at random otherwise).
SVG_HASHSALT = "inertial-repro"
#: ``savefig`` metadata per format: no dates, no software stamp.
METADATA = {"png": {"Software": None}, "svg": {"Date": None, "Creator": None}}


def render(fig, dpi: float, salt: str = SVG_HASHSALT) -> dict[str, bytes]:
    """``{"png": bytes, "svg": bytes}`` of ``fig`` (a Matplotlib figure), deterministically."""
    out: dict[str, bytes] = {}
    engine = fig.get_layout_engine()
    rc = {"svg.hashsalt": salt, "svg.fonttype": "path"}
    # no automatic layout engine either: set_layout_engine(None) then leaves the figure without
    rc |= {"figure.autolayout": False, "figure.constrained_layout.use": False}
    with matplotlib.rc_context(rc):
        if isinstance(engine, PlaceHolderLayoutEngine):
            fig.set_layout_engine(None)  # its execute() does nothing: no layout pass to run
        try:
            for fmt in ("png", "svg"):
                buf = io.BytesIO()
                with measured_once(fig):  # ticks and tick-label extents once per draw
                    fig.savefig(buf, format=fmt, dpi=dpi, metadata=METADATA[fmt])
                out[fmt] = buf.getvalue()
        finally:
            if isinstance(engine, PlaceHolderLayoutEngine):
                fig.set_layout_engine(engine)
    return out


def write_png_svg(fig, png_path: str | Path, dpi: float) -> list[Path]:
    """Write ``png_path`` and the SVG beside it (same stem); returns both paths."""
    png_path = Path(png_path)
    if png_path.suffix != ".png":
        raise ValueError(f"figure path {str(png_path)!r} must end in .png (the SVG goes beside it)")
    data = render(fig, dpi)
    return [
        write_bytes(png_path, data["png"]),
        write_bytes(png_path.with_suffix(".svg"), data["svg"]),
    ]
