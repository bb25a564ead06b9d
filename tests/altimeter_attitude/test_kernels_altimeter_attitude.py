"""The numba kernels of the filter loops (kernels_euler, kernels_c, jit) against the numpy
loops they replace (the reference, ``compiled=False``), filterpy, and their fallbacks."""

from __future__ import annotations

import numpy as np
import pytest

from pipeline.altimeter_attitude import complementary, euler_filters, jit, linear_kf, model
from pipeline.altimeter_attitude.scenario import ROOT, build_scenario, load_scenario
from pipeline.altimeter_attitude.sensors import simulate_inputs
from pipeline.altimeter_attitude.ukf import NotPositiveDefiniteError
from pipeline.generated import altimeter_attitude as gen

PAPER = ROOT / "config" / "scenarios" / "altimeter_attitude" / "paper.yaml"
FIELDS = ("roll", "pitch", "roll_sigma", "pitch_sigma", "c", "norm_error")


@pytest.fixture(scope="module")
def short():
    """The paper scenario cut to its first 30 s (pull-up and push-over), 3 noisy runs."""
    base = load_scenario(PAPER)
    raw = {**base.raw, "trajectory": {**base.raw["trajectory"], "duration_s": 30.0}}
    raw["trajectory"]["maneuvers"] = [
        m for m in base.raw["trajectory"]["maneuvers"] if m["start_s"] + m["duration_s"] <= 30.0
    ]
    sc = build_scenario(raw, base.path)
    return sc, simulate_inputs(sc.profiles, sc.sensors, sc.initial, 3, sc.seed, sc.name)


def _runs(sc, inp, compiled):
    out = linear_kf.run_linear_kf(
        inp, sc.k, sc.input_matrix, tuple(linear_kf.VARIANTS), sc.p0_radial, compiled=compiled
    )
    out.append(
        euler_filters.run_ukf(inp, sc.ukf_alpha, sc.ukf_beta, sc.ukf_kappa, compiled=compiled)
    )
    out.append(euler_filters.run_ekf(inp, compiled=compiled))
    out.append(complementary.run_complementary(inp, sc.omega_c, sc.xi, compiled=compiled))
    return out


def _max_diff(a, b) -> float:
    worst = 0.0
    for f in FIELDS:
        x, y = getattr(a, f), getattr(b, f)
        assert x.shape == y.shape, f
        assert np.array_equal(np.isnan(x), np.isnan(y)), f
        if not np.all(np.isnan(x)):
            worst = max(worst, float(np.nanmax(np.abs(x - y))))
    return worst


def test_kernels_equal_the_numpy_loops(short):
    """Every filter, compiled and numpy, on the same 3 runs: every estimate, sigma, c and
    1 - c^T c within 1e-9 (seen: ~1e-12; the summation order differs), and the filters'
    estimates really move (not a copy of the initial state)."""
    sc, inp = short
    for a, b in zip(_runs(sc, inp, True), _runs(sc, inp, False), strict=True):
        assert a.filter == b.filter
        assert _max_diff(a, b) < 1e-9, a.filter
        assert np.ptp(a.roll[0]) > 1e-3, a.filter


def test_compiled_ukf_equals_filterpy(short):
    """The compiled UKF on one run equals filterpy 2.0.0's UnscentedKalmanFilter (given the
    plain scalar RK4 model, the same sigma points and data) to 1e-9 rad."""
    from pipeline.altimeter_attitude.benchmark import filterpy_ukf

    sc, inp = short
    ours = euler_filters.run_ukf(inp, sc.ukf_alpha, sc.ukf_beta, sc.ukf_kappa)
    ref = filterpy_ukf(inp, 1, sc.ukf_alpha, sc.ukf_beta, sc.ukf_kappa)
    assert np.abs(ours.roll[1] - ref[:, 0]).max() < 1e-9
    assert np.abs(ours.pitch[1] - ref[:, 1]).max() < 1e-9


