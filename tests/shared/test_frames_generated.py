"""derivations.frames' Euler-rate map, transport rate and lat/lon rates, and the generated
pipeline/generated/frames.py, each against an independent numeric path (scipy rotations,
finite differences of numeric DCMs and positions, numpy's cross product) at seeded points."""

from __future__ import annotations

import numpy as np
import pytest
from scipy.spatial.transform import Rotation

from pipeline.generated import frames as gf

RNG = np.random.default_rng(20240602)


def _omega_fd(mat_of_t, t0: float, h: float = 1e-5) -> np.ndarray:
    """[omega^{AB}]^A of a numeric DCM [T]^{AB}(t), from the rotation between t -/+ h."""
    m_minus, m_plus, m0 = mat_of_t(t0 - h), mat_of_t(t0 + h), mat_of_t(t0)
    return m0 @ (Rotation.from_matrix(m_plus.T @ m_minus).as_rotvec() / (2 * h))


def test_mat_tn_and_rot_z_are_scipy_rotations_vectorised():
    angles = RNG.uniform(-np.pi, np.pi, (40, 3))
    got = gf.mat_tn(angles[:, 0], angles[:, 1], angles[:, 2])
    assert got.shape == (40, 3, 3)
    expected = Rotation.from_euler("ZYX", angles).as_matrix().transpose(0, 2, 1)
    np.testing.assert_allclose(got, expected, rtol=0, atol=1e-14)
    rz = gf.rot_z(angles[:, 0])
    np.testing.assert_allclose(
        rz, Rotation.from_euler("z", angles[:, :1]).as_matrix().transpose(0, 2, 1), atol=1e-14
    )
    assert gf.mat_tn(0.1, 0.2, 0.3).shape == (3, 3)


def test_mat_ne_rows_are_north_east_down():
    lat, lon = RNG.uniform(-1.5, 1.5, 20), RNG.uniform(-3, 3, 20)
    m = gf.mat_ne(lat, lon)
    up = np.stack([np.cos(lat) * np.cos(lon), np.cos(lat) * np.sin(lon), np.sin(lat)], -1)
    east = np.cross([0.0, 0.0, 1.0], up)
    east /= np.linalg.norm(east, axis=-1, keepdims=True)
    north = np.cross(up, east)
    np.testing.assert_allclose(m, np.stack([north, east, -up], axis=1), atol=1e-14)


def test_body_rate_from_euler_rates_matches_finite_difference():
    for _ in range(15):
        c = RNG.uniform(-1, 1, (3, 2))  # angle(t) = c0 + c1 t for psi, theta, phi
        t0 = RNG.uniform(-1, 1)

        def mat(t, c=c):
            return gf.mat_tn(*(c[:, 0] + c[:, 1] * t))

        psi, theta, phi = c[:, 0] + c[:, 1] * t0
        w = gf.body_rate_from_euler_rates(theta, phi, c[2, 1], c[1, 1], c[0, 1])
        np.testing.assert_allclose(w, _omega_fd(mat, t0), atol=1e-8)


def test_skew_is_the_cross_product_vectorised():
    w, v = RNG.normal(size=(25, 3)), RNG.normal(size=(25, 3))
    s = gf.skew(w[:, 0], w[:, 1], w[:, 2])
    np.testing.assert_allclose(np.einsum("nij,nj->ni", s, v), np.cross(w, v), atol=1e-14)


def test_earth_and_transport_rates_match_finite_differences_of_mat_ne():
    omega = 7.292115e-5
    for _ in range(15):
        lat0, lon0 = RNG.uniform(-1.4, 1.4), RNG.uniform(-3, 3)
        lat_dot, lon_dot = RNG.uniform(-1e-3, 1e-3, 2)

        def n_e(t, lat0=lat0, lon0=lon0, lat_dot=lat_dot, lon_dot=lon_dot):
            return gf.mat_ne(lat0 + lat_dot * t, lon0 + lon_dot * t)

        # inertial longitude lon + omega t: the inertial rate of NED = Earth + transport rate
        def n_i(t, lat0=lat0, lon0=lon0, lat_dot=lat_dot, lon_dot=lon_dot):
            return gf.mat_ne(lat0 + lat_dot * t, lon0 + (lon_dot + omega) * t)

        fd_en = _omega_fd(n_e, 0.0, h=1e-1)
        fd_in = _omega_fd(n_i, 0.0, h=1e-1)
        np.testing.assert_allclose(gf.transport_rate_n(lat0, lat_dot, lon_dot), fd_en, atol=1e-12)
        np.testing.assert_allclose(
            gf.earth_rate_n(omega, lat0) + gf.transport_rate_n(lat0, lat_dot, lon_dot),
            fd_in,
            atol=1e-12,
        )


