"""Loading and validating configuration files against JSON schemas.

Every config file (scenarios, published values) is validated before any compute
starts. Errors name the file, the field (dotted path), the offending value and
what is allowed, e.g.::

    config/scenarios/<slug>/x.yaml: site.lat_deg = 95: must be < 90
"""

from __future__ import annotations

import hashlib
import json
from pathlib import Path
from typing import Any

import jsonschema
import yaml

__all__ = ["ConfigError", "load_yaml", "load_schema", "validate", "sha256_of", "dotted_get"]

SCHEMAS = Path(__file__).resolve().parents[1] / "config" / "schemas"


class ConfigError(ValueError):
    """A config file is malformed; the message names file, field, value and what is allowed."""


def load_yaml(path: str | Path) -> Any:
    """Parse a YAML file, turning parse errors into :class:`ConfigError`."""
    path = Path(path)
    if not path.is_file():
        raise ConfigError(f"{path}: file not found")
    try:
        return yaml.safe_load(path.read_text(encoding="utf-8"))
    except yaml.YAMLError as exc:
        raise ConfigError(f"{path}: not valid YAML: {exc}") from exc


def load_schema(name: str) -> dict[str, Any]:
    """Load ``config/schemas/<name>.schema.json``."""
    return json.loads((SCHEMAS / f"{name}.schema.json").read_text(encoding="utf-8"))


def _field(error: jsonschema.ValidationError) -> str:
    parts = [str(p) for p in error.absolute_path]
    return ".".join(parts) if parts else "(top level)"


def _allowed(error: jsonschema.ValidationError) -> str:
    v, vv = error.validator, error.validator_value
    if v == "minimum":
        return f"must be >= {vv}"
    if v == "exclusiveMinimum":
        return f"must be > {vv}"
    if v == "maximum":
        return f"must be <= {vv}"
    if v == "exclusiveMaximum":
        return f"must be < {vv}"
    if v == "enum":
        return f"must be one of {vv}"
    if v == "type":
        return f"must be of type {vv}"
    if v == "additionalProperties":
        allowed = sorted(error.schema.get("properties", {}))
        return f"unknown key ({error.message}); allowed keys: {allowed}"
    if v == "required":
        return error.message
    if v in ("minItems", "maxItems", "uniqueItems", "pattern", "const"):
        return f"{v} {vv!r} violated: {error.message}"
    return error.message


def validate(data: Any, schema: dict[str, Any], source: str | Path) -> None:
    """Validate ``data`` against ``schema``; raise :class:`ConfigError` listing every problem."""
    validator = jsonschema.Draft202012Validator(schema)
    errors = sorted(validator.iter_errors(data), key=lambda e: list(map(str, e.absolute_path)))
    if not errors:
        return
    lines = []
    for err in errors:
        value = (
            "" if err.validator in ("additionalProperties", "required") else f" = {err.instance!r}"
        )
        lines.append(f"{source}: {_field(err)}{value}: {_allowed(err)}")
    raise ConfigError("\n".join(lines))


def sha256_of(data: Any) -> str:
    """Stable hash of a parsed config (canonical JSON)."""
    blob = json.dumps(data, sort_keys=True, separators=(",", ":"), default=str).encode()
    return hashlib.sha256(blob).hexdigest()


def dotted_get(data: Any, dotted: str, source: str | Path = "<config>") -> Any:
    """``data['a']['b']`` for ``'a.b'``; ConfigError naming the file and field if missing."""
    node = data
    for part in dotted.split("."):
        if isinstance(node, dict) and part in node:
            node = node[part]
        elif isinstance(node, list) and part.isdigit() and int(part) < len(node):
            node = node[int(part)]
        else:
            raise ConfigError(f"{source}: field {dotted!r} not found (missing {part!r})")
    return node
