"""Platform-drift paper (slug ``platform_drift``): stable-platform position-independent
navigation versus strapdown under constant gyro drift.

Modules: :mod:`scenario` (validated scenario files), :mod:`trajectory` (truth kinematics on a
spherical rotating Earth), :mod:`platform` (physical platform + the paper's algorithm, eqs.
9-16, 25), :mod:`strapdown` (NED strapdown comparator), :mod:`analytic` (eqs. 32, 36 from the
generated code), :mod:`run` (results files and CLI).
"""
