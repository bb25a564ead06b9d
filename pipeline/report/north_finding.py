"""HTML report of the north-finding reproduction (one self-contained page).

Reads the results contract (``results/north_finding/``), the published values
(``config/published/north_finding.yaml``), the scenario configs
(``config/scenarios/north_finding/*.yaml``) and the figures written by
:mod:`pipeline.north_finding.figures`, and writes ``reports/north_finding.html``.

Required: the published YAML, ``verdicts.csv`` and ``equation_audit.csv``.
Everything else (scenario result files, figures, sensitivity, provenance,
benchmarks, scenario configs) is optional and shown as "not available" when
absent. A scenario decision whose dotted ``field`` does not exist in its YAML is
an error (``ValueError`` naming the file and the field).

CLI::

    python -m pipeline.report.north_finding --results-dir results/north_finding \\
        --scenarios-dir config/scenarios/north_finding \\
        --published config/published/north_finding.yaml --out reports/north_finding.html
"""

# No `from __future__ import annotations`: Snakemake's script: directive prepends a
# preamble, after which a __future__ import would be a SyntaxError.
if "snakemake" in globals():  # run by Snakemake's script: directive from the repo root
    import os as _os
    import sys as _sys

    _sys.path.insert(0, _os.getcwd())

import argparse
import json
import re
from collections.abc import Mapping, Sequence
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd
import yaml

from pipeline.columns import AUDIT_COLUMNS, AUDIT_STATUSES, VERDICT_COLUMNS, VERDICT_KINDS, VERDICTS
from pipeline.north_finding.columns import (
    AZIMUTH_METHODS,
    ERROR_BUDGET_COLUMNS,
    ERROR_SOURCES,
    ESTIMATE_COLUMNS,
    MC_SUMMARY_COLUMNS,
    MC_TRIAL_COLUMNS,
    METHODS,
    QUANTITIES,
    SENSITIVITY_COLUMNS,
    SENSORS,
)
from pipeline.north_finding.figures import FIGURE_FILES, load_published
from pipeline.north_finding.paper import CITATION as PAPER_CITATION
from pipeline.north_finding.paper import FIGURE_CAPTIONS
from pipeline.north_finding.paper import TITLE as PAPER_TITLE
from pipeline.report import html as H

__all__ = [
    "FIGURE_CAPTIONS",
    "QUANTITY_LABELS",
    "audit_counts",
    "build_page",
    "discover_scenarios",
    "load_decisions",
    "main",
    "render_page",
    "resolve_dotted",
    "run_from_snakemake",
    "verdict_counts",
]

SLUG = "north_finding"
QUANTITY_LABELS: dict[str, str] = {
    "phi_deg": "roll φ (deg)",
    "theta_deg": "pitch θ (deg)",
    "psi_deg": "azimuth ψ (deg)",
    "acc_bias_ug": "accelerometer bias (µg)",
    "acc_scale": "accelerometer scale factor S",
    "acc_scale_approx": "accelerometer scale factor S (first-order approx.)",
    "gyro_bias_rad_s": "gyro bias (rad/s)",
    "gyro_scale": "gyro scale factor S",
    "gyro_scale_approx": "gyro scale factor S (first-order approx.)",
}

_UNITLESS = {"", "1", "-", "none", "dimensionless"}
_NON_SCENARIO_DIRS = {"figures", "benchmarks", "logs", "log"}
_SCENARIO_FILES = (
    "estimates.csv",
    "mc_summary.csv",
    "mc_trials.csv",
    "error_budget.csv",
    "provenance.json",
)


# --------------------------------------------------------------------------- small readers


def _read_csv(path: Path, columns: Sequence[str], *, as_text: bool = False) -> pd.DataFrame | None:
    """CSV with the required ``columns``; ``None`` if the file is absent.
    ``as_text`` keeps every cell as printed (strings, empty cells as "")."""
    if not path.is_file():
        return None
    df = pd.read_csv(path, dtype=str, keep_default_na=False) if as_text else pd.read_csv(path)
    missing = [c for c in columns if c not in df.columns]
    if missing:
        raise ValueError(f"{path}: missing columns {missing} (has {list(df.columns)})")
    return df


