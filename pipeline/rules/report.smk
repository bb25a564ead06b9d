# The combined report of every paper in config["papers"]: reports/reproduction.html and
# reports/reproduction.pdf (scoreboard, one section per paper, provenance), the two formats of
# one document, written by one job (the document is built once).


rule reproduction:
    input:
        **reproduction_inputs(),
        code=code(script="reproduction.py"),
        config_file="config/config.yaml",
    output:
        html=tagged(f"{REPORTS}/reproduction.html", "reproduction", "Reports", "reproduction"),
        pdf=tagged(f"{REPORTS}/reproduction.pdf", "reproduction", "Reports", "reproduction"),
    log:
        f"{RESULTS}/logs/reproduction.log",
    benchmark:
        f"{RESULTS}/benchmarks/reproduction.tsv"
    priority: job_priority(f"{RESULTS}/benchmarks/reproduction.tsv")
    conda:
        ENV
    threads: job_threads(f"{RESULTS}/benchmarks/reproduction.tsv")
    resources:
        **job_resources(f"{RESULTS}/benchmarks/reproduction.tsv"),
    script:
        "../scripts/reproduction.py"
