"""The combined report reports/reproduction.html (pipeline.report.document + reproduction_html).

Two cases, each checked in full:

* ``repository``: the document built from the repository's own ``results/`` and ``reports/``
  (on a fresh clone, from the reduced workflow run of ``results_repo``, tests/conftest.py);
* ``synthetic``: a small results tree written here (verdicts and audit rows, with the kinds of
  the differing equations, for every
  published item of the repository's ``config/published``, MathML, distinct PNG figures,
  provenance, benchmarks) with the per-paper pages rendered from the papers' report sections
  (``pipeline.report.page_html``). It always runs, so the suite never passes without checking a
  report.

Checks: the HTML parses (balanced elements, well-formed MathML), every ``#id`` link
resolves, every relative href exists beside the report, every image is a data URI and
nothing refers to a network; the scoreboard counts equal counts computed here with pandas
from verdicts.csv and equation_audit.csv; and headless Chromium (``/usr/bin/chromium``, the
DevTools protocol over a pipe: tests/browser_harness.py) loads the file with no console error,
exception or failed load, and writes a screenshot of the scoreboard to
``results/reproduction_scoreboard.png``.
"""

from __future__ import annotations

import base64
import dataclasses
import json
import re
import shutil
import xml.etree.ElementTree as ET
from html.parser import HTMLParser
from pathlib import Path

import pandas as pd
import pytest
import yaml

from pipeline.report import html as H
from pipeline.report.document import Document, build_document
from pipeline.report.reproduction_html import render_html, write_html
from tests.browser_harness import chromium_load, needs_chromium
from tests.workflow_harness import NEEDS_RUN

ROOT = Path(__file__).resolve().parents[2]
SCREENSHOT = ROOT / "results" / "reproduction_scoreboard.png"
SLUGS = yaml.safe_load((ROOT / "config" / "config.yaml").read_text(encoding="utf-8"))["papers"]
VOID = {"area", "base", "br", "col", "embed", "hr", "img", "input", "link", "meta", "source",
        "track", "wbr"}  # fmt: skip


# --------------------------------------------------------------------------- synthetic tree

_MATH = '<math xmlns="http://www.w3.org/1998/Math/MathML"><mrow>{}</mrow></math>'


def _png(index: int, path: Path) -> None:
    from PIL import Image

    path.parent.mkdir(parents=True, exist_ok=True)
    Image.new("RGB", (48, 32), ((37 * index) % 256, (91 * index) % 256, 200)).save(path)


def _figure_names(slug: str) -> list[str]:
    from pipeline.registry import load_paper

    return load_paper(slug).figure_files


#: the synthetic causes of failing rows: (kind, title, detail)
SYNTHETIC_CAUSES = (
    ("unpublished", "the synthetic run is not given", "The synthetic run is not given (N = 7)."),
    ("paper_error", "the synthetic formula drops a term", "Eq. 9 drops 2 x (residual 2 x)."),
)


def _synthetic_verdicts(published: dict) -> pd.DataFrame:
    """Every item and claim with a verdict; every fourth item fails, and every fourth claim is
    judged on two curves (``/a`` upheld, ``/b`` not upheld); a failing row carries one of two
    causes (title and full text) or none."""
    items = published.get("items") or published.get("values") or []
    rows = []

    def cause(i: int, verdict: str) -> list[str]:
        if verdict not in ("not_reproduced", "not_upheld") or i % 3 == 2:
            return ["", "", ""]
        return list(SYNTHETIC_CAUSES[i % 2])

    for i, it in enumerate(items):
        kind = it.get("kind", "exact")
        good = "consistent" if kind == "statistical" else "reproduced"
        verdict = "not_reproduced" if i % 4 == 3 else good
        method = it.get("method") or it.get("filter") or it.get("scheme") or ""
        rows.append([it["id"], kind, it.get("quantity", ""), method, str(it.get("value", "")),
                     "1.0", verdict, f"synthetic note {i}", *cause(i, verdict)])  # fmt: skip
    words = ("upheld", "not_upheld", "upheld", "not_checkable")
    for i, c in enumerate(published.get("claims") or []):
        curves = [("/a", "upheld"), ("/b", "not_upheld")] if i % 4 == 0 else [("", words[i % 4])]
        for suffix, verdict in curves:
            rows.append([c["id"] + suffix, "claim", "", "", c.get("text", ""), "evidence",
                         verdict, c.get("source", ""), *cause(i, verdict)])  # fmt: skip
    return pd.DataFrame(
        rows,
        columns=["id", "kind", "quantity", "method", "published", "reproduced", "verdict", "note",
                 "cause_kind", "cause", "cause_detail"],
    )  # fmt: skip


