# Snakemake script: equation audit of one paper. params.audit: e.g. derivations.platform_drift.audit
import importlib
import sys

from pipeline.atomic import write_csv
from pipeline.columns import AUDIT_COLUMNS

with open(snakemake.log[0], "w") as log:  # noqa: F821
    sys.stderr = log
    frame = importlib.import_module(snakemake.params.audit).audit_frame()  # noqa: F821
    write_csv(snakemake.output[0], frame, AUDIT_COLUMNS)  # noqa: F821
    print(frame["status"].value_counts().to_string(), file=log)
