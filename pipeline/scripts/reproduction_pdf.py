# Snakemake script: the combined reproduction report as a PDF, reports/reproduction.pdf
# (Typst via the typst package; the same document as reports/reproduction.html).
from pathlib import Path

from pipeline.report.document import build_document
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
    out = write_pdf(doc, snakemake.output[0], root=root)  # noqa: F821
    print(f"wrote {out} ({out.stat().st_size} bytes)")
