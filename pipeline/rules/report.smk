# The combined report of every paper in config["papers"]: reports/reproduction.html and
# reports/reproduction.pdf (scoreboard, one section per paper, provenance).


rule reproduction_html:
    input:
        **reproduction_inputs(),
        code=code(script="reproduction_report.py"),
        config_file="config/config.yaml",
    output:
        tagged(f"{REPORTS}/reproduction.html", "reproduction", "Reports", "reproduction"),
    log:
        f"{RESULTS}/logs/reproduction_html.log",
    benchmark:
        f"{RESULTS}/benchmarks/reproduction_html.tsv"
    priority: job_priority(f"{RESULTS}/benchmarks/reproduction_html.tsv")
    conda:
        ENV
    threads: job_threads(f"{RESULTS}/benchmarks/reproduction_html.tsv")
    resources:
        **job_resources(f"{RESULTS}/benchmarks/reproduction_html.tsv"),
    script:
        "../scripts/reproduction_report.py"


rule reproduction_pdf:
    input:
        **reproduction_inputs(),
        code=code(script="reproduction_pdf.py"),
        config_file="config/config.yaml",
    output:
        tagged(f"{REPORTS}/reproduction.pdf", "reproduction", "Reports", "reproduction"),
    log:
        f"{RESULTS}/logs/reproduction_pdf.log",
    benchmark:
        f"{RESULTS}/benchmarks/reproduction_pdf.tsv"
    priority: job_priority(f"{RESULTS}/benchmarks/reproduction_pdf.tsv")
    conda:
        ENV
    threads: job_threads(f"{RESULTS}/benchmarks/reproduction_pdf.tsv")
    resources:
        **job_resources(f"{RESULTS}/benchmarks/reproduction_pdf.tsv"),
    script:
        "../scripts/reproduction_pdf.py"
