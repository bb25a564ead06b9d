"""The north_finding report sections (its page ``reports/north_finding.html`` and its part of
the combined report).

Reads the results contract (``results/north_finding/``), the published values
(``config/published/north_finding.yaml``), the scenario configs
(``config/scenarios/north_finding/*.yaml``) and the figures written by
:mod:`pipeline.north_finding.figures`.

Required: the published YAML, ``verdicts.csv`` and ``equation_audit.csv``. Everything else
(scenario result files, figures, sensitivity, provenance, benchmarks, scenario configs) is
optional and shown as "not available" when absent. A scenario decision whose dotted
``field`` does not exist in its YAML is an error (``ValueError`` naming the file and the
field).
"""

from __future__ import annotations

from collections.abc import Sequence
from pathlib import Path
from typing import Any

import numpy as np
import pandas as pd

from pipeline.columns import AUDIT_COLUMNS, AUDIT_STATUSES, VERDICT_COLUMNS, VERDICT_KINDS, VERDICTS
from pipeline.north_finding.columns import ERROR_BUDGET_COLUMNS
from pipeline.north_finding.error_propagation import azimuth_error_budget, noise_free_agreement
from pipeline.north_finding.paper import CITATION, PAPER, TITLE
from pipeline.north_finding.published_items import load_published
from pipeline.north_finding.report_n import n_inference_section
from pipeline.north_finding.report_results import (
    assumptions_section,
    discover_scenarios,
    provenance_section,
    read_csv,
    scenario_section,
)
from pipeline.report.figures import figure_blocks
from pipeline.report.model import (
    VERDICT_EXTRA_COLUMNS,
    Block,
    Bullets,
    PaperReport,
    Paragraph,
    ReportInputs,
    Section,
    frame_table,
    not_available,
)
from pipeline.report.plain import predicate_sentence, row_labels
from pipeline.verdicts.published import load_published as load_published_file

__all__ = ["QUANTITY_LABELS", "audit_counts", "report", "verdict_counts"]

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


def _require(df: pd.DataFrame | None, path: Path) -> pd.DataFrame:
    if df is None:
        raise FileNotFoundError(f"{path}: required input is missing")
    return df


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


def _spelled(counts: pd.Series) -> str:
    return ", ".join(f"{int(n)} {str(w).replace('_', ' ')}" for w, n in counts.items())


# --------------------------------------------------------------------------- sections


def _summary(
    items: pd.DataFrame, claims: pd.DataFrame, verdicts: pd.DataFrame, audit: pd.DataFrame
) -> list[Block]:
    vc, ac = verdict_counts(verdicts), audit_counts(audit)
    n_tables = int(items["table_no"].dropna().nunique())
    blocks: list[Block] = [
        Paragraph(
            f"This page puts every published number and claim of “{TITLE}” ({CITATION}) beside "
            "what this project derived and computed. "
            f"The published values file lists {len(items)} numbers from {n_tables} tables "
            f"and {len(claims)} claims; verdicts.csv has {len(verdicts)} verdicts: "
            f"{_spelled(vc)}. The equation audit checked {len(audit)} printed equations against "
            f"the SymPy derivation: {_spelled(ac)}. Where a printed equation differs, the "
            "pipeline uses the derived one. Verdict rules: exact (ideal sensor, equal to the "
            "printed precision), approximate (a value the text gives as 'about', within one "
            "unit of its last significant digit or 10 %, the larger), statistical (where the published value falls in the Monte "
            "Carlo distribution), claim (a predicate over results, judged at each averaging "
            "count N where it ranks methods)."
        )
    ]
    extra = [v for v in vc.index if v not in VERDICTS]
    if extra:
        blocks.append(Paragraph(f"Unknown verdict words in verdicts.csv: {', '.join(extra)}."))
    crosstab = pd.crosstab(verdicts["verdict"], verdicts["kind"])
    order = [v for v in VERDICTS if v in crosstab.index] + sorted(
        set(crosstab.index) - set(VERDICTS)
    )
    kinds = [k for k in VERDICT_KINDS if k in crosstab.columns] + sorted(
        set(crosstab.columns) - set(VERDICT_KINDS)
    )
    crosstab = crosstab.loc[order, kinds].reset_index()
    crosstab.columns.name = None
    blocks.append(frame_table(crosstab, status="verdict", caption="Verdicts by kind"))
    return blocks


def _audit(audit: pd.DataFrame) -> list[Block]:
    audit = (
        audit.assign(_k=_equation_key(audit["equation"]))
        .sort_values("_k", kind="stable")
        .drop(columns="_k")
    )
    differs = audit[audit["status"] == "differs"]
    blocks: list[Block] = []
    if len(differs):
        blocks.append(
            Paragraph(
                "Printed equations that differ from the derivation "
                "(the pipeline uses the derived form):"
            )
        )
        blocks.append(
            Bullets(
                [
                    f"Eq. {r.equation}: {r.note or 'no note'} (residual {r.residual})"
                    for r in differs.itertuples()
                ]
            )
        )
    else:
        blocks.append(Paragraph("No printed equation differs from the derivation."))
    blocks.append(
        frame_table(
            audit[AUDIT_COLUMNS], status="status", caption="Equation audit (equation_audit.csv)"
        )
    )
    return blocks


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


