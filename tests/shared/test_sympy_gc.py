"""pipeline.sympy_gc: the collector is off inside, back on after (or left off if it was), what
was alive is frozen at the end, also after an exception; the four SymPy scripts run in it."""

from __future__ import annotations

import ast
import gc
from pathlib import Path

import pytest

from pipeline.sympy_gc import paused_gc

ROOT = Path(__file__).resolve().parents[2]
SCRIPTS = ("derive.py", "derive_frames.py", "equation_audit.py", "codegen_check.py")


@pytest.fixture(autouse=True)
def _unfrozen():
    """Each test starts and ends with nothing frozen and the collector on."""
    gc.unfreeze()
    yield
    gc.unfreeze()
    gc.enable()


def test_off_inside_on_after_and_frozen():
    kept = [object() for _ in range(10)]
    with paused_gc():
        assert not gc.isenabled()
    assert gc.isenabled() and gc.get_freeze_count() >= len(kept)


def test_left_off_if_it_was_off_and_restored_after_an_exception():
    gc.disable()
    with paused_gc():
        pass
    assert not gc.isenabled()
    gc.enable()
    with pytest.raises(RuntimeError), paused_gc():
        raise RuntimeError("boom")
    assert gc.isenabled() and gc.get_freeze_count() > 0


@pytest.mark.parametrize("script", SCRIPTS)
def test_the_sympy_scripts_run_in_it(script):
    """The script's first statement imports paused_gc, its second is ``with paused_gc():``
    holding the rest (the imports of SymPy and the derivations included)."""
    tree = ast.parse((ROOT / "pipeline" / "scripts" / script).read_text(encoding="utf-8"))
    first, second, *rest = tree.body
    assert isinstance(first, ast.ImportFrom) and first.module == "pipeline.sympy_gc"
    assert isinstance(second, ast.With) and not rest
    call = second.items[0].context_expr
    assert isinstance(call, ast.Call) and getattr(call.func, "id", None) == "paused_gc"
