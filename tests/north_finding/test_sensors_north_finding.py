"""Sensor model of north_finding (specific force, angular rate) against independent numerics.

The independent path never uses derivations/: the table, attitude and Earth rotations come
from scipy.spatial.transform.Rotation, velocities and accelerations from finite differences
of the sensor position, the angular rate from finite differences of the body-to-inertial
rotation. Then every generated function is compared with the lambdified derivation.
"""

from __future__ import annotations

import numpy as np
import pytest
import sympy as sp
from scipy.spatial.transform import Rotation

from pipeline.generated import north_finding as gen

SEED = 7100
N_POINTS = 40


def _rz(angle: float) -> np.ndarray:
    """Active rotation about z: maps B coordinates to T coordinates for a table turned by angle."""
    return Rotation.from_euler("z", angle).as_matrix()


def _mat_nt(psi: float, theta: float, phi: float) -> np.ndarray:
    """T (body/table frame) to N (NED) coordinates for yaw psi, pitch theta, roll phi."""
    return Rotation.from_euler("ZYX", [psi, theta, phi]).as_matrix()


def _random_case(rng: np.random.Generator) -> dict[str, float]:
    return {
        "g": rng.uniform(9.7, 9.9),
        # a large 'Earth rate' as well as the real one: the Coriolis and Earth-rate terms are
        # then not hidden under gravity and the table rate (the model is linear in Omega)
        "omega_ie": float(rng.choice([7.292115e-5, rng.uniform(0.05, 1.0)])),
        "lat": rng.uniform(-1.5, 1.5),
        "psi": rng.uniform(-np.pi, np.pi),
        "theta": rng.uniform(-1.4, 1.4),
        "phi": rng.uniform(-1.4, 1.4),
        "tau0": rng.uniform(0, 2 * np.pi),
        "l": rng.uniform(0.05, 1.0),
        "w": rng.uniform(-2.0, 2.0),
        "w_dot": rng.uniform(-2.0, 2.0),
    }


def _tau(c: dict[str, float], t: float) -> float:
    return c["tau0"] + c["w"] * t + 0.5 * c["w_dot"] * t**2


def _deriv(f, h: float) -> tuple[np.ndarray, np.ndarray]:
    """First and second derivative at 0 by five-point central differences (error O(h^4))."""
    fm2, fm1, f0, fp1, fp2 = (np.asarray(f(k * h)) for k in (-2, -1, 0, 1, 2))
    d1 = (fm2 - 8 * fm1 + 8 * fp1 - fp2) / (12 * h)
    d2 = (-fm2 + 16 * fm1 - 30 * f0 + 16 * fp1 - fp2) / (12 * h**2)
    return d1, d2


def numeric_specific_force(c: dict[str, float]) -> np.ndarray:
    """f^B = R_BT (a_T + 2 Omega_T x v_T - g_T), all terms computed numerically."""
    lever = np.array([c["l"], 0.0, 0.0])
    v_t, a_t = _deriv(lambda t: _rz(_tau(c, t)) @ lever, 1e-3)
    m_nt = _mat_nt(c["psi"], c["theta"], c["phi"])
    omega_n = c["omega_ie"] * np.array([np.cos(c["lat"]), 0.0, -np.sin(c["lat"])])
    omega_t = m_nt.T @ omega_n
    g_t = m_nt.T @ np.array([0.0, 0.0, c["g"]])
    f_t = a_t + 2 * np.cross(omega_t, v_t) - g_t
    return _rz(c["tau0"]).T @ f_t


def _mat_en(lat: float, lon: float) -> np.ndarray:
    """NED to Earth-fixed: columns are the north, east, down axes in E (built by hand)."""
    north = [-np.sin(lat) * np.cos(lon), -np.sin(lat) * np.sin(lon), np.cos(lat)]
    east = [-np.sin(lon), np.cos(lon), 0.0]
    down = [-np.cos(lat) * np.cos(lon), -np.cos(lat) * np.sin(lon), -np.sin(lat)]
    return np.array([north, east, down]).T


def numeric_angular_rate(c: dict[str, float], lon: float = 0.4) -> np.ndarray:
    """omega^{BI} in B from finite differences of C_IB(t) = R_IE(t) R_EN R_NT R_TB(t)."""
    m_en = _mat_en(c["lat"], lon)
    m_nt = _mat_nt(c["psi"], c["theta"], c["phi"])

    def c_ib(t: float) -> np.ndarray:
        return _rz(c["omega_ie"] * t) @ m_en @ m_nt @ _rz(_tau(c, t))

    h = 1e-5
    # C(t+h) = C(t) exp([w_B x] h): body-frame increment over [-h, h]
    return Rotation.from_matrix(c_ib(-h).T @ c_ib(h)).as_rotvec() / (2 * h)


def _cases() -> list[dict[str, float]]:
    rng = np.random.default_rng(SEED)
    return [_random_case(rng) for _ in range(N_POINTS)]


