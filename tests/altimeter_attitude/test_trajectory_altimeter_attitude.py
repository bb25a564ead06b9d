"""Truth trajectory of the altimeter-attitude paper: analytic consistency checks.

The body rates, specific force, vertical velocity and altitude of
:mod:`pipeline.altimeter_attitude.trajectory` are integrated independently (solve_ivp,
DOP853) and compared with the analytic truth; the channel derivatives of
:mod:`pipeline.altimeter_attitude.profiles` are checked by finite differences; bad scenarios
must fail with the field named.
"""

from __future__ import annotations

import copy
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from pipeline.altimeter_attitude.profiles import CHANNELS, Profiles
from pipeline.altimeter_attitude.trajectory import load_factor, mat_from_euler, truth

G = 9.80665
T_END = 90.0
RTOL, ATOL = 1e-11, 1e-12


def _m(channel, start, duration, amplitude):
    return {"channel": channel, "start_s": start, "duration_s": duration, "amplitude": amplitude}


MANEUVERING = {
    "duration_s": T_END,
    "gravity_m_s2": G,
    "initial": {
        "speed_m_s": 60.0,
        "flight_path_deg": 0.0,
        "heading_deg": 30.0,
        "roll_deg": 0.0,
        "alpha_deg": 3.0,
        "altitude_m": 1000.0,
    },
    "intensity": 1.0,
    "maneuvers": [
        _m("flight_path_deg", 10.0, 4.0, 20.0),  # pull-up
        _m("alpha_deg", 10.0, 4.0, 4.0),
        _m("speed_m_s", 15.0, 10.0, 15.0),  # speed change
        _m("flight_path_deg", 20.0, 4.0, -20.0),  # back to level
        _m("alpha_deg", 20.0, 4.0, -4.0),
        _m("flight_path_deg", 30.0, 5.0, -15.0),  # push-over
        _m("flight_path_deg", 40.0, 5.0, 15.0),
        _m("speed_m_s", 48.0, 8.0, -10.0),
        _m("roll_deg", 55.0, 3.0, 45.0),  # roll in
        _m("heading_deg", 57.0, 15.0, 90.0),  # heading change
        _m("roll_deg", 72.0, 3.0, -45.0),  # roll out
    ],
}


@pytest.fixture(scope="module")
def prof() -> Profiles:
    return Profiles.from_config(MANEUVERING)


def _skew(w):
    return np.array([[0.0, -w[2], w[1]], [w[2], 0.0, -w[0]], [-w[1], w[0], 0.0]])


def _check_times():
    return np.linspace(0.0, T_END, 50)


# 1 --------------------------------------------------------------------------------------
def test_body_rates_integrate_to_attitude(prof):
    t_chk = _check_times()

    def rhs(t, y):
        w = truth(prof, t).rate_b[0]
        return (y.reshape(3, 3) @ _skew(w)).ravel()

    mat0 = truth(prof, 0.0).mat_nb[0]
    sol = solve_ivp(
        rhs, (0.0, T_END), mat0.ravel(), method="DOP853", rtol=RTOL, atol=ATOL, t_eval=t_chk
    )
    assert sol.success
    integrated = sol.y.T.reshape(-1, 3, 3)
    err = np.max(np.abs(integrated - truth(prof, t_chk).mat_nb))
    print(f"attitude from integrated rates: max |dC| = {err:.2e}")
    assert err < 1e-7
    # the profile really manoeuvres
    tr = truth(prof, np.linspace(0.0, T_END, 2001))
    assert np.ptp(tr.pitch) > math.radians(30) and np.ptp(tr.roll) > math.radians(40)
    assert np.max(load_factor(tr)) > 1.5 and np.min(load_factor(tr)) < 0.6


# 2 --------------------------------------------------------------------------------------
def test_vertical_channel_integrates_to_truth(prof):
    t_chk = _check_times()

    def rhs(t, y):
        tr = truth(prof, t)
        v_d_dot = tr.c[0] @ tr.force_b[0] + G
        return [v_d_dot, -y[0]]

    tr0 = truth(prof, 0.0)
    sol = solve_ivp(
        rhs,
        (0.0, T_END),
        [tr0.v_d[0], tr0.h[0]],
        method="DOP853",
        rtol=RTOL,
        atol=ATOL,
        t_eval=t_chk,
    )
    assert sol.success
    tr = truth(prof, t_chk)
    err_v = np.max(np.abs(sol.y[0] - tr.v_d))
    err_h = np.max(np.abs(sol.y[1] - tr.h))
    print(f"vertical channel: max |dV_d| = {err_v:.2e} m/s, max |dh| = {err_h:.2e} m")
    assert err_v < 1e-6
    assert err_h < 1e-5
    assert np.ptp(tr.h) > 50.0  # the altitude really changes


