"""Scenario discovery and parse-time validation, shared by every paper's Snakemake rules.

A paper's scenarios are the files ``config/scenarios/<slug>/<name>.yaml``; the workflow runs
every one, and validates them all when it is parsed, so a bad file stops it before any job.
"""

from __future__ import annotations

import re
from pathlib import Path
from typing import Any

__all__ = ["scenario_names", "decisions_with_values", "whole_multiple"]


#: A scenario name: it becomes a directory of results/ and a wildcard value.
NAME_PATTERN = re.compile(r"^[a-z0-9][a-z0-9_-]{0,63}$")


def scenario_names(directory: str | Path) -> list[str]:
    """Names of every scenario file ``<directory>/<name>.yaml``, sorted; ConfigError for a
    name that cannot be a results directory and for a scenario file that would be ignored."""
    from pipeline.config import ConfigError

    directory = Path(directory)
    ignored = sorted(p.name for p in directory.glob("*.yml"))
    if ignored:
        raise ConfigError(
            f"{directory / ignored[0]}: file name ends in .yml; allowed: scenario files end in "
            ".yaml (a .yml file would be ignored)"
        )
    names = sorted(p.name[: -len(".yaml")] for p in directory.glob("*.yaml"))
    for name in names:
        if not NAME_PATTERN.match(name):
            raise ConfigError(
                f"{directory / (name + '.yaml')}: scenario name {name!r}: allowed: "
                f"{NAME_PATTERN.pattern} (lower-case letters, digits, '_' and '-'; it names a "
                "results directory)"
            )
    if not names:
        raise ConfigError(f"{directory}: no scenario files (*.yaml) found")
    return names


def decisions_with_values(raw: dict[str, Any], path: str | Path) -> list[dict[str, Any]]:
    """A scenario's ``decisions`` (field, text), each with the value found at its field;
    ConfigError (naming the file) if a decision names a field the scenario does not have."""
    from pipeline.config import ConfigError, dotted_get

    out = []
    for index, decision in enumerate(raw.get("decisions", [])):
        try:
            out.append({**decision, "value": dotted_get(raw, decision["field"], path)})
        except ConfigError as exc:
            raise ConfigError(
                f"{path}: decisions.{index}.field = {decision['field']!r}: not a field of this "
                f"scenario ({str(exc).rsplit('(', 1)[-1].rstrip(')')}); allowed: the dotted path "
                "of one of its fields, e.g. 'site.lat_deg'"
            ) from None
    return out


def whole_multiple(value: float, step: float) -> bool:
    """True if ``value`` is a whole number of ``step`` (to 1e-9 relative)."""
    n = value / step
    return abs(n - round(n)) <= 1e-9 * max(1.0, abs(n))