def test_ukf_not_positive_definite_falls_back_and_names_the_run(short):
    """A run whose P0 is singular: the kernel flags it, the numpy loop reruns and raises
    NotPositiveDefiniteError naming that run only."""
    sc, inp = short
    sigma0 = inp.sigma0.copy()
    sigma0[1, 2] = 0.0
    bad = inp.__class__(**{**inp.__dict__, "sigma0": sigma0})
    with pytest.raises(NotPositiveDefiniteError, match=r"trial indices \[1\]"):
        euler_filters.run_ukf(bad, sc.ukf_alpha, sc.ukf_beta, sc.ukf_kappa)


def test_linear_kf_exact_exponential_step_falls_back_to_numpy(short, monkeypatch):
    """With A_DT_MAX = 0 every step needs the exact exponential: the compiled path gives up
    and the numpy loop's result comes back, bit for bit (the kernel alone differs at ~1e-13)."""
    sc, inp = short
    monkeypatch.setattr(model.ChunkDiscretisation, "A_DT_MAX", 0.0)
    a = linear_kf.run_linear_kf(inp, sc.k, sc.input_matrix, ("linear_kf",), compiled=True)[0]
    b = linear_kf.run_linear_kf(inp, sc.k, sc.input_matrix, ("linear_kf",), compiled=False)[0]
    for f in FIELDS:
        np.testing.assert_array_equal(getattr(a, f), getattr(b, f), err_msg=f)


def test_compiled_generated_functions_equal_the_generated_ones():
    """The compiled generated formulas (jit.py) return what the generated numpy functions do."""
    rng = np.random.default_rng(7)
    for fn, n_args in (
        (gen.euler_model_rhs, 11),
        (gen.euler_process_noise, 5),
        (gen.euler_state_jacobian, 8),
        (gen.accel_third_row, 3),
        (gen.third_row_rotation, 8),
        (gen.gamma_term_closed, 9),
        (gen.euler_jacobian_third_row, 3),
    ):
        args = [float(v) for v in rng.uniform(0.1, 0.9, n_args)]
        want = np.asarray(fn(*args), dtype=float)
        got = np.asarray(getattr(jit, fn.__name__)(*args), dtype=float)
        np.testing.assert_allclose(got, want, rtol=1e-14, atol=1e-15, err_msg=fn.__name__)
    assert jit.normalisation_error(0.6, 0.0, 0.8) == gen.normalisation_error(0.6, 0.0, 0.8)


def test_numba_cache_is_outside_the_source_tree():
    """numba's cache (NUMBA_CACHE_DIR) is not written next to the sources: no .nbi/.nbc
    under pipeline/ after the kernels ran (the tests above compiled them)."""
    import os

    cache = os.environ["NUMBA_CACHE_DIR"]
    assert not str(cache).startswith(str(ROOT / "pipeline"))
    assert not list((ROOT / "pipeline").rglob("*.nbi"))
    assert not list((ROOT / "pipeline").rglob("*.nbc"))


def test_euler_model_rhs_structure_the_ukf_kernel_shares():
    """kernels_euler.ukf_runs integrates the sigma points whose roll and pitch are the centre
    point's with the centre point's stages: it rests on d[phi, theta, V_d]/dt not depending on
    V_d and h, and dh/dt = -V_d, bit for bit (here on the compiled generated formula)."""
    rng = np.random.default_rng(11)
    for _ in range(200):
        phi, theta = rng.uniform(-1.5, 1.5, 2)
        rest = [float(v) for v in rng.normal(0.0, 3.0, 6)] + [9.80665]
        ref = jit.euler_model_rhs(phi, theta, 0.0, 0.0, *rest)
        for v_d, h in rng.normal(0.0, 100.0, (5, 2)):
            out = jit.euler_model_rhs(phi, theta, v_d, h, *rest)
            assert out[:3] == ref[:3]
            assert out[3] == -v_d


