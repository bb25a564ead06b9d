# Snakemake script: the altimeter-attitude HTML page.
import sys
from pathlib import Path

from pipeline.report.altimeter_attitude import build_page

with open(snakemake.log[0], "w") as log:  # noqa: F821
    sys.stderr = log
    build_page(
        Path(snakemake.input.audit).parent,  # noqa: F821
        "config/scenarios/altimeter_attitude",
        snakemake.output[0],  # noqa: F821
        published_scenario=snakemake.config["altimeter_attitude"]["published_scenario"],  # noqa: F821
        audit=snakemake.input.audit,  # noqa: F821
        verdicts=snakemake.input.verdicts,  # noqa: F821
        summaries=list(snakemake.input.summaries),  # noqa: F821
        sweep=snakemake.input.sweep,  # noqa: F821
        figures_dir=Path(snakemake.input.figures[0]).parent,  # noqa: F821
    )
    print(f"wrote {snakemake.output[0]}", file=log)  # noqa: F821
