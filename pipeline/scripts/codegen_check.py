# Snakemake script: fail if a generated module differs from what its derivations generate: the
# paper's (input.generated) and the shared frames module every paper calls (input.frames), each
# rendered from the functions in its derivation artefact: the paper's (input.derivation, the
# derive rule, derivations.<slug>.generate) and the frames one (input.frames_derivation, the
# derive_frames rule, derivations.generate_frames).
# The cyclic garbage collector is paused for the whole job, imports included (pipeline.job_gc).
from pipeline.job_gc import paused_gc

with paused_gc():
    from pathlib import Path

    from derivations.artefact import load
    from derivations.codegen import render_module
    from pipeline.atomic import write_text
    from pipeline.script_log import logged

    with logged(snakemake.log[0], written=snakemake.output):  # noqa: F821
        modules = [
            *load(snakemake.input.derivation)["modules"],  # noqa: F821
            *load(snakemake.input.frames_derivation)["modules"],  # noqa: F821
        ]
        paths = [snakemake.input.generated, snakemake.input.frames]  # noqa: F821
        lines = []
        for module, path in zip(modules, paths, strict=True):
            generated = Path(path)
            if generated.read_text(encoding="utf-8") != render_module(
                module["functions"], module["header"]
            ):
                raise SystemExit(
                    f"{generated} is stale: run `python -m {module['generator']}` and commit it"
                )
            lines.append(f"{generated} is fresh\n")
        write_text(snakemake.output[0], "".join(lines))  # noqa: F821
