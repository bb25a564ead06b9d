"""SymPy derivations of the three papers.

SymPy draws from its own random generator (``sympy.core.random``), which Python seeds from the
operating system in every process: the assumptions system shuffles the order in which it tries
facts with it, and some simplification and polynomial algorithms pick random points. Measured on
the north-finding derivations (PYTHONHASHSEED=0, six seeds): the pickled derivation artefact came
out with two different byte strings, and in two of the six processes ``simplify`` of one residual
ran past the 600 s CPU guard, so the equation audit's residual text differed from run to run
(found by tests/shared/test_byte_identity.py in CI). Importing this package seeds that generator,
so every process that derives (the derive, audit and codegen steps, the notebooks, the tests)
makes the same choices.
"""

import os

# SymPy's cache (an LRU of its core operations) holds 1,000 entries unless SYMPY_CACHE_SIZE says
# otherwise, read when SymPy is first imported (the workflow's scripts import this package
# first). The derivations and the audit's simplifications evict entries they reuse at that size;
# at 50,000 the north-finding audit took about 12 % less CPU time, with the same outputs. A
# notebook imports SymPy before this package: the build gives its kernel the same size in its
# environment (pipeline.notebook_html.KERNEL_SYMPY_CACHE_SIZE, named there, not imported).
SYMPY_CACHE_SIZE = "50000"
os.environ.setdefault("SYMPY_CACHE_SIZE", SYMPY_CACHE_SIZE)

import sympy.core.random as _sympy_random  # noqa: E402

#: seed of SymPy's random generator in every process that imports ``derivations``
SYMPY_SEED = 0
_sympy_random.seed(SYMPY_SEED)

# A snapshot of derivations another process computed (the workflow's derive step, for the
# paper's notebook), named by INERTIAL_REPRO_DERIVATION_MEMO: see derivations.memo.
from derivations import memo as _memo  # noqa: E402

_memo.preload_env()
