"""The altimeter_attitude plug-in: roll and pitch from an IMU and a barometric altimeter, a linear
Kalman filter on the third DCM row against a UKF (100-run Monte Carlo; Figs. 2-12).

>>> PAPER.slug, PAPER.paper_figure_numbers
('altimeter_attitude', [2, 3, 4, 5, 6, 7, 8, 9, 10, 11, 12])
"""

from __future__ import annotations

from pipeline.altimeter_attitude.scenario import load_scenario
from pipeline.altimeter_attitude.workflow import FIGURES, SWEEP_FIGURE
from pipeline.paper import FigureSpec, Paper

__all__ = ["PAPER", "TITLE", "CITATION"]

TITLE = "Strapdown attitude estimation using IMU and altimeter integration for maneuvering vehicles"
CITATION = (
    "H. Ghanbarpour Asl, S. H. Pourtakdust (Sharif University of Technology), "
    "Persian journal paper with an English abstract; its journal and year are not in the seed text"
)


def _number(file: str) -> int | None:
    head = file.split("_", 1)[0]
    return int(head[3:]) if head[3:].isdigit() else None


PAPER = Paper(
    slug="altimeter_attitude",
    title=TITLE,
    citation=CITATION,
    load_scenario=load_scenario,
    figures=tuple(
        FigureSpec(f, _number(f), f"Fig. {_number(f)}" if _number(f) else "not in the paper")
        for f in [*FIGURES, SWEEP_FIGURE]
    ),
)
