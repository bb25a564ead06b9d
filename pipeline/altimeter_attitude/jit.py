"""The generated formulas compiled with numba, for the filter kernels (scalar arguments).

:mod:`pipeline.generated.altimeter_attitude` stays the one source of every formula: its
functions are compiled here as they are (their code objects, ``numba.njit(cache=True)``), not
re-typed, with ``np`` bound to the scalar ``math`` functions (numba lowers ``np.sin`` of a
float to ``math.sin``'s code, so the numbers are the same, but typing numpy's ufuncs costs
compile time). They end in ``_broadcast(out0, ...)``, which in compiled code is overloaded
to return the outputs as a tuple of floats (scalars need no broadcasting), so a kernel can
index it.

numba's on-disk cache goes to ``<base>/<key>``: ``base`` is ``NUMBA_CACHE_DIR`` if set, else
``.snakemake/numba-cache`` of the checkout (ignored by git, removed by ``make clean``), so no
file is written into the source tree and a fresh clone compiles once (~10 CPU-s, all five kernels) on first
use. ``key`` hashes this file, the generated module and the numba version: numba invalidates a
cached function only when its own file changes, not when a function it calls from another
file does. The kernels (kernels_euler, kernels_c, mc_sums) call only their own module's
functions and the compiled generated ones of this module, so a regenerated formula or a
changed option here must start a fresh cache, and does (only files the kernels import are
read, so the workflow's code inputs stay those of the import graph).

The kernels called from Python are declared with :func:`kernel`: a process's first call of
one (numba loads it from the cache or compiles and saves it) holds an exclusive lock on the
cache directory, so jobs that start together on a fresh clone (the workflow runs the three
scenarios, the sweep and the UKF tuning side by side) compile each kernel once between them:
the others wait, idle, and then load it (~0.1 CPU-s) instead of compiling it again.
"""

from __future__ import annotations

import contextlib
import fcntl
import functools
import hashlib
import os
import sys
from collections.abc import Iterator
from importlib.metadata import version
from pathlib import Path

from pipeline.altimeter_attitude.scenario import ROOT

_HERE = Path(__file__).resolve().parent
#: the files whose change a cached kernel would not see (any change: a fresh cache directory)
CACHE_SOURCES = (
    _HERE / "jit.py",
    ROOT / "pipeline" / "generated" / "altimeter_attitude.py",
)


def cache_key() -> str:
    digest = hashlib.sha256(f"numba {version('numba')}".encode())
    for path in CACHE_SOURCES:
        digest.update(path.read_bytes())
    return digest.hexdigest()[:16]


_BASE = Path(os.environ.get("NUMBA_CACHE_DIR") or ROOT / ".snakemake" / "numba-cache")
_KEY = cache_key()
if _BASE.name != _KEY:  # (a child process inherits the keyed directory)
    os.environ["NUMBA_CACHE_DIR"] = str(_BASE / _KEY)

import numba  # noqa: E402  (after NUMBA_CACHE_DIR: numba reads it at import)
from llvmlite import ir  # noqa: E402
from numba.core import types  # noqa: E402
from numba.extending import intrinsic, overload  # noqa: E402

from pipeline.generated import altimeter_attitude as gen  # noqa: E402

