# Snakemake script: the platform-drift HTML page.
import sys
from pathlib import Path

from pipeline.report.platform_drift import build_page

with open(snakemake.log[0], "w") as log:  # noqa: F821
    sys.stderr = log
    build_page(
        Path(snakemake.input.audit).parent, "config/scenarios/platform_drift", snakemake.output[0]
    )  # noqa: F821
