# Snakemake script: execute a notebook and export it as one self-contained HTML page (mathematics
# as MathML, figures as data URIs, no script or network resource, the same bytes every run; see
# pipeline/notebook_html.py).
import sys

from pipeline.atomic import write_text
from pipeline.notebook_html import build

with open(snakemake.log[0], "w") as log:  # noqa: F821
    sys.stderr = log
    write_text(snakemake.output[0], build(snakemake.input.notebook))  # noqa: F821
