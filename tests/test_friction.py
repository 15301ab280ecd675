import math

import numpy as np
import pytest

from stickslip.errors import ParameterError
from stickslip.friction import Coulomb, LinearWeakening, Stribeck, UserLaw, law_names, make_law

LAWS = [Coulomb(0.6, 0.4), LinearWeakening(0.5, 0.4, 0.5), Stribeck(0.6, 0.4, 0.1),
        UserLaw(lambda v: 0.4 + 0.2 * math.exp(-abs(v) / 0.1), 0.6)]


@pytest.mark.parametrize("law", LAWS, ids=lambda l: type(l).__name__)
def test_slope_matches_finite_difference(law):
    for v in (-0.7, -0.05, 0.03, 0.4):
        h = 1e-6
        fd = (law.kinetic(v + h) - law.kinetic(v - h)) / (2 * h)
        assert law.slope(v) == pytest.approx(fd, rel=1e-5, abs=1e-8)


@pytest.mark.parametrize("law", LAWS, ids=lambda l: type(l).__name__)
def test_laws_are_even_and_bounded_by_static(law):
    v = np.linspace(0.001, 1.5, 50)
    assert np.allclose(law.kinetic(v), law.kinetic(-v))
    assert np.all(law.kinetic(v) <= law.static + 1e-15)


def test_affine_representation_reproduces_the_law():
    for law in (Coulomb(0.6, 0.4), LinearWeakening(0.5, 0.4, 0.5)):
        mu0, mu1 = law.affine
        v = np.linspace(-1, 1, 11)
        assert np.allclose(law.kinetic(v), mu0 - mu1 * np.abs(v))
    assert Stribeck(0.6, 0.4, 0.1).affine is None


def test_stribeck_is_continuous_at_the_stick_limit():
    law = Stribeck(0.6, 0.4, 0.1)
    assert law.kinetic(1e-14) == pytest.approx(0.6)
    assert law.kinetic(1e3) == pytest.approx(0.4)


def test_linear_weakening_validity_range():
    assert LinearWeakening(0.4, 0.4, 0.5).max_speed == 2.0
    assert LinearWeakening(0.4, 0.4, 0.0).max_speed == math.inf


@pytest.mark.parametrize("build, name", [
    (lambda: Coulomb(0.3, 0.4), "fs"), (lambda: Coulomb(0.6, -0.1), "fd"), (lambda: Coulomb(float("nan"), 0.4), "fs"),
    (lambda: LinearWeakening(0.6, 0.4, -1.0), "tau"), (lambda: Stribeck(0.6, 0.4, 0.0), "vs"),
    (lambda: UserLaw(3.0, 0.5), "mu"), (lambda: make_law("viscous", fs=0.6, fd=0.4), "law"),
    (lambda: make_law("stribeck", fs=0.6, fd=0.4), "vs"), (lambda: make_law("stribeck", fs=0.6, fd=0.4, tau=0.1), "tau"),
    (lambda: make_law("coulomb", fs=0.6, fd=0.4, vs=0.1), "vs"),
])
def test_invalid_parameters_name_themselves(build, name):
    with pytest.raises(ParameterError) as err:
        build()
    assert err.value.name == name
    assert name in str(err.value) and "must be" in str(err.value)


def test_user_law_rejects_negative_coefficients():
    law = UserLaw(lambda v: 0.4 - abs(v), 0.5)
    with pytest.raises(ParameterError, match=r"mu\(v_r\)"):
        law.kinetic(2.0)


def test_registry_names_the_cli_choices():
    assert law_names() == ["coulomb", "linear-weakening", "stribeck"]
    assert isinstance(make_law("linear-weakening", fs=0.5, fd=0.4, tau=0.5), LinearWeakening)
