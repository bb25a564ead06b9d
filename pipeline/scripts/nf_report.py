# Snakemake script: the north-finding HTML page (pipeline.report.page_html.build_page).
import sys
from pathlib import Path

from pipeline.registry import load_paper
from pipeline.report.model import ReportInputs
from pipeline.report.page_html import build_page

with open(snakemake.log[0], "w") as log:  # noqa: F821
    sys.stderr = log
    out = build_page(
        load_paper("north_finding"),
        ReportInputs(
            results=Path(snakemake.input.audit).parent,  # noqa: F821
            scenarios=Path("config/scenarios/north_finding"),
            published=Path(snakemake.input.published),  # noqa: F821
            figures=Path(snakemake.input.figures[0]).parent,  # noqa: F821
            settings=snakemake.config.get("north_finding") or {},  # noqa: F821
        ),
        snakemake.output[0],  # noqa: F821
    )
    print(f"wrote {out}", file=log)
