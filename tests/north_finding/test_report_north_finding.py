"""Figures and HTML report of north_finding, on synthetic inputs built here.

The fixture mimics the results contract (DESIGN.md, pipeline/columns.py) with a
seeded RNG: published values shaped like the paper's Tables 1-12, verdicts,
an equation audit, two scenario result directories (one without the optional
sensitivity/provenance/benchmark files), scenario configs with decisions.
"""

from __future__ import annotations

import json
import os
import re
import shutil
import struct
import subprocess
import sys
from collections import Counter
from html.parser import HTMLParser
from pathlib import Path

import numpy as np
import pandas as pd
import pytest
import yaml

from pipeline.columns import AUDIT_COLUMNS, VERDICT_COLUMNS, VERDICTS
from pipeline.north_finding import figures as F
from pipeline.north_finding import report as R
from pipeline.north_finding.columns import (
    ERROR_BUDGET_COLUMNS,
    ERROR_SOURCES,
    ESTIMATE_COLUMNS,
    MC_SUMMARY_COLUMNS,
    MC_TRIAL_COLUMNS,
    METHOD_QUANTITIES,
    SENSITIVITY_COLUMNS,
)
from pipeline.north_finding.figures_spec import FIGURE_FILES
from pipeline.north_finding.percent_errors import abs_error_quantiles, published_error_pct
from pipeline.north_finding.published_items import canonical_quantity, load_published
from pipeline.north_finding.report_results import TIMINGS_NOTE, resolve_dotted
from pipeline.report import html as H
from pipeline.report.model import ReportInputs, Table
from tests.hang_guard import HANG_GUARD_S