def test_full_velocity_integrates_and_force_is_consistent(prof):
    rng = np.random.default_rng(1)
    t = rng.uniform(0.0, T_END, 200)
    tr = truth(prof, t)
    # algebraic: C_b^n f^b + g^n = a^n
    acc = np.einsum("nij,nj->ni", tr.mat_nb, tr.force_b) + np.array([0.0, 0.0, G])
    err_a = np.max(np.abs(acc - tr.acc_n))
    # c is the third row of C_b^n, of unit norm, and v_d = v^n[2] = -V sin(gam)
    assert np.array_equal(tr.c, tr.mat_nb[:, 2, :])
    np.testing.assert_allclose(np.linalg.norm(tr.c, axis=1), 1.0, rtol=0, atol=1e-15)
    np.testing.assert_allclose(tr.v_d, -tr.speed * np.sin(tr.flight_path), rtol=0, atol=1e-13)
    print(f"C_b^n f^b + g^n - a^n: max = {err_a:.2e} m/s^2")
    assert err_a < 1e-12

    # dynamic: a^n integrates to v^n
    t_chk = _check_times()
    sol = solve_ivp(
        lambda s, y: truth(prof, s).acc_n[0],
        (0.0, T_END),
        truth(prof, 0.0).vel_n[0],
        method="DOP853",
        rtol=RTOL,
        atol=ATOL,
        t_eval=t_chk,
    )
    err_v = np.max(np.abs(sol.y.T - truth(prof, t_chk).vel_n))
    print(f"v^n from integrated a^n: max = {err_v:.2e} m/s")
    assert err_v < 1e-6


def test_altitude_quadrature_against_fine_reference(prof):
    # h at a few sparse times (long pieces) equals h on a dense grid (short pieces)
    t_dense = np.linspace(0.0, T_END, 90_001)
    h_dense = truth(prof, t_dense).h
    t_sparse = np.array([T_END, 3.0, 33.3, 61.0])
    h_sparse = truth(prof, t_sparse).h
    idx = np.array([np.argmin(np.abs(t_dense - s)) for s in t_sparse])
    assert np.allclose(t_dense[idx], t_sparse, rtol=0, atol=1e-9)
    err = np.max(np.abs(h_sparse - h_dense[idx]))
    print(f"altitude: sparse vs dense quadrature max diff = {err:.2e} m")
    assert err < 1e-9
    # steady climb: h = h0 + V sin(gam) t exactly
    cfg = copy.deepcopy(MANEUVERING)
    cfg["maneuvers"] = []
    cfg["initial"]["flight_path_deg"] = 5.0
    climb = Profiles.from_config(cfg)
    t = np.array([0.0, 0.5, 17.0, 90.0])
    expected = 1000.0 + 60.0 * math.sin(math.radians(5.0)) * t
    np.testing.assert_allclose(truth(climb, t).h, expected, rtol=0, atol=1e-10)


# 3 --------------------------------------------------------------------------------------
@pytest.mark.parametrize("name", CHANNELS)
def test_channel_derivatives_match_finite_differences(prof, name):
    rng = np.random.default_rng(7)
    t = rng.uniform(0.0, T_END, 400)
    bps = prof.breakpoints()
    # S''' jumps at the maneuver starts/ends: keep the stencil off them
    t = t[np.min(np.abs(t[:, None] - bps[None, :]), axis=1) > 1e-3]
    step = 1e-5
    val, d1, d2 = prof.channel(name, t)
    vp, d1p, _ = prof.channel(name, t + step)
    vm, d1m, _ = prof.channel(name, t - step)
    fd1 = (vp - vm) / (2 * step)
    fd2 = (d1p - d1m) / (2 * step)
    # relative to the channel's largest derivative (pointwise relative fails at zeros)
    grid = np.linspace(0.0, T_END, 20_001)
    _, g1, g2 = prof.channel(name, grid)
    scale1, scale2 = np.max(np.abs(g1)), np.max(np.abs(g2))
    assert scale1 > 0 and scale2 > 0
    e1 = np.max(np.abs(fd1 - d1)) / scale1
    e2 = np.max(np.abs(fd2 - d2)) / scale2
    print(f"{name}: relative FD error d1 {e1:.1e}, d2 {e2:.1e}")
    assert e1 < 1e-6
    assert e2 < 1e-6
    # also the continuity of value, first and second derivative across each breakpoint
    for b in bps:
        lo = prof.channel(name, np.array([b - 1e-9]))
        hi = prof.channel(name, np.array([b + 1e-9]))
        for k, sc in enumerate((1.0, scale1, scale2)):
            assert abs(hi[k][0] - lo[k][0]) <= 1e-6 * max(sc, 1.0)