def test_ukf_kernel_shared_stages_equal_full_integration(short):
    """The UKF kernel (5 of 9 sigma points integrated in full) gives the very numbers of the
    same kernel integrating every point (compiled again with the sharing test disabled)."""
    import numba

    from pipeline.altimeter_attitude import kernels_euler

    sc, inp = short
    want = euler_filters.run_ukf(inp, sc.ukf_alpha, sc.ukf_beta, sc.ukf_kappa)
    saved = kernels_euler._same_bits
    try:  # numba freezes the globals a function sees when it compiles it (no cache here)
        kernels_euler._same_bits = numba.njit(lambda a, b: False)
        full = numba.njit(error_model="numpy")(kernels_euler.ukf_runs.dispatcher.py_func)
        weights = euler_filters.ukf.MerweWeights(
            n=4, alpha=sc.ukf_alpha, beta=sc.ukf_beta, kappa=sc.ukf_kappa
        )
        x, P = euler_filters._initial(inp)
        sens = inp.sensors
        xs, var, failed = full(
            *euler_filters._kernel_inputs(inp), x, P, np.array(weights.Wm),
            np.array(weights.Wc), weights.scale, inp.dt, inp.g, sens.gyro_sigma**2,
            sens.accel_sigma**2, sens.altimeter_sigma**2, euler_filters.Q_FLOOR,
        )  # fmt: skip
    finally:
        kernels_euler._same_bits = saved
    assert not failed.any()
    np.testing.assert_array_equal(xs[..., 0], want.roll)
    np.testing.assert_array_equal(xs[..., 1], want.pitch)
    np.testing.assert_array_equal(np.sqrt(var[..., 0]), want.roll_sigma)
    np.testing.assert_array_equal(np.sqrt(var[..., 1]), want.pitch_sigma)


def _plus_one(a):
    return a + 1.0


def test_kernel_first_call_holds_the_compile_lock(tmp_path, monkeypatch):
    """jit.kernel: the first call in a process takes the cache directory's lock (another
    process holding it makes the call wait), later calls do not."""
    import fcntl
    import os
    import threading

    calls = []
    disp = jit.kernel(_plus_one)
    monkeypatch.setattr(jit, "jit_lock_path", lambda: tmp_path / "compile.lock")
    fd = os.open(tmp_path / "compile.lock", os.O_RDWR | os.O_CREAT)
    fcntl.flock(fd, fcntl.LOCK_EX)
    worker = threading.Thread(target=lambda: calls.append(disp(1.0)))
    worker.start()
    worker.join(0.5)
    assert worker.is_alive() and not calls  # waits for the lock
    os.close(fd)
    worker.join(60)
    assert calls == [2.0]
    assert disp.dispatcher.signatures and disp(2.0) == 3.0


def test_first_kernel_call_does_not_import_scipy_linalg():
    """A fresh process's first kernel call (numba's registries loaded) leaves scipy.linalg
    unimported and importable (jit._without_scipy_linalg); the kernel computes as before."""
    import subprocess
    import sys

    code = (
        "import sys\n"
        "import numpy as np\n"
        "from pipeline.altimeter_attitude import kernels_c\n"
        "c = kernels_c.complementary_runs(np.zeros((1, 2, 3)), np.ones((1, 2, 3)),\n"
        "    np.array([[0.0, 0.0, 1.0]]), 0.01, 1.0, 0.1)\n"
        "assert 'scipy.linalg' not in sys.modules, 'scipy.linalg imported'\n"
        "import scipy.linalg\n"
        "print(c.shape, scipy.linalg.__name__)\n"
    )
    res = subprocess.run(
        [sys.executable, "-c", code], cwd=ROOT, capture_output=True, text=True, timeout=600
    )
    assert res.returncode == 0, res.stderr
    assert res.stdout.split() == ["(1,", "3,", "3)", "scipy.linalg"]