def _synthetic_tree(base: Path) -> Path:
    """A small but complete results tree (see the module docstring); returns its root."""
    from pipeline.config import sha256_of
    from pipeline.registry import load_paper
    from pipeline.report.model import ReportInputs
    from pipeline.report.page_html import build_page

    shutil.copytree(ROOT / "config", base / "config")
    fig_index = 0
    for slug in SLUGS:
        rdir = base / "results" / slug
        rdir.mkdir(parents=True)
        published = yaml.safe_load(
            (base / "config" / "published" / f"{slug}.yaml").read_text(encoding="utf-8")
        )
        _synthetic_verdicts(published).to_csv(rdir / "verdicts.csv", index=False)
        statuses = ["match", "differs", "not_checkable", "match", "differs", "match", "match"]
        audit = pd.DataFrame(
            {
                "equation": [str(i + 1) for i in range(len(statuses))],
                "status": statuses,
                "residual": [
                    "0" if s == "match" else ("x - 1" if s == "differs" else "") for s in statuses
                ],  # fmt: skip
                "note": [f"note {i}" for i in range(len(statuses))],
                # the two differing rows: an error of the paper and an artefact of the text
                "kind": ["", "paper_error", "", "", "text_artefact", "", ""],
            }
        )
        audit.to_csv(rdir / "equation_audit.csv", index=False)
        math = []
        for r in audit.itertuples():
            ok = r.status != "not_checkable"
            math.append(
                {
                    "equation": r.equation,
                    "status": r.status,
                    "printed_mathml": _MATH.format("<mi>x</mi><mo>+</mo><mn>1</mn>")
                    if ok
                    else None,
                    "derived_mathml": _MATH.format("<msup><mi>x</mi><mn>2</mn></msup>")
                    if ok
                    else None,
                    "residual_mathml": _MATH.format("<mi>&#945;</mi><mo>-</mo><mn>1</mn>")
                    if r.status == "differs"
                    else None,
                    "printed_srepr": "Symbol('x')" if ok else None,
                    "derived_srepr": "Symbol('x')" if ok else None,
                    "residual_srepr": "Integer(1)" if r.status == "differs" else None,
                }
            )
        (rdir / "equation_math.json").write_text(json.dumps(math), encoding="utf-8")
        for name in _figure_names(slug):
            fig_index += 1
            _png(fig_index, rdir / "figures" / name)
        for k, f in enumerate(sorted((base / "config" / "scenarios" / slug).glob("*.yaml"))):
            prov = {
                "config_sha256": sha256_of(yaml.safe_load(f.read_text(encoding="utf-8"))),
                "git_describe": "synthetic",
                "packages": {"python": "3.11", "numpy": "2.0"},
                "scenario": f.stem,
                "scenario_file": f"config/scenarios/{slug}/{f.name}",
                "seed": 1000 + k,
                "seed_scheme": "SeedSequence([seed, scenario, trial])",
            }
            (rdir / f.stem).mkdir()
            (rdir / f.stem / "provenance.json").write_text(json.dumps(prov), encoding="utf-8")
        bench = rdir / "benchmarks"
        bench.mkdir()
        for job, s in (("audit", 1.25), ("verdicts", 0.5)):
            (bench / f"{job}.tsv").write_text(
                f"s\th:m:s\tmax_rss\n{s}\t0:00:01\t100.0\n", encoding="utf-8"
            )
        notebooks = base / "reports" / "notebooks"
        notebooks.mkdir(parents=True, exist_ok=True)
        (notebooks / f"{slug}.html").write_text(
            f"<!DOCTYPE html><html><body><p>{slug}</p></body></html>", encoding="utf-8"
        )
        settings = yaml.safe_load((base / "config" / "config.yaml").read_text("utf-8")).get(slug)
        inputs = ReportInputs.under(slug, base / "results", base / "config", settings)
        build_page(load_paper(slug), inputs, base / "reports" / f"{slug}.html")
    return base


