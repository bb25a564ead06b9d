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

# In another fresh process: call every function of a snapshot with its arguments, without the
# snapshot (the notebook's path when it runs alone), and write {function: [(key, srepr)]}.
_FRESH = """
import importlib, pickle, sys
import sympy as sp
snap = pickle.loads(sys.stdin.buffer.read())
out = {}
for name, results in snap.items():
    module, _, qualname = name.rpartition(".")
    fn = getattr(importlib.import_module(module), qualname)
    out[name] = [(repr(key), sp.srepr(fn(*key[0], **dict(key[1])))) for key in results]
sys.stdout.buffer.write(pickle.dumps(out))
"""


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
        mine = [(repr(key), sp.srepr(memo.fresh_copy(value))) for key, value in results.items()]
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