def _require(df: pd.DataFrame | None, path: Path) -> pd.DataFrame:
    if df is None:
        raise FileNotFoundError(f"{path}: required input is missing")
    return df


def _order_key(values: pd.Series, order: Sequence[str]) -> pd.Series:
    """Sort key: position in ``order``, unknown values after it."""
    pos = {v: i for i, v in enumerate(order)}
    return values.astype(str).map(lambda v: pos.get(v, len(order)))


def _sorted(df: pd.DataFrame) -> pd.DataFrame:
    keys: list[str] = []
    tmp = df.copy()
    if "method" in tmp.columns:
        tmp["_m"] = _order_key(tmp["method"], METHODS)
        keys += ["_m", "method"]
    if "quantity" in tmp.columns:
        tmp["_q"] = _order_key(tmp["quantity"], QUANTITIES)
        keys += ["_q", "quantity"]
    if not keys:
        return df
    return tmp.sort_values(keys, kind="stable").drop(
        columns=[k for k in ("_m", "_q") if k in tmp.columns]
    )


def _equation_key(eq: pd.Series) -> pd.Series:
    """Natural order of equation numbers: 9 < 17 < 19.a < 19.b < 20."""
    m = eq.astype(str).str.extract(r"^\s*(\d+)(.*)$")
    num = pd.to_numeric(m[0], errors="coerce").fillna(np.inf)
    return num.astype(float).map(lambda v: f"{v:012.0f}" if np.isfinite(v) else "~") + m[1].fillna(
        eq.astype(str)
    )


# --------------------------------------------------------------------------- counts


def verdict_counts(verdicts: pd.DataFrame) -> pd.Series:
    """Rows of ``verdicts.csv`` per verdict: every word of ``VERDICTS`` (zeros
    included, in that order), then any other word found (a producer bug)."""
    counts = verdicts["verdict"].astype(str).value_counts()
    extra = sorted(set(counts.index) - set(VERDICTS))
    return counts.reindex(list(VERDICTS) + extra, fill_value=0).astype(int)


def audit_counts(audit: pd.DataFrame) -> pd.Series:
    """Rows of ``equation_audit.csv`` per status (``AUDIT_STATUSES`` first, zeros included)."""
    counts = audit["status"].astype(str).value_counts()
    extra = sorted(set(counts.index) - set(AUDIT_STATUSES))
    return counts.reindex(list(AUDIT_STATUSES) + extra, fill_value=0).astype(int)


# --------------------------------------------------------------------------- scenario configs


def resolve_dotted(data: Any, field: str, *, source: str | Path = "<config>") -> Any:
    """Value at a dotted path (``"noise.n_avg"``, list items by index:
    ``"misalignment.rows.0"``). Raises ``ValueError`` naming ``source`` and
    ``field`` if any part is missing."""
    node = data
    done: list[str] = []
    for part in str(field).split("."):
        if isinstance(node, Mapping) and part in node:
            node = node[part]
        elif (
            isinstance(node, list)
            and re.fullmatch(r"-?\d+", part)
            and -len(node) <= int(part) < len(node)
        ):
            node = node[int(part)]
        else:
            where = ".".join(done) or "<top level>"
            raise ValueError(
                f"{source}: decision field '{field}' not found ('{part}' is missing under {where})"
            )
        done.append(part)
    return node


def _render_value(value: Any) -> str:
    """A config value as text: strings as they are, everything else as JSON
    (``5.0`` stays ``5.0``, ``True`` -> ``true``, mappings and lists compact)."""
    if isinstance(value, str):
        return value
    return json.dumps(value, ensure_ascii=False, default=str)


