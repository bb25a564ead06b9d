# Snakemake script: Figs. 5-8 of the platform-drift paper, published values overlaid.
import sys
from pathlib import Path

from pipeline.platform_drift.figures import run

with open(snakemake.log[0], "w") as log:  # noqa: F821
    sys.stderr = log
    results_dir = Path(snakemake.input.errors[0]).parents[1]  # noqa: F821
    out_dir = Path(snakemake.output[0]).parent  # noqa: F821
    run(results_dir, "config/scenarios/platform_drift", out_dir, snakemake.input.published)  # noqa: F821
