"""The generated formulas compiled with numba, for the filter kernels (scalar arguments).

:mod:`pipeline.generated.altimeter_attitude` stays the one source of every formula: its
functions are compiled here as they are (``numba.njit(gen.f, cache=True)``), not re-typed.
They end in ``_broadcast(out0, ...)``, which in compiled code is overloaded to return the
outputs as a tuple of floats (scalars need no broadcasting), so a kernel can index it.

numba's on-disk cache goes to ``NUMBA_CACHE_DIR``, by default ``.snakemake/numba-cache`` of
the checkout (ignored by git, removed by ``make clean``); no file is written into the source
tree, and a fresh clone compiles once (~20 CPU-s) on first use.
"""

from __future__ import annotations

import os

from pipeline.altimeter_attitude.scenario import ROOT

os.environ.setdefault("NUMBA_CACHE_DIR", str(ROOT / ".snakemake" / "numba-cache"))

import numba  # noqa: E402  (after NUMBA_CACHE_DIR: numba reads it at import)
from numba.extending import overload  # noqa: E402

from pipeline.generated import altimeter_attitude as gen  # noqa: E402

__all__ = [
    "accel_third_row",
    "euler_jacobian_third_row",
    "euler_model_rhs",
    "euler_process_noise",
    "euler_state_jacobian",
    "gamma_term_closed",
    "njit",
    "normalisation_error",
    "third_row_rotation",
]


@overload(gen._broadcast)
def _broadcast_scalars(*outs):
    """Compiled ``_broadcast`` of scalars: the outputs as a homogeneous tuple of floats."""
    items = "".join(f"float(outs[{i}]), " for i in range(len(outs)))
    namespace: dict = {}
    exec(f"def impl(*outs):\n    return ({items})\n", namespace)
    return namespace["impl"]


def njit(fn):
    """``numba.njit(cache=True)``: strict IEEE arithmetic (no fastmath), cached on disk."""
    return numba.njit(cache=True)(fn)


# the generated functions the kernels call (scalar in, tuple of floats out)
euler_model_rhs = njit(gen.euler_model_rhs)
euler_process_noise = njit(gen.euler_process_noise)
euler_state_jacobian = njit(gen.euler_state_jacobian)
accel_third_row = njit(gen.accel_third_row)
third_row_rotation = njit(gen.third_row_rotation)
normalisation_error = njit(gen.normalisation_error)
gamma_term_closed = njit(gen.gamma_term_closed)
euler_jacobian_third_row = njit(gen.euler_jacobian_third_row)
