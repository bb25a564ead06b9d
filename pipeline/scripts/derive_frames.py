# Snakemake script: the shared frames module's derivations (derivations.generate_frames),
# computed once for every paper and pickled (derivations.artefact.build_frames); each paper's
# codegen check renders them and compares with pipeline/generated/frames.py.
# The cyclic garbage collector is paused for the whole job, imports included (pipeline.job_gc).
from pipeline.job_gc import paused_gc

with paused_gc():
    from derivations import artefact
    from pipeline.atomic import write_bytes
    from pipeline.script_log import logged

    with logged(snakemake.log[0], written=snakemake.output):  # noqa: F821
        built = artefact.build_frames()
        write_bytes(snakemake.output[0], artefact.dumps(built))  # noqa: F821
        print(f"{len(built['modules'][0]['functions'])} functions")