TRUTH = {
    "phi_deg": 50.0,
    "theta_deg": 30.0,
    "psi_deg": 88.0,
    "acc_bias_ug": 100.0,
    "acc_scale": 1.00005,
    "acc_scale_approx": 1.00005,
    "gyro_bias_rad_s": 4.85e-8,
    "gyro_scale": 1.00002,
    "gyro_scale_approx": 1.00002,
}
SHORT = {
    "phi_deg": "phi",
    "theta_deg": "theta",
    "psi_deg": "psi",
    "acc_bias_ug": "acc_bias",
    "acc_scale": "acc_scale",
    "gyro_bias_rad_s": "gyro_bias",
    "gyro_scale": "gyro_scale",
    "gyro_scale_approx": "gyro_scale_approx",
}
UNIT = {
    "phi_deg": "deg",
    "theta_deg": "deg",
    "psi_deg": "deg",
    "acc_bias_ug": "ug",
    "acc_scale": "1",
    "gyro_bias_rad_s": "rad/s",
    "gyro_scale": "1",
    "gyro_scale_approx": "1",
}
# (table, quantity, sensor, {method: (value, error_pct)}) as in the paper's digest
PAPER_TABLES = [
    (
        1,
        "phi_deg",
        "real",
        {
            "L1": ("50.0050", "0.0110"),
            "L2": ("50.0056", "0.0110"),
            "L3": ("50.0030", "0.0070"),
            "L4": ("50.0720", "0.1450"),
        },
    ),
    (
        2,
        "theta_deg",
        "real",
        {
            "L1": ("29.9990", "0.0016"),
            "L2": ("29.9995", "0.0015"),
            "L3": ("30.0040", "0.0120"),
            "L4": ("29.9940", "0.0210"),
        },
    ),
    (3, "acc_bias_ug", "real", {"L5": ("77.4", "22.3")}),
    (4, "acc_scale", "real", {"L5": ("1.000068", "0.0018")}),
    (5, "psi_deg", "ideal", {m: ("88", "0") for m in ("A1c1", "A1c2", "A2", "A3", "A4", "A5")}),
    (6, "gyro_bias_rad_s", "ideal", {"A4": ("4.85e-8", "0")}),
    (7, "gyro_scale", "ideal", {m: ("1.00002", "0") for m in ("A4", "A5", "A6")}),
    (8, "gyro_scale_approx", "ideal", {"A5": ("1.0000199", "0")}),
    (
        9,
        "psi_deg",
        "real",
        {
            "A1c1": ("88.0012", "0.0014"),
            "A1c2": ("88.0043", "0.0050"),
            "A2": ("87.9890", "0.0121"),
            "A3": ("88.4420", "0.502"),
            "A4": ("88.0015", "0.0017"),
            "A5": ("88.0017", "0.0020"),
        },
    ),
    (10, "gyro_bias_rad_s", "real", {"A4": ("4.49e-8", "3.063")}),
    (
        11,
        "gyro_scale",
        "real",
        {
            "A4": ("1.000012", "0.0037"),
            "A5": ("1.0000199", "0.0000036"),
            "A6": ("1.000050", "0.00310"),
        },
    ),
    (
        12,
        "gyro_scale_approx",
        "real",
        {"A5": ("1.0000198", "0.000003614"), "A6": ("1.0000049", "0.0000312")},
    ),
]
CLAIMS = [
    {
        "id": "C1.roll_best",
        "text": "Levelling: method 3 (y channel, 4 positions) is best.",
        "source": "Sec. 6",
        "label": "Sec. 6",
        "predicate": {
            "test": "argmin",
            "quantity": "phi_deg",
            "methods": ["L1", "L2", "L3", "L4"],
            "expect": "L3",
        },
    },
    {
        "id": "C2.azimuth_best",
        "text": "Azimuth: method 1 case 1 is best.",
        "source": "Sec. 6",
        "label": "Sec. 6",
        "predicate": {
            "test": "argmin",
            "quantity": "psi_deg",
            "methods": ["A1c1", "A5"],
            "expect": "A1c1",
        },
    },
    {
        "id": "C4.roll_L1_L2_equal",
        "text": "In levelling methods 1 and 2 the roll errors are approximately equal",
        "source": "Sec. 5-1-1",
        "label": "Sec. 5-1-1",
        "note": "'approximately equal' read as RMS errors within 20 % of each other",
        "predicate": {
            "test": "close",
            "a": {"method": "L1"},
            "b": {"method": "L2"},
            "rel_tol": 0.2,
        },
    },
    {
        "id": "C3.gyro_scale_best",
        "text": "Gyro scale factor: method 5 is recommended.",
        "source": "Sec. 6",
        "label": "Sec. 6",
        "predicate": {
            "test": "argmin",
            "quantity": "gyro_scale",
            "methods": ["A4", "A5", "A6"],
            "expect": "A5",
        },
    },
]
SCENARIO_PAPER = {
    "description": "The paper's Section 5 setting with heavy averaging.",
    "truth": {"phi_deg": 50.0, "theta_deg": 30.0, "psi_deg": 88.0, "latitude_deg": 35.0},
    "noise": {"model": "gaussian", "sigma_fraction": 0.05, "n_avg": 1000000},
    "misalignment": {"rows": [[0.0, 10.0, -10.0], [5.0, 0.0, 5.0]]},
    "decisions": [
        {"field": "noise.n_avg", "text": "The paper averages but never says how many samples."},
        {
            "field": "noise.sigma_fraction",
            "text": "'about 5 % of the nominal values' read as sigma = 0.05 g.",
        },
        {
            "field": "misalignment.rows.0",
            "text": "Signs of the off-diagonal terms are not printed.",
        },
        {"field": "truth", "text": "Section 5 angles."},
    ],
}
SCENARIO_LOW = {
    "description": "Less averaging, to show the noise floor.",
    "noise": {"model": "gaussian", "sigma_fraction": 0.05, "n_avg": 1000},
    "decisions": [{"field": "noise.n_avg", "text": "Two orders of magnitude below 'paper'."}],
}
N_TRIALS = 1000


def _published_items() -> list[dict]:
    items = []
    for table, q, sensor, rows in PAPER_TABLES:
        for m, (value, err) in rows.items():
            kind = "exact" if sensor == "ideal" else "statistical"
            items.append(
                {
                    "id": f"T{table}.{SHORT[q]}.{m}",
                    "label": f"Table {table}",
                    "quantity": q,
                    "select": {"method": m, "sensor": sensor},
                    "value": value,
                    "error_pct": err,
                    "unit": UNIT[q],
                    "kind": kind,
                }
            )
    # Tables 1-4 also print an all-zero "ideal" column
    for table, q, _, rows in PAPER_TABLES[:4]:
        for m in rows:
            items.append(
                {
                    "id": f"T{table}.{SHORT[q]}.{m}.ideal",
                    "label": f"Table {table}",
                    "quantity": q,
                    "select": {"method": m, "sensor": "ideal"},
                    "value": None,  # the ideal column prints only "0 %"
                    "error_pct": "0",
                    "unit": UNIT[q],
                    "kind": "exact",
                }
            )
    return items


