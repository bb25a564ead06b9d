"""The built reports speak the paper's language: no verdict-row id (``T9.psi.A3``,
``C2/proposed_simulated``) and no JSON-like value (``{"mode": ...}``) where readers look, and
no results file or column name (``ukf_tuning.csv``, ``imu_rate_hz``, ``linear_kf``: every
results file name and every snake_case string constant of ``pipeline/columns.py`` and
``pipeline/<slug>/columns.py``) in the cause texts, the prose that says why a row fails.

Row ids may appear only in the dedicated column (:data:`pipeline.report.vocabulary.ROW_ID`) of
the per-row tables, for cross-reference with verdicts.csv; in the PDF (pdftotext has no table
structure) only on the pages of Appendix B, the supporting results. The scan reads the built
files (``reports/*.html``, ``reports/reproduction.pdf``) and the ids of every built
``results/<slug>/verdicts.csv``; it skips what is not built.
"""

from __future__ import annotations

import ast
import re
import shutil
import subprocess
from html.parser import HTMLParser
from pathlib import Path

import pandas as pd
import pytest

from pipeline.report.vocabulary import ROW_ID

ROOT = Path(__file__).resolve().parents[2]
SLUGS = ("north_finding", "platform_drift", "altimeter_attitude")
#: a brace (or bracket) opening a key and a colon: a mapping printed as JSON or a Python dict
JSON_LIKE = re.compile(r"[{\[]\s*[\"'“‘]?[A-Za-z_][\w ]*[\"'”’]?\s*:")
_SKIP = {"script", "style", "math", "svg"}


def id_pattern(ids: list[str]) -> re.Pattern[str]:
    """Ids that carry a '.' or '/' (a bare 'C1' is too common a token to scan for), with their
    bases, matched as whole tokens.

    >>> p = id_pattern(["T9.psi.A3", "C2/proposed_simulated", "C1"])
    >>> [m.group() for m in p.finditer("T9.psi.A3, C2 and C2/proposed_simulated; T9.psi.A33")]
    ['T9.psi.A3', 'C2/proposed_simulated']
    """
    tokens = {t for i in ids for t in (i, i.split("/", 1)[0]) if re.search(r"[./]", t)}
    alts = "|".join(re.escape(t) for t in sorted(tokens, key=len, reverse=True))
    return re.compile(rf"(?<![\w.]){'(?:' + alts + ')' if alts else '(?!)'}(?![\w])")


class _Text(HTMLParser):
    """The text a reader sees, without the cells of the row-id columns."""

    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.parts: list[str] = []
        self.skip = 0
        self.tables: list[dict] = []

    def handle_starttag(self, tag: str, attrs: list) -> None:
        if tag in _SKIP:
            self.skip += 1
        elif tag == "table":
            self.tables.append({"head": [], "row_head": [], "col": -1, "in_id": False})
        elif self.tables and tag == "tr":
            t = self.tables[-1]
            t["col"], t["row_head"] = -1, []
        elif self.tables and tag in ("td", "th"):
            t = self.tables[-1]
            t["col"] += 1
            t["cell"] = tag
            t["in_id"] = tag == "td" and t["col"] < len(t["head"]) and t["head"][t["col"]] == ROW_ID
            t["buf"] = []

    def handle_endtag(self, tag: str) -> None:
        if tag in _SKIP:
            self.skip = max(0, self.skip - 1)
        elif tag == "table" and self.tables:
            self.tables.pop()
        elif self.tables and tag == "th":
            t = self.tables[-1]
            t["row_head"].append(" ".join("".join(t.get("buf", [])).split()))
        elif self.tables and tag == "tr":
            t = self.tables[-1]
            if t["row_head"]:
                t["head"] = t["row_head"]
        if self.tables and tag in ("td", "th"):
            self.tables[-1]["in_id"] = False

    def handle_data(self, data: str) -> None:
        if self.skip:
            return
        if self.tables:
            t = self.tables[-1]
            t.setdefault("buf", []).append(data)
            if t["in_id"]:
                return
        self.parts.append(data)


def html_text(path: Path) -> str:
    parser = _Text()
    parser.feed(path.read_text(encoding="utf-8"))
    return " ".join(" ".join(parser.parts).split())


def _ids(root: Path = ROOT) -> list[str]:
    ids: list[str] = []
    for slug in SLUGS:
        path = root / "results" / slug / "verdicts.csv"
        if path.exists():
            ids += list(pd.read_csv(path, dtype=str, keep_default_na=False)["id"])
    if not ids:
        pytest.skip("no results/<slug>/verdicts.csv built")
    return ids


def _offences(text: str, pattern: re.Pattern[str]) -> list[str]:
    out = [f"id {m.group()!r}: ...{text[max(0, m.start() - 60) : m.end() + 20]}..." for m in pattern.finditer(text)]  # fmt: skip
    out += [f"JSON-like: ...{text[max(0, m.start() - 60) : m.end() + 40]}..." for m in JSON_LIKE.finditer(text)]  # fmt: skip
    return out


#: a results column (or value) name: snake_case with at least one underscore
SNAKE = re.compile(r"^[a-z][a-z0-9]*(?:_[a-z0-9]+)+$")


