"""Small, paper-agnostic helpers for self-contained HTML report pages.

Everything a page needs is inline: the CSS is a ``<style>`` block, images are
base64 ``data:`` URIs, and there is no JavaScript, external stylesheet or CDN.
The output is deterministic (no timestamps), so rebuilding a page from the same
inputs gives the same bytes.

The pages are rendered from the document model (:mod:`pipeline.report.model`) by
:mod:`pipeline.report.reproduction_html` and :mod:`pipeline.report.page_html`, which use these
helpers. Every function returns an HTML *fragment* (a ``str``) except :func:`page` (a whole
document).
"""

from __future__ import annotations

import base64
import html as _html
import math
import os
import re
from collections.abc import Iterable
from numbers import Integral, Real
from pathlib import Path
from typing import Any

__all__ = [
    "DEFAULT_CSS",
    "css_class",
    "escape",
    "format_value",
    "page",
    "paragraph",
    "png_data_uri",
    "slugify",
    "toc",
]

#: Inline stylesheet. Row classes ``v-<word>`` colour verdict/status words used by
#: every paper of the project (reproduced, consistent, upheld, match are good;
#: not_reproduced, not_upheld are bad; not_checkable is neutral), ``t-<tone>`` the tone of
#: pipeline.report.vocabulary (a printed equation that differs is bad only as an error of the
#: paper, amber otherwise).
DEFAULT_CSS = """
body { font-family: system-ui, -apple-system, "Segoe UI", Roboto, "DejaVu Sans", sans-serif;
       max-width: 1200px; margin: 0 auto; padding: 1em 2em; line-height: 1.45; color: #1b1b1b; }
h1 { font-size: 1.7em; margin-bottom: 0.2em; }
h2 { border-bottom: 2px solid #ccc; padding-bottom: 0.15em; margin-top: 2em; }
h3 { margin-top: 1.5em; }
h2 a, h3 a, h4 a, h5 a { color: inherit; text-decoration: none; }
span.secno { color: #666; margin-right: 0.4em; font-variant-numeric: tabular-nums; }
section { margin-bottom: 1em; }
nav.toc ul { columns: 2; }
table.data { border-collapse: collapse; margin: 0.5em 0 1em 0; font-size: 0.9em; }
table.data caption { text-align: left; font-weight: bold; padding: 0.3em 0; }
table.data th, table.data td { border: 1px solid #bbb; padding: 0.25em 0.55em;
                               vertical-align: top; }
table.data th { background: #eef0f3; text-align: left; }
table.data td.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
tr.v-reproduced td, tr.v-consistent td, tr.v-upheld td, tr.v-match td { background: #eaf6ea; }
tr.v-not_reproduced td, tr.v-not_upheld td, tr.t-bad td { background: #fbe3e1; }
tr.v-not_checkable td { background: #f1f1f1; color: #555; }
tr.v-missing td, tr.t-partial td, tr.v-differs td { background: #fff4d6; }
span.v-reproduced, span.v-consistent, span.v-upheld, span.v-match {
  color: #1d6b1d; font-weight: bold; }
span.v-not_reproduced, span.v-not_upheld, span.t-bad { color: #a3261a; font-weight: bold; }
span.v-not_checkable { color: #555; font-weight: bold; }
span.v-missing, span.t-partial, span.v-differs { color: #8a5a00; font-weight: bold; }
tr.v-differs.t-bad td { background: #fbe3e1; }
span.v-differs.t-bad { color: #a3261a; }
tr.v-differs.t-neutral td { background: #f1f1f1; }
span.v-differs.t-neutral { color: #555; }
ul.marks { list-style: none; padding-left: 0.2em; }
ul.marks li { margin: 0.35em 0; }
span.mark { display: inline-block; min-width: 3.4em; font-weight: bold; }
span.mark.m-re { color: #1d6b1d; }
span.mark.m-not-re { color: #a3261a; }
span.mark.m-not-checkable { color: #555; min-width: 7.5em; }
ul.marks span.where { color: #555; }
ul.marks span.basis { color: #444; font-size: 0.9em; margin-left: 3.6em; display: inline-block; }
details.matching { margin: 0.4em 0 1.2em 0; }
details.matching summary { cursor: pointer; color: #1f4e99; }
figure { margin: 1em 0 2em 0; }
figure img { max-width: 100%; height: auto; border: 1px solid #ddd; }
figcaption { font-size: 0.9em; color: #333; max-width: 60em; }
p.na { color: #777; font-style: italic; }
code, pre { font-family: "DejaVu Sans Mono", Menlo, Consolas, monospace; font-size: 0.9em; }
pre { background: #f6f6f6; padding: 0.5em; overflow-x: auto; }
dl.kv { display: grid; grid-template-columns: max-content auto; gap: 0.15em 1em; }
dl.kv dt { font-weight: bold; }
dl.kv dd { margin: 0; }
"""

