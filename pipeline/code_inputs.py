"""The code a workflow step runs, computed from the import graph of its entry points.

Every repository module a step's entry module imports, directly or through other modules
(and the packages' ``__init__.py`` files on the way), is an input of the step's rule, so an
edit to any of them reruns exactly the steps that import it. Only modules of this repository
count (top-level packages ``derivations`` and ``pipeline``); imports inside functions count
too (they run when the step does).

>>> files = module_closure(["pipeline.registry"])
>>> "pipeline/registry.py" in files and "pipeline/paper.py" in files and "pipeline/config.py" in files
True
>>> [f for f in files if not f.startswith("pipeline/")]
[]
>>> module_closure(["no_such_package.module"])
Traceback (most recent call last):
...
ValueError: no_such_package.module: not a module of this repository (packages: derivations, pipeline)
"""

from __future__ import annotations

import ast
import json
from collections.abc import Iterable
from functools import cache
from pathlib import Path

__all__ = ["PACKAGES", "module_closure", "module_file", "notebook_imports", "script_imports"]

ROOT = Path(__file__).resolve().parents[1]
#: the repository's own top-level packages (imports of anything else are not followed)
PACKAGES = ("derivations", "pipeline")


def module_file(name: str, root: Path = ROOT) -> Path | None:
    """The file of module ``name`` under ``root`` (``a/b.py`` or ``a/b/__init__.py``)."""
    if name.split(".", 1)[0] not in PACKAGES:
        return None
    base = root.joinpath(*name.split("."))
    for candidate in (base.with_suffix(".py"), base / "__init__.py"):
        if candidate.is_file():
            return candidate
    return None


def _imported_names(tree: ast.AST, module: str, is_package: bool) -> set[str]:
    """Absolute names a module's source imports (``from a import b`` gives ``a`` and ``a.b``)."""
    names: set[str] = set()
    for node in ast.walk(tree):
        if isinstance(node, ast.Import):
            names.update(alias.name for alias in node.names)
        elif isinstance(node, ast.ImportFrom):
            if node.level:
                parts = module.split(".")
                keep = len(parts) - node.level + (1 if is_package else 0)
                base = ".".join(parts[:keep] + ([node.module] if node.module else []))
            else:
                base = node.module or ""
            names.add(base)
            names.update(f"{base}.{alias.name}" for alias in node.names)
    return names


@cache
def _direct(name: str, root: Path) -> tuple[str, ...]:
    path = module_file(name, root)
    if path is None:
        return ()
    tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
    found = _imported_names(tree, name, path.name == "__init__.py")
    return tuple(sorted(n for n in found if module_file(n, root) is not None))


def _with_parents(name: str) -> list[str]:
    parts = name.split(".")
    return [".".join(parts[: i + 1]) for i in range(len(parts))]


def module_closure(modules: Iterable[str], root: Path = ROOT) -> list[str]:
    """Repository-relative files of ``modules`` and everything they import, sorted."""
    root = Path(root)
    todo = []
    for name in modules:
        if module_file(name, root) is None:
            raise ValueError(
                f"{name}: not a module of this repository (packages: {', '.join(PACKAGES)})"
            )
        todo.append(name)
    seen: set[str] = set()
    while todo:
        name = todo.pop()
        for item in _with_parents(name):
            if item in seen or module_file(item, root) is None:
                continue
            seen.add(item)
            todo.extend(_direct(item, root))
    return sorted(str(module_file(n, root).relative_to(root)) for n in seen)


def script_imports(path: str | Path, root: Path = ROOT) -> list[str]:
    """Repository modules a script file (not itself a module) imports."""
    tree = ast.parse(Path(root, path).read_text(encoding="utf-8"), filename=str(path))
    return sorted(n for n in _imported_names(tree, "", False) if module_file(n, root))


def notebook_imports(path: str | Path, root: Path = ROOT) -> list[str]:
    """Repository modules the code cells of a notebook import (IPython magics skipped)."""
    nb = json.loads(Path(root, path).read_text(encoding="utf-8"))
    names: set[str] = set()
    for cell in nb.get("cells", []):
        if cell.get("cell_type") != "code":
            continue
        source = "".join(cell.get("source", []))
        lines = [ln for ln in source.splitlines() if not ln.lstrip().startswith(("%", "!"))]
        try:
            tree = ast.parse("\n".join(lines))
        except SyntaxError as exc:
            raise ValueError(f"{path}: a code cell is not valid Python: {exc}") from exc
        names |= _imported_names(tree, "", False)
    return sorted(n for n in names if module_file(n, root))
