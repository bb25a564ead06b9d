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
* ``modules``: per generated module (the paper's and the shared frames module) its path
  name, header and :class:`derivations.codegen.GeneratedFunction` list; the codegen check
  renders them and compares the text with the committed module.

Pickle, protocol fixed: SymPy expressions, matrices and dataclasses round-trip, and with
hash randomisation off (PYTHONHASHSEED=0 in the workflow's jobs) the bytes are the same in
every run.
"""

from __future__ import annotations

import importlib
import pickle
from pathlib import Path
from typing import Any

# the classes the artefact holds: imported here so that every reader of an artefact declares
# (through this module's imports) the code its objects are rebuilt with
from derivations.checks import Check
from derivations.codegen import GeneratedFunction

__all__ = ["PROTOCOL", "build", "dumps", "load"]

PROTOCOL = 4
#: the keys of an artefact, in order
KEYS = ("audit_module", "generator_module", "checks", "modules")


def build(audit_module: str, generator_module: str) -> dict[str, Any]:
    """The derivations of one paper: its audit checks and the functions of its generated
    module and of the shared frames module, with their headers."""
    audit = importlib.import_module(audit_module)
    modules = []
    for name in (generator_module, "derivations.generate_frames"):
        generator = importlib.import_module(name)
        modules.append(
            {"generator": name, "header": generator.HEADER, "functions": generator.functions()}
        )
    return {
        "audit_module": audit_module,
        "generator_module": generator_module,
        "checks": audit.checks(),
        "modules": modules,
    }


def dumps(artefact: dict[str, Any]) -> bytes:
    """The artefact as pickle bytes (fixed protocol)."""
    return pickle.dumps({k: artefact[k] for k in KEYS}, protocol=PROTOCOL)


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
