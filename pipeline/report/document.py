"""The content model of the combined reproduction report (HTML and PDF).

Both renderers (``pipeline.report.reproduction_html`` and the Typst/PDF renderer)
read one :class:`Document` built here from the results; neither reads a CSV
itself. The model is plain data: text fields are plain text (no HTML), except the
``*_mathml`` fields of :class:`EquationRow`, which hold complete ``<math>``
elements (or ``None``).
"""

from __future__ import annotations

import base64
import hashlib
import importlib
import json
import math
import re
from collections.abc import Iterator, Mapping, Sequence
from dataclasses import dataclass, field
from html.parser import HTMLParser
from pathlib import Path
from typing import Any

import pandas as pd
import yaml

from pipeline.columns import AUDIT_COLUMNS, VERDICT_COLUMNS
from pipeline.provenance import git_describe
from pipeline.verdicts import published_items

__all__ = [
    "Block",
    "Document",
    "EquationRow",
    "EquationTable",
    "Figure",
    "Link",
    "Paragraph",
    "ScoreRow",
    "Section",
    "Table",
    "build_document",
    "counts",
    "equation_groups",
    "equation_list",
    "formless",
    "rescience_line",
    "score_row",
]

ROOT = Path(__file__).resolve().parents[2]


@dataclass(frozen=True)
class Paragraph:
    """One paragraph of plain text."""

    text: str


@dataclass(frozen=True)
class Table:
    """A table of plain-text cells; ``highlight`` lists row indices to emphasise
    (the rows whose verdict or status is a failure)."""

    columns: list[str]
    rows: list[list[str]]
    caption: str = ""
    highlight: list[int] = field(default_factory=list)


@dataclass(frozen=True)
class Figure:
    """A PNG figure. ``label`` is the paper's numbering (``"Fig. 7"``; ``"Extra fig. 1"`` for a
    figure the paper does not have); ``caption`` does not repeat the label, so renderers
    show ``label`` then ``caption``. ``path`` is absolute (the PNG under ``results/``)."""

    path: str
    caption: str
    label: str


@dataclass(frozen=True)
class EquationRow:
    """One row of an equation audit, with the printed/derived/residual forms as
    MathML (complete ``<math>`` elements) and SymPy ``srepr`` strings (None where absent)."""

    paper: str
    equation: str
    status: str
    note: str
    residual_text: str
    printed_mathml: str | None
    derived_mathml: str | None
    residual_mathml: str | None
    printed_srepr: str | None
    derived_srepr: str | None
    residual_srepr: str | None


@dataclass(frozen=True)
class EquationTable:
    rows: list[EquationRow]
    caption: str = ""


@dataclass(frozen=True)
class Link:
    """A link; ``target`` is an href relative to the report (e.g. ``notebooks/x.html``)."""

    text: str
    target: str


Block = Paragraph | Table | Figure | EquationTable | Link


@dataclass(frozen=True)
class Section:
    id: str
    title: str
    blocks: list[Block]
    subsections: list[Section] = field(default_factory=list)


@dataclass(frozen=True)
class ScoreRow:
    """One paper's line of the scoreboard; every count is computed from the CSVs.

    ``audit``: match / differs / not_checkable; ``numbers``: reproduced /
    consistent / not_reproduced; ``claims``: upheld / not_upheld / not_checkable;
    ``line``: the ReScience-style one-line verdict; ``anchor``: the section id.
    """

    slug: str
    title: str
    audit: dict[str, int]
    numbers: dict[str, int]
    claims: dict[str, int]
    line: str
    anchor: str


@dataclass(frozen=True)
class Document:
    title: str
    subtitle: str
    generated_from: str
    scoreboard: list[ScoreRow]
    sections: list[Section]


def formless(row: EquationRow) -> bool:
    """An audit row with nothing to typeset (no printed, derived or residual form)."""
    return not (row.printed_srepr or row.derived_srepr or row.residual_srepr) and (
        not row.residual_text or row.status == "match"
    )


def equation_groups(rows: Sequence[EquationRow]) -> Iterator[list[EquationRow]]:
    """The audit rows, consecutive rows with no forms and the same status and note grouped
    (eqs. 1-11 of north_finding, all "not in the seed text", become one group)."""
    group: list[EquationRow] = []
    for row in rows:
        if (
            group
            and formless(row)
            and formless(group[-1])
            and (row.status, row.note) == (group[-1].status, group[-1].note)
        ):
            group.append(row)
            continue
        if group:
            yield group
        group = [row]
    if group:
        yield group


def equation_list(names: list[str]) -> str:
    """``1–11`` for a run of consecutive integers, else the names separated by commas."""
    if len(names) > 1 and all(n.isdigit() for n in names):
        nums = [int(n) for n in names]
        if nums == list(range(nums[0], nums[0] + len(nums))):
            return f"{nums[0]}–{nums[-1]}"
    return ", ".join(names)


# =========================================================================== building

#: Status and verdict words counted on the scoreboard (every word shown, zeros included).
AUDIT_WORDS = ("match", "differs", "not_checkable")
NUMBER_WORDS = ("reproduced", "consistent", "not_reproduced")
CLAIM_WORDS = ("upheld", "not_upheld", "not_checkable")
#: Verdict/status words that mark a row as a failure (``Table.highlight``).
FAILURE_WORDS = ("not_reproduced", "not_upheld", "differs", "missing")

