# Snakemake script: the latitude sweep of the platform-drift paper (a figure it lacks).
import sys

from pipeline.atomic import write_csv
from pipeline.platform_drift.sweep import SWEEP_COLUMNS, plot, sweep

with open(snakemake.log[0], "w") as log:  # noqa: F821
    sys.stderr = log
    frame = sweep(snakemake.input.scenario, log=lambda m: print(m, file=log, flush=True))
    write_csv(snakemake.output.csv, frame, SWEEP_COLUMNS)
    plot(frame, snakemake.output.png)  # and the SVG beside it (snakemake.output.svg)
