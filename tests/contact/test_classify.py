"""Classification of the limit regime: on synthetic travelling patterns with known answers,
and on a real run whose limit wave is compared with linear theory."""

import numpy as np
import pytest

from stickslip.brake import BrakeParams, growth_rates
from stickslip.brake.ring import RingRun, RingScheme, integrate
from stickslip.contact import (SEPARATION, SLIP_NEG, SLIP_POS, STICK, classify, count_zones, pattern_shift,
                               regime_name)
from stickslip.errors import ParameterError

BASE = BrakeParams(xi=1.5, nu=0.3, gamma=1.0, delta=0.001, friction=0.7)


def _synthetic(n=3, c=-0.8, K=48, modulate=0.0, N=128, drift=0.0):
    """A RingRun holding the pattern ``X(theta - c t)`` of period ``2 pi / n`` sampled at K times
    (its second harmonic's phase drifting by ``drift`` radians over the window)."""
    scheme = RingScheme(BASE, N)
    step = 5
    ts = scheme.dt * step * (np.arange(K) + 1)
    phase = n * (scheme.theta[None, :] - c * ts[:, None])
    wave = np.sin(phase) + 0.3 * np.sin(2 * phase + drift * ts[:, None] / ts[-1])
    wave *= 1 + modulate * np.sin(3 * scheme.theta[None, :] + 40 * ts[:, None] / ts[-1])
    state = np.full(wave.shape, SLIP_POS, np.int8)
    state[wave > 0.9] = STICK
    state[wave < -0.9] = SEPARATION
    state[(wave > 0.6) & (wave < 0.65)] = SLIP_NEG
    U = BASE.delta + 1e-4 * np.maximum(-wave - 0.9, 0.0)
    V = 0.002 + 1e-4 * wave
    frac = np.stack([np.mean(state == k, axis=1) for k in range(4)], axis=1)
    series = {"t": ts, "energy": np.ones(K), "kinetic": np.ones(K), "fractions": frac,
              "modes_U": np.fft.rfft(U, axis=1)[:, :33] / N, "modes_V": np.fft.rfft(V, axis=1)[:, :33] / N}
    zero = np.zeros_like(U)
    snapshots = {"snap_t": ts, "U": U, "V": V, "Ud": zero, "Vd": zero, "P": zero, "Q": zero, "state": state}
    settings = {"chunk": step, "samples_total": K, "snap_every": 1, "tail_samples": K, "samples_per_transit": 32,
                "modes": 32, "contact": True, "initial": "synthetic", "initial_hash": ""}
    return RingRun(scheme, settings, series, snapshots, {}, K)


def test_synthetic_travelling_wave_is_recognised():
    run = _synthetic(n=3, c=-0.8)
    res = classify(run)
    assert res.regime == "stick-slip-separation-reverse-slip"
    assert res.n == 3 and res.n_fft == 3
    assert res.c == pytest.approx(-0.8, rel=1e-3)
    assert res.stationary and res.residual < 0.08 and res.state_mismatch < 0.1  # interpolation of kinks
    d = res.to_dict()
    assert d["regime"] == res.regime and set(d["fractions"]) == {"stick", "slip", "reverse_slip", "separation"}


@pytest.mark.parametrize("c", [0.5, -1.5])
def test_wave_speed_sign_convention(c):
    """``phi = theta - c t``: a pattern moving towards increasing theta has ``c > 0``."""
    assert classify(_synthetic(n=2, c=c)).c == pytest.approx(c, rel=1e-3)


def test_modulated_pattern_is_not_stationary():
    res = classify(_synthetic(n=3, c=-0.8, modulate=0.5))
    assert not res.stationary and res.residual > 0.1


def test_a_wave_that_drifts_slowly_across_the_window_is_not_stationary():
    """The second harmonic's phase drifts by 2 rad over 48 snapshots: two consecutive ones differ
    by 0.04 rad of it (a misfit of about 1 % of the pattern, stationary by that measure), the
    first and last by 2 rad. Every pair of the window is compared, so it is not stationary."""
    res = classify(_synthetic(n=3, c=-0.8, drift=2.0))
    assert res.c == pytest.approx(-0.8, rel=0.05)
    assert not res.stationary and res.residual > 0.1


def test_helpers():
    assert regime_name({"separation", "stick"}) == "stick-separation"
    assert regime_name(["reverse_slip", "slip", "stick", "separation"]) == "stick-slip-separation-reverse-slip"
    assert regime_name([]) == "none"
    mask = np.array([1, 1, 0, 0, 1, 0, 1, 1, 1, 0, 0, 1], bool)  # runs: [11, 0, 1], [4], [6, 7, 8]
    assert count_zones(mask) == 3 and count_zones(mask, min_run=2) == 2 and count_zones(mask, min_run=4) == 0
    assert count_zones(np.ones(5, bool)) == 1 and count_zones(np.zeros(5, bool)) == 0
    # an open line does not wrap: [0, 1] and [11] are two runs, of 2 and 1 nodes
    assert count_zones(mask, periodic=False) == 4 and count_zones(mask, min_run=2, periodic=False) == 2
    assert count_zones(np.ones(3, bool), min_run=4, periodic=False) == 0
    theta = 2 * np.pi * np.arange(64) / 64
    x = np.exp(np.cos(theta))
    assert pattern_shift(x, np.exp(np.cos(theta - 0.3))) == pytest.approx(0.3, abs=5e-3)


def test_too_short_window_is_refused():
    run = _synthetic(K=2)
    with pytest.raises(ParameterError) as err:
        classify(run)
    assert err.value.name == "transits" and "3 snapshots" in str(err.value)
    with pytest.raises(ParameterError) as err:
        classify(_synthetic(), min_fraction=1.0)
    assert err.value.name == "min_fraction"


def test_real_limit_wave_travels_at_the_phase_speed_of_its_linear_mode():
    """Case 1 of section 3.1 with the paper's damped scheme on 256 nodes: only mode 2 of
    steady sliding is unstable in the discrete scheme; the run ends on a stationary 2-mode
    stick-slip wave moving against the shaft at the speed ``-Im s(2) / 2`` of linear theory."""
    p = BrakeParams.from_physical(1.0, 4e-4, 0.2)
    scheme = RingScheme(p, 256, 0.9)
    rates = scheme.growth_rates(range(1, 9)).real
    assert rates[1] > 0 and np.all(np.delete(rates, 1) < 0)
    res = classify(integrate(p, 256, transits=300, beta2=0.9))
    assert res.regime == "stick-slip" and res.n == 2 and res.n_fft == 2 and res.stationary
    assert res.c == pytest.approx(growth_rates(p, 2).modes[0].wave_speed, rel=2e-3)
    assert 0.01 < res.fractions["stick"] < 0.1