__all__ = [
    "accel_third_row",
    "euler_jacobian_third_row",
    "euler_model_rhs",
    "euler_process_noise",
    "euler_state_jacobian",
    "fma",
    "gamma_term_closed",
    "kernel",
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


@intrinsic
def fma(typingctx, a, b, c):
    """a * b + c rounded once (LLVM's llvm.fma: the FMA instruction, or libm's fma where
    there is none), for float64 arguments: how OpenBLAS's dgemm, hence numpy's ``@`` on
    float64 matrices, accumulates its products."""
    sig = types.float64(types.float64, types.float64, types.float64)

    def codegen(context, builder, signature, args):
        d = ir.DoubleType()
        fn = builder.module.declare_intrinsic("llvm.fma", [d], ir.FunctionType(d, [d, d, d]))
        return builder.call(fn, args)

    return sig, codegen


def njit(fn):
    """``numba.njit(cache=True)``: strict IEEE arithmetic (no fastmath) with numpy's error
    model (x / 0 is inf or NaN, as in the numpy code, not ZeroDivisionError), cached on disk."""
    return numba.njit(cache=True, error_model="numpy")(fn)


def _compile_lock_path() -> Path:
    """The lock file in the directory numba caches to (read by numba at its import)."""
    path = Path(numba.config.CACHE_DIR or os.environ["NUMBA_CACHE_DIR"])
    path.mkdir(parents=True, exist_ok=True)
    return path / "compile.lock"


def jit_lock_path() -> Path:
    return _compile_lock_path()


@contextlib.contextmanager
def _without_scipy_linalg() -> Iterator[None]:
    """numba's first compilation or cache load in a process imports its numpy implementations
    (``numba.np.arraymath``), which import ``scipy.linalg`` only to learn whether ``np.dot``
    may call BLAS (~0.3 CPU-s a process, the largest part of that import). No kernel here
    uses numpy's linear algebra, so while this context is open the import fails at once
    (``sys.modules[name] = None``) and numba takes ``np.dot`` to have no BLAS. Nothing is
    blocked once it closes, nor when ``scipy.linalg`` was imported already; the compiled code
    of the kernels is the same (they call no BLAS)."""
    name = "scipy.linalg"
    if name in sys.modules or "numba.np.arraymath" in sys.modules:
        yield
        return
    sys.modules[name] = None  # type: ignore[assignment]
    try:
        yield
    finally:
        if sys.modules.get(name, 0) is None:
            del sys.modules[name]


def kernel(fn):
    """:func:`njit` for a kernel called from Python: its first call in a process (cache load
    or compilation) holds the cache directory's lock (``compile.lock``, ``flock``), so no two
    processes compile the same kernel at once; a waiting one then loads what the other saved.
    That first call does not import ``scipy.linalg`` (:func:`_without_scipy_linalg`).
    The dispatcher is ``.dispatcher``."""
    dispatcher = njit(fn)

    @functools.wraps(fn)
    def call(*args):
        if dispatcher.signatures:
            return dispatcher(*args)
        with _without_scipy_linalg():
            try:
                fd = os.open(jit_lock_path(), os.O_RDWR | os.O_CREAT, 0o644)
            except OSError:  # a read-only cache directory: numba then compiles without caching
                return dispatcher(*args)
            try:
                try:
                    fcntl.flock(fd, fcntl.LOCK_EX)
                except OSError:  # a file system without locks (some network mounts): no lock
                    pass
                return dispatcher(*args)
            finally:
                os.close(fd)  # (releases the lock)

    call.dispatcher = dispatcher
    return call


import math as _math  # noqa: E402
import types as _types  # noqa: E402

_SCALAR_NP = _types.ModuleType("scalar_np")
for _name, _fn in (
    ("sin", _math.sin), ("cos", _math.cos), ("tan", _math.tan), ("sqrt", _math.sqrt),
    ("arcsin", _math.asin), ("arctan2", _math.atan2),
):  # fmt: skip
    setattr(_SCALAR_NP, _name, _fn)


def _scalar(fn):
    """The generated function ``fn`` with ``np.sin`` etc. read from ``_SCALAR_NP``."""
    return _types.FunctionType(fn.__code__, {**vars(gen), "np": _SCALAR_NP}, fn.__name__)


# the generated functions the kernels call (scalar in, tuple of floats out)
euler_model_rhs = njit(_scalar(gen.euler_model_rhs))
euler_process_noise = njit(_scalar(gen.euler_process_noise))
euler_state_jacobian = njit(_scalar(gen.euler_state_jacobian))
accel_third_row = njit(_scalar(gen.accel_third_row))
third_row_rotation = njit(_scalar(gen.third_row_rotation))
normalisation_error = njit(_scalar(gen.normalisation_error))
gamma_term_closed = njit(_scalar(gen.gamma_term_closed))
euler_jacobian_third_row = njit(_scalar(gen.euler_jacobian_third_row))
