# Shared set-up: config validation, import path, the paper-independent inputs and the tags of
# `snakemake --report reports/snakemake.html`.
import os
import re
import sys
from pathlib import Path

from snakemake.utils import validate

validate(config, "../../config/schemas/config.schema.json")

# Scripts import `derivations` and `pipeline` from the repository root: the workflow puts the
# root on the PYTHONPATH of its jobs (set here for them; nothing is required from the caller).
os.environ.update(
    PYTHONPATH=os.pathsep.join(p for p in (workflow.basedir, os.getenv("PYTHONPATH", "")) if p)
)

sys.path.insert(0, workflow.basedir)

RESULTS = config["results_dir"]
REPORTS = config["reports_dir"]
SCHEMAS = "config/schemas"
# The software every rule runs with, for `snakemake --sdm conda`. `make reproduce` runs the
# rules in the hash-checked .venv built from environment.lock instead; a test keeps the pins of
# this file equal to the lock's.
ENV = "../envs/inertial-repro.yaml"
# Captions of the outputs tagged for `snakemake --report` (reStructuredText, Jinja-templated).
CAPTIONS = "../../reports/snakemake"

# code every numeric rule depends on (edits rerun what they affect)
COMMON_CODE = [
    "pipeline/columns.py",
    "pipeline/config.py",
    "pipeline/atomic.py",
    "pipeline/provenance.py",
]
# the shared code a per-paper page is rendered with (pipeline.report.page_html.build_page)
PAGE_CODE = [
    "pipeline/paper.py",
    "pipeline/registry.py",
    "pipeline/report/model.py",
    "pipeline/report/page_html.py",
    "pipeline/report/blocks_html.py",
    "pipeline/report/html.py",
    "pipeline/report/equations.py",
    "pipeline/report/figures.py",
]


def tagged(path, paper, subcategory, caption, **labels):
    """``path`` marked for the Snakemake report: category = the paper's slug, one caption per
    kind of output (``reports/snakemake/<caption>.rst``), ``labels`` shown beside it."""
    return report(
        path,
        caption=f"{CAPTIONS}/{caption}.rst",
        category=paper,
        subcategory=subcategory,
        labels=labels or None,
    )


def tagged_figure(path, paper, paper_figures):
    """A figure for the Snakemake report, labelled with the paper's figure number (from the
    file name, ``fig<N>_...``) or as a figure the paper does not have."""
    name = Path(path).name
    m = re.match(r"fig(\d+)_", name)
    number = int(m.group(1)) if m else None
    figure = f"Fig. {number}" if number in paper_figures else "not in the paper"
    return tagged(path, paper, "Figures", "figure", figure=figure, file=name)
