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


def _set(name, index, value):
    def corrupt(ds):
        bad = ds.copy(deep=True)
        bad[name][index] = value(bad[name].values[index]) if callable(value) else value
        return bad
    return corrupt


def _attr(name, value):
    return lambda ds: ds.assign_attrs({name: value})


# (figure, label, corruption, part of the name of the check that must fail on it)
COMMON = [("residual", _set("residual", 0, 1e-3), "multiple-shooting residual"),
          ("inequality", _set("min_margin", 0, -0.1), "inequalities"),
          ("solve_ivp profile", _set("ivp_profile_error", 0, 1e-4), "solve_ivp"),
          ("solve_ivp switching", _set("ivp_switching", 0, 1e-6), "solve_ivp"),
          ("energy", _set("energy_residual", 0, 1e-6), "energy balance"),
          ("ring work", _set("ring_work", 0, 1e-6), "energy balance"),
          ("return map", _set("return_map_mismatch", 0, 1e-6), "return map")]
CORRUPTIONS = [(fig, *c) for fig in ("5", "6", "12") for c in COMMON] + [
    ("5", "not self-similar speed", _set("c", -1, lambda c: c * (1 + 1e-6)), "self-similar"),
    ("6", "no impact", _set("n_impacts", 0, 0), "impact"),
    ("6", "impact gains energy", _set("impact_dissipation", 0, lambda d: -d), "impact"),
    ("12", "ring without reverse slip", lambda ds: ds.assign(ring_reverse_slip=ds["ring_reverse_slip"] * 0),
     "reverse slip"),
    ("12", "wave without overshoot", lambda ds: ds.assign(slip_velocity=abs(ds["slip_velocity"])), "reverse slip"),
    ("12", "ring breaks the mode", lambda ds: ds.assign(ring_n_fft=ds["ring_n_fft"] * 0 + 7), "mode-8"),
    ("12", "ring drifts", lambda ds: ds.assign(ring_c=ds["ring_c"] * 1.01), "mode-8"),
    ("11", "continuation off the direct solves", _set("direct_c", 0, lambda c: c * 1.01), "direct solves"),
    ("11", "no birth", _set("event_kind", slice(None), "change"), "born"),
    ("11", "no stick-slip-separation", _set("structure", slice(None), "stick|slip"), "ends in"),
    ("11", "a point fails its checks", _attr("min_margin", -1.0), "every point"),
    ("11", "a residual", _attr("max_residual", 1e-6), "every point"),
]


@pytest.mark.parametrize("fig, label, corrupt, name", CORRUPTIONS, ids=[f"fig{c[0]} {c[1]}" for c in CORRUPTIONS])
def test_each_check_rejects_corrupted_data(data, fig, label, corrupt, name):
    before = {c.name: c.passed for c in MODULES[fig].check(data[fig]) if name in c.name}
    after = {c.name: c.passed for c in MODULES[fig].check(corrupt(data[fig])) if name in c.name}
    assert len(before) == 1 and all(before.values()), before
    assert not any(after.values()), f"{label}: passed on corrupted data"


def test_figure_5_waves_are_self_similar_in_omega(data):
    ds = data["5"]
    assert np.ptp((ds["c"] * ds["omega"]).values) < 1e-8 * abs(float(ds["c"][0] * ds["omega"][0]))


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
