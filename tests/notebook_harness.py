"""Shared harness of the notebook tests: read a notebook, check it is stored clean, execute it.

The notebook runs with nbclient in a fresh python3 kernel whose working directory is the
repository root and whose PYTHONPATH starts with it, so ``derivations`` and ``pipeline`` import
without installing the project. Every cell error is collected and reported at once.
"""

from __future__ import annotations

import os
import time
from pathlib import Path

import nbformat
from nbclient import NotebookClient

from tests.hang_guard import HANG_GUARD_S

ROOT = Path(__file__).resolve().parents[1]
TIMEOUT_S = HANG_GUARD_S


def read(path: Path) -> nbformat.NotebookNode:
    return nbformat.read(path, as_version=4)


def assert_stored_clean(path: Path) -> None:
    """Valid nbformat, python3 kernelspec, no stored outputs or execution counts."""
    nb = read(path)
    nbformat.validate(nb)
    assert nb.metadata["kernelspec"]["name"] == "python3"
    for i, cell in enumerate(nb.cells):
        if cell.cell_type == "code":
            assert cell.outputs == [], f"cell {i} has stored outputs"
            assert cell.execution_count is None, f"cell {i} has an execution count"


def stream_text(cell: nbformat.NotebookNode) -> str:
    return "".join(out.get("text", "") for out in cell.outputs if out.output_type == "stream")


def execute(path: Path, monkeypatch) -> list[nbformat.NotebookNode]:
    """Execute the notebook; assert no cell raised and every code cell ran; return the
    executed code cells."""
    nb = read(path)
    # the kernel inherits this environment: make the repository importable in it
    existing = os.environ.get("PYTHONPATH", "")
    monkeypatch.setenv("PYTHONPATH", str(ROOT) + (os.pathsep + existing if existing else ""))
    client = NotebookClient(
        nb,
        timeout=TIMEOUT_S,
        kernel_name="python3",
        resources={"metadata": {"path": str(ROOT)}},
        allow_errors=True,  # collect every error, then report them below
    )
    start = time.perf_counter()
    client.execute()
    elapsed = time.perf_counter() - start
    errors = []
    for i, cell in enumerate(nb.cells):
        if cell.cell_type != "code":
            continue
        for out in cell.outputs:
            if out.output_type == "error":
                first = cell.source.splitlines()[0] if cell.source else ""
                errors.append(f"cell {i} ({first!r}): {out.ename}: {out.evalue}")
    assert not errors, "notebook cells raised:\n" + "\n".join(errors)
    code = [c for c in nb.cells if c.cell_type == "code"]
    assert all(c.execution_count is not None for c in code), "not every code cell ran"
    assert elapsed < TIMEOUT_S
    return code
