"""Loading and validating a published-values file (``config/published/<slug>.yaml``).

One format for every paper (``config/schemas/published.schema.json``). The file is validated
before any compute: the schema, then the rules a schema cannot express (unique ids, finite
numbers), then, when the paper package passes them, its item selectors and its claim
predicates' arguments. Every problem is reported at once, each naming the file, the entry, the
field, the bad value and what is allowed; the error is a :class:`pipeline.config.ConfigError`.

>>> import tempfile, pathlib
>>> d = pathlib.Path(tempfile.mkdtemp())
>>> (d / "p.yaml").write_text(
...     "paper: demo\\nitems:\\n  - {id: A, label: Table 1, kind: exact, quantity: x, value: '1.5'}\\n"
...     "claims: []\\n", encoding="utf-8") > 0
True
>>> [i["label"] for i in load_published(d / "p.yaml")["items"]]
['Table 1']
>>> load_published(d / "p.yaml")["items"].clear()  # a copy: the next call has its own
>>> len(load_published(d / "p.yaml")["items"])
1
>>> (d / "p.yaml").write_text(
...     "paper: demo\\nitems:\\n  - {id: A, label: Table 1, kind: about, quantity: x, value: '1.5'}\\n"
...     "claims: []\\n", encoding="utf-8") > 0
True
>>> load_published(d / "p.yaml")  # doctest: +ELLIPSIS
Traceback (most recent call last):
...
pipeline.config.ConfigError: ...p.yaml: 1 problem(s):
...p.yaml: item 'A' (items[0]), field 'kind': bad value 'about'; allowed: one of ['exact', 'approximate', 'statistical']
"""

from __future__ import annotations

import copy
import math
from collections.abc import Callable, Iterator, Mapping, Sequence
from pathlib import Path
from typing import Any, Protocol

import jsonschema

from pipeline.config import ConfigError, load_schema, load_yaml
from pipeline.verdicts.main_claims import check_main_claims
from pipeline.verdicts.reading import check_reading

__all__ = [
    "SCHEMA_NAME",
    "describe_error",
    "ItemCheck",
    "Problem",
    "check_published",
    "load_published",
    "published_items",
]

SCHEMA_NAME = "published"

#: (field, bad value, what is allowed) of one problem of one entry.
Problem = tuple[str, Any, str]
#: A paper's check of an item's selectors: the problems it finds (empty if none).
ItemCheck = Callable[[Mapping[str, Any]], Sequence[Problem]]


class _Predicates(Protocol):
    """What load_published needs of a claim registry (pipeline.verdicts.claims.ClaimRegistry)."""

    def check(self, predicate: Mapping[str, Any]) -> Sequence[Problem]: ...


def _where(data: Any, path: Sequence[Any]) -> tuple[str, list[Any]]:
    """(entry description, the rest of the path) of a path into the file."""
    if len(path) >= 2 and path[0] in ("items", "claims") and isinstance(path[1], int):
        entry = data[path[0]][path[1]]
        ident = entry.get("id") if isinstance(entry, Mapping) else None
        kind = "item" if path[0] == "items" else "claim"
        return f"{kind} {ident!r} ({path[0]}[{path[1]}])", list(path[2:])
    if len(path) >= 2 and path[0] == "main_claims" and isinstance(path[1], int):
        entry = data[path[0]][path[1]]
        label = entry.get("label") if isinstance(entry, Mapping) else None
        return f"main claim {label!r} (main_claims[{path[1]}])", list(path[2:])
    return "top level", list(path)


def _field(parts: Sequence[Any]) -> str:
    out = ""
    for part in parts:
        out += f"[{part}]" if isinstance(part, int) else (f".{part}" if out else str(part))
    return out


def _line(filename: str, where: str, field: str, value: Any, allowed: str) -> str:
    return f"{filename}: {where}, field {field or '(entry)'!r}: bad value {value!r}; allowed: {allowed}"