def load_decisions(path: str | Path) -> tuple[str, pd.DataFrame]:
    """``(description, decisions)`` of one scenario YAML; decisions has columns
    ``field, value, why`` with the value resolved at the dotted ``field``."""
    path = Path(path)
    with path.open(encoding="utf-8") as fh:
        data = yaml.safe_load(fh) or {}
    if not isinstance(data, Mapping):
        raise ValueError(f"{path}: a scenario config must be a mapping")
    description = str(data.get("description") or "").strip()
    raw = data.get("decisions") or []
    if not isinstance(raw, list):
        raise ValueError(f"{path}: 'decisions' must be a list of {{field, text}}")
    rows = []
    for i, d in enumerate(raw):
        if not isinstance(d, Mapping) or "field" not in d or "text" not in d:
            raise ValueError(f"{path}: decisions[{i}] needs 'field' and 'text' (got {d!r})")
        value = resolve_dotted(data, str(d["field"]), source=path)
        rows.append(
            {"field": str(d["field"]), "value": _render_value(value), "why": str(d["text"]).strip()}
        )
    return description, pd.DataFrame(rows, columns=["field", "value", "why"])


def discover_scenarios(results_dir: str | Path) -> list[Path]:
    """Scenario result directories under ``results_dir`` (those holding any
    scenario result file); ``paper`` first, then alphabetical."""
    results_dir = Path(results_dir)
    if not results_dir.is_dir():
        return []
    dirs = [
        d
        for d in results_dir.iterdir()
        if d.is_dir()
        and d.name not in _NON_SCENARIO_DIRS
        and any((d / f).is_file() for f in _SCENARIO_FILES)
    ]
    return sorted(dirs, key=lambda d: (d.name != "paper", d.name))


# --------------------------------------------------------------------------- sections


def _count_span(attr: str, word: str, n: int) -> str:
    """``<span data-{attr}=word>n</span> word``: machine-readable counts in the summary."""
    return (
        f'<span class="count {H.css_class(word)}" data-{attr}="{H.escape(word)}">{int(n)}</span> '
        f"{H.escape(word.replace('_', ' '))}"
    )


def _summary(
    items: pd.DataFrame, claims: pd.DataFrame, verdicts: pd.DataFrame, audit: pd.DataFrame
) -> str:
    vc, ac = verdict_counts(verdicts), audit_counts(audit)
    vparts = ", ".join(_count_span("verdict", v, n) for v, n in vc.items())
    aparts = ", ".join(_count_span("status", s, n) for s, n in ac.items())
    n_tables = int(items["table_no"].dropna().nunique())
    text = (
        f"This page puts every published number and claim of “{H.escape(PAPER_TITLE)}” "
        f"({H.escape(PAPER_CITATION)}) beside what this project derived and computed. "
        f"The published values file lists {len(items)} numbers from {n_tables} tables "
        f"and {len(claims)} claims; "
        f"<code>verdicts.csv</code> has {len(verdicts)} verdicts: {vparts}. "
        f"The equation audit checked {len(audit)} printed equations against the SymPy "
        f"derivation: {aparts}. "
        "Where a printed equation differs, the pipeline uses the derived one. Verdict rules: "
        "<em>exact</em> (ideal sensor, equal to the printed precision), "
        "<em>statistical</em> (where the published "
        "value falls in the Monte Carlo distribution), <em>claim</em> (a predicate over results)."
    )
    extra = [v for v in vc.index if v not in VERDICTS]
    warn = ""
    if extra:
        warn = H.paragraph(f"Unknown verdict words in verdicts.csv: {', '.join(extra)}.", cls="na")
    crosstab = pd.crosstab(verdicts["verdict"], verdicts["kind"])
    order = [v for v in VERDICTS if v in crosstab.index] + sorted(
        set(crosstab.index) - set(VERDICTS)
    )
    kinds = [k for k in VERDICT_KINDS if k in crosstab.columns] + sorted(
        set(crosstab.columns) - set(VERDICT_KINDS)
    )
    crosstab = crosstab.loc[order, kinds].reset_index()
    crosstab.columns.name = None
    return (
        f'<p class="summary">{text}</p>\n'
        + warn
        + H.table(crosstab, class_column="verdict", caption="Verdicts by kind")
    )


