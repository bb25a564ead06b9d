# platform_drift: position error of a stable-platform INS with the position-independent algorithm.
from pipeline.platform_drift.workflow import (  # noqa: E402
    SIMULATION_CODE as PD_SIMULATION_CODE,
    scenarios as pd_scenarios,
    validate_scenarios as pd_validate_scenarios,
)

PD = f"{RESULTS}/platform_drift"
PD_SCENARIOS = pd_scenarios("config/scenarios/platform_drift")
# every scenario file is validated when the workflow is parsed, before any job runs
pd_validate_scenarios(PD_SCENARIOS)
PD_DERIVATIONS = sorted(
    str(p) for p in Path("derivations/platform_drift").glob("*.py") if p.name != "__init__.py"
)
PD_FILES = [
    "errors",
    "errors_diagnostic",
    "errors_long",
    "errors_long_diagnostic",
    "summary",
]
PD_PAPER_FIGURES = range(5, 9)  # Figs. 5-8 of the paper; fig9 (latitude sweep) is ours
PD_FIGURES = [
    "fig5_stationary.png",
    "fig6_latitude_change.png",
    "fig7_longitude_change.png",
    "fig8_lat_lon_change.png",
]


rule platform_drift_all:
    input:
        f"{REPORTS}/platform_drift.html",
        f"{REPORTS}/notebooks/platform_drift.html",


rule platform_drift_codegen_check:
    input:
        PD_DERIVATIONS,
        "derivations/codegen.py",
        generated="pipeline/generated/platform_drift.py",
    output:
        f"{PD}/codegen_check.txt",
    log:
        f"{PD}/logs/codegen_check.log",
    benchmark:
        f"{PD}/benchmarks/codegen_check.tsv"
    conda:
        ENV
    params:
        generator="derivations.platform_drift.generate",
    script:
        "../scripts/codegen_check.py"


rule platform_drift_audit:
    input:
        PD_DERIVATIONS,
        "derivations/checks.py",
    output:
        csv=tagged(f"{PD}/equation_audit.csv", "platform_drift", "Equation audit", "audit"),
        math=f"{PD}/equation_math.json",
    log:
        f"{PD}/logs/audit.log",
    benchmark:
        f"{PD}/benchmarks/audit.tsv"
    conda:
        ENV
    params:
        audit="derivations.platform_drift.audit",
    script:
        "../scripts/equation_audit.py"


rule platform_drift_simulate:
    input:
        PD_SIMULATION_CODE,
        COMMON_CODE,
        codegen=f"{PD}/codegen_check.txt",
        scenario="config/scenarios/platform_drift/{scenario}.yaml",
        schema=f"{SCHEMAS}/platform_drift_scenario.schema.json",
    output:
        **{f: f"{PD}/{{scenario}}/{f}.csv" for f in PD_FILES if f != "summary"},
        summary=tagged(
            f"{PD}/{{scenario}}/summary.csv",
            "platform_drift",
            "Scenario summaries",
            "scenario_summary",
            scenario="{scenario}",
        ),
        provenance=f"{PD}/{{scenario}}/provenance.json",
    log:
        f"{PD}/logs/simulate_{{scenario}}.log",
    benchmark:
        f"{PD}/benchmarks/simulate_{{scenario}}.tsv"
    conda:
        ENV
    script:
        "../scripts/pd_simulate.py"


rule platform_drift_verdicts:
    input:
        "pipeline/platform_drift/verdicts.py",
        published="config/published/platform_drift.yaml",
        schema=f"{SCHEMAS}/published_platform_drift.schema.json",
        errors=expand(f"{PD}/{{scenario}}/errors.csv", scenario=PD_SCENARIOS),
        errors_long=expand(f"{PD}/{{scenario}}/errors_long.csv", scenario=PD_SCENARIOS),
    output:
        tagged(f"{PD}/verdicts.csv", "platform_drift", "Verdicts", "verdicts"),
    log:
        f"{PD}/logs/verdicts.log",
    benchmark:
        f"{PD}/benchmarks/verdicts.tsv"
    conda:
        ENV
    script:
        "../scripts/pd_verdicts.py"


rule platform_drift_figures:
    input:
        "pipeline/platform_drift/figures.py",
        published="config/published/platform_drift.yaml",
        errors=expand(f"{PD}/{{scenario}}/errors.csv", scenario=PD_SCENARIOS),
        diagnostic=expand(f"{PD}/{{scenario}}/errors_diagnostic.csv", scenario=PD_SCENARIOS),
    output:
        [tagged_figure(f"{PD}/figures/{f}", "platform_drift", PD_PAPER_FIGURES) for f in PD_FIGURES],
        # the vector twins the PDF report typesets
        [f"{PD}/figures/{Path(f).stem}.svg" for f in PD_FIGURES],
    log:
        f"{PD}/logs/figures.log",
    benchmark:
        f"{PD}/benchmarks/figures.tsv"
    conda:
        ENV
    script:
        "../scripts/pd_figures.py"


rule platform_drift_report:
    input:
        PAGE_CODE,
        "pipeline/platform_drift/report.py",
        "pipeline/platform_drift/paper.py",
        "pipeline/platform_drift/scenario.py",
        audit=f"{PD}/equation_audit.csv",
        verdicts=f"{PD}/verdicts.csv",
        summaries=expand(f"{PD}/{{scenario}}/summary.csv", scenario=PD_SCENARIOS),
        figures=[f"{PD}/figures/{f}" for f in PD_FIGURES],
        sweep=f"{PD}/figures/fig9_latitude.png",
    output:
        tagged(f"{REPORTS}/platform_drift.html", "platform_drift", "Pages", "page"),
    log:
        f"{PD}/logs/report.log",
    benchmark:
        f"{PD}/benchmarks/report.tsv"
    conda:
        ENV
    script:
        "../scripts/pd_report.py"


rule platform_drift_latitude_sweep:
    input:
        PD_SIMULATION_CODE,
        "pipeline/platform_drift/sweep.py",
        scenario="config/scenarios/platform_drift/stationary.yaml",
        codegen=f"{PD}/codegen_check.txt",
    output:
        csv=f"{PD}/latitude_sweep.csv",
        png=tagged_figure(f"{PD}/figures/fig9_latitude.png", "platform_drift", PD_PAPER_FIGURES),
        svg=f"{PD}/figures/fig9_latitude.svg",
    log:
        f"{PD}/logs/latitude_sweep.log",
    benchmark:
        f"{PD}/benchmarks/latitude_sweep.tsv"
    conda:
        ENV
    script:
        "../scripts/pd_sweep.py"


rule platform_drift_notebook:
    input:
        PD_DERIVATIONS,
        f"{PD}/stationary/errors.csv",
        notebook="notebooks/platform_drift.ipynb",
    output:
        tagged(f"{REPORTS}/notebooks/platform_drift.html", "platform_drift", "Pages", "notebook"),
    log:
        f"{PD}/logs/notebook.log",
    benchmark:
        f"{PD}/benchmarks/notebook.tsv"
    conda:
        ENV
    script:
        "../scripts/execute_notebook.py"
