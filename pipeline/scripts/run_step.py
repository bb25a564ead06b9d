# Snakemake script of every paper step: calls params.entry (pipeline.steps.run_step). The heap
# is frozen at the end, so the interpreter's exit does not scan it (pipeline.job_gc).
from pipeline.job_gc import frozen_at_exit

with frozen_at_exit():
    from pipeline.steps import run_step

    run_step(snakemake)  # noqa: F821