def _audit_section(audit: pd.DataFrame) -> str:
    audit = (
        audit.assign(_k=_equation_key(audit["equation"]))
        .sort_values("_k", kind="stable")
        .drop(columns="_k")
    )
    differs = audit[audit["status"] == "differs"]
    body = ""
    if len(differs):
        lis = "".join(
            f"<li><strong>Eq. {H.escape(r.equation)}</strong>: {H.escape(r.note) or 'no note'} "
            f"(residual <code>{H.escape(r.residual)}</code>)</li>\n"
            for r in differs.itertuples()
        )
        body += (
            H.paragraph(
                "Printed equations that differ from the derivation "
                "(the pipeline uses the derived form):"
            )
            + f'<ul class="differs">\n{lis}</ul>\n'
        )
    else:
        body += H.paragraph("No printed equation differs from the derivation.")
    body += H.table(
        audit[AUDIT_COLUMNS], class_column="status", caption="Equation audit (equation_audit.csv)"
    )
    return body


def _table_heading(n: int, rows: pd.DataFrame) -> str:
    quantities = ", ".join(
        dict.fromkeys(QUANTITY_LABELS.get(str(q), str(q)) for q in rows["quantity"])
    )
    sensors = [str(s) for s in dict.fromkeys(rows["sensor"]) if s]
    return f"Table {n} — {quantities}" + (f"; {' and '.join(sensors)} sensor" if sensors else "")


def _published_cell(items: pd.DataFrame) -> pd.Series:
    """``value unit (error %)`` as printed; ``error %`` alone where the paper prints no value."""

    def cell(value: Any, unit: Any, err: Any) -> str:
        has_value = value is not None and not pd.isna(value) and str(value) != ""
        has_err = err is not None and not pd.isna(err) and str(err) != ""
        unitless = unit is None or pd.isna(unit) or str(unit).lower() in _UNITLESS
        unit_s = "" if unitless else f" {unit}"
        if has_value:
            return f"{value}{unit_s}" + (f" ({err} %)" if has_err else "")
        return f"{err} % error" if has_err else ""

    cells = [cell(*t) for t in zip(items["value"], items["unit"], items["error_pct"], strict=True)]
    return pd.Series(cells, index=items.index, dtype=object)


def _tables_section(items: pd.DataFrame, verdicts: pd.DataFrame) -> str:
    v = verdicts.drop_duplicates("id", keep="first").set_index("id")
    joined = items.assign(
        published=_published_cell(items),
        reproduced=items["id"].map(v["reproduced"]).fillna(""),
        verdict=items["id"].map(v["verdict"]).fillna("missing"),
        note=items["id"].map(v["note"]).fillna("no verdict in verdicts.csv"),
        sensor=items["sensor"].fillna(""),
    )
    cols = ["id", "method", "sensor", "published", "reproduced", "verdict", "note"]
    body = H.paragraph(
        "Published: the value as printed, with the printed percent error in parentheses. "
        "Reproduced and verdict: from verdicts.csv. “missing”: the published item has no verdict."
    )
    for n, rows in joined[joined["table_no"].notna()].groupby("table_no", sort=True):
        n = int(n)
        body += H.section(
            _table_heading(n, rows),
            H.table(rows[cols], class_column="verdict"),
            anchor=f"table-{n}",
            level=3,
        )
    other = joined[joined["table_no"].isna()]
    if len(other):
        body += H.section(
            "Published items outside Tables 1–12",
            H.table(other[cols], class_column="verdict"),
            anchor="table-other",
            level=3,
        )
    return body