# --------------------------------------------------------------------------- fixtures


@dataclasses.dataclass
class Built:
    case: str
    root: Path
    reports: Path
    doc: Document
    html: str
    path: Path


@pytest.fixture(scope="module", params=[pytest.param("repository", marks=NEEDS_RUN), "synthetic"])
def built(request, tmp_path_factory) -> Built:
    if request.param == "repository":
        # this checkout's results, or on a fresh clone the reduced workflow run's
        root = request.getfixturevalue("results_repo")
    else:
        root = _synthetic_tree(tmp_path_factory.mktemp("synthetic"))
    doc = build_document(root)
    path = write_html(doc, tmp_path_factory.mktemp("report") / "reproduction.html")
    return Built(request.param, root, root / "reports", doc, path.read_text("utf-8"), path)


# --------------------------------------------------------------------------- 1. structure


class _Collector(HTMLParser):
    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.ids: list[str] = []
        self.refs: list[tuple[str, str, str]] = []  # (tag, attribute, value)
        self.stack: list[str] = []
        self.errors: list[str] = []
        self.tags: list[str] = []
        self.math_depth = 0

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        self.tags.append(tag)
        if "id" in a:
            self.ids.append(a["id"])
        for key in ("href", "src"):
            if key in a:
                self.refs.append((tag, key, a[key] or ""))
        if tag not in VOID:
            self.stack.append(tag)

    def handle_startendtag(self, tag, attrs):
        a = dict(attrs)
        if "id" in a:
            self.ids.append(a["id"])

    def handle_endtag(self, tag):
        if tag in VOID:
            return
        if not self.stack or self.stack[-1] != tag:
            self.errors.append(f"</{tag}> closes <{self.stack[-1] if self.stack else None}>")
            if tag in self.stack:
                while self.stack and self.stack.pop() != tag:
                    pass
            return
        self.stack.pop()


def _collect(html: str) -> _Collector:
    c = _Collector()
    c.feed(html)
    c.close()
    return c


def test_html_parses_and_every_reference_resolves(built):
    c = _collect(built.html)
    assert not c.errors, c.errors[:5]
    assert c.stack == [], f"unclosed elements: {c.stack[:10]}"
    assert len(c.ids) == len(set(c.ids)), "duplicate ids"
    ids = set(c.ids)
    internal = [v for _, k, v in c.refs if k == "href" and v.startswith("#")]
    assert internal, "no internal links"
    missing = sorted({v for v in internal if v[1:] not in ids})
    assert not missing, f"links to missing ids: {missing[:10]}"
    for slug in SLUGS:
        assert slug in ids and f"#{slug}" in internal
    relative = [v for t, k, v in c.refs if k == "href" and t == "a" and not v.startswith("#")]
    assert relative, "no relative links (notebooks)"
    for href in relative:
        assert not re.match(r"^[a-z][a-z0-9+.-]*:", href), f"non-relative link {href}"
        assert (built.reports / href).is_file(), f"{href} does not exist beside the report"
    for slug in SLUGS:
        assert f"notebooks/{slug}.html" in relative
    imgs = [v for t, k, v in c.refs if t == "img"]
    assert imgs, "no figures"
    for src in imgs:
        assert src.startswith("data:image/png;base64,"), src[:60]
        assert base64.b64decode(src.split(",", 1)[1])[:8] == b"\x89PNG\r\n\x1a\n"
    for tag, _, value in c.refs:
        if tag in ("script", "link", "img", "iframe", "source"):
            assert not re.match(r"^\s*(https?:)?//", value), f"network reference {tag} {value}"
    assert "script" not in c.tags and "link" not in c.tags and "iframe" not in c.tags
    assert not re.search(r"@import|url\(\s*['\"]?(https?:)?//", built.html)


