"""Root causes of the north-finding rows that are not reproduced or not upheld.

Each function computes one :class:`~pipeline.verdicts.cause.Cause` from the results (and the
published values and the equation audit they are compared with), or None when its evidence
does not hold in these results, so a cause is never asserted on results that do not show it.
The same cause explains every row it names (same text), so the summary counts it once:

* :func:`levelling_method4`: the paper's method-4 levelling row (Tables 1-2) is not what its
  eq. 26 gives at balanced positions, and no common N makes it noise (unpublished run);
* :func:`azimuth_method2`: no table angle tau gives the paper's method-2 azimuth (Table 9);
* :func:`same_estimator`: azimuth methods 4 and 5 are one estimator of S (paper error);
* :func:`ls_positions`: the least-squares levelling methods 2, 4 at unpublished positions;
* :func:`acc_bias_misalignment`: the size of method 5's bias error (the misalignment terms).

:func:`for_item` and :func:`for_ranking` say which cause explains a published item or a ranking
claim's row. Results keys: estimates, mc_trials, error_budget, ranking, ranking_pairs, a2_scan
(frames), provenance (dict), scenario (Scenario or None), audit (frame or None), published
(the validated published file).
"""

from __future__ import annotations

import math
from collections.abc import Callable, Mapping, MutableMapping, Sequence
from statistics import NormalDist
from typing import Any

import numpy as np
import pandas as pd

from pipeline.north_finding.ranking import rank_sets
from pipeline.north_finding.scenario import POSITION_NEEDS
from pipeline.verdicts.cause import Cause
from pipeline.verdicts.kinds import RANK_BAND

__all__ = [
    "LEVEL_QUANTITIES",
    "acc_bias_misalignment",
    "azimuth_method2",
    "for_item",
    "for_ranking",
    "levelling_method4",
    "ls_positions",
    "noise_only_n",
    "same_estimator",
]

#: The levelling quantities (Tables 1, 2).
LEVEL_QUANTITIES = ("phi_deg", "theta_deg")
#: The least-squares levelling method of each channel and the 4-position method it extends.
LS_PARTNER = {"L2": "L1", "L4": "L3"}
#: Two-sided normal quantile of the statistical rank band ([0.5, 99.5] -> 2.576).
Z_BAND = NormalDist().inv_cdf(1.0 - RANK_BAND[0] / 100.0)
#: Noise-free values closer than this (deg) are the same angle.
SAME_ANGLE_DEG = 1e-9


def _g(x: float) -> str:
    """A count to two significant digits: 1.1e4, 670, 6.7e4."""
    mantissa, exponent = f"{x:.1e}".split("e")
    k = int(exponent)
    if k < 3:
        return f"{float(f'{x:.2g}'):g}"
    return f"{mantissa.rstrip('0').rstrip('.')}e{k}"


def _memo(results: Mapping[str, Any], name: str, make: Callable[[], Cause | None]) -> Cause | None:
    """One computation per results: every row a cause explains gets the same object."""
    if not isinstance(results, MutableMapping):
        return make()
    store = results.setdefault("_causes", {})
    if name not in store:
        store[name] = make()
    return store[name]


def _real(results: Mapping[str, Any], method: str, quantity: str) -> pd.Series | None:
    est = results.get("estimates")
    if est is None:
        return None
    row = est[(est["sensor"] == "real") & (est["method"] == method) & (est["quantity"] == quantity)]
    return None if row.empty else row.iloc[0]


def _items(results: Mapping[str, Any], kind: str = "statistical") -> list[Mapping[str, Any]]:
    published = results.get("published") or {}
    return [i for i in published.get("items", []) if i["kind"] == kind]


def _item(results: Mapping[str, Any], method: str, quantity: str) -> Mapping[str, Any] | None:
    found = [
        i for i in _items(results) if i["select"]["method"] == method and i["quantity"] == quantity
    ]
    return found[0] if len(found) == 1 else None


def _deviation(results: Mapping[str, Any], item: Mapping[str, Any]) -> tuple[float, float] | None:
    """(printed - noise-free real value, Monte Carlo std at the scenario's N) of an item."""
    method, quantity = item["select"]["method"], item["quantity"]
    real = _real(results, method, quantity)
    trials = results.get("mc_trials")
    if real is None or trials is None:
        return None
    mc = trials[(trials["method"] == method) & (trials["quantity"] == quantity)]["estimate"]
    if mc.size < 2:
        return None
    return float(item["value"]) - float(real["estimate"]), float(mc.std(ddof=1))


