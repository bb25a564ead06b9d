# Snakemake script: equation audit of the north-finding paper.
import sys

from derivations.north_finding.audit import audit_frame
from pipeline.atomic import write_csv
from pipeline.columns import AUDIT_COLUMNS

with open(snakemake.log[0], "w") as log:  # noqa: F821
    sys.stderr = log
    frame = audit_frame()
    write_csv(snakemake.output[0], frame, AUDIT_COLUMNS)  # noqa: F821
    print(frame["status"].value_counts().to_string(), file=log)
