"""HTML report of altimeter_attitude, built in tmp_path.

Inputs: the real results (``results/altimeter_attitude/``: verdicts, rms summaries, sweep,
provenance) where they exist, synthetic stand-ins where they do not; always a small synthetic
equation audit and tiny matplotlib PNGs for the figures (their producers may not have run).
The real scenario files are used for the Assumptions section.
"""

from __future__ import annotations

import json
import math
import re
import shutil
from collections import Counter
from html.parser import HTMLParser
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
from matplotlib.figure import Figure

from pipeline.altimeter_attitude import report as R
from pipeline.altimeter_attitude.columns import (
    ALTIMETER_FILTERS,
    RMS_SUMMARY_COLUMNS,
    SWEEP_COLUMNS,
    UKF_TUNING_COLUMNS,
    WINDOW_SUMMARY_COLUMNS,
)
from pipeline.altimeter_attitude.paper import PAPER
from pipeline.altimeter_attitude.report_tuning import tuning_sentence
from pipeline.altimeter_attitude.scenario import load_scenario
from pipeline.altimeter_attitude.ukf import MerweWeights
from pipeline.altimeter_attitude.workflow import FIGURES, SWEEP_FIGURE
from pipeline.columns import AUDIT_COLUMNS, VERDICT_COLUMNS
from pipeline.report import html as H
from pipeline.report.model import Bullets, ReportInputs
from pipeline.report.page_html import render_page
from pipeline.report.plain import plain_value
from pipeline.scenarios import scenario_names

REPO = Path(__file__).resolve().parents[2]
REAL = REPO / "results" / "altimeter_attitude"
SCEN_DIR = REPO / "config" / "scenarios" / "altimeter_attitude"
SECTIONS = [
    "summary",
    "equation-audit",
    "verdicts",
    "results",
    "figures",
    "findings",
    "assumptions",
    "provenance",
]

AUDIT = pd.DataFrame(
    {
        "equation": ["7", "14", "26.A", "30.L", "31.Ppred", "13a"],
        "status": ["match", "match", "match", "differs", "match", "not_checkable"],
        "residual": ["0", "0", "0", "Matrix([[0], [0], [0], [-dt**2*g/2], [0]])", "0", ""],
        "note": [
            "",
            "",
            "",
            "L = dt B drops the <gravity> & 'dt^2' term",
            "",
            "definition",
        ],
        "kind": ["", "", "", "convention", "", ""],
    }
)[AUDIT_COLUMNS]


# --------------------------------------------------------------------------- inputs


def _synthetic_summary(rng: np.random.Generator) -> pd.DataFrame:
    n = len(ALTIMETER_FILTERS)
    df = pd.DataFrame({"filter": list(ALTIMETER_FILTERS)})
    for c in RMS_SUMMARY_COLUMNS[1:-1]:
        df[c] = rng.uniform(0.2, 3.0, n)
    no_cov = df["filter"].isin(["complementary", "accel_leveling"])
    df.loc[no_cov, ["roll_sigma_deg", "pitch_sigma_deg", "nees_roll", "nees_pitch"]] = np.nan
    df["n_runs"] = 100
    return df[RMS_SUMMARY_COLUMNS]


def _synthetic_windows(summary: pd.DataFrame) -> pd.DataFrame:
    """window_summary.csv: the flight is rms_summary.csv, the window after the first bank half of it."""
    after = summary.copy()
    after[RMS_SUMMARY_COLUMNS[1:-1]] *= 0.5
    return pd.concat(
        [
            summary.assign(window="flight", t_start_s=20.0, t_end_s=200.0),
            after.assign(window="after_bank", t_start_s=140.18, t_end_s=200.0),
        ]
    )[WINDOW_SUMMARY_COLUMNS]