def noise_only_n(results: Mapping[str, Any], item: Mapping[str, Any]) -> float | None:
    """The largest N at which noise alone puts the printed value inside the rank band around
    the noise-free value, with the Monte Carlo std scaled as 1/sqrt(N) from the scenario's N."""
    dev = _deviation(results, item)
    n_sc = (results.get("provenance") or {}).get("n_avg")
    if dev is None or not n_sc or dev[0] == 0:
        return None
    d, s = dev
    return float(n_sc) * (Z_BAND * s / abs(d)) ** 2


def _as_close(results: Mapping[str, Any], items: Sequence[Mapping[str, Any]], n: float) -> float:
    """Probability that noise at N leaves every item as close to its noise-free value as printed."""
    n_sc = float(results["provenance"]["n_avg"])
    p = 1.0
    for item in items:
        dev = _deviation(results, item)
        if dev is not None and dev[1] > 0:
            p *= math.erf(abs(dev[0]) / (dev[1] * math.sqrt(n_sc / n) * math.sqrt(2.0)))
    return p


def _siblings(results: Mapping[str, Any], labels: set[str], method: str) -> list[Mapping[str, Any]]:
    return [i for i in _items(results) if i["label"] in labels and i["select"]["method"] != method]


def _audit_match(results: Mapping[str, Any], equations: Sequence[str]) -> bool:
    audit = results.get("audit")
    if audit is None:
        return False
    status = dict(zip(audit["equation"].astype(str), audit["status"], strict=True))
    return all(status.get(e) == "match" for e in equations)


def _n_ls(results: Mapping[str, Any]) -> str:
    sc = results.get("scenario")
    if sc is None or not sc.ls_positions_deg():
        return "our"
    tau = np.sort(np.asarray(sc.ls_positions_deg()) % 360.0)
    gaps = np.diff(np.r_[tau, tau[0] + 360.0])
    even = np.allclose(gaps, gaps[0])
    return f"our {tau.size}{' equally spaced' if even else ''}"


# --------------------------------------------------------------------------- the causes
def levelling_method4(results: Mapping[str, Any]) -> Cause | None:
    """The paper's method-4 levelling row is not eq. 26 at balanced positions (see module)."""
    return _memo(results, "levelling_method4", lambda: _levelling_method4(results))


def _levelling_method4(results: Mapping[str, Any]) -> Cause | None:
    real = {(m, q): _real(results, m, q) for m in ("L3", "L4") for q in LEVEL_QUANTITIES}
    printed = {(m, q): _item(results, m, q) for m in ("L3", "L4") for q in LEVEL_QUANTITIES}
    if any(v is None for v in (*real.values(), *printed.values())):
        return None
    ours = {k: float(v["estimate"]) for k, v in real.items()}
    if any(abs(ours["L4", q] - ours["L3", q]) > SAME_ANGLE_DEG for q in LEVEL_QUANTITIES):
        return None
    bounds = [noise_only_n(results, printed["L4", q]) for q in LEVEL_QUANTITIES]
    if any(b is None for b in bounds):
        return None
    n = min(bounds)
    labels = {printed["L4", q]["label"] for q in LEVEL_QUANTITIES}
    p = _as_close(results, _siblings(results, labels, "L4"), n)
    never = all(
        not (c.separated and c.d > 0)
        for s in rank_sets(results)
        if not s.noise_free
        for q in LEVEL_QUANTITIES
        if s.get("L4", q) is not None and s.get("L3", q) is not None
        for c in [s.compare(q, "L4", "L3")]
    )
    audit = (
        ", which the equation audit finds as derived" if _audit_match(results, ("25", "26")) else ""
    )
    phi, th = LEVEL_QUANTITIES
    text = (
        f"Levelling method 4 is the least squares of eq. 26{audit}: noise-free at "
        f"{_n_ls(results)} positions it returns method 3's roll {ours['L4', phi]:.4f} deg and "
        f"pitch {ours['L4', th]:.4f} deg (the paper prints {printed['L3', phi]['value']} and "
        f"{printed['L3', th]['value']} deg for method 3)"
        + (", and with noise it is at no N less accurate than method 3" if never else "")
        + f", while the paper prints {printed['L4', phi]['value']} and "
        f"{printed['L4', th]['value']} deg for method 4 "
        f"({float(printed['L4', phi]['value']) - ours['L4', phi]:+.4f} and "
        f"{float(printed['L4', th]['value']) - ours['L4', th]:+.4f} deg off); noise alone would "
        f"put these there only at N <= {_g(n)} samples averaged, where its other rows of "
        f"{' and '.join(sorted(labels))} would lie as close to their noise-free values as "
        f"printed with probability {p:.0e}, so the paper's method-4 row comes from a run it "
        "does not describe"
    )
    return Cause(
        "unpublished", "levelling method 4's printed row comes from an undescribed run", text
    )