def _pairs() -> pd.DataFrame:
    """(method, quantity, truth, published real % error or a made-up one)."""
    pub = {
        (m, q): float(e)
        for _, q, s, rows in PAPER_TABLES
        if s == "real"
        for m, (_, e) in rows.items()
    }
    rows = [
        (m, q, TRUTH[q], pub.get((m, q), 1e-3)) for m, qs in METHOD_QUANTITIES.items() for q in qs
    ]
    return pd.DataFrame(rows, columns=["method", "quantity", "truth", "pub_pct"])


def make_inputs(root: Path, seed: int = 20230101, *, with_optional: bool = True) -> dict[str, Path]:
    """Write a complete synthetic input tree under ``root``; return its paths."""
    rng = np.random.default_rng(seed)
    results = root / "results" / "north_finding"
    scen_cfg = root / "config" / "scenarios" / "north_finding"
    published = root / "config" / "published" / "north_finding.yaml"
    for d in (results, scen_cfg, published.parent):
        d.mkdir(parents=True, exist_ok=True)

    items = _published_items()
    published.write_text(
        yaml.safe_dump(
            {"paper": "north_finding", "items": items, "claims": CLAIMS},
            sort_keys=False,
            allow_unicode=True,
        ),
        encoding="utf-8",
    )

    ids = [i["id"] for i in items] + [c["id"] for c in CLAIMS]
    kinds = [i["kind"] for i in items] + ["claim"] * len(CLAIMS)
    verdict_by_kind = {
        "exact": ["reproduced", "not_reproduced"],
        "statistical": ["consistent", "not_reproduced"],
        "claim": ["upheld", "not_upheld", "not_checkable"],
    }
    verdict = [str(rng.choice(verdict_by_kind[k])) for k in kinds]
    ids.append("T99.orphan.L1")  # a verdict with no published item
    kinds.append("exact")
    verdict.append("reproduced")
    pd.DataFrame(
        {
            "id": ids,
            "kind": kinds,
            "quantity": [i.split(".")[1] for i in ids],
            "method": [i.split(".")[2] if i.startswith("T") else "" for i in ids],
            "published": ["x"] * len(ids),
            "reproduced": [f"{v:.6g}" for v in rng.normal(50, 1, len(ids))],
            "verdict": verdict,
            "note": ["synthetic <note> & 'quotes'"] * len(ids),
        }
    )[VERDICT_COLUMNS].to_csv(results / "verdicts.csv", index=False)

    eqs = [str(e) for e in range(12, 72)] + ["19.a", "19.b", "47.E"]
    status = rng.choice(["match", "match", "match", "differs", "not_checkable"], len(eqs))
    pd.DataFrame(
        {
            "equation": eqs,
            "status": status,
            "residual": np.where(status == "differs", "g*sin(theta) - g*cos(theta)", "0"),
            "note": np.where(
                status == "differs", "OCR swapped sin and cos (typo of the paper)", ""
            ),
            "kind": np.where(status == "differs", "paper_error", ""),
        }
    )[AUDIT_COLUMNS].to_csv(results / "equation_audit.csv", index=False)

    pairs = _pairs()
    for name, cfg, full in (
        ("paper", SCENARIO_PAPER, with_optional),
        ("low_avg", SCENARIO_LOW, False),
    ):
        (scen_cfg / f"{name}.yaml").write_text(
            yaml.safe_dump(cfg, sort_keys=False), encoding="utf-8"
        )
        d = results / name
        d.mkdir(exist_ok=True)
        sign = rng.choice([-1.0, 1.0], len(pairs))
        real_pct = sign * pairs["pub_pct"].to_numpy() * rng.uniform(0.3, 1.5, len(pairs))
        est = pd.concat(
            [
                pairs.assign(sensor="ideal", estimate=pairs["truth"], error_pct=0.0),
                pairs.assign(
                    sensor="real",
                    estimate=pairs["truth"] * (1 + real_pct / 100),
                    error_pct=real_pct,
                ),
            ]
        ).assign(scan_bound_deg=np.nan, flag="")
        est[ESTIMATE_COLUMNS].to_csv(d / "estimates.csv", index=False)
        # Monte Carlo: trials are an array axis (no Python loop)
        k = len(pairs)
        err = real_pct[None, :] + pairs["pub_pct"].to_numpy()[None, :] * rng.standard_normal(
            (N_TRIALS, k)
        )
        trials = pd.DataFrame(
            {
                "trial": np.repeat(np.arange(N_TRIALS), k),
                "method": np.tile(pairs["method"].to_numpy(), N_TRIALS),
                "quantity": np.tile(pairs["quantity"].to_numpy(), N_TRIALS),
                "truth": np.tile(pairs["truth"].to_numpy(), N_TRIALS),
                "error_pct": err.ravel(),
            }
        )
        trials["estimate"] = trials["truth"] * (1 + trials["error_pct"] / 100)
        trials[MC_TRIAL_COLUMNS].to_csv(d / "mc_trials.csv", index=False)
        g = trials.groupby(["method", "quantity"], sort=False)["estimate"]
        summ = (
            g.agg(["mean", "std"])
            .join(g.quantile([0.05, 0.5, 0.95]).unstack().set_axis(["p05", "p50", "p95"], axis=1))
            .reset_index()
        )
        summ = summ.merge(pairs[["method", "quantity", "truth"]]).assign(n_trials=N_TRIALS)
        summ[MC_SUMMARY_COLUMNS].to_csv(d / "mc_summary.csv", index=False)
        eb = pairs.merge(pd.DataFrame({"source": list(ERROR_SOURCES)}), how="cross")
        eb["error_pct"] = rng.normal(0, 1, len(eb)) * eb["pub_pct"]
        eb["error"] = eb["error_pct"] / 100 * eb["truth"]
        eb[ERROR_BUDGET_COLUMNS].to_csv(d / "error_budget.csv", index=False)
        if full:
            n_avg = np.logspace(2, 8, 13)
            az = pairs[pairs["quantity"] == "psi_deg"]
            sens = az.merge(pd.DataFrame({"n_avg": n_avg}), how="cross")
            sens["rms_error_pct"] = (
                sens["pub_pct"] * np.sqrt(1e6 / sens["n_avg"]) * 1.3 + 0.3 * sens["pub_pct"]
            )
            sens["rms_error"] = sens["rms_error_pct"] / 100 * sens["truth"]
            sens["n_trials"] = 200
            sens[SENSITIVITY_COLUMNS].to_csv(d / "sensitivity.csv", index=False)
            (d / "provenance.json").write_text(
                json.dumps(
                    {
                        "git_describe": "v0.1-3-gabc1234",
                        "config_sha256": "ab" * 32,
                        "packages": {"numpy": "2.4.6", "pandas": "3.1.1"},
                        "seed": seed,
                        "scenario": name,
                        "created_by": "pipeline.north_finding.simulate",
                        "n_avg": 1000000,
                    },
                    indent=1,
                ),
                encoding="utf-8",
            )
    if with_optional:
        bench = results / "benchmarks"
        bench.mkdir(exist_ok=True)
        for rule, s in (("simulate_paper", 12.5), ("figures", 3.25)):
            (bench / f"{rule}.tsv").write_text(
                "s\th:m:s\tmax_rss\tmax_vms\tmax_uss\tmax_pss\tio_in\tio_out\tmean_load\tcpu_time\n"
                f"{s}\t0:00:{s:05.2f}\t512.3\t900.1\t500.0\t505.0\t1.0\t2.0\t95.0\t{s}\n",
                encoding="utf-8",
            )
    return {
        "root": root,
        "results": results,
        "scenarios": scen_cfg,
        "published": published,
        "figures": results / "figures",
        "out": root / "reports" / "north_finding.html",
    }


