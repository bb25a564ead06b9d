# Shared set-up: config validation, import path, and the paper-independent inputs.
import os
import sys
from pathlib import Path

from snakemake.utils import validate

validate(config, "../../config/schemas/config.schema.json")

# scripts import `derivations` and `pipeline` from the repository root
os.environ["PYTHONPATH"] = os.pathsep.join(
    p for p in (workflow.basedir, os.environ.get("PYTHONPATH", "")) if p
)

sys.path.insert(0, workflow.basedir)

RESULTS = config["results_dir"]
REPORTS = config["reports_dir"]
SCHEMAS = "config/schemas"

# code every numeric rule depends on (edits rerun what they affect)
COMMON_CODE = [
    "pipeline/columns.py",
    "pipeline/config.py",
    "pipeline/atomic.py",
    "pipeline/provenance.py",
]
