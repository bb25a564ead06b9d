# Snakemake script: Figs. 1-5 of the north-finding paper and the sensitivity figure.
import sys
from pathlib import Path

from pipeline.north_finding.figures import run

with open(snakemake.log[0], "w") as log:  # noqa: F821
    sys.stderr = log
    run(
        Path(snakemake.input.mc_trials).parent,  # noqa: F821
        snakemake.input.published,  # noqa: F821
        Path(snakemake.output[0]).parent,  # noqa: F821
    )