# --------------------------------------------------------------------------- helpers

VOID = {
    "area",
    "base",
    "br",
    "col",
    "embed",
    "hr",
    "img",
    "input",
    "link",
    "meta",
    "source",
    "track",
    "wbr",
}


class StrictParser(HTMLParser):
    """Collects tags/attributes and records structural errors (mismatched or
    unclosed tags), which html.parser itself tolerates silently."""

    def __init__(self) -> None:
        super().__init__(convert_charrefs=True)
        self.stack: list[str] = []
        self.errors: list[str] = []
        self.starts: list[tuple[str, dict[str, str | None]]] = []
        self.spans: list[tuple[dict[str, str | None], str]] = []
        self._span: dict[str, str | None] | None = None
        self._text: list[str] = []

    def handle_starttag(self, tag, attrs):
        a = dict(attrs)
        self.starts.append((tag, a))
        if tag not in VOID:
            self.stack.append(tag)
        if tag == "span":
            self._span, self._text = a, []

    def handle_startendtag(self, tag, attrs):
        self.starts.append((tag, dict(attrs)))

    def handle_endtag(self, tag):
        if tag in VOID:
            return
        if not self.stack or self.stack[-1] != tag:
            self.errors.append(
                f"</{tag}> closes <{self.stack[-1] if self.stack else None}> at {self.getpos()}"
            )
            if tag in self.stack:
                while self.stack and self.stack.pop() != tag:
                    pass
            return
        self.stack.pop()
        if tag == "span" and self._span is not None:
            self.spans.append((self._span, "".join(self._text)))
            self._span = None

    def handle_data(self, data):
        if self._span is not None:
            self._text.append(data)

    def close(self):
        super().close()
        if self.stack:
            self.errors.append(f"unclosed tags at end: {self.stack}")