def _synthetic_verdicts() -> pd.DataFrame:
    rows = [
        (
            "V1.lkf_roll",
            "statistical",
            "roll_rms_deg",
            "linear_kf",
            "0.16",
            "0.9",
            "not_reproduced",
        ),
        ("V2.lkf_pitch", "statistical", "pitch_rms_deg", "linear_kf", "0.07", "0.08", "consistent"),
        (
            "V2.lkf_pitch/after_bank",
            "approximate",
            "pitch_rms_deg",
            "linear_kf",
            "0.07",
            "0.3",
            "not_reproduced",
        ),
        ("V3.ukf_roll", "statistical", "roll_rms_deg", "ukf", "0.21", "0.5", "not_reproduced"),
        ("V4.ukf_pitch", "statistical", "pitch_rms_deg", "ukf", "0.10", "0.5", "not_reproduced"),
        (
            "C1.linear_beats_ukf",
            "claim",
            "less_rms",
            "linear_kf",
            "linear beats UKF",
            "roll 0.9 vs 0.5",
            "not_upheld",
        ),
        # the ids the published file's main claims name (config/published/altimeter_attitude.yaml)
        ("C2.lkf_sigma_consistent", "claim", "nees", "linear_kf", "consistent", "0.9", "upheld"),
        ("C3.ukf_sigma_consistent", "claim", "nees", "ukf", "consistent", "1.5", "not_upheld"),
        ("C4.lkf_error_bounded", "claim", "bounded", "linear_kf", "bounded", "ratio 0.4", "upheld"),
        ("C5.norm_error_stable", "claim", "norm", "linear_kf", "small", "1e-3", "upheld"),
    ]
    df = pd.DataFrame(rows, columns=VERDICT_COLUMNS[:-1])
    df["note"] = "synthetic"
    return df[VERDICT_COLUMNS]


def _synthetic_sweep(rng: np.random.Generator) -> pd.DataFrame:
    rows = [
        (p, v, f, *rng.uniform(0.3, 2.0, 2), 25, *rng.uniform(0.2, 0.6, 2), 140.0)
        for p, vals in (("imu_rate_hz", (25, 50, 100)), ("initial_error_deg", (0.5, 2, 5)))
        for v in vals
        for f in ("linear_kf", "ukf")
    ]
    return pd.DataFrame(rows, columns=SWEEP_COLUMNS)


def _synthetic_tuning(rng: np.random.Generator) -> pd.DataFrame:
    rows = []
    for a in (0.5, 1.0):
        for k in (-1.0, 0.0):
            w = MerweWeights(4, a, 2.0, k)
            rows.append(
                {
                    "alpha": a,
                    "kappa": k,
                    "beta": 2.0,
                    "wm0": w.Wm[0],
                    "wc0": w.Wc[0],
                    "nonnegative_weights": bool((w.Wm >= 0).all() and (w.Wc >= 0).all()),
                    "chosen": (a, k) == (1.0, 0.0),
                    **{c: rng.uniform(0.1, 0.6) for c in UKF_TUNING_COLUMNS[7:13]},
                    "n_runs": 100,
                    "status": "ok",
                }
            )
    return pd.DataFrame(rows, columns=UKF_TUNING_COLUMNS)


def _tiny_png(path: Path, label: str) -> None:
    fig = Figure(figsize=(1.2, 0.8), dpi=40)
    ax = fig.add_subplot()
    ax.plot([0, 1], [0, 1])
    ax.set_title(label, fontsize=5)
    fig.savefig(path, format="png")