#: Which sections of each per-paper page (``reports/<slug>.html``, by element id) feed which
#: subsection of the paper's section here. ``published: None``: the published-vs-reproduced
#: tables are grouped here from verdicts.csv by the paper's figure/table numbering.
PAGE_PARTS: dict[str, dict[str, list[str] | None]] = {
    "north_finding": {
        "summary": ["summary"],
        "published": ["published-vs-reproduced", "claims"],
        "figures": ["figures"],
        "findings": ["findings"],
        "assumptions": ["assumptions"],
    },
    "platform_drift": {
        "summary": ["summary"],
        "published": None,
        "figures": ["figures"],
        "findings": ["summaries"],
        "assumptions": ["assumptions"],
    },
    "altimeter_attitude": {
        "summary": ["summary"],
        "published": None,
        "figures": ["figures"],
        "findings": ["findings", "results"],
        "assumptions": ["assumptions"],
    },
}
#: A page whose slug is not listed above: these page sections by id (missing ones skipped).
DEFAULT_PAGE_PARTS: dict[str, list[str] | None] = {
    "summary": ["summary"],
    "published": None,
    "figures": ["figures"],
    "findings": ["findings"],
    "assumptions": ["assumptions"],
}

#: Report module per paper, for its title and citation.
PAPER_MODULES = {
    "north_finding": ("pipeline.report.north_finding", "PAPER_TITLE", "PAPER_CITATION"),
    "platform_drift": ("pipeline.report.platform_drift", "TITLE", "CITATION"),
    "altimeter_attitude": ("pipeline.report.altimeter_attitude", "PAPER_TITLE", "PAPER_CITATION"),
}


def build_document(
    root: Path = ROOT,
    results_dir: str | Path = "results",
    reports_dir: str | Path = "reports",
    config: str | Path = "config",
) -> Document:
    """Build the report's content from the results (nothing typed by hand).

    ``results_dir``, ``reports_dir`` and ``config`` (the config directory) are taken
    relative to ``root`` unless absolute. Reads, per paper listed in
    ``<config>/config.yaml`` (``papers``): ``equation_audit.csv``,
    ``equation_math.json``, ``verdicts.csv``, the figures, the scenario
    ``provenance.json`` files and ``benchmarks/*.tsv`` under ``results/<slug>/``;
    ``config/scenarios/<slug>/*.yaml`` and ``config/published/<slug>.yaml``; and the
    per-paper page ``reports/<slug>.html`` whose summary, tables, findings and
    assumptions sections are reused. Raises ``FileNotFoundError`` naming a missing
    required input (audit, verdicts, per-paper page).
    """
    root = Path(root)
    results = _under(root, results_dir)
    reports = _under(root, reports_dir)
    config_dir = _under(root, config)
    cfg = _load_yaml(config_dir / "config.yaml")
    slugs = [str(s) for s in (cfg.get("papers") or [])]
    if not slugs:
        raise ValueError(f"{config_dir / 'config.yaml'}: no 'papers' listed")
    papers = [_load_paper(slug, results, reports, config_dir, cfg) for slug in slugs]
    scoreboard = [p.score for p in papers]
    sections = [_how_to_read(papers)]
    sections += [_paper_section(p) for p in papers]
    sections.append(_provenance_section(papers, root, config_dir))
    sections = _unique_ids(sections)
    n = len(papers)
    return Document(
        title="Reproducing three inertial-navigation papers"
        if n == 3
        else f"Reproducing {n} inertial-navigation paper{'s' if n != 1 else ''}",
        subtitle=(
            "Every printed equation, published number and claim beside what this project "
            "derived with SymPy and computed: a reproducibility audit"
        ),
        generated_from=git_describe(root),
        scoreboard=scoreboard,
        sections=sections,
    )


# --------------------------------------------------------------------------- small helpers


def _under(root: Path, p: str | Path) -> Path:
    p = Path(p)
    return p if p.is_absolute() else root / p


def _load_yaml(path: Path) -> dict[str, Any]:
    if not path.is_file():
        raise FileNotFoundError(f"{path}: required input is missing")
    with path.open(encoding="utf-8") as fh:
        data = yaml.safe_load(fh) or {}
    if not isinstance(data, dict):
        raise ValueError(f"{path}: expected a mapping")
    return data


def _read_text_csv(path: Path, columns: Sequence[str]) -> pd.DataFrame:
    """A results CSV with every cell as printed (strings); required."""
    if not path.is_file():
        raise FileNotFoundError(f"{path}: required input is missing")
    df = pd.read_csv(path, dtype=str, keep_default_na=False)
    missing = [c for c in columns if c not in df.columns]
    if missing:
        raise ValueError(f"{path}: missing columns {missing} (has {list(df.columns)})")
    return df[list(columns)]


def counts(values: Sequence[str] | pd.Series, words: Sequence[str]) -> dict[str, int]:
    """How often each of ``words`` occurs in ``values`` (zeros included, in that order);
    any other word found is appended (a producer bug, shown rather than hidden)."""
    out = {w: 0 for w in words}
    for v in values:
        out[str(v)] = out.get(str(v), 0) + 1
    return out


def _plural(n: int, one: str, many: str | None = None) -> str:
    return f"{n} {one if n == 1 else (many or one + 's')}"


def _words(word: str) -> str:
    return word.replace("_", " ")


# --------------------------------------------------------------------------- the per-paper page


_VOID_TAGS = {"img", "br", "hr", "meta", "link", "input", "col", "wbr", "source"}


@dataclass
class _Node:
    tag: str
    attrs: dict[str, str]
    children: list[_Node | str] = field(default_factory=list)

    def elements(self) -> list[_Node]:
        return [c for c in self.children if isinstance(c, _Node)]

    def text(self) -> str:
        parts: list[str] = []
        for c in self.children:
            parts.append(c if isinstance(c, str) else c.text())
        return "".join(parts)

    def find_all(self, tag: str) -> list[_Node]:
        out = []
        for c in self.elements():
            if c.tag == tag:
                out.append(c)
            out.extend(c.find_all(tag))
        return out


