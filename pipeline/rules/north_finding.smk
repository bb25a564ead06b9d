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
NF_FILES = ["estimates.csv", "mc_trials.csv", "mc_summary.csv", "error_budget.csv", "sensitivity.csv", "provenance.json"]
NF_FIGURES = [f"fig{i}_{n}.png" for i, n in enumerate(["roll", "pitch", "azimuth", "bias", "scale", "sensitivity"], 1)]


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
    params:
        generator="derivations.north_finding.generate",
    log:
        f"{NF}/logs/codegen_check.log",
    benchmark:
        f"{NF}/benchmarks/codegen_check.tsv"
    script:
        "../scripts/codegen_check.py"


rule north_finding_audit:
    input:
        DERIVATION_CODE,
        "derivations/checks.py",
        "derivations/north_finding/printed.py",
        "derivations/north_finding/audit.py",
    output:
        csv=f"{NF}/equation_audit.csv",
        math=f"{NF}/equation_math.json",
    params:
        audit="derivations.north_finding.audit",
    log:
        f"{NF}/logs/audit.log",
    benchmark:
        f"{NF}/benchmarks/audit.tsv"
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
        f"{NF}/verdicts.csv",
    log:
        f"{NF}/logs/verdicts.log",
    benchmark:
        f"{NF}/benchmarks/verdicts.tsv"
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
        [f"{NF}/figures/{f}" for f in NF_FIGURES],
    log:
        f"{NF}/logs/figures.log",
    benchmark:
        f"{NF}/benchmarks/figures.tsv"
    script:
        "../scripts/nf_figures.py"


rule north_finding_notebook:
    input:
        DERIVATION_CODE,
        notebook="notebooks/north_finding.ipynb",
    output:
        f"{REPORTS}/notebooks/north_finding.html",
    log:
        f"{NF}/logs/notebook.log",
    benchmark:
        f"{NF}/benchmarks/notebook.tsv"
    script:
        "../scripts/execute_notebook.py"


rule north_finding_report:
    input:
        "pipeline/report/north_finding.py",
        "pipeline/report/html.py",
        audit=f"{NF}/equation_audit.csv",
        verdicts=f"{NF}/verdicts.csv",
        published="config/published/north_finding.yaml",
        scenarios=expand(f"{NF}/{{scenario}}/estimates.csv", scenario=NF_SCENARIOS),
        scenario_files=expand("config/scenarios/north_finding/{scenario}.yaml", scenario=NF_SCENARIOS),
        figures=[f"{NF}/figures/{f}" for f in NF_FIGURES],
    output:
        f"{REPORTS}/north_finding.html",
    log:
        f"{NF}/logs/report.log",
    benchmark:
        f"{NF}/benchmarks/report.tsv"
    script:
        "../scripts/nf_report.py"
