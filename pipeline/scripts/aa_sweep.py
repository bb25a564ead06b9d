# Snakemake script: the one-at-a-time sensitivity sweep of the altimeter-attitude paper.
from pipeline.altimeter_attitude.scenario import load_scenario
from pipeline.altimeter_attitude.sweep import run_sweep
from pipeline.atomic import write_csv
from pipeline.columns import SWEEP_COLUMNS

with open(snakemake.log[0], "w") as log:  # noqa: F821
    settings = snakemake.params.sweep  # noqa: F821
    frame = run_sweep(
        load_scenario(snakemake.input.scenario),  # noqa: F821
        dict(settings["values"]),
        int(settings["n_runs"]),
        tuple(settings["filters"]),
        log=lambda m: print(m, file=log, flush=True),
    )
    write_csv(snakemake.output[0], frame, SWEEP_COLUMNS)  # noqa: F821