class _TreeBuilder(HTMLParser):
    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.root = _Node("#root", {})
        self.stack = [self.root]

    def handle_starttag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        node = _Node(tag, {k: v or "" for k, v in attrs})
        self.stack[-1].children.append(node)
        if tag not in _VOID_TAGS:
            self.stack.append(node)

    def handle_startendtag(self, tag: str, attrs: list[tuple[str, str | None]]) -> None:
        self.stack[-1].children.append(_Node(tag, {k: v or "" for k, v in attrs}))

    def handle_endtag(self, tag: str) -> None:
        for i in range(len(self.stack) - 1, 0, -1):
            if self.stack[i].tag == tag:
                del self.stack[i:]
                return

    def handle_data(self, data: str) -> None:
        self.stack[-1].children.append(data)


def _parse_html(text: str) -> _Node:
    b = _TreeBuilder()
    b.feed(text)
    b.close()
    return b.root


def _clean(text: str) -> str:
    return re.sub(r"\s+", " ", text).strip()


class _Page:
    """A per-paper page: its top-level sections by id, and its figures resolved to files."""

    def __init__(self, path: Path, figures_dir: Path) -> None:
        if not path.is_file():
            raise FileNotFoundError(f"{path}: required input is missing (the per-paper page)")
        self.path = path
        tree = _parse_html(path.read_text(encoding="utf-8"))
        body = next(iter(tree.find_all("body")), tree)
        self.sections = {s.attrs.get("id", ""): s for s in body.elements() if s.tag == "section"}
        self.figure_files: dict[str, Path] = {}
        self.figure_names: dict[str, Path] = {}
        if figures_dir.is_dir():
            for f in sorted(figures_dir.glob("*.png")):
                self.figure_files[hashlib.sha256(f.read_bytes()).hexdigest()] = f
                self.figure_names[f.stem] = f
        self.extra_figures = 0

    def section(self, page_id: str, id_prefix: str) -> Section | None:
        node = self.sections.get(page_id)
        return None if node is None else self._section(node, id_prefix)

    # ----------------------------------------------------------------- conversion
    def _section(self, node: _Node, id_prefix: str) -> Section:
        title = ""
        blocks: list[Block] = []
        subs: list[Section] = []
        for child in node.children:
            if isinstance(child, str):
                if child.strip():
                    blocks.append(Paragraph(_clean(child)))
                continue
            if child.tag in ("h1", "h2", "h3", "h4", "h5", "h6") and not title:
                title = _clean(child.text())
            elif child.tag == "section":
                subs.append(self._section(child, id_prefix))
            else:
                blocks.extend(self._blocks(child))
        sid = f"{id_prefix}-{node.attrs.get('id') or _slug(title)}"
        return Section(id=sid, title=title, blocks=blocks, subsections=subs)

    def _blocks(self, el: _Node) -> list[Block]:
        tag = el.tag
        if tag == "p":
            text = _clean(el.text())
            return [Paragraph(text)] if text else []
        if tag in ("ul", "ol"):
            return [
                Paragraph(f"• {_clean(li.text())}")
                for li in el.elements()
                if li.tag == "li" and _clean(li.text())
            ]
        if tag == "table":
            return [_table_from_node(el)]
        if tag == "dl":
            rows: list[list[str]] = []
            for c in el.elements():
                if c.tag == "dt":
                    rows.append([_clean(c.text()), ""])
                elif c.tag == "dd" and rows:
                    rows[-1][1] = _clean(c.text())
            return [Table(columns=["field", "value"], rows=rows)] if rows else []
        if tag == "figure":
            return [self._figure(el)]
        if tag in ("h4", "h5", "h6"):
            text = _clean(el.text())
            return [Paragraph(text)] if text else []
        if tag in ("nav", "style", "script", "header"):
            return []
        out: list[Block] = []
        for c in el.children:
            if isinstance(c, str):
                if c.strip():
                    out.append(Paragraph(_clean(c)))
            else:
                out.extend(self._blocks(c))
        return out

    def _figure(self, el: _Node) -> Block:
        caption = " ".join(_clean(c.text()) for c in el.find_all("figcaption"))
        imgs = el.find_all("img")
        path = None
        if imgs:
            src = imgs[0].attrs.get("src", "")
            if src.startswith("data:image/png;base64,"):
                data = base64.b64decode(src.split(",", 1)[1])
                path = self.figure_files.get(hashlib.sha256(data).hexdigest())
            if path is None:
                alt = Path(imgs[0].attrs.get("alt", "")).stem
                path = self.figure_names.get(alt)
        if path is None:
            return Paragraph(
                f"{caption or 'A figure'} (not available: the page's image is not among "
                "the results' figure files)."
            )
        label, text = _split_label(caption)
        if label is None or "not in the paper" in text.lower():
            # numbered apart from the paper's figures, whatever the page called it
            self.extra_figures += 1
            if label is not None:
                text = f"{text} (figure file {path.stem})"
            label = f"Extra fig. {self.extra_figures}"
        return Figure(path=str(path.resolve()), caption=text, label=label)


def _split_label(caption: str) -> tuple[str | None, str]:
    """``"Fig. 7 (paper Fig. 7): x"`` -> ``("Fig. 7", "(paper Fig. 7): x")``;
    ``"Not in the paper: x"`` -> ``(None, "(not in the paper): x")``."""
    m = re.match(r"^(Fig\.\s*\d+[a-z]?)[\s:.\u2014-]*(.*)$", caption, flags=re.S)
    if m:
        return m.group(1), m.group(2).strip()
    m = re.match(r"^not in the paper\s*:\s*(.*)$", caption, flags=re.S | re.I)
    if m:
        return None, f"(not in the paper): {m.group(1).strip()}"
    return None, caption


def _slug(text: str) -> str:
    return re.sub(r"[^a-z0-9]+", "-", str(text).lower()).strip("-") or "x"


