"""Small, paper-agnostic helpers for self-contained HTML report pages.

Everything a page needs is inline: the CSS is a ``<style>`` block, images are
base64 ``data:`` URIs, and there is no JavaScript, external stylesheet or CDN.
The output is deterministic (no timestamps), so rebuilding a page from the same
inputs gives the same bytes.

Typical use::

    from pipeline.report import html as H

    body = H.section("Summary", H.paragraph("..."), anchor="summary")
    body += H.section("Verdicts", H.table(df, class_column="verdict"), anchor="verdicts")
    H.write_atomic("reports/x.html", H.page("Title", body))

Every function returns an HTML *fragment* (a ``str``) except :func:`page`
(a whole document) and :func:`write_atomic`.
"""

from __future__ import annotations

import base64
import html as _html
import math
import os
import re
from collections.abc import Callable, Iterable, Mapping, Sequence
from numbers import Integral, Real
from pathlib import Path
from typing import Any

import pandas as pd

from pipeline.atomic import write_bytes

__all__ = [
    "DEFAULT_CSS",
    "css_class",
    "definition_list",
    "escape",
    "figure",
    "format_value",
    "not_available",
    "page",
    "paragraph",
    "png_data_uri",
    "section",
    "slugify",
    "table",
    "toc",
    "write_atomic",
]