def make_inputs(root: Path, *, figures: bool = True, audit: bool = True) -> dict:
    """A results tree under ``root``: real files copied where present, synthetic otherwise."""
    rng = np.random.default_rng(7)
    results = root / "results" / "altimeter_attitude"
    results.mkdir(parents=True)
    names = scenario_names(SCEN_DIR)
    for f in ("verdicts.csv", "sweep.csv"):
        if (REAL / f).is_file():
            shutil.copy(REAL / f, results / f)
    if not (results / "verdicts.csv").is_file():
        _synthetic_verdicts().to_csv(results / "verdicts.csv", index=False)
    if not (results / "sweep.csv").is_file():
        _synthetic_sweep(rng).to_csv(results / "sweep.csv", index=False)
    summaries = []
    for name in names:
        d = results / name
        d.mkdir()
        for f in ("rms_summary.csv", "provenance.json"):
            if (REAL / name / f).is_file():
                shutil.copy(REAL / name / f, d / f)
        if not (d / "rms_summary.csv").is_file():
            _synthetic_summary(rng).to_csv(d / "rms_summary.csv", index=False)
        if name == "paper":
            if (REAL / name / "ukf_tuning.csv").is_file():
                shutil.copy(REAL / name / "ukf_tuning.csv", d / "ukf_tuning.csv")
            else:
                _synthetic_tuning(rng).to_csv(d / "ukf_tuning.csv", index=False)
        if (REAL / name / "window_summary.csv").is_file():
            shutil.copy(REAL / name / "window_summary.csv", d / "window_summary.csv")
        else:
            _synthetic_windows(pd.read_csv(d / "rms_summary.csv")).to_csv(
                d / "window_summary.csv", index=False
            )
        if not (d / "provenance.json").is_file():
            (d / "provenance.json").write_text(
                json.dumps(
                    {
                        "git_describe": "v0-synthetic",
                        "config_sha256": load_scenario(SCEN_DIR / f"{name}.yaml").config_sha256,
                        "seeds": {"seed": 1, "n_runs": 100},
                        "packages": {"numpy": "x", "pandas": "y"},
                    }
                ),
                encoding="utf-8",
            )
        summaries.append(d / "rms_summary.csv")
    if audit:
        AUDIT.to_csv(results / "equation_audit.csv", index=False)
    figdir = results / "figures"
    figdir.mkdir()
    if figures:
        for name in [*FIGURES, SWEEP_FIGURE]:
            _tiny_png(figdir / name, name)
    out = root / "reports" / "altimeter_attitude.html"
    return {"results": results, "summaries": summaries, "figures": figdir, "out": out}


class Parser(HTMLParser):
    """Start tags with attributes, text of each <span data-...>, mismatched end tags."""

    VOID = {"img", "meta", "br", "hr", "link", "input"}

    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.starts: list[tuple[str, dict]] = []
        self.spans: list[tuple[dict, str]] = []
        self.stack: list[str] = []
        self.errors: list[str] = []
        self._span: dict | None = None
        self._text: list[str] = []

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        self.starts.append((tag, a))
        if tag not in self.VOID:
            self.stack.append(tag)
        if tag == "span":
            self._span, self._text = a, []

    def handle_endtag(self, tag):
        if tag in self.VOID:
            return
        if not self.stack or self.stack[-1] != tag:
            self.errors.append(f"</{tag}> at {self.getpos()}")
            return
        self.stack.pop()
        if tag == "span" and self._span is not None:
            self.spans.append((self._span, "".join(self._text)))
            self._span = None

    def handle_data(self, data):
        if self._span is not None:
            self._text.append(data)


def parse(text: str) -> Parser:
    p = Parser()
    p.feed(text)
    p.close()
    return p


def section_html(text: str, anchor: str) -> str:
    """The HTML of ``<section id=anchor>`` (sections nest, so count open/close tags)."""
    start = text.index(f'<section id="{anchor}">')
    depth, i = 0, start
    for m in re.finditer(r"<section\b|</section>", text[start:]):
        depth += 1 if m.group(0) == "<section" else -1
        if depth == 0:
            i = start + m.end()
            break
    return text[start:i]


def plain(html: str) -> str:
    """``html`` without the class the renderer gives cells that read as numbers."""
    return html.replace(' class="num"', "")


def inputs(results: Path, figures: Path | None = None) -> ReportInputs:
    return ReportInputs(
        results,
        SCEN_DIR,
        REPO / "config" / "published" / "altimeter_attitude.yaml",
        figures if figures is not None else results / "figures",
        {"published_scenario": "paper"},
    )


