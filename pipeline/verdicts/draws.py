"""An approximate number that is one draw of a noisy run, judged on our Monte Carlo of it.

A text may print as "about X" a number that its own noisy simulation produced (a restated
real-sensor table value). Then ours is not one value but the distribution the paper's draw
comes from: the values the printed form reads as, [X - tolerance, X + tolerance] with the
tolerance of :mod:`pipeline.verdicts.reading`, are ranked in our (weighted) Monte Carlo, and the
number is ``consistent`` when that interval meets the rank band
:data:`~pipeline.verdicts.kinds.RANK_BAND`, else ``not_reproduced``
(:func:`pipeline.verdicts.kinds.judge` calls this for an approximate item whose
:class:`~pipeline.verdicts.kinds.Found` has ``samples``).

>>> import numpy as np
>>> from pipeline.verdicts.kinds import Found
>>> item = {"id": "S", "kind": "approximate", "quantity": "e", "unit": "%", "value": "22",
...         "printed_as": "about"}
>>> judge_draw = lambda s: approximate_draw(item, Found(samples=np.asarray(s)), 2.2, "r").verdict
>>> judge_draw(np.linspace(0.0, 60.0, 601)), judge_draw(np.linspace(26.0, 28.0, 201))
('consistent', 'not_reproduced')
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

import numpy as np

from pipeline.verdicts.kinds import (
    RANK_BAND,
    Found,
    Judged,
    _missing,
    percentile_rank,
    shown_unit,
)
from pipeline.verdicts.printed import fmt_printed_plus
from pipeline.verdicts.reading import fmt_limit

__all__ = ["approximate_draw"]


def approximate_draw(item: Mapping[str, Any], found: Found, stated: float, rule: str) -> Judged:
    """An approximate number that is one draw of a noisy run: the reading interval
    [X - tolerance, X + tolerance] against our Monte Carlo's rank band."""
    sample = np.asarray(found.samples, dtype=float)
    if sample.size == 0:
        return _missing("no Monte Carlo samples", item)
    w = None if found.weights is None else np.asarray(found.weights, dtype=float)
    printed, u = item["value"], shown_unit(item)
    published = float(printed)
    lo, hi = RANK_BAND
    r_lo = percentile_rank(sample, published - stated, w)
    r_hi = percentile_rank(sample, published + stated, w)
    rank = percentile_rank(sample, published, w)
    ok = r_hi >= lo and r_lo <= hi
    qs = [lo, 5.0, 50.0, 95.0, hi]
    q_lo, p05, p50, p95, q_hi = (
        np.percentile(sample, qs)
        if w is None
        else np.percentile(sample, qs, weights=w, method="inverted_cdf")
    )
    of = (
        f"{sample.size} Monte Carlo trials"
        if w is None
        else f"the weighted mixture of {sample.size} Monte Carlo trials"
    )
    tolerance = (
        f"the values read as {printed}{u}, +-{fmt_limit(stated)}{u} ({rule}), meet the "
        f"percentile-rank band [{lo}, {hi}] of {of}, i.e. "
        f"[{fmt_printed_plus(float(q_lo), printed)}, {fmt_printed_plus(float(q_hi), printed)}]{u}"
    )
    reason = (
        f"the printed value is one draw of the paper's noisy run: {printed}{u} at percentile rank "
        f"{rank:.1f}, its reading interval at ranks {r_lo:.1f} to {r_hi:.1f} of {of} "
        f"({'meets' if ok else 'outside'} [{lo}, {hi}])"
    )
    notes = [f"MC 5-95 %: [{p05:.10g}, {p95:.10g}]"]
    if found.value is not None and math.isfinite(float(found.value)):
        notes.append(f"noise-free: {fmt_printed_plus(float(found.value), printed)}{u}")
    return Judged(
        fmt_printed_plus(float(p50), printed) + u,
        "consistent" if ok else "not_reproduced",
        tolerance,
        reason,
        tuple(notes),
    )