# 4 --------------------------------------------------------------------------------------
@pytest.mark.parametrize(
    ("flight_path", "roll", "alpha"), [(0.0, 0.0, 3.0), (7.0, 20.0, -2.0), (-10.0, -30.0, 5.0)]
)
def test_unaccelerated_segment_reads_minus_g_c(flight_path, roll, alpha):
    cfg = copy.deepcopy(MANEUVERING)
    cfg["maneuvers"] = []
    cfg["initial"].update(flight_path_deg=flight_path, roll_deg=roll, alpha_deg=alpha)
    tr = truth(Profiles.from_config(cfg), np.linspace(0.0, T_END, 101))
    assert np.array_equal(tr.rate_b, np.zeros_like(tr.rate_b))
    assert np.array_equal(tr.acc_n, np.zeros_like(tr.acc_n))
    assert np.array_equal(tr.force_b, -G * tr.c)
    np.testing.assert_allclose(load_factor(tr), 1.0, rtol=0, atol=1e-15)
    theta, phi = math.radians(flight_path + alpha), math.radians(roll)
    np.testing.assert_allclose(
        tr.force_b[0],
        G
        * np.array(
            [math.sin(theta), -math.sin(phi) * math.cos(theta), -math.cos(phi) * math.cos(theta)]
        ),
        rtol=0,
        atol=1e-15,
    )


# 5 --------------------------------------------------------------------------------------
def _bad(mutate):
    cfg = copy.deepcopy(MANEUVERING)
    mutate(cfg)
    return cfg


BAD_CASES = [
    (lambda c: c["maneuvers"][0].update(channel="yaw_deg"), r"maneuvers\[0\]\.channel.*yaw_deg"),
    (lambda c: c["maneuvers"][1].update(duration_s=0.0), r"maneuvers\[1\]\.duration_s.*> 0"),
    (lambda c: c["maneuvers"][2].update(duration_s=-3.0), r"maneuvers\[2\]\.duration_s"),
    (lambda c: c["maneuvers"][3].update(start_s=-1.0), r"maneuvers\[3\]\.start_s.*\[0, duration_s"),
    (lambda c: c["maneuvers"][3].update(start_s=T_END), r"maneuvers\[3\]\.start_s"),
    (lambda c: c.update(duration_s=0.0), r"duration_s"),
    (lambda c: c["maneuvers"].append(_m("speed_m_s", 60.0, 5.0, -64.5)), r"speed_m_s.*> 1"),
    (lambda c: c["initial"].update(speed_m_s=1.0), r"speed_m_s"),
    (lambda c: c["maneuvers"].append(_m("flight_path_deg", 80.0, 5.0, -81.0)), r"flight_path_deg"),
    (lambda c: c["initial"].update(alpha_deg=60.0), r"pitch"),
    (lambda c: c["maneuvers"][0].update(amplitude=75.0), r"pitch"),
    (lambda c: c["initial"].update(roll_deg=-80.0), r"roll_deg"),
    (lambda c: c["maneuvers"].append(_m("roll_deg", 1.0, 1.0, 85.0)), r"roll_deg.*80"),
]


@pytest.mark.parametrize(("mutate", "match"), BAD_CASES)
def test_bad_config_names_the_field(mutate, match):
    with pytest.raises(ValueError, match=match):
        Profiles.from_config(_bad(mutate))


def test_unknown_channel_in_evaluation(prof):
    with pytest.raises(ValueError, match="channel"):
        prof.channel("yaw_deg", np.zeros(3))


def test_intensity_scales_maneuvers():
    half = Profiles.from_config({**MANEUVERING, "intensity": 0.5})
    full = Profiles.from_config(MANEUVERING)
    t = np.linspace(0.0, T_END, 301)
    for name in CHANNELS:
        v0 = full.initial[name]
        np.testing.assert_allclose(
            half.channel(name, t)[0] - v0, 0.5 * (full.channel(name, t)[0] - v0), atol=1e-14
        )