def results_names(root: Path = ROOT) -> set[str]:
    """Every results file name (``*.csv``, ``*.json``) the columns modules mention, every
    snake_case string constant they define (column names, filter and window tokens) and the
    sweep's parameter names (the values of its ``parameter`` column)."""
    from pipeline.altimeter_attitude.sweep import PARAMETERS

    out: set[str] = {p for p in PARAMETERS if SNAKE.match(p)}
    for path in [root / "pipeline" / "columns.py", *sorted(root.glob("pipeline/*/columns.py"))]:
        text = path.read_text(encoding="utf-8")
        out |= set(re.findall(r"\b\w+\.(?:csv|json)\b", text))
        for node in ast.walk(ast.parse(text)):
            if isinstance(node, ast.Constant) and isinstance(node.value, str):
                if SNAKE.match(node.value):
                    out.add(node.value)
    return out


def name_pattern(names: set[str]) -> re.Pattern[str]:
    """The names as whole tokens.

    >>> p = name_pattern({"ukf_tuning.csv", "linear_kf"})
    >>> [m.group() for m in p.finditer("see ukf_tuning.csv: linear_kf, linear_kf_x, linear KF")]
    ['ukf_tuning.csv', 'linear_kf']
    """
    alts = "|".join(re.escape(t) for t in sorted(names, key=len, reverse=True))
    return re.compile(rf"(?<![\w.]){'(?:' + alts + ')' if alts else '(?!)'}(?![\w])")


def test_the_names_scanned_for_include_files_columns_and_tokens():
    names = results_names()
    assert {"ukf_tuning.csv", "imu_rate_hz", "linear_kf", "n_profile.csv", "phi_deg"} <= names
    assert "filter" not in names and "method" not in names  # plain words are not scanned


@pytest.mark.parametrize("slug", SLUGS)
def test_cause_texts_use_reader_words_not_results_names(slug, results_repo):
    """The cause columns of verdicts.csv are printed as prose in the reports (the failing rows'
    root causes): they name filters, parameters and files in words."""
    path = results_repo / "results" / slug / "verdicts.csv"
    if not path.exists():
        pytest.skip(f"{path} not built")
    table = pd.read_csv(path, dtype=str, keep_default_na=False)
    pattern = name_pattern(results_names())
    offences = [
        f"{row_id} {column}: {m.group()!r} in ...{text[max(0, m.start() - 60) : m.end() + 20]}..."
        for column in ("cause", "cause_detail")
        for row_id, text in zip(table["id"], table[column], strict=True)
        for m in pattern.finditer(text)
    ]
    assert not offences, f"{path}: {len(offences)} offence(s):\n" + "\n".join(offences[:20])


def test_the_scan_finds_ids_and_json_outside_the_row_id_column(tmp_path):
    """The scanner itself: an id or a JSON value in text or in another column is found; an id
    under the row-id column is not."""
    page = tmp_path / "p.html"
    page.write_text(
        f"<p>ok</p><table><tr><th>item</th><th>{ROW_ID}</th></tr>"
        "<tr><td>Table 9, azimuth method 3</td><td>T9.psi.A3</td></tr></table>",
        encoding="utf-8",
    )
    pattern = id_pattern(["T9.psi.A3", "C2/proposed_simulated"])
    assert _offences(html_text(page), pattern) == []
    for bad in (
        "<p>see T9.psi.A3</p>",
        '<td>{"mode": "scan"}</td>',
        "<p>C2/proposed_simulated</p>",
    ):
        page.write_text(bad, encoding="utf-8")
        assert _offences(html_text(page), pattern), bad
    page.write_text(
        "<table><tr><th>item</th><th>id</th></tr><tr><td>x</td><td>T9.psi.A3</td></tr></table>",
        encoding="utf-8",
    )
    assert _offences(html_text(page), pattern)  # only the row-id column may hold ids


@pytest.mark.parametrize("name", ["reproduction", *SLUGS])
def test_built_html_shows_no_ids_or_json_where_readers_look(name, results_repo):
    path = results_repo / "reports" / f"{name}.html"
    if not path.exists():
        pytest.skip(f"{path} not built")
    offences = _offences(html_text(path), id_pattern(_ids(results_repo)))
    assert not offences, f"{path}: {len(offences)} offence(s):\n" + "\n".join(offences[:20])


def _pdf_pages(path: Path) -> list[str]:
    out = subprocess.run(
        ["pdftotext", "-layout", str(path), "-"], capture_output=True, text=True, check=True
    ).stdout
    return out.split("\f")


def test_built_pdf_shows_no_ids_or_json_outside_appendix_b(results_repo):
    path = results_repo / "reports" / "reproduction.pdf"
    if not path.exists():
        pytest.skip(f"{path} not built")
    if shutil.which("pdftotext") is None:
        pytest.skip("pdftotext not installed")
    pages = _pdf_pages(path)
    heading = re.compile(r"^\s*([A-Z]) (\S.*?)\s*$", re.M)
    appendix = ""
    pattern = id_pattern(_ids(results_repo))
    offences = []
    for k, page in enumerate(pages, 1):
        text = " ".join(page.split())
        if "Contents" not in page:  # the contents page lists every heading with dots
            for m in heading.finditer(page):
                if m.group(2).startswith(("Supporting results", "Assumptions", "Provenance")):
                    appendix = m.group(1)
        found = _offences(text, pattern)
        if appendix == "B":
            found = [f for f in found if f.startswith("JSON-like")]
        offences += [f"page {k}: {f}" for f in found]
    assert not offences, f"{path}: {len(offences)} offence(s):\n" + "\n".join(offences[:20])
