r"""Loading and validating configuration files against JSON schemas.

Every config file (scenarios, published values) is validated before any compute
starts. Errors name the file, the field (dotted path), the offending value and
what is allowed, e.g.::

    config/scenarios/<slug>/x.yaml: site.lat_deg = 95: must be < 90

What a schema cannot say is refused here for every file: duplicate keys (YAML keeps the
last silently), non-finite numbers (``.nan``, ``.inf`` pass every schema bound), a
document that expands past :data:`MAX_VALUES` values through aliases (an alias bomb), a
file over :data:`MAX_BYTES`, bytes that are not UTF-8, and tags other than YAML's own.

>>> load_text("a: 1\na: 2\n", "x.yaml")
Traceback (most recent call last):
...
pipeline.config.ConfigError: x.yaml: line 2: a: duplicate key (the first is on line 1); allowed: each key once
>>> load_text("site: {g_m_s2: .inf}", "x.yaml")
Traceback (most recent call last):
...
pipeline.config.ConfigError: x.yaml: site.g_m_s2 = inf: not a finite number; allowed: finite numbers only
>>> load_text("a: &x [1, 2]\nb: *x\n", "x.yaml")
{'a': [1, 2], 'b': [1, 2]}
"""

from __future__ import annotations

import hashlib
import json
import math
from pathlib import Path
from typing import Any

import jsonschema
import yaml

__all__ = [
    "MAX_BYTES",
    "MAX_VALUES",
    "ConfigError",
    "check_values",
    "dotted_get",
    "inside_repository",
    "load_schema",
    "load_text",
    "load_yaml",
    "sha256_of",
    "validate",
]

#: The largest config file read (bytes): the repository's largest is ~20 kB.
MAX_BYTES = 1_000_000
#: The most values (scalars, lists, mappings) a config document may hold after aliases expand.
MAX_VALUES = 200_000
#: The longest value quoted in an error message (characters).
MAX_QUOTED = 200

SCHEMAS = Path(__file__).resolve().parents[1] / "config" / "schemas"


class ConfigError(ValueError):
    """A config file is malformed; the message names file, field, value and what is allowed."""


class _DuplicateKeys:
    """Refuses a key given twice in one mapping (YAML keeps the last silently)."""

    name: str

    def construct_mapping(self, node: yaml.MappingNode, deep: bool = False) -> dict[Any, Any]:
        first_line: dict[Any, int] = {}
        for key_node, _ in node.value:
            key = self.construct_object(key_node, deep=True)  # type: ignore[attr-defined]
            line = key_node.start_mark.line + 1
            try:
                if key in first_line:
                    raise ConfigError(
                        f"{self.name}: line {line}: {key}: duplicate key (the first is on line "
                        f"{first_line[key]}); allowed: each key once"
                    )
                first_line[key] = line
            except TypeError:  # an unhashable key: the base class reports it
                continue
        return super().construct_mapping(node, deep=deep)  # type: ignore[misc]


class _StrictLoader(_DuplicateKeys, yaml.SafeLoader):
    """YAML's safe loader (pure Python) that refuses a key given twice in one mapping: the
    one whose errors this module words (libyaml's messages differ)."""


# libyaml's parser with the same constructor and resolver: ~10x faster on the repository's
# files (every workflow start parses ~30 of them); a document it refuses is parsed again
# by _StrictLoader, so that every error reads the same either way.
_FastLoader: type | None = (
    type("_FastLoader", (_DuplicateKeys, yaml.CSafeLoader), {})
    if getattr(yaml, "__with_libyaml__", False)
    else None
)


def _parse(loader_class: type, text: str, source: str | Path) -> Any:
    loader = loader_class(text)
    loader.name = str(source)
    try:
        return loader.get_single_data()
    finally:
        loader.dispose()


def quoted(value: Any) -> str:
    """``repr(value)``, cut to :data:`MAX_QUOTED` characters for an error message."""
    text = repr(value)
    return text if len(text) <= MAX_QUOTED else text[: MAX_QUOTED - 3] + "..."


def check_values(data: Any, source: str | Path, finite: bool = True) -> None:
    """Refuse documents over :data:`MAX_VALUES` and (``finite``) non-finite numbers, naming
    each field."""
    problems: list[str] = []
    count = 0
    stack: list[tuple[str, Any]] = [("", data)]
    while stack:
        where, node = stack.pop()
        count += 1
        if count > MAX_VALUES:
            raise ConfigError(
                f"{source}: expands to more than {MAX_VALUES} values (YAML anchors and aliases?); "
                "allowed: a config document of at most that many values"
            )
        if isinstance(node, dict):
            stack += [(f"{where}.{k}" if where else str(k), v) for k, v in node.items()]
        elif isinstance(node, list):
            stack += [(f"{where}.{i}" if where else str(i), v) for i, v in enumerate(node)]
        elif finite and isinstance(node, float) and not math.isfinite(node):
            problems.append(
                f"{source}: {where or '(top level)'} = {node}: not a finite number; "
                "allowed: finite numbers only"
            )
    if problems:
        raise ConfigError("\n".join(sorted(problems)))


