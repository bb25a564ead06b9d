# Snakemake script: the sensitivity-sweep figure of the altimeter-attitude paper.
from pathlib import Path

from pipeline.altimeter_attitude.figures import published_rms, write_sweep
from pipeline.config import load_yaml

with open(snakemake.log[0], "w") as log:  # noqa: F821
    published = published_rms(load_yaml(snakemake.input.published))  # noqa: F821
    write_sweep(Path(snakemake.input.sweep), Path(snakemake.output[0]), published)  # noqa: F821
    print(f"wrote {snakemake.output[0]}", file=log)  # noqa: F821