def test_latlon_rates_reproduce_the_velocity_and_transport_rate_velocity_form():
    rho = 6.4e6
    for _ in range(15):
        lat0, lon0 = RNG.uniform(-1.4, 1.4), RNG.uniform(-3, 3)
        v_n, v_e = RNG.uniform(-300, 300, 2)
        lat_dot, lon_dot = gf.latlon_rates(v_n, v_e, lat0, rho)

        def r_e(t, lat0=lat0, lon0=lon0, lat_dot=lat_dot, lon_dot=lon_dot):
            return -rho * gf.mat_ne(lat0 + lat_dot * t, lon0 + lon_dot * t)[2]

        h = 1e-2
        v = gf.mat_ne(lat0, lon0) @ ((r_e(h) - r_e(-h)) / (2 * h))
        np.testing.assert_allclose(v, [v_n, v_e, 0.0], rtol=0, atol=1e-6)
        np.testing.assert_allclose(
            gf.transport_rate_n_velocity(v_n, v_e, lat0, rho),
            gf.transport_rate_n(lat0, lat_dot, lon_dot),
            rtol=1e-14,
            atol=1e-20,
        )


@pytest.mark.parametrize("name", gf.__all__)
def test_every_generated_frames_function_broadcasts(name):
    """Scalars give the trailing shape only; arrays of shape (4,) prepend it."""
    fn = getattr(gf, name)
    n_args = fn.__code__.co_argcount
    one = fn(*([0.3] * n_args))
    many = fn(*([np.full(4, 0.3)] * n_args))
    assert many.shape == (4, *one.shape)
    np.testing.assert_array_equal(many[2], one)


def test_scalar_arguments_take_the_fast_path_to_the_same_arrays():
    """Called with Python floats (as the integrators' right-hand sides call them), the generated
    functions' _broadcast and _shaped skip broadcasting; called with 0-d arrays they take the
    general path. Both give arrays of the same shape, dtype and bits, outputs of 0 included."""
    from pipeline.generated import platform_drift as gp

    cases = [
        (gf.mat_ne, (0.61, -1.3)),  # a matrix (_shaped)
        (gf.skew, (1.5, -2.0, 0.25)),  # a matrix with exact zeros on the diagonal
        (gf.earth_rate_n, (7.292115e-5, 0.61)),  # a vector with a 0 component
        (gf.latlon_rates, (3.0, -4.0, 0.61, 6.4e6)),  # a tuple of scalars (_broadcast)
    ]
    cases += [(getattr(gp, name), None) for name in gp.__all__[:3]]
    checked = 0
    for fn, args in cases:
        if args is None:  # a platform_drift function: every argument 0.3
            args = (0.3,) * fn.__code__.co_argcount
        fast, slow = fn(*args), fn(*(np.asarray(a) for a in args))
        fast = fast if isinstance(fast, tuple) else (fast,)
        slow = slow if isinstance(slow, tuple) else (slow,)
        assert len(fast) == len(slow), fn.__name__
        for a, b in zip(fast, slow, strict=True):
            assert isinstance(a, np.ndarray) and a.dtype == b.dtype == float, fn.__name__
            assert a.shape == b.shape and a.tobytes() == b.tobytes(), fn.__name__
            checked += 1
    assert checked >= 7


def test_array_and_scalar_arguments_broadcast_to_the_elementwise_results():
    """An array argument beside scalar ones (one shape besides the scalars': no call of
    broadcast_shapes) and two arrays that broadcast against each other give, element by
    element, the bits of the scalar calls."""
    lat = np.array([-1.2, 0.0, 0.4, 1.5])
    got = gf.mat_ne(lat, 0.7)
    assert got.shape == (4, 3, 3)
    for i, v in enumerate(lat.tolist()):
        assert got[i].tobytes() == gf.mat_ne(v, 0.7).tobytes()
    lon = np.array([[0.1], [-2.0]])
    got = gf.mat_ne(lat, lon)  # (4,) against (2, 1): (2, 4)
    assert got.shape == (2, 4, 3, 3)
    for j, w in enumerate(lon[:, 0].tolist()):
        for i, v in enumerate(lat.tolist()):
            assert got[j, i].tobytes() == gf.mat_ne(v, w).tobytes()
    rates = gf.earth_rate_n(7.292115e-5, lat)  # a vector with a constant 0 component
    assert rates.shape == (4, 3) and not rates[:, 1].any()
