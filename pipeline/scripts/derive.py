# Snakemake script: the derivations of one paper, computed once and pickled
# (derivations.artefact): the audit's checks (params.audit: derivations.<slug>.audit) and the
# functions of the paper's generated module (params.generator) and of the shared frames module.
# The equation audit and the codegen check read this artefact instead of deriving again; the
# notebook preloads the results of the derivation functions computed on the way (the memo).
# The cyclic garbage collector is paused for the whole job, imports included (pipeline.job_gc).
from pipeline.job_gc import paused_gc

with paused_gc():
    from derivations import artefact, memo
    from pipeline.atomic import write_bytes
    from pipeline.script_log import logged

    with logged(snakemake.log[0], written=snakemake.output):  # noqa: F821
        built = artefact.build(snakemake.params.audit, snakemake.params.generator)  # noqa: F821
        write_bytes(snakemake.output[0], artefact.dumps(built))  # noqa: F821
        # what was derived on the way, for the paper's notebook (derivations.memo)
        write_bytes(snakemake.output.memo, memo.dumps(memo.snapshot()))  # noqa: F821
        print(
            f"{len(built['checks'])} checks, {sum(len(m['functions']) for m in built['modules'])} functions"
        )
