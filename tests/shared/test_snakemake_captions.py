"""Issue 15: Snakemake's report renders each distinct caption once
(:mod:`pipeline.snakemake_captions`), with the HTML it rendered before, byte for byte."""

from __future__ import annotations

import warnings
from pathlib import Path
from types import SimpleNamespace

import jinja2
import pytest
import snakemake.report
from docutils.core import publish_parts

from pipeline import run_snakemake
from pipeline.snakemake_captions import cheaper_captions, memoised_publish_parts

ROOT = Path(__file__).resolve().parents[2]
CAPTIONS = sorted((ROOT / "reports" / "snakemake").glob("*.rst"))

# what Snakemake appends to every caption: a link target per output (abridged)
LINKS = "\n\n.. _Workflow: #\n.. _Statistics: #\n.. _Figures: #figures\n.. _fig1.png: #abc123\n"
# texts docutils reports problems in (an unknown reference, a bad title underline)
FAULTY = [
    "See `nowhere`_ for more.\n",
    "Title\n===\n\nText with *emphasis and ``literal``.\n",
    ".. note:: a directive\n\n   with a body, and a footnote [#]_.\n\n.. [#] the footnote\n",
]


def _texts() -> list[str]:
    return [p.read_text(encoding="utf-8") + LINKS for p in CAPTIONS] + FAULTY


def _plain(text: str, **kwargs) -> dict[str, str]:
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # docutils' deprecation of writer_name
        return publish_parts(text, **kwargs)


@pytest.mark.parametrize("kwargs", [{"writer_name": "html"}, {}])
def test_same_parts_as_docutils(kwargs: dict) -> None:
    """Every part of every caption (and of faulty texts) is what docutils gives without the
    memo and the shared settings, on the first call and on a repeated one."""
    assert CAPTIONS, "no caption files in reports/snakemake/"
    cached = memoised_publish_parts(_plain)
    for text in _texts():
        expected = _plain(text, **kwargs)
        assert cached(text, **kwargs) == expected
        assert cached(text, **kwargs) == expected


def test_settings_not_shared_between_calls() -> None:
    """A call's settings do not leak into the next: a document with a title, then one without,
    then the first again give docutils' own parts each time (docutils writes into them)."""
    cached = memoised_publish_parts(_plain)
    texts = ["Title\n=====\n\nbody\n", "just a paragraph\n", "Other\n=====\n\ntext\n"]
    for text in texts + texts:
        assert cached(text, writer_name="html") == _plain(text, writer_name="html")


def test_templates_compiled_once_render_the_same() -> None:
    """The report's records render the same captions with the template cache; each source is
    compiled once per environment."""

    class Record:
        def __init__(self, source: str, value: str):
            self.source, self.value = source, value

        def render(self, env, links: str) -> None:
            self.caption = env.from_string(self.source + links).render(value=self.value)

    env = jinja2.Environment()
    compiled = []
    from_string = env.from_string
    env.from_string = lambda source: compiled.append(source) or from_string(source)
    records = [Record("Figure ``{{ value }}``.", v) for v in ("a", "b", "a")]
    expected = [jinja2.Environment().from_string(r.source + "!").render(value=r.value) for r in records]  # fmt: skip
    module = SimpleNamespace(publish_parts=_plain, FileRecord=Record)
    assert cheaper_captions(module)
    for r in records:
        r.render(env, "!")
    assert [r.caption for r in records] == expected == ["Figure ``a``.!", "Figure ``b``.!", "Figure ``a``.!"]  # fmt: skip
    assert len(compiled) == 1


def test_pinned_report_module_has_what_is_patched() -> None:
    """Snakemake's report module still has the names the patch replaces (an upgrade that renames
    them makes this fail rather than the patch silently vanish); a module without them is left
    alone."""
    assert callable(snakemake.report.publish_parts)
    assert callable(snakemake.report.FileRecord.render)
    assert not cheaper_captions(SimpleNamespace(publish_parts=_plain))


def test_applied_only_to_a_report() -> None:
    assert run_snakemake.wants_report(["--cores", "2", "--report", "r.html"])
    assert run_snakemake.wants_report(["--report=r.html", "--report-after-run"])
    assert not run_snakemake.wants_report(["--cores", "2", "--report-stylesheet", "s.css"])