def _tables(items: pd.DataFrame, verdicts: pd.DataFrame) -> Section:
    v = verdicts.drop_duplicates("id", keep="first").set_index("id")
    joined = items.assign(
        published=_published_cell(items),
        reproduced=items["id"].map(v["reproduced"]).fillna(""),
        verdict=items["id"].map(v["verdict"]).fillna("missing"),
        note=items["id"].map(v["note"]).fillna("no verdict in verdicts.csv"),
        sensor=items["sensor"].fillna(""),
    )
    cols = ["id", "method", "sensor", "published", "reproduced", "verdict", "note"]
    extra = [c for c in VERDICT_EXTRA_COLUMNS if c in v.columns]  # where recorded
    joined = joined.assign(**{c: items["id"].map(v[c]).fillna("") for c in extra})
    cols += extra
    subs = [
        Section(
            f"table-{int(n)}",
            _table_heading(int(n), rows),
            [frame_table(rows[cols], status="verdict")],
        )
        for n, rows in joined[joined["table_no"].notna()].groupby("table_no", sort=True)
    ]
    other = joined[joined["table_no"].isna()]
    if len(other):
        subs.append(
            Section(
                "table-other",
                "Published items outside Tables 1–12",
                [frame_table(other[cols], status="verdict")],
            )
        )
    intro = Paragraph(
        "Published: the value as printed, with the printed percent error in parentheses. "
        "Reproduced and verdict: from verdicts.csv. “missing”: the published item has no verdict."
    )
    return Section(
        "published-vs-reproduced", "Published vs reproduced (Tables 1–12)", [intro], subs
    )


def _claim_rows(claims: pd.DataFrame, verdicts: pd.DataFrame) -> pd.DataFrame:
    """One row per verdict row of each claim (``<claim id>/<suffix>``: one per N judged), in
    the published file's order; a claim without a verdict row appears once as "missing"."""
    rows = []
    base = verdicts["id"].astype(str).str.split("/").str[0]
    for _, claim in claims.iterrows():
        meta = claim.to_dict()
        meta["note_claim"] = meta.pop("note", None)
        mine = verdicts[base == str(claim["id"])]
        if mine.empty:
            rows.append({**meta, "verdict": "missing", "reproduced": "",
                         "note": "no verdict in verdicts.csv"})  # fmt: skip
        for _, row in mine.iterrows():
            rows.append({**meta, **row.to_dict()})
    return pd.DataFrame(rows)


def _claims(
    claims: pd.DataFrame, items: pd.DataFrame, verdicts: pd.DataFrame, names: dict[str, str]
) -> Section:
    v = verdicts.drop_duplicates("id", keep="first").set_index("id")
    blocks: list[Block] = []
    subs: list[Section] = []
    if len(claims):
        c = _claim_rows(claims, verdicts)
        reading = c["note_claim"] if "note_claim" in c.columns else pd.Series(None, index=c.index)
        c = c.assign(
            predicate=c["predicate"].map(lambda p: predicate_sentence(p, names)),
            reading=reading.map(lambda x: "" if x is None or pd.isna(x) else str(x)),
        )
        cols = ["id", "text", "source", "reading", "predicate", "reproduced", "verdict", "note"]
        extra = [k for k in VERDICT_EXTRA_COLUMNS if k in v.columns]  # where recorded
        c = c.assign(**{k: c[k].fillna("") if k in c.columns else "" for k in extra})
        cols += extra
        if not c["reading"].astype(bool).any():
            cols.remove("reading")
        blocks.append(
            Paragraph(
                "reading: how this project reads a vague claim; "
                "predicate: the rule the verdict applies."
            )
        )
        blocks.append(frame_table(c[cols], status="verdict"))
    else:
        blocks.append(not_available("Claims in the published values file"))
    known = set(items["id"].astype(str)) | set(claims["id"].astype(str))
    orphans = verdicts[~verdicts["id"].astype(str).str.split("/").str[0].isin(known)]
    if len(orphans):
        subs.append(
            Section(
                "orphan-verdicts",
                "Verdicts without a published item or claim",
                [
                    Paragraph(
                        "These rows of verdicts.csv name an id that the published values file "
                        "does not have."
                    ),
                    frame_table(orphans[VERDICT_COLUMNS], status="verdict"),
                ],
            )
        )
    return Section("claims", "Claims", blocks, subs)


