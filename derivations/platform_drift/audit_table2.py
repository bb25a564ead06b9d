"""Equation audit of the platform-drift paper, Table 2 (appendix): the classical stable-platform
error formulas the paper compares with (Pitman).
"""

from __future__ import annotations

import sympy as sp

from derivations.checks import Check
from derivations.platform_drift import printed as P
from derivations.platform_drift import schuler as sch
from derivations.platform_drift import symbols as s

__all__ = ["checks"]


def _table2() -> list[Check]:
    t2 = sch.table2()
    out = []
    notes = {
        "T2.1": "x-channel Schuler loop with accelerometer bias B_x",
        "T2.2": "initial tilt phi_y(0) about the y axis (delta_a_x = -g phi_y)",
        "T2.3": "velocity change DeltaV_x at t = 0 through scale factor k_x: impulse k_x DeltaV_x",
        "T2.4": "gyro drift eps_y: phi_y_dot = delta_v_x / R_0 + eps_y",
        "T2.6": "initial velocity error",
        "T2.7": "initial azimuth error phi_z(0) couples the cross velocity v_y into phi_y_dot "
        "(phi x omega term); VI_c = v_y",
    }
    for key in ("T2.1", "T2.2", "T2.3", "T2.4"):
        out.append(Check(key, printed=P.PRINTED[key], derived=t2[key], if_match=notes[key]))
    out.append(
        Check(
            "T2.5",
            printed=P.PRINTED["T2.5"].xreplace({s.eps_z_p: s.eps_z}),
            derived=sp.Matrix(t2["T2.5"]),
            discrepancy="notation",
            if_differs="notation of the cited source: the printed Dx, Dy equal the derived ones for eps'_z = "
            "eps_z / 2, a prime the paper never defines (Pitman's notation), so the printed form is "
            "not shown wrong; with eps'_z read as the row's azimuth drift eps_z (the row is headed "
            "eps_z) they are twice the derived (eps_z v_y / 2)[t^2 - 2(1 - cos w_0 t)/w_0^2]: phi_z "
            "= eps_z t gives delta_x'' + w_0^2 delta_x = w_0^2 v_y eps_z t^2 / 2. The generated "
            "table2_azimuth_drift takes eps_z and uses the derived form",
        )
    )
    out.append(
        Check(
            "T2.6",
            printed=P.PRINTED["T2.6"],
            derived=t2["T2.6"],
            if_match=notes["T2.6"],
        )
    )
    out.append(
        Check(
            "T2.7",
            printed=P.PRINTED["T2.7"].xreplace({s.VI_c: s.v_y}),
            derived=t2["T2.7"],
            if_match=notes["T2.7"],
        )
    )
    out.append(
        Check(
            "T2.8",
            not_checkable="legend row: omega_0 Schuler frequency, R_0 Earth radius, DeltaV_x "
            "velocity change, VI_c cross inertial velocity; example v_x = v_y = 1000 ft/s",
        )
    )
    return out


def checks() -> list[Check]:
    """The checks of this section, in equation order."""
    return [
        *_table2(),
    ]