def _table_from_node(el: _Node) -> Table:
    caption = " ".join(_clean(c.text()) for c in el.find_all("caption"))
    columns: list[str] = []
    rows: list[list[str]] = []
    highlight: list[int] = []
    for tr in el.find_all("tr"):
        cells = [c for c in tr.elements() if c.tag in ("td", "th")]
        if cells and all(c.tag == "th" for c in cells) and not columns and not rows:
            columns = [_clean(c.text()) for c in cells]
            continue
        classes = set(tr.attrs.get("class", "").split())
        if any(f"v-{w}" in classes for w in FAILURE_WORDS):
            highlight.append(len(rows))
        rows.append([_clean(c.text()) for c in cells])
    if not columns:
        columns = [""] * max((len(r) for r in rows), default=0)
    return Table(columns=columns, rows=rows, caption=caption, highlight=highlight)


def _inline_single_tables(section: Section) -> Section:
    """A subsection holding one table and nothing else becomes that table, captioned
    with the subsection's title (keeps the PDF's heading depth at three)."""
    blocks: list[Block] = list(section.blocks)
    subs: list[Section] = []
    for sub in section.subsections:
        sub = _inline_single_tables(sub)
        if not sub.subsections and len(sub.blocks) == 1 and isinstance(sub.blocks[0], Table):
            t = sub.blocks[0]
            cap = sub.title if not t.caption else f"{sub.title}: {t.caption}"
            blocks.append(Table(t.columns, t.rows, cap, t.highlight))
        else:
            subs.append(sub)
    return Section(section.id, section.title, blocks, subs)


def _flatten_deep(section: Section, depth: int, max_depth: int = 2) -> Section:
    """Sections nested deeper than ``max_depth`` (counted from a page section at ``depth``
    1) are merged into their parent: their title captions their first uncaptioned table,
    or opens a paragraph."""
    if depth < max_depth:
        return Section(
            section.id,
            section.title,
            section.blocks,
            [_flatten_deep(s, depth + 1, max_depth) for s in section.subsections],
        )
    blocks: list[Block] = list(section.blocks)
    for sub in section.subsections:
        sub = _flatten_deep(sub, depth + 1, max_depth)
        inner = list(sub.blocks)
        k = next((i for i, b in enumerate(inner) if isinstance(b, Table) and not b.caption), None)
        if k is None:
            inner.insert(0, Paragraph(f"{sub.title}:"))
        else:
            t = inner[k]
            assert isinstance(t, Table)
            inner[k] = Table(t.columns, t.rows, sub.title, t.highlight)
        blocks += inner
    return Section(section.id, section.title, blocks, [])


def _is_extra_figure(block: Block) -> bool:
    return isinstance(block, Figure) and "not in the paper" in block.caption.lower()


def _all_figures(section: Section) -> list[Figure]:
    out = [b for b in section.blocks if isinstance(b, Figure)]
    for s in section.subsections:
        out += _all_figures(s)
    return out


# --------------------------------------------------------------------------- one paper


@dataclass
class _Paper:
    slug: str
    title: str
    citation: str
    audit: pd.DataFrame
    math: list[dict[str, Any]]
    verdicts: pd.DataFrame
    published: dict[str, Any]
    page: _Page
    parts: dict[str, list[str] | None]
    results: Path
    reports: Path
    scenarios_dir: Path
    score: ScoreRow


def _load_paper(
    slug: str, results: Path, reports: Path, config_dir: Path, cfg: Mapping[str, Any]
) -> _Paper:
    rdir = results / slug
    audit = _read_text_csv(rdir / "equation_audit.csv", AUDIT_COLUMNS)
    verdicts = _read_text_csv(rdir / "verdicts.csv", VERDICT_COLUMNS)
    math_path = rdir / "equation_math.json"
    math = json.loads(math_path.read_text(encoding="utf-8")) if math_path.is_file() else []
    published_path = config_dir / "published" / f"{slug}.yaml"
    published = _load_yaml(published_path) if published_path.is_file() else {}
    title, citation = _paper_title(slug)
    page = _Page(reports / f"{slug}.html", rdir / "figures")
    score = score_row(slug, title, audit, verdicts)
    return _Paper(
        slug=slug,
        title=title,
        citation=citation,
        audit=audit,
        math=math,
        verdicts=verdicts,
        published=published,
        page=page,
        parts=PAGE_PARTS.get(slug, DEFAULT_PAGE_PARTS),
        results=rdir,
        reports=reports,
        scenarios_dir=config_dir / "scenarios" / slug,
        score=score,
    )


def _paper_title(slug: str) -> tuple[str, str]:
    spec = PAPER_MODULES.get(slug)
    if spec is None:
        return slug, ""
    module = importlib.import_module(spec[0])
    return str(getattr(module, spec[1], slug)), str(getattr(module, spec[2], ""))


# --------------------------------------------------------------------------- scoreboard


def _compact_ids(ids: Sequence[str], all_ids: Sequence[str] = (), limit: int = 5) -> str:
    """The ids in ``ids``, at most ``limit`` shown. An id with variants (``F5.3.crossover/
    proposed_simulated``: one published item judged on several curves) is named by its base
    when every variant of it in ``all_ids`` is in ``ids``, else by the variants in ``ids``."""
    chosen = list(dict.fromkeys(str(i) for i in ids))
    variants: dict[str, list[str]] = {}
    for i in dict.fromkeys(str(i) for i in [*all_ids, *chosen]):
        variants.setdefault(i.split("/")[0], []).append(i)
    names: list[str] = []
    for i in chosen:
        base = i.split("/")[0]
        whole = all(v in chosen for v in variants[base])
        name = base if whole else i
        if name not in names:
            names.append(name)
    shown = ", ".join(names[:limit])
    if len(names) > limit:
        shown += f" and {len(names) - limit} more"
    return shown


_NOT_REPRODUCED_WHY = {
    "exact": "beyond the printed precision or stated tolerance",
    "statistical": "outside the Monte Carlo tolerance",
}


_LEADING_NUMBER = re.compile(r"^\s*([+-]?(?:\d+(?:\.\d*)?|\.\d+)(?:[eE][+-]?\d+)?)(\s*\S*)\s*$")