# 6 --------------------------------------------------------------------------------------
FIELDS = ("t", "roll", "pitch", "yaw", "rate_b", "force_b", "vel_n", "acc_n", "v_d", "c")


def test_vectorised_equals_elementwise(prof):
    rng = np.random.default_rng(3)
    t = np.concatenate(([0.0, T_END, 12.0, 12.0], rng.uniform(0.0, T_END, 60)))
    full = truth(prof, t)
    assert full.mat_nb.shape == (t.size, 3, 3) and full.rate_b.shape == (t.size, 3)
    for i, ti in enumerate(t):
        one = truth(prof, np.array([ti]))
        for name in FIELDS:
            np.testing.assert_allclose(
                getattr(one, name)[0], getattr(full, name)[i], rtol=1e-14, atol=1e-15
            )
        np.testing.assert_allclose(one.h[0], full.h[i], rtol=0, atol=1e-9)
        np.testing.assert_allclose(one.mat_nb[0], full.mat_nb[i], rtol=0, atol=1e-15)
    # order, repeats and a start after 0 do not matter
    order = np.argsort(t)
    sorted_tr = truth(prof, t[order])
    np.testing.assert_allclose(sorted_tr.h, full.h[order], rtol=0, atol=1e-9)
    late = truth(prof, np.linspace(50.0, 60.0, 11))
    ref = truth(prof, np.linspace(0.0, 60.0, 61))
    np.testing.assert_allclose(late.h, ref.h[50:], rtol=0, atol=1e-9)
    # mid-interval sampling is just another set of times
    dt = 0.01
    mid = truth(prof, np.arange(0.0, 5.0, dt) + dt / 2)
    assert np.all(np.isfinite(mid.force_b))


def test_mat_from_euler_is_rz_ry_rx():
    phi, theta, psi = 0.3, -0.7, 2.1

    def rx(a):
        return np.array([[1, 0, 0], [0, math.cos(a), -math.sin(a)], [0, math.sin(a), math.cos(a)]])

    def ry(a):
        return np.array([[math.cos(a), 0, math.sin(a)], [0, 1, 0], [-math.sin(a), 0, math.cos(a)]])

    def rz(a):
        return np.array([[math.cos(a), -math.sin(a), 0], [math.sin(a), math.cos(a), 0], [0, 0, 1]])

    mat = mat_from_euler(phi, theta, psi)
    np.testing.assert_allclose(mat, rz(psi) @ ry(theta) @ rx(phi), rtol=0, atol=1e-15)
    c = [-math.sin(theta), math.sin(phi) * math.cos(theta), math.cos(phi) * math.cos(theta)]
    np.testing.assert_allclose(mat[2], c, rtol=0, atol=1e-16)


def test_generated_flight_path_direction_is_the_rotated_x_axis_and_its_partials():
    """u(gam, chi) against the first column of the generated 3-2-1 C_b^n (yaw chi, pitch gam,
    no roll), its partials against central differences, and h_dot = -V u_3: independent
    paths, each failing on a sign or a swapped angle."""
    from pipeline.generated import altimeter_attitude as gen
    from pipeline.generated import frames

    rng = np.random.default_rng(25)
    gam, chi, speed = (
        rng.uniform(-1.2, 1.2, 300),
        rng.uniform(-3, 3, 300),
        rng.uniform(50, 300, 300),
    )

    def u(g, c):
        return np.stack(gen.flight_path_direction(g, c), -1).reshape(-1, 3, 3)

    got = u(gam, chi)
    x_axis = np.swapaxes(frames.mat_tn(chi, gam, np.zeros_like(gam)), -1, -2)[:, :, 0]
    np.testing.assert_allclose(got[:, 0], x_axis, rtol=0, atol=1e-15)
    h = 1e-6
    for k, (dg, dc) in ((1, (h, 0.0)), (2, (0.0, h))):
        numeric = (u(gam + dg, chi + dc)[:, 0] - u(gam - dg, chi - dc)[:, 0]) / (2 * h)
        np.testing.assert_allclose(got[:, k], numeric, rtol=0, atol=1e-9)
    np.testing.assert_allclose(gen.climb_rate(speed, gam), -speed * got[:, 0, 2], rtol=1e-15)
