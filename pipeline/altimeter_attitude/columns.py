"""Column names of the altimeter_attitude results files (units in the names), and its method/quantity names."""

from __future__ import annotations

# results/<slug>/<scenario>/rms_summary.csv (contract of issue 4): one row per
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
# results/<slug>/<scenario>/run_rms.csv: per Monte Carlo run and filter, the RMS
# over time (after the transient) of the roll and pitch errors (paired comparisons of filters)
RUN_RMS_COLUMNS = ["run", "filter", "roll_rms_deg", "pitch_rms_deg"]
# results/<slug>/<scenario>/window_summary.csv: the rms_summary.csv statistics over each
# averaging window (pipeline/altimeter_attitude/windows.py): "flight" (after the transient, as
# rms_summary.csv) and "after_bank" (after the first bank that makes roll observable); start and
# end in s, NaN statistics when the scenario has no such window
WINDOWS = ("flight", "after_bank")
#: how the report names each window (the after-bank window is no steady state: it starts
#: where the first bank ends and runs to the end of the flight)
WINDOW_LABELS = {"flight": "flight window", "after_bank": "window after the first bank"}
WINDOW_SUMMARY_COLUMNS = ["window", "t_start_s", "t_end_s", *RMS_SUMMARY_COLUMNS]
# results/<slug>/<scenario>/window_run_rms.csv: run_rms.csv over each averaging window
WINDOW_RUN_RMS_COLUMNS = ["window", *RUN_RMS_COLUMNS]
# results/<slug>/<scenario>/timeseries.csv: per filter and output time, RMS over
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
# results/<slug>/<scenario>/truth.csv: the nominal trajectory (Figs 2-6) and the
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
# results/<slug>/sweep.csv: one-at-a-time sweep around the paper scenario; the RMS over the
# flight after the transient, then (added later, at the end) over the window after the first bank and its start
SWEEP_COLUMNS = [
    "parameter",
    "value",
    "filter",
    "roll_rms_deg",
    "pitch_rms_deg",
    "n_runs",
    "after_bank_roll_rms_deg",
    "after_bank_pitch_rms_deg",
    "after_bank_start_s",
]
# results/<slug>/<published scenario>/ukf_tuning.csv: the UKF over a grid of its sigma-point
# parameters (pipeline/altimeter_attitude/ukf_tuning.py), RMS over runs and over the flight
# after the transient, Monte Carlo and the noise-free run with an exact start
UKF_TUNING_COLUMNS = [
    "alpha",
    "kappa",
    "beta",
    "wm0",
    "wc0",
    "nonnegative_weights",
    "chosen",
    "roll_rms_deg",
    "pitch_rms_deg",
    "nees_roll",
    "nees_pitch",
    "noise_free_roll_rms_deg",
    "noise_free_pitch_rms_deg",
    "n_runs",
    "status",
]
# flight-log CLI output: estimated attitude per IMU sample
FLIGHTLOG_OUTPUT_COLUMNS = [
    "t_s",
    "filter",
    "roll_deg",
    "pitch_deg",
    "roll_sigma_deg",
    "pitch_sigma_deg",
]