def parse(text: str) -> StrictParser:
    p = StrictParser()
    p.feed(text)
    p.close()
    return p


def png_size(path: Path) -> tuple[int, int]:
    data = path.read_bytes()
    assert data[:8] == b"\x89PNG\r\n\x1a\n", f"{path} is not a PNG"
    assert data[12:16] == b"IHDR"
    assert data.rstrip(b"\x00")[-8:-4] == b"IEND" or b"IEND" in data[-12:], (
        f"{path} has no IEND chunk"
    )
    return struct.unpack(">II", data[16:24])


@pytest.fixture(scope="module")
def built(tmp_path_factory) -> dict[str, Path]:
    paths = make_inputs(tmp_path_factory.mktemp("nf"))
    F.run(paths["results"] / "paper", paths["published"], paths["figures"])
    R.build_page(paths["results"], paths["scenarios"], paths["published"], paths["out"])
    return paths


# --------------------------------------------------------------------------- figures


def test_every_figure_is_a_reasonable_png_and_svg(built):
    for stem in FIGURE_FILES:
        png, svg = built["figures"] / f"{stem}.png", built["figures"] / f"{stem}.svg"
        w, h = png_size(png)
        assert 600 <= w <= 3000 and 400 <= h <= 2000, (stem, w, h)
        assert 15_000 < png.stat().st_size < 2_000_000, (stem, png.stat().st_size)
        assert svg.read_text(encoding="utf-8").lstrip().startswith("<?xml"), stem
    assert not list(built["figures"].glob(".*.tmp")), "temporary files left behind"


def test_figures_are_byte_identical_on_rerun(built, tmp_path):
    F.run(built["results"] / "paper", built["published"], tmp_path)
    for stem in FIGURE_FILES:
        for ext in ("png", "svg"):
            a, b = built["figures"] / f"{stem}.{ext}", tmp_path / f"{stem}.{ext}"
            assert a.read_bytes() == b.read_bytes(), f"{stem}.{ext} differs between runs"


def test_cli_output_does_not_depend_on_hash_seed(built, tmp_path):
    """Layout solvers can depend on set order; run the CLI in a fresh process
    with another PYTHONHASHSEED and compare bytes with the in-process run."""
    repo = Path(__file__).resolve().parents[2]
    env = {**os.environ, "PYTHONHASHSEED": "12345", "PYTHONPATH": str(repo)}
    cmd = [
        sys.executable,
        "-m",
        "pipeline.north_finding.figures",
        "--scenario-dir",
        str(built["results"] / "paper"),
        "--published",
        str(built["published"]),
        "--out-dir",
        str(tmp_path),
    ]
    proc = subprocess.run(
        cmd, cwd=repo, env=env, capture_output=True, text=True, timeout=HANG_GUARD_S
    )
    assert proc.returncode == 0, proc.stderr
    for stem in FIGURE_FILES:
        for ext in ("png", "svg"):
            a, b = built["figures"] / f"{stem}.{ext}", tmp_path / f"{stem}.{ext}"
            assert a.read_bytes() == b.read_bytes(), f"{stem}.{ext} depends on PYTHONHASHSEED"


