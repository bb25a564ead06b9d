"""derivations.frames: rotation matrices, Earth rate, Poisson's equation, skew matrices.

Every symbolic result is checked against an independent numeric path
(scipy.spatial.transform.Rotation, hand-built NED axes, finite differences of the
numeric DCM), at seeded random points.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from scipy.spatial.transform import Rotation

from derivations import frames

RNG_SEED = 20240601
a, t = sp.symbols("a t", real=True)
psi, theta, phi, lat, lon, Om = sp.symbols("psi theta phi lambda ell Omega", real=True)


def _points(n: int, low: float, high: float, dim: int, seed: int = RNG_SEED) -> np.ndarray:
    return np.random.default_rng(seed).uniform(low, high, size=(n, dim))


# --------------------------------------------------------------------------------------------
# elementary rotations
# --------------------------------------------------------------------------------------------
@pytest.mark.parametrize("rot", [frames.rot_x, frames.rot_y, frames.rot_z])
def test_elementary_rotation_is_orthogonal_with_det_one(rot):
    m = rot(a)
    assert sp.simplify(m * m.T - sp.eye(3)) == sp.zeros(3, 3)
    assert sp.simplify(m.det()) == 1


@pytest.mark.parametrize(
    ("rot", "axis"), [(frames.rot_x, "x"), (frames.rot_y, "y"), (frames.rot_z, "z")]
)
def test_elementary_rotation_is_passive_scipy_rotation(rot, axis):
    """A frame turned by ``a`` about k maps old coordinates to new ones: the transpose of scipy's
    active rotation matrix."""
    f = sp.lambdify(a, rot(a), "numpy")
    for (x,) in _points(20, -np.pi, np.pi, 1):
        expected = Rotation.from_euler(axis, x).as_matrix().T
        np.testing.assert_allclose(np.asarray(f(x), dtype=float), expected, rtol=0, atol=1e-14)


def test_mat_tn_equals_scipy_zyx_transposed():
    """[T]^{TN} of the 3-2-1 sequence = (R_z(psi) R_y(theta) R_x(phi))^T (scipy's intrinsic ZYX)."""
    f = sp.lambdify((psi, theta, phi), frames.mat_tn(psi, theta, phi), "numpy")
    for p, th, ph in _points(50, -np.pi, np.pi, 3):
        expected = Rotation.from_euler("ZYX", [p, th, ph]).as_matrix().T
        np.testing.assert_allclose(
            np.asarray(f(p, th, ph), dtype=float), expected, rtol=0, atol=1e-14
        )


def test_mat_tn_orthogonal_det_one():
    m = frames.mat_tn(psi, theta, phi)
    f = sp.lambdify((psi, theta, phi), m, "numpy")
    for p in _points(20, -np.pi, np.pi, 3):
        mm = np.asarray(f(*p), dtype=float)
        np.testing.assert_allclose(mm @ mm.T, np.eye(3), atol=1e-14)
        assert np.linalg.det(mm) == pytest.approx(1.0, abs=1e-14)


def test_mat_ne_rows_are_the_ned_axes_in_earth_frame():
    """Rows of [T]^{NE} are the north, east and down unit vectors written in E (built by hand)."""
    f = sp.lambdify((lat, lon), frames.mat_ne(lat, lon), "numpy")
    for la, lo in _points(30, -1.5, 1.5, 2) * [1, 2]:
        north = [-np.sin(la) * np.cos(lo), -np.sin(la) * np.sin(lo), np.cos(la)]
        east = [-np.sin(lo), np.cos(lo), 0.0]
        down = [-np.cos(la) * np.cos(lo), -np.cos(la) * np.sin(lo), -np.sin(la)]
        np.testing.assert_allclose(
            np.asarray(f(la, lo), dtype=float), np.array([north, east, down]), rtol=0, atol=1e-14
        )


# --------------------------------------------------------------------------------------------
# Earth rate and gravity
# --------------------------------------------------------------------------------------------
def test_earth_rate_n_symbolic():
    w = frames.earth_rate_n(Om, lat)
    expected = Om * sp.Matrix([sp.cos(lat), 0, -sp.sin(lat)])
    assert sp.simplify(w - expected) == sp.zeros(3, 1)
    assert lon not in w.free_symbols


def test_earth_rate_n_independent_of_longitude_numerically():
    """[T]^{NE}(lat, lon) [0, 0, Omega] is the same for every longitude (scipy-free numeric path)."""
    m = sp.lambdify((lat, lon), frames.mat_ne(lat, lon), "numpy")
    omega = 7.292115e-5
    for la, lo1, lo2 in _points(30, -1.5, 1.5, 3) * [1, 2, 2]:
        w1 = np.asarray(m(la, lo1), dtype=float) @ [0, 0, omega]
        w2 = np.asarray(m(la, lo2), dtype=float) @ [0, 0, omega]
        np.testing.assert_allclose(w1, w2, rtol=0, atol=1e-18)
        np.testing.assert_allclose(w1, omega * np.array([np.cos(la), 0, -np.sin(la)]), atol=1e-18)


def test_gravity_n_points_down():
    g = sp.Symbol("g", positive=True)
    assert frames.gravity_n(g) == sp.Matrix([0, 0, g])


# --------------------------------------------------------------------------------------------
# skew / unskew
# --------------------------------------------------------------------------------------------
def test_skew_is_cross_product_and_unskew_inverts_it():
    w = sp.Matrix(sp.symbols("w1 w2 w3", real=True))
    v = sp.Matrix(sp.symbols("v1 v2 v3", real=True))
    assert sp.expand(frames.skew(w) * v - w.cross(v)) == sp.zeros(3, 1)
    assert frames.unskew(frames.skew(w)) == w
    assert frames.skew(w).T == -frames.skew(w)
    # round trip the other way on a generic skew-symmetric matrix
    m = frames.skew(sp.Matrix(sp.symbols("m1 m2 m3", real=True)))
    assert frames.skew(frames.unskew(m)) == m


def test_skew_numeric_cross_product():
    for w, v in _points(20, -3, 3, 6).reshape(20, 2, 3):
        s = np.asarray(frames.skew(sp.Matrix(w)), dtype=float)
        np.testing.assert_allclose(s @ v, np.cross(w, v), atol=1e-14)


# --------------------------------------------------------------------------------------------
# angular velocity from a DCM (Poisson's equation)
# --------------------------------------------------------------------------------------------
def _omega_fd(mat_of_t, t0: float, h: float = 1e-5) -> np.ndarray:
    """[omega^{AB}]^A from the numeric DCM [T]^{AB}(t) without Poisson's equation.

    Columns of [T]^{AB}^T are A's axes in B; the active rotation (in B) carrying A(t - h) to
    A(t + h) is T(t + h)^T T(t - h), whose rotation vector / 2h is omega^{AB} in B; map it to A.
    """
    m_minus, m_plus, m0 = mat_of_t(t0 - h), mat_of_t(t0 + h), mat_of_t(t0)
    rotvec_b = Rotation.from_matrix(m_plus.T @ m_minus).as_rotvec() / (2 * h)
    return m0 @ rotvec_b


def test_angular_velocity_of_rot_z_is_plus_w_about_z():
    """Frame A turned by w t about z of B: omega^{AB} = [0, 0, +w] (A turns positively about z)."""
    w = sp.Symbol("w", real=True)
    res = frames.angular_velocity_from_dcm(frames.rot_z(w * t), t)
    assert sp.simplify(res - sp.Matrix([0, 0, w])) == sp.zeros(3, 1)
    f = sp.lambdify(t, frames.rot_z(0.7 * t), "numpy")
    fd = _omega_fd(lambda x: np.asarray(f(x), dtype=float), 0.3)
    np.testing.assert_allclose(fd, [0, 0, 0.7], atol=1e-9)


def test_angular_velocity_general_dcm_matches_finite_difference():
    """A 3-2-1 DCM with time-varying angles: Poisson's equation vs the finite-difference rotation."""
    rng = np.random.default_rng(RNG_SEED)
    c = sp.symbols("c0:9", real=True)
    psi_t = c[0] + c[1] * t + c[2] * t**2
    th_t = c[3] + c[4] * t + c[5] * t**2
    ph_t = c[6] + c[7] * t + c[8] * t**2
    mat = frames.mat_tn(psi_t, th_t, ph_t)
    w = frames.angular_velocity_from_dcm(mat, t, simplify=False)
    fw = sp.lambdify((t, *c), w, "numpy")
    fm = sp.lambdify((t, *c), mat, "numpy")
    for _ in range(15):
        coeffs = rng.uniform(-1, 1, 9)
        t0 = rng.uniform(-1, 1)
        sym = np.asarray(fw(t0, *coeffs), dtype=float).ravel()
        fd = _omega_fd(lambda x, cc=coeffs: np.asarray(fm(x, *cc), dtype=float), t0)
        np.testing.assert_allclose(sym, fd, rtol=0, atol=1e-8 * max(1.0, np.linalg.norm(fd)))


def test_angular_velocity_composes_by_addition():
    """omega^{AC} = omega^{AB} + [T]^{AB} omega^{BC} for A = rot_x(u t) over B = rot_z(v t) over C."""
    u, v = sp.symbols("u v", real=True)
    m_ab, m_bc = frames.rot_x(u * t), frames.rot_z(v * t)
    lhs = frames.angular_velocity_from_dcm(m_ab * m_bc, t)
    rhs = frames.angular_velocity_from_dcm(m_ab, t) + m_ab * frames.angular_velocity_from_dcm(
        m_bc, t
    )
    assert sp.simplify(lhs - rhs) == sp.zeros(3, 1)
