# Reproduction workflow: `snakemake --cores 2` (or `make reproduce`). Every paper listed in
# config/config.yaml (`papers:`) is a plug-in, pipeline/<slug>/paper.py; nothing here names one.
#
#   derivations --audit-->    results/<slug>/equation_audit.csv        (derive.smk)
#   derivations --codegen-->  pipeline/generated/<slug>.py, checked fresh
#   notebooks   --execute-->  reports/notebooks/<slug>.html
#   scenarios   --<steps>-->  results/<slug>/<scenario>/..., verdicts, figures, reports/<slug>.html
#                                                                       (steps.smk, PAPER.steps)
#   everything  --report-->   reports/reproduction.html|pdf             (report.smk)


# config/config.yaml read strictly first: Snakemake's own reader (the `configfile:` directive)
# reports binary bytes, unknown tags, tabs or an empty file with its stack frames
import sys

sys.path.insert(0, workflow.basedir)
from pipeline.config import ConfigError  # noqa: E402
from pipeline.registry import check_config_file  # noqa: E402

try:
    check_config_file(f"{workflow.basedir}/config/config.yaml")
except ConfigError as _error:
    sys.stderr.write(f"{_error}\n")
    raise SystemExit(1) from None


configfile: "config/config.yaml"


# `snakemake --report reports/snakemake.html`: outputs tagged in pipeline/rules/*.smk
report: "reports/snakemake/workflow.rst"


include: "pipeline/rules/common.smk"


wildcard_constraints:
    paper="|".join(PAPERS),


include: "pipeline/rules/derive.smk"
include: "pipeline/rules/steps.smk"
include: "pipeline/rules/report.smk"


rule all:
    input:
        [paper_targets(slug) for slug in PAPERS],
        rules.reproduction.output,


# Under a cluster executor (`make reproduce-slurm`) the targets and the steps that take seconds
# run here, on the login node: submitting one costs more than running it (common.smk).
workflow.localrules(*local_rules(workflow.rules))
