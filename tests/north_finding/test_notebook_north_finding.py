"""The north_finding walkthrough notebook executes without errors and cites eqs. 47 and 50.

The notebook is run with nbclient in a fresh python3 kernel whose working directory is the
repository root and whose PYTHONPATH starts with it, so that ``derivations`` and ``pipeline``
import without installing the project (the first code cell also finds the root on its own).
"""

from __future__ import annotations

from pathlib import Path

import pytest

from tests import notebook_harness as harness

ROOT = Path(__file__).resolve().parents[2]
NOTEBOOK = ROOT / "notebooks" / "north_finding.ipynb"


def test_notebook_is_stored_without_outputs():
    harness.assert_stored_clean(NOTEBOOK)


@pytest.mark.parametrize("ref", ["eq. 47", "eq. 50"])
def test_notebook_cites_method3_equations(ref):
    cells = [c for c in harness.read(NOTEBOOK).cells if ref in c.source]
    assert cells, f"no cell references {ref!r}"


@pytest.mark.slow  # about 30 s (kernel start-up plus the SymPy derivations)
def test_notebook_executes_without_errors(monkeypatch):
    code = harness.execute(NOTEBOOK, monkeypatch)
    assert code, "the notebook has no code cells"
