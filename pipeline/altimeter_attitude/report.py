"""The altimeter_attitude report sections (its page ``reports/altimeter_attitude.html`` and its
part of the combined report): summary, audit, verdicts, per-scenario RMS, figures, findings
beyond the paper, assumptions and provenance.

Inputs (:class:`~pipeline.report.model.ReportInputs`; ``results/altimeter_attitude/``):

* ``verdicts.csv`` (required), ``equation_audit.csv`` (shown as "not available" if absent);
* ``<scenario>/rms_summary.csv``, ``<scenario>/noise_free.csv``,
  ``<scenario>/window_summary.csv`` (optional) and ``<scenario>/provenance.json`` of every
  scenario folder holding an rms_summary.csv;
* ``sweep.csv`` (the one-at-a-time sensitivity sweep) and ``<published>/ukf_tuning.csv``;
* ``figures/*.png`` (``PAPER.figures``; a missing figure is shown as "not available");
* the scenario files ``config/scenarios/altimeter_attitude/*.yaml`` (description, decisions);
* the setting ``published_scenario`` (default ``paper``).

Every number is read or computed from these files; the prose around them is a template.
"""

from __future__ import annotations

import hashlib
import json
from collections.abc import Callable, Mapping, Sequence
from pathlib import Path
from typing import Any

import pandas as pd

from pipeline.altimeter_attitude.columns import (
    ALTIMETER_FILTERS,
    RMS_SUMMARY_COLUMNS,
    SWEEP_COLUMNS,
    UKF_TUNING_COLUMNS,
    WINDOW_SUMMARY_COLUMNS,
)
from pipeline.altimeter_attitude.paper import PAPER
from pipeline.altimeter_attitude.report_findings import (
    DASH,
    filter_order,
    findings_section,
    fmt3,
    sweep_table,
)
from pipeline.altimeter_attitude.report_summary import (
    after_bank_blocks,
    headline_blocks,
    summary_blocks,
)
from pipeline.altimeter_attitude.report_trouble import filter_trouble_blocks
from pipeline.altimeter_attitude.report_tuning import TUNING_ID, tuning_section
from pipeline.altimeter_attitude.scenario import Scenario, load_scenario
from pipeline.altimeter_attitude.workflow import FIGURES, SWEEP_FIGURE
from pipeline.columns import AUDIT_COLUMNS, VERDICT_COLUMNS
from pipeline.report.figures import figure_blocks
from pipeline.report.html import format_value, slugify
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
from pipeline.report.plain import plain_value

__all__ = ["FILTER_LABELS", "build_page", "report"]

FILTER_LABELS: dict[str, str] = {
    "linear_kf": "linear Kalman filter on x = [C31, C32, C33, V_d, h] (eqs. 26, 31), with the "
    "multiplicative-noise term Gamma (Q kron P) Gamma^T",
    "linear_kf_no_gamma": "the same linear filter without the Gamma (Q kron P) Gamma^T term",
    "ukf": "unscented Kalman filter on [roll, pitch, V_d, h] (Sec. 6)",
    "ekf": "extended Kalman filter on the same Euler-angle model (the paper says it diverges)",
    "complementary": "PI complementary filter of Fig. 1 (cruise levelling inside the loop)",
    "gyro_only": "gyro propagation of c (eq. 14), no correction",
    "accel_leveling": "accelerometer levelling (eqs. 17-b, 11) at every step",
}


def _read(
    path: Path, columns: Sequence[str], *, as_text: bool = False, optional: Sequence[str] = ()
) -> pd.DataFrame | None:
    """The CSV at ``path`` with the contract ``columns`` (in that order) and the ``optional``
    ones it has, by name; None if absent."""
    if not path.is_file():
        return None
    df = pd.read_csv(path, dtype=str, keep_default_na=False) if as_text else pd.read_csv(path)
    missing = [c for c in columns if c not in df.columns]
    if missing:
        raise ValueError(f"{path}: missing columns {missing} (has {list(df.columns)})")
    extra = [c for c in optional if c in df.columns and c not in columns]
    return df[[*columns, *extra]]


def _value_text(value: Any) -> str:
    """A config value as plain text (no JSON: :func:`pipeline.report.plain.plain_value`)."""
    return plain_value(value)


