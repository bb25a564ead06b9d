"""Every HTML page under reports/ reads without a network.

The pages: the combined ``reproduction.html``, each paper's ``<slug>.html`` and executed notebook
``notebooks/<slug>.html`` (the papers from config/config.yaml), and Snakemake's own
``snakemake.html`` where ``make reproduce`` wrote it. They come from ``results_repo``
(tests/conftest.py): this checkout's if the workflow has run here, else the reduced workflow run.

For each page:

* static: no ``src``/``href``/``data`` of a script, link, img, iframe, source, embed, object,
  audio, video or track names a network (``http:``, ``https:``, ``//host``), no stylesheet
  imports one (``@import``, ``url(http...)``), and no script imports a module from one;
* in headless Chromium with the network off (no DNS, DevTools offline): no failed request, and
  every request the page makes is for a ``file:`` or ``data:`` URL; and, except in Snakemake's
  report (whose embedded scripts log a warning of their own), no console error or exception;
* a notebook page has MathML and no LaTeX left for a script to typeset, and no script at all.

The probe is checked first on a page that asks for a CDN script, a remote image and a remote
stylesheet: it must see each request and its failure.
"""

from __future__ import annotations

import re
from html.parser import HTMLParser
from pathlib import Path

import pytest
import yaml

from tests.browser_harness import chromium_load, needs_chromium
from tests.workflow_harness import NEEDS_RUN

ROOT = Path(__file__).resolve().parents[2]
SLUGS = yaml.safe_load((ROOT / "config" / "config.yaml").read_text(encoding="utf-8"))["papers"]
#: the pages every run writes (paths under reports/); Snakemake's report is checked if present
PAGES = ["reproduction.html"] + [p for s in SLUGS for p in (f"{s}.html", f"notebooks/{s}.html")]
SNAKEMAKE_REPORT = "snakemake.html"
#: elements whose URL attribute the browser fetches on its own
FETCHING = {"script", "link", "img", "iframe", "source", "embed", "object", "audio", "video",
            "track", "input", "frame"}  # fmt: skip
NETWORK = re.compile(r"^\s*(?:[a-z][a-z0-9+.-]*:)?//|^\s*(?:https?|ftp|wss?):", re.I)
LOCAL_SCHEMES = ("file:", "data:")


class _Page(HTMLParser):
    """URL attributes of fetching elements, inline script bodies, and the text a reader sees
    outside code, preformatted output, styles, scripts and MathML."""

    SKIP = {"pre", "code", "style", "script", "math", "textarea"}

    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.refs: list[tuple[str, str, str]] = []
        self.tags: list[str] = []
        self.scripts: list[str] = []
        self.text: list[str] = []
        self._skip: list[str] = []

    def handle_starttag(self, tag, attrs):
        self.tags.append(tag)
        if tag in FETCHING:
            self.refs += [(tag, k, v or "") for k, v in attrs if k in ("src", "href", "data",
                                                                       "srcset", "poster")]  # fmt: skip
        if tag in self.SKIP:
            self._skip.append(tag)

    def handle_endtag(self, tag):
        if self._skip and self._skip[-1] == tag:
            self._skip.pop()

    def handle_data(self, data):
        if self._skip and self._skip[-1] == "script":
            self.scripts.append(data)
        elif not self._skip:
            self.text.append(data)


def network_references(html: str) -> list[str]:
    """Every way ``html`` would fetch from a network by itself, as ``<tag attr=value>``."""
    page = _Page()
    page.feed(html)
    page.close()
    found = [f"<{t} {k}={v[:100]}>" for t, k, v in page.refs if NETWORK.match(v)]
    found += [f"css {m[0][:100]}" for m in re.finditer(
        r"@import\s+(?:url\()?\s*['\"]?(?:https?:)?//[^'\"\s)]*|url\(\s*['\"]?(?:https?:)?//[^)]*",
        html, re.I)]  # fmt: skip
    for body in page.scripts:
        found += [f"script import {m[0][:100]}" for m in re.finditer(
            r"\bimport\s*\(?\s*['\"`](?:https?:)?//[^'\"`]*", body)]  # fmt: skip
    return found


@pytest.fixture(scope="module")
def reports(request) -> Path:
    return request.getfixturevalue("results_repo") / "reports"


