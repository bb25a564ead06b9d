# Snakemake script: verdicts of the platform-drift paper.
import sys
from pathlib import Path

from pipeline.platform_drift.verdicts import write_verdicts

with open(snakemake.log[0], "w") as log:  # noqa: F821
    sys.stderr = log
    results_dir = Path(snakemake.input.errors[0]).parents[1]  # noqa: F821
    write_verdicts(snakemake.input.published, results_dir, snakemake.output[0])  # noqa: F821
