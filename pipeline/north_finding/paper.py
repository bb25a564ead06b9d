"""The north_finding plug-in: levelling and north finding at rest with one accelerometer and one
gyro on a turntable (methods L1-L5, A1-A6; Tables 1-12, Figs. 1-5).

>>> PAPER.slug, PAPER.paper_figure_numbers
('north_finding', [1, 2, 3, 4, 5])
"""

from __future__ import annotations

from pipeline.north_finding.scenario import load_scenario
from pipeline.paper import FigureSpec, Paper

__all__ = ["PAPER", "TITLE", "CITATION", "FIGURE_CAPTIONS"]

TITLE = "The derivation of modern inertial navigation methods at stationary state"
CITATION = (
    "Mohammadkarimi, Nourani, Alizadeh Roknabadi, J. Aerospace Science and Technology (Persian), "
    "vol. 13 no. 1, 2023"
)

_BOX = (
    "Boxes: Monte Carlo distribution of |percent error| of the noisy real sensor "
    "(box 25–75 %, whiskers 5–95 %, line median); hollow circle: real sensor without noise; "
    "red diamond: the percent error printed in the paper. Log scale."
)
#: figure file stem -> caption (after the label "Fig. N" or "Extra fig. k")
FIGURE_CAPTIONS: dict[str, str] = {
    "fig1_roll": (
        f"(paper Fig. 1, Table 1): roll φ percent error of levelling methods L1–L4. {_BOX}"
    ),
    "fig2_pitch": (
        f"(paper Fig. 2, Table 2): pitch θ percent error of levelling methods L1–L4. {_BOX}"
    ),
    "fig3_azimuth": (
        f"(paper Fig. 3, Table 9): azimuth ψ percent error of azimuth methods "
        f"A1c1, A1c2, A2, A3, A4, A5. {_BOX}"
    ),
    "fig4_bias": (
        f"(paper Fig. 4, Tables 3 and 10): percent error of the accelerometer bias "
        f"(levelling method 5) and the gyro bias (azimuth method 4). {_BOX}"
    ),
    "fig5_scale": (
        f"(paper Fig. 5, Tables 4, 11, 12): percent error of the accelerometer scale factor "
        f"(method L5), the gyro scale factor (A4, A5, A6) and its first-order approximation "
        f"(A5, A6). {_BOX}"
    ),
    "fig6_sensitivity": (
        "Monte Carlo RMS percent error of the azimuth estimate against "
        "the number of samples averaged per table position (log–log). Dashed vertical line: the "
        "scenario's default n_avg; short ticks at the right edge: the published percent error of "
        "each method, in the method's colour. The paper does not state n_avg; this figure shows "
        "which averaging its errors imply."
    ),
}

PAPER = Paper(
    slug="north_finding",
    title=TITLE,
    citation=CITATION,
    load_scenario=load_scenario,
    figures=tuple(
        FigureSpec(f"{stem}.png", number if number <= 5 else None, caption)
        for number, (stem, caption) in enumerate(FIGURE_CAPTIONS.items(), 1)
    ),
    report="pipeline.north_finding.report:report",
)
