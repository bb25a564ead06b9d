"""The set-up's warm-up: the project's bytecode, then each listed paper's own work before a
workflow, e.g. numba kernels compiled into their on-disk cache so the workflow's jobs load
them instead.

``python -m pipeline.warm_up [--force] [--config FILE]`` (``make warm-kernels``, run by
``make reproduce`` under its lock and by ``make test``) calls, for each paper of ``papers:`` in
``config/config.yaml`` (or ``FILE``), in that order, the function its plug-in names in
:attr:`pipeline.paper.Paper.warm_up` with ``[]`` (or ``["--force"]``). A paper without one is
skipped. Each warm-up keeps its own stamp and returns at once when it is done (~0.1 CPU-s).

First the project's packages (:data:`PACKAGES`) are compiled to bytecode (``__pycache__``,
``compileall``; nothing to do when it is current, ~0.05 CPU-s): with ``PYTHONDONTWRITEBYTECODE``
set, as on some CI and shared machines, Python would otherwise compile every module it imports
from source in every one of the workflow's ~40 jobs (~0.1 CPU-s a job, measured), and without
it the first jobs would write the same files.

A warm-up is an optimisation: the workflow gives the same bytes without it. So nothing here
stops the set-up: an unreadable config, a paper that cannot be loaded, a warm-up that raises
or returns non-zero each print a ``warning:`` line (a traceback for an exception) and the
next paper is warmed; the exit status is 0. The workflow reports a bad config or plug-in
itself, with its own clear error.
"""

from __future__ import annotations

import argparse
import compileall
import sys
import traceback
from pathlib import Path

from pipeline.registry import ROOT, check_config_file, load_paper

__all__ = ["PACKAGES", "compile_bytecode", "main", "warm_papers"]

#: the packages the workflow's jobs import from this checkout
PACKAGES = ("pipeline", "derivations")


def compile_bytecode(root: Path = ROOT) -> bool:
    """Each module of :data:`PACKAGES` compiled to ``__pycache__`` if its bytecode is missing
    or stale (Python's own check: the source's mtime and size); False (a warning printed) if
    one did not compile, which its import will then report."""
    ok = all(compileall.compile_dir(root / p, quiet=1) for p in PACKAGES)
    if not ok:
        print("warning: bytecode: a module did not compile (above)", file=sys.stderr)
    return ok


def warm_papers(slugs: list[str], force: bool = False, root: Path = ROOT) -> list[str]:
    """Run each paper's warm-up; the slugs whose warm-up failed (each failure warned about)."""
    failed = []
    for slug in slugs:
        try:
            function = load_paper(slug, root).warm_up_function()
            status = 0 if function is None else function(["--force"] if force else [])
            why = f"exit status {status}"
        except Exception as exc:  # noqa: BLE001  (an optimisation: see the module docstring)
            traceback.print_exc()
            status, why = 1, f"{type(exc).__name__}: {exc}"
        if status:
            print(
                f"warning: {slug}: the set-up's warm-up failed ({why}); the workflow's jobs do "
                "that work themselves",
                file=sys.stderr,
            )
            failed.append(slug)
    return failed


def main(argv: list[str] | None = None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--force", action="store_true", help="redo each warm-up even if done")
    parser.add_argument(
        "--config", default="config/config.yaml", help="the config whose papers are warmed"
    )
    args = parser.parse_args(argv)
    compile_bytecode()
    try:
        slugs = check_config_file(args.config).get("papers") or []
        if not isinstance(slugs, list) or not all(isinstance(s, str) for s in slugs):
            raise ValueError(f"papers = {slugs!r}: not a list of slugs")
    except Exception as exc:  # noqa: BLE001  (the workflow reports a bad config itself)
        print(f"warning: warm-up skipped: {args.config}: {exc}", file=sys.stderr)
        return 0
    warm_papers(slugs, args.force)
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
