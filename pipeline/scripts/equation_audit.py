# Snakemake script: equation audit of one paper. params.audit: derivations.<slug>.audit
# Writes equation_audit.csv (the contract) and equation_math.json (printed, derived and residual
# forms as MathML and SymPy srepr, for the reports).
import importlib

from derivations.checks import audit_outputs
from pipeline.atomic import write_csv, write_json
from pipeline.columns import AUDIT_COLUMNS
from pipeline.script_log import logged

with logged(snakemake.log[0], written=snakemake.output):  # noqa: F821
    module = importlib.import_module(snakemake.params.audit)  # noqa: F821
    frame, records = audit_outputs(module.checks())
    write_csv(snakemake.output.csv, frame, AUDIT_COLUMNS)  # noqa: F821
    write_json(snakemake.output.math, records)  # noqa: F821
    print(frame["status"].value_counts().to_string())
