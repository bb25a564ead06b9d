"""pipeline.platform_drift.dop853 is scipy.integrate.solve_ivp's DOP853, bit for bit.

The port exists only so that a simulation job need not import ``scipy.integrate`` (~0.6 s of
CPU); every number it gives must be SciPy's: the coefficients, the values at ``t_eval``, the
evaluation count, the failure path. The platform and strapdown systems are integrated over a
moving and a resting scenario by both, and compared byte for byte. The lazily computed truth
(:class:`pipeline.platform_drift.trajectory.Truth`) equals the formulas it replaced.
"""

from __future__ import annotations

import math
import os
import subprocess
import sys
import warnings
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import solve_ivp as scipy_solve_ivp
from scipy.integrate._ivp import dop853_coefficients as scipy_coef

from pipeline.generated import frames
from pipeline.generated import platform_drift as gen
from pipeline.platform_drift import dop853
from pipeline.platform_drift import dop853_coefficients as coef
from pipeline.platform_drift import platform as pf
from pipeline.platform_drift import strapdown as sd
from pipeline.platform_drift.scenario import load_scenario
from pipeline.platform_drift.trajectory import c3

SCEN = Path(__file__).resolve().parents[2] / "config" / "scenarios" / "platform_drift"


def _same(ours: dop853.OdeResult, theirs) -> None:
    assert ours.success == theirs.success
    assert ours.message == theirs.message
    assert ours.nfev == theirs.nfev
    assert ours.t.tobytes() == np.asarray(theirs.t).tobytes()
    assert ours.y.shape == theirs.y.shape
    assert ours.y.tobytes() == theirs.y.tobytes()


@pytest.mark.parametrize("name", ["N_STAGES", "N_STAGES_EXTENDED", "INTERPOLATOR_POWER"])
def test_counts_are_scipys(name):
    assert getattr(coef, name) == getattr(scipy_coef, name)


@pytest.mark.parametrize("name", ["A", "B", "C", "D", "E3", "E5"])
def test_coefficients_are_scipys_bit_for_bit(name):
    ours, theirs = getattr(coef, name), getattr(scipy_coef, name)
    assert ours.shape == theirs.shape and ours.tobytes() == theirs.tobytes()


def _lotka_volterra(t, y):
    return np.array([1.5 * y[0] - y[0] * y[1], -3.0 * y[1] + y[0] * y[1]])


