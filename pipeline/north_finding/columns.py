"""Column names of the north_finding results files (units in the names), and its method/quantity names."""

from __future__ import annotations

# results/<slug>/<scenario>/estimates.csv; scan_bound_deg: for A3's psi, the bound (deg) on its
# error from the step of the peak scan (pipeline/north_finding/scan_bound.py; 0 when the table
# stops at the true tau*, empty for other rows); flag: a3_scan_bound_exceeds_accuracy when that
# bound exceeds the scenario's a3_accuracy_deg, a3_scan_bound_unknown when no bound can be
# computed (fewer than 2 peak readings), else empty
ESTIMATE_COLUMNS = [
    "sensor",
    "method",
    "quantity",
    "truth",
    "estimate",
    "error_pct",
    "scan_bound_deg",
    "flag",
]
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

# results/<slug>/<scenario>/ranking.csv: Monte Carlo RMS % error of every method at each
# averaging count N of the scenario's ranking block (the claims that rank methods are judged
# at each N), and ranking_pairs.csv: per N and quantity, the paired difference of the squared
# % errors of two methods over the same trials (its mean and standard error) and their largest
# per-trial difference (0 where two methods are the same estimator).
RANKING_COLUMNS = ["n_avg", "method", "quantity", "rms_error_pct", "n_trials"]
RANKING_PAIR_COLUMNS = [
    "n_avg",
    "quantity",
    "method_a",
    "method_b",
    "mean_sq_diff_pct2",
    "se_sq_diff_pct2",
    "max_abs_diff_pct",
    "n_trials",
]

# results/<slug>/<scenario>/a2_scan.csv: the noise-free real-sensor azimuth of method A2 at
# every whole-degree table angle (the paper does not give its tau).
A2_SCAN_COLUMNS = ["tau_deg", "psi_deg", "error_deg"]

# results/<slug>/<scenario>/n_profile.csv: per grid N, the profile log-likelihood of the used
# statistical rows (robust, and with the plain Gaussian, eps = 0, for comparison), how many
# rows are used and how many lie inside the rank band there, the largest Kolmogorov-Smirnov
# distance of a Gaussian fit, the Monte Carlo trials used per N (the fewest finite trials of
# any row: NaN trials are dropped, and counted in n_trouble.csv), and whether N is the
# maximum-likelihood N of all used rows.
N_PROFILE_COLUMNS = [
    "n_avg",
    "log_lik",
    "log_lik_gaussian",
    "n_rows_used",
    "n_rows_in_band",
    "max_ks",
    "n_trials",
    "inferred",
]
# results/<slug>/<scenario>/n_rows.csv: per statistical row and grid N, the Gaussian fitted to
# the trials (mean, std, KS distance), the published value's percentile rank among the trials,
# whether it is inside the band, the row's robust log-likelihood as it enters the composite
# likelihood (times row_weight), row_weight (1 / sum_j r_ij^2 over the used rows, r the
# correlation of the rows' trials: correlated rows share their vote), the posterior probability
# that the row comes from the contamination component (a run the paper does not describe),
# whether the row is used (not excluded by rule 1), and the row's leave-one-out weight of that
# N (the likelihood of the other rows, normalised over the grid; the row is judged on the
# mixture of the trials at every N with these weights).
N_ROW_COLUMNS = [
    "id",
    "method",
    "quantity",
    "published",
    "n_avg",
    "mean",
    "std",
    "ks",
    "rank_pct",
    "in_band",
    "log_lik",
    "row_weight",
    "outlier_prob",
    "used",
    "weight",
]
# results/<slug>/<scenario>/n_robustness.csv: the inference rerun on the grid ("grid") and on
# its powers of ten alone ("decades"), at the scenario's contamination and each of
# contamination_check: the N inferred from all rows, and the statistical rows outside the rank
# band in their leave-one-out mixture (their count and ids, ";"-separated).
N_ROBUSTNESS_COLUMNS = [
    "grid",
    "contamination",
    "n_inferred",
    "n_not_consistent",
    "not_consistent",
]
# results/<slug>/<scenario>/mc_trials_judged.csv: the Monte Carlo trials (as mc_trials.csv) at
# every grid N of the N inference (the rows' weights, and those of the reweighted likelihoods
# of the sensitivity, may fall on any).
# results/<slug>/n_sensitivity.csv: the N inference with the rows reweighted
# (pipeline/north_finding/n_sensitivity.py): inferred N, its weight, effective number of rows,
# and the verdict rows that change.
MC_JUDGED_COLUMNS = ["n_avg", *MC_TRIAL_COLUMNS]
N_SENSITIVITY_COLUMNS = [
    "variant",
    "n_inferred",
    "weight_at_n",
    "effective_rows",
    "n_changed",
    "changed",
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
