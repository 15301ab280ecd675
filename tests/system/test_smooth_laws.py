"""Systems whose laws are not affine in the slip speed (Stribeck, a user's function), no rate-and-state
contact: they move by `rate_state_simulate` (Radau between the switches, the switches as events).
Checked against an integration written out here (the stuck block's coordinate eliminated, LSODA with
its own event location, the laws' formulas written again), and the cycle against it too."""

import json
import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from stickslip.cli import run as cli
from stickslip.errors import NoSolutionError, ParameterError
from stickslip.friction import Stribeck, UserLaw
from stickslip.system import (Contact, System, continue_system, integrated, limit_cycle, rate_state_cycle,
                              rate_state_simulate, simulate, system_from_dict)

from .pair_reference import stick_slip_pair

N, FS, FD, VS = 10.0, 0.6, 0.4, 0.05
M1, M2, K1, K2, KC, C1, V1, V2 = 1.0, 0.5, 2e3, 1e3, 300.0, 2.0, 2.0, 0.05


def _mu1(v):  # the user's law of block 1 (on a fast belt: it never sticks), written again below
    return 0.3 + 0.2 / (1.0 + 4.0 * abs(v))


def _pair(belt=V2):
    K = [[K1 + KC, -KC], [-KC, K2 + KC]]
    return System(mass=np.diag([M1, M2]), stiffness=K, damping=np.diag([C1, 0.0]), contacts=[
        Contact([1.0, 0.0], N, UserLaw(_mu1, fs=0.5), surface_speed=V1),
        Contact([0.0, 1.0], N, Stribeck(FS, FD, VS), surface_speed=belt)])


def _reference(t_eval, x0, v0, belt=V2):
    """The pair written out apart: block 2 slipping (s = +-1) with s N (fd + (fs - fd) exp(-|v|/vs)), or
    stuck (x2 = x2s + belt (t - ts), eliminated) while its springs' force stays within fs N."""
    def slipping(t, y, s):
        x1, x2, u1, u2 = y
        f1 = N * (0.3 + 0.2 / (1.0 + 4.0 * abs(V1 - u1)))
        f2 = s * N * (FD + (FS - FD) * math.exp(-abs(belt - u2) / VS))
        return [u1, u2, (-(K1 + KC) * x1 + KC * x2 - C1 * u1 + f1) / M1, (KC * x1 - (K2 + KC) * x2 + f2) / M2]

    def stuck(t, y, x2s, ts):
        x1, u1 = y
        x2 = x2s + belt * (t - ts)
        return [u1, (-(K1 + KC) * x1 + KC * x2 - C1 * u1 + N * (0.3 + 0.2 / (1.0 + 4.0 * abs(V1 - u1)))) / M1]

    def hold(t, y, x2s, ts):  # the friction force that keeps block 2 on its belt
        return -(KC * y[0] - (K2 + KC) * (x2s + belt * (t - ts)))

    return stick_slip_pair(t_eval, [x0[0], x0[1], v0[0], v0[1]], slipping, stuck, hold, belt, FS * N)


@pytest.mark.parametrize("x2, v2", [(0.0, 0.0), (0.004, 0.0), (0.0, 4.0 * V2), (-0.003, -0.2)])
def test_the_pair_with_a_user_law_and_a_stribeck_law_follows_an_integration_written_apart(x2, v2):
    system = _pair()
    assert integrated(system)
    x0, v0 = [N * _mu1(V1) / (K1 + KC), x2], [0.0, v2]
    run = rate_state_simulate(system, x0=x0, v0=v0, t_end=1.5, samples=1501)
    ref, events = _reference(run.t, x0, v0)
    assert np.all(np.abs(run.x - ref).max(axis=0) < 1e-7 * np.ptp(ref, axis=0))
    assert len(events) >= 4 and [s for _, s in events] == list(run.event_state)
    assert run.event_time == pytest.approx([t for t, _ in events], abs=1e-9)
    assert run.psi.shape == (1501, 2, 0)
    slipping = run.states[:, 1] != 0
    assert run.friction_force[slipping, 1] == pytest.approx(run.states[slipping, 1] * N * (
        FD + (FS - FD) * np.exp(-np.abs(run.slip_rate[slipping, 1]) / VS)), rel=1e-12)