def describe_error(err: jsonschema.ValidationError, rest: Sequence[Any]) -> Problem:
    """(field, bad value, allowed) of a schema error at ``rest`` (the path inside its entry)."""
    field = _field(rest)
    instance, validator, expected = err.instance, err.validator, err.validator_value
    if validator == "additionalProperties" and isinstance(instance, Mapping):
        known = sorted(err.schema.get("properties", {}))
        extra = sorted(str(k) for k in instance if k not in known)
        key = extra[0] if extra else "?"
        return (
            f"{field}.{key}" if field else key,
            f"unknown key {key!r}",
            f"only the keys {known}",
        )
    if validator == "required" and isinstance(instance, Mapping):
        missing = [k for k in expected if k not in instance]
        key = missing[0] if missing else "?"
        why = ""
        if key == "printed_as" and instance.get("kind"):
            why = (
                f" for kind {instance['kind']!r} (an approximate item says how the paper printed "
                "it, which sets its tolerance: printed_as 'about' for a value printed as 'about "
                "X', 'plot' for a value read off a figure, with figure: {label, axis})"
            )
        return (
            f"{field}.{key}" if field else key,
            "missing",
            f"the required keys {list(expected)}{why}",
        )
    if validator == "enum":
        allowed = f"one of {list(expected)}"
    elif validator == "const":
        allowed = f"exactly {expected!r}"
    elif validator == "pattern":
        allowed = f"a string matching {expected!r}" + (
            " (a printed number with '.' as decimal point, e.g. '50.0050' or '4.85e-8')"
            if "[0-9]+(" in str(expected)
            else ""
        )
    elif validator == "type":
        allowed = f"type {expected}"
    elif validator == "oneOf":
        allowed = "exactly one of 'abs' or 'rel'"
    elif validator == "not":
        allowed = (
            "no 'tolerance' for an approximate item (its printed_as sets it, one rule for every "
            "paper)"
            if isinstance(instance, Mapping) and instance.get("kind") == "approximate"
            else "no 'tolerance' for a statistical item (its rule is the percentile band)"
        )
        instance = instance.get("tolerance") if isinstance(instance, Mapping) else instance
        field = f"{field}.tolerance" if field else "tolerance"
    elif validator in _SIGNS:
        allowed = f"a number {_SIGNS[validator]} {expected}"
    elif validator in ("minItems", "maxItems", "uniqueItems", "minLength"):
        allowed = f"{validator} {expected!r} ({err.message})"
    else:
        allowed = err.message
    return field, instance, allowed


_SIGNS = {"minimum": ">=", "exclusiveMinimum": ">", "maximum": "<=", "exclusiveMaximum": "<"}


def _schema_problem(err: jsonschema.ValidationError, data: Any, filename: str) -> str:
    where, rest = _where(data, list(err.absolute_path))
    return _line(filename, where, *describe_error(err, rest))


def _non_finite(node: Any, path: list[Any]) -> Iterator[list[Any]]:
    """Paths of every NaN or infinite number, and of every printed string that overflows."""
    if isinstance(node, float) and not math.isfinite(node):
        yield path
    elif isinstance(node, Mapping):
        for key, value in node.items():
            if key in ("value", "error_pct") and isinstance(value, str):
                try:
                    bad = not math.isfinite(float(value))
                except ValueError:
                    bad = False  # the schema's pattern reports it
                if bad:
                    yield [*path, key]
            else:
                yield from _non_finite(value, [*path, key])
    elif isinstance(node, list):
        for i, value in enumerate(node):
            yield from _non_finite(value, [*path, i])


def _get(data: Any, path: Sequence[Any]) -> Any:
    for part in path:
        data = data[part]
    return data


