"""The platform_drift plug-in: position error of a stable-platform INS with the
position-independent algorithm under gyro drift (eqs. 28-36, Table 2; Figs. 5-8).

>>> PAPER.slug, PAPER.paper_figure_numbers
('platform_drift', [5, 6, 7, 8])
"""

from __future__ import annotations

from pipeline.paper import FigureSpec, Paper
from pipeline.platform_drift.scenario import load_scenario

__all__ = ["PAPER", "TITLE", "CITATION"]

TITLE = (
    "Gyroscope drift error analysis in the position-independent navigation algorithm of a "
    "stable platform inertial system"
)
CITATION = (
    "M. Ghesmati, J. Heirani Nobari, M. R. Arvan, A. Kashaninia, Persian journal paper with an "
    "English abstract, accepted 1397 (2018); the journal's name is not in the seed text"
)

_CURVES = (
    "position error of the proposed scheme (analytic and simulated) and of the strapdown INS; "
    "dashed: the proposed scheme with the true azimuth rate in eq. 16 (the part of the error "
    "eqs. 33-36 model); black diamond and dotted line: the 2 h strapdown error and the "
    "crossover time the paper's text gives for that panel (config/published/platform_drift.yaml)."
)

PAPER = Paper(
    slug="platform_drift",
    title=TITLE,
    citation=CITATION,
    load_scenario=load_scenario,
    figures=(
        FigureSpec("fig5_stationary.png", 5, f"(stationary vehicle): {_CURVES}"),
        FigureSpec("fig6_latitude_change.png", 6, f"(large latitude change): {_CURVES}"),
        FigureSpec("fig7_longitude_change.png", 7, f"(large longitude change): {_CURVES}"),
        FigureSpec(
            "fig8_lat_lon_change.png", 8, f"(large latitude and longitude change): {_CURVES}"
        ),
        FigureSpec(
            "fig9_latitude.png",
            None,
            "the stationary case rerun at latitudes 0-80 deg; error at 2 h of each curve. The "
            "strapdown channel-3 error scales with cos(latitude).",
        ),
    ),
    report="pipeline.platform_drift.report:report",
)