def fmt3(x) -> str:
    return "—" if x is None or (isinstance(x, float) and math.isnan(x)) else f"{float(x):.3f}"


@pytest.fixture(scope="module")
def built(tmp_path_factory) -> dict:
    paths = make_inputs(tmp_path_factory.mktemp("aa"))
    R.build_page(paths["results"], SCEN_DIR, paths["out"], figures_dir=paths["figures"])
    paths["text"] = paths["out"].read_text(encoding="utf-8")
    return paths


# --------------------------------------------------------------------------- tests


def test_page_written_atomically(built):
    out = built["out"]
    assert out.is_file() and out.stat().st_size > 0
    assert sorted(p.name for p in out.parent.iterdir()) == [out.name]  # no temp files left


def test_well_formed_sections_and_toc(built):
    p = parse(built["text"])
    assert p.errors == [] and p.stack == []
    ids = [a.get("id") for t, a in p.starts if t == "section"]
    assert len(ids) == len(set(ids)), Counter(ids)
    for s in SECTIONS:
        assert s in ids, s
    # the page follows the one template of every paper (pipeline.report.paper_section); the
    # paper's own sections keep their ids, under the template's sections and appendices
    toc = section_toc_links(built["text"])
    assert toc[:6] == ["summary", "equations", "published", "claims", "figures", "findings"]
    assert all(f'<section id="{t}">' in built["text"] for t in toc)


def section_toc_links(text: str) -> list[str]:
    nav = re.search(r'<nav class="toc">(.*?)</nav>', text, re.S).group(1)
    return re.findall(r'href="#([^"]+)"', nav)


def test_verdict_and_audit_counts_equal_the_csv(built):
    verdicts = pd.read_csv(built["results"] / "verdicts.csv", dtype=str, keep_default_na=False)
    audit = pd.read_csv(built["results"] / "equation_audit.csv", dtype=str, keep_default_na=False)
    expected = {
        "values": Counter(verdicts.loc[verdicts["kind"] != "claim", "verdict"]),
        "claims": Counter(verdicts.loc[verdicts["kind"] == "claim", "verdict"]),
        "audit": Counter(audit["status"]),
    }
    summary = R.report(inputs(built["results"], built["figures"])).section("summary")
    (counts,) = [b for b in summary.blocks if isinstance(b, Bullets)][:1]
    shown: dict[str, dict[str, int]] = {}
    for group, item in zip(("audit", "values", "claims"), counts.items, strict=True):
        tail = item.split(", ", 1)[1].rstrip(".")
        shown[group] = {
            w.replace(" ", "_"): int(n) for n, w in re.findall(r"(\d+) ([a-z ]+)", tail)
        }
    for item in counts.items:  # every count is on the page
        assert H.escape(item) in section_html(built["text"], "summary-overview")
    for group in expected:
        assert {k: v for k, v in shown[group].items() if v} == dict(expected[group]), group
    # the standard words are shown even at zero
    assert {"upheld", "not_upheld", "not_checkable"} <= set(shown["claims"])
    # a value kind's words (pipeline.verdicts.kinds.NUMBER_VERDICTS), and no other kind's
    from pipeline.verdicts.kinds import NUMBER_VERDICTS

    kinds = set(verdicts.loc[verdicts["kind"] != "claim", "kind"])
    words = {w for k in kinds for w in NUMBER_VERDICTS[k] if w != "not_checkable"}
    assert words <= set(shown["values"]) <= words | {"not_checkable"}
    assert {"match", "differs", "not_checkable"} <= set(shown["audit"])


