"""WGS-84 normal gravity (pipeline/altimeter_attitude/gravity.py) against published values."""

from __future__ import annotations

import math

import pytest

from pipeline.altimeter_attitude import gravity


def test_equator_and_pole_are_the_published_values():
    """gamma_e and gamma_p of NIMA TR8350.2 Table 3.3 (9.780 and 9.832 m/s^2): the pole value
    checks Somigliana's formula with the tabulated k and e^2, which are derived constants."""
    assert gravity.normal_gravity(0.0) == pytest.approx(9.7803253359, abs=1e-10)
    assert gravity.normal_gravity(90.0) == pytest.approx(9.8321849378, abs=1e-9)
    assert gravity.normal_gravity(-90.0) == gravity.normal_gravity(90.0)
    # k = b gamma_p / (a gamma_e) - 1 with b = a (1 - f)
    k = (1 - gravity.F) * gravity.GAMMA_P / gravity.GAMMA_E - 1
    assert k == pytest.approx(gravity.K, rel=1e-8)  # the table's constants are rounded


def test_free_air_gradient_and_height_term():
    """The linear height term is the free-air gradient 0.3086 mGal/m (3.086e-6 s^-2); against
    the inverse-square law g (a / (a + h))^2 (= g (1 - 2h/a + 3h^2/a^2) to second order) the
    expansion differs by its flattening and centrifugal part, 2 g (f + m - 2 f sin^2) h / a."""
    g0 = gravity.normal_gravity(45.0)
    gradient = (g0 - gravity.normal_gravity(45.0, 1.0)) / 1.0
    assert gradient == pytest.approx(3.086e-6, rel=3e-3)
    for h in (1000.0, 10000.0):
        inverse_square = g0 * (gravity.A / (gravity.A + h)) ** 2
        part = 2 * g0 * (gravity.F + gravity.M - 2 * gravity.F * 0.5) * h / gravity.A
        diff = inverse_square - gravity.normal_gravity(45.0, h)
        assert diff == pytest.approx(part, rel=5e-3)  # to O(h / a)


def test_standard_gravity_latitude():
    """9.80665 (standard gravity) is WGS-84 sea-level normal gravity near 45.5 deg."""
    lo, hi = gravity.normal_gravity(45.0), gravity.normal_gravity(46.0)
    assert lo < 9.80665 < hi


@pytest.mark.parametrize(
    ("lat", "h", "match"),
    [
        (math.nan, 0.0, "latitude = nan deg"),
        (-90.5, 0.0, "latitude = -90.5 deg"),
        (0.0, math.inf, "height = inf m"),
        (0.0, 30000.0, r"height = 30000.0 m: must be a finite number in \[-1000, 20000\]"),
    ],
)
def test_bad_input_is_named(lat, h, match):
    with pytest.raises(ValueError, match=match):
        gravity.normal_gravity(lat, h)