def _claims_section(claims: pd.DataFrame, items: pd.DataFrame, verdicts: pd.DataFrame) -> str:
    v = verdicts.drop_duplicates("id", keep="first").set_index("id")
    body = ""
    if len(claims):
        reading = (
            claims["note"] if "note" in claims.columns else pd.Series(None, index=claims.index)
        )
        c = claims.assign(
            predicate=claims["predicate"].map(_render_value),
            reading=reading.map(lambda x: "" if x is None or pd.isna(x) else str(x)),
            verdict=claims["id"].map(v["verdict"]).fillna("missing"),
            reproduced=claims["id"].map(v["reproduced"]).fillna(""),
            note=claims["id"].map(v["note"]).fillna("no verdict in verdicts.csv"),
        )
        cols = ["id", "text", "source", "reading", "predicate", "reproduced", "verdict", "note"]
        if not c["reading"].astype(bool).any():
            cols.remove("reading")
        body += H.paragraph(
            "reading: how this project reads a vague claim; "
            "predicate: the rule the verdict applies."
        ) + H.table(c[cols], class_column="verdict")
    else:
        body += H.not_available("Claims in the published values file")
    known = set(items["id"].astype(str)) | set(claims["id"].astype(str))
    orphans = verdicts[~verdicts["id"].astype(str).isin(known)]
    if len(orphans):
        body += H.section(
            "Verdicts without a published item or claim",
            H.paragraph(
                "These rows of verdicts.csv name an id that the published values file "
                "does not have."
            )
            + H.table(orphans[VERDICT_COLUMNS], class_column="verdict"),
            anchor="orphan-verdicts",
            level=3,
        )
    return body


def _figures_section(figures_dir: Path) -> str:
    body = H.paragraph(f"Figures from {figures_dir.as_posix()} (PNG embedded; SVG beside them).")
    for stem in FIGURE_FILES:
        body += H.figure(
            figures_dir / f"{stem}.png",
            alt=stem,
            caption=FIGURE_CAPTIONS.get(stem, stem),
            anchor=stem.replace("_", "-"),
            missing_text=f"{stem}.png: not available",
        )
    return body


def _estimates_pivot(est: pd.DataFrame, sensor: str) -> pd.DataFrame:
    sel = est[est["sensor"].astype(str) == sensor]
    if sel.empty:
        return pd.DataFrame()
    cell = sel["estimate"].map(lambda x: H.format_value(x, 10)) + sel["error_pct"].map(
        lambda e: "" if pd.isna(e) else f" ({float(e):+.3g} %)"
    )
    sel = sel.assign(cell=cell)
    wide = sel.pivot_table(index="method", columns="quantity", values="cell", aggfunc="first")
    truth = (
        sel.drop_duplicates("quantity")
        .set_index("quantity")["truth"]
        .map(lambda x: H.format_value(x, 10))
    )
    wide = pd.concat([truth.to_frame().T.rename(index={"truth": "truth"}), wide])
    wide.index = ["truth", *wide.index[1:]]
    rows = ["truth"] + sorted(
        wide.index[1:], key=lambda m: (METHODS.index(m) if m in METHODS else len(METHODS), m)
    )
    cols = sorted(
        wide.columns, key=lambda q: (QUANTITIES.index(q) if q in QUANTITIES else len(QUANTITIES), q)
    )
    out = wide.loc[rows, cols].fillna("")
    out.index.name = "method"
    return out.reset_index()


