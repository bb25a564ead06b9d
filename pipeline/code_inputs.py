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

Parsing every module's source costs ~0.5 s of CPU on each parse of the Snakefile (a no-op
``make reproduce`` included), so the imports each file names are kept in
``.snakemake/code_imports.json``, keyed by the file's path, size and modification time
(nanoseconds): a file whose size or mtime changed is parsed again. The graph itself is
walked every time (a new or deleted module is seen), only the parsing is saved.
"""

from __future__ import annotations

import ast
import json
import os
from collections.abc import Iterable, Iterator
from functools import cache
from pathlib import Path
from typing import Any

__all__ = ["PACKAGES", "module_closure", "module_file", "notebook_imports", "script_imports"]

ROOT = Path(__file__).resolve().parents[1]
#: the repository's own top-level packages (imports of anything else are not followed)
PACKAGES = ("derivations", "pipeline")
#: the parse cache, under the root given to :func:`module_closure` (Snakemake's own directory)
CACHE_FILE = Path(".snakemake", "code_imports.json")
#: bumped when what is cached changes meaning
_CACHE_VERSION = 1


def module_file(name: str, root: Path = ROOT) -> Path | None:
    """The file of module ``name`` under ``root`` (``a/b.py`` or ``a/b/__init__.py``)."""
    if name.split(".", 1)[0] not in PACKAGES:
        return None
    base = root.joinpath(*name.split("."))
    for candidate in (base.with_suffix(".py"), base / "__init__.py"):
        if candidate.is_file():
            return candidate
    return None


# the fields that hold statements (an import is a statement: no expression holds one)
_BLOCKS = ("body", "orelse", "finalbody", "handlers", "cases")


def _statements(tree: ast.AST) -> Iterator[ast.AST]:
    """Every statement of ``tree`` (and the except handlers and match cases holding some),
    at any depth: a tenth of the nodes ``ast.walk`` visits, the same imports."""
    todo = [tree]
    while todo:
        node = todo.pop()
        yield node
        for field in _BLOCKS:
            todo.extend(getattr(node, field, ()))


def _imported_names(tree: ast.AST, module: str, is_package: bool) -> set[str]:
    """Absolute names a module's source imports (``from a import b`` gives ``a`` and ``a.b``)."""
    names: set[str] = set()
    for node in _statements(tree):
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


class _ParseCache:
    """Imported names per source file, ``{path: [size, mtime_ns, names]}``, read once per
    process from ``root/.snakemake/code_imports.json`` and written back (atomically) when an
    entry was added or replaced."""

    def __init__(self, root: Path) -> None:
        self.path = root / CACHE_FILE
        self.entries: dict[str, list[Any]] = {}
        self.dirty = False
        try:
            data = json.loads(self.path.read_text(encoding="utf-8"))
        except (OSError, ValueError):
            return  # absent or unreadable: start empty (it is only a cache)
        if isinstance(data, dict) and data.get("version") == _CACHE_VERSION:
            entries = data.get("files")
            self.entries = entries if isinstance(entries, dict) else {}

    def names(self, path: Path, parse: Any) -> list[str]:
        """The names ``parse(path)`` gives, from the cache while size and mtime match."""
        stat = path.stat()
        key = str(path)
        hit = self.entries.get(key)
        if (
            isinstance(hit, list)
            and len(hit) == 3
            and hit[:2] == [stat.st_size, stat.st_mtime_ns]
            and isinstance(hit[2], list)
        ):
            return hit[2]
        names = sorted(parse(path))
        self.entries[key] = [stat.st_size, stat.st_mtime_ns, names]
        self.dirty = True
        return names

    def save(self) -> None:
        """Write the cache if it changed and ``.snakemake`` exists; a failure is ignored."""
        if not self.dirty or not self.path.parent.is_dir():
            return
        text = json.dumps({"version": _CACHE_VERSION, "files": self.entries}, sort_keys=True)
        tmp = self.path.with_name(f".{self.path.name}.{os.getpid()}.tmp")
        try:
            tmp.write_text(text, encoding="utf-8")
            os.replace(tmp, self.path)  # atomic: a concurrent reader sees old or new
            self.dirty = False
        except OSError:
            tmp.unlink(missing_ok=True)


@cache
def _parse_cache(root: Path) -> _ParseCache:
    return _ParseCache(root)


def _module_names(path: Path, module: str) -> set[str]:
    tree = ast.parse(path.read_text(encoding="utf-8"), filename=str(path))
    return _imported_names(tree, module, path.name == "__init__.py")


@cache
def _direct(name: str, root: Path) -> tuple[str, ...]:
    path = module_file(name, root)
    if path is None:
        return ()
    found = _parse_cache(root).names(path, lambda p: _module_names(p, name))
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
    _parse_cache(root).save()
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
