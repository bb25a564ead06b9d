"""The roll and pitch RMS values the paper prints (Sec. 6), read from the published-values file.

:func:`published_rms` turns the parsed ``config/published/altimeter_attitude.yaml`` into
``{filter: {roll_rms_deg: v, pitch_rms_deg: v}}``; :func:`published_value` looks one value up
(None where the paper prints none), for the overlays of the figures.

>>> data = {"items": [{"id": "V1", "quantity": "roll_rms_deg", "value": "0.16",
...                    "select": {"filter": "linear_kf"}}]}
>>> published_rms(data)
{'linear_kf': {'roll_rms_deg': 0.16}}
>>> published_value(published_rms(data), "linear_kf", "pitch_rms_deg") is None
True
"""

from __future__ import annotations

import math
from collections.abc import Mapping
from typing import Any

__all__ = ["RMS_QUANTITIES", "published_rms", "published_value"]

RMS_QUANTITIES = ("roll_rms_deg", "pitch_rms_deg")


def published_rms(data: Any) -> dict[str, dict[str, float]]:
    """The published RMS values ``{filter: {roll_rms_deg: v, pitch_rms_deg: v}}``.

    ``data`` is the parsed ``config/published/altimeter_attitude.yaml`` (the shared format of
    pipeline.verdicts): entries under the top-level ``items:`` list, e.g. ``{id: V1.lkf_roll,
    kind: approximate, quantity: roll_rms_deg, value: "0.16", select: {filter: linear_kf},
    ...}``. Entries of the roll/pitch RMS quantities are kept, others are skipped. A missing
    field, a non-numeric or non-positive value, or a duplicated (filter, quantity) raises
    ValueError naming the entry.
    """
    if not isinstance(data, Mapping) or "items" not in data:
        raise ValueError("published values: no top-level 'items:' list")
    items = data["items"]
    if not isinstance(items, list):
        raise ValueError(f"published values: 'items' is {type(items).__name__}, not a list")
    out: dict[str, dict[str, float]] = {}
    for i, entry in enumerate(items):
        if not isinstance(entry, Mapping):
            raise ValueError(f"published entry items[{i}] is not a mapping: {entry!r}")
        name = f"{entry['id']!r}" if entry.get("id") is not None else f"items[{i}]"
        select = entry.get("select") if isinstance(entry.get("select"), Mapping) else {}
        flat = {**entry, "filter": select.get("filter")}
        missing = [k for k in ("quantity", "value", "filter") if flat.get(k) is None]
        if missing:
            raise ValueError(f"published entry {name}: missing field(s) {missing}")
        if entry["quantity"] not in RMS_QUANTITIES:
            continue
        filt, qty, text = flat["filter"], entry["quantity"], entry["value"]
        if not isinstance(filt, str) or not filt:
            raise ValueError(f"published entry {name}: filter = {filt!r} is not a filter name")
        try:
            value = float(text) if isinstance(text, str) else None
        except ValueError:
            value = None
        if value is None:
            raise ValueError(
                f"published entry {name}: value = {text!r} is not a number string (the printed "
                "digits, e.g. '0.16')"
            )
        if not math.isfinite(value) or value <= 0:
            raise ValueError(f"published entry {name}: value = {text!r} must be finite and > 0")
        if qty in out.get(filt, {}):
            raise ValueError(f"published entry {name}: {filt}.{qty} is given twice")
        out.setdefault(filt, {})[qty] = value
    return out


def published_value(published: Mapping | None, filt: str, qty: str) -> float | None:
    """published[filt][qty] as a float, None if the dict or the entry is absent."""
    if published is None:
        return None
    if not isinstance(published, Mapping):
        raise ValueError(
            f"published must be a dict filter -> {{quantity: value}}, got {published!r}"
        )
    entry = published.get(filt)
    if entry is None:
        return None
    if not isinstance(entry, Mapping):
        raise ValueError(f"published[{filt!r}] must be a dict quantity -> value, got {entry!r}")
    value = entry.get(qty)
    if value is None:
        return None
    if isinstance(value, bool) or not isinstance(value, int | float) or not math.isfinite(value):
        raise ValueError(f"published[{filt!r}][{qty!r}] = {value!r} is not a finite number")
    return float(value)
