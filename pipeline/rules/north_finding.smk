# north_finding: levelling and north finding with one accelerometer and one gyro on a turntable.
import sys

sys.path.insert(0, workflow.basedir)
from pipeline.north_finding.workflow import (  # noqa: E402
    DERIVATION_CODE,
    SIMULATION_CODE,
    scenarios,
    validate_scenarios,
)

NF = f"{RESULTS}/north_finding"
NF_SCENARIOS = scenarios("config/scenarios/north_finding")
# every scenario file is validated when the workflow is parsed, before any job runs
validate_scenarios(NF_SCENARIOS)
NF_PUBLISHED_SCENARIO = config["north_finding"]["published_scenario"]
NF_FILES = [
    "estimates.csv",
    "mc_trials.csv",
    "mc_summary.csv",
    "error_budget.csv",
    "sensitivity.csv",
    "provenance.json",
]
NF_PAPER_FIGURES = range(1, 6)  # Figs. 1-5 of the paper; fig6 is ours
NF_FIGURES = [
    f"fig{i}_{n}.png"
    for i, n in enumerate(["roll", "pitch", "azimuth", "bias", "scale", "sensitivity"], 1)
]


rule north_finding_all:
    input:
        f"{REPORTS}/north_finding.html",
        f"{REPORTS}/notebooks/north_finding.html",


rule north_finding_codegen_check:
    input:
        DERIVATION_CODE,
        generated="pipeline/generated/north_finding.py",
    output:
        f"{NF}/codegen_check.txt",
    log:
        f"{NF}/logs/codegen_check.log",
    benchmark:
        f"{NF}/benchmarks/codegen_check.tsv"
    conda:
        ENV
    params:
        generator="derivations.north_finding.generate",
    script:
        "../scripts/codegen_check.py"


rule north_finding_audit:
    input:
        DERIVATION_CODE,
        "derivations/checks.py",
        "derivations/north_finding/printed.py",
        "derivations/north_finding/audit.py",
    output:
        csv=tagged(f"{NF}/equation_audit.csv", "north_finding", "Equation audit", "audit"),
        math=f"{NF}/equation_math.json",
    log:
        f"{NF}/logs/audit.log",
    benchmark:
        f"{NF}/benchmarks/audit.tsv"
    conda:
        ENV
    params:
        audit="derivations.north_finding.audit",
    script:
        "../scripts/equation_audit.py"


rule north_finding_simulate:
    input:
        SIMULATION_CODE,
        COMMON_CODE,
        codegen=f"{NF}/codegen_check.txt",
        scenario="config/scenarios/north_finding/{scenario}.yaml",
        schema=f"{SCHEMAS}/north_finding_scenario.schema.json",
    output:
        **{f.split(".")[0]: f"{NF}/{{scenario}}/{f}" for f in NF_FILES},
    log:
        f"{NF}/logs/simulate_{{scenario}}.log",
    benchmark:
        f"{NF}/benchmarks/simulate_{{scenario}}.tsv"
    conda:
        ENV
    script:
        "../scripts/nf_simulate.py"


rule north_finding_verdicts:
    input:
        "pipeline/compare.py",
        published="config/published/north_finding.yaml",
        schema=f"{SCHEMAS}/published.schema.json",
        estimates=f"{NF}/{NF_PUBLISHED_SCENARIO}/estimates.csv",
        mc_trials=f"{NF}/{NF_PUBLISHED_SCENARIO}/mc_trials.csv",
        error_budget=f"{NF}/{NF_PUBLISHED_SCENARIO}/error_budget.csv",
    output:
        tagged(f"{NF}/verdicts.csv", "north_finding", "Verdicts", "verdicts"),
    log:
        f"{NF}/logs/verdicts.log",
    benchmark:
        f"{NF}/benchmarks/verdicts.tsv"
    conda:
        ENV
    script:
        "../scripts/nf_verdicts.py"


rule north_finding_figures:
    input:
        "pipeline/north_finding/figures.py",
        published="config/published/north_finding.yaml",
        estimates=f"{NF}/{NF_PUBLISHED_SCENARIO}/estimates.csv",
        mc_trials=f"{NF}/{NF_PUBLISHED_SCENARIO}/mc_trials.csv",
        sensitivity=f"{NF}/{NF_PUBLISHED_SCENARIO}/sensitivity.csv",
        provenance=f"{NF}/{NF_PUBLISHED_SCENARIO}/provenance.json",
    output:
        [tagged_figure(f"{NF}/figures/{f}", "north_finding", NF_PAPER_FIGURES) for f in NF_FIGURES],
        # the vector twins the PDF report typesets
        [f"{NF}/figures/{Path(f).stem}.svg" for f in NF_FIGURES],
    log:
        f"{NF}/logs/figures.log",
    benchmark:
        f"{NF}/benchmarks/figures.tsv"
    conda:
        ENV
    script:
        "../scripts/nf_figures.py"


rule north_finding_notebook:
    input:
        DERIVATION_CODE,
        notebook="notebooks/north_finding.ipynb",
    output:
        tagged(f"{REPORTS}/notebooks/north_finding.html", "north_finding", "Pages", "notebook"),
    log:
        f"{NF}/logs/notebook.log",
    benchmark:
        f"{NF}/benchmarks/notebook.tsv"
    conda:
        ENV
    script:
        "../scripts/execute_notebook.py"


rule north_finding_report:
    input:
        PAGE_CODE,
        "pipeline/north_finding/report.py",
        "pipeline/north_finding/report_results.py",
        "pipeline/north_finding/error_propagation.py",
        "pipeline/north_finding/paper.py",
        "pipeline/north_finding/figures.py",
        "pipeline/north_finding/scenario.py",
        "pipeline/compare.py",
        audit=f"{NF}/equation_audit.csv",
        verdicts=f"{NF}/verdicts.csv",
        published="config/published/north_finding.yaml",
        scenarios=expand(f"{NF}/{{scenario}}/estimates.csv", scenario=NF_SCENARIOS),
        scenario_files=expand(
            "config/scenarios/north_finding/{scenario}.yaml", scenario=NF_SCENARIOS
        ),
        figures=[f"{NF}/figures/{f}" for f in NF_FIGURES],
    output:
        tagged(f"{REPORTS}/north_finding.html", "north_finding", "Pages", "page"),
    log:
        f"{NF}/logs/report.log",
    benchmark:
        f"{NF}/benchmarks/report.tsv"
    conda:
        ENV
    script:
        "../scripts/nf_report.py"
