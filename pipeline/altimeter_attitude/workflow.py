"""File names of the altimeter_attitude figures (the paper plug-in, the figures and the page use
them)."""

from __future__ import annotations

__all__ = ["FIGURES", "SWEEP_FIGURE"]

# Figs 2-12 of the paper (published scenario), our filter comparison, and the sweep
FIGURES = [
    "fig2_third_row.png",
    "fig3_specific_force.png",
    "fig4_vertical_channel.png",
    "fig5_angular_rates.png",
    "fig6_roll_pitch.png",
    "fig7_lkf_rms_error.png",
    "fig8_lkf_c_rms.png",
    "fig9_lkf_sigma.png",
    "fig10_norm_error.png",
    "fig11_ukf_sigma.png",
    "fig12_ukf_rms_error.png",
    "fig_compare_filters.png",
]
SWEEP_FIGURE = "fig_sweep.png"