def azimuth_method2(results: Mapping[str, Any]) -> Cause | None:
    """No table angle gives the paper's method-2 azimuth (Table 9)."""
    return _memo(results, "azimuth_method2", lambda: _azimuth_method2(results))


def _azimuth_method2(results: Mapping[str, Any]) -> Cause | None:
    item, real = _item(results, "A2", "psi_deg"), _real(results, "A2", "psi_deg")
    scan, budget, sc = results.get("a2_scan"), results.get("error_budget"), results.get("scenario")
    if item is None or real is None or scan is None or scan.empty or budget is None or sc is None:
        return None
    bias = budget[(budget["method"] == "A2") & (budget["quantity"] == "psi_deg") & (budget["source"] == "bias")]  # fmt: skip
    n = noise_only_n(results, item)
    if bias.empty or n is None:
        return None
    mag = scan["error_deg"].abs()
    k = mag.idxmin()
    printed_err = float(item["value"]) - float(real["truth"])
    if mag[k] <= abs(printed_err):
        return None  # some tau does give the printed row: the angle would explain it
    p = _as_close(results, _siblings(results, {item["label"]}, "A2"), n)
    ours = float(real["estimate"]) - float(real["truth"])
    text = (
        "The paper does not give the table angle of azimuth method 2, and no whole-degree angle "
        "gives its row: the method reads the gyro at one angle, so the gyro bias enters psi uncorrected "
        f"({float(bias['error'].iloc[0]):+.4f} deg of our {ours:+.4f} deg noise-free error at "
        f"tau = {sc.table['a2_tau_deg']:g} deg); at every whole-degree tau the noise-free error "
        f"is at least {mag[k]:.4f} deg in size (smallest at tau = {scan['tau_deg'][k]:g} deg), "
        f"against the printed {printed_err:+.4f} deg ({item['value']} deg); noise alone would "
        f"reach it only at N <= {_g(n)}, where the paper's other {item['label']} rows would lie "
        f"as close to their noise-free values as printed with probability {p:.0e}"
    )
    return Cause("unpublished", "no table angle gives azimuth method 2's row", text)


def same_estimator(results: Mapping[str, Any], quantity: str, a: str, b: str) -> Cause | None:
    """Methods a and b read the same positions and agree on every trial and noise-free."""
    return _memo(results, f"same:{quantity}:{a}:{b}", lambda: _same(results, quantity, a, b))


def _same(results: Mapping[str, Any], quantity: str, a: str, b: str) -> Cause | None:
    if POSITION_NEEDS.get(a) != POSITION_NEEDS.get(b):
        return None
    sets = [s for s in rank_sets(results) if s.get(a, quantity) is not None and s.get(b, quantity) is not None]  # fmt: skip
    if not sets or not all(s.compare(quantity, a, b).identical for s in sets):
        return None
    mc = [s for s in sets if not s.noise_free]
    biggest = max((max(s.pairs.get((quantity, a, b), s.pairs.get((quantity, b, a), (0, 0, 0)))[2], 0.0) for s in mc), default=0.0)  # fmt: skip
    trials = sum(s.n_trials for s in mc)
    taus = ", ".join(f"{t:g}" for _, t in POSITION_NEEDS[a])
    pa, pb = _item(results, a, quantity), _item(results, b, quantity)
    printed = (
        f", although {pa['label']} prints {pa['value']} for method {a[1:]} and {pb['value']} "
        f"for method {b[1:]}"
        if pa is not None and pb is not None and pa["value"] != pb["value"]
        else ""
    )
    names = (results.get("published") or {}).get("names") or {}
    text = (
        f"Azimuth methods {a[1:]} and {b[1:]} solve the same gyro readings (tau = {taus} deg) "
        "for the same bias, scale factor and azimuth, so they are one estimator: their "
        f"{names.get(quantity, quantity.replace('_', ' '))} errors agree to {biggest:.0e} % on every one of {trials} Monte Carlo "
        f"trials at {len(mc)} value{'s' if len(mc) != 1 else ''} of N and noise-free, and method {b[1:]} cannot be more "
        f"accurate than method {a[1:]}{printed}"
    )
    return Cause("paper_error", f"azimuth methods {a[1:]} and {b[1:]} are one estimator", text)


def ls_positions(results: Mapping[str, Any]) -> Cause | None:
    """Least-squares levelling methods 2 and 4: same fit as methods 1 and 3, more readings."""
    return _memo(results, "ls_positions", lambda: _ls_positions(results))


