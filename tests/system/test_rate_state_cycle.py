"""Limit cycles of systems with rate-and-state contacts: the cycle closes under an independent
integration of the equations (written here in theta, not psi; LSODA), its multipliers are those of
that integration's flow map by central differences, and a long independent run settles on its
period."""

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from stickslip.errors import NoSolutionError
from stickslip.rsf import RateState
from stickslip.system import Contact, System, rate_state_cycle

A, B, DC, F0, V0 = 0.01, 0.015, 1e-5, 0.6, 1e-6
N, V, M = 10.0, 1e-6, 1e3
K_C = N * (B - A) / DC * (1 + M * V ** 2 / (N * A * DC))


def block(fraction, evolution="slip"):
    law = RateState(a=A, b=B, dc=DC, f0=F0, v_ref=V0, evolution=evolution)
    return System([[M]], [[fraction * K_C]], [Contact([1.0], N, law, V)])


def equations(k, evolution="slip"):
    """m x'' = -k x + N mu(V - x', theta), theta' by the law, in (x, x', theta)."""
    def rhs(t, y):
        x, v, theta = y
        vr = V - v
        mu = F0 + A * math.log(vr / V0) + B * math.log(V0 * theta / DC)
        if evolution == "slip":
            dtheta = -vr * theta / DC * math.log(vr * theta / DC)
        else:
            dtheta = 1.0 - vr * theta / DC
        return [v, (-k * x + N * mu) / M, dtheta]
    return rhs


def flow(rhs, y0, T):
    sol = solve_ivp(rhs, (0.0, T), y0, method="LSODA", rtol=1e-12, atol=[1e-18, 1e-20, 1e-16])
    return sol.y[:, -1]


@pytest.fixture(scope="module")
def cycle():
    return rate_state_cycle(block(0.9))


@pytest.mark.slow
def test_the_cycle_closes_under_an_independent_integration(cycle):
    rhs = equations(0.9 * K_C)
    y0 = np.array([cycle.x0[0], cycle.v0[0], DC * math.exp(cycle.psi0[0][0]) / V0])
    end = flow(rhs, y0, cycle.period)
    sol = solve_ivp(rhs, (0.0, cycle.period), y0, method="LSODA", rtol=1e-12, atol=[1e-18, 1e-20, 1e-16],
                    dense_output=True)
    ranges = np.ptp(sol.sol(np.linspace(0.0, cycle.period, 2001)), axis=1)
    assert np.all(np.abs(end - y0) < 1e-5 * ranges)
    assert cycle.slip_rate_max[0] > 10 * V  # a real stick-slip-like cycle, not steady sliding


@pytest.mark.slow
def test_the_multipliers_are_those_of_the_independent_flow_map(cycle):
    rhs = equations(0.9 * K_C)
    y0 = np.array([cycle.x0[0], cycle.v0[0], DC * math.exp(cycle.psi0[0][0]) / V0])
    sol = solve_ivp(rhs, (0.0, cycle.period), y0, method="LSODA", rtol=1e-12, atol=[1e-18, 1e-20, 1e-16],
                    dense_output=True)
    ranges = np.ptp(sol.sol(np.linspace(0.0, cycle.period, 2001)), axis=1)
    Phi = np.zeros((3, 3))
    for j in range(3):
        d = np.zeros(3)
        d[j] = 1e-5 * ranges[j]
        Phi[:, j] = (flow(rhs, y0 + d, cycle.period) - flow(rhs, y0 - d, cycle.period)) / (2 * d[j])
    expected = np.sort(np.abs(np.linalg.eigvals(Phi)))[::-1]
    assert np.allclose(np.abs(cycle.multipliers), expected, atol=1e-4)
    assert abs(abs(cycle.multipliers[0]) - 1.0) < 1e-4 and cycle.stable


@pytest.mark.slow
def test_a_long_independent_run_settles_on_the_period(cycle):
    rhs = equations(0.9 * K_C)
    start = [cycle.x0[0] * 1.001, cycle.v0[0], DC * math.exp(cycle.psi0[0][0]) / V0]
    t_end = 40 * cycle.period
    sol = solve_ivp(rhs, (0.0, t_end), start, method="LSODA", rtol=1e-11, atol=[1e-18, 1e-20, 1e-16],
                    dense_output=True)
    t = np.linspace(30 * cycle.period, t_end, 200001)
    r = np.log((V - sol.sol(t)[1]) / V)
    up = np.nonzero((r[:-1] < 0) & (r[1:] >= 0))[0]
    crossings = t[up] - r[up] * (t[up + 1] - t[up]) / (r[up + 1] - r[up])
    assert np.diff(crossings)[-3:] == pytest.approx(np.full(3, cycle.period), rel=1e-5)


@pytest.mark.slow
def test_the_amplitude_is_half_the_swing_of_the_independent_integration(cycle):
    """Half the peak-to-peak displacement over one period of the LSODA integration in theta
    (20001 samples: the extremes sampled within (T/20000)^2 of the curvature, far below 1e-6)."""
    rhs = equations(0.9 * K_C)
    y0 = np.array([cycle.x0[0], cycle.v0[0], DC * math.exp(cycle.psi0[0][0]) / V0])
    sol = solve_ivp(rhs, (0.0, cycle.period), y0, method="LSODA", rtol=1e-12, atol=[1e-18, 1e-20, 1e-16],
                    dense_output=True)
    x = sol.sol(np.linspace(0.0, cycle.period, 20001))[0]
    assert cycle.amplitude[0] == pytest.approx(0.5 * np.ptp(x), rel=1e-4)


@pytest.mark.slow
def test_the_cycle_follows_the_rules_of_results(cycle):
    from ..cf_rules import problems
    assert problems(cycle.to_xarray(), "rate-state cycle") == []
    assert cycle.to_dict()["period"] == cycle.period


def test_stable_steady_sliding_has_no_cycle_to_settle_on():
    with pytest.raises(NoSolutionError, match="settled|no cycle"):
        rate_state_cycle(block(1.2), transient=2000.0)


@pytest.mark.slow
def test_a_relaxation_cycle_whose_sampled_bursts_wander_is_not_taken_for_a_decay(monkeypatch):
    """The slip-law block of examples/rate_state/one_block.toml at 0.93 k_c: its slip bursts are sharp and
    their sampled heights wander by 0.2 % a period, which was refused as a decay toward steady sliding
    (three shrinking swings in a row, 0.1 % each allowed). Its cycle is stable (multiplier 0.26)."""
    from pathlib import Path

    from stickslip.system.config import read_table, system_from_dict
    monkeypatch.chdir(Path(__file__).resolve().parents[2])
    data = read_table("examples/rate_state/one_block.toml")
    data["stiffness"] = [[4652.8125]]
    relaxation = rate_state_cycle(system_from_dict(data))
    assert relaxation.stable
