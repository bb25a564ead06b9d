"""Check a user's config file before Snakemake reads it: ``make reproduce CONFIG=my.yaml``.

Snakemake reads ``--configfile`` files itself, before the Snakefile runs, and reports binary
bytes with a traceback and bad YAML without naming the file. ``make reproduce CONFIG=FILE``
first runs ::

    python -m pipeline.check_config FILE [FILE ...]

which reads ``config/config.yaml`` and each FILE strictly (:func:`pipeline.config.load_yaml`:
binary, tags, duplicate keys, NaN, alias bombs), merges them as Snakemake does (a FILE's
mapping updates the config's recursively; any other value replaces it) and checks the result
as the workflow would at parse time (:func:`pipeline.registry.check_workflow`: schema, paper
plug-ins, scenario and published files). Only then is Snakemake started with
``--configfile FILE``. One ``error:`` line and exit status 2 on the first problem.

>>> merged({"a": {"b": 1, "c": 2}, "d": [1]}, {"a": {"c": 3}, "d": [2]})
{'a': {'b': 1, 'c': 3}, 'd': [2]}
"""

from __future__ import annotations

import sys
from collections.abc import Mapping
from pathlib import Path
from typing import Any

from pipeline.config import ConfigError
from pipeline.registry import ROOT, check_config_file, check_workflow

__all__ = ["check", "main", "merged"]


def merged(base: Mapping[str, Any], update: Mapping[str, Any]) -> dict[str, Any]:
    """``base`` updated by ``update`` the way Snakemake merges ``--configfile`` files
    (``snakemake.utils.update_config``: nested mappings merged, other values replaced)."""
    out = dict(base)
    for key, value in update.items():
        if isinstance(value, Mapping) and isinstance(out.get(key), Mapping):
            out[key] = merged(out[key], value)
        else:
            out[key] = value
    return out


def check(files: list[str], root: Path = ROOT) -> str:
    """The config the workflow would run with ``--configfile files``, checked; a one-line
    summary. Raises ConfigError naming the file, the field and the value."""
    base = root / "config" / "config.yaml"
    config = check_config_file(base)
    for name in files:
        path = Path(name)
        if not path.is_file():
            what = "a directory" if path.is_dir() else "not found"
            raise ConfigError(f"{name}: {what}; allowed: a YAML config file (CONFIG=FILE)")
        config = merged(config, check_config_file(path))
    papers, _ = check_workflow(config, [base, *files], root)
    return (
        f"config ok: {', '.join(files)} over {base.relative_to(root)} (papers: {', '.join(papers)})"
    )


def main(argv: list[str] | None = None) -> int:
    files = list(sys.argv[1:] if argv is None else argv)
    if not files or any(f.startswith("-") for f in files):
        sys.stderr.write("usage: python -m pipeline.check_config CONFIG.yaml [CONFIG.yaml ...]\n")
        return 2
    try:
        print(check(files))
    except ConfigError as exc:
        sys.stderr.write(f"error: {exc}\n")
        return 2
    return 0


if __name__ == "__main__":
    raise SystemExit(main())
