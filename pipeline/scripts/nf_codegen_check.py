# Snakemake script: fail if pipeline/generated/north_finding.py is not what the derivations generate.
import sys
from pathlib import Path

from derivations.north_finding.generate import source
from pipeline.atomic import write_text

with open(snakemake.log[0], "w") as log:  # noqa: F821
    sys.stderr = log
    generated = Path(snakemake.input.generated)  # noqa: F821
    if generated.read_text(encoding="utf-8") != source():
        raise SystemExit(
            f"{generated} is stale: run `python -m derivations.north_finding.generate` and commit it"
        )
    write_text(snakemake.output[0], f"{generated} is fresh\n")  # noqa: F821
