"""What differs between two runs of the same notebook, removed, and what would differ, refused.

An executed notebook's page (:mod:`pipeline.notebook_html`) must have the same bytes every
run. :func:`normalise` removes what varies between runs: how printed text was split into
stream messages, execution timestamps, widget state, JavaScript and widget-view outputs
(random element ids), pandas Styler's random table ids, object addresses in default reprs.
:func:`wall_clock_reads` finds the cells that read the clock, whose output no normalisation
can make the same (the notebook is then refused; the workflow records a notebook's run time in
the rule's benchmark file).
"""

from __future__ import annotations

import re

import nbformat
from nbconvert.preprocessors import CoalesceStreamsPreprocessor

__all__ = ["DROPPED_MIME", "normalise", "wall_clock_reads"]

#: output MIME types dropped by ``normalise``: scripts and widget views (a page that runs no
#: script cannot show them, and nbconvert gives each a random element id)
DROPPED_MIME = ("application/javascript", "application/vnd.jupyter.widget-view+json")
_STYLER_ID = re.compile(r'<table id="T_(?P<uuid>[0-9a-z_]+?)"')
_ADDRESS = re.compile(r"(?<= at )0x[0-9a-fA-F]{4,16}\b")


def _renumber_addresses(text: str, seen: dict[str, str]) -> str:
    """Object addresses of default reprs (``<... at 0x7f...>``) -> ``0x1``, ``0x2``... by first
    appearance in the notebook (equal addresses stay equal)."""
    return _ADDRESS.sub(lambda m: seen.setdefault(m[0].lower(), f"0x{len(seen) + 1}"), text)


def normalise(nb: nbformat.NotebookNode) -> nbformat.NotebookNode:
    """Remove from an executed notebook, in place, what differs between two runs: how a
    cell's printed text was split into stream messages (consecutive ones are merged, as
    nbconvert's CoalesceStreamsPreprocessor does), execution timestamps, widget state,
    JavaScript and widget-view outputs, pandas Styler table ids (``T_<random>`` ->
    ``T_c<cell>o<output>``), object addresses in default reprs."""
    nb, _ = CoalesceStreamsPreprocessor().preprocess(nb, {})
    nb.metadata.pop("widgets", None)
    addresses: dict[str, str] = {}
    for ci, cell in enumerate(nb.cells):
        cell.metadata.pop("execution", None)
        if cell.cell_type != "code":
            continue
        outputs = []
        for oi, out in enumerate(cell.outputs):
            data = out.get("data")
            if data is not None:
                for mime in DROPPED_MIME:
                    data.pop(mime, None)
                if not data:
                    continue
                html = data.get("text/html")
                if isinstance(html, str):
                    for uuid in dict.fromkeys(m["uuid"] for m in _STYLER_ID.finditer(html)):
                        html = re.sub(rf"\bT_{re.escape(uuid)}(?![0-9a-z])", f"T_c{ci}o{oi}", html)
                    data["text/html"] = html
                for mime in ("text/plain", "text/html"):
                    if isinstance(data.get(mime), str):
                        data[mime] = _renumber_addresses(data[mime], addresses)
            if out.get("output_type") == "stream":
                out["text"] = _renumber_addresses(out["text"], addresses)
            outputs.append(out)
        cell.outputs = outputs
    return nb


#: calls whose results differ between runs: a page that prints one is never the same twice
#: (the workflow records a notebook's run time in the rule's benchmark file)
_WALL_CLOCK = re.compile(
    r"\b(?:time\.(?:perf_counter|perf_counter_ns|time|time_ns|monotonic|monotonic_ns|process_time)"
    r"|datetime\.(?:now|today|utcnow)|date\.today)\s*\(|^\s*%%?time(?:it)?\b",
    re.M,
)


def wall_clock_reads(nb: nbformat.NotebookNode) -> list[str]:
    """``cell <i>: <line>`` for each line of a code cell that reads the clock (``time.time()``,
    ``time.perf_counter()``, ``datetime.now()``, ``%time``...).

    >>> nb = nbformat.v4.new_notebook(cells=[nbformat.v4.new_code_cell("t0 = time.perf_counter()")])
    >>> wall_clock_reads(nb)
    ['cell 0: t0 = time.perf_counter()']
    """
    found = []
    for i, cell in enumerate(nb.cells):
        if cell.cell_type == "code":
            lines = cell.source.splitlines()
            found += [f"cell {i}: {ln.strip()}" for ln in lines if _WALL_CLOCK.search(ln)]
    return found