def test_abs_error_quantiles_match_numpy():
    rng = np.random.default_rng(1)
    err = rng.normal(0.01, 0.02, 500)
    trials = pd.DataFrame(
        {
            "trial": np.arange(500),
            "method": "L1",
            "quantity": "phi_deg",
            "truth": 50.0,
            "estimate": 50 * (1 + err / 100),
            "error_pct": err,
        }
    )
    q = abs_error_quantiles(trials).loc[("L1", "phi_deg")]
    np.testing.assert_allclose(
        q[["p05", "p50", "p95"]].to_numpy(float), np.quantile(np.abs(err), [0.05, 0.5, 0.95])
    )
    assert q["n"] == 500


def test_published_error_pct_reads_the_yaml(built):
    items, claims = load_published(built["published"])
    pub = published_error_pct(items, "real")
    assert pub[("L4", "phi_deg")] == pytest.approx(0.145)
    assert pub[("A3", "psi_deg")] == pytest.approx(0.502)
    assert ("A1c1", "psi_deg") in pub.index and len(claims) == len(CLAIMS)
    assert (
        canonical_quantity("phi") == "phi_deg"
        and canonical_quantity("gyro_bias") == "gyro_bias_rad_s"
    )


def test_figures_render_without_sensitivity_or_provenance(tmp_path):
    paths = make_inputs(tmp_path, with_optional=False)
    written = F.run(paths["results"] / "paper", paths["published"], paths["figures"])
    assert {p.name for p in written} == {f"{s}.{e}" for s in FIGURE_FILES for e in ("png", "svg")}


def test_figures_step_checks_its_declared_outputs(built, tmp_path):
    """The workflow's figures step writes every figure and refuses a declaration that differs."""
    out = tmp_path / "figures"
    outputs = {
        "png": [str(out / f"{s}.png") for s in FIGURE_FILES],
        "svg": [str(out / f"{s}.svg") for s in FIGURE_FILES],
    }
    inputs = {
        "mc_trials": str(built["results"] / "paper" / "mc_trials.csv"),
        "published": str(built["published"]),
    }
    F.figures_step(inputs, outputs, {}, print)
    for stem in FIGURE_FILES:
        assert (out / f"{stem}.png").read_bytes() == (built["figures"] / f"{stem}.png").read_bytes()
    outputs["svg"].pop()  # the sensitivity SVG is written but no longer declared
    with pytest.raises(ValueError, match="declares"):
        F.figures_step(inputs, outputs, {}, print)


# --------------------------------------------------------------------------- page


def test_page_is_well_formed_and_self_contained(built):
    text = built["out"].read_text(encoding="utf-8")
    p = parse(text)
    assert p.errors == []
    imgs = [a for t, a in p.starts if t == "img"]
    assert len(imgs) == len(FIGURE_FILES)
    for a in imgs:
        assert (a.get("src") or "").startswith("data:image/png;base64,"), a.get("src", "")[:40]
    for t, a in p.starts:
        for attr in ("src", "href"):
            v = (a.get(attr) or "").strip().lower()
            assert not re.match(r"^(https?:|//|ftp:)", v), (t, attr, v[:60])
        assert t not in ("script", "link", "iframe"), t
    stripped = re.sub(r'src="data:[^"]*"', "", text)
    assert "http://" not in stripped and "https://" not in stripped


def test_one_section_per_published_table(built):
    items, _ = load_published(built["published"])
    expected = {f"table-{int(n)}" for n in items["table_no"].dropna().unique()}
    assert len(expected) == 12
    p = parse(built["out"].read_text(encoding="utf-8"))
    found = Counter(
        a.get("id")
        for t, a in p.starts
        if t == "section" and re.fullmatch(r"table-\d+", a.get("id") or "")
    )
    assert set(found) == expected and all(v == 1 for v in found.values()), found
    # every published id appears in the page
    text = built["out"].read_text(encoding="utf-8")
    missing = [i for i in items["id"] if f"<td>{H.escape(i)}</td>" not in text]
    assert missing == []


