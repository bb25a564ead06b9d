# Snakemake script of every paper step: calls params.entry (pipeline.steps.run_step).
from pipeline.steps import run_step

run_step(snakemake)
