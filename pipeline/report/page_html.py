"""A paper's page ``reports/<slug>.html``: the same template as its section of the combined
report (:mod:`pipeline.report.paper_section`, the same sections in the same order, built from
the same :class:`~pipeline.report.paper_parts.PaperParts`), then its discussion and the
appendices (the equation forms, the assumptions, the paper's further sections), rendered with
the combined report's block renderer (:mod:`pipeline.report.blocks_html`).

One self-contained file: inline CSS, figures as ``data:`` URIs, no script, nothing fetched;
the same inputs give the same bytes.

``python -m pipeline.report.page_html --paper <slug> --out reports/<slug>.html`` (the inputs
at their conventional places under ``--results-dir`` and ``--config-dir``).
"""

from __future__ import annotations

import argparse
import os
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path

from pipeline.atomic import write_text
from pipeline.paper import Paper
from pipeline.report import html as H
from pipeline.report.blocks_html import render_sections, section_numbers
from pipeline.report.model import Link, PaperReport, ReportInputs, Section
from pipeline.report.paper_parts import PaperParts, load_parts
from pipeline.report.paper_section import (
    assumptions_section,
    discussion_section,
    forms_section,
    further_sections,
    paper_section,
    supporting_section,
)

__all__ = ["build_page", "main", "page_sections", "page_step", "render_page"]


def _unprefixed(sections: list[Section], slug: str, seen: set[str]) -> list[Section]:
    """The sections with ``<slug>-`` dropped from their ids (on its own page a paper's ids
    need no prefix: they keep the ids its report gives them), each id unique."""

    def fix(s: Section) -> Section:
        base = s.id[len(slug) + 1 :] if s.id.startswith(f"{slug}-") else s.id
        sid, k = base, 2
        while sid in seen:
            sid, k = f"{base}-{k}", k + 1
        seen.add(sid)
        return Section(sid, s.title, s.blocks, [fix(c) for c in s.subsections])

    return [fix(s) for s in sections]


def page_sections(p: PaperParts) -> tuple[list[Section], list[Section]]:
    """(sections, appendices) of a paper's page: the template's main sections and the
    discussion; the equation forms, the results the findings rest on, the assumptions and
    the paper's further sections."""
    seen: set[str] = set()
    sections, appendices = _page_sections(p)
    return _unprefixed(sections, p.slug, seen), _unprefixed(appendices, p.slug, seen)


def _page_sections(p: PaperParts) -> tuple[list[Section], list[Section]]:
    main = paper_section(p, "Appendix A", page=True)
    sections = [*main.subsections, discussion_section(p, f"{p.slug}-discussion", "Discussion")]
    appendices = [forms_section(p, "Equation audit: the forms")]
    supporting = supporting_section(p, "Supporting results", flatten=False)
    appendices += [supporting] if supporting is not None else []
    appendices.append(assumptions_section(p, "Assumptions where the paper is silent"))
    further = further_sections(p)
    if further:
        appendices.append(Section(f"{p.slug}-further", "The paper's own sections", [], further))
    return sections, appendices


def render_page(paper: Paper, parts: PaperParts | PaperReport) -> str:
    """The page as an HTML string: title, reference, contents, then the sections. Given the
    paper's :class:`PaperReport` alone (no results read), its sections as they are."""
    title = f"Reproduction report: {paper.title}"
    if isinstance(parts, PaperReport):
        sections, appendices = list(parts.sections), []
    else:
        sections, appendices = page_sections(parts)
    numbers = section_numbers(sections, appendices)
    back = Link("the combined report", "reproduction.html")
    body = (
        f"<header><h1>{H.escape(title)}</h1>\n"
        f"<p>{H.escape(paper.citation)}. The three papers together: "
        f'<a href="{back.target}">{back.text}</a>.</p>\n'
        "</header>\n"
    )
    body += H.toc([(s.id, f"{numbers[s.id]} {s.title}") for s in [*sections, *appendices]])
    body += render_sections(sections, appendices, numbers, status_rows=True)
    return H.page(title, body)


def build_page(paper: Paper, inputs: ReportInputs, out: str | os.PathLike[str]) -> Path:
    """Build ``paper``'s parts from ``inputs`` and write its page to ``out`` atomically
    (nothing is written if an input is missing or malformed)."""
    return write_text(out, render_page(paper, load_parts(paper, inputs)))


def page_step(inputs: Mapping, outputs: Mapping, params: Mapping, log: Callable) -> None:
    """The page step of every paper (``Step(..., "pipeline.report.page_html:page_step")``):
    ``params["paper"]`` the slug, ``params["settings"]`` its settings; the folders come from
    the named inputs ``audit`` (results), ``scenario_files``, ``published`` and ``figures``."""
    from pipeline.registry import load_paper

    inputs_ = ReportInputs(
        results=Path(inputs["audit"]).parent,
        scenarios=Path(inputs["scenario_files"][0]).parent,
        published=Path(inputs["published"]),
        figures=Path(inputs["figures"][0]).parent,
        settings=dict(params.get("settings") or {}),
    )
    out = build_page(load_paper(params["paper"]), inputs_, outputs["page"])
    log(f"wrote {out}")


def main(argv: Sequence[str] | None = None) -> int:
    from pipeline.registry import load_paper

    ap = argparse.ArgumentParser(
        prog="python -m pipeline.report.page_html", description=__doc__.split("\n\n")[0]
    )
    ap.add_argument("--paper", required=True, help="the paper's slug")
    ap.add_argument("--results-dir", default="results")
    ap.add_argument("--config-dir", default="config")
    ap.add_argument("--out", required=True)
    a = ap.parse_args(argv)
    import yaml

    cfg_path = Path(a.config_dir) / "config.yaml"
    cfg = yaml.safe_load(cfg_path.read_text(encoding="utf-8")) if cfg_path.is_file() else {}
    inputs = ReportInputs.under(a.paper, a.results_dir, a.config_dir, (cfg or {}).get(a.paper))
    print(build_page(load_paper(a.paper), inputs, a.out))
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