def test_summary_counts_equal_fixture_counts(built):
    verdicts = pd.read_csv(built["results"] / "verdicts.csv")
    audit = pd.read_csv(built["results"] / "equation_audit.csv", dtype=str)
    expected_v = Counter(verdicts["verdict"])
    expected_a = Counter(audit["status"])
    rep = R.report(
        ReportInputs(built["results"], built["scenarios"], built["published"], built["figures"])
    )
    blocks = rep.section("summary").blocks
    text = blocks[0].text
    m = re.search(r"verdicts\.csv has \d+ verdicts: (.*?)\. The equation audit", text)
    shown_v = {w.replace(" ", "_"): int(n) for n, w in re.findall(r"(\d+) ([a-z ]+)", m.group(1))}
    m = re.search(r"the SymPy derivation: (.*?)\. Where", text)
    shown_a = {w.replace(" ", "_"): int(n) for n, w in re.findall(r"(\d+) ([a-z ]+)", m.group(1))}
    assert set(shown_v) >= set(VERDICTS)
    # the verdicts-by-kind table counts the same rows
    (by_kind,) = [b for b in blocks if isinstance(b, Table)]
    assert {r[0]: sum(int(c) for c in r[1:]) for r in by_kind.rows if r[0]} == {
        k: v for k, v in shown_v.items() if v
    }
    # one vocabulary: the page shows the word, never the CSV's token
    page = built["out"].read_text(encoding="utf-8")
    assert '<span class="v-not_reproduced t-bad">not reproduced</span>' in page
    assert ">not_reproduced<" not in page
    assert {k: v for k, v in shown_v.items() if v} == dict(expected_v)
    assert {k: v for k, v in shown_a.items() if v} == dict(expected_a)
    assert sum(shown_v.values()) == len(verdicts)


def test_differs_rows_are_highlighted_with_notes(built):
    text = built["out"].read_text(encoding="utf-8")
    audit = pd.read_csv(built["results"] / "equation_audit.csv", dtype=str)
    n_differs = int((audit["status"] == "differs").sum())
    assert n_differs > 0
    assert text.count('<tr class="v-differs">') == n_differs
    assert "OCR swapped sin and cos" in text
    assert "&lt;note&gt;" in text and "<note>" not in text  # notes are escaped


def test_assumptions_show_resolved_values(built):
    text = built["out"].read_text(encoding="utf-8")
    # values as the config writes them (not reformatted as numbers: 1000000, not 1e+06)
    assert '<td>noise.n_avg</td><td class="num">1000000</td>' in text
    assert "<td>misalignment.rows.0</td><td>0.0, 10.0, -10.0</td>" in text  # plain, no JSON
    assert '<td>noise.n_avg</td><td class="num">1000</td>' in text  # low_avg scenario


def test_optional_inputs_absent_say_not_available(tmp_path):
    paths = make_inputs(tmp_path, with_optional=False)
    out = R.build_page(paths["results"], paths["scenarios"], paths["published"], paths["out"])
    text = out.read_text(encoding="utf-8")
    assert parse(text).errors == []
    assert "sensitivity.csv: not available" in text
    assert "Fig. 1 (fig1_roll.png): not available." in text  # figures not built


def test_page_is_deterministic(built, tmp_path):
    out = R.build_page(
        built["results"], built["scenarios"], built["published"], tmp_path / "page.html"
    )
    assert out.read_bytes() == built["out"].read_bytes()


def test_published_cells_and_claims(built):
    text = built["out"].read_text(encoding="utf-8")
    assert "<td>50.0050 deg (0.0110 %)</td>" in text
    assert "<td>0 % error</td>" in text  # ideal column: no value printed
    assert "within 20 % of each other" in text  # the claim's reading
    assert "rel_tol = 0.2" in text and "&quot;rel_tol&quot;" not in text  # a sentence, no JSON


