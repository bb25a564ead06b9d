# Snakemake script: fail if a generated module differs from what its derivations generate.
# params.generator: the module with source(), derivations.<slug>.generate
import importlib
from pathlib import Path

from pipeline.atomic import write_text
from pipeline.script_log import logged

with logged(snakemake.log[0], written=snakemake.output):  # noqa: F821
    generator = importlib.import_module(snakemake.params.generator)  # noqa: F821
    generated = Path(snakemake.input.generated)  # noqa: F821
    if generated.read_text(encoding="utf-8") != generator.source():
        raise SystemExit(
            f"{generated} is stale: run `python -m {generator.__name__}` and commit it"
        )
    write_text(snakemake.output[0], f"{generated} is fresh\n")  # noqa: F821
