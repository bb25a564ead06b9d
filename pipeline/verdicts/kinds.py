"""The kinds of published number and their rules: one meaning each, for every paper.

exact
    The reproduced value equals the printed value to the printed precision: rounding it, or
    truncating it toward zero, to the printed digits gives the printed number
    (:func:`pipeline.verdicts.printed.equals_printed`). A printed % error beside the value is
    compared with our |% error| the same way. An item may state a tighter tolerance (``abs``
    or ``rel``, ``applies_to: value`` or ``applies_to: error_pct``) with its reason, where the printed digits
    mean exactly (a printed 0 % of an exact inversion). ``reproduced`` / ``not_reproduced``.
approximate
    A value read off a plot or printed as "about": |ours - published| <= the tolerance its
    printed form gives (``printed_as``, one rule for every paper, :mod:`pipeline.verdicts.reading`:
    "about X" -> max(one unit of the last significant digit, 10 % of |X|); read off a plot ->
    max(half a tick of the figure's axis, stated once per figure, one unit of the printed
    digit)), plus two standard errors of ours when ours is itself a Monte Carlo estimate (0 for
    a deterministic value). No item states its own tolerance. ``reproduced`` /
    ``not_reproduced``. Where the printed number is itself one draw of the paper's noisy
    simulation (the package gives ``samples``: our Monte Carlo of that number), it is judged
    like a statistical number on the values its printed form reads as: ``consistent`` when some
    value within the tolerance of the printed one has its percentile rank in
    :data:`RANK_BAND` (the reading interval meets the band), else ``not_reproduced``.
statistical
    Where the published value falls in our Monte Carlo distribution: its percentile rank
    100 (#{trials < v} + #{trials = v} / 2) / n; ``consistent`` if the rank lies in
    :data:`RANK_BAND`, else ``not_reproduced``. The test's power is reported: the range of
    values it accepts (the 0.5 and 99.5 percentiles) as a share of the published value, and
    the noise-free (deterministic) value beside it where the paper package gives one. A
    package may give per-sample ``weights`` (a mixture of Monte Carlo runs, e.g. over an
    unknown parameter): the rank is then 100 (sum of the weights of the trials < v + half
    those = v) / (sum of the weights), and the percentiles are the weighted ones (inverted
    CDF); without weights every trial weighs the same, as above.

A paper package says what it found for an item in a :class:`Found`; it gives ``missing`` (the
reason) when its results hold nothing to compare with, and the verdict is ``not_checkable``.

>>> item = {"id": "T8", "label": "Table 8", "kind": "exact", "quantity": "s", "value": "1.0000199"}
>>> judge(item, Found(value=1.0000199999907)).verdict
'reproduced'
>>> judge(item, Found(value=1.0000201)).verdict
'not_reproduced'
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from dataclasses import dataclass
from typing import Any

import numpy as np

from pipeline.verdicts.cause import Cause
from pipeline.verdicts.printed import (
    REL_SLACK,
    equals_printed,
    fmt_full,
    fmt_printed_plus,
    half_unit,
    unit,
)
from pipeline.verdicts.reading import fmt_limit, limit

__all__ = [
    "DRAW_VERDICTS",
    "NOISE_FREE_AGREES",
    "NUMBER_VERDICTS",
    "RANK_BAND",
    "Found",
    "Judged",
    "consistency_note",
    "judge",
    "percentile_rank",
    "shown_unit",
    "stated_tolerance",
]

#: Percentile-rank band in which a published value is consistent with the Monte Carlo.
RANK_BAND = (0.5, 99.5)
#: The verdicts a published number can get, per kind.
NUMBER_VERDICTS = {
    "exact": ("reproduced", "not_reproduced", "not_checkable"),
    "approximate": ("reproduced", "not_reproduced", "not_checkable"),
    "statistical": ("consistent", "not_reproduced", "not_checkable"),
}
#: The verdicts of an approximate number that is one draw of a noisy run (judged on our Monte
#: Carlo of it, :mod:`pipeline.verdicts.draws`).
DRAW_VERDICTS = ("consistent", "not_reproduced", "not_checkable")
#: Note of a statistical item whose noise-free value equals the published one to within one
#: unit of its last printed digit.
NOISE_FREE_AGREES = (
    "the noise-free real value equals the published one to within one unit of its last printed "
    "digit: the table matches deterministic error propagation"
)


@dataclass(frozen=True)
class Found:
    """What a paper package found in its results for one published item (one verdict row).

    ``value``: our deterministic value in the item's unit (exact, approximate; NaN when the
    quantity does not occur, e.g. no crossover, with ``shown`` saying so); ``error_pct``: our
    % error (exact items printing one); ``samples``: Monte Carlo samples (statistical);
    ``weights``: optional per-sample weights of ``samples`` (None: equal);
    ``noise_free``: the noise-free value beside them; ``truth``: the true value (for the
    printed table's own consistency); ``standard_error``: of ``value`` when it is a Monte
    Carlo estimate; ``suffix``: row id suffix when an item is judged on several curves;
    ``cause``: the root cause when the row is not reproduced (:mod:`pipeline.verdicts.cause`).
    """

    method: str = ""
    value: float | None = None
    error_pct: float | None = None
    samples: np.ndarray | None = None
    weights: np.ndarray | None = None
    noise_free: float | None = None
    noise_free_error_pct: float | None = None
    truth: float | None = None
    standard_error: float = 0.0
    suffix: str = ""
    missing: str = ""
    shown: str | None = None
    notes: tuple[str, ...] = ()
    cause: Cause | None = None


@dataclass(frozen=True)
class Judged:
    """The verdict of one number: reproduced text, verdict, tolerance, reason and notes."""

    reproduced: str
    verdict: str
    tolerance: str
    reason: str
    notes: tuple[str, ...] = ()


def _g(x: float) -> str:
    return f"{x:.3g}"


def shown_unit(item: Mapping[str, Any]) -> str:
    """`` <unit>`` to print beside a value, or ``""`` when the quantity name carries the unit.

    >>> shown_unit({"quantity": "error_2h_m", "unit": "km"}), shown_unit({"quantity": "phi_deg", "unit": "deg"})
    (' km', '')
    """
    u = item.get("unit")
    if not u or u == "dimensionless" or str(item["quantity"]).endswith(f"_{u}"):
        return ""
    return f" {u}"


def _tolerance(item: Mapping[str, Any], on: str) -> Mapping[str, Any] | None:
    tol = item.get("tolerance")
    return tol if tol and tol.get("applies_to", "value") == on else None


def _exact_tolerance(printed: str, tol: Mapping[str, Any] | None, what: str) -> str:
    if tol is None:
        return (
            f"{what}: the printed digits of {printed} (rounding: +-{_g(half_unit(printed))}; "
            f"truncation: [{printed}, +{_g(unit(printed))}))"
        )
    limit = float(tol["abs"]) if "abs" in tol else float(tol["rel"]) * abs(float(printed))
    return f"{what}: |ours - printed| <= {_g(limit)} ({tol['reason']})"


def stated_tolerance(item: Mapping[str, Any]) -> str:
    """The tolerance of an item's kind as the published file states it (before any result).

    >>> stated_tolerance({"kind": "exact", "quantity": "x", "value": "88"})
    'value: the printed digits of 88 (rounding: +-0.5; truncation: [88, +1))'
    >>> stated_tolerance({"kind": "approximate", "quantity": "x", "value": "4.5",
    ...                   "printed_as": "about"})
    "+-0.45 (printed as 'about 4.5': one unit of its last significant digit (0.1) or 10% of it (0.45), the larger), + 2 SE when ours is a Monte Carlo estimate"
    """
    kind = item["kind"]
    if kind == "exact":
        return "; ".join(
            _exact_tolerance(item[field], _tolerance(item, field), what)
            for field, what in (("value", "value"), ("error_pct", "% error"))
            if item.get(field) is not None
        )
    if kind == "approximate":
        stated, rule = limit(item)
        return f"+-{fmt_limit(stated)}{shown_unit(item)} ({rule}), + 2 SE when ours is a Monte Carlo estimate"
    return f"percentile rank in [{RANK_BAND[0]}, {RANK_BAND[1]}] of the Monte Carlo trials"


def _compare(
    ours: float, printed: str, tol: Mapping[str, Any] | None, what: str
) -> tuple[bool, str, str]:
    """(passed, tolerance text, reason text) of one printed number of an exact item."""
    tolerance = _exact_tolerance(printed, tol, what)
    if tol is None:
        ok, how = equals_printed(ours, printed)
        reason = (
            f"{what}: ours {fmt_full(ours)} {how} to the printed {printed}"
            if ok
            else f"{what}: ours {fmt_full(ours)} gives {printed} neither by rounding nor by "
            f"truncation (|ours - printed| = {_g(abs(ours - float(printed)))})"
        )
        return ok, tolerance, reason
    value = float(printed)
    limit = float(tol["abs"]) if "abs" in tol else float(tol["rel"]) * abs(value)
    diff = abs(ours - value)
    ok = diff <= limit + REL_SLACK * max(abs(ours), abs(value))
    reason = f"{what}: |ours - printed| = {_g(diff)} {'<=' if ok else '>'} {_g(limit)}"
    return ok, tolerance, reason


def _exact(item: Mapping[str, Any], found: Found) -> Judged:
    parts: list[tuple[bool, str, str]] = []
    if item.get("value") is not None:
        if found.value is None:
            return _missing("no reproduced value", item)
        parts.append(_compare(found.value, item["value"], _tolerance(item, "value"), "value"))
        reproduced = fmt_full(found.value) + shown_unit(item)
    else:
        reproduced = "" if found.error_pct is None else f"{abs(found.error_pct):.3g} %"
    if item.get("error_pct") is not None:
        if found.error_pct is None:
            return _missing("no reproduced % error", item)
        tol = _tolerance(item, "error_pct")
        parts.append(_compare(abs(found.error_pct), item["error_pct"], tol, "% error"))
    ok = all(p[0] for p in parts)
    return Judged(
        reproduced,
        "reproduced" if ok else "not_reproduced",
        "; ".join(p[1] for p in parts),
        "; ".join(p[2] for p in parts),
    )


def _approximate(item: Mapping[str, Any], found: Found) -> Judged:
    printed = item["value"]
    published = float(printed)
    stated, rule = limit(item)
    se = float(found.standard_error)
    allowed = stated + 2.0 * se
    u = shown_unit(item)
    tolerance = f"+-{fmt_limit(stated)}{u}" + (
        f" + 2 SE ({_g(se)}) = +-{fmt_limit(allowed)}{u}" if se else ""
    )
    tolerance += f" ({rule})"
    if found.samples is not None:
        from pipeline.verdicts.draws import approximate_draw

        return approximate_draw(item, found, stated, rule)
    if found.value is None:
        return _missing("no reproduced value", item)
    ours = float(found.value)
    reproduced = found.shown or (fmt_printed_plus(ours, printed) + u)
    if not math.isfinite(ours):
        reason = f"our results have no such value ({reproduced}) to set beside {printed}{u}"
        return Judged(reproduced, "not_reproduced", tolerance, reason)
    diff = abs(ours - published)
    ok = diff <= allowed * (1 + REL_SLACK)
    reason = f"|ours - published| = {_g(diff)}{u} {'<=' if ok else '>'} {_g(allowed)}{u}"
    if published:
        reason += f"; ours is {ours / published:.2f}x the published"
    return Judged(reproduced, "reproduced" if ok else "not_reproduced", tolerance, reason)


def percentile_rank(samples: np.ndarray, value: float, weights: np.ndarray | None = None) -> float:
    """100 (#{samples < value} + #{samples = value} / 2) / n; with ``weights``, the weighted
    counts over the total weight.

    >>> percentile_rank(np.arange(10.0), 4.0), percentile_rank(np.arange(10.0), 20.0)
    (45.0, 100.0)
    >>> percentile_rank(np.arange(4.0), 1.5, np.array([0.1, 0.1, 0.4, 0.4]))
    20.0
    """
    if weights is None:
        n = samples.size
        return float(100.0 * (np.sum(samples < value) + 0.5 * np.sum(samples == value)) / n)
    w = np.asarray(weights, dtype=float)
    below, tie = np.sum(w[samples < value]), np.sum(w[samples == value])
    return float(100.0 * (below + 0.5 * tie) / np.sum(w))


def _statistical(item: Mapping[str, Any], found: Found) -> Judged:
    if found.samples is None or found.samples.size == 0:
        return _missing("no Monte Carlo samples", item)
    sample = np.asarray(found.samples, dtype=float)
    printed = item["value"]
    published = float(printed)
    w = None if found.weights is None else np.asarray(found.weights, dtype=float)
    rank = percentile_rank(sample, published, w)
    lo, hi = RANK_BAND
    ok = lo <= rank <= hi
    qs = [lo, 5.0, 50.0, 95.0, hi]
    q_lo, p05, p50, p95, q_hi = (
        np.percentile(sample, qs)
        if w is None
        else np.percentile(sample, qs, weights=w, method="inverted_cdf")
    )
    width = (q_hi - q_lo) / abs(published) * 100.0 if published else math.inf
    of = (
        f"{sample.size} Monte Carlo trials"
        if w is None
        else f"the weighted mixture of {sample.size} Monte Carlo trials"
    )
    tolerance = (
        f"percentile rank in [{lo}, {hi}] of {of}, i.e. any value in "
        f"[{fmt_printed_plus(float(q_lo), printed)}, {fmt_printed_plus(float(q_hi), printed)}] (a range {width:.3g} % of the published value wide)"
    )
    reason = (
        f"published value at percentile rank {rank:.1f} of {of} "
        f"({'inside' if ok else 'outside'} [{lo}, {hi}])"
    )
    notes = [f"MC 5-95 %: [{p05:.10g}, {p95:.10g}]"]
    if found.noise_free is not None:
        err = found.noise_free_error_pct
        notes.append(
            f"noise-free real: {found.noise_free:.10g}"
            + (f" (error {err:+.4g} %)" if err is not None else "")
        )
        same, how = equals_printed(found.noise_free, printed)
        notes.append(
            f"noise-free vs published by the exact rule: {how} to the printed {printed}"
            if same
            else f"noise-free vs published by the exact rule: differs from the printed {printed}"
        )
        if abs(found.noise_free - published) <= unit(printed) * (1 + 1e-9):
            notes.append(NOISE_FREE_AGREES)
    else:
        notes.append("noise-free real: n/a")
    if found.truth:
        implied = 100.0 * (published - found.truth) / abs(found.truth)
        printed_pct = item.get("error_pct")
        notes.append(
            f"published value implies error {_fmt_pct(implied, sign=True)} %"
            + (f" (printed {printed_pct} %)" if printed_pct is not None else "")
        )
    return Judged(
        fmt_full(float(p50)),
        "consistent" if ok else "not_reproduced",
        tolerance,
        reason,
        tuple(notes),
    )


def _fmt_pct(x: float, sign: bool = False) -> str:
    """A percentage with 4 significant digits in fixed notation (0.00001000, 22.60)."""
    if x == 0 or not math.isfinite(x):
        return f"{x:+g}" if sign else f"{x:g}"
    places = max(0, 3 - math.floor(math.log10(abs(x))))
    return f"{x:+.{places}f}" if sign else f"{x:.{places}f}"


def _missing(what: str, item: Mapping[str, Any]) -> Judged:
    return Judged("", "not_checkable", stated_tolerance(item), f"not checkable: {what}")


def consistency_note(item: Mapping[str, Any], truth: float | None) -> str | None:
    """Whether a printed value and its printed % error agree with each other, given the truth.

    They agree when |value - truth| / |truth| x 100 differs from the printed % by at most the
    rounding of the two printed numbers. None when they agree or there is nothing to check.

    >>> consistency_note({"value": "77.4", "error_pct": "22.3"}, 100.0)
    'table internally inconsistent: value implies 22.60 %, table prints 22.3 %'
    >>> consistency_note({"value": "77.7", "error_pct": "22.3"}, 100.0) is None
    True
    """
    if item.get("value") is None or item.get("error_pct") is None:
        return None
    if not truth:
        return "internal consistency not checked: no non-zero truth in the results"
    value, printed = float(item["value"]), float(item["error_pct"])
    implied = abs(value - truth) / abs(truth) * 100.0
    tol = half_unit(item["error_pct"]) + half_unit(item["value"]) / abs(truth) * 100.0
    if abs(implied - printed) <= tol * (1 + 1e-9):
        return None
    return (
        f"table internally inconsistent: value implies {_fmt_pct(implied)} %, "
        f"table prints {item['error_pct']} %"
    )


_RULES = {"exact": _exact, "approximate": _approximate, "statistical": _statistical}


def judge(item: Mapping[str, Any], found: Found) -> Judged:
    """The verdict of one published item on what the paper package found for it."""
    if found.missing:
        return _missing(found.missing, item)
    judged = _RULES[item["kind"]](item, found)
    allowed = NUMBER_VERDICTS[item["kind"]]
    if item["kind"] == "approximate" and found.samples is not None:
        allowed = DRAW_VERDICTS  # one draw of a noisy run (pipeline.verdicts.draws)
    if judged.verdict not in allowed:  # pragma: no cover (a rule's bug)
        raise AssertionError(f"{item['id']}: verdict {judged.verdict!r} for {item['kind']}")
    return judged
