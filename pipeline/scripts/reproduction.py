# Snakemake script: the combined reproduction report, reports/reproduction.html and
# reports/reproduction.pdf (Typst via the typst package), from one document built once: the
# two formats of the same article, so one job reads the results and runs the papers' report
# functions once (two jobs used to build the same document twice, ~1.3 CPU-s each, and paid
# the imports twice).
# The collector is paused (pipeline.job_gc: no Matplotlib figure here; its ~390 collections
# took ~0.2 CPU-s, and the job's memory is the same without them) and freed memory is kept
# for reuse (pipeline.heap_reuse: ~85 MB fewer pages touched, the same peak): the job took
# 3.50 CPU-s, 3.17 with both (medians of 7 alternating runs, outputs byte-identical).
from pipeline.job_gc import paused_gc

with paused_gc():
    from pipeline.heap_reuse import keep_freed_memory

    keep_freed_memory()  # before the imports and the document allocate

    from pathlib import Path

    from pipeline.report.document import build_document
    from pipeline.report.reproduction_html import write_html
    from pipeline.report.reproduction_pdf import write_pdf
    from pipeline.script_log import logged

    with logged(snakemake.log[0], written=snakemake.output):  # noqa: F821
        root = Path.cwd()
        doc = build_document(
            root=root,
            results_dir=snakemake.config["results_dir"],  # noqa: F821
            reports_dir=snakemake.config["reports_dir"],  # noqa: F821
            config=Path(snakemake.input.config_file).parent,  # noqa: F821
        )
        html = write_html(doc, snakemake.output.html)  # noqa: F821
        for row in doc.scoreboard:
            print(f"{row.slug}: {row.line}")
        print(f"wrote {html} ({html.stat().st_size} bytes)")
        pdf = write_pdf(doc, snakemake.output.pdf, root=root)  # noqa: F821
        print(f"wrote {pdf} ({pdf.stat().st_size} bytes)")
