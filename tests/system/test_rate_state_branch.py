"""Limit cycles of rate-and-state systems followed along a parameter (`stickslip.system.rate_state_branch`),
against the Hopf point of steady sliding: the closed-form critical stiffness and frequency, and the
criticality the first Lyapunov coefficient of the spring-slider gives (`stickslip.rsf.hopf`, its normal
form: computed apart from these shooting runs)."""

import math

import numpy as np
import pytest

from stickslip.errors import ParameterError
from stickslip.friction import Coulomb
from stickslip.rsf import RateState, SpringSlider
from stickslip.rsf.hopf import hopf_criticality
from stickslip.system import Contact, System, continue_system

N, V, A, B, DC = 10.0, 1e-6, 0.01, 0.015, 1e-5
LAW = RateState(a=A, b=B, dc=DC)  # aging


def _kc(mass):
    return N * (B - A) / DC * (1 + mass * V ** 2 / (N * A * DC))


def _block(mass):
    return lambda k: System([[mass]], [[k]], [Contact([1.0], N, LAW, surface_speed=V)])


@pytest.mark.slow
def test_a_supercritical_hopf_point_grows_stable_cycles_as_the_square_root_of_the_distance():
    """With inertia m = 1e6 kg the normal form says supercritical (l1 < 0): below k_c the cycles are stable,
    their amplitude ~ (k_c - k)^(1/2) and their period tends to the Hopf period 2 pi / w,
    w = V / D_c sqrt((b - a) / a)."""
    mass = 1e6
    assert hopf_criticality(SpringSlider(LAW, normal_stress=N, stiffness=1.0, mass=mass), V).criticality == \
        "supercritical"
    kc = _kc(mass)
    branch = continue_system(_block(mass), 0.97 * kc, 0.9995 * kc, points=6, parameter="stiffness[0][0]")
    assert branch.stopped.startswith("reached") and branch.values.size == 6 and np.all(branch.stable)
    distance, amplitude = kc - branch.values, branch.amplitude[:, 0]
    order = math.log(amplitude[0] / amplitude[-1]) / math.log(distance[0] / distance[-1])
    assert 0.45 <= order <= 0.55, order
    hopf_period = 2 * math.pi / (V / DC * math.sqrt((B - A) / A))
    assert branch.period[-1] == pytest.approx(hopf_period, rel=2e-3)
    assert np.all(np.diff(branch.period) < 0)  # toward it


@pytest.mark.slow
@pytest.mark.deep  # 6 minutes (Radau runs of every cycle along the branch): make test-deep
def test_a_subcritical_hopf_point_has_stable_cycles_beyond_it_up_to_a_fold():
    """With m = 1e5 kg the normal form says subcritical (l1 > 0): the stable cycle of k < k_c persists
    where steady sliding is stable too (k >= k_c, finite amplitude), up to a fold of cycles just beyond,
    where its leading multiplier tends to 1 and the branch ends (next to the fold Newton's method may
    land on either of the two cycles that meet there: the stable one, or the unstable one born at k_c)."""
    mass = 1e5
    assert hopf_criticality(SpringSlider(LAW, normal_stress=N, stiffness=1.0, mass=mass), V).criticality == \
        "subcritical"
    kc = _kc(mass)
    branch = continue_system(_block(mass), 0.95 * kc, 1.05 * kc, points=5, parameter="stiffness[0][0]")
    assert branch.stopped.startswith("no cycle beyond") and kc < branch.values[-1] < 1.05 * kc
    at = int(np.argmin(np.abs(branch.values - kc)))  # the value k_c itself
    assert branch.values[at] == pytest.approx(kc, rel=1e-12) and np.all(branch.stable[:at + 1])
    assert branch.amplitude[at, 0] > 0.25 * branch.amplitude[0, 0]
    assert branch.multipliers[-1, 0] > branch.multipliers[0, 0]  # (its leading multiplier heads for 1)
    assert branch.to_xarray()["psi0"].shape == (branch.values.size, 1)


def test_what_a_rate_and_state_branch_cannot_take_is_refused_naming_it():
    mass = 1e6
    with pytest.raises(ParameterError, match="periods = 2.*rate-and-state"):
        continue_system(_block(mass), 5000.0, 6000.0, points=3, periods=2)
    with pytest.raises(ParameterError, match="build"):
        continue_system(lambda k: None, 5000.0, 6000.0, points=3)
    coulomb = lambda k: System([[1.0]], [[k]], [Contact([1.0], N, Coulomb(0.6, 0.4), surface_speed=V)])  # noqa: E731
    with pytest.raises(ParameterError, match="psi0"):
        continue_system(coulomb, 100.0, 200.0, points=3, psi0=[[0.1]])



@pytest.mark.slow
@pytest.mark.deep  # 3.5 minutes: make test-deep
def test_a_relaxation_cycle_is_followed_where_newton_alone_stalls(capsys, monkeypatch):
    """The slip-law block of examples/rate_state/one_block.toml (a cycle of sharp slip bursts): from 0.9
    k_c, Newton's method from the cycle before stalls (its return misses by 6e-4 at 0.937 k_c); the
    branch lets the motion settle there and goes on. Its cycle at the end is the one a transient
    settles on at that stiffness (a consistency check of two paths of ours)."""
    import json
    from pathlib import Path

    from stickslip.cli import run
    from stickslip.system import rate_state_cycle
    from stickslip.system.config import read_table, system_from_dict

    monkeypatch.chdir(Path(__file__).resolve().parents[2])
    file = "examples/rate_state/one_block.toml"
    code = run(["system", "continue", file, "--parameter", "stiffness[0][0]", "--stop", "4900", "--points", "3",
                "--json"])
    assert code == 0
    branch = json.loads(capsys.readouterr().out)
    assert branch["stopped"].startswith("reached") and branch["values"] == [4504.5, 4702.25, 4900.0]
    data = read_table(file)
    data["stiffness"] = [[4900.0]]
    assert branch["period"][-1] == pytest.approx(rate_state_cycle(system_from_dict(data)).period, rel=1e-6)