def test_mathml_is_well_formed_and_present(built):
    from pipeline.report.model import EquationTable, walk

    maths = re.findall(r"<math\b.*?</math>", built.html, flags=re.S)
    n_expected = sum(
        1
        for s in walk(built.doc.appendices)
        for b in s.blocks
        if isinstance(b, EquationTable)
        for r in b.rows
        # the same expression printed and derived is shown once, as "printed = derived"
        for m in (
            (r.printed_mathml,)
            if r.printed_srepr and r.printed_srepr == r.derived_srepr
            else (r.printed_mathml, r.derived_mathml)
        )
        if m
    )
    assert n_expected > 0 and len(maths) >= n_expected
    for m in maths:
        ET.fromstring(m)  # raises on malformed XML


def test_rendering_is_deterministic(built):
    assert render_html(built.doc) == built.html


def test_sections_in_the_documented_order(built):
    from pipeline.report.paper_section import MAIN_TITLES

    ids = [s.id for s in built.doc.sections]
    assert ids == ["introduction", *SLUGS, "discussion", "references"]
    assert [s.id for s in built.doc.appendices] == [
        "equation-audits",
        "supporting",
        "assumptions",
        "provenance",
    ]
    for slug in SLUGS:
        sec = next(s for s in built.doc.sections if s.id == slug)
        assert tuple(s.title for s in sec.subsections) == MAIN_TITLES, slug
    # the papers' discussions, the same order
    discussion = next(s for s in built.doc.sections if s.id == "discussion")
    assert [s.id for s in discussion.subsections] == [f"discussion-{s}" for s in SLUGS]


def _figures(section):
    from pipeline.report.model import Figure, walk

    return [b for s in walk([section]) for b in s.blocks if isinstance(b, Figure)]


def test_pages_and_report_show_the_same_figures(built):
    """The combined report and each page are rendered from the same sections: every figure of
    a paper (label, caption, file) is on its page and in its section of the report, and the
    report reads no page (removing the pages changes nothing)."""
    for slug in SLUGS:
        sec = next(s for s in built.doc.sections if s.id == slug)
        figs = _figures(sec)
        assert figs, slug
        page = (built.reports / f"{slug}.html").read_text(encoding="utf-8")
        for f in figs:
            caption = f"<figcaption><strong>{H.escape(f.label)}</strong> "
            caption += f"{H.escape(f.caption)}</figcaption>"
            assert caption in page, (slug, f.label)
            assert f.in_paper == f.label.startswith("Fig. "), f.label
    if built.case == "synthetic":
        moved = built.reports.parent / "pages-moved"
        moved.mkdir()
        for slug in SLUGS:
            (built.reports / f"{slug}.html").rename(moved / f"{slug}.html")
        try:
            again = render_html(build_document(built.root))
        finally:
            for slug in SLUGS:
                (moved / f"{slug}.html").rename(built.reports / f"{slug}.html")
        assert again == built.html


# --------------------------------------------------------------------------- 2. the counts


def _expected_counts(results: Path, slug: str) -> tuple[dict, dict, dict, dict]:
    """(audit, published numbers, claims, self-checks) counted from the CSVs; a self-check is
    a row of an item the published file marks self_check (read here from the yaml)."""
    audit = pd.read_csv(results / slug / "equation_audit.csv", dtype=str, keep_default_na=False)
    verdicts = pd.read_csv(results / slug / "verdicts.csv", dtype=str, keep_default_na=False)
    published = yaml.safe_load((ROOT / "config" / "published" / f"{slug}.yaml").read_text())
    marked = {i["id"] for i in published["items"] if i.get("self_check")}
    is_check = verdicts["id"].str.split("/").str[0].isin(marked)
    is_claim = verdicts["kind"] == "claim"
    return (
        audit["status"].value_counts().to_dict(),
        verdicts.loc[~is_claim & ~is_check, "verdict"].value_counts().to_dict(),
        verdicts.loc[is_claim, "verdict"].value_counts().to_dict(),
        verdicts.loc[is_check, "verdict"].value_counts().to_dict(),
    )


def _nonzero(d: dict) -> dict:
    return {k: v for k, v in d.items() if v}


def _html_counts(html: str, slug: str) -> dict[str, dict[str, int]]:
    row = re.search(rf'<tr class="counts" id="score-{re.escape(slug)}">(.*?)</tr>', html, re.S)
    assert row, f"no scoreboard row for {slug}"
    out: dict[str, dict[str, int]] = {}
    for group, word, n in re.findall(
        r'data-group="(\w+)" data-word="(\w+)">(\d+)(?:<span class="kinds">[^<]*</span>)?</td>',
        row.group(1),
    ):
        out.setdefault(group, {})[word] = int(n)
    return out