#: Inline stylesheet. Row classes ``v-<word>`` colour verdict/status words used by
#: every paper of the project (reproduced, consistent, upheld, match are good;
#: not_reproduced, not_upheld, differs are bad; not_checkable is neutral).
DEFAULT_CSS = """
body { font-family: system-ui, -apple-system, "Segoe UI", Roboto, "DejaVu Sans", sans-serif;
       max-width: 1200px; margin: 0 auto; padding: 1em 2em; line-height: 1.45; color: #1b1b1b; }
h1 { font-size: 1.7em; margin-bottom: 0.2em; }
h2 { border-bottom: 2px solid #ccc; padding-bottom: 0.15em; margin-top: 2em; }
h3 { margin-top: 1.5em; }
section { margin-bottom: 1em; }
nav.toc ul { columns: 2; }
table.data { border-collapse: collapse; margin: 0.5em 0 1em 0; font-size: 0.9em; }
table.data caption { text-align: left; font-weight: bold; padding: 0.3em 0; }
table.data th, table.data td { border: 1px solid #bbb; padding: 0.25em 0.55em;
                               vertical-align: top; }
table.data th { background: #eef0f3; text-align: left; }
table.data td.num { text-align: right; font-variant-numeric: tabular-nums; white-space: nowrap; }
tr.v-reproduced td, tr.v-consistent td, tr.v-upheld td, tr.v-match td { background: #eaf6ea; }
tr.v-not_reproduced td, tr.v-not_upheld td, tr.v-differs td { background: #fbe3e1; }
tr.v-not_checkable td { background: #f1f1f1; color: #555; }
tr.v-missing td { background: #fff4d6; }
span.v-reproduced, span.v-consistent, span.v-upheld, span.v-match {
  color: #1d6b1d; font-weight: bold; }
span.v-not_reproduced, span.v-not_upheld, span.v-differs { color: #a3261a; font-weight: bold; }
span.v-not_checkable { color: #555; font-weight: bold; }
span.v-missing { color: #8a6100; font-weight: bold; }
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


def _is_numeric(value: Any) -> bool:
    return isinstance(value, Real) and not isinstance(value, bool)


def paragraph(text: str, *, raw: bool = False, cls: str | None = None) -> str:
    """``<p>`` with escaped text (``raw=True`` if ``text`` is already HTML)."""
    attr = f' class="{escape(cls)}"' if cls else ""
    return f"<p{attr}>{text if raw else escape(text)}</p>\n"


def not_available(what: str) -> str:
    """A uniform 'X: not available' note."""
    return paragraph(f"{what}: not available.", cls="na")


def section(title: str, body: str, *, anchor: str | None = None, level: int = 2) -> str:
    """``<section id=anchor>`` with a heading (``h{level}``) and an HTML body."""
    anchor = anchor or slugify(title)
    level = min(max(int(level), 1), 6)
    return (
        f'<section id="{escape(anchor)}">\n'
        f'<h{level}><a href="#{escape(anchor)}">{escape(title)}</a></h{level}>\n'
        f"{body}</section>\n"
    )


def toc(entries: Iterable[tuple[str, str]]) -> str:
    """Table of contents from ``(anchor, title)`` pairs (in-page links only)."""
    items = "".join(f'<li><a href="#{escape(a)}">{escape(t)}</a></li>\n' for a, t in entries)
    return f'<nav class="toc"><ul>\n{items}</ul></nav>\n'


def definition_list(
    mapping: Mapping[str, Any], *, value_format: Callable[[Any], str] | None = None
) -> str:
    """Key/value pairs as ``<dl class="kv">``; values are escaped (after ``value_format``)."""
    fmt = value_format or format_value
    rows = "".join(f"<dt>{escape(k)}</dt><dd>{escape(fmt(v))}</dd>\n" for k, v in mapping.items())
    return f'<dl class="kv">\n{rows}</dl>\n'


def table(
    df: pd.DataFrame,
    *,
    class_column: str | None = None,
    row_classes: Sequence[str] | None = None,
    caption: str | None = None,
    formatters: Mapping[str, Callable[[Any], str]] | None = None,
    index: bool = False,
    sig: int = 9,
    table_id: str | None = None,
    empty_text: str = "no rows",
) -> str:
    """Render a DataFrame as an HTML table (all text escaped).

    ``class_column``: every row gets ``class="v-<value of that column>"`` (see
    :data:`DEFAULT_CSS`), and that cell is wrapped in a matching ``<span>``.
    ``row_classes``: explicit class per row (overrides ``class_column``).
    ``formatters``: per-column ``value -> str``; other cells go through
    :func:`format_value` with ``sig`` significant digits. Numeric cells are
    right-aligned. ``index=True`` renders the (possibly multi-level) index as
    leading columns.
    """
    if index:
        df = df.reset_index()
    if df.empty:
        return paragraph(f"{caption + ': ' if caption else ''}{empty_text}.", cls="na")
    if row_classes is not None and len(row_classes) != len(df):
        raise ValueError(f"row_classes has {len(row_classes)} entries for {len(df)} rows")
    if class_column is not None and class_column not in df.columns:
        raise ValueError(f"class_column {class_column!r} not in columns {list(df.columns)}")
    formatters = dict(formatters or {})
    columns = [str(c) for c in df.columns]
    idattr = f' id="{escape(table_id)}"' if table_id else ""
    parts = [f'<table class="data"{idattr}>\n']
    if caption:
        parts.append(f"<caption>{escape(caption)}</caption>\n")
    parts.append(
        "<thead><tr>"
        + "".join(f"<th>{escape(c)}</th>" for c in columns)
        + "</tr></thead>\n<tbody>\n"
    )
    class_pos = list(df.columns).index(class_column) if class_column is not None else None
    for i, row in enumerate(df.itertuples(index=False, name=None)):
        if row_classes is not None:
            cls = row_classes[i]
        elif class_pos is not None:
            cls = css_class(row[class_pos])
        else:
            cls = ""
        cells = []
        for j, (name, value) in enumerate(zip(df.columns, row, strict=True)):
            fmt = formatters.get(name)
            text = fmt(value) if fmt is not None else format_value(value, sig)
            body = escape(text)
            if class_pos is not None and j == class_pos and text:
                body = f'<span class="{css_class(value)}">{body}</span>'
            td = ' class="num"' if _is_numeric(value) else ""
            cells.append(f"<td{td}>{body}</td>")
        tr = f' class="{escape(cls)}"' if cls else ""
        parts.append(f"<tr{tr}>" + "".join(cells) + "</tr>\n")
    parts.append("</tbody>\n</table>\n")
    return "".join(parts)


def png_data_uri(source: str | os.PathLike[str] | bytes) -> str:
    """``data:image/png;base64,...`` from PNG bytes or a PNG file path.

    Raises ``ValueError`` if the bytes are not a PNG (checks the signature).
    """
    data = source if isinstance(source, bytes) else Path(source).read_bytes()
    if not data.startswith(b"\x89PNG\r\n\x1a\n"):
        raise ValueError(f"not a PNG: {source if not isinstance(source, bytes) else '<bytes>'}")
    return "data:image/png;base64," + base64.b64encode(data).decode("ascii")


def figure(
    source: str | os.PathLike[str] | bytes | None,
    *,
    alt: str,
    caption: str | None = None,
    anchor: str | None = None,
    missing_text: str | None = None,
) -> str:
    """``<figure>`` with an embedded PNG (data URI) and a caption.

    If ``source`` is ``None`` or a path that does not exist, the figure holds a
    'not available' note instead of an image, so a page still renders.
    """
    idattr = f' id="{escape(anchor)}"' if anchor else ""
    cap = f"<figcaption>{escape(caption)}</figcaption>\n" if caption else ""
    if source is None or (not isinstance(source, bytes) and not Path(source).is_file()):
        note = missing_text or f"{alt}: not available"
        return f'<figure{idattr}>\n<p class="na">{escape(note)}.</p>\n{cap}</figure>\n'
    uri = png_data_uri(source)
    return f'<figure{idattr}>\n<img src="{uri}" alt="{escape(alt)}">\n{cap}</figure>\n'


def page(title: str, body: str, *, css: str = DEFAULT_CSS, lang: str = "en") -> str:
    """A complete, self-contained HTML5 document (inline CSS, no scripts)."""
    return (
        "<!DOCTYPE html>\n"
        f'<html lang="{escape(lang)}">\n<head>\n<meta charset="utf-8">\n'
        '<meta name="viewport" content="width=device-width, initial-scale=1">\n'
        f"<title>{escape(title)}</title>\n<style>{css}</style>\n</head>\n"
        f"<body>\n{body}</body>\n</html>\n"
    )


def write_atomic(
    path: str | os.PathLike[str], data: str | bytes, *, encoding: str = "utf-8"
) -> Path:
    """Write ``data`` to ``path`` atomically (temp file, fsync, ``os.replace``; pipeline.atomic).

    A reader never sees a half-written file, and a crash leaves the old file.
    """
    payload = data.encode(encoding) if isinstance(data, str) else bytes(data)
    return write_bytes(path, payload)
