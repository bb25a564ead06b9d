"""The paper's analytic position error (eqs. 32, 36), evaluated with the GENERATED code.

The formulas come from ``pipeline/generated/platform_drift.py`` (derived with SymPy in
``derivations/platform_drift``); this module only assembles them:

* channel 1 (eq. 32): ``(int p_merror, int q_merror) = gen.error_ch1(...)``, that is
  ``(-b_g1 t + b_g1 sin(sqrt(k_sh) t)/sqrt(k_sh), 0)``, signed as derived (and printed);
* channel 3 (eq. 36): ``(int p_merror, int q_merror) = gen.error_ch3(...)``;
* both: the two rate-error integrals added as vectors.

The position error is ``R * |(int p_merror, int q_merror)|`` (m). The analysis is for a
stationary vehicle; moving scenarios use the start latitude (scenario field
``analytic.latitude``). ``k_sh`` is the stationary Schuler constant
``g/R - omega_e^2 cos^2(lat)`` with the mass gravity ``g = GM/R_G^2`` and ``R = R_G``; its
period ``2 pi / sqrt(k_sh)`` is ``gen.oscillation_period`` (eq. 30).
"""

from __future__ import annotations

import numpy as np

from pipeline.generated import platform_drift as gen
from pipeline.platform_drift.scenario import Scenario

__all__ = ["constants", "error_m", "eq36_undefined"]


def eq36_undefined(sc: Scenario) -> str:
    """Why eq. 36 cannot be evaluated in ``sc`` (it divides by omega_e sin(lat0)), or "".

    >>> from types import SimpleNamespace as NS
    >>> eq36_undefined(NS(route=NS(lat0=0.0), name="equator"))[:40]
    'eq. 36 divides by omega_e sin(lat0), and'
    >>> eq36_undefined(NS(route=NS(lat0=0.6), name="tehran"))
    ''
    """
    if np.sin(sc.route.lat0) != 0.0:
        return ""
    return (
        f"eq. 36 divides by omega_e sin(lat0), and scenario {sc.name} starts at latitude 0: its "
        "channel-3 analytic curve is undefined"
    )


def constants(sc: Scenario) -> dict[str, float]:
    """k_sh, alpha (the one used in eq. 36), the plumb deflection and the Schuler period."""
    rho = sc.earth.radius + sc.route.altitude
    g = sc.earth.gm / rho**2
    lat0, we = sc.route.lat0, sc.earth.omega_e
    k_sh = float(gen.k_sh_stationary(g, rho, we, lat0))
    deflection = float(gen.alpha_deflection(rho, we, lat0, g))
    if sc.analytic_alpha == "plumb_deflection" or sc.initial_level == "plumb":
        alpha = deflection
    else:  # initial_tilt of a mass-level platform: no tilt from the mass vertical
        alpha = 0.0
    return {
        "g_mass_m_s2": g,
        "R_G_m": rho,
        "k_sh_1_s2": k_sh,
        # eq. 30: the tilt oscillation's period 2 pi / sqrt(k_sh)
        "schuler_period_s": float(gen.oscillation_period(k_sh)),
        "alpha_rad": alpha,
        "plumb_deflection_rad": deflection,
    }


def error_m(sc: Scenario, case: str, t: np.ndarray) -> np.ndarray:
    """Analytic position error (m) of the proposed scheme at times ``t`` for ``case``; NaN where
    the case has a channel-3 drift and eq. 36 is undefined (:func:`eq36_undefined`)."""
    c = constants(sc)
    b1, _, b3 = sc.platform_drift(case)
    t = np.asarray(t, dtype=float)
    p_int = np.zeros_like(t)
    q_int = np.zeros_like(t)
    if b1 != 0.0:
        # eq. 32: int p_merror = -b_g1 t + b_g1 sin(sqrt(k) t)/sqrt(k), int q_merror = 0
        p1, q1 = gen.error_ch1(t, b1, c["k_sh_1_s2"])
        p_int = p_int + np.asarray(p1, dtype=float)
        q_int = q_int + np.asarray(q1, dtype=float)
    if b3 != 0.0 and eq36_undefined(sc):
        return np.full_like(t, np.nan)
    if b3 != 0.0:
        p3, q3 = gen.error_ch3(
            t, b3, sc.earth.omega_e, sc.route.lat0, sc.psi0, c["k_sh_1_s2"], c["alpha_rad"]
        )
        p_int = p_int + np.asarray(p3, dtype=float)
        q_int = q_int + np.asarray(q3, dtype=float)
    # eq. 32 (second line): R sqrt((int p_merror)^2 + (int q_merror)^2)
    return sc.earth.radius * np.hypot(p_int, q_int)
