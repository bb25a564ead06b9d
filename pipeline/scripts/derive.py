# Snakemake script: the derivations of one paper, computed once and pickled
# (derivations.artefact): the audit's checks (params.audit: derivations.<slug>.audit) and the
# functions of the paper's generated module (params.generator) and of the shared frames module.
# The equation audit and the codegen check read this artefact instead of deriving again.
from derivations import artefact
from pipeline.atomic import write_bytes
from pipeline.script_log import logged

with logged(snakemake.log[0], written=snakemake.output):  # noqa: F821
    built = artefact.build(snakemake.params.audit, snakemake.params.generator)  # noqa: F821
    write_bytes(snakemake.output[0], artefact.dumps(built))  # noqa: F821
    print(
        f"{len(built['checks'])} checks, {sum(len(m['functions']) for m in built['modules'])} functions"
    )
