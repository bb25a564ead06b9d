# Reproduction workflow: `snakemake --cores 2` (or `make reproduce`). Every paper listed in
# config/config.yaml (`papers:`) is a plug-in, pipeline/<slug>/paper.py; nothing here names one.
#
#   derivations --audit-->    results/<slug>/equation_audit.csv        (derive.smk)
#   derivations --codegen-->  pipeline/generated/<slug>.py, checked fresh
#   notebooks   --execute-->  reports/notebooks/<slug>.html
#   scenarios   --<steps>-->  results/<slug>/<scenario>/..., verdicts, figures, reports/<slug>.html
#                                                                       (steps.smk, PAPER.steps)
#   everything  --report-->   reports/reproduction.html|pdf             (report.smk)


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
        rules.reproduction_html.output,
        rules.reproduction_pdf.output,
