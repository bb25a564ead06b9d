# Snakemake script: equation audit of one paper, from its derivation artefact
# (input.derivation, written by the derive rule: the checks, each a printed and a derived form).
# Writes equation_audit.csv (the contract) and equation_math.json (printed, derived and residual
# forms as MathML and SymPy srepr, for the reports).
from derivations.artefact import load
from derivations.checks import audit_outputs
from pipeline.atomic import write_csv, write_json
from pipeline.columns import AUDIT_COLUMNS
from pipeline.script_log import logged

with logged(snakemake.log[0], written=snakemake.output):  # noqa: F821
    frame, records = audit_outputs(load(snakemake.input.derivation)["checks"])  # noqa: F821
    write_csv(snakemake.output.csv, frame, AUDIT_COLUMNS)  # noqa: F821
    write_json(snakemake.output.math, records)  # noqa: F821
    print(frame["status"].value_counts().to_string())
