"""Console subcommands of this paper, read by ``pipeline/cli.py`` (``inertial-repro``).

Light on purpose: only the name, the module that runs it and a summary; the module is
imported when the subcommand runs.
"""

from __future__ import annotations

from pipeline.cli import Command

__all__ = ["COMMANDS"]

COMMANDS = {
    "flight-log": Command(
        "pipeline.altimeter_attitude.flightlog",
        "roll and pitch (NED, 3-2-1 Euler angles, deg) from an IMU + barometric altimeter "
        "flight-log CSV, one row per IMU sample, columns t_s, gyro_x_rad_s, gyro_y_rad_s, "
        "gyro_z_rad_s (or _deg_s), accel_x_m_s2, accel_y_m_s2, accel_z_m_s2, altimeter_m "
        "(body axes x forward, y right, z down)",
    ),
}
