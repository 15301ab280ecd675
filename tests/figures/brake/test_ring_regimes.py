"""Figures of ring runs (limit regimes, initial condition): quick data, checks that pass on it
and fail on wrong data, plots, netCDF."""

import numpy as np
import pytest
import xarray as xr

from stickslip.brake import BrakeParams, separation_number
from stickslip.figures.brake import initial_condition, ring_regimes

from ..helpers import assert_png


@pytest.fixture(scope="module")
def regimes():
    return ring_regimes.compute(quick=True)


@pytest.fixture(scope="module")
def seeds():
    return initial_condition.compute(quick=True)


@pytest.mark.slow  # on the quick data of two figures (17 s): the slow set
def test_regime_checks_pass_on_computed_data(regimes):
    checks = ring_regimes.check(regimes)
    assert len(checks) == 6 and all(c.passed for c in checks), [c for c in checks if not c.passed]
    assert regimes["energy"].attrs["units"] == "E R^2 / M" and regimes["omega"].attrs["units"] == "rad/s"


@pytest.mark.slow  # on the quick data of two figures (17 s): the slow set
def test_regime_checks_fail_on_wrong_data(regimes):
    bad = regimes.copy(deep=True)
    bad["fraction"].loc[dict(case=0, setting=0, kind="stick")] = 0.0
    bad["c_over_sqrt_a"][1, 1] = 0.5
    bad["regime"][0, 1] = "stick-slip-separation"
    bad["sweep_fraction"].loc[dict(kind="separation")] = 0.0
    bad["growth"].loc[dict(beta2=0.9, grid=1024)] = bad["growth"].sel(beta2=0.9, grid=128).values
    bad["growth"].loc[dict(beta2=0.9, grid=128)] = 0.1
    assert [c.passed for c in ring_regimes.check(bad)] == [False] * 6


@pytest.mark.slow  # on the quick data of two figures (17 s): the slow set
def test_initial_condition_checks(seeds):
    checks = initial_condition.check(seeds)
    assert len(checks) == 3 and all(c.passed for c in checks), [c for c in checks if not c.passed]
    bad = seeds.copy(deep=True)
    bad["n_fft"][0, 1] = bad["n_fft"][0, 0]  # also differs from the other grid
    bad["energy_spread"][0, 0] = 0.5
    assert [c.passed for c in initial_condition.check(bad)] == [False, False, False]


def test_separation_number_is_kappa_times_a_geometry_factor():
    p1, p2 = BrakeParams.from_physical(50.0, 1e-4, 0.7), BrakeParams.from_physical(200.0, 1e-4, 0.7)
    kappa = lambda p: p.delta / np.sqrt(p.gamma)  # noqa: E731
    assert separation_number(p1) / kappa(p1) == pytest.approx(separation_number(p2) / kappa(p2), rel=1e-12)
    assert separation_number(p1) == pytest.approx(4 * separation_number(p2), rel=1e-12)


@pytest.mark.slow  # on the quick data of two figures (17 s): the slow set
def test_plots_and_netcdf(regimes, seeds, tmp_path):
    for ds, plot, name in ((regimes, ring_regimes.plot, "regimes"), (seeds, initial_condition.plot, "seeds")):
        assert_png(plot, ds, tmp_path / f"{name}.png")
        ds.to_netcdf(tmp_path / f"{name}.nc")
        back = xr.load_dataset(tmp_path / f"{name}.nc")
        assert back["regime"].values.tolist() == ds["regime"].values.tolist()
