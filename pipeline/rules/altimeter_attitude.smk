# altimeter_attitude: roll/pitch from IMU + altimeter, linear KF on the third DCM row vs UKF.
from pipeline.altimeter_attitude.workflow import (  # noqa: E402
    FIGURES as AA_FIGURES,
    RESULT_FILES as AA_FILES,
    SIMULATION_CODE as AA_SIMULATION_CODE,
    SWEEP_FIGURE as AA_SWEEP_FIGURE,
    scenarios as aa_scenarios,
    validate_scenarios as aa_validate_scenarios,
)

AA = f"{RESULTS}/altimeter_attitude"
AA_SCENARIOS = aa_scenarios("config/scenarios/altimeter_attitude")
# every scenario file is validated when the workflow is parsed, before any job runs
aa_validate_scenarios(AA_SCENARIOS)
AA_PAPER_FIGURES = range(2, 13)  # Figs. 2-12 of the paper; the filter comparison and sweep are ours
AA_PUBLISHED_SCENARIO = config["altimeter_attitude"]["published_scenario"]
AA_DERIVATIONS = sorted(
    str(p) for p in Path("derivations/altimeter_attitude").glob("*.py") if p.name != "__init__.py"
)


rule altimeter_attitude_all:
    input:
        f"{REPORTS}/altimeter_attitude.html",
        f"{REPORTS}/notebooks/altimeter_attitude.html",


rule altimeter_attitude_codegen_check:
    input:
        AA_DERIVATIONS,
        "derivations/codegen.py",
        generated="pipeline/generated/altimeter_attitude.py",
    output:
        f"{AA}/codegen_check.txt",
    log:
        f"{AA}/logs/codegen_check.log",
    benchmark:
        f"{AA}/benchmarks/codegen_check.tsv"
    conda:
        ENV
    params:
        generator="derivations.altimeter_attitude.generate",
    script:
        "../scripts/codegen_check.py"


rule altimeter_attitude_audit:
    input:
        AA_DERIVATIONS,
        "derivations/checks.py",
    output:
        csv=tagged(f"{AA}/equation_audit.csv", "altimeter_attitude", "Equation audit", "audit"),
        math=f"{AA}/equation_math.json",
    log:
        f"{AA}/logs/audit.log",
    benchmark:
        f"{AA}/benchmarks/audit.tsv"
    conda:
        ENV
    params:
        audit="derivations.altimeter_attitude.audit",
    script:
        "../scripts/equation_audit.py"


rule altimeter_attitude_simulate:
    input:
        AA_SIMULATION_CODE,
        COMMON_CODE,
        codegen=f"{AA}/codegen_check.txt",
        scenario="config/scenarios/altimeter_attitude/{scenario}.yaml",
        schema=f"{SCHEMAS}/altimeter_attitude_scenario.schema.json",
    output:
        **{f: f"{AA}/{{scenario}}/{f}.csv" for f in AA_FILES if f != "rms_summary"},
        rms_summary=tagged(
            f"{AA}/{{scenario}}/rms_summary.csv",
            "altimeter_attitude",
            "Scenario summaries",
            "scenario_summary",
            scenario="{scenario}",
        ),
        provenance=f"{AA}/{{scenario}}/provenance.json",
    log:
        f"{AA}/logs/simulate_{{scenario}}.log",
    benchmark:
        f"{AA}/benchmarks/simulate_{{scenario}}.tsv"
    conda:
        ENV
    script:
        "../scripts/aa_simulate.py"


rule altimeter_attitude_sweep:
    input:
        AA_SIMULATION_CODE,
        "pipeline/altimeter_attitude/sweep.py",
        codegen=f"{AA}/codegen_check.txt",
        scenario=config["altimeter_attitude"]["sweep"]["base_scenario"],
    output:
        tagged(f"{AA}/sweep.csv", "altimeter_attitude", "Sweep", "sweep"),
    log:
        f"{AA}/logs/sweep.log",
    benchmark:
        f"{AA}/benchmarks/sweep.tsv"
    conda:
        ENV
    params:
        sweep=config["altimeter_attitude"]["sweep"],
    script:
        "../scripts/aa_sweep.py"


