# Snakemake script: the combined reproduction report, reports/reproduction.html.
from pathlib import Path

from pipeline.report.document import build_document
from pipeline.report.reproduction_html import write_html
from pipeline.script_log import logged

with logged(snakemake.log[0], written=snakemake.output):  # noqa: F821
    doc = build_document(
        root=Path.cwd(),
        results_dir=snakemake.config["results_dir"],  # noqa: F821
        reports_dir=snakemake.config["reports_dir"],  # noqa: F821
        config=Path(snakemake.input.config_file).parent,  # noqa: F821
    )
    out = write_html(doc, snakemake.output[0])  # noqa: F821
    for row in doc.scoreboard:
        print(f"{row.slug}: {row.line}")
    print(f"wrote {out} ({out.stat().st_size} bytes)")
