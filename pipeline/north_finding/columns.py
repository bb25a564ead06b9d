"""Column names of the north_finding results files (units in the names), and its method/quantity names."""

from __future__ import annotations

# results/<slug>/<scenario>/estimates.csv
ESTIMATE_COLUMNS = ["sensor", "method", "quantity", "truth", "estimate", "error_pct"]
SENSORS = ("ideal", "real")

# results/<slug>/<scenario>/mc_summary.csv
MC_SUMMARY_COLUMNS = ["method", "quantity", "truth", "mean", "std", "p05", "p50", "p95", "n_trials"]

# results/<slug>/<scenario>/mc_trials.csv (one row per trial, method, quantity)
MC_TRIAL_COLUMNS = ["trial", "method", "quantity", "truth", "estimate", "error_pct"]

# results/<slug>/<scenario>/error_budget.csv: deterministic error of the
# noise-free real run with one error source switched on at a time, and the Monte
# Carlo standard deviation as the 'noise' source.
ERROR_BUDGET_COLUMNS = ["method", "quantity", "source", "error", "error_pct"]
ERROR_SOURCES = ("scale_factor", "misalignment", "bias", "noise", "all_deterministic")

# results/<slug>/<scenario>/sensitivity.csv: Monte Carlo spread against the
# number of samples averaged per table position.
SENSITIVITY_COLUMNS = [
    "n_avg",
    "method",
    "quantity",
    "truth",
    "rms_error",
    "rms_error_pct",
    "n_trials",
]

LEVELING_METHODS = ("L1", "L2", "L3", "L4", "L5")
AZIMUTH_METHODS = ("A1c1", "A1c2", "A2", "A3", "A4", "A5", "A6")
METHODS = LEVELING_METHODS + AZIMUTH_METHODS

QUANTITIES = (
    "phi_deg",
    "theta_deg",
    "psi_deg",
    "acc_bias_ug",
    "acc_scale",
    "acc_scale_approx",
    "gyro_bias_rad_s",
    "gyro_scale",
    "gyro_scale_approx",
)

# Which quantities each method produces.
METHOD_QUANTITIES = {
    "L1": ("phi_deg", "theta_deg"),
    "L2": ("phi_deg", "theta_deg"),
    "L3": ("phi_deg", "theta_deg"),
    "L4": ("phi_deg", "theta_deg"),
    "L5": ("acc_bias_ug", "acc_scale", "acc_scale_approx"),
    "A1c1": ("psi_deg",),
    "A1c2": ("psi_deg",),
    "A2": ("psi_deg",),
    "A3": ("psi_deg",),
    "A4": ("psi_deg", "gyro_bias_rad_s", "gyro_scale"),
    "A5": ("psi_deg", "gyro_scale", "gyro_scale_approx"),
    "A6": ("gyro_scale", "gyro_scale_approx"),
}