def yaml_problem(exc: yaml.YAMLError, source: str | Path) -> str:
    """One line for a YAML error: the file, the line and column, the problem and what is
    allowed (an unknown tag: YAML's standard tags only).

    >>> load_text("a: !!python/object/apply:os.system ['true']", "x.yaml")
    Traceback (most recent call last):
    ...
    pipeline.config.ConfigError: x.yaml: line 1, column 4: tag 'tag:yaml.org,2002:python/object/apply:os.system': not allowed; allowed: YAML's standard tags only (plain values, lists and mappings; no !!python/... or custom tags)
    """
    mark = getattr(exc, "problem_mark", None) or getattr(exc, "context_mark", None)
    where = f"line {mark.line + 1}, column {mark.column + 1}: " if mark is not None else ""
    problem = str(getattr(exc, "problem", None) or exc).splitlines()[0]
    if isinstance(exc, yaml.constructor.ConstructorError) and "constructor for the tag" in problem:
        tag = problem.rsplit(" ", 1)[-1]
        return (
            f"{source}: {where}tag {tag}: not allowed; allowed: YAML's standard tags only "
            "(plain values, lists and mappings; no !!python/... or custom tags)"
        )
    hint = " (indent with spaces, not tabs)" if "'\\t'" in problem else ""
    return (
        f"{source}: {where}not valid YAML: {problem[:MAX_QUOTED]}; allowed: a YAML document{hint}"
    )


def load_text(text: str, source: str | Path, finite: bool = True) -> Any:
    """Parse YAML ``text`` read from ``source`` strictly (see the module docstring);
    ``finite=False`` leaves non-finite numbers to a caller that names them better."""
    try:
        if _FastLoader is None:
            raise yaml.YAMLError("libyaml not available")
        data = _parse(_FastLoader, text, source)
    except (yaml.YAMLError, ConfigError, RecursionError):
        data = _strict_parse(text, source)  # the same document, its error worded here
    check_values(data, source, finite)
    return data


def _strict_parse(text: str, source: str | Path) -> Any:
    """``text`` parsed by the pure-Python loader; every problem as :class:`ConfigError`."""
    try:
        return _parse(_StrictLoader, text, source)
    except ConfigError:
        raise
    except yaml.YAMLError as exc:
        raise ConfigError(yaml_problem(exc, source)) from None
    except RecursionError:
        raise ConfigError(
            f"{source}: nested too deeply; allowed: a plain config document"
        ) from None


def load_yaml(path: str | Path, finite: bool = True) -> Any:
    """Parse a YAML file strictly, turning every problem into :class:`ConfigError`
    (``finite``: see :func:`load_text`)."""
    path = Path(path)
    if not path.is_file():
        raise ConfigError(f"{path}: file not found")
    size = path.stat().st_size
    if size > MAX_BYTES:
        raise ConfigError(f"{path}: {size} bytes; allowed: a config file of at most {MAX_BYTES}")
    raw = path.read_bytes()
    try:
        text = raw.decode("utf-8")
    except UnicodeDecodeError as exc:
        raise ConfigError(
            f"{path}: byte {exc.start} = {raw[exc.start : exc.start + 1]!r}: not UTF-8 text; "
            "allowed: a UTF-8 YAML file"
        ) from None
    if "\x00" in text:
        raise ConfigError(f"{path}: contains NUL bytes (a binary file?); allowed: a YAML text file")
    return load_text(text, path, finite)


def inside_repository(value: str, field: str, source: str | Path, root: Path) -> Path:
    """``root / value`` for a relative directory that stays inside ``root``; ConfigError if
    ``value`` is absolute or leaves it (``..``).

    >>> inside_repository("results", "results_dir", "config.yaml", Path("/repo"))
    PosixPath('/repo/results')
    >>> inside_repository("../escaped", "results_dir", "config.yaml", Path("/repo"))
    Traceback (most recent call last):
    ...
    pipeline.config.ConfigError: config.yaml: results_dir = '../escaped': leaves the repository; allowed: a relative path inside it, without '..'
    """
    parts = Path(value).parts
    if Path(value).is_absolute() or ".." in parts or not parts:
        raise ConfigError(
            f"{source}: {field} = {value!r}: leaves the repository; "
            "allowed: a relative path inside it, without '..'"
        )
    return root / value


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
    """Validate ``data`` against ``schema``; raise :class:`ConfigError` listing every problem.

    Non-finite numbers are refused first, whatever the schema says (JSON schema's bounds
    accept NaN)."""
    check_values(data, source)
    validator = jsonschema.Draft202012Validator(schema)
    errors = sorted(validator.iter_errors(data), key=lambda e: list(map(str, e.absolute_path)))
    if not errors:
        return
    lines = []
    for err in errors:
        value = (
            ""
            if err.validator in ("additionalProperties", "required")
            else f" = {quoted(err.instance)}"
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