def test_value_words_follow_the_kinds():
    """'reproduced' is the word of exact and approximate values, 'consistent' of statistical
    ones: approximate values never count as 'consistent'."""
    from pipeline.altimeter_attitude.report_summary import _value_words

    def frame(*kinds):
        return pd.DataFrame({"kind": list(kinds), "verdict": ["not_reproduced"] * len(kinds)})

    assert _value_words(frame("approximate")) == ["reproduced", "not_reproduced"]
    assert _value_words(frame("statistical")) == ["consistent", "not_reproduced"]
    assert _value_words(frame("exact", "statistical")) == [
        "reproduced",
        "consistent",
        "not_reproduced",
    ]


def test_headline_reads_published_and_ours(built):
    verdicts = pd.read_csv(built["results"] / "verdicts.csv", dtype=str, keep_default_na=False)
    summary = pd.read_csv(built["results"] / "paper" / "rms_summary.csv").set_index("filter")
    windows = pd.read_csv(built["results"] / "paper" / "window_summary.csv")
    summary_sec = plain(section_html(built["text"], "summary-overview"))
    # the headline table is with the results (an appendix), its sentence in the summary
    sec = plain(section_html(built["text"], "results"))
    assert "Published RMS errors" not in summary_sec
    for r in verdicts[verdicts["kind"] != "claim"].itertuples():
        window = r.id.rsplit("/", 1)[1] if "/" in r.id else "flight"
        w = windows[(windows["window"] == window) & (windows["filter"] == r.method)]
        ours = fmt3(w.iloc[0][r.quantity])
        if window == "flight":  # window_summary.csv repeats rms_summary.csv for the flight
            assert ours == fmt3(summary.at[r.method, r.quantity])
        # the row is named by its filter, window and quantity (no internal id)
        assert f"<td>{r.method}</td><td>{window}</td><td>{r.quantity}</td>" in sec
        assert f"<td>{H.escape(r.published)}</td>" in sec
        assert f"<td>{ours}</td>" in sec, (r.id, ours)
    lkf = "/".join(fmt3(summary.at["linear_kf", f"{a}_rms_deg"]) for a in ("roll", "pitch"))
    assert f"linear_kf roll/pitch RMS over the flight window {lkf} deg" in summary_sec
    # every not-upheld claim is stated with its evidence, in the table of every verdict row
    rows = plain(section_html(built["text"], "rows"))
    for r in verdicts[verdicts["verdict"] == "not_upheld"].itertuples():
        assert H.escape(r.reproduced) in rows, r.id


def test_every_rms_summary_value_appears_formatted(built):
    for path in built["summaries"]:
        name = path.parent.name
        sec = plain(section_html(built["text"], f"results-{H.slugify(name)}"))
        df = pd.read_csv(path)
        assert len(df) == len(ALTIMETER_FILTERS)
        for row in df.itertuples(index=False):
            cells = [f"<td>{row.filter}</td>"] + [
                f"<td>{fmt3(getattr(row, c))}</td>" for c in RMS_SUMMARY_COLUMNS[1:-1]
            ]
            cells.append(f"<td>{int(row.n_runs)}</td>")
            assert "".join(cells) in sec, (name, row.filter)


def test_differs_rows_highlighted_first_and_escaped(built):
    sec = section_html(built["text"], "equation-audit")
    assert sec.count('<tr class="v-differs">') == int((AUDIT["status"] == "differs").sum())
    rows = re.findall(r'<tr class="v-([a-z_]+)">', sec)
    assert rows[0] == "differs" and len(rows) == len(AUDIT)
    assert "Eq. 30.L" in sec
    assert "&lt;gravity&gt; &amp; &#x27;dt^2&#x27;" in sec and "<gravity>" not in sec


def test_images_are_data_uris_and_no_external_urls(built):
    text = built["text"]
    p = parse(text)
    imgs = [a for t, a in p.starts if t == "img"]
    assert len(imgs) == len(FIGURES) + 1
    for a in imgs:
        assert a["src"].startswith("data:image/png;base64,"), a["src"][:40]
    for t, a in p.starts:
        assert t not in ("script", "link", "iframe"), t
        for attr in ("src", "href"):
            v = (a.get(attr) or "").strip().lower()
            assert not re.match(r"^(https?:|//|ftp:|file:)", v), (t, attr, v[:60])
    stripped = re.sub(r'src="data:[^"]*"', "", text)
    assert "http://" not in stripped and "https://" not in stripped