def test_ukf_without_third_row_gives_the_same_angles(short):
    """run_ukf(third_row=False) (the UKF tuning's form): the same roll, pitch and sigmas bit
    for bit, c left NaN instead of computed."""
    sc, inp = short
    args = (sc.ukf_alpha, sc.ukf_beta, sc.ukf_kappa)
    full = euler_filters.run_ukf(inp, *args)
    lean = euler_filters.run_ukf(inp, *args, third_row=False)
    for f in ("roll", "pitch", "roll_sigma", "pitch_sigma", "norm_error"):
        np.testing.assert_array_equal(getattr(lean, f), getattr(full, f), err_msg=f)
    assert lean.c.shape == full.c.shape and np.isnan(lean.c).all()
    assert np.isfinite(full.c).all()


def test_linear_kf_chunk_terms_are_chunk_discretisation_bit_for_bit(short):
    """The linear-KF kernel's own F terms (kernels_c.chunk_terms, chunk_order) are
    ChunkDiscretisation's numpy arrays bit for bit, signed zeros included (a stationary
    gyro), wherever numpy's ``w @ w`` is fused multiply-adds in k order (OpenBLAS's dgemm);
    with another BLAS, to round-off."""
    from pipeline.altimeter_attitude import kernels_c

    sc, inp = short
    gyro, accel = inp.gyro.copy(), inp.accel.copy()
    c0, c1, dt = 100, 356, inp.dt
    gyro[0, c0] = [0.0, -0.0, 0.0]
    gyro[1, c0 + 1] = [-0.0, -0.0, -0.0]
    disc = model.ChunkDiscretisation(*model.a_blocks(gyro[:, c0:c1], accel[:, c0:c1]), dt)
    basis, coef = np.ascontiguousarray(model._INPUT_BASIS), model.series_coefficients(dt)
    w, w2, v, pw, terms = (np.empty(shape) for shape in ((3, 3), (3, 3), (3, 3), 22, (3, 3, 3)))
    order, theta_max = kernels_c.chunk_order(
        gyro, accel, c0, c1, basis, coef, dt, linear_kf.CHUNK_TOL, w, w2, v, pw, terms
    )
    theta2 = -0.5 * np.trace(disc.w_block * dt @ (disc.w_block * dt), axis1=-2, axis2=-1)
    assert theta_max == float(np.sqrt(theta2.max(initial=0.0))) and 2 < order < 40
    fma_blas = True
    for i in range(inp.n_runs):
        for j, step in enumerate(range(c0, c1)):
            t2 = kernels_c.chunk_terms(
                gyro, accel, i, step, basis, coef, order, dt, w, w2, v, pw, terms
            )
            fma_blas &= np.array_equal(w @ w, w2)
            got = terms.ravel()
            want = np.concatenate(
                [disc.exp_w[i, j].ravel()]
                + [disc.f_psi[q][i, j] for q in range(3)]
                + [disc.f_xi[q][i, j] for q in range(3)]
            )
            if fma_blas:
                assert t2 == theta2[i, j]
                assert np.array_equal(got.view(np.int64), want.view(np.int64)), (i, step)
            else:
                np.testing.assert_allclose(got, want, rtol=1e-14, atol=1e-18)


def test_bench_step_scaling_times_each_length(short, monkeypatch, capsys):
    """Part 5 of the benchmark runs every filter on each length and prints its cost per
    run-step and the longest/shortest ratio (malloc left as it is in this test process)."""
    from pipeline.altimeter_attitude import benchmark, heap

    kept = []
    monkeypatch.setattr(heap, "keep_freed_memory", lambda: kept.append(True) or True)
    sc, inp = short
    per = benchmark.step_scaling(sc, inp, parts=(2, 1), repeats=2)
    out = capsys.readouterr().out
    assert kept == [True] and len(per) == 2 and all(p > 0 for p in per)
    for t in (inp.n_steps // 2, inp.n_steps):
        assert f"\n   {t:7d} " in out
    assert f"at {inp.n_steps} steps / at {inp.n_steps // 2}: {per[1] / per[0]:.2f}" in out
