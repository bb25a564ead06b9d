"""pipeline.job_gc: paused_gc's collector is off inside, back on after (or left off if it was),
what was alive is frozen at the end, also after an exception; frozen_at_exit freezes at the end
and leaves the collector as it was; every job script runs in one of the two."""

from __future__ import annotations

import ast
import gc
from pathlib import Path

import pytest

from pipeline.job_gc import frozen_at_exit, paused_gc

ROOT = Path(__file__).resolve().parents[2]
SCRIPTS = (
    "derive.py",
    "derive_frames.py",
    "equation_audit.py",
    "codegen_check.py",
    "reproduction.py",
)
#: the other job scripts: the collector on while they run, the heap frozen at the end
FROZEN_SCRIPTS = ("run_step.py",)


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


def test_frozen_at_exit_leaves_the_collector_and_freezes_also_after_an_exception():
    kept = [object() for _ in range(10)]
    with frozen_at_exit():
        assert gc.isenabled()
    assert gc.isenabled() and gc.get_freeze_count() >= len(kept)
    gc.unfreeze()
    with pytest.raises(RuntimeError), frozen_at_exit():
        raise RuntimeError("boom")
    assert gc.get_freeze_count() > 0


def _manager(script: str) -> str:
    """The name of the context manager the whole script runs in (asserting that shape: an
    import from pipeline.job_gc among imports and constants, then one ``with`` holding the
    rest)."""
    tree = ast.parse((ROOT / "pipeline" / "scripts" / script).read_text(encoding="utf-8"))
    *before, last = tree.body
    assert any(isinstance(s, ast.ImportFrom) and s.module == "pipeline.job_gc" for s in before)
    assert all(
        isinstance(s, ast.Import | ast.ImportFrom)
        or (isinstance(s, ast.Assign) and isinstance(s.value, ast.Constant))
        for s in before
    )
    assert isinstance(last, ast.With)
    call = last.items[0].context_expr
    assert isinstance(call, ast.Call)
    return getattr(call.func, "id", "")


@pytest.mark.parametrize("script", SCRIPTS)
def test_the_sympy_scripts_run_in_paused_gc(script):
    """The SymPy scripts (and the combined report's, which builds no Matplotlib figure):
    the script's first statement imports paused_gc, its second is ``with paused_gc():``
    holding the rest (the imports of SymPy and the derivations included)."""
    assert _manager(script) == "paused_gc"


@pytest.mark.parametrize("script", FROZEN_SCRIPTS)
def test_the_other_scripts_run_in_frozen_at_exit(script):
    assert _manager(script) == "frozen_at_exit"


def test_every_job_script_is_one_of_them():
    """A new job script gets one of the two (else its exit scans the heap: 0.1-0.4 s a job)."""
    scripts = {p.name for p in (ROOT / "pipeline" / "scripts").glob("*.py")}
    assert scripts == {*SCRIPTS, *FROZEN_SCRIPTS, "execute_notebook.py"}
    assert _manager("execute_notebook.py") == "paused_gc"
