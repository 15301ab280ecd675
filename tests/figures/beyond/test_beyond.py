"""The figures beyond the paper: their checks pass on the computed data and fail on data that
contradict the closed forms (each planted into the dataset)."""

import numpy as np
import pytest

from stickslip.figures.beyond import adams, flutter, rsf_slider, squeal


@pytest.fixture(scope="module")
def rsf_data():
    return rsf_slider.compute(quick=True)


@pytest.fixture(scope="module")
def squeal_data():
    return squeal.compute(quick=True)


def _failed(checks):
    return [c.name for c in checks if not c.passed]


def test_the_slider_checks_pass_and_catch_a_wrong_critical_stiffness(rsf_data):
    assert _failed(rsf_slider.check(rsf_data)) == []
    wrong = rsf_data.copy(deep=True)
    wrong["critical_stiffness"][-1] *= 1 + 1e-6  # one point off the closed form
    assert any("k_c" in name for name in _failed(rsf_slider.check(wrong)))
    stuck = rsf_data.copy(deep=True)
    stuck["friction"].loc[{"law": "aging"}] = np.minimum(stuck["friction"].sel(law="aging"), 0.6)  # no healing
    assert any("heals" in name for name in _failed(rsf_slider.check(stuck)))


def test_the_squeal_checks_pass_and_catch_a_wrong_threshold_or_an_open_orbit(squeal_data):
    assert _failed(squeal.check(squeal_data)) == []
    wrong = squeal_data.copy(deep=True)
    wrong["mu_critical"] = wrong["mu_critical"] * (1 + 1e-5)
    assert any("flutter" in name for name in _failed(squeal.check(wrong)))
    drift = squeal_data.copy(deep=True)
    drift["closing_error"] = drift["closing_error"] + 1e-6
    assert any("closes" in name for name in _failed(squeal.check(drift)))


@pytest.mark.slow
def test_the_flutter_checks_pass_and_catch_a_growth_off_the_relation_or_a_stalled_convergence():
    data = flutter.compute(quick=True)
    assert _failed(flutter.check(data)) == []
    wrong = data.copy(deep=True)
    wrong["growth"].loc[{"law": "Coulomb", "mode": 4}] *= 1.03  # one mode 3 % off the relation
    assert any("Coulomb sliding grows" in name for name in _failed(flutter.check(wrong)))
    stalled = data.copy(deep=True)
    stalled["difference"].loc[{"law": "Prakash-Clifton"}] = 1e-3  # the differences stop falling
    assert any("converges" in name for name in _failed(flutter.check(stalled)))


@pytest.mark.slow
def test_the_adams_checks_pass_and_catch_a_growth_off_the_relation_or_a_growing_identical_pair():
    data = adams.compute(quick=True)
    assert _failed(adams.check(data)) == []
    wrong = data.copy(deep=True)
    wrong["growth"] = wrong["growth"] * 1.02  # 2 % off the relation
    assert any("relation's rate" in name for name in _failed(adams.check(wrong)))
    grown = data.copy(deep=True)
    grown["identical_growth"] = grown["identical_growth"] * 0 + 0.01
    assert any("identical" in name for name in _failed(adams.check(grown)))
