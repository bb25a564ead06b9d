# Snakemake script: run one platform-drift scenario.
from pathlib import Path

from pipeline.platform_drift.run import run_scenario

with open(snakemake.log[0], "w") as log:  # noqa: F821

    def say(message: str) -> None:
        print(message, file=log, flush=True)

    run_scenario(snakemake.input.scenario, Path(snakemake.output.errors).parent, log=say)  # noqa: F821