_VOID = re.compile(r"[^a-z0-9_-]+")


def escape(value: object) -> str:
    """HTML-escape ``str(value)`` (quotes included); ``None``/NaN become ``""``."""
    if value is None:
        return ""
    if isinstance(value, float) and math.isnan(value):
        return ""
    return _html.escape(str(value), quote=True)


def slugify(text: object) -> str:
    """A lower-case anchor/class token: ``"Table 1 — roll"`` -> ``"table-1-roll"``."""
    slug = re.sub(r"[^a-z0-9]+", "-", str(text).lower()).strip("-")
    return slug or "x"


def css_class(value: object, prefix: str = "v-") -> str:
    """Class token for a verdict/status word: ``"not_reproduced"`` -> ``"v-not_reproduced"``."""
    token = _VOID.sub("-", str(value).strip().lower()).strip("-")
    return f"{prefix}{token or 'none'}"


def format_value(value: Any, sig: int = 9) -> str:
    """Format one cell: integers as is, floats with ``sig`` significant digits
    (no trailing noise like ``0.30000000000000004``), NaN/None as ``""``."""
    if value is None:
        return ""
    if isinstance(value, bool):
        return str(value)
    if isinstance(value, Integral):
        return str(int(value))
    if isinstance(value, Real):
        x = float(value)
        if math.isnan(x):
            return ""
        if math.isinf(x):
            return "inf" if x > 0 else "-inf"
        return f"{x:.{sig}g}"
    return str(value)


def paragraph(text: str, *, raw: bool = False, cls: str | None = None) -> str:
    """``<p>`` with escaped text (``raw=True`` if ``text`` is already HTML)."""
    attr = f' class="{escape(cls)}"' if cls else ""
    return f"<p{attr}>{text if raw else escape(text)}</p>\n"


def toc(entries: Iterable[tuple[str, str]]) -> str:
    """Table of contents from ``(anchor, title)`` pairs (in-page links only)."""
    items = "".join(f'<li><a href="#{escape(a)}">{escape(t)}</a></li>\n' for a, t in entries)
    return f'<nav class="toc"><ul>\n{items}</ul></nav>\n'


def png_data_uri(source: str | os.PathLike[str] | bytes) -> str:
    """``data:image/png;base64,...`` from PNG bytes or a PNG file path.

    Raises ``ValueError`` if the bytes are not a PNG (checks the signature).
    """
    data = source if isinstance(source, bytes) else Path(source).read_bytes()
    if not data.startswith(b"\x89PNG\r\n\x1a\n"):
        raise ValueError(f"not a PNG: {source if not isinstance(source, bytes) else '<bytes>'}")
    return "data:image/png;base64," + base64.b64encode(data).decode("ascii")


def page(title: str, body: str, *, css: str = DEFAULT_CSS, lang: str = "en") -> str:
    """A complete, self-contained HTML5 document (inline CSS, no scripts)."""
    return (
        "<!DOCTYPE html>\n"
        f'<html lang="{escape(lang)}">\n<head>\n<meta charset="utf-8">\n'
        '<meta name="viewport" content="width=device-width, initial-scale=1">\n'
        f"<title>{escape(title)}</title>\n<style>{css}</style>\n</head>\n"
        f"<body>\n{body}</body>\n</html>\n"
    )
