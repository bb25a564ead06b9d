"""The pendulum's report sections (its page and its part of the combined report)."""

from __future__ import annotations

import pandas as pd
from pipeline.pendulum.paper import PAPER
from pipeline.pendulum.scenario import load_scenario

from pipeline.columns import AUDIT_COLUMNS, VERDICT_COLUMNS
from pipeline.report.figures import figure_blocks
from pipeline.report.model import PaperReport, Paragraph, ReportInputs, Section, Table, frame_table

__all__ = ["report"]


def _csv(path) -> pd.DataFrame:
    if not path.is_file():
        raise FileNotFoundError(f"{path}: required input is missing")
    return pd.read_csv(path, dtype=str, keep_default_na=False)


def report(inputs: ReportInputs) -> PaperReport:
    audit = _csv(inputs.results / "equation_audit.csv")[AUDIT_COLUMNS]
    verdicts = _csv(inputs.results / "verdicts.csv")
    counts = verdicts["verdict"].value_counts()
    summary = Paragraph(
        f"{len(audit)} printed equations audited ({(audit['status'] == 'differs').sum()} "
        f"differ); {len(verdicts)} verdicts: "
        + ", ".join(f"{n} {k}" for k, n in counts.items())
        + "."
    )
    decisions = []
    for path in sorted(inputs.scenarios.glob("*.yaml")):
        raw = load_scenario(path).raw
        decisions += [[path.stem, d["field"], d["text"]] for d in raw.get("decisions", [])]
    sections = [
        Section("summary", "Summary", [summary]),
        Section("equation-audit", "Equation audit", [frame_table(audit, status="status")]),
        Section(
            "verdicts",
            "Published numbers and claims",
            [frame_table(verdicts[VERDICT_COLUMNS], status="verdict")],
        ),
        Section("figures", "Figures", figure_blocks(PAPER, inputs.figures)),
        Section(
            "assumptions", "Assumptions", [Table(["scenario", "field", "decision"], decisions)]
        ),
    ]
    parts = {
        "summary": ["summary"],
        "published": None,
        "figures": ["figures"],
        "findings": [],
        "assumptions": ["assumptions"],
    }
    return PaperReport(sections, parts)
