# Snakemake script: the north-finding HTML page.
import sys
from pathlib import Path

from pipeline.report.north_finding import build_page

with open(snakemake.log[0], "w") as log:  # noqa: F821
    sys.stderr = log
    build_page(
        results_dir=Path(snakemake.input.audit).parent,  # noqa: F821
        scenarios_dir="config/scenarios/north_finding",
        published=snakemake.input.published,  # noqa: F821
        out=snakemake.output[0],  # noqa: F821
        figures_dir=Path(snakemake.input.figures[0]).parent,  # noqa: F821
    )
