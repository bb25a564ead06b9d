# Snakemake script: equation audit of one paper, from its derivation artefact
# (input.derivation, written by the derive rule: the checks, each a printed and a derived form).
# Writes equation_audit.csv (the contract) and equation_math.json (printed, derived and residual
# forms as MathML and SymPy srepr, for the reports). The rows are strings: written without
# pandas (pipeline.atomic.write_text_csv, the bytes write_csv gives them; ~0.3 CPU-s a job).
# The cyclic garbage collector is paused for the whole job, imports included (pipeline.job_gc).
from pipeline.job_gc import paused_gc

with paused_gc():
    from collections import Counter

    from derivations.artefact import load
    from derivations.checks import audit_records
    from pipeline.atomic import write_json, write_text_csv
    from pipeline.columns import AUDIT_COLUMNS
    from pipeline.script_log import logged

    with logged(snakemake.log[0], written=snakemake.output):  # noqa: F821
        rows, records = audit_records(load(snakemake.input.derivation)["checks"])  # noqa: F821
        write_text_csv(snakemake.output.csv, rows, AUDIT_COLUMNS)  # noqa: F821
        write_json(snakemake.output.math, records)  # noqa: F821
        counts = Counter(row["status"] for row in rows).most_common()
        print("\n".join(["status", *(f"{status:<13} {n:>4}" for status, n in counts)]))
