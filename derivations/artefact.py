"""One derivation artefact per paper: the paper's derivations computed once, in one process.

The equation audit, the codegen check and the notebook of a paper use the same derivations
(the audit's derived forms and the generator's functions share their building blocks), and
each used to recompute them in its own process. The workflow's ``derive`` rule calls
:func:`build` once per paper and pickles the result to ``results/<slug>/derivation.pkl``,
which is a declared input of the audit and the codegen check; they :func:`load` it instead
of deriving again.

What the artefact holds, and what stays independent:

* ``checks``: the audit's :class:`derivations.checks.Check` list. Each pairs the paper's
  equation as printed (transcribed in ``printed.py``, not derived) with the derived form;
  the audit compares the two, so the artefact is checked against an independent path.
* ``modules``: the paper's generated module: its generator's name, header and
  :class:`derivations.codegen.GeneratedFunction` list; the codegen check renders them and
  compares the text with the committed module. The shared frames module has an artefact of
  its own (:func:`build_frames`, ``results/frames_derivation.pkl``), built once for all papers.

Each unit (a generated module's functions, the audit's checks) is derived from SymPy's random
generator freshly seeded (:data:`derivations.SYMPY_SEED`), so what it gives does not depend on
what else the process derived first.

Pickle, protocol fixed: SymPy expressions, matrices and dataclasses round-trip, and with
hash randomisation off (PYTHONHASHSEED=0 in the workflow's jobs) the bytes are the same in
every run.
"""

from __future__ import annotations

import importlib
import pickle
from pathlib import Path
from typing import Any

import sympy.core.random as _sympy_random

# the classes the artefact holds: imported here so that every reader of an artefact declares
# (through this module's imports) the code its objects are rebuilt with
from derivations.canonical_pickle import canonical_dumps
from derivations.checks import Check
from derivations.codegen import GeneratedFunction
from derivations.factors_dict import lean_dict_factors
from derivations.futrig_memo import memoised_futrig

__all__ = ["FRAMES", "PROTOCOL", "build", "build_frames", "dumps", "load"]

PROTOCOL = 4
#: the generator of the shared frames module
FRAMES = "derivations.generate_frames"
#: the keys of an artefact, in order
KEYS = ("audit_module", "generator_module", "checks", "modules")


def _generated(name: str) -> dict[str, Any]:
    """One generated module's functions and header, derived from a freshly seeded SymPy
    generator (what a unit derives does not depend on what the process derived before)."""
    generator = importlib.import_module(name)
    _reseed()
    return {"generator": name, "header": generator.HEADER, "functions": generator.functions()}


def _reseed() -> None:
    from derivations import SYMPY_SEED

    _sympy_random.seed(SYMPY_SEED)


def build(audit_module: str, generator_module: str) -> dict[str, Any]:
    """The derivations of one paper: its audit checks and the functions of its generated
    module, with its header. The shared frames module is derived once for every paper
    (:func:`build_frames`, the ``derive_frames`` rule), not in each paper's artefact."""
    audit = importlib.import_module(audit_module)
    # each trigsimp node once in the process; Factors of a dict without a throw-away SymPy Dict
    # (the same results: derivations.futrig_memo, derivations.factors_dict)
    with memoised_futrig(), lean_dict_factors():
        modules = [_generated(generator_module)]
        _reseed()
        checks = audit.checks()
    return {
        "audit_module": audit_module,
        "generator_module": generator_module,
        "checks": checks,
        "modules": modules,
    }


def build_frames() -> dict[str, Any]:
    """The artefact of the shared frames module (pipeline/generated/frames.py), which every
    paper's generated code calls: its functions only, no audit checks."""
    return {
        "audit_module": None,
        "generator_module": FRAMES,
        "checks": [],
        "modules": _frames_modules(),
    }


def _frames_modules() -> list[dict[str, Any]]:
    with memoised_futrig(), lean_dict_factors():
        return [_generated(FRAMES)]


def dumps(artefact: dict[str, Any]) -> bytes:
    """The artefact as pickle bytes (fixed protocol), each SymPy value written once
    (:func:`derivations.canonical_pickle.canonical_dumps`): the bytes depend on the values only."""
    return canonical_dumps({k: artefact[k] for k in KEYS}, PROTOCOL)


def load(path: str | Path) -> dict[str, Any]:
    """The artefact written by the ``derive`` rule; a one-line error if it is not one."""
    path = Path(path)
    try:
        artefact = pickle.loads(path.read_bytes())
    except (OSError, pickle.UnpicklingError, EOFError, AttributeError, ImportError) as exc:
        raise SystemExit(
            f"{path}: not a readable derivation artefact ({exc}); rerun the derive rule"
        ) from None
    if not isinstance(artefact, dict) or tuple(artefact) != KEYS:
        raise SystemExit(f"{path}: not a derivation artefact (keys {KEYS} expected)")
    functions = [f for m in artefact["modules"] for f in m["functions"]]
    if not all(isinstance(c, Check) for c in artefact["checks"]) or not all(
        isinstance(f, GeneratedFunction) for f in functions
    ):
        raise SystemExit(f"{path}: not a derivation artefact (checks and functions expected)")
    return artefact