def _scenario_section(d: Path) -> str:
    body = ""
    est = _read_csv(d / "estimates.csv", ESTIMATE_COLUMNS)
    body += "<h4>Estimates (noise-free runs)</h4>\n"
    if est is None:
        body += H.not_available("estimates.csv")
    else:
        body += H.paragraph(
            "Cells: estimate (signed percent error, 100·(estimate − truth)/|truth|)."
        )
        for sensor in SENSORS:
            body += H.table(
                _estimates_pivot(est, sensor), caption=f"{sensor} sensor", empty_text="no rows"
            )
    mcs = _read_csv(d / "mc_summary.csv", MC_SUMMARY_COLUMNS)
    body += "<h4>Monte Carlo summary</h4>\n"
    body += (
        H.not_available("mc_summary.csv")
        if mcs is None
        else H.table(_sorted(mcs)[MC_SUMMARY_COLUMNS])
    )
    trials_path = d / "mc_trials.csv"
    if trials_path.is_file():
        trials = _read_csv(trials_path, MC_TRIAL_COLUMNS)
        assert trials is not None
        body += H.paragraph(
            f"mc_trials.csv: {trials['trial'].nunique()} trials, {len(trials)} rows."
        )
    else:
        body += H.not_available("mc_trials.csv")
    eb = _read_csv(d / "error_budget.csv", ERROR_BUDGET_COLUMNS)
    body += "<h4>Error budget (percent error per error source)</h4>\n"
    if eb is None:
        body += H.not_available("error_budget.csv")
    else:
        wide = eb.pivot_table(
            index=["method", "quantity"], columns="source", values="error_pct", aggfunc="first"
        )
        cols = [s for s in ERROR_SOURCES if s in wide.columns] + sorted(
            set(wide.columns) - set(ERROR_SOURCES)
        )
        wide = _sorted(wide[cols].reset_index())
        wide.columns.name = None
        body += H.paragraph(
            "Signed percent error of the noise-free real run with one error source switched on "
            "at a time; "
            "noise: the Monte Carlo standard deviation."
        ) + H.table(wide, sig=4)
    sens = _read_csv(d / "sensitivity.csv", SENSITIVITY_COLUMNS)
    body += "<h4>Sensitivity to averaging</h4>\n"
    if sens is None:
        body += H.not_available("sensitivity.csv")
    else:
        body += H.paragraph(
            f"sensitivity.csv: {len(sens)} rows, n_avg from {H.format_value(sens['n_avg'].min())} "
            f"to {H.format_value(sens['n_avg'].max())}, "
            f"methods {', '.join(sorted(map(str, sens['method'].unique())))}; "
            "see Fig. 6."
        )
    return body


def _assumptions_section(scenarios_dir: Path) -> str:
    files = (
        sorted(scenarios_dir.glob("*.yaml"), key=lambda f: (f.stem != "paper", f.stem))
        if scenarios_dir.is_dir()
        else []
    )
    if not files:
        return H.not_available(f"Scenario configs in {scenarios_dir.as_posix()}")
    body = H.paragraph(
        "Where the paper is silent, each scenario config decides; the value shown is read "
        "from the config "
        "at the named field."
    )
    for f in files:
        description, decisions = load_decisions(f)
        inner = H.paragraph(description or "(no description)")
        inner += H.table(decisions, empty_text="no decisions listed")
        body += H.section(
            f"Scenario {f.stem} ({f.as_posix()})",
            inner,
            anchor=f"assumptions-{H.slugify(f.stem)}",
            level=3,
        )
    return body


def _provenance_block(prov: Mapping[str, Any]) -> str:
    flat = {k: v for k, v in prov.items() if k != "packages"}
    body = H.definition_list(flat, value_format=_render_value)
    pkgs = prov.get("packages")
    if isinstance(pkgs, Mapping) and pkgs:
        df = pd.DataFrame(sorted(pkgs.items()), columns=["package", "version"])
        body += H.table(df, caption="packages")
    return body


def _benchmarks(bench_dir: Path) -> str:
    files = sorted(bench_dir.rglob("*.tsv")) if bench_dir.is_dir() else []
    if not files:
        return H.not_available("Benchmarks (results/north_finding/benchmarks/*.tsv)")
    rows = []
    for f in files:
        df = pd.read_csv(f, sep="\t")
        if "s" not in df.columns:
            raise ValueError(
                f"{f}: not a Snakemake benchmark file (no 's' column; has {list(df.columns)})"
            )
        rows.append(
            {
                "rule": f.relative_to(bench_dir).with_suffix("").as_posix(),
                "runs": len(df),
                "wall time (s, mean)": float(df["s"].mean()),
                "h:m:s": str(df["h:m:s"].iloc[0]) if "h:m:s" in df.columns and len(df) else "",
                "max_rss (MB)": float(pd.to_numeric(df["max_rss"], errors="coerce").max())
                if "max_rss" in df.columns
                else float("nan"),
            }
        )
    return H.table(pd.DataFrame(rows), caption="Snakemake benchmarks (wall time per rule)", sig=4)


