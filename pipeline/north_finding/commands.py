"""Console subcommands of this paper, read by ``pipeline/cli.py`` (``inertial-repro``).

Light on purpose: only the name, the module that runs it and a summary; the module is
imported when the subcommand runs.
"""

from __future__ import annotations

from pipeline.cli import Command

__all__ = ["COMMANDS"]

COMMANDS = {
    "north-finding": Command(
        "pipeline.north_finding.cli",
        "levelling, north finding and sensor calibration from turntable readings: 'estimate' "
        "reads a readings CSV, one row per reading, columns tau_deg, axis, role, accel_m_s2, "
        "gyro_rad_s, n_samples (table angle tau about the table's z axis, deg; averaged "
        "specific force, m/s^2, and angular rate, rad/s); 'simulate-readings' writes one",
    ),
}
