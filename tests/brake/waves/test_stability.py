"""Persistence of travelling waves under the ring dynamics (numerical evidence).

The time stepper is first validated on steady sliding (kept exactly; flutter growth rates
of the linear theory reproduced), then started from waves.
"""

import math

import numpy as np
import pytest

from stickslip.brake import BrakeParams, growth_rates
from stickslip.brake.waves.stability import RingState, step_ring, wave_persistence
from stickslip.brake.waves.zones import Scaling
from stickslip.brake.waves.solve import travelling_wave
from stickslip.errors import ParameterError

P = BrakeParams(xi=1.5, nu=0.3, gamma=1.0, delta=1.0, friction=0.7)


def _steady(params, N, perturb=0.0, m=2):
    sc = Scaling(params)
    co = sc.coefficients
    th = 2 * np.pi * np.arange(N) / N
    Ve = params.friction * co.g * sc.delta / co.h
    st = RingState(np.full(N, sc.delta), Ve + perturb * np.cos(m * th), np.zeros(N), np.zeros(N))
    return st, co, sc.delta, th[1], Ve


def test_steady_sliding_is_kept_exactly():
    st, co, delta, dth, Ve = _steady(P, 64)
    state = step_ring(st, co, delta, P.friction, dth, 0.2 * dth / math.sqrt(co.a), 2000)
    assert np.all(state == 1)  # every node slips forward
    assert np.max(np.abs(st.U - delta)) < 1e-12 and np.max(np.abs(st.V - Ve)) < 1e-12


@pytest.mark.parametrize("m", [2, 4])
def test_stepper_reproduces_the_flutter_growth_rate(m):
    st, co, delta, dth, _ = _steady(P, 128, perturb=1e-7, m=m)
    dt = 0.1 * dth / math.sqrt(co.a)
    n_sub = int(0.4 / dt)
    t, amp = [], []
    for k in range(20):
        step_ring(st, co, delta, P.friction, dth, dt, n_sub)
        t.append((k + 1) * n_sub * dt)
        amp.append(abs(np.fft.fft(st.V)[m]))
    rate = np.polyfit(t[5:], np.log(amp[5:]), 1)[0]
    assert rate == pytest.approx(growth_rates(P, [m]).growth_rate[0], rel=0.03)


@pytest.fixture(scope="module")
def stick_slip():
    return travelling_wave(P.replace(friction=0.2), 4)


@pytest.fixture(scope="module")
def reverse():
    return travelling_wave(P.replace(friction=0.2, delta=0.05), 8)


def test_a_stick_slip_wave_travels_on_the_ring_but_a_perturbation_grows(stick_slip):
    r = wave_persistence(stick_slip, nodes=256, periods=20)
    assert r.drift[1] < 0.01 and np.all(np.abs(r.lag[:5]) < 0.05)  # it is a solution of [12]
    assert r.growth_rate > 0.02  # ... but a perturbation grows (flutter inside the slip zone)
    assert r.growth_rate < growth_rates(stick_slip.params, [400]).growth_rate[0]  # below sup Re s


def test_the_mode_8_wave_with_reverse_slip_attracts_nearby_states(reverse):
    r = wave_persistence(reverse, nodes=256, periods=20)
    assert r.persists and r.growth_rate < 0


def test_persistence_outputs(reverse):
    r = wave_persistence(reverse, nodes=128, periods=3)
    ds = r.to_xarray()
    assert ds.sizes["time"] == 4 and ds["lag"].attrs["units"] == "rad" and "growth_rate" in ds.attrs


@pytest.mark.parametrize("kwargs, name", [(dict(nodes=130), "nodes"), (dict(cfl=0.9), "cfl"),
                                          (dict(periods=0), "periods")])
def test_bad_input(reverse, kwargs, name):
    with pytest.raises(ParameterError, match=name):
        wave_persistence(reverse, **kwargs)