def _provenance_section(results_dir: Path, scenarios: Sequence[Path]) -> str:
    body = ""
    top = results_dir / "provenance.json"
    if top.is_file():
        body += H.section(
            "Paper-level results",
            _provenance_block(json.loads(top.read_text(encoding="utf-8"))),
            anchor="provenance-top",
            level=3,
        )
    for d in scenarios:
        p = d / "provenance.json"
        inner = (
            _provenance_block(json.loads(p.read_text(encoding="utf-8")))
            if p.is_file()
            else H.not_available("provenance.json")
        )
        body += H.section(
            f"Scenario {d.name}", inner, anchor=f"provenance-{H.slugify(d.name)}", level=3
        )
    if not scenarios and not top.is_file():
        body += H.not_available("Provenance")
    body += H.section(
        "Benchmarks", _benchmarks(results_dir / "benchmarks"), anchor="benchmarks", level=3
    )
    return body


# --------------------------------------------------------------------------- page


def _findings_section(results_dir: Path, verdicts: pd.DataFrame) -> str:
    """Findings that go beyond the paper, computed from the results (nothing typed by hand)."""
    from pipeline.verdicts import NOISE_FREE_AGREES

    body = ""
    stat = verdicts[verdicts["kind"] == "statistical"]
    agree = stat[stat["note"].str.contains(NOISE_FREE_AGREES, regex=False)]
    body += H.paragraph(
        f"Deterministic error propagation: for {len(agree)} of the {len(stat)} real-sensor values "
        "of Tables 1-4 and 9-12, our noise-free real-sensor value (scale factor, misalignment and "
        "bias propagated through the derived formulas, no noise) equals the published value to "
        "within one unit of its last printed digit: "
        + (", ".join(agree["id"]) if len(agree) else "none")
        + ". The paper's 'real sensor' tables therefore reflect the deterministic sensor errors "
        "with the noise averaged out; the Monte Carlo spread at our averaging count is shown in "
        "Figs. 1-5 and its dependence on the count in Fig. 6."
    )
    budget_path = results_dir / "paper" / "error_budget.csv"
    budget = _read_csv(budget_path, ERROR_BUDGET_COLUMNS)
    if budget is not None and not budget.empty:
        psi = budget[budget["quantity"] == "psi_deg"].pivot_table(
            index="method", columns="source", values="error", aggfunc="first"
        )
        psi = psi.reindex([m for m in AZIMUTH_METHODS if m in psi.index])
        body += H.paragraph(
            "Azimuth error budget of the paper scenario (deg; the error with one source at a time, "
            "noise = Monte Carlo standard deviation). Method 1 cancels the gyro bias in its "
            "differences and methods 4-5 estimate it; methods 2 and 3 use single readings that "
            "carry it, so the 0.01 deg/h bias (6.6e-4 of the Earth rate) shifts their azimuth. "
            "Method 3 reads the maximum of a function that is flat in psi, which amplifies it most."
        )
        body += H.table(psi.reset_index(), sig=4)
    return body


