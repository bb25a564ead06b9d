# Snakemake script: fail if a generated module differs from what its derivations generate: the
# paper's (params.generator: derivations.<slug>.generate, with source()) and the shared frames
# module every paper calls (derivations.generate_frames).
import importlib
from pathlib import Path

from pipeline.atomic import write_text
from pipeline.script_log import logged

with logged(snakemake.log[0], written=snakemake.output):  # noqa: F821
    pairs = [
        (importlib.import_module(snakemake.params.generator), snakemake.input.generated),  # noqa: F821
        (importlib.import_module("derivations.generate_frames"), snakemake.input.frames),  # noqa: F821
    ]
    lines = []
    for generator, path in pairs:
        generated = Path(path)
        if generated.read_text(encoding="utf-8") != generator.source():
            raise SystemExit(
                f"{generated} is stale: run `python -m {generator.__name__}` and commit it"
            )
        lines.append(f"{generated} is fresh\n")
    write_text(snakemake.output[0], "".join(lines))  # noqa: F821
