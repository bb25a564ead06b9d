"""Claim predicates of the synthetic pendulum paper (registered in :data:`CLAIMS`)."""

from __future__ import annotations

from collections.abc import Mapping
from typing import Any

from pipeline.verdicts.claims import ClaimRegistry, ClaimResult

__all__ = ["CLAIMS"]

CLAIMS = ClaimRegistry()


@CLAIMS.register(
    "isochronous",
    {
        "type": "object",
        "required": ["scenario", "max_amplitude_deg", "rel_tol"],
        "properties": {
            "scenario": {"type": "string"},
            "max_amplitude_deg": {"type": "number", "exclusiveMinimum": 0},
            "rel_tol": {"type": "number", "exclusiveMinimum": 0},
        },
    },
)
def isochronous(args: Mapping[str, Any], results: Any) -> list[ClaimResult]:
    """Up to max_amplitude_deg the integrated period stays within rel_tol of eq. 3's."""
    tol = f"|T / T_eq3 - 1| <= {args['rel_tol']:g} for amplitudes <= {args['max_amplitude_deg']:g} deg"
    frame = results.get(args["scenario"])
    if frame is None:
        return [ClaimResult("not_checkable", "", tol, f"no results for {args['scenario']}")]
    small = frame[frame["amplitude_deg"] <= args["max_amplitude_deg"]]
    if len(small) < 2:
        why = f"fewer than two amplitudes <= {args['max_amplitude_deg']:g} deg in the scenario"
        return [ClaimResult("not_checkable", "", tol, why)]
    dev = float((small["period_s"] / small["small_angle_s"] - 1).abs().max())
    ok = dev <= args["rel_tol"]
    text = f"max |T / T_eq3 - 1| = {dev:.3g}"
    reason = f"{dev:.3g} {'<=' if ok else '>'} {args['rel_tol']:g}"
    return [ClaimResult("upheld" if ok else "not_upheld", text, tol, reason, quantity="period_s")]