def render_page(
    results_dir: str | Path = "results/north_finding",
    scenarios_dir: str | Path = "config/scenarios/north_finding",
    published: str | Path = "config/published/north_finding.yaml",
    figures_dir: str | Path | None = None,
) -> str:
    """The report as an HTML string (see :func:`build_page`)."""
    results_dir, scenarios_dir = Path(results_dir), Path(scenarios_dir)
    figures_dir = Path(figures_dir) if figures_dir is not None else results_dir / "figures"
    items, claims = load_published(published)
    verdicts = _require(
        _read_csv(results_dir / "verdicts.csv", VERDICT_COLUMNS, as_text=True),
        results_dir / "verdicts.csv",
    )
    audit = _require(
        _read_csv(results_dir / "equation_audit.csv", AUDIT_COLUMNS, as_text=True),
        results_dir / "equation_audit.csv",
    )
    scenarios = discover_scenarios(results_dir)

    sections: list[tuple[str, str, str]] = [
        ("summary", "Summary", _summary(items, claims, verdicts, audit)),
        ("equation-audit", "Equation audit", _audit_section(audit)),
        (
            "published-vs-reproduced",
            "Published vs reproduced (Tables 1–12)",
            _tables_section(items, verdicts),
        ),
        ("claims", "Claims", _claims_section(claims, items, verdicts)),
        ("figures", "Figures 1–6", _figures_section(figures_dir)),
        ("findings", "Findings beyond the paper", _findings_section(results_dir, verdicts)),
        (
            "scenarios",
            "Per-scenario results",
            "".join(
                H.section(
                    f"Scenario {d.name}",
                    _scenario_section(d),
                    anchor=f"scenario-{H.slugify(d.name)}",
                    level=3,
                )
                for d in scenarios
            )
            or H.not_available(f"Scenario results in {results_dir.as_posix()}"),
        ),
        ("assumptions", "Assumptions", _assumptions_section(scenarios_dir)),
        ("provenance", "Provenance", _provenance_section(results_dir, scenarios)),
    ]
    title = f"Reproduction report: {PAPER_TITLE}"
    body = (
        f"<header><h1>{H.escape(title)}</h1>\n"
        f"<p>{H.escape(PAPER_CITATION)} — slug <code>{SLUG}</code></p>\n</header>\n"
    )
    body += H.toc([(a, t) for a, t, _ in sections])
    body += "".join(H.section(t, b, anchor=a) for a, t, b in sections)
    return H.page(title, body)


def build_page(
    results_dir: str | Path = "results/north_finding",
    scenarios_dir: str | Path = "config/scenarios/north_finding",
    published: str | Path = "config/published/north_finding.yaml",
    out: str | Path = "reports/north_finding.html",
    figures_dir: str | Path | None = None,
) -> Path:
    """Build the report and write it atomically to ``out``; returns ``out``.

    ``figures_dir`` defaults to ``<results_dir>/figures``. Raises
    ``FileNotFoundError`` for a missing required input and ``ValueError`` for a
    malformed one (missing columns; a scenario decision whose field is absent).
    """
    return H.write_atomic(out, render_page(results_dir, scenarios_dir, published, figures_dir))


def run_from_snakemake(smk: Any) -> Path:
    """Entry for Snakemake's ``script:``: ``params`` may set results_dir,
    scenarios_dir, figures_dir; ``input.published``; ``output[0]`` is the page."""
    p = smk.params
    get = p.get if hasattr(p, "get") else (lambda k, d=None: d)
    return build_page(
        results_dir=get("results_dir", "results/north_finding"),
        scenarios_dir=get("scenarios_dir", "config/scenarios/north_finding"),
        published=smk.input.published,
        out=smk.output[0],
        figures_dir=get("figures_dir", None),
    )


def main(argv: Sequence[str] | None = None) -> int:
    ap = argparse.ArgumentParser(
        prog="python -m pipeline.report.north_finding", description=__doc__.split("\n\n")[0]
    )
    ap.add_argument("--results-dir", default="results/north_finding")
    ap.add_argument("--scenarios-dir", default="config/scenarios/north_finding")
    ap.add_argument("--published", default="config/published/north_finding.yaml")
    ap.add_argument("--figures-dir", default=None)
    ap.add_argument("--out", default="reports/north_finding.html")
    a = ap.parse_args(argv)
    print(build_page(a.results_dir, a.scenarios_dir, a.published, a.out, a.figures_dir))
    return 0


if __name__ == "__main__":
    if "snakemake" in globals():
        run_from_snakemake(snakemake)  # type: ignore[name-defined]  # noqa: F821
    else:
        raise SystemExit(main())
