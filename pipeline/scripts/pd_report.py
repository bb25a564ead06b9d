# Snakemake script: the platform-drift HTML page (pipeline.report.page_html.build_page).
import sys
from pathlib import Path

from pipeline.registry import load_paper
from pipeline.report.model import ReportInputs
from pipeline.report.page_html import build_page

with open(snakemake.log[0], "w") as log:  # noqa: F821
    sys.stderr = log
    out = build_page(
        load_paper("platform_drift"),
        ReportInputs(
            results=Path(snakemake.input.audit).parent,  # noqa: F821
            scenarios=Path("config/scenarios/platform_drift"),
            published=Path("config/published/platform_drift.yaml"),
            figures=Path(snakemake.input.figures[0]).parent,  # noqa: F821
            settings=snakemake.config.get("platform_drift") or {},  # noqa: F821
        ),
        snakemake.output[0],  # noqa: F821
    )
    print(f"wrote {out}", file=log)
