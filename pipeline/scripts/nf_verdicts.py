# Snakemake script: verdict of every published number and claim of the north-finding paper.
import sys
from pathlib import Path

from pipeline.north_finding.verdicts import write_verdicts

with open(snakemake.log[0], "w") as log:  # noqa: F821
    sys.stderr = log
    write_verdicts(
        snakemake.input.published,  # noqa: F821
        Path(snakemake.input.estimates).parent,  # noqa: F821
        snakemake.output[0],  # noqa: F821
    )