def _number(text: object) -> tuple[float, str] | None:
    """``(value, unit)`` of a cell such as ``"0.16"`` or ``"2400 s"`` (one unit word at most)."""
    m = _LEADING_NUMBER.match(str(text))
    if m is None:
        return None
    value = float(m.group(1))
    return (value, m.group(2).strip()) if math.isfinite(value) else None


def _ratio_range(rows: pd.DataFrame) -> str:
    """How far ours is from the published value over rows where both are numbers (published
    non-zero): ``"2.7\u20136.7x"`` when every ratio is at least 2 or at most 1/2, else the
    relative difference, ``"+0.01 to +0.5 % off"``; ``""`` if no row has two numbers."""
    ratios = []
    for pub, ours in zip(rows["published"], rows["reproduced"], strict=True):
        a, b = _number(pub), _number(ours)
        if a is not None and b is not None and a[0] != 0 and a[1] == b[1]:  # same unit
            ratios.append(b[0] / a[0])
    if not ratios:
        return ""
    lo, hi = min(ratios), max(ratios)
    if lo >= 2 or hi <= 0.5:
        span = f"{lo:.2g}" if f"{lo:.2g}" == f"{hi:.2g}" else f"{lo:.2g}\u2013{hi:.2g}"
        return f"ours {span}x the published"
    d_lo, d_hi = 100 * (lo - 1), 100 * (hi - 1)
    span = f"{d_lo:+.2g}" if f"{d_lo:+.2g}" == f"{d_hi:+.2g}" else f"{d_lo:+.2g} to {d_hi:+.2g}"
    return f"ours {span} % off the published"


def rescience_line(audit: pd.DataFrame, verdicts: pd.DataFrame) -> str:
    """The ReScience-style one-line verdict of a paper, filled from the CSVs.

    Full reproduction: every published number reproduced or consistent and every claim
    upheld; not reproduced: none of them; partial otherwise. The reasons name the
    numbers not reproduced (by kind, with the range of ours / published), the claims not
    upheld or not checkable, and the printed equations that differ from the derivation.
    """
    numbers = verdicts[verdicts["kind"] != "claim"]
    claims = verdicts[verdicts["kind"] == "claim"]
    nc = counts(numbers["verdict"], NUMBER_WORDS)
    cc = counts(claims["verdict"], CLAIM_WORDS)
    ac = counts(audit["status"], AUDIT_WORDS)
    n_good = nc["reproduced"] + nc["consistent"]
    n_bad = len(numbers) - n_good
    c_good = cc["upheld"]
    c_bad = len(claims) - c_good
    if len(numbers) + len(claims) == 0:
        status = "Nothing to reproduce"
    elif n_bad == 0 and c_bad == 0:
        status = "Full reproduction"
    elif n_good == 0 and c_good == 0:
        status = "Not reproduced"
    else:
        status = "Partial reproduction"
    parts: list[str] = []
    if len(numbers):
        text = f"{n_good} of {_plural(len(numbers), 'published number')} reproduced or consistent"
        bad = numbers[numbers["verdict"] != "reproduced"]
        bad = bad[bad["verdict"] != "consistent"]
        if len(bad):
            groups = []
            for kind, g in bad.groupby("kind", sort=False):
                why = _NOT_REPRODUCED_WHY.get(str(kind), f"{kind} values")
                spread = _ratio_range(g)
                if spread:
                    why += f"; {spread}"
                groups.append(f"{_compact_ids(list(g['id']), list(numbers['id']))} ({why})")
            text += "; not reproduced: " + "; ".join(groups)
        parts.append(text)
    if len(claims):
        text = f"{c_good} of {_plural(len(claims), 'claim')} upheld"
        for word in ("not_upheld", "not_checkable"):
            ids = list(claims.loc[claims["verdict"] == word, "id"])
            if ids:
                text += f"; {_words(word)}: {_compact_ids(ids, list(claims['id']))}"
        other = claims[~claims["verdict"].isin(CLAIM_WORDS)]
        if len(other):
            text += f"; other verdicts: {_compact_ids(list(other['id']), list(claims['id']))}"
        parts.append(text)
    if len(audit):
        text = (
            f"{ac['differs']} of {_plural(len(audit), 'printed equation')} differ from the "
            "derivation"
        )
        if ac["differs"]:
            text += " (the derived forms are used)"
        if ac["not_checkable"]:
            text += f", {ac['not_checkable']} not checkable"
        parts.append(text)
    return f"{status}: " + ". ".join(parts) + "."


def score_row(slug: str, title: str, audit: pd.DataFrame, verdicts: pd.DataFrame) -> ScoreRow:
    """The scoreboard row of one paper, counted from its audit and verdict tables."""
    numbers = verdicts[verdicts["kind"] != "claim"]
    claims = verdicts[verdicts["kind"] == "claim"]
    return ScoreRow(
        slug=slug,
        title=title,
        audit=counts(audit["status"], AUDIT_WORDS),
        numbers=counts(numbers["verdict"], NUMBER_WORDS),
        claims=counts(claims["verdict"], CLAIM_WORDS),
        line=rescience_line(audit, verdicts),
        anchor=slug,
    )


# --------------------------------------------------------------------------- sections


