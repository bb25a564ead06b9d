# Snakemake script: run one altimeter-attitude scenario (100-run Monte Carlo of every filter).
from pathlib import Path

from pipeline.altimeter_attitude.run import run_scenario

with open(snakemake.log[0], "w") as log:  # noqa: F821

    def say(message: str) -> None:
        print(message, file=log, flush=True)

    run_scenario(snakemake.input.scenario, Path(snakemake.output.rms_summary).parent, log=say)  # noqa: F821
