"""The growth-rate figure: data, checks (that can fail) and plot."""

import numpy as np
import pytest

from stickslip.brake import BrakeParams, growth_rates
from stickslip.brake.figures import check_stability, grid_growth_rates, plot_stability, stability_figure_data
from stickslip.errors import ParameterError


@pytest.fixture(scope="module")
def ds():
    return stability_figure_data(quick=True)


def test_checks_pass_on_computed_data(ds):
    checks = check_stability(ds)
    assert len(checks) == 4 and all(c.passed for c in checks), [c for c in checks if not c.passed]
    assert ds["growth_rate_si"].attrs["units"] == "1/s"
    # Omega Re s is the same for the same f whatever Omega: here it grows with f only
    assert np.all(np.diff(ds["growth_rate_limit"] * ds["omega"]) > 0)


def test_checks_fail_on_wrong_data(ds):
    bad = ds.copy(deep=True)
    bad["growth_rate"][0, 2] = -1.0
    bad["growth_rate_grid"][1, 0] *= 1.01
    bad["coupling"][0, 0] = -bad["coupling"][0, 0]  # an extra sign change for nu = 0.2
    assert [c.passed for c in check_stability(bad)] == [False, False, False, False]


def test_grid_route_is_independent_of_the_closed_form():
    p = BrakeParams(2.0, 0.45, 3e-6, 0.002, 1.3)
    modes = [1, 2, 5]
    assert grid_growth_rates(p, modes, nodes=13) == pytest.approx(growth_rates(p, modes).growth_rate, rel=1e-4)


@pytest.mark.parametrize("kwargs, name", [(dict(nodes=12), "nodes"), (dict(nodes=9), "nodes"),
                                          (dict(penalty=0.0), "penalty"), (dict(modes=[]), "modes")])
def test_grid_route_rejects_bad_input(kwargs, name):
    args = dict(params=BrakeParams(1.5, 0.3, 1.0, 0.001, 0.5), modes=[1, 5], nodes=13) | kwargs
    with pytest.raises(ParameterError) as err:
        grid_growth_rates(**args)
    assert err.value.name == name


def test_plot_writes_a_png(ds, tmp_path):
    path = tmp_path / "brake_stability.png"
    plot_stability(ds, path)
    assert path.read_bytes()[:8] == b"\x89PNG\r\n\x1a\n"