def test_figure_captions_name_the_paper_figure(built):
    sec = section_html(built["text"], "figures")
    for name in FIGURES:
        m = re.match(r"fig(\d+)_", name)
        if m:
            assert f"paper Fig. {m.group(1)})" in sec, name
    # the sweep (not a figure of the paper) is with the findings beyond it
    assert "<caption>sweep.csv</caption>" in section_html(built["text"], "sweep")


def test_sweep_table_holds_every_point(built):
    sweep = pd.read_csv(built["results"] / "sweep.csv")
    sec = plain(section_html(built["text"], "sweep"))
    for r in sweep.itertuples():
        assert f"<td>{fmt3(r.roll_rms_deg)}</td>" in sec
        assert f"<td>{fmt3(r.pitch_rms_deg)}</td>" in sec


def test_ukf_tuning_table_holds_every_setting_and_marks_the_used_one(built):
    tuning = pd.read_csv(built["results"] / "paper" / "ukf_tuning.csv")
    sec = plain(section_html(built["text"], "ukf-tuning"))
    assert H.escape(tuning_sentence(tuning)) in sec
    for r in tuning.itertuples():
        assert f"<td>{fmt3(r.pitch_rms_deg)}</td>" in sec
        assert f"<td>{fmt3(r.noise_free_pitch_rms_deg)}</td>" in sec
    used = tuning[tuning["chosen"]]
    assert len(used) == 1 and bool(used["nonnegative_weights"].iloc[0])
    assert sec.count("<td>yes</td>") == int(
        tuning["chosen"].sum() + tuning["nonnegative_weights"].sum()
    )


def test_findings_are_computed(built):
    sec = plain(section_html(built["text"], "findings"))
    for path in built["summaries"]:
        s = pd.read_csv(path).set_index("filter")
        for angle in ("roll", "pitch"):
            r = s[f"{angle}_rms_deg"]
            best = r.idxmin()
            assert (
                f"<td>{path.parent.name}</td><td>{angle}</td><td>{best}</td>"
                f"<td>{fmt3(r.min())}</td>"
            ) in sec
            a, b = (
                s.at["linear_kf", f"{angle}_rms_deg"],
                s.at["linear_kf_no_gamma", f"{angle}_rms_deg"],
            )
            assert f"{100 * (a - b) / b:+.1f} %" in sec
    sweep = pd.read_csv(built["results"] / "sweep.csv")
    for (param, filt), g in sweep.groupby(["parameter", "filter"]):
        for angle in ("roll", "pitch"):
            lo, hi = g[f"{angle}_rms_deg"].min(), g[f"{angle}_rms_deg"].max()
            assert f"{filt} {angle} RMS" in sec and f"{fmt3(lo)}–{fmt3(hi)} deg" in sec, param


def test_assumptions_show_each_decision_with_its_value(built):
    sec = plain(section_html(built["text"], "assumptions"))
    for f in sorted(SCEN_DIR.glob("*.yaml")):
        sc = load_scenario(f)
        sub = section_html(sec, f"assumptions-{H.slugify(f.stem)}")
        assert H.escape(str(sc.raw["description"]).strip()) in sub
        for d in sc.decisions():
            v = plain_value(d["value"])  # plain text, no JSON
            assert f"<td>{H.escape(d['field'])}</td><td>{H.escape(v)}</td>" in sub, d["field"]