def _audit(audit: pd.DataFrame | None, path: str) -> list[Block]:
    if audit is None:
        return [not_available(f"Equation audit ({path})")]
    differs = audit[audit["status"] == "differs"]
    if len(differs):
        blocks: list[Block] = [
            Paragraph(
                f"{len(differs)} of {len(audit)} printed equations differ from the derivation "
                "(the pipeline uses the derived form):"
            ),
            Bullets(
                [
                    f"Eq. {r.equation}: {r.note or 'no note'} (residual {r.residual})"
                    for r in differs.itertuples()
                ]
            ),
        ]
    else:
        blocks = [
            Paragraph(f"None of the {len(audit)} printed equations differs from the derivation.")
        ]
    ordered = pd.concat([differs, audit[audit["status"] != "differs"]])
    blocks.append(
        frame_table(
            ordered,
            status="status",
            caption="equation_audit.csv (differs rows first, then in file order)",
        )
    )
    return blocks


#: the root-cause columns of verdicts.csv (the summary lists each cause once with its rows)
CAUSE = ("cause_kind", "cause")


def _verdicts(verdicts: pd.DataFrame) -> Section:
    # the cause's title stays; its full text is in the Summary's list of causes
    shown = verdicts.drop(columns=[c for c in ("cause_detail",) if c in verdicts.columns])
    values = shown[shown["kind"] != "claim"]
    claims = shown[shown["kind"] == "claim"]
    intro = Paragraph(
        "Values: the paper's approximate RMS errors against ours over two windows of the "
        "published scenario (window_summary.csv), rows /flight (after the transient) and "
        "/after_bank (after the first bank that makes roll observable); tolerance and Monte Carlo "
        "standard error in the tolerance and note columns. Claims: a predicate over the "
        "results; the reproduced column is its computed evidence. The sigma-consistency claims "
        "have one row per angle: NEES above the chi-square band means the filter's sigma is "
        "too small (over-confident), below it too large (under-confident). The cause_kind "
        "and cause columns give the kind and title of a failing row's root cause (the Summary "
        "states each cause once, in full, with its rows); 'unpublished' means it cannot be reproduced from what the paper "
        "publishes, which does not refute it."
    )
    return Section(
        "verdicts",
        "Published numbers and claims",
        [intro],
        [
            Section("verdicts-values", "Published values", [frame_table(values, status="verdict")]),
            Section("verdicts-claims", "Claims", [frame_table(claims, status="verdict")]),
        ],
    )


def _results(
    summaries: Mapping[str, pd.DataFrame],
    descriptions: Mapping[str, str],
    published: str,
    windows: Mapping[str, pd.DataFrame] | None = None,
    headline: Sequence[Block] = (),
    results_dir: Path = Path("results/altimeter_attitude"),
) -> Section:
    blocks: list[Block] = [
        *headline,
        Paragraph(
            "rms_summary.csv per scenario: RMS over runs and over time after the transient; "
            "sigma: RMS of the filter's own standard deviation; NEES: mean of error^2 / sigma^2 "
            f"(1 for a consistent filter). {DASH}: the filter has no covariance. Filters:"
        ),
        frame_table(
            pd.DataFrame(list(FILTER_LABELS.items()), columns=["filter", "description"]),
        ),
    ]
    if not summaries:
        blocks.append(not_available("rms_summary.csv"))
    subs = []
    for name, s in summaries.items():
        missing = [f for f in ALTIMETER_FILTERS if f not in set(s["filter"])]
        s = s.set_index("filter").reindex(filter_order(list(s["filter"]))).reset_index()
        fmts = {c: fmt3 for c in RMS_SUMMARY_COLUMNS if c not in ("filter", "n_runs")}
        fmts["n_runs"] = lambda x: DASH if pd.isna(x) else str(int(x))
        inner: list[Block] = [Paragraph(descriptions[name])] if descriptions.get(name) else []
        inner.append(frame_table(s, formatters=fmts))
        inner += after_bank_blocks((windows or {}).get(name))
        inner += filter_trouble_blocks(results_dir / name / "numerical_trouble.csv")
        if missing:
            inner.append(Paragraph(f"Filters without results: {', '.join(missing)}."))
        title = f"Scenario {name}" + (" (published scenario)" if name == published else "")
        subs.append(Section(f"results-{slugify(name)}", title, inner))
    return Section("results", "Results per scenario", blocks, subs)


