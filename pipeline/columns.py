"""Column names of the results files (the results contract of DESIGN.md).

Every reader and writer of a results CSV imports its columns from here, so a
rename happens in one place. Units are carried in the names (``_deg``,
``_ug``, ``_rad_s``, ``_pct``).
"""

from __future__ import annotations

# results/<slug>/equation_audit.csv
AUDIT_COLUMNS = ["equation", "status", "residual", "note"]
AUDIT_STATUSES = ("match", "differs", "not_checkable")

# results/<slug>/verdicts.csv
VERDICT_COLUMNS = ["id", "kind", "quantity", "method", "published", "reproduced", "verdict", "note"]
VERDICT_KINDS = ("exact", "statistical", "claim")
# exact -> reproduced | not_reproduced; statistical -> consistent | not_reproduced;
# claim -> upheld | not_upheld | not_checkable
VERDICTS = ("reproduced", "consistent", "not_reproduced", "upheld", "not_upheld", "not_checkable")

# results/north_finding/<scenario>/estimates.csv
ESTIMATE_COLUMNS = ["sensor", "method", "quantity", "truth", "estimate", "error_pct"]
SENSORS = ("ideal", "real")

# results/north_finding/<scenario>/mc_summary.csv
MC_SUMMARY_COLUMNS = ["method", "quantity", "truth", "mean", "std", "p05", "p50", "p95", "n_trials"]

# results/north_finding/<scenario>/mc_trials.csv (one row per trial, method, quantity)
MC_TRIAL_COLUMNS = ["trial", "method", "quantity", "truth", "estimate", "error_pct"]

# results/north_finding/<scenario>/error_budget.csv: deterministic error of the
# noise-free real run with one error source switched on at a time, and the Monte
# Carlo standard deviation as the 'noise' source.
ERROR_BUDGET_COLUMNS = ["method", "quantity", "source", "error", "error_pct"]
ERROR_SOURCES = ("scale_factor", "misalignment", "bias", "noise", "all_deterministic")

# results/north_finding/<scenario>/sensitivity.csv: Monte Carlo spread against the
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

# results/platform_drift/<scenario>/errors.csv (and errors_long.csv, errors_diagnostic.csv)
ERRORS_COLUMNS = ["t_s", "case", "scheme", "error_m"]
DRIFT_CASES = ("none", "ch1", "ch3", "ch1_ch3")
DRIFT_SCHEMES = ("proposed_analytic", "proposed_simulated", "strapdown")
# results/platform_drift/<scenario>/summary.csv
DRIFT_SUMMARY_COLUMNS = ["case", "scheme", "error_2h_m", "error_max_m", "crossover_s"]

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

# results/altimeter_attitude/<scenario>/rms_summary.csv (contract of issue 4): one row per
# filter; RMS over runs and over time after the transient; sigma = RMS of the filter's own
# standard deviation; nees = mean of error^2 / sigma^2 (1 for a consistent filter)
RMS_SUMMARY_COLUMNS = [
    "filter",
    "roll_rms_deg",
    "pitch_rms_deg",
    "roll_sigma_deg",
    "pitch_sigma_deg",
    "nees_roll",
    "nees_pitch",
    "n_runs",
]
ALTIMETER_FILTERS = (
    "linear_kf",  # eq. 26/31 with the Gamma (Q kron P) Gamma^T term
    "linear_kf_no_gamma",  # the same without that term
    "ukf",  # Euler-angle UKF (Sec. 6)
    "ekf",  # Euler-angle EKF (the paper says it diverges)
    "complementary",  # PI complementary filter of Fig. 1
    "gyro_only",  # gyro propagation (eq. 14), no correction
    "accel_leveling",  # eq. 17-b / 11 at every step (cruise assumption)
)
# results/altimeter_attitude/<scenario>/run_rms.csv: per Monte Carlo run and filter, the RMS
# over time (after the transient) of the roll and pitch errors (paired comparisons of filters)
RUN_RMS_COLUMNS = ["run", "filter", "roll_rms_deg", "pitch_rms_deg"]
# results/altimeter_attitude/<scenario>/timeseries.csv: per filter and output time, RMS over
# runs of the errors, of the filter's sigma, and of the normalisation error 1 - c^T c
TIMESERIES_COLUMNS = [
    "t_s",
    "filter",
    "roll_rms_deg",
    "pitch_rms_deg",
    "roll_sigma_deg",
    "pitch_sigma_deg",
    "c1_rms",
    "c2_rms",
    "c3_rms",
    "norm_error_rms",
    "nees_roll",
    "nees_pitch",
]
# results/altimeter_attitude/<scenario>/truth.csv: the nominal trajectory (Figs 2-6) and the
# sensor outputs of run 0
TRUTH_COLUMNS = [
    "t_s",
    "c31",
    "c32",
    "c33",
    "roll_deg",
    "pitch_deg",
    "yaw_deg",
    "v_d_m_s",
    "h_m",
    "load_factor",
    "gyro_x_deg_s",
    "gyro_y_deg_s",
    "gyro_z_deg_s",
    "accel_x_m_s2",
    "accel_y_m_s2",
    "accel_z_m_s2",
    "altimeter_m",
]
# results/altimeter_attitude/sweep.csv: one-at-a-time sweep around the paper scenario
SWEEP_COLUMNS = ["parameter", "value", "filter", "roll_rms_deg", "pitch_rms_deg", "n_runs"]
# flight-log CLI output: estimated attitude per IMU sample
FLIGHTLOG_OUTPUT_COLUMNS = [
    "t_s",
    "filter",
    "roll_deg",
    "pitch_deg",
    "roll_sigma_deg",
    "pitch_sigma_deg",
]
