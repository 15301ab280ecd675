"""The regime-map figure: its checks pass on the computed maps and fail on a wrong one; plot."""

import pytest

from stickslip.brake.maps import REGIME_CODES
from stickslip.figures.brake.regime_maps import check, compute, plot

from ..helpers import assert_png


@pytest.mark.slow  # a minute: maps computed twice
def test_figure_checks_fail_on_a_wrong_map(tmp_path):
    ds = compute(True, cache=tmp_path)
    assert all(c.passed for c in check(ds))
    bad = ds.copy(deep=True)
    bad["ring_regime"] = bad["ring_regime"] * 0 + REGIME_CODES["stick-slip"]  # no separation anywhere
    assert not all(c.passed for c in check(bad))
    assert_png(plot, ds, tmp_path / "maps.png")