def _figures(figures_dir: Path, sweep: pd.DataFrame | None, sweep_trouble: Path) -> Section:
    inner: list[Block] = list(figure_blocks(PAPER, figures_dir, [SWEEP_FIGURE]))
    if sweep is None or sweep.empty:
        inner.append(not_available("sweep.csv"))
    else:
        inner.append(
            Paragraph(
                "Parameters varied one at a time around the published scenario: "
                + ", ".join(
                    f"{p} ({', '.join(format_value(v) for v in sorted(g['value'].unique()))})"
                    for p, g in sweep.groupby("parameter", sort=False)
                )
                + "."
            )
        )
        inner.append(sweep_table(sweep))
        inner += filter_trouble_blocks(sweep_trouble)
    return Section(
        "figures",
        "Figures",
        list(figure_blocks(PAPER, figures_dir, FIGURES)),
        [Section("sweep", "Sensitivity sweep", inner)],
    )


def _assumptions(scenarios: Mapping[Path, Scenario], shown: Callable[[Path], str]) -> Section:
    if not scenarios:
        return Section("assumptions", "Assumptions", [not_available("Scenario files")])
    subs = []
    for path, sc in scenarios.items():
        rows = pd.DataFrame(
            [
                {"field": d["field"], "value": _value_text(d["value"]), "decision": str(d["text"])}
                for d in sc.decisions()
            ],
            columns=["field", "value", "decision"],
        )
        subs.append(
            Section(
                f"assumptions-{slugify(path.stem)}",
                f"Scenario {path.stem} ({shown(path)})",
                [
                    Paragraph(str(sc.raw.get("description", "")).strip() or "(no description)"),
                    frame_table(rows, empty_text="no decisions listed"),
                ],
            )
        )
    intro = Paragraph(
        "Where the paper is silent, each scenario file decides; the value shown is read from the "
        "file at the named field."
    )
    return Section("assumptions", "Assumptions", [intro], subs)


def _flatten(data: Mapping[str, Any], prefix: str = "") -> dict[str, Any]:
    out: dict[str, Any] = {}
    for k, v in data.items():
        key = f"{prefix}{k}"
        if isinstance(v, Mapping):
            out.update(_flatten(v, f"{key}."))
        elif isinstance(v, list):
            out[key] = ", ".join(map(str, v))
        else:
            out[key] = v
    return out


def _provenance(
    scenario_dirs: Mapping[str, Path],
    scenarios: Mapping[str, Scenario],
    inputs: Sequence[Path],
    shown: Callable[[Path], str],
) -> Section:
    subs = []
    for name, d in scenario_dirs.items():
        p = d / "provenance.json"
        if not p.is_file():
            inner: list[Block] = [not_available(shown(p))]
        else:
            data = json.loads(p.read_text(encoding="utf-8"))
            flat = _flatten({k: v for k, v in data.items() if k != "packages"})
            if name in scenarios and "config_sha256" in data:
                now = scenarios[name].config_sha256
                flat["config_sha256 equals the scenario file's now"] = (
                    "yes" if now == data["config_sha256"] else f"no (file now: {now})"
                )
            inner = [
                frame_table(
                    pd.DataFrame(list(flat.items()), columns=["field", "value"]),
                    formatters={"value": _value_text},
                )
            ]
            pkgs = data.get("packages")
            if isinstance(pkgs, Mapping) and pkgs:
                inner.append(
                    frame_table(
                        pd.DataFrame(sorted(pkgs.items()), columns=["package", "version"]),
                        caption="packages",
                    )
                )
        subs.append(Section(f"provenance-{slugify(name)}", f"Scenario {name}", inner))
    rows = pd.DataFrame(
        [
            {"file": shown(p), "sha256": hashlib.sha256(p.read_bytes()).hexdigest()}
            for p in inputs
            if p.is_file()
        ],
        columns=["file", "sha256"],
    )
    subs.append(Section("provenance-inputs", "Input files of this page", [frame_table(rows)]))
    return Section("provenance", "Provenance", [], subs)


