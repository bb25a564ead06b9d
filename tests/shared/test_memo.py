"""The derivation memo across processes (derivations.memo): what a paper's derive step computes
on the way is what a fresh process derives for the same call, so a notebook that preloads it
shows what it would have derived itself; a preload reaches functions imported after it; a
caller's edit of a result never reaches the next caller."""

from __future__ import annotations

import os
import pickle
import subprocess
import sys

import pytest
import sympy as sp

from derivations import memo
from pipeline.registry import ROOT, load_papers  # the bytes across runs: test_byte_identity

# In a fresh process: build the paper's artefact as the derive step does and write its memo.
_DERIVE = """
import sys
from derivations import artefact, memo
artefact.build(sys.argv[1], sys.argv[2])
sys.stdout.buffer.write(memo.dumps(memo.snapshot()))
"""

# The text a result is compared by: srepr of each SymPy object in it (assumptions included); a
# plain object (the Setting a covariance_identity result carries) by its class and attributes.
_TEXT = """
import sympy as sp

def text(value):
    if isinstance(value, dict):
        return "{" + ", ".join(f"{k!r}: {text(v)}" for k, v in value.items()) + "}"
    if isinstance(value, (list, tuple)):
        return type(value).__name__ + "(" + ", ".join(text(v) for v in value) + ")"
    if isinstance(value, (sp.Basic, sp.MatrixBase)) or not hasattr(value, "__dict__"):
        return sp.srepr(value)
    return type(value).__qualname__ + text(dict(sorted(vars(value).items())))
"""
_namespace: dict = {}
exec(_TEXT, _namespace)
_text = _namespace["text"]

# In another fresh process: call every function of a snapshot with its arguments, without the
# snapshot (the notebook's path when it runs alone), and write {function: [(key, text)]}; an
# argument keyed by its contents (a matrix, an object: memo.freeze) is rebuilt from the key.
_FRESH = (
    _TEXT
    + """
import importlib, pickle, sys
from derivations.memo import thaw
snap = pickle.loads(sys.stdin.buffer.read())
out = {}
for name, results in snap.items():
    module, _, qualname = name.rpartition(".")
    fn = getattr(importlib.import_module(module), qualname)
    out[name] = [
        (repr(key), text(fn(*thaw(key[0]), **{k: thaw(v) for k, v in key[1]}))) for key in results
    ]
sys.stdout.buffer.write(pickle.dumps(out))
"""
)


def _run(script: str, *args: str, stdin: bytes = b"") -> bytes:
    env = dict(os.environ, PYTHONHASHSEED="0", PYTHONPATH=str(ROOT))
    env.pop(memo.ENV_VAR, None)
    done = subprocess.run(
        [sys.executable, "-c", script, *args],
        input=stdin,
        capture_output=True,
        cwd=ROOT,
        env=env,
        check=False,
    )
    assert done.returncode == 0, done.stderr.decode()[-3000:]
    return done.stdout


@pytest.mark.slow
@pytest.mark.parametrize("slug", ["altimeter_attitude", "north_finding", "platform_drift"])
def test_the_derive_memo_is_what_a_fresh_process_derives(slug):
    paper = load_papers([slug])[slug]
    raw = _run(_DERIVE, paper.audit_module, paper.generator_module)
    snap = pickle.loads(raw)
    assert snap, f"{slug}: derive memoised nothing"
    fresh = pickle.loads(_run(_FRESH, stdin=raw))
    assert sorted(fresh) == sorted(snap)
    for name, results in snap.items():
        mine = [(repr(key), _text(memo.fresh_copy(value))) for key, value in results.items()]
        assert mine == fresh[name], name


def test_a_preload_reaches_a_function_imported_later():
    qualname = "test_a_preload_reaches_a_function_imported_later.<locals>.later"
    memo.preload({f"{__name__}.{qualname}": {((), ()): sp.Integer(7)}})

    @memo.derivation
    def later():
        raise AssertionError("derived although preloaded")

    assert later() == 7


