"""The growth-rate figure: data, checks (that can fail) and plot."""

import numpy as np
import pytest

from stickslip.figures.brake.stability import check as check_stability
from stickslip.figures.brake.stability import compute, plot

from ..helpers import assert_png


@pytest.fixture(scope="module")
def ds():
    return compute(quick=True)


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


def test_plot_writes_a_png(ds, tmp_path):
    assert_png(plot, ds, tmp_path / "brake_stability.png")