def report(inputs: ReportInputs) -> PaperReport:
    """The paper's report sections, built from ``inputs`` (see the module docstring)."""
    results = inputs.results
    published_scenario = str(inputs.settings.get("published_scenario", "paper"))
    audit_path = results / "equation_audit.csv"
    verdicts_path = results / "verdicts.csv"
    sweep_path = results / "sweep.csv"
    tuning_path = results / published_scenario / "ukf_tuning.csv"
    summary_paths = sorted(results.glob("*/rms_summary.csv"))
    audit = _read(audit_path, AUDIT_COLUMNS, as_text=True)
    verdicts = _read(
        verdicts_path, VERDICT_COLUMNS, as_text=True, optional=(*VERDICT_EXTRA_COLUMNS, *CAUSE)
    )
    if verdicts is None:
        raise FileNotFoundError(f"{verdicts_path}: required input is missing")
    sweep = _read(sweep_path, SWEEP_COLUMNS)
    by_name: dict[str, pd.DataFrame] = {}
    for p in summary_paths:
        by_name[p.parent.name] = _read(p, RMS_SUMMARY_COLUMNS)  # type: ignore[assignment]
    order = sorted(by_name, key=lambda n: (n != published_scenario, n))
    sums = {n: by_name[n] for n in order}
    dirs = {n: results / n for n in order}
    windows = {
        p.parent.name: df
        for p in summary_paths
        if (df := _read(p.parent / "window_summary.csv", WINDOW_SUMMARY_COLUMNS)) is not None
    }
    noise_free = {  # in file order (the published scenario is not moved first here)
        p.parent.name: df
        for p in summary_paths
        if (df := _read(p.parent / "noise_free.csv", RMS_SUMMARY_COLUMNS)) is not None
    }
    files = sorted(
        inputs.scenarios.glob("*.yaml"), key=lambda f: (f.stem != published_scenario, f.stem)
    )
    scenarios = {f: load_scenario(f) for f in files}  # each read once (was thrice: ~40 ms)
    by_name = {f.stem: sc for f, sc in scenarios.items()}
    descriptions = {n: str(sc.raw.get("description", "")).strip() for n, sc in by_name.items()}
    sections = [
        Section(
            "summary", "Summary", summary_blocks(audit, verdicts, sums, published_scenario, windows)
        ),
        Section("equation-audit", "Equation audit", _audit(audit, inputs.shown(audit_path))),
        _verdicts(verdicts),
        _results(
            sums,
            descriptions,
            published_scenario,
            windows,
            headline_blocks(verdicts, sums, published_scenario, windows),
            results,
        ),
        _figures(inputs.figures, sweep, results / "sweep_trouble.csv"),
        findings_section(sums, sweep, noise_free),
        # the grid behind the UKF's settings: a supporting appendix of the combined report
        tuning_section(_read(tuning_path, UKF_TUNING_COLUMNS), inputs.shown(tuning_path)),
        _assumptions(scenarios, inputs.shown),
        _provenance(
            dirs,
            by_name,
            [
                audit_path,
                verdicts_path,
                *summary_paths,
                *(p.parent / "window_summary.csv" for p in summary_paths),
                sweep_path,
                tuning_path,
            ],
            inputs.shown,
        ),
    ]
    parts = {
        "summary": ["summary"],
        "published": None,
        "figures": ["figures"],
        "findings": ["findings", "results", TUNING_ID],
        "assumptions": ["assumptions"],
    }
    return PaperReport(sections, parts)


def build_page(
    results_dir: str | Path = "results/altimeter_attitude",
    scenarios_dir: str | Path = "config/scenarios/altimeter_attitude",
    out: str | Path = "reports/altimeter_attitude.html",
    *,
    published: str | Path = "config/published/altimeter_attitude.yaml",
    published_scenario: str = "paper",
    figures_dir: str | Path | None = None,
) -> Path:
    """Write the page ``out`` from explicit inputs (``figures_dir`` defaults to
    ``<results_dir>/figures``); nothing is written if a required input is missing."""
    from pipeline.report.page_html import build_page as write_page

    results = Path(results_dir)
    inputs = ReportInputs(
        results=results,
        scenarios=Path(scenarios_dir),
        published=Path(published),
        figures=Path(figures_dir) if figures_dir is not None else results / "figures",
        settings={"published_scenario": published_scenario},
    )
    return write_page(PAPER, inputs, out)