@pytest.mark.parametrize(
    "rtol, atol",
    [(1e-3, 1e-6), (1e-10, np.array([1e-12, 1e-9])), (1e-16, 1e-12)],  # 1e-16: rtol raised
)
def test_textbook_problem_matches_scipy(rtol, atol):
    t_eval = np.linspace(0.0, 15.0, 301)
    y0 = np.array([10.0, 5.0])
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        ours = dop853.solve_ivp(_lotka_volterra, (0.0, 15.0), y0, t_eval, rtol, atol)
        theirs = scipy_solve_ivp(
            _lotka_volterra, (0.0, 15.0), y0, method="DOP853", t_eval=t_eval, rtol=rtol, atol=atol
        )
    # the same warning from both (or none): rtol below 100 eps is raised to it
    assert [str(w.message) for w in caught[: len(caught) // 2]] == [
        str(w.message) for w in caught[len(caught) // 2 :]
    ]
    assert len(caught) == (2 if rtol < 100 * np.finfo(float).eps else 0)
    _same(ours, theirs)


def test_t_eval_between_steps_and_a_failure_match_scipy():
    # sparse t_eval (steps without an output) and a blow-up the step size cannot follow
    t_eval = np.array([0.0, 0.3, 0.9])

    def blow_up(t, y):
        return y**2

    ours = dop853.solve_ivp(blow_up, (0.0, 2.0), np.array([1.0]), t_eval, 1e-8, 1e-10)
    theirs = scipy_solve_ivp(
        blow_up, (0.0, 2.0), np.array([1.0]), method="DOP853", t_eval=t_eval, rtol=1e-8, atol=1e-10
    )
    assert not ours.success
    _same(ours, theirs)


def test_bad_arguments_are_refused():
    y0 = np.array([1.0])
    with pytest.raises(ValueError, match="forward"):
        dop853.solve_ivp(lambda t, y: -y, (1.0, 0.0), y0, np.array([0.5]), 1e-6, 1e-9)
    with pytest.raises(ValueError, match="sorted"):
        dop853.solve_ivp(lambda t, y: -y, (0.0, 1.0), y0, np.array([0.5, 0.2]), 1e-6, 1e-9)
    with pytest.raises(ValueError, match="within"):
        dop853.solve_ivp(lambda t, y: -y, (0.0, 1.0), y0, np.array([1.5]), 1e-6, 1e-9)
    with pytest.raises(ValueError, match="finite"):
        dop853.solve_ivp(lambda t, y: -y, (0.0, 1.0), np.array([np.nan]), [1.0], 1e-6, 1e-9)


@pytest.mark.parametrize("name", ["stationary", "lat_lon_change"])
def test_platform_and_strapdown_match_scipy(name):
    sc = load_scenario(SCEN / f"{name}.yaml")
    traj = sc.trajectory()
    t_eval = sc.times(900.0)
    span = (float(t_eval[0]), float(t_eval[-1]))
    p_drift = np.array([sc.platform_drift(c) for c in sc.cases])
    n = len(sc.cases)
    y0 = pf._y0(pf.initial_state(traj, sc.initial_level), n)
    args = (pf.make_rhs(traj, p_drift), span, y0)
    ours = dop853.solve_ivp(*args, t_eval, sc.rtol, pf._atol(n))
    theirs = scipy_solve_ivp(*args, method="DOP853", t_eval=t_eval, rtol=sc.rtol, atol=pf._atol(n))
    _same(ours, theirs)
    # the strapdown simulation as it calls the port, against SciPy's integration of its RHS
    s_drift = np.array([sc.strapdown_drift(c) for c in sc.cases])
    got = sd.simulate(traj, s_drift, t_eval, sc.rtol)
    tr = traj.at(0.0)
    c_bn = sd.NWU_TO_NED @ tr.nwu_i.T @ traj.body_i(tr)
    v_ned = (
        sd.NWU_TO_NED
        @ tr.nwu_i.T
        @ gen.ground_velocity(*tr.v_i, *tr.r_i, *frames.earth_rate_e(traj.earth.omega_e))
    )
    row = np.concatenate([c_bn.ravel(), v_ned[:2], [tr.lat, tr.lon]])
    ref = scipy_solve_ivp(
        sd.make_rhs(traj, s_drift),
        span,
        np.tile(row, n),
        method="DOP853",
        t_eval=t_eval,
        rtol=sc.rtol,
        atol=sd._atol(n),
    )
    y = ref.y.reshape(n, sd.N_STATE, -1)
    assert int(got["nfev"]) == ref.nfev
    assert got["lat"].tobytes() == y[:, 11].tobytes()
    assert got["lon"].tobytes() == y[:, 12].tobytes()


@pytest.mark.parametrize("name", ["stationary", "lat_lon_change"])
def test_lazy_truth_equals_the_eager_formulas(name):
    """Truth's vectors, computed when read, are the former eager formulas, bit for bit."""
    traj = load_scenario(SCEN / f"{name}.yaml").trajectory()
    p, e, rho = traj.path, traj.earth, traj.rho
    for t in (0.0, 37.5, 1234.5, 4000.0):
        tr = traj.at(t)
        s, sd_, sdd = traj.progress(t)
        lat = p.lat0 + p.dlat * s
        lat_d, lat_dd = p.dlat * sd_, p.dlat * sdd
        lam_d, lam_dd = p.dlon * sd_ + e.omega_e, p.dlon * sdd
        cl, sl = math.cos(lat), math.sin(lat)
        m = frames.mat_ne(lat, p.lon0 + p.dlon * s + e.omega_e * t)
        north, east, up = m[0], m[1], -m[2]
        a_i = rho * (
            (lat_dd + lam_d * lam_d * sl * cl) * north
            + (lam_dd * cl - 2.0 * lam_d * lat_d * sl) * east
            - (lat_d * lat_d + lam_d * lam_d * cl * cl) * up
        )
        expected = {
            "r_i": rho * up,
            "v_i": rho * (lat_d * north + lam_d * cl * east),
            "a_i": a_i,
            "f_i": a_i + (e.gm / rho**2) * up,
            "nwu_i": np.column_stack((north, -east, up)),
            "w_nwu": frames.transport_rate_n(lat, lat_d, lam_d) * np.array([1.0, -1.0, -1.0]),
            "c3_b": c3(traj.psi0 - (traj.course(lat) - traj.chi0)),
        }
        for key, value in expected.items():
            assert getattr(tr, key).tobytes() == value.tobytes(), (t, key)
        chi_d = float(gen.course_rate(p.dlat, p.dlon, lat, lat_d)) if traj.moving else 0.0
        assert math.copysign(1.0, tr.psi_b_dot) == math.copysign(1.0, -chi_d)
        assert tr.psi_b_dot == -chi_d


def test_c3_memo_keeps_the_sign_of_zero_and_is_read_only():
    traj = load_scenario(SCEN / "stationary.yaml").trajectory()
    plus, minus = traj.c3_memo(0.0), traj.c3_memo(-0.0)
    assert plus.tobytes() == c3(0.0).tobytes() and minus.tobytes() == c3(-0.0).tobytes()
    assert plus.tobytes() != minus.tobytes()  # sin(-0.0) = -0.0
    assert traj.c3_memo(-0.0) is minus
    with pytest.raises(ValueError):
        minus[0, 0] = 2.0


def test_simulation_steps_do_not_import_scipy_integrate():
    """The reason for the port: the simulate and latitude_sweep steps' modules leave
    scipy.integrate (~0.6 s of CPU per process) unimported."""
    code = (
        "import sys\n"
        "import pipeline.platform_drift.run, pipeline.platform_drift.sweep\n"
        "import pipeline.platform_drift.steps\n"
        "print('scipy.integrate' in sys.modules)\n"
    )
    root = SCEN.parents[2]
    out = subprocess.run(
        [sys.executable, "-c", code],
        cwd=root,
        env=dict(os.environ, PYTHONPATH=str(root)),
        capture_output=True,
        text=True,
        check=True,
    )
    assert out.stdout.strip() == "False"


def test_w_nwu_memo_is_the_generated_rate_and_read_only():
    traj = load_scenario(SCEN / "stationary.yaml").trajectory()
    for args in ((0.5, 0.0, 7.29e-5), (0.5, -0.0, 7.29e-5), (0.5, 1e-6, 7.3e-5)):
        got = traj.w_nwu_memo(*args)
        want = frames.transport_rate_n(*args) * np.array([1.0, -1.0, -1.0])
        assert got.tobytes() == want.tobytes()
        assert traj.w_nwu_memo(*args) is got
    with pytest.raises(ValueError):
        got[0] = 1.0
