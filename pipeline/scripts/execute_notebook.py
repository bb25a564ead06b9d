# Snakemake script: execute a notebook and export it as one self-contained HTML page (mathematics
# as MathML, figures as data URIs, no script or network resource, the same bytes every run; see
# pipeline/notebook_html.py). The kernel preloads the derivations the paper's derive step
# computed (derivations/memo.py): the same results, without deriving them again.

# The cyclic garbage collector is paused for the whole job, imports included (pipeline.job_gc):
# the export builds nbconvert's and BeautifulSoup's trees of the page, and the collector scanned
# them and the imported modules over and over (the kernel pauses its own, pipeline.notebook_kernel).
import os

from pipeline.job_gc import paused_gc

# derivations.memo.ENV_VAR, named here rather than imported: importing derivations imports SymPy
# (~0.4 CPU-s), which this process does not use (the kernel does; tests/shared/test_memo.py
# checks that the two names agree)
ENV_VAR = "INERTIAL_REPRO_DERIVATION_MEMO"

with paused_gc():
    from pipeline.atomic import write_text
    from pipeline.notebook_html import build
    from pipeline.script_log import logged

    with logged(snakemake.log[0], written=snakemake.output):  # noqa: F821
        # the kernel (inheriting this environment) preloads what the derive step computed
        os.environ[ENV_VAR] = os.path.abspath(snakemake.input.memo)  # noqa: F821
        write_text(snakemake.output[0], build(snakemake.input.notebook))  # noqa: F821