def test_scoreboard_counts_equal_the_csv_counts(built):
    assert [r.slug for r in built.doc.scoreboard] == SLUGS
    for row in built.doc.scoreboard:
        audit, numbers, claims, checks = _expected_counts(built.root / "results", row.slug)
        assert _nonzero(row.self_checks) == checks, row.slug
        assert _nonzero(row.audit) == audit, row.slug
        assert _nonzero(row.numbers) == numbers, row.slug
        assert _nonzero(row.claims) == claims, row.slug
        shown = _html_counts(built.html, row.slug)
        assert _nonzero(shown["audit"]) == audit
        assert _nonzero(shown["numbers"]) == numbers
        assert _nonzero(shown["claims"]) == claims
        assert _nonzero(shown["self_checks"]) == checks
        n_numbers, n_good = (
            sum(numbers.values()),
            numbers.get("reproduced", 0) + numbers.get("consistent", 0),
        )
        if n_numbers:
            assert f"{n_good} of {n_numbers} published number" in row.line
        n_claims = sum(claims.values())
        if n_claims:
            assert f"{claims.get('upheld', 0)} of {n_claims} claim" in row.line
        # the status follows the main claims' marks (computed here from the CSV and the file)
        marks = _expected_marks(built.root, row.slug)
        if marks:
            expected = (
                "Full reproduction"
                if all(m == "Re" for m in marks)
                else "Not reproduced"
                if not any(m == "Re" for m in marks)
                else "Partial reproduction"
            )
            assert row.line.startswith(expected), (row.slug, marks)
            assert [m.mark for m in row.summary.main_claims] == marks


def _expected_marks(root: Path, slug: str) -> list[str]:
    """Each main claim's mark, recomputed from verdicts.csv and the published file."""
    published = yaml.safe_load((root / "config" / "published" / f"{slug}.yaml").read_text("utf-8"))
    v = pd.read_csv(root / "results" / slug / "verdicts.csv", dtype=str, keep_default_na=False)
    marks = []

    def named(i: str, entries: list[str]) -> bool:
        return any(
            i.startswith(e) if e.endswith(".") else (i == e or i.startswith(e + "/"))
            for e in entries
        )

    for claim in published.get("main_claims") or []:
        rows = v[[named(i, claim["rows"]) for i in v["id"]]]
        verdicts = set(rows["verdict"])
        if verdicts & {"not_reproduced", "not_upheld"}:
            marks.append("not_Re")
        elif verdicts <= {"reproduced", "consistent", "upheld"} and len(rows):
            marks.append("Re")
        else:
            marks.append("not_checkable")
    return marks


def _text(html: str) -> str:
    """The text a reader sees (tags, attributes and the stylesheet dropped)."""
    body = re.sub(r"<style>.*?</style>", " ", html, flags=re.S)
    return " ".join(re.sub(r"<[^>]+>", " ", body).split())


def test_first_page_names_no_internal_id(built):
    """The summaries name the paper's labels, never a verdict row id of verdicts.csv."""
    for row in built.doc.scoreboard:
        v = pd.read_csv(built.root / "results" / row.slug / "verdicts.csv", dtype=str,
                        keep_default_na=False)  # fmt: skip
        ids = set(v["id"]) | {i.split("/")[0] for i in v["id"]}
        text = " ".join([*row.summary.sentences, *(m.basis for m in row.summary.main_claims)])
        named = {i for i in ids if re.search(rf"(?<![\w.]){re.escape(i)}(?![\w/])", text)}
        assert not named, (row.slug, sorted(named)[:5])
        assert len(row.summary.sentences) == 3
        assert row.summary.sentences[0].startswith("Reproduced")


#: the most words of a main claim's basis on the first page (its counts, a few labels)
BASIS_WORDS = 40  # a main claim's basis: counts and at most a few labels (one line or two)


