# Reproduction workflow: one include per paper; `snakemake --cores 2` (or `make reproduce`).
#
#   derivations --audit-->   results/<slug>/equation_audit.csv
#   derivations --codegen--> pipeline/generated/<slug>.py   (committed; checked fresh here)
#   scenarios   --simulate-> results/<slug>/<scenario>/*.csv
#   published   --compare--> results/<slug>/verdicts.csv
#   results     --figures--> results/<slug>/figures/
#   notebooks   --execute--> reports/notebooks/<slug>.html
#   everything  --report-->  reports/<slug>.html, reports/reproduction.html|pdf


configfile: "config/config.yaml"


# `snakemake --report reports/snakemake.html`: outputs tagged in pipeline/rules/*.smk
report: "reports/snakemake/workflow.rst"


include: "pipeline/rules/common.smk"
include: "pipeline/rules/north_finding.smk"
include: "pipeline/rules/platform_drift.smk"
include: "pipeline/rules/altimeter_attitude.smk"
include: "pipeline/rules/reproduction.smk"


rule all:
    input:
        rules.north_finding_all.input,
        rules.platform_drift_all.input,
        rules.altimeter_attitude_all.input,
        rules.reproduction_all.input,