def _ls_positions(results: Mapping[str, Any]) -> Cause | None:
    diffs = []
    for ls, four in LS_PARTNER.items():
        for q in LEVEL_QUANTITIES:
            x, y = _real(results, ls, q), _real(results, four, q)
            if x is None or y is None:
                return None
            diffs.append(abs(float(x["error_pct"]) - float(y["error_pct"])))
    sets = [s for s in rank_sets(results) if not s.noise_free and s.n_avg is not None]
    if not sets or max(diffs) > 1e-6:
        return None
    s0 = sets[0]
    ratios = [
        s0.get(ls, q) / s0.get(four, q)
        for ls, four in LS_PARTNER.items()
        for q in LEVEL_QUANTITIES
        if s0.get(ls, q) and s0.get(four, q)
    ]
    if not ratios:
        return None
    n_four = len(POSITION_NEEDS["L1"])
    text = (
        "The paper does not give the positions of the least-squares levelling methods 2 and 4 "
        f"(any n >= 3 over a turn); at {_n_ls(results)} positions each is, noise-free, the same "
        f"fit as the {n_four}-position method of its channel (methods 2 and 1, 4 and 3 agree to "
        f"{max(diffs):.0e} % in roll and pitch), and it averages more readings, so where noise "
        f"dominates its RMS error is {min(ratios):.2f} to {max(ratios):.2f} of theirs "
        f"({s0.where})"
    )
    return Cause("unpublished", "least-squares levelling positions are not given", text)


def acc_bias_misalignment(results: Mapping[str, Any]) -> Cause | None:
    """The accelerometer bias error of method 5 is the misalignment; its terms are unpublished."""
    return _memo(results, "acc_bias_misalignment", lambda: _acc_bias(results))


def _acc_bias(results: Mapping[str, Any]) -> Cause | None:
    budget, sc = results.get("error_budget"), results.get("scenario")
    item, real = _item(results, "L5", "acc_bias_ug"), _real(results, "L5", "acc_bias_ug")
    if budget is None or sc is None or sc.raw.get("accelerometer") is None or item is None or real is None:  # fmt: skip
        return None
    row = budget[(budget["method"] == "L5") & (budget["quantity"] == "acc_bias_ug") & (budget["source"] == "misalignment")]  # fmt: skip
    if row.empty:
        return None
    mis = float(row["error"].iloc[0])
    truth, ours = float(real["truth"]), float(real["error_pct"])
    paper = 100.0 * (float(item["value"]) - truth) / abs(truth)
    arcsec = sorted(set(sc.raw["accelerometer"]["misalignment_arcsec"].values()))
    terms = len(sc.raw["accelerometer"]["misalignment_arcsec"])
    if len(arcsec) != 1 or mis == 0:
        return None
    need = arcsec[0] * paper / (100.0 * mis / abs(truth))
    text = (
        "The paper gives one accelerometer misalignment size, not which terms are non-zero or "
        f"their signs; with all {terms} at {arcsec[0]:+g} arcsec (our decision) they move method "
        f"5's bias estimate by {mis:+.2f} ug, so our noise-free bias error is {ours:+.2f} %, and "
        f"the paper's {paper:+.1f} % ({item['label']}: {item['value']} ug) would need "
        f"{need:+.1f} arcsec"
    )
    return Cause("unpublished", "accelerometer misalignment terms are not given", text)


# --------------------------------------------------------------------------- which cause
def for_item(item: Mapping[str, Any], results: Mapping[str, Any]) -> Cause | None:
    """The cause that explains a published item's row when it fails (None: none known)."""
    method, quantity = item["select"]["method"], item["quantity"]
    if method == "L4" and quantity in LEVEL_QUANTITIES:
        return levelling_method4(results)
    if method == "A2" and quantity == "psi_deg":
        return azimuth_method2(results)
    if method == "L5" and quantity.startswith("acc_bias"):
        return acc_bias_misalignment(results)
    return None


def for_ranking(
    quantity: str,
    expect: str | None,
    rivals: Sequence[str],
    identical: Sequence[str],
    results: Mapping[str, Any],
) -> Cause | None:
    """The cause of a failing row of a claim about ``quantity``: ``expect`` is the method the
    paper ranks first (None for a closeness claim), ``rivals`` the methods that match or beat
    it, ``identical`` those that are the same estimator."""
    if quantity in LEVEL_QUANTITIES:
        if expect == "L4" or "L4" in rivals:
            return levelling_method4(results)
        return ls_positions(results)
    for other in identical:
        first, second = sorted((expect or "", other))
        cause = same_estimator(results, quantity, first, second)
        if cause is not None:
            return cause
    return None