def test_first_page_sentences_are_short_and_name_each_cause_once(built):
    """Per paper three sentences, each at most SENTENCE_WORDS words; each cause's title
    (verdicts.csv ``cause``) once on the first page, in the third sentence, with its number of
    rows; its full text (``cause_detail``) not there but in the paper's section; a main claim's
    basis short."""
    from pipeline.report.labels import MAX_LABELS
    from pipeline.report.summary import SENTENCE_WORDS

    for row in built.doc.scoreboard:
        s = row.summary
        v = pd.read_csv(built.root / "results" / row.slug / "verdicts.csv", dtype=str,
                        keep_default_na=False)  # fmt: skip
        for k, sentence in enumerate(s.sentences):
            assert len(sentence.split()) <= SENTENCE_WORDS, (row.slug, k, sentence)
        front = " ".join([*s.sentences, *(m.basis for m in s.main_claims)])
        failing = v[v["verdict"].isin(["not_reproduced", "not_upheld"])]
        for title, rows in failing[failing["cause"] != ""].groupby("cause"):
            assert front.count(title) == 1, (row.slug, title)
            assert f"{title} (" in s.sentences[2] and f"{len(rows)} row" in s.sentences[2]
        for detail in set(failing["cause_detail"]) - {""}:
            assert detail not in front
            assert H.escape(detail) in built.html  # listed in full in the paper's section
        for m in s.main_claims:
            assert len(m.basis.split()) <= BASIS_WORDS, (row.slug, m.basis)
            assert m.basis.count(",") <= 2 * MAX_LABELS, m.basis


def test_no_raw_verdict_tokens_in_the_text(built):
    """One vocabulary: the reader sees 'not reproduced', never the CSV's token; in the report
    and on every paper's page."""
    pages = [built.html] + [
        (built.reports / f"{slug}.html").read_text(encoding="utf-8") for slug in SLUGS
    ]
    for html in pages:
        text = _text(html)
        for token in ("not_reproduced", "not_upheld", "not_checkable"):
            assert token not in text, token


def test_only_errors_of_the_paper_are_red(built):
    """A printed equation that differs is red (tone bad) only as an error of the paper; the
    matching ones are listed, their forms in a collapsed <details>."""
    rows = re.findall(r'<tr class="v-differs (t-\w+)"[^>]*>.*?<span class="v-differs t-\w+ '
                      r'(k-[\w-]+)">([^<]*)</span>', built.html, flags=re.S)  # fmt: skip
    assert rows
    for tone_class, kind_class, words in rows:
        assert (tone_class == "t-bad") == (kind_class == "k-paper-error"), words
        assert words.startswith("differs: ")
    if built.case == "synthetic":
        kinds = {k for _, k, _ in rows}
        assert {"k-paper-error", "k-text-artefact"} <= kinds
    assert '<details class="matching"><summary>' in built.html
    assert "<details open" not in built.html


# --------------------------------------------------------------------------- 3. the browser


@needs_chromium
def test_chromium_probe_sees_console_errors(tmp_path):
    """The probe itself works: a page with a console error, an exception and a missing
    image is reported (so an empty list below means a clean page, not a deaf probe)."""
    bad = tmp_path / "bad.html"
    bad.write_text(
        '<!DOCTYPE html><html><head><title>x</title></head><body><img src="missing.png">'
        '<script>console.error("boom"); undefinedFunction();</script></body></html>',
        encoding="utf-8",
    )
    problems = chromium_load(bad.as_uri())
    text = "\n".join(problems)
    assert "boom" in text and "undefinedFunction" in text and "ERR_FILE_NOT_FOUND" in text


@needs_chromium
def test_chromium_loads_the_report_cleanly_and_screenshots_the_scoreboard(built, tmp_path):
    # the real results (this checkout's, or the reduced run's on a fresh clone) give the
    # screenshot a person looks at, under results/; the synthetic one stays in tmp_path
    shot = SCREENSHOT if built.case == "repository" else tmp_path / "scoreboard.png"
    problems = chromium_load(built.path.as_uri(), screenshot=shot)
    assert problems == []
    data = shot.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    from PIL import Image

    with Image.open(shot) as im:
        width, height = im.size
        assert width == 1400 and 300 < height < 9000
        colours = im.convert("RGB").getcolors(maxcolors=1 << 20)
        assert colours is not None and len(colours) > 50, "screenshot looks blank"