def _how_to_read(papers: Sequence[_Paper]) -> Section:
    n_eq = sum(len(p.audit) for p in papers)
    n_num = sum(int((p.verdicts["kind"] != "claim").sum()) for p in papers)
    n_claim = sum(int((p.verdicts["kind"] == "claim").sum()) for p in papers)
    blocks: list[Block] = [
        Paragraph(
            f"This report audits {_plural(len(papers), 'paper')}: {n_eq} printed equations, "
            f"{n_num} published numbers and {n_claim} claim verdicts in all. Each paper's "
            "equations were transcribed as printed and compared with a SymPy derivation from "
            "first principles; its numbers and claims were recomputed by simulation from the "
            "derived equations and compared with the published values by a rule that fits "
            "their kind. Every count and verdict here is read from the result files "
            "(equation_audit.csv, verdicts.csv) the workflow wrote; none is typed by hand."
        ),
        Paragraph(
            "The scoreboard has one row per paper. Equations: printed equations that match "
            "the derivation, differ from it (a typo of the paper or an artefact of the text; "
            "the pipeline then uses the derived form) or cannot be checked (not checkable: "
            "definitions, numeric statements, text). Published numbers: reproduced (an exact, "
            "ideal-sensor value equal to the printed precision or within the stated "
            "tolerance), consistent (a noise-dependent value inside the Monte Carlo "
            "distribution) or not reproduced. Claims: a predicate over the results, upheld, "
            "not upheld or not checkable; where a paper's claim is judged on two variants "
            "(e.g. analytic and simulated curves) each variant counts once."
        ),
        Paragraph(
            "The line under each paper follows ReScience C: full reproduction when every "
            "published number is reproduced or consistent and every claim is upheld, not "
            "reproduced when none is, partial otherwise; it names the numbers and claims that "
            "fail. Each paper's section gives its summary, the equation audit with the printed "
            "and derived forms typeset, the published tables in the paper's own numbering "
            "beside ours, the figures, the assumptions made where the paper is silent, the "
            "findings that go beyond the paper and a link to the executed notebook. The last "
            "section records the provenance of the results."
        ),
        Table(
            columns=["word", "applies to", "meaning"],
            rows=[
                ["match", "equation", "printed form equals the derivation (residual 0)"],
                ["differs", "equation", "printed form differs; residual shown, derived form used"],
                ["not_checkable", "equation, claim", "cannot be decided from the paper's data"],
                ["reproduced", "exact number", "equal to the printed precision or tolerance"],
                ["consistent", "statistical number", "inside the Monte Carlo distribution"],
                ["not_reproduced", "number", "outside the precision, tolerance or distribution"],
                ["upheld", "claim", "the claim's predicate holds on our results"],
                ["not_upheld", "claim", "the predicate fails; the evidence is in the table"],
            ],
            caption="Verdict and status words",
            highlight=[1, 5, 7],
        ),
    ]
    return Section(id="how-to-read", title="How to read this report", blocks=blocks)


def _paper_section(p: _Paper) -> Section:
    subs = [
        _summary(p),
        _equations(p),
        _published(p),
    ]
    figures, extra_figs, extra_subs = _figures(p)
    subs.append(figures)
    subs.append(_assumptions(p))
    subs.append(_findings(p, extra_figs, extra_subs))
    subs.append(_notebook(p))
    # the heading is the paper's title: the intro gives only the reference
    intro = [Paragraph(f"Reproduced paper: {p.citation}.".replace("..", "."))] if p.citation else []
    return Section(id=p.slug, title=p.title, blocks=intro, subsections=subs)


def _page_blocks(p: _Paper, key: str, prefix: str) -> tuple[list[Block], list[Section]]:
    """Blocks and subsections of the page sections listed for ``key``."""
    blocks: list[Block] = []
    subs: list[Section] = []
    ids = p.parts.get(key) or []
    for i, page_id in enumerate(ids):
        sec = p.page.section(page_id, p.slug)
        if sec is None:
            blocks.append(Paragraph(f"Not available: section '{page_id}' of {p.page.path.name}."))
            continue
        sec = _flatten_deep(_inline_single_tables(sec), depth=1)
        if i == 0:
            blocks += sec.blocks
            subs += sec.subsections
        else:
            subs.append(sec)
    return blocks, subs


def _summary(p: _Paper) -> Section:
    blocks: list[Block] = [Paragraph(p.score.line)]
    page_blocks, page_subs = _page_blocks(p, "summary", p.slug)
    blocks += page_blocks
    blocks.append(Link(f"The per-paper page with every detail: {p.slug}.html", f"{p.slug}.html"))
    return Section(f"{p.slug}-summary", "Summary", blocks, page_subs)


def _equation_sort_key(eq: str) -> tuple[float, str]:
    m = re.match(r"^\s*(\d+)(.*)$", str(eq))
    return (float(m.group(1)), m.group(2)) if m else (float("inf"), str(eq))


def _equations(p: _Paper) -> Section:
    by_eq: dict[str, dict[str, Any]] = {}
    for item in p.math:
        by_eq.setdefault(str(item.get("equation")), item)
    rows = []
    for r in p.audit.itertuples(index=False):
        m = by_eq.get(str(r.equation), {})
        rows.append(
            EquationRow(
                paper=p.slug,
                equation=str(r.equation),
                status=str(r.status),
                note=str(r.note),
                residual_text=str(r.residual),
                printed_mathml=m.get("printed_mathml"),
                derived_mathml=m.get("derived_mathml"),
                residual_mathml=m.get("residual_mathml"),
                printed_srepr=m.get("printed_srepr"),
                derived_srepr=m.get("derived_srepr"),
                residual_srepr=m.get("residual_srepr"),
            )
        )
    ac = p.score.audit
    differs = [r.equation for r in rows if r.status == "differs"]
    text = (
        f"{_plural(len(rows), 'printed equation')} checked against the derivation: "
        f"{ac['match']} match, {ac['differs']} differ, {ac['not_checkable']} not checkable. "
        "Printed: the equation as the paper prints it, transcribed into SymPy; derived: the "
        "same quantity from the derivation; residual: printed minus derived, simplified, "
        "shown where they differ."
    )
    if differs:
        text += (
            " Equations that differ (the pipeline uses the derived form): "
            + ", ".join(differs)
            + "."
        )
    no_math = sum(1 for r in rows if r.printed_mathml is None and r.derived_mathml is None)
    if no_math:
        text += (
            f" {_plural(no_math, 'row')} without a typeset form: the audit had no SymPy "
            "expression to compare (see the note)."
        )
    return Section(
        f"{p.slug}-equations",
        "Equation audit",
        [
            Paragraph(text),
            EquationTable(rows, caption=f"Equation audit ({p.slug}/equation_audit.csv)"),
        ],
    )