def test_a_preload_reaches_a_function_already_imported():
    calls = []

    @memo.derivation
    def twice(x):
        calls.append(x)
        return 2 * x

    x = sp.Symbol("x")
    name = f"{twice.__module__}.{twice.__qualname__}"
    memo.preload({name: {((x,), ()): sp.Integer(5)}})
    assert twice(x) == 5 and calls == []
    assert twice(sp.Symbol("y")) == 2 * sp.Symbol("y") and len(calls) == 1


def test_the_environment_variable_names_the_snapshot(tmp_path, monkeypatch):
    name = f"{__name__}.from_env"
    path = tmp_path / "memo.pkl"
    path.write_bytes(memo.dumps({name: {((), ()): sp.Integer(3)}}))
    monkeypatch.setenv(memo.ENV_VAR, str(path))
    assert memo.preload_env() == path
    assert memo.snapshot()[name] == {((), ()): 3}
    monkeypatch.delenv(memo.ENV_VAR)
    assert memo.preload_env() is None


def test_callers_get_their_own_copies():
    @memo.derivation
    def table():
        return {"m": sp.Matrix([1, 2])}

    first = table()
    first["m"][0] = 0
    first["extra"] = 1
    assert table() == {"m": sp.Matrix([1, 2])}


def _plain_function() -> None:
    """A function as an argument: keyed as it is (by identity), never by its attributes."""


class _Problem:
    """An argument compared by identity, as the Setting of the multiplicative-noise proofs is."""

    def __init__(self, m: sp.Matrix, sizes: list[int]) -> None:
        self.m, self.sizes = m, sizes


def test_matrix_and_object_arguments_are_keyed_by_their_contents():
    calls = []

    @memo.derivation
    def trace_of(problem, extra):
        calls.append(problem)
        return problem.m.trace() + extra[0, 0]

    x = sp.Symbol("x")
    assert trace_of(_Problem(sp.Matrix([[x, 1], [2, 3]]), [2]), sp.Matrix([[1]])) == x + 4
    # an equal object rebuilt (as in another process) and an equal matrix: the result, not a call
    assert trace_of(_Problem(sp.Matrix([[x, 1], [2, 3]]), [2]), sp.Matrix([[1]])) == x + 4
    assert len(calls) == 1
    # a change of any attribute, or of the matrix argument, is another key
    changed = _Problem(sp.Matrix([[x, 1], [2, 3]]), [2])
    changed.m[1, 1] = 5
    assert trace_of(changed, sp.Matrix([[1]])) == x + 6
    assert trace_of(_Problem(sp.Matrix([[x, 1], [2, 3]]), [3]), sp.Matrix([[1]])) == x + 4
    assert trace_of(_Problem(sp.Matrix([[x, 1], [2, 3]]), [2]), sp.Matrix([[2]])) == x + 5
    assert len(calls) == 4
    # the keys survive pickling (the derive step's snapshot) and rebuild equal arguments
    name = f"{trace_of.__module__}.{trace_of.__qualname__}"
    keys = list(pickle.loads(memo.dumps(memo.snapshot()))[name])
    args, _ = keys[0]
    problem, extra = memo.thaw(args)
    assert isinstance(problem, _Problem) and problem.sizes == [2]
    assert problem.m == sp.Matrix([[x, 1], [2, 3]]) and isinstance(problem.m, sp.MutableDenseMatrix)
    assert isinstance(extra, sp.MutableDenseMatrix) and extra == sp.Matrix([[1]])
    assert trace_of(problem, extra) == x + 4 and len(calls) == 4


def test_functions_and_hashable_values_are_their_own_keys():
    x = sp.Symbol("x")
    for value in (x, 3, "a", (x, 1), sp.ImmutableMatrix([x]), sp.sin, _plain_function):
        assert memo.freeze(value) == value and memo.thaw(memo.freeze(value)) == value


def test_the_notebook_job_names_the_memo_variable_the_kernel_reads():
    """pipeline/scripts/execute_notebook.py names the variable rather than importing it (importing
    derivations imports SymPy, which that process does not use): the same name."""
    script = (ROOT / "pipeline" / "scripts" / "execute_notebook.py").read_text(encoding="utf-8")
    assert f'ENV_VAR = "{memo.ENV_VAR}"' in script
