# Snakemake script: execute a notebook and export it to HTML (outputs embedded, no network).
import sys

import nbformat
from nbclient import NotebookClient
from nbconvert import HTMLExporter

from pipeline.atomic import write_text

with open(snakemake.log[0], "w") as log:  # noqa: F821
    sys.stderr = log
    nb = nbformat.read(snakemake.input.notebook, as_version=4)  # noqa: F821
    NotebookClient(
        nb, timeout=600, kernel_name="python3", resources={"metadata": {"path": "."}}
    ).execute()
    body, _ = HTMLExporter(embed_images=True).from_notebook_node(nb)
    write_text(snakemake.output[0], body)  # noqa: F821