def _published_items(published: Mapping[str, Any]) -> list[Mapping[str, Any]]:
    return published_items(published)


def _group_label(item: Mapping[str, Any] | None) -> str:
    if not item:
        return "Other published numbers"
    ref = str(item.get("label") or "").strip()
    if not ref:
        return "Other published numbers"
    return re.split(r"\s*\(", ref)[0]


def _published(p: _Paper) -> Section:
    prefix = f"{p.slug}-published"
    if p.parts.get("published"):
        blocks, subs = _page_blocks(p, "published", prefix)
        for i, s in enumerate(subs):
            if not s.title:
                subs[i] = Section(s.id, "Claims", s.blocks, s.subsections)
        return Section(prefix, "Published vs reproduced", blocks, subs)
    # grouped here: numbers by the paper's table/figure, then the claims
    items = {str(i.get("id")): i for i in _published_items(p.published)}
    numbers = p.verdicts[p.verdicts["kind"] != "claim"]
    claims = p.verdicts[p.verdicts["kind"] == "claim"]
    blocks: list[Block] = [
        Paragraph(
            "Published: the value as the paper prints it (config/published); reproduced: "
            "our value; verdict and note: from verdicts.csv. Grouped by the paper's figure "
            "or table."
        )
    ]
    groups: dict[str, list[list[str]]] = {}
    marks: dict[str, list[int]] = {}
    for r in numbers.itertuples(index=False):
        label = _group_label(items.get(str(r.id).split("/")[0]))
        rows = groups.setdefault(label, [])
        if r.verdict in FAILURE_WORDS:
            marks.setdefault(label, []).append(len(rows))
        rows.append([r.id, r.quantity, r.method, r.published, r.reproduced, r.verdict, r.note])
    order = sorted(groups, key=lambda g: (_equation_sort_key(re.sub(r"^\D+", "", g)), g))
    for label in order:
        blocks.append(
            Table(
                columns=["id", "quantity", "method", "published", "reproduced", "verdict", "note"],
                rows=groups[label],
                caption=f"{label}: published numbers",
                highlight=marks.get(label, []),
            )
        )
    if len(claims):
        rows = []
        hl = []
        for r in claims.itertuples(index=False):
            if r.verdict in FAILURE_WORDS:
                hl.append(len(rows))
            rows.append([r.id, r.method, r.published, r.reproduced, r.verdict, r.note])
        blocks.append(
            Table(
                columns=["id", "applies to", "claim", "evidence (computed)", "verdict", "source"],
                rows=rows,
                caption="Claims",
                highlight=hl,
            )
        )
    return Section(prefix, "Published vs reproduced", blocks)


def _figures(p: _Paper) -> tuple[Section, list[Figure], list[Section]]:
    """The paper's figures; figures 'not in the paper' (and subsections holding only
    such figures) are returned separately for the findings."""
    prefix = f"{p.slug}-figures"
    blocks, subs = _page_blocks(p, "figures", prefix)
    keep = [b for b in blocks if not _is_extra_figure(b)]
    extra = [b for b in blocks if _is_extra_figure(b)]
    keep_subs, extra_subs = [], []
    for s in subs:
        figs = _all_figures(s)
        (extra_subs if figs and all(_is_extra_figure(f) for f in figs) else keep_subs).append(s)
    figs = [b for b in keep if isinstance(b, Figure)]
    intro = Paragraph(
        f"{_plural(len(figs), 'figure')} in the paper's numbering, redrawn from our results"
        "; where the paper prints a value, it is overlaid. Figures that are not in the paper "
        "are under Findings beyond the paper."
    )
    non_fig = [b for b in keep if not isinstance(b, Figure)]
    return (
        Section(prefix, "Figures", [intro, *non_fig, *figs], keep_subs),
        extra,  # type: ignore[return-value]
        extra_subs,
    )


def _assumptions(p: _Paper) -> Section:
    prefix = f"{p.slug}-assumptions"
    blocks, subs = _page_blocks(p, "assumptions", prefix)
    if not any(isinstance(b, Paragraph) for b in blocks):
        blocks.insert(
            0,
            Paragraph(
                "Where the paper is silent, each scenario file decides; the value shown is read "
                "from the file at the named field."
            ),
        )
    return Section(prefix, "Assumptions", blocks, subs)


def _findings(p: _Paper, extra_figs: list[Figure], extra_subs: list[Section]) -> Section:
    prefix = f"{p.slug}-findings"
    blocks, subs = _page_blocks(p, "findings", prefix)
    return Section(prefix, "Findings beyond the paper", [*blocks, *extra_figs], subs + extra_subs)


def _notebook(p: _Paper) -> Section:
    blocks: list[Block] = [
        Paragraph(
            "The notebook steps through the SymPy derivations of this paper and the equation "
            "audit; the workflow executed it and exported it to HTML beside this report."
        ),
        Link(f"Executed notebook: notebooks/{p.slug}.html", f"notebooks/{p.slug}.html"),
    ]
    return Section(f"{p.slug}-notebook", "Notebook", blocks)


# --------------------------------------------------------------------------- provenance


def _fmt_seed(prov: Mapping[str, Any]) -> str:
    parts = []
    for key in ("seed", "seeds"):
        v = prov.get(key)
        if isinstance(v, Mapping):
            parts += [f"{k}={v[k]}" for k in sorted(v)]
        elif v is not None:
            parts.append(f"{key}={v}")
    return ", ".join(parts) or "none"


def _config_now(path: Path) -> str:
    """sha256 of the scenario file as parsed now (pipeline.config.sha256_of)."""
    from pipeline.config import sha256_of

    if not path.is_file():
        return "file absent"
    with path.open(encoding="utf-8") as fh:
        return sha256_of(yaml.safe_load(fh))


