"""Figures 5, 6, 11, 12: the checks pass on computed data, fail on corrupted data, plots draw."""

import numpy as np
import pytest

from stickslip.figures.brake import fig5, fig6, fig11, fig12

from ..helpers import assert_png

FIGS = ["5", "6", "11", "12"]
MODULES = {"5": fig5, "6": fig6, "11": fig11, "12": fig12}


@pytest.fixture(scope="module")
def data():
    return {k: MODULES[k].compute(quick=True) for k in FIGS}


@pytest.mark.parametrize("fig", FIGS)
def test_checks_pass_on_computed_data(data, fig):
    checks = MODULES[fig].check(data[fig])
    assert len(checks) >= 5
    assert all(c.passed for c in checks), [c for c in checks if not c.passed]


def _corrupt(fig, ds):
    bad = ds.copy(deep=True)
    if fig == "11":
        bad["direct_c"][0] = bad["direct_c"][0] * 1.01
        bad["event_kind"][:] = "change"
        bad["structure"][-1] = "stick|slip"
        bad["structure"][-2] = "stick|slip"
        bad["structure"][-3] = "stick|slip"
        bad["structure"][:] = "stick|slip"
        bad.attrs["min_margin"] = -1.0
        return bad, 5
    bad["residual"][0] = 1e-3
    bad["min_margin"][0] = -0.1
    bad["ivp_switching"][0] = 1e-3
    bad["energy_residual"][0] = 1e-2
    bad["return_map_mismatch"][0] = 1e-3
    bad["c"][0] = -bad["c"][0]
    bad["regime"][0] = "stick-slip-reverse-slip"
    return bad, 6


@pytest.mark.parametrize("fig", FIGS)
def test_checks_fail_on_corrupted_data(data, fig):
    bad, expected_failures = _corrupt(fig, data[fig])
    checks = MODULES[fig].check(bad)
    assert sum(not c.passed for c in checks) >= expected_failures


def test_figure_5_waves_are_self_similar_in_omega(data):
    ds = data["5"]
    assert np.ptp((ds["c"] * ds["omega"]).values) < 1e-8 * abs(float(ds["c"][0] * ds["omega"][0]))
    assert set(ds["regime"].values) == {"stick-slip"}


def test_figure_12_has_overshoot(data):
    ds = data["12"]
    assert ds.attrs["modes"] == 8 and float(ds["slip_velocity"].min()) < 0
    assert float(ds["reverse_fraction"][0]) > 0


@pytest.mark.parametrize("fig", FIGS)
def test_plots_are_written(data, fig, tmp_path):
    path = tmp_path / f"fig{fig}.png"
    assert_png(MODULES[fig].plot, data[fig], path)
    assert path.stat().st_size > 10_000


@pytest.mark.parametrize("fig", FIGS)
def test_datasets_round_trip_through_netcdf(data, fig, tmp_path):
    path = tmp_path / f"fig{fig}.nc"
    data[fig].to_netcdf(path)
    import xarray as xr
    with xr.open_dataset(path) as back:
        assert MODULES[fig].check(back)[0].passed
