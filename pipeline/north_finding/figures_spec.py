"""What each north-finding figure shows: Figs 1-5 of the paper as panels (a quantity and the
methods that estimate it), the sensitivity figure (Fig. 6, not in the paper), and the file
stems of all of them.

>>> [f.stem for f in FIGURES]
['fig1_roll', 'fig2_pitch', 'fig3_azimuth', 'fig4_bias', 'fig5_scale']
>>> FIGURE_FILES[-1]
'fig6_sensitivity'
"""

from __future__ import annotations

from dataclasses import dataclass

from pipeline.north_finding.columns import LEVELING_METHODS
from pipeline.north_finding.figures_style import COLUMN, FULL

__all__ = [
    "Panel",
    "FigureSpec",
    "FIGURES",
    "SENSITIVITY_STEM",
    "SENSITIVITY_TITLE",
    "FIGURE_FILES",
]


@dataclass(frozen=True)
class Panel:
    """One axes: a quantity and the methods (x categories) that estimate it."""

    quantity: str
    methods: tuple[str, ...]
    title: str = ""
    xlabel: str = "method"


@dataclass(frozen=True)
class FigureSpec:
    """One output figure (``stem`` -> ``stem.png`` and ``stem.svg``)."""

    stem: str
    title: str
    panels: tuple[Panel, ...]
    size: tuple[float, float] = (COLUMN, 2.7)


FIGURES: tuple[FigureSpec, ...] = (
    FigureSpec(
        "fig1_roll",
        "Fig. 1 — roll φ percent error per levelling method (real sensor)",
        (Panel("phi_deg", LEVELING_METHODS[:4], xlabel="levelling method"),),
    ),
    FigureSpec(
        "fig2_pitch",
        "Fig. 2 — pitch θ percent error per levelling method (real sensor)",
        (Panel("theta_deg", LEVELING_METHODS[:4], xlabel="levelling method"),),
    ),
    FigureSpec(
        "fig3_azimuth",
        "Fig. 3 — azimuth ψ percent error per azimuth method (real sensor)",
        (Panel("psi_deg", ("A1c1", "A1c2", "A2", "A3", "A4", "A5"), xlabel="azimuth method"),),
        size=(COLUMN, 2.7),
    ),
    FigureSpec(
        "fig4_bias",
        "Fig. 4 — sensor bias percent error (real sensor)",
        (
            Panel("acc_bias_ug", ("L5",), "(a) accelerometer bias", "levelling method"),
            Panel("gyro_bias_rad_s", ("A4",), "(b) gyro bias", "azimuth method"),
        ),
        size=(COLUMN, 2.7),
    ),
    FigureSpec(
        "fig5_scale",
        "Fig. 5 — scale-factor percent error (real sensor)",
        (
            Panel("acc_scale", ("L5",), "(a) accelerometer S", "levelling method"),
            Panel("gyro_scale", ("A4", "A5", "A6"), "(b) gyro S", "azimuth method"),
            Panel("gyro_scale_approx", ("A5", "A6"), "(c) gyro S, first order", "azimuth method"),
        ),
        size=(FULL, 2.6),
    ),
)
SENSITIVITY_STEM = "fig6_sensitivity"
SENSITIVITY_TITLE = "Fig. 6 (not in the paper) — azimuth RMS percent error vs samples averaged"
#: Every figure stem this module writes, in order (``.png`` and ``.svg`` each).
FIGURE_FILES: tuple[str, ...] = tuple(f.stem for f in FIGURES) + (SENSITIVITY_STEM,)