def _scenario_dirs(rdir: Path) -> list[Path]:
    return (
        sorted(
            (d for d in rdir.iterdir() if d.is_dir() and (d / "provenance.json").is_file()),
            key=lambda d: (d.name != "paper", d.name),
        )
        if rdir.is_dir()
        else []
    )


def _provenance_section(papers: Sequence[_Paper], root: Path, config_dir: Path) -> Section:
    runs: list[list[str]] = []
    hl: list[int] = []
    pkgs: dict[str, dict[str, list[str]]] = {}
    describes: dict[str, int] = {}
    schemes: dict[str, list[str]] = {}
    for p in papers:
        for d in _scenario_dirs(p.results):
            prov = json.loads((d / "provenance.json").read_text(encoding="utf-8"))
            sha = str(prov.get("config_sha256", ""))
            file = prov.get("scenario_file") or f"{p.scenarios_dir.name}/{d.name}.yaml"
            scen_path = (
                _under(root, file)
                if prov.get("scenario_file")
                else (p.scenarios_dir / f"{d.name}.yaml")
            )
            now = _config_now(scen_path)
            same = "yes" if sha and now == sha else "no"
            if same == "no":
                hl.append(len(runs))
            desc = str(prov.get("git_describe", ""))
            describes[desc] = describes.get(desc, 0) + 1
            runs.append([p.slug, d.name, desc, sha[:16], same, _fmt_seed(prov)])
            scheme = str(prov.get("seed_scheme") or "not recorded")
            schemes.setdefault(p.slug, [])
            if scheme not in schemes[p.slug]:
                schemes[p.slug].append(scheme)
            for name, version in (prov.get("packages") or {}).items():
                pkgs.setdefault(str(name), {}).setdefault(str(version), []).append(
                    f"{p.slug}/{d.name}"
                )
    git = Section(
        "provenance-code",
        "Code version",
        [
            Paragraph(
                f"This report was built at git describe {git_describe(root)}. The scenario "
                "results were computed at: "
                + ", ".join(f"{k or 'unknown'} ({_plural(n, 'run')})" for k, n in describes.items())
                + "."
                if describes
                else f"This report was built at git describe {git_describe(root)}."
            )
        ],
    )
    scen = Section(
        "provenance-scenarios",
        "Scenario configurations and seeds",
        [
            Paragraph(
                "config sha256: the hash recorded in the scenario's provenance.json (canonical "
                "JSON of the parsed scenario file; the full hash is in that file); 'matches "
                "file now': whether the scenario file in config/ still hashes to it. Seeds: the master seed of the "
                "scenario's random streams (numpy SeedSequence, spawned per scenario and trial)."
            ),
            Table(
                columns=[
                    "paper",
                    "scenario",
                    "git describe",
                    "config sha256 (first 16 hex digits)",
                    "matches file now",
                    "seeds",
                ],
                rows=runs,
                caption="Scenario runs (results/<paper>/<scenario>/provenance.json)",
                highlight=hl,
            ),
            Table(
                columns=["paper", "seed scheme"],
                rows=[[slug, s] for slug, ss in schemes.items() for s in ss],
                caption="How each paper derives its random streams",
            ),
        ],
    )
    from pipeline.provenance import package_versions

    here = package_versions(tuple(sorted(set(pkgs) - {"python"})))
    prow = []
    for name in sorted(pkgs, key=lambda n: (n != "python", n)):
        versions = pkgs[name]
        if len(versions) == 1:
            recorded = next(iter(versions))
        else:
            recorded = "; ".join(f"{v} ({len(w)} runs)" for v, w in sorted(versions.items()))
        prow.append([name, recorded, here.get(name, "")])
    packages = Section(
        "provenance-packages",
        "Package versions",
        [
            Table(
                columns=["package", "recorded in the results", "this report's build"],
                rows=prow,
                caption="Package versions",
            )
        ],
    )
    bench_rows: list[list[str]] = []
    totals: list[str] = []
    for p in papers:
        bdir = p.results / "benchmarks"
        files = sorted(bdir.glob("*.tsv")) if bdir.is_dir() else []
        total = 0.0
        for f in files:
            df = pd.read_csv(f, sep="\t")
            if "s" not in df.columns or df.empty:
                raise ValueError(f"{f}: not a Snakemake benchmark file (no 's' column or no row)")
            s = float(pd.to_numeric(df["s"], errors="coerce").mean())
            rss = (
                float(pd.to_numeric(df["max_rss"], errors="coerce").max())
                if "max_rss" in df.columns
                else float("nan")
            )
            total += s
            bench_rows.append([p.slug, f.stem, f"{s:.2f}", "" if math.isnan(rss) else f"{rss:.0f}"])
        if files:
            totals.append(f"{p.slug} {total:.1f} s")
    wall = Section(
        "provenance-wall-time",
        "Wall time per workflow step",
        [
            Paragraph(
                "Wall time of each workflow job, from the Snakemake benchmark files "
                "(results/<paper>/benchmarks/<job>.tsv, column s). Sum per paper: "
                + (", ".join(totals) if totals else "no benchmark files")
                + " (jobs of different papers may have run in parallel)."
            ),
            Table(
                columns=["paper", "job", "wall time (s)", "max RSS (MB)"],
                rows=bench_rows,
                caption="Wall time per workflow step",
            ),
        ],
    )
    return Section(
        "provenance",
        "Provenance",
        [
            Paragraph(
                "Every results file records the code version, the scenario's config hash, the "
                "package versions and the seeds; they are collected here."
            )
        ],
        [git, scen, packages, wall],
    )


def _unique_ids(sections: list[Section]) -> list[Section]:
    seen: set[str] = set()

    def fix(s: Section) -> Section:
        sid = s.id
        k = 2
        while sid in seen:
            sid = f"{s.id}-{k}"
            k += 1
        seen.add(sid)
        return Section(sid, s.title, s.blocks, [fix(c) for c in s.subsections])

    return [fix(s) for s in sections]
