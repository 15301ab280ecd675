"""Wave speeds, Rayleigh speed and Radok coefficients (paper section 4.1)."""

import math

import numpy as np
import pytest

from stickslip.errors import ParameterError
from stickslip.halfspace import Material, radok, rayleigh_speed_ratio, wave_speed_ratio
from stickslip.halfspace.waves import rayleigh_function


def test_wave_speeds_from_moduli():
    mat = Material(2.1e11, 0.3, 7850.0)
    G = 2.1e11 / 2.6
    lam = 2.1e11 * 0.3 / (1.3 * 0.4)
    assert mat.c2 == pytest.approx(math.sqrt(G / 7850.0), rel=1e-14)
    assert mat.c1 == pytest.approx(math.sqrt((lam + 2 * G) / 7850.0), rel=1e-14)
    assert mat.c1 / mat.c2 == pytest.approx(wave_speed_ratio(0.3), rel=1e-14)


@pytest.mark.parametrize("nu", [0.0, 0.1, 0.25, 0.3, 0.45, 0.499])
def test_rayleigh_root(nu):
    xi = rayleigh_speed_ratio(nu)
    assert 0.87 < xi < 0.96
    assert abs(rayleigh_function(xi, wave_speed_ratio(nu))) < 1e-13
    # Viktorov's approximation (0.862 + 1.14 nu)/(1 + nu), good to about 1.5 %
    assert xi == pytest.approx((0.862 + 1.14 * nu) / (1 + nu), rel=1.5e-2)


def test_rayleigh_published_value():
    # nu = 1/4 (Poisson solid): xi^2 = 2 - 2/sqrt(3), xi = 0.9194
    assert rayleigh_speed_ratio(0.25) == pytest.approx(math.sqrt(2 - 2 / math.sqrt(3)), rel=1e-13)
    assert rayleigh_speed_ratio(0.25) == pytest.approx(0.9194, abs=5e-5)


def test_radok_stable_forms_match_definitions():
    c = np.linspace(-0.999, -0.01, 300)
    rd = radok(c, 0.3, 0.5)
    c1 = wave_speed_ratio(0.3)
    b1, b2 = np.sqrt(1 - c**2 / c1**2), np.sqrt(1 - c**2)
    np.testing.assert_allclose(rd.gamma1, b1 * (1 - b2**2), rtol=1e-12)
    np.testing.assert_allclose(rd.gamma2, 1 + b2**2 - 2 * b1 * b2, rtol=1e-9)
    np.testing.assert_allclose(rd.one_minus_b1b2, 1 - b1 * b2, rtol=1e-10)
    np.testing.assert_allclose(np.tan(np.pi * rd.alpha), 0.5 * rd.gamma2 / rd.gamma1, rtol=1e-12)
    np.testing.assert_allclose(rd.K, np.pi * (0.5 - rd.alpha) / np.cos(np.pi * rd.alpha), rtol=1e-13)
    np.testing.assert_allclose(rd.gamma_mod, rd.gamma1 * np.cos(np.pi * rd.alpha) + 0.5 * rd.gamma2 * np.sin(np.pi * rd.alpha), rtol=1e-13)


def test_radok_signs_and_alpha_range():
    c = -(1 - np.cos(np.pi * (np.arange(5000) + 0.5) / 5000)) / 2
    for nu in (0.0, 0.3, 0.49):
        for mu in (0.01, 0.5, 5.0):
            rd = radok(c, nu, mu)
            assert np.all(rd.gamma1 > 0) and np.all(rd.gamma2 > 0)
            assert np.all((rd.alpha > 0) & (rd.alpha < 0.5))
            assert np.all(rd.K_minus_one > 0) and np.all(rd.one_minus_b1b2 > 0)


def test_radok_limits():
    nu, mu = 0.3, 0.5
    c1 = wave_speed_ratio(nu)
    slow = radok(-1e-9, nu, mu)  # c -> 0: gamma2/gamma1 -> 1/c1bar^2
    assert float(slow.gamma2 / slow.gamma1) == pytest.approx(1 / c1**2, rel=1e-8)
    assert float(slow.alpha) == pytest.approx(math.atan(mu / c1**2) / math.pi, rel=1e-8)
    fast = radok(-1 + 1e-14, nu, mu)  # c -> -1: beta2 -> 0, gamma1 -> beta1, gamma2 -> 1
    b1 = math.sqrt(1 - 1 / c1**2)
    assert float(fast.beta2) < 1e-6
    assert float(fast.gamma1) == pytest.approx(b1, rel=1e-6)
    assert float(fast.gamma2) == pytest.approx(1.0, rel=1e-6)


def test_alpha_is_the_exponent_of_g():
    """[42]: g = -(gamma1 + i mu gamma2)/(gamma1 - i mu gamma2) = -exp(2 i pi alpha), |g| = 1."""
    rd = radok(np.linspace(-0.99, -0.01, 50), 0.3, 0.7)
    g = -(rd.gamma1 + 1j * 0.7 * rd.gamma2) / (rd.gamma1 - 1j * 0.7 * rd.gamma2)
    np.testing.assert_allclose(g, -np.exp(2j * np.pi * rd.alpha), atol=1e-14)


@pytest.mark.parametrize("kwargs, name", [
    (dict(cbar=0.0, nu=0.3, mu=0.5), "c"), (dict(cbar=-1.0, nu=0.3, mu=0.5), "c"),
    (dict(cbar=0.3, nu=0.3, mu=0.5), "c"), (dict(cbar=np.nan, nu=0.3, mu=0.5), "c"),
    (dict(cbar=[-0.5, -1.2], nu=0.3, mu=0.5), "c"), (dict(cbar=-0.5, nu=0.5, mu=0.5), "nu"),
    (dict(cbar=-0.5, nu=-0.1, mu=0.5), "nu"), (dict(cbar=-0.5, nu=0.3, mu=0.0), "mu"),
])
def test_radok_rejects_bad_input(kwargs, name):
    with pytest.raises(ParameterError) as err:
        radok(**kwargs)
    assert err.value.name == name
    assert name in str(err.value) and "must be" in str(err.value)


def test_material_rejects_bad_input():
    with pytest.raises(ParameterError, match="young"):
        Material(-1.0, 0.3, 7850)
    with pytest.raises(ParameterError, match="poisson"):
        Material(2e11, 0.5, 7850)
    with pytest.raises(ParameterError, match="density"):
        Material(2e11, 0.3, 0)
