# The combined report of all papers: reports/reproduction.html and reports/reproduction.pdf
# (scoreboard, one section per paper, provenance), built from every paper's results and page.
# Uses NF, PD, AA and the figure and scenario lists of the per-paper rule files.
# the document (pipeline.report.document.build_document): shared modules, and each paper's
# report sections (the code its page rule lists)
DOCUMENT_CODE = [
    *PAGE_CODE,
    "pipeline/report/document.py",
    "pipeline/report/scoreboard.py",
    "pipeline/report/published.py",
    "pipeline/report/paper_section.py",
    "pipeline/report/provenance_section.py",
    *[str(f) for f in rules.north_finding_report.input if str(f).startswith("pipeline/")],
    *[str(f) for f in rules.platform_drift_report.input if str(f).startswith("pipeline/")],
    *[str(f) for f in rules.altimeter_attitude_report.input if str(f).startswith("pipeline/")],
]
REPRODUCTION_CODE = [*DOCUMENT_CODE, "pipeline/report/reproduction_html.py"]
REPRODUCTION_PDF_CODE = [
    *DOCUMENT_CODE,
    "pipeline/report/reproduction_pdf.py",
    "pipeline/report/typst_math.py",
]
REPRODUCTION_FIGURES = (
    [f"{NF}/figures/{f}" for f in NF_FIGURES]
    + [f"{PD}/figures/{f}" for f in PD_FIGURES + ["fig9_latitude.png"]]
    + [f"{AA}/figures/{f}" for f in AA_FIGURES + [AA_SWEEP_FIGURE]]
)
# the PDF typesets the SVG beside each PNG
REPRODUCTION_SVG = [str(Path(f).with_suffix(".svg")) for f in REPRODUCTION_FIGURES]
REPRODUCTION_PROVENANCE = (
    expand(f"{NF}/{{scenario}}/provenance.json", scenario=NF_SCENARIOS)
    + expand(f"{PD}/{{scenario}}/provenance.json", scenario=PD_SCENARIOS)
    + expand(f"{AA}/{{scenario}}/provenance.json", scenario=AA_SCENARIOS)
)
REPRODUCTION_SCENARIO_FILES = (
    expand("config/scenarios/north_finding/{scenario}.yaml", scenario=NF_SCENARIOS)
    + expand("config/scenarios/platform_drift/{scenario}.yaml", scenario=PD_SCENARIOS)
    + expand("config/scenarios/altimeter_attitude/{scenario}.yaml", scenario=AA_SCENARIOS)
)


rule reproduction_all:
    input:
        f"{REPORTS}/reproduction.html",
        f"{REPORTS}/reproduction.pdf",


REPRODUCTION_INPUTS = dict(
    config_file="config/config.yaml",
    audits=[f"{d}/equation_audit.csv" for d in (NF, PD, AA)],
    math=[f"{d}/equation_math.json" for d in (NF, PD, AA)],
    verdicts=[f"{d}/verdicts.csv" for d in (NF, PD, AA)],
    published=expand("config/published/{paper}.yaml", paper=config["papers"]),
    scenarios=REPRODUCTION_SCENARIO_FILES,
    provenance=REPRODUCTION_PROVENANCE,
    figures=REPRODUCTION_FIGURES,
    # not read: the pages' rules declare every results file the papers' report sections read
    # (build_document calls the same section functions), so their inputs are built first
    pages=expand(f"{REPORTS}/{{paper}}.html", paper=config["papers"]),
    notebooks=expand(f"{REPORTS}/notebooks/{{paper}}.html", paper=config["papers"]),
)


rule reproduction_html:
    input:
        REPRODUCTION_CODE,
        COMMON_CODE,
        **REPRODUCTION_INPUTS,
    output:
        tagged(f"{REPORTS}/reproduction.html", "reproduction", "Reports", "reproduction"),
    log:
        f"{RESULTS}/logs/reproduction_html.log",
    benchmark:
        f"{RESULTS}/benchmarks/reproduction_html.tsv"
    conda:
        ENV
    script:
        "../scripts/reproduction_report.py"


rule reproduction_pdf:
    input:
        REPRODUCTION_PDF_CODE,
        COMMON_CODE,
        REPRODUCTION_SVG,
        **REPRODUCTION_INPUTS,
    output:
        tagged(f"{REPORTS}/reproduction.pdf", "reproduction", "Reports", "reproduction"),
    log:
        f"{RESULTS}/logs/reproduction_pdf.log",
    benchmark:
        f"{RESULTS}/benchmarks/reproduction_pdf.tsv"
    conda:
        ENV
    script:
        "../scripts/reproduction_pdf.py"
