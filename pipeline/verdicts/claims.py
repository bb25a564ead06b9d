"""The claim registry: a paper package registers its claim predicates by name.

A claim in the published file names its test (``predicate: {test: argmax, ...arguments}``);
the paper's :class:`ClaimRegistry` holds, for each name, the function that judges it and the
JSON schema of its arguments, so bad arguments are reported before any compute. The function
gets the arguments and the paper's results and returns one :class:`ClaimResult` per curve (or
case, or filter) that bears on the claim; the engine writes one verdict row for each.

>>> reg = ClaimRegistry()
>>> @reg.register("above", {"type": "object", "required": ["limit"],
...                         "properties": {"limit": {"type": "number"}}})
... def above(args, results):
...     ok = results["x"] > args["limit"]
...     return [ClaimResult("upheld" if ok else "not_upheld", f"x = {results['x']}",
...                         f"x > {args['limit']}", "compared x with the limit")]
>>> [r.verdict for r in reg.evaluate({"test": "above", "limit": 1}, {"x": 2.0})]
['upheld']
>>> [r.verdict for r in reg.evaluate({"test": "above", "limit": 3}, {"x": 2.0})]
['not_upheld']
>>> reg.check({"test": "above"})
[('limit', 'missing', "the required keys ['limit']")]
>>> reg.check({"test": "below", "limit": 1})
[('test', 'below', "a test of this paper's claim registry: ['above']")]
"""

from __future__ import annotations

from collections.abc import Callable, Mapping, Sequence
from dataclasses import dataclass, field
from typing import Any

import jsonschema

from pipeline.verdicts.cause import Cause
from pipeline.verdicts.published import Problem, describe_error

__all__ = ["CLAIM_VERDICTS", "ClaimFunction", "ClaimRegistry", "ClaimResult", "ClaimTest"]

#: The verdicts a claim can get.
CLAIM_VERDICTS = ("upheld", "not_upheld", "not_checkable")


@dataclass(frozen=True)
class ClaimResult:
    """The judgement of one claim on one curve (or case, filter, ...).

    ``reproduced``: what was computed; ``tolerance``: the threshold the test applied;
    ``reason``: why the verdict follows. ``suffix`` (e.g. the curve's name) makes the row id
    ``<claim id>/<suffix>`` when a claim is judged on several curves; ``cause``: the root cause
    when it is not upheld (:mod:`pipeline.verdicts.cause`).
    """

    verdict: str
    reproduced: str
    tolerance: str
    reason: str
    method: str = ""
    quantity: str = ""
    published: str | None = None
    suffix: str = ""
    notes: tuple[str, ...] = ()
    cause: Cause | None = None

    def __post_init__(self) -> None:
        if self.verdict not in CLAIM_VERDICTS:
            raise ValueError(
                f"claim verdict {self.verdict!r}: allowed: one of {list(CLAIM_VERDICTS)}"
            )


#: A claim predicate: (its arguments from the published file, the paper's results) -> results.
ClaimFunction = Callable[[Mapping[str, Any], Any], Sequence[ClaimResult]]
#: An extra check of the arguments the schema cannot express: the problems it finds.
ArgsCheck = Callable[[Mapping[str, Any]], Sequence[Problem]]


@dataclass(frozen=True)
class ClaimTest:
    """A registered predicate: its name, function, argument schema and extra check."""

    name: str
    function: ClaimFunction
    args_schema: Mapping[str, Any]
    check: ArgsCheck | None = None
    doc: str = ""


@dataclass
class ClaimRegistry:
    """Name -> :class:`ClaimTest` of one paper."""

    tests: dict[str, ClaimTest] = field(default_factory=dict)

    def register(
        self, name: str, args_schema: Mapping[str, Any], check: ArgsCheck | None = None
    ) -> Callable[[ClaimFunction], ClaimFunction]:
        """Decorator: register ``function`` as the test ``name`` with its argument schema."""

        def decorate(function: ClaimFunction) -> ClaimFunction:
            if name in self.tests:
                raise ValueError(f"claim test {name!r} is registered twice")
            schema = {"additionalProperties": False, **args_schema}
            jsonschema.Draft202012Validator.check_schema(schema)
            doc = (function.__doc__ or "").strip().split("\n\n")[0]
            self.tests[name] = ClaimTest(name, function, schema, check, doc)
            return function

        return decorate

    def names(self) -> list[str]:
        """The registered test names, sorted."""
        return sorted(self.tests)

    def check(self, predicate: Mapping[str, Any]) -> list[Problem]:
        """Problems of a claim's predicate: an unknown test, or arguments its schema rejects."""
        name = predicate.get("test")
        test = self.tests.get(str(name))
        if test is None:
            return [("test", name, f"a test of this paper's claim registry: {self.names()}")]
        args = _arguments(predicate)
        validator = jsonschema.Draft202012Validator(test.args_schema)
        errors = sorted(validator.iter_errors(args), key=lambda e: [str(p) for p in e.path])
        problems = [describe_error(e, list(e.absolute_path)) for e in errors]
        if not problems and test.check is not None:
            problems += list(test.check(args))
        return problems

    def evaluate(self, predicate: Mapping[str, Any], results: Any) -> list[ClaimResult]:
        """Run the predicate's test on the results: one :class:`ClaimResult` per curve."""
        problems = self.check(predicate)
        if problems:
            raise ValueError(f"claim predicate {dict(predicate)!r}: {problems}")
        out = list(self.tests[predicate["test"]].function(_arguments(predicate), results))
        if not out:
            raise ValueError(f"claim test {predicate['test']!r} returned no result")
        return out


def _arguments(predicate: Mapping[str, Any]) -> dict[str, Any]:
    return {k: v for k, v in predicate.items() if k != "test"}