def check_published(
    data: Any,
    filename: str,
    *,
    claims: _Predicates | None = None,
    check_item: ItemCheck | None = None,
) -> list[str]:
    """Every problem of a parsed published-values file, one line each (empty if none)."""
    validator = jsonschema.Draft202012Validator(load_schema(SCHEMA_NAME))
    errors = sorted(
        validator.iter_errors(data),
        key=lambda e: [(0, p) if isinstance(p, int) else (1, str(p)) for p in e.absolute_path],
    )
    problems = [_schema_problem(e, data, filename) for e in errors]
    if problems:
        return problems
    for path in _non_finite(data, []):
        where, rest = _where(data, path)
        problems.append(
            _line(filename, where, _field(rest), _get(data, path), "a finite number (no NaN/inf)")
        )
    seen: dict[str, str] = {}
    for section in ("items", "claims"):
        for index, entry in enumerate(data[section]):
            where, _ = _where(data, [section, index])
            if entry["id"] in seen:
                problems.append(
                    _line(
                        filename,
                        where,
                        "id",
                        entry["id"],
                        f"a unique id (already used at {seen[entry['id']]})",
                    )
                )
            seen.setdefault(entry["id"], f"{section}[{index}]")
    for index, item in enumerate(data["items"]):
        where, _ = _where(data, ["items", index])
        if item["kind"] == "exact" and item.get("value") is None and item.get("error_pct") is None:
            problems.append(
                _line(filename, where, "value", None, "a printed number in value or error_pct")
            )
        tol = item.get("tolerance")
        if tol and tol.get("applies_to") == "error_pct" and item.get("error_pct") is None:
            problems.append(
                _line(
                    filename,
                    where,
                    "tolerance.applies_to",
                    "error_pct",
                    "only with a printed error_pct",
                )
            )
        if item.get("printed_as") is not None and item["kind"] != "approximate":
            problems.append(
                _line(
                    filename,
                    where,
                    "printed_as",
                    item["printed_as"],
                    "only on an approximate item (exact and statistical have their own rules)",
                )
            )
        for field, value, allowed in check_reading(item, data.get("figures")):
            problems.append(_line(filename, where, field, value, allowed))
        if check_item is not None:
            for field, value, allowed in check_item(item):
                problems.append(_line(filename, where, field, value, allowed))
    for where, field, value, allowed in check_main_claims(data):
        problems.append(_line(filename, where, field, value, allowed))
    if claims is not None:
        for index, claim in enumerate(data["claims"]):
            where, _ = _where(data, ["claims", index])
            for field, value, allowed in claims.check(claim["predicate"]):
                problems.append(_line(filename, where, f"predicate.{field}", value, allowed))
    return problems


def load_published(
    path: str | Path,
    *,
    claims: _Predicates | None = None,
    check_item: ItemCheck | None = None,
) -> dict[str, Any]:
    """Read and validate a published-values file; return it as parsed (items, claims).

    ``claims`` (the paper's claim registry) checks every predicate's test name and arguments;
    ``check_item`` (the paper's selector check) every item. Without them only the shared format
    is checked (enough for a reader that wants the items' ids, labels and printed values).
    Raises :class:`ConfigError` listing every problem.
    """
    key = _memo_key(path, claims, check_item)
    if key in _CHECKED:
        return copy.deepcopy(_CHECKED[key][-1])
    data = load_yaml(path, finite=False)  # non-finite values: named per item below
    problems = check_published(data, str(path), claims=claims, check_item=check_item)
    if problems:
        raise ConfigError(f"{path}: {len(problems)} problem(s):\n" + "\n".join(problems))
    if key is not None:  # the checks held with it: their ids in the key stay theirs
        _CHECKED[key] = (claims, check_item, copy.deepcopy(data))
    return data


#: files this process has read and found valid, by path, bytes and the checks (the ids of the
#: claim registry and item check, which a dataclass registry cannot be hashed by): a report
#: job reads one file up to three times (its page's parts, the paper's report and its items:
#: ~15 ms of schema validation each for the largest file) and a verdicts job twice; a copy of
#: the parsed file is returned (0.3 ms), not parsed and validated again
_CHECKED: dict[tuple[Any, ...], Any] = {}


def _memo_key(path: str | Path, claims: Any, check_item: Any) -> tuple[Any, ...] | None:
    """The memo's key of a call (its file's bytes in it: an edited file is read anew), or None
    for an unreadable file (not memoised: load_yaml words the error)."""
    try:
        return (str(Path(path).resolve()), Path(path).read_bytes(), id(claims), id(check_item))
    except OSError:
        return None


def published_items(published: Mapping[str, Any]) -> list[Mapping[str, Any]]:
    """The items of a parsed published-values file (``[]`` if it has none).

    >>> published_items({"items": [{"id": "A", "label": "Table 1"}]})[0]["label"]
    'Table 1'
    >>> published_items({})
    []
    """
    items = published.get("items") if isinstance(published, Mapping) else None
    return [i for i in items if isinstance(i, Mapping)] if isinstance(items, list) else []
