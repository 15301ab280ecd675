"""Waves against the ring integration: checks on computed and corrupted data; the ring's
initial condition taken from a wave."""

import numpy as np
import pytest

from stickslip.brake import BrakeParams, travelling_wave
from stickslip.brake.ring import initial_from_wave
from stickslip.figures.brake.paper import FIG12
from stickslip.figures.brake.waves_vs_ring import check as check_comparison
from stickslip.figures.brake.waves_vs_ring import compute, plot

from ..helpers import assert_png


@pytest.fixture(scope="module")
def ds():
    return compute(quick=True)


def test_checks_pass_on_computed_data(ds):
    failed = [c.name for c in check_comparison(ds) if not c.passed]
    assert not failed, failed


def test_checks_fail_on_wrong_data(ds):
    bad = ds.copy(deep=True)
    bad["ring_c"] = bad["ring_c"] * 1.05
    bad["growth_rate"] = -bad["growth_rate"]
    verdicts = {c.name: c.passed for c in check_comparison(bad)}
    assert not verdicts["started on a wave, the ring integration keeps its speed"]
    assert not any(v for k, v in verdicts.items() if "stability" in k)


def test_initial_condition_is_the_wave_moving_at_c():
    p = BrakeParams.from_physical(FIG12["omega"], FIG12["mismatch"], FIG12["friction"])
    wave = travelling_wave(p, FIG12["modes"], regime="stick-slip-separation-reverse-slip")
    ic = initial_from_wave(wave, 256)
    # the nodes in stick move with the shaft: V_t = 1
    theta = 2 * np.pi * np.arange(256) / 256
    stick = wave.evaluate(theta)["slip_velocity"] == 0
    assert stick.any() and np.allclose(ic.Vd[stick], 1.0, atol=1e-9)


def test_plot(ds, tmp_path):
    assert_png(plot, ds, tmp_path / "waves_vs_ring.png")
