"""Column names of the platform_drift results files (units in the names), and its method/quantity names."""

from __future__ import annotations

# results/<slug>/<scenario>/errors.csv (and errors_long.csv, errors_diagnostic.csv)
ERRORS_COLUMNS = ["t_s", "case", "scheme", "error_m"]
DRIFT_CASES = ("none", "ch1", "ch3", "ch1_ch3")
DRIFT_SCHEMES = ("proposed_analytic", "proposed_simulated", "strapdown")
# results/<slug>/<scenario>/summary.csv
DRIFT_SUMMARY_COLUMNS = ["case", "scheme", "error_2h_m", "error_max_m", "crossover_s"]
