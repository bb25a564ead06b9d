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

PAPER = Paper(
    slug="platform_drift",
    title=TITLE,
    citation=CITATION,
    load_scenario=load_scenario,
    figures=(
        FigureSpec("fig5_stationary.png", 5, "Fig. 5: stationary vehicle"),
        FigureSpec("fig6_latitude_change.png", 6, "Fig. 6: large latitude change"),
        FigureSpec("fig7_longitude_change.png", 7, "Fig. 7: large longitude change"),
        FigureSpec("fig8_lat_lon_change.png", 8, "Fig. 8: large latitude and longitude change"),
        FigureSpec(
            "fig9_latitude.png",
            None,
            "Extra fig. 9 (not in the paper): position error after 2 h against latitude",
        ),
    ),
)