def test_the_pairs_cycle_closes_under_the_integration_written_apart():
    system = _pair()
    cycle = rate_state_cycle(system, x0=[N * _mu1(V1) / (K1 + KC), 0.0], transient=3.0)
    assert cycle.psi0 == ()
    t = np.linspace(0.0, cycle.period, 2001)
    ref, events = _reference(t, cycle.x0, cycle.v0)
    assert np.abs(ref[-1] - cycle.x0).max() < 1e-6 * np.ptp(ref, axis=0).max()
    assert any(s == 0 for _, s in events)  # a stick-slip cycle
    assert abs(cycle.multipliers - 1.0).min() < 1e-4  # the flow's own


def test_the_exact_path_points_to_the_integrated_one_and_the_command_line_takes_the_example(capsys):
    with pytest.raises(ParameterError) as err:
        simulate(_pair(), t_end=1.0)
    assert err.value.name == "contacts[0].friction" and "rate_state_simulate" in str(err.value)
    with pytest.raises(ParameterError):
        limit_cycle(_pair())
    file = Path(__file__).resolve().parents[2] / "examples" / "stribeck" / "two_blocks.toml"
    assert cli(["system", "simulate", str(file), "--t-end", "0.5", "--x0", "0.0,0.001", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["events"] >= 2 and all(math.isfinite(v) for v in out["x_end"])
    assert cli(["system", "cycle", str(file), "--transient", "3", "--x0", "0.0017,0", "--json"]) == 0
    cycle = json.loads(capsys.readouterr().out)
    assert cycle["stable"] and 0.1 < cycle["period"] < 0.3 and cycle["slip_rate_min"][1] == 0.0  # stick-slip
    assert cli(["system", "simulate", str(file), "--t-end", "0.5", "--psi0", "[1.0]"]) == 2
    assert "--psi0" in capsys.readouterr().err


def test_the_pairs_cycle_followed_along_its_belt_speed_closes_under_the_integration_written_apart():
    branch = continue_system(_pair, V2, 1.2 * V2, points=3, x0=[N * _mu1(V1) / (K1 + KC), 0.0], transient=3.0)
    assert branch.stopped.startswith("reached stop") and len(branch.values) == 3
    x0, v0 = branch.x0[-1], branch.v0[-1]
    t = np.linspace(0.0, branch.period[-1], 2001)
    ref, _ = _reference(t, x0, v0, belt=1.2 * V2)
    assert np.abs(ref[-1] - x0).max() < 1e-6 * np.ptp(ref, axis=0).max()


@settings(max_examples=40, deadline=None, suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(vs=st.one_of(st.floats(allow_nan=True, allow_infinity=True),
                    st.sampled_from([0.0, 5e-324, 1e-300, 1e-12, 1e-9, 1e4, 1e300, -0.05, "0.05", True, None, [0.05]])),
       fs=st.sampled_from([0.6, 0.4, 10.0]))
def test_a_stribeck_speed_from_its_range_its_edges_and_beyond_runs_or_is_named(vs, fs):
    contact = {"direction": [0.0, 1.0], "normal_force": N, "law": "stribeck", "fs": fs, "fd": min(fs, FD),
               "surface_speed": V2}
    if vs is not None:
        contact["vs"] = vs
    data = {"mass": [[M1, 0.0], [0.0, M2]], "stiffness": [[K1 + KC, -KC], [-KC, K2 + KC]],
            "contact": [{"direction": [1.0, 0.0], "normal_force": N, "fs": 0.4, "fd": 0.4, "surface_speed": V1},
                        contact]}
    declared = (isinstance(vs, (int, float)) and not isinstance(vs, bool) and math.isfinite(vs)
                and 1e-9 <= vs <= 1e4)  # the declared range of vs, written here
    try:
        system = system_from_dict(data)
    except ParameterError as err:
        assert not declared and err.name == "contact[1].vs" and "vs" in str(err)
        return
    assert declared
    try:
        run = rate_state_simulate(system, x0=[0.0, 0.002], t_end=0.05, samples=11)
    except NoSolutionError as err:  # said, not crashed
        assert str(err)
        return
    assert np.all(np.isfinite(run.x)) and np.all(np.isfinite(run.friction_force))
