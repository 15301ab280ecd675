"""The wave-stability figure: its checks pass on the computed data and fail on planted data
(a Moreau run that sees no instability, a leading multiplier that does not settle, a discrete
wave speed that does not approach the continuous one)."""

import numpy as np
import pytest
import xarray as xr

from stickslip.cf import from_file
from stickslip.figures.brake import wave_stability


def _failed(ds):
    return [c.name for c in wave_stability.check(ds) if not c.passed]


def _table(growth, errors, moreau):
    """A dataset of the shape `compute` makes, for the checks alone."""
    return xr.Dataset({"growth_per_period": (("wave", "nodes"), np.array(growth)),
                       "speed_error": (("wave", "nodes"), np.array(errors)),
                       "moreau_growth_per_period": ("wave", np.array(moreau))},
                      coords={"wave": ["a", "b"], "nodes": [64, 128, 256]})


def test_the_checks_catch_planted_tables():
    good = _table([[0.06, 0.066, 0.067], [0.17, 0.21, 0.23]], [[4e-3, 1e-3, 2.5e-4]] * 2, [0.05, 0.18])
    assert _failed(good) == []
    assert any("Moreau" in n for n in _failed(_table([[0.06, 0.066, 0.067]] * 2, [[4e-3, 1e-3, 2.5e-4]] * 2,
                                                     [-0.01, 0.05])))
    assert any("converges" in n for n in _failed(_table([[0.06, 0.066, 0.09]] * 2, [[4e-3, 1e-3, 2.5e-4]] * 2,
                                                        [0.05, 0.05])))
    assert any("speed" in n for n in _failed(_table([[0.06, 0.066, 0.067]] * 2, [[4e-3, 1e-3, 2e-3]] * 2,
                                                    [0.05, 0.05])))


@pytest.mark.slow
def test_the_checks_pass_on_the_computed_data(quick_report):
    """On the quick data of the shared quick report (its most expensive figure)."""
    folder, summary = quick_report
    outcome = next(o for o in summary.outcomes if o.spec.key == "wave-stability")
    assert [c.name for c in outcome.checks if not c.passed] == []
    ds = from_file(xr.load_dataset(folder / "data" / "wave-stability.nc"))  # as the report reads it back
    assert _failed(ds) == [] and "unstable" in wave_stability.describe(ds)


def test_the_separating_waves_check_catches_a_motion_that_does_not_converge_to_the_moreau_steppers():
    def table(refinement):
        ds = _table([[0.06, 0.066, 0.067], [0.17, 0.21, 0.23]], [[4e-3, 1e-3, 2.5e-4]] * 2, [0.05, 0.18])
        sep = ds.isel(wave=[0]).assign_coords(wave=["c (separates)"])
        ds = xr.concat([ds, sep], dim="wave")
        return ds.assign(moreau_refinement=("moreau_steps", np.array(refinement)))
    assert _failed(table([1e-3, 5e-4, 2.5e-4])) == []
    assert any("Moreau stepper" in n for n in _failed(table([1e-3, 9e-4, 8e-4])))  # not first order
    assert any("Moreau stepper" in n for n in _failed(table([4e-3, 2e-3, 1e-3])))  # too far
