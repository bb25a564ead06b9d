"""One bound on how long a subprocess started by a test may run: a guard against a hang, not a
speed limit.

The suite takes about 10 minutes on an idle 2-core machine and was measured at 37 minutes on a
loaded one (load ~9). Every subprocess a test starts (Snakemake, make, a notebook kernel's
cell, a browser) is stopped only after :data:`HANG_GUARD_S`, far above what any of them takes
on a slow machine, so a slow or loaded machine never fails the suite, while a run that hangs
(a deadlock, a lost child) still ends. No test asserts a wall time.
"""

from __future__ import annotations

#: seconds after which a test's subprocess is taken to be hung
HANG_GUARD_S = 3600.0