def _page(reports: Path, name: str) -> Path:
    page = reports / name
    if name == SNAKEMAKE_REPORT and not page.is_file():
        pytest.skip(f"reports/{name} not written here (make reproduce writes it)")
    assert page.is_file(), f"reports/{name} is missing"
    return page


# --------------------------------------------------------------------------- the checks' checks


def test_static_check_finds_network_references():
    bad = (
        '<html><head><script src="https://cdn.example/x.js"></script>'
        '<link rel="stylesheet" href="//cdn.example/a.css"><style>@import url("http://e/b.css");'
        "p { background: url(https://e/c.png) }</style></head><body>"
        '<img src="http://e/d.png"><iframe src="HTTPS://e/f"></iframe>'
        '<script type="module">const m = await import("https://cdn.example/m.mjs");</script>'
        '<a href="https://example.org/">a link is not fetched</a>'
        '<img src="data:image/png;base64,AAAA"><img src="figures/local.png"></body></html>'
    )
    found = network_references(bad)
    assert len(found) == 7, found
    assert not any("example.org" in f or "local.png" in f or "data:" in f for f in found)


@needs_chromium
def test_browser_probe_sees_every_network_request(tmp_path):
    bad = tmp_path / "bad.html"
    bad.write_text(
        "<!DOCTYPE html><html><head><title>x</title>"
        '<link rel="stylesheet" href="https://cdn.example.invalid/style.css">'
        '<script src="https://cdn.example.invalid/lib.js"></script></head>'
        '<body><img src="http://images.example.invalid/a.png">'
        '<img src="data:image/gif;base64,R0lGODlhAQABAAAAACw=" alt="pixel"></body></html>',
        encoding="utf-8",
    )
    requests: list[str] = []
    problems = chromium_load(bad.as_uri(), offline=True, requests=requests)
    remote = [u for u in requests if not u.startswith(LOCAL_SCHEMES)]
    assert {u.split("/")[2] for u in remote} == {"cdn.example.invalid", "images.example.invalid"}
    failed = [p for p in problems if p.startswith("failed request: ")]
    assert len(failed) == 3, problems
    assert any(u.startswith("file:") for u in requests)


# --------------------------------------------------------------------------- the pages


def _run_params(values: list[str]) -> list:
    return [pytest.param(v, marks=NEEDS_RUN) for v in values]


def _needs_run(test):
    for mark in NEEDS_RUN:
        test = mark(test)
    return test


@_needs_run
def test_every_page_is_checked(reports):
    """The list above is every HTML page under reports/ (a new page joins it or this fails)."""
    on_disk = {p.relative_to(reports).as_posix() for p in reports.rglob("*.html")}
    assert on_disk - {SNAKEMAKE_REPORT} == set(PAGES)


@pytest.mark.parametrize("name", _run_params(PAGES + [SNAKEMAKE_REPORT]))
def test_page_refers_to_no_network(name, reports):
    assert network_references(_page(reports, name).read_text(encoding="utf-8")) == []


@pytest.mark.parametrize("slug", _run_params(SLUGS))
def test_notebook_page_is_mathml_without_scripts(slug, reports):
    html = _page(reports, f"notebooks/{slug}.html").read_text(encoding="utf-8")
    page = _Page()
    page.feed(html)
    page.close()
    assert "script" not in page.tags, "a notebook page runs no script"
    assert page.tags.count("math") > 20, "the notebook's mathematics is MathML"
    text = " ".join(page.text)
    raw = re.findall(r"\$[^$]{0,80}\\[A-Za-z]+[^$]{0,80}\$|\\begin\{[a-z]+\*?\}|\\\(|\\\[", text)
    assert raw == [], f"LaTeX left for a script to typeset: {raw[:5]}"


@needs_chromium
@pytest.mark.parametrize("name", _run_params(PAGES + [SNAKEMAKE_REPORT]))
def test_page_loads_offline_without_a_failed_or_remote_request(name, reports):
    page = _page(reports, name)
    requests: list[str] = []
    problems = chromium_load(page.as_uri(), offline=True, requests=requests)
    if name == SNAKEMAKE_REPORT:
        # Snakemake's own embedded scripts write to the console (Tailwind's "should not be used
        # in production" warning); what it requests is checked all the same
        problems = [p for p in problems if p.startswith("failed request: ")]
    assert problems == []
    assert page.as_uri() in requests
    remote = [u[:120] for u in requests if not u.startswith(LOCAL_SCHEMES)]
    assert remote == []