@pytest.mark.parametrize(
    "case", _cases(), ids=lambda c: f"tau{c['tau0']:.2f}_Om{c['omega_ie']:.1e}"
)
def test_specific_force_matches_numeric_kinematics(case):
    c = case
    generated = np.array(
        gen.specific_force_b(
            c["g"],
            c["omega_ie"],
            c["lat"],
            c["psi"],
            c["theta"],
            c["phi"],
            c["tau0"],
            c["l"],
            c["w"],
            c["w_dot"],
        ),
        dtype=float,
    )
    expected = numeric_specific_force(c)
    np.testing.assert_allclose(generated, expected, rtol=0, atol=1e-6 * np.linalg.norm(expected))


@pytest.mark.parametrize("case", _cases()[:15], ids=lambda c: f"tau{c['tau0']:.2f}")
def test_specific_force_rotating_terms_without_gravity(case):
    """With g = 0 only the table terms and Coriolis remain: they are checked at full weight."""
    c = {**case, "g": 0.0, "omega_ie": 0.5}
    generated = np.array(
        gen.specific_force_b(
            c["g"],
            c["omega_ie"],
            c["lat"],
            c["psi"],
            c["theta"],
            c["phi"],
            c["tau0"],
            c["l"],
            c["w"],
            c["w_dot"],
        ),
        dtype=float,
    )
    expected = numeric_specific_force(c)
    np.testing.assert_allclose(generated, expected, rtol=0, atol=1e-6 * np.linalg.norm(expected))


def test_specific_force_at_rest_is_minus_gravity():
    """Eq. 15: at rest on a still table f^B = -g^B; with tau = 0 the x reading is g sin(theta)."""
    rng = np.random.default_rng(SEED + 1)
    for _ in range(20):
        g, om, lat, psi, th, ph, tau = rng.uniform(-1.3, 1.3, 7)
        g = 9.8
        f = np.array(gen.specific_force_b(g, om, lat, psi, th, ph, tau, 0.3, 0.0, 0.0), dtype=float)
        expected = -(_rz(tau).T @ _mat_nt(psi, th, ph).T @ [0, 0, g])
        np.testing.assert_allclose(f, expected, atol=1e-12)


@pytest.mark.parametrize(
    "case", _cases(), ids=lambda c: f"tau{c['tau0']:.2f}_Om{c['omega_ie']:.1e}"
)
def test_angular_rate_matches_numeric_rotation(case):
    c = case
    generated = np.array(
        gen.angular_rate_b(
            c["omega_ie"], c["lat"], c["psi"], c["theta"], c["phi"], c["tau0"], c["w"]
        ),
        dtype=float,
    )
    expected = numeric_angular_rate(c)
    np.testing.assert_allclose(generated, expected, rtol=0, atol=1e-6 * np.linalg.norm(expected))


def test_angular_rate_still_table_is_earth_rate_only():
    """Table still: |omega^{BI}| = Omega for any attitude and latitude, independent of longitude."""
    rng = np.random.default_rng(SEED + 2)
    om = 7.292115e-5
    for _ in range(20):
        c = {**_random_case(rng), "omega_ie": om, "w": 0.0, "w_dot": 0.0}
        w = np.array(
            gen.angular_rate_b(om, c["lat"], c["psi"], c["theta"], c["phi"], c["tau0"], 0.0),
            dtype=float,
        )
        assert np.linalg.norm(w) == pytest.approx(om, rel=1e-12)
        np.testing.assert_allclose(w, numeric_angular_rate(c, lon=2.0), rtol=0, atol=1e-6 * om)


# --------------------------------------------------------------------------------------------
# generated module == lambdified derivations
# --------------------------------------------------------------------------------------------
@pytest.fixture(scope="module")
def generated_functions():
    from derivations.north_finding import generate

    return generate.functions()


def test_every_generated_function_is_covered(generated_functions):
    assert [f.name for f in generated_functions] == list(gen.__all__)


def test_generated_functions_equal_lambdified_derivations(generated_functions):
    """Every function of pipeline/generated/north_finding.py equals its SymPy expression."""
    rng = np.random.default_rng(SEED + 3)
    for fn in generated_functions:
        single = isinstance(fn.exprs, sp.Basic)
        exprs = [fn.exprs] if single else list(fn.exprs)
        ref = sp.lambdify(list(fn.args), exprs, "numpy")
        compiled = getattr(gen, fn.name)
        finite = 0
        for _ in range(25):
            # (0.15, 1.3): angles away from 0 and pi/2, positive readings and coefficients
            args = rng.uniform(0.15, 1.3, len(fn.args))
            with np.errstate(all="ignore"):
                want = np.array(ref(*args), dtype=float).ravel()
                got = np.array(
                    compiled(*args) if not single else [compiled(*args)], dtype=float
                ).ravel()
            assert got.shape == want.shape, fn.name
            np.testing.assert_array_equal(np.isnan(got), np.isnan(want), err_msg=fn.name)
            ok = np.isfinite(want)
            finite += int(ok.all())
            scale = np.max(np.abs(want[ok]), initial=1.0)
            np.testing.assert_allclose(
                got[ok], want[ok], rtol=1e-12, atol=1e-12 * scale, err_msg=fn.name
            )
        assert finite >= 5, f"{fn.name}: too few finite sample points"