rule altimeter_attitude_verdicts:
    input:
        "pipeline/altimeter_attitude/verdicts.py",
        published="config/published/altimeter_attitude.yaml",
        schema=f"{SCHEMAS}/published_altimeter_attitude.schema.json",
        scenario=f"config/scenarios/altimeter_attitude/{AA_PUBLISHED_SCENARIO}.yaml",
        results=expand(f"{AA}/{AA_PUBLISHED_SCENARIO}/{{f}}.csv", f=AA_FILES),
    output:
        tagged(f"{AA}/verdicts.csv", "altimeter_attitude", "Verdicts", "verdicts"),
    log:
        f"{AA}/logs/verdicts.log",
    benchmark:
        f"{AA}/benchmarks/verdicts.tsv"
    conda:
        ENV
    script:
        "../scripts/aa_verdicts.py"


rule altimeter_attitude_figures:
    input:
        "pipeline/altimeter_attitude/figures.py",
        truth=f"{AA}/{AA_PUBLISHED_SCENARIO}/truth.csv",
        timeseries=f"{AA}/{AA_PUBLISHED_SCENARIO}/timeseries.csv",
        summary=f"{AA}/{AA_PUBLISHED_SCENARIO}/rms_summary.csv",
        published="config/published/altimeter_attitude.yaml",
    output:
        [
            tagged_figure(f"{AA}/figures/{f}", "altimeter_attitude", AA_PAPER_FIGURES)
            for f in AA_FIGURES
        ],
        # the vector twins the PDF report typesets
        [f"{AA}/figures/{Path(f).stem}.svg" for f in AA_FIGURES],
    log:
        f"{AA}/logs/figures.log",
    benchmark:
        f"{AA}/benchmarks/figures.tsv"
    conda:
        ENV
    script:
        "../scripts/aa_figures.py"


rule altimeter_attitude_sweep_figure:
    input:
        "pipeline/altimeter_attitude/figures.py",
        sweep=f"{AA}/sweep.csv",
        published="config/published/altimeter_attitude.yaml",
    output:
        tagged_figure(f"{AA}/figures/{AA_SWEEP_FIGURE}", "altimeter_attitude", AA_PAPER_FIGURES),
        f"{AA}/figures/{Path(AA_SWEEP_FIGURE).stem}.svg",
    log:
        f"{AA}/logs/sweep_figure.log",
    benchmark:
        f"{AA}/benchmarks/sweep_figure.tsv"
    conda:
        ENV
    script:
        "../scripts/aa_sweep_figure.py"


rule altimeter_attitude_report:
    input:
        PAGE_CODE,
        "pipeline/altimeter_attitude/report.py",
        "pipeline/altimeter_attitude/report_summary.py",
        "pipeline/altimeter_attitude/report_findings.py",
        "pipeline/altimeter_attitude/filter_comparison.py",
        "pipeline/altimeter_attitude/paper.py",
        "pipeline/altimeter_attitude/scenario.py",
        "pipeline/altimeter_attitude/workflow.py",
        audit=f"{AA}/equation_audit.csv",
        verdicts=f"{AA}/verdicts.csv",
        summaries=expand(f"{AA}/{{scenario}}/rms_summary.csv", scenario=AA_SCENARIOS),
        noise_free=expand(f"{AA}/{{scenario}}/noise_free.csv", scenario=AA_SCENARIOS),
        sweep=f"{AA}/sweep.csv",
        figures=[f"{AA}/figures/{f}" for f in AA_FIGURES + [AA_SWEEP_FIGURE]],
    output:
        tagged(f"{REPORTS}/altimeter_attitude.html", "altimeter_attitude", "Pages", "page"),
    log:
        f"{AA}/logs/report.log",
    benchmark:
        f"{AA}/benchmarks/report.tsv"
    conda:
        ENV
    script:
        "../scripts/aa_report.py"


rule altimeter_attitude_notebook:
    input:
        AA_DERIVATIONS,
        notebook="notebooks/altimeter_attitude.ipynb",
    output:
        tagged(
            f"{REPORTS}/notebooks/altimeter_attitude.html",
            "altimeter_attitude",
            "Pages",
            "notebook",
        ),
    log:
        f"{AA}/logs/notebook.log",
    benchmark:
        f"{AA}/benchmarks/notebook.tsv"
    conda:
        ENV
    script:
        "../scripts/execute_notebook.py"