def test_provenance_shown(built):
    sec = plain(section_html(built["text"], "provenance"))
    for path in built["summaries"]:
        prov = json.loads((path.parent / "provenance.json").read_text(encoding="utf-8"))
        sub = section_html(sec, f"provenance-{H.slugify(path.parent.name)}")
        assert H.escape(prov["git_describe"]) in sub and prov["config_sha256"] in sub
        assert f"<td>seeds.seed</td><td>{prov['seeds']['seed']}</td>" in sub
        for pkg, version in prov["packages"].items():
            assert f"<td>{H.escape(pkg)}</td><td>{H.escape(version)}</td>" in sub


def test_deterministic(built, tmp_path):
    out = R.build_page(
        built["results"], SCEN_DIR, tmp_path / "again.html", figures_dir=built["figures"]
    )
    assert out.read_bytes() == built["out"].read_bytes()


def test_missing_audit_and_figures_say_not_available(tmp_path):
    paths = make_inputs(tmp_path, figures=False, audit=False)
    text = render_page(PAPER, R.report(inputs(paths["results"])))  # summaries discovered
    assert parse(text).errors == []
    assert "equation_audit.csv not available" in text
    assert f"({FIGURES[0]}): not available" in text and "<img" not in text
    for s in SECTIONS:
        assert f'<section id="{s}">' in text


def test_missing_verdicts_raise(tmp_path):
    paths = make_inputs(tmp_path, figures=False)
    (paths["results"] / "verdicts.csv").unlink()
    with pytest.raises(FileNotFoundError, match="verdicts.csv"):
        R.build_page(paths["results"], SCEN_DIR, paths["out"])
    assert not paths["out"].exists()


def test_page_step(tmp_path, monkeypatch):
    """The workflow's page step (pipeline.report.page_html.page_step) with its named inputs."""
    from pipeline.report.page_html import page_step

    monkeypatch.chdir(REPO)
    paths = make_inputs(tmp_path)
    out = tmp_path / "smk" / "altimeter_attitude.html"
    said = []
    inputs = {
        "audit": str(paths["results"] / "equation_audit.csv"),
        "published": str(REPO / "config" / "published" / "altimeter_attitude.yaml"),
        "figures": [str(paths["figures"] / f) for f in [*FIGURES, SWEEP_FIGURE]],
        "scenario_files": sorted(str(p) for p in SCEN_DIR.glob("*.yaml")),
    }
    params = {"paper": "altimeter_attitude", "settings": {"published_scenario": "paper"}}
    page_step(inputs, {"page": str(out)}, params, said.append)
    text = out.read_text(encoding="utf-8")
    assert text.count("data:image/png;base64,") == len(FIGURES) + 1
    assert said == [f"wrote {out}"]


def test_summary_names_no_row_by_id():
    """The paper's own summary says what the paper does and how ours compares; it does not
    repeat the failing rows by id (the shared template groups them by cause, in the paper's
    labels, and lists every row in the appendix)."""
    from pipeline.altimeter_attitude.report_summary import summary_blocks
    from pipeline.report.model import Paragraph, Table

    v = _synthetic_verdicts()
    v["tolerance"], v["reason"], v["cause_kind"], v["cause"] = "t", "r", "", ""
    blocks = summary_blocks(None, v, {}, "paper")
    text = " ".join(
        b.text if isinstance(b, Paragraph) else " ".join(getattr(b, "items", [])) for b in blocks
    )
    assert not [b for b in blocks if isinstance(b, Table)]
    for i in v.loc[v["verdict"].isin(["not_reproduced", "not_upheld"]), "id"]:
        assert i not in text, i


def test_after_bank_window_table_per_scenario(built):
    for path in built["summaries"]:
        w = pd.read_csv(path.parent / "window_summary.csv")
        after = w[w["window"] == "after_bank"]
        sec = plain(section_html(built["text"], f"results-{H.slugify(path.parent.name)}"))
        start = float(after["t_start_s"].iloc[0])
        assert f"After-bank window {start:.5g}-" in sec
        for row in after.itertuples():
            assert f"<td>{row.filter}</td><td>{fmt3(row.roll_rms_deg)}</td>" in sec