def test_provenance_shown_and_timings_left_to_the_benchmark_files(built):
    text = built["out"].read_text(encoding="utf-8")
    assert "simulate_paper" not in text and "0:00:12.50" not in text  # benchmark rows absent
    assert "benchmark files results/north_finding/benchmarks/*.tsv" in text
    assert "benchmark files" in TIMINGS_NOTE
    assert "v0.1-3-gabc1234" in text


def test_missing_decision_field_raises_naming_file_and_field(tmp_path):
    paths = make_inputs(tmp_path, with_optional=False)
    bad = dict(
        SCENARIO_LOW,
        decisions=[{"field": "noise.samples_per_position", "text": "typo in the path"}],
    )
    cfg = paths["scenarios"] / "broken.yaml"
    cfg.write_text(yaml.safe_dump(bad), encoding="utf-8")
    with pytest.raises(ValueError) as exc:
        R.build_page(paths["results"], paths["scenarios"], paths["published"], paths["out"])
    msg = str(exc.value)
    assert "broken.yaml" in msg and "noise.samples_per_position" in msg
    assert not paths["out"].exists()  # nothing half-written


def test_resolve_dotted_indexes_lists_and_rejects_missing():
    data = {"a": {"b": [10, {"c": 3}]}}
    assert resolve_dotted(data, "a.b.1.c") == 3
    assert resolve_dotted(data, "a.b.0") == 10
    for bad in ("a.x", "a.b.2", "a.b.0.c", "z"):
        with pytest.raises(ValueError, match=re.escape(bad)):
            resolve_dotted(data, bad, source="s.yaml")


def test_html_helpers():
    from pipeline.report.blocks_html import render_block
    from pipeline.report.model import Figure, frame_table

    df = pd.DataFrame({"id": ["a<b"], "x": [0.1 + 0.2], "verdict": ["not_reproduced"]})
    t = render_block(frame_table(df, status="verdict"), status_rows=True)
    assert '<tr class="v-not_reproduced">' in t and "a&lt;b" in t and "0.3<" in t
    assert parse(t).errors == []
    with pytest.raises(ValueError):
        H.png_data_uri(b"GIF89a")
    missing = render_block(Figure("/nonexistent/f.png", "c", "Fig. 1"))
    assert missing.count("not available") == 1 and "<img" not in missing


def test_tolerance_and_reason_shown_where_verdicts_csv_has_them(built, tmp_path):
    results = tmp_path / "results"
    shutil.copytree(built["results"], results)
    v = pd.read_csv(results / "verdicts.csv", dtype=str, keep_default_na=False)
    v = v.assign(tolerance=[f"tol {i}" for i in range(len(v))], reason="a reason")
    v.to_csv(results / "verdicts.csv", index=False)
    out = R.build_page(results, built["scenarios"], built["published"], tmp_path / "p.html")
    text = out.read_text(encoding="utf-8")
    assert "<th>tolerance</th><th>reason</th>" in text
    assert "<td>tol 0</td><td>a reason</td>" in text
    # without them the template's tables still name the tolerance column, the paper's do not
    assert "<th>tolerance</th><th>reason</th>" not in built["out"].read_text(encoding="utf-8")


def test_a_claim_judged_at_several_n_shows_one_row_per_n():
    """Claim rows ``<claim id>/N=...`` are the claim's rows (not orphans); a claim without a
    verdict row shows once as missing; the claim's own note is its reading."""
    from pipeline.north_finding.report import _claim_rows

    claims = pd.DataFrame(
        [
            {"id": "C1", "text": "t1", "source": "s", "note": "reading", "predicate": {}},
            {"id": "C2", "text": "t2", "source": "s", "note": None, "predicate": {}},
        ]
    )
    verdicts = pd.DataFrame(
        {
            "id": ["C1/N=1", "C1/noise-free", "C10"],
            "verdict": ["not_upheld", "upheld", "upheld"],
            "reproduced": ["a", "b", "c"],
            "note": ["n1", "n2", "n3"],
        }
    )
    rows = _claim_rows(claims, verdicts)
    assert list(rows["id"]) == ["C1/N=1", "C1/noise-free", "C2"]
    assert list(rows["verdict"]) == ["not_upheld", "upheld", "missing"]
    assert list(rows["note"])[:2] == ["n1", "n2"] and rows["note_claim"].iloc[0] == "reading"
