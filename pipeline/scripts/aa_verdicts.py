# Snakemake script: verdicts of the altimeter-attitude paper (published scenario's results).
from pathlib import Path

from pipeline.altimeter_attitude.verdicts import write_verdicts

with open(snakemake.log[0], "w") as log:  # noqa: F821
    frame = write_verdicts(
        snakemake.input.published,  # noqa: F821
        snakemake.input.scenario,  # noqa: F821
        Path(snakemake.input.results[0]).parent,  # noqa: F821
        snakemake.output[0],  # noqa: F821
    )
    print(frame["verdict"].value_counts().to_string(), file=log)