def _findings(results: Path, verdicts: pd.DataFrame, published: dict) -> list[Block]:
    """Findings that go beyond the paper, computed from the results (nothing typed by hand)."""
    agree, n_stat = noise_free_agreement(verdicts)
    blocks: list[Block] = [
        Paragraph(
            f"Deterministic error propagation: for {len(agree)} of the {n_stat} real-sensor "
            "values of Tables 1-4 and 9-12, our noise-free real-sensor value (scale factor, "
            "misalignment and bias propagated through the derived formulas, no noise) equals "
            "the published value to within one unit of its last printed digit: "
            + ("; ".join(dict.fromkeys(row_labels(agree, published))) if agree else "none")
            + ". The paper's 'real sensor' tables therefore reflect the deterministic sensor "
            "errors with the noise averaged out; the Monte Carlo spread at our averaging count "
            "is shown in Figs. 1-5 and its dependence on the count in Fig. 6."
        )
    ]
    budget = read_csv(results / "paper" / "error_budget.csv", ERROR_BUDGET_COLUMNS)
    if budget is not None and not budget.empty:
        blocks.append(
            Paragraph(
                "Azimuth error budget of the paper scenario (deg; the error with one source at "
                "a time, noise = Monte Carlo standard deviation). Method 1 cancels the gyro bias "
                "in its differences and methods 4-5 estimate it; methods 2 and 3 use single "
                "readings that carry it, so the 0.01 deg/h bias (6.6e-4 of the Earth rate) "
                "shifts their azimuth. Method 3 reads the maximum of a function that is flat in "
                "psi, which amplifies it most."
            )
        )
        psi = azimuth_error_budget(budget)
        psi.columns.name = None
        blocks.append(frame_table(psi.reset_index(), sig=4))
    return blocks


def report(inputs: ReportInputs) -> PaperReport:
    """The paper's report sections, built from ``inputs`` (see the module docstring)."""
    results, pub = inputs.results, inputs.settings.get("published_scenario", "paper")
    items, claims = load_published(inputs.published)
    published = load_published_file(inputs.published)
    names = dict(published.get("names") or {})
    # only a "Table N" label names a table (the text's "Sec. 5-2-2" is no Table 5)
    numbers = items["table"].astype(str).str.extract(r"^Table (\d+)$")[0]
    items = items.assign(table_no=pd.to_numeric(numbers, errors="coerce").astype(float))
    verdicts, audit = (
        _require(read_csv(results / name, cols, as_text=True), results / name)
        for name, cols in (("verdicts.csv", VERDICT_COLUMNS), ("equation_audit.csv", AUDIT_COLUMNS))
    )
    scenarios: Sequence[Path] = discover_scenarios(results)
    figures: list[Block] = [
        Paragraph(f"Figures from {inputs.shown(inputs.figures)} (PNG embedded; SVG beside them).")
    ]
    figures += figure_blocks(PAPER, inputs.figures)
    n_sec = n_inference_section(results, pub, inputs.shown, published)
    sections = [
        Section("summary", "Summary", _summary(items, claims, verdicts, audit)),
        Section("equation-audit", "Equation audit", _audit(audit)),
        _tables(items, verdicts),
        _claims(claims, items, verdicts, names),
        Section("figures", "Figures 1–6", figures),
        Section("findings", "Findings beyond the paper", _findings(results, verdicts, published)),
        n_sec,  # the inferred N: a supporting appendix of the combined report
        Section(
            "scenarios",
            "Per-scenario results",
            [] if scenarios else [not_available(f"Scenario results in {inputs.shown(results)}")],
            [scenario_section(d) for d in scenarios],
        ),
        assumptions_section(inputs.scenarios, inputs.shown),
        provenance_section(results, scenarios),
    ]
    parts = {
        "summary": ["summary"],
        "published": ["published-vs-reproduced", "claims"],
        "figures": ["figures"],
        "findings": ["findings", "n-inference"],
        "assumptions": ["assumptions"],
    }
    return PaperReport(sections, parts)


def build_page(
    results_dir: str | Path = "results/north_finding",
    scenarios_dir: str | Path = "config/scenarios/north_finding",
    published: str | Path = "config/published/north_finding.yaml",
    out: str | Path = "reports/north_finding.html",
    figures_dir: str | Path | None = None,
) -> Path:
    """Write the page ``out`` from explicit inputs (``figures_dir`` defaults to
    ``<results_dir>/figures``); FileNotFoundError / ValueError name a missing or malformed
    input, and nothing is written then."""
    from pipeline.report.page_html import build_page as write_page

    results = Path(results_dir)
    inputs = ReportInputs(
        results=results,
        scenarios=Path(scenarios_dir),
        published=Path(published),
        figures=Path(figures_dir) if figures_dir is not None else results / "figures",
    )
    return write_page(PAPER, inputs, out)
