"""The derivation artefact (derivations.artefact): what the derive rule pickles round-trips to
the same checks and the same generated source, its bytes do not depend on the process, and a
file that is not an artefact stops the reader with one line naming the file."""

from __future__ import annotations

import os
import subprocess
import sys

import pytest
import sympy as sp

from derivations import artefact, generate_frames
from derivations.checks import Check, run_check
from derivations.codegen import render_module
from pipeline.registry import ROOT

_SCRIPT = """
import sys
import sympy as sp
from derivations import artefact, generate_frames
from derivations.checks import Check
x = sp.Symbol("x", real=True)
checks = [Check("1", printed=sp.Matrix([sp.sin(x) ** 2]), derived=sp.Matrix([1 - sp.cos(x) ** 2]))]
modules = [{"generator": "derivations.generate_frames", "header": generate_frames.HEADER,
            "functions": generate_frames.functions()}]
sys.stdout.buffer.write(artefact.dumps({"audit_module": "a", "generator_module": "g",
                                        "checks": checks, "modules": modules}))
"""


def _frames_artefact() -> dict:
    x = sp.Symbol("x", real=True)
    return {
        "audit_module": "a",
        "generator_module": "g",
        "checks": [
            Check(
                "1", printed=sp.Matrix([sp.sin(x) ** 2]), derived=sp.Matrix([1 - sp.cos(x) ** 2])
            ),
            Check("2", printed=2 * x, derived=3 * x, discrepancy="wrong_term", if_differs="typo"),
        ],
        "modules": [
            {
                "generator": "derivations.generate_frames",
                "header": generate_frames.HEADER,
                "functions": generate_frames.functions(),
            }
        ],
    }


def test_round_trip_keeps_checks_and_generated_source(tmp_path):
    built = _frames_artefact()
    path = tmp_path / "derivation.pkl"
    path.write_bytes(artefact.dumps(built))
    loaded = artefact.load(path)
    assert [run_check(c) for c in loaded["checks"]] == [run_check(c) for c in built["checks"]]
    assert [run_check(c).residual for c in loaded["checks"]] == ["0", "-x"]
    module = loaded["modules"][0]
    assert render_module(module["functions"], module["header"]) == generate_frames.source()


def test_bytes_are_the_same_in_two_processes():
    env = {**os.environ, "PYTHONHASHSEED": "0", "PYTHONPATH": str(ROOT)}
    runs = [
        subprocess.run(
            [sys.executable, "-c", _SCRIPT], cwd=ROOT, env=env, capture_output=True, check=True
        ).stdout
        for _ in range(2)
    ]
    assert runs[0] == runs[1] and len(runs[0]) > 1000


@pytest.mark.parametrize(
    "content, says",
    [
        (b"not a pickle", "not a readable derivation artefact"),
        (artefact.pickle.dumps({"checks": []}), "keys"),
    ],
)
def test_a_file_that_is_not_an_artefact_is_refused_in_one_line(tmp_path, content, says):
    path = tmp_path / "derivation.pkl"
    path.write_bytes(content)
    with pytest.raises(SystemExit) as info:
        artefact.load(path)
    message = str(info.value)
    assert str(path) in message and says in message and "\n" not in message


def test_the_frames_artefact_renders_the_committed_frames_module():
    """build_frames (the derive_frames rule, once for all papers) gives the functions of
    pipeline/generated/frames.py, and no audit checks."""
    built = artefact.build_frames()
    assert built["checks"] == [] and built["generator_module"] == artefact.FRAMES
    (module,) = built["modules"]
    assert render_module(module["functions"], module["header"]) == generate_frames.source()


def test_a_unit_derives_the_same_whatever_the_process_derived_before():
    """Each unit starts from a freshly seeded SymPy generator: the frames functions derived
    after another derivation are those derived first."""
    first = artefact.dumps(artefact.build_frames())
    sp.simplify(sp.sin(sp.Symbol("y")) ** 2 + sp.cos(sp.Symbol("y")) ** 2)  # draws, caches
    sp.core.random.random()
    assert artefact.dumps(artefact.build_frames()) == first


def test_the_bytes_depend_on_the_values_not_on_which_objects_are_shared():
    """Equal SymPy objects (and strings) are written once whether or not they are one Python
    object: SymPy's cache decides that, so the bytes would otherwise depend on what the process
    derived before. The artefact loads back to equal values."""
    x = sp.Symbol("x", real=True)
    shared = sp.sin(x) + 1
    # an equal but distinct object, built by unpickling (bypasses SymPy's cache)
    copy = artefact.pickle.loads(artefact.pickle.dumps(shared))
    assert copy == shared and copy is not shared
    name = "".join(["na", "me"])

    def built(second, label):
        return {
            "audit_module": "a",
            "generator_module": "g",
            "checks": [Check("1", printed=sp.Matrix([shared]), derived=sp.Matrix([second]))],
            "modules": [{"generator": "name", "header": label, "functions": []}],
        }

    one = artefact.dumps(built(shared, "name"))
    assert artefact.dumps(built(copy, name)) == one
    loaded = artefact.pickle.loads(one)
    assert loaded["checks"][0].derived == sp.Matrix([shared])
    assert one != artefact.pickle.dumps(built(copy, name), protocol=artefact.PROTOCOL)
