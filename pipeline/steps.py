"""Running one paper step (a :class:`pipeline.paper.Step`) from its Snakemake rule.

The rule's script (``pipeline/scripts/run_step.py``) hands its ``snakemake`` object to
:func:`run_step`, which resolves ``params.entry`` (``"module:function"``), opens the rule's
log (stderr goes there too) and calls ``entry(inputs, outputs, params, log)`` with plain
values: each named input/output a path (``str``) or a list of paths, ``params`` the rule's
other params plus ``wildcards``.

Every file of the repository the step opens for reading must be one of its inputs (its code
included): an audit hook records what the step opens, and a read of anything else fails the
step, naming the file, so that a rule never misses an input (an edit to it would not rerun
the step).

>>> resolve("pipeline.steps:resolve") is resolve
True
>>> resolve("pipeline.steps")
Traceback (most recent call last):
...
ValueError: step entry 'pipeline.steps': must be 'module:function'
"""

from __future__ import annotations

import os
import sys
from collections.abc import Callable, Iterable, Mapping
from pathlib import Path
from typing import Any

from pipeline.paper import StepEntry, named_function
from pipeline.script_log import logged

__all__ = ["plain", "resolve", "run_step", "undeclared_reads", "watch_reads"]


def resolve(entry: str) -> StepEntry:
    """The function ``entry`` names (``"package.module:function"``)."""
    return named_function(entry, "step entry")


def plain(named: Any) -> dict[str, Any]:
    """A Snakemake ``Namedlist`` (or a mapping) as ``{name: str | list[str]}``."""
    items = named.items() if hasattr(named, "items") else []
    out: dict[str, Any] = {}
    for key, value in items:
        out[key] = [str(v) for v in value] if isinstance(value, list) else value
    return out


def watch_reads() -> list[Any]:
    """Start recording the paths this process opens for reading (an audit hook, for the rest
    of the process); returns the list the hook appends to."""
    opened: list[Any] = []

    def hook(event: str, args: tuple) -> None:
        if event == "open" and args and isinstance(args[0], (str, bytes, os.PathLike)):
            mode, flags = (args[1], args[2]) if len(args) > 2 else (None, 0)
            reading = (
                ("r" in mode and "+" not in mode)
                if isinstance(mode, str)
                else (
                    mode is None and isinstance(flags, int) and flags & os.O_ACCMODE == os.O_RDONLY
                )
            )
            if reading:
                opened.append(args[0])

    sys.addaudithook(hook)
    return opened


_NOT_INPUTS = (".venv", ".snakemake", "__pycache__", ".git")
#: Snakemake's wall-clock benchmark files: a page shows them, but they are timings of this
#: run, not inputs of any result (and a page cannot depend on its own benchmark).
_TIMINGS = "benchmarks"


def undeclared_reads(opened: Iterable[Any], declared: Iterable[str], root: Path) -> list[str]:
    """Files under ``root`` in ``opened`` that are not ``declared`` (paths relative to root);
    directories and the environment (.venv, .snakemake, caches) are not counted.

    >>> root = Path.cwd()
    >>> undeclared_reads(["pipeline/steps.py", "README.md", "/etc/hosts"], ["README.md"], root)
    ['pipeline/steps.py']
    >>> undeclared_reads([str(root / ".venv" / "pyvenv.cfg"), ".git/HEAD"], [], root)
    []
    """
    # the environment's own files (most of what a step opens: the modules it imports) are
    # left out by their path as opened, before the costly resolve of each (~0.06 CPU-s a step)
    environment = tuple(
        f"{r}{os.sep}{d}{os.sep}" for r in {str(root), str(root.resolve())} for d in _NOT_INPUTS
    )
    root = root.resolve()
    allowed = {(root / d).resolve() for d in declared}
    found = set()
    for raw in {os.fsdecode(r) for r in opened}:
        path = Path(raw)
        path = path if path.is_absolute() else root / path
        if str(path).startswith(environment) and ".." not in path.parts:
            continue
        path = path.resolve()
        if not path.is_relative_to(root) or path in allowed or not path.is_file():
            continue
        rel = path.relative_to(root)
        if rel.parts and rel.parts[0] in _NOT_INPUTS or "__pycache__" in rel.parts:
            continue
        if _TIMINGS in rel.parts[:-1] and rel.suffix == ".tsv":
            continue
        found.add(str(rel))
    return sorted(found)


def _flat(named: Mapping[str, Any]) -> list[str]:
    return [p for v in named.values() for p in (v if isinstance(v, list) else [v])]


def run_step(smk: Any) -> None:
    """Run the step of a Snakemake ``script:`` job; fail if it read an undeclared file."""
    opened = watch_reads()
    params = plain(smk.params)
    entry = resolve(params.pop("entry"))
    params["wildcards"] = dict(smk.wildcards.items())
    inputs: Mapping[str, Any] = plain(smk.input)
    outputs: Mapping[str, Any] = plain(smk.output)
    with logged(smk.log[0], written=_flat(outputs)) as log_file:

        def log(message: str) -> None:
            print(message, file=log_file, flush=True)

        call: Callable[..., None] = entry
        call(inputs, outputs, params, log)
        extra = undeclared_reads(opened, _flat(inputs) + _flat(outputs), Path.cwd())
        if extra:
            raise ValueError(
                f"step {smk.rule} read files that are not inputs of its rule (declare them in "
                f"the paper's Step.inputs, so that an edit reruns the step): {extra}"
            )
