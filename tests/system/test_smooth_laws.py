"""Systems whose laws are not affine in the slip speed (Stribeck, a user's function), no rate-and-state
contact: they move by `rate_state_simulate` (between the switches compiled DOP853 where the laws
compile, else Radau; the switches as events). Both paths checked against an integration written out
here (the stuck block's coordinate eliminated, LSODA with its own event location, the laws' formulas
written again), and the cycle against it too."""

import json
import math
from fractions import Fraction
from pathlib import Path

import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings, strategies as st

from stickslip.cli import run as cli
from stickslip.errors import NoSolutionError, ParameterError
from stickslip.friction import LinearWeakening, Stribeck, UserLaw
from stickslip.system import (Contact, Harmonic, System, continue_system, integrated, limit_cycle, rate_state_cycle,
                              rate_state_simulate, simulate, system_from_dict)

from stickslip.system.rate_state import RateStateEquations
from stickslip.system.rate_state_modes import mode_events
from stickslip.system.smoothkernel import Compiled, Failed, compiled_laws

from .pair_reference import stick_slip_pair
from ..budget import examples

N, FS, FD, VS = 10.0, 0.6, 0.4, 0.05
M1, M2, K1, K2, KC, C1, V1, V2 = 1.0, 0.5, 2e3, 1e3, 300.0, 2.0, 2.0, 0.05


def _mu1(v):  # the user's law of block 1 (on a fast belt: it never sticks), written again below
    return 0.3 + 0.2 / (1.0 + 4.0 * abs(v))


#: Harmonic forces F1 cos(W1 t) on block 1 and F2 sin(W1 t) on block 2 (N, rad/s) for the forced runs,
#: written again in the reference.
F1, F2, W1 = 3.0, 0.5, 40.0


def _pair(belt=V2, forced=False, linear=False):
    K = [[K1 + KC, -KC], [-KC, K2 + KC]]
    harmonics = [Harmonic(W1, cos=[F1, 0.0], sin=[0.0, F2])] if forced else ()
    law1 = LinearWeakening(0.5, 0.5, 0.2) if linear else UserLaw(_mu1, fs=0.5)  # (affine: 0.5 (1 - 0.2 |v|))
    return System(mass=np.diag([M1, M2]), stiffness=K, damping=np.diag([C1, 0.0]), harmonics=harmonics, contacts=[
        Contact([1.0, 0.0], N, law1, surface_speed=V1),
        Contact([0.0, 1.0], N, Stribeck(FS, FD, VS), surface_speed=belt)])


def _law1(v, linear):  # block 1's law written again
    return 0.5 * (1.0 - 0.2 * abs(v)) if linear else 0.3 + 0.2 / (1.0 + 4.0 * abs(v))


def _reference(t_eval, x0, v0, belt=V2, forced=False, linear=False):
    """The pair written out apart: block 2 slipping (s = +-1) with s N (fd + (fs - fd) exp(-|v|/vs)), or
    stuck (x2 = x2s + belt (t - ts), eliminated) while its springs' force stays within fs N."""
    def slipping(t, y, s):
        x1, x2, u1, u2 = y
        f1 = N * _law1(V1 - u1, linear) + forced * F1 * math.cos(W1 * t)
        f2 = s * N * (FD + (FS - FD) * math.exp(-abs(belt - u2) / VS)) + forced * F2 * math.sin(W1 * t)
        return [u1, u2, (-(K1 + KC) * x1 + KC * x2 - C1 * u1 + f1) / M1, (KC * x1 - (K2 + KC) * x2 + f2) / M2]

    def stuck(t, y, x2s, ts):
        x1, u1 = y
        x2 = x2s + belt * (t - ts)
        f1 = N * _law1(V1 - u1, linear) + forced * F1 * math.cos(W1 * t)
        return [u1, (-(K1 + KC) * x1 + KC * x2 - C1 * u1 + f1) / M1]

    def hold(t, y, x2s, ts):  # the friction force that keeps block 2 on its belt
        return -(KC * y[0] - (K2 + KC) * (x2s + belt * (t - ts)) + forced * F2 * math.sin(W1 * t))

    return stick_slip_pair(t_eval, [x0[0], x0[1], v0[0], v0[1]], slipping, stuck, hold, belt, FS * N)


@pytest.mark.parametrize("method", ["compiled", "radau"])
@pytest.mark.parametrize("x2, v2, forced, linear", [(0.0, 0.0, False, False), (0.004, 0.0, False, False),
                                                    (0.0, 4.0 * V2, False, False), (-0.003, -0.2, False, False),
                                                    (0.004, 0.0, True, False), (0.004, 0.0, False, True)])
def test_the_pair_with_a_user_law_and_a_stribeck_law_follows_an_integration_written_apart(x2, v2, forced, linear,
                                                                                         method):
    system = _pair(forced=forced, linear=linear)
    assert integrated(system)
    x0, v0 = [N * _mu1(V1) / (K1 + KC), x2], [0.0, v2]
    # Radau in Python costs 3 s a simulated second: a third of the run, five switches or more, every kind met
    t_end = 1.5 if method == "compiled" else 0.5
    run = rate_state_simulate(system, x0=x0, v0=v0, t_end=t_end, samples=int(1000 * t_end) + 1, method=method)
    ref, events = _reference(run.t, x0, v0, forced=forced, linear=linear)
    assert np.all(np.abs(run.x - ref).max(axis=0) < 1e-7 * np.ptp(ref, axis=0))
    assert len(events) >= 4 and [s for _, s in events] == list(run.event_state)
    assert run.event_time == pytest.approx([t for t, _ in events], abs=1e-9)
    assert run.psi.shape == (run.t.size, 2, 0)
    slipping = run.states[:, 1] != 0
    assert run.friction_force[slipping, 1] == pytest.approx(run.states[slipping, 1] * N * (
        FD + (FS - FD) * np.exp(-np.abs(run.slip_rate[slipping, 1]) / VS)), rel=1e-12)
    held = -(KC * run.x[~slipping, 0] - (K2 + KC) * run.x[~slipping, 1] + forced * F2 * np.sin(W1 * run.t[~slipping]))
    assert np.sum(~slipping) > 10 and run.friction_force[~slipping, 1] == pytest.approx(held, rel=1e-9, abs=1e-9 * N)


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


@settings(max_examples=examples(40), suppress_health_check=[HealthCheck.function_scoped_fixture])
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


def _blocky(v):  # numba cannot compile it (a Fraction): its runs stay with Radau
    return float(Fraction(3, 10)) + 0.2 / (1.0 + 4.0 * abs(v))


def _runaway(v):  # no value beyond a slip speed of 1 m/s (a NaN): the compiled run stops, Radau says why
    return 0.3 + 0.2 / (1.0 + 4.0 * abs(v)) + (math.nan if abs(v) > 1.0 else 0.0)


def _sticky(v):  # beyond 1 m/s of slip rising steeply, out of the declared range [0, 10] from 1.19 m/s
    return 0.3 + 0.2 / (1.0 + 4.0 * abs(v)) + 50.0 * max(abs(v) - 1.0, 0.0)


def test_laws_the_compiled_flows_cannot_take_run_with_radau_and_a_method_out_of_its_list_is_named():
    for method in ("fast", "", None, 1, np.array(["auto", "radau"]), ["auto"]):
        with pytest.raises(ParameterError) as err:
            rate_state_simulate(_pair(), t_end=0.1, method=method)
        assert err.value.name == "method" and "auto, compiled, radau" in str(err.value)
    blocky = System(mass=np.diag([M1, M2]), stiffness=[[K1 + KC, -KC], [-KC, K2 + KC]], damping=np.diag([C1, 0.0]),
                    contacts=[Contact([1.0, 0.0], N, UserLaw(_blocky, fs=0.5), surface_speed=V1),
                              Contact([0.0, 1.0], N, Stribeck(FS, FD, VS), surface_speed=V2)])
    with pytest.raises(ParameterError) as err:
        rate_state_simulate(blocky, t_end=0.1, method="compiled")
    assert err.value.name == "method" and "radau" in str(err.value)
    x0 = [N * _mu1(V1) / (K1 + KC), 0.004]
    auto = rate_state_simulate(blocky, x0=x0, t_end=0.3, samples=301)  # Radau, with the same law as _mu1
    ref, _ = _reference(auto.t, x0, [0.0, 0.0])
    assert np.all(np.abs(auto.x - ref).max(axis=0) < 1e-7 * np.ptp(ref, axis=0))
    for law, value in ((_runaway, "= nan"), (_sticky, "[0, 10]")):
        runaway = System(mass=np.diag([M1, M2]), stiffness=[[K1 + KC, -KC], [-KC, K2 + KC]],
                         damping=np.diag([C1, 0.0]), contacts=[
                             Contact([1.0, 0.0], N, UserLaw(law, fs=0.5), surface_speed=0.5),
                             Contact([0.0, 1.0], N, Stribeck(FS, FD, VS), surface_speed=V2)])
        with pytest.raises(ParameterError) as err:  # pushed beyond 1 m/s of slip: said by the Radau run
            rate_state_simulate(runaway, x0=[0.0, 0.0], v0=[-2.0, 0.0], t_end=0.3, method="compiled")
        assert err.value.name == "mu(v_r)" and value in str(err.value)


def test_the_compiled_flow_stops_at_a_coefficient_out_of_range_between_the_samples():
    """The compiled run samples the laws only where it is sampled (`sampled`, in Python): a coefficient out
    of the declared range met between two samples has to stop the compiled flow itself."""
    system = System(mass=np.diag([M1, M2]), stiffness=[[K1 + KC, -KC], [-KC, K2 + KC]], damping=np.diag([C1, 0.0]),
                    contacts=[Contact([1.0, 0.0], N, UserLaw(_sticky, fs=0.5), surface_speed=0.5),
                              Contact([0.0, 1.0], N, Stribeck(FS, FD, VS), surface_speed=V2)])
    eq = RateStateEquations(system)
    flows = Compiled(eq, compiled_laws(eq))
    eq.set_mode((-1, 1))
    y = np.array([0.0, 0.0, 0.9, 0.0])  # slipping backward at 0.4 m/s, pushed toward 1.0 m/s by its spring
    assert flows.solve(0.0, 1e-4, y, np.array([0.0]), 1e-10, mode_events(eq)).status == 0  # below 1 m/s: runs
    with pytest.raises(Failed):
        flows.solve(0.0, 0.5, y + np.array([-0.2, 0.0, 0.0, 0.0]), np.array([0.0]), 1e-10, mode_events(eq))


def _law_a(v):
    return 0.35 + 0.1 * math.exp(-abs(v) / 0.02)


def _law_b(v):
    return 0.3 + 0.15 / (1.0 + 10.0 * abs(v))


def _law_c(v):
    return 0.32 + 0.1 / (1.0 + abs(v) / 0.05) ** 2


@pytest.mark.slow  # the law slots' compiled code (its first compilation takes 10 s of a fresh clone's test run)
def test_four_contacts_under_four_laws_compiled_agree_with_radau_consistency():
    """A consistency check of the compiled path's law slots (each contact's law its own function; the
    Radau path calls the laws themselves): four blocks in a chain, three users' laws and Stribeck's."""
    K = 2e3 * np.eye(4) + 1e3 * (np.eye(4, k=1) + np.eye(4, k=-1) - np.diag([0.0, 1.0, 1.0, 0.0]))
    laws = [UserLaw(_law_a, fs=0.5), UserLaw(_law_b, fs=0.5), UserLaw(_law_c, fs=0.5), Stribeck(0.5, 0.35, 0.03)]
    system = System(mass=0.4 * np.eye(4), stiffness=K, damping=0.5 * np.eye(4),
                    harmonics=[Harmonic(30.0, sin=[0, 0, 0, 2.0])],
                    contacts=[Contact(np.eye(4)[i], 20.0, laws[i], surface_speed=0.1) for i in range(4)])
    x0 = [0.002, 0.0, -0.002, 0.001]
    fast = rate_state_simulate(system, x0, t_end=1.0, samples=101, method="compiled")
    slow = rate_state_simulate(system, x0, t_end=1.0, samples=101, method="radau")
    assert fast.event_time.size == slow.event_time.size >= 8 and set(fast.event_contact) == {0, 1, 2, 3}
    assert np.abs(fast.x - slow.x).max() < 1e-7 * np.ptp(slow.x)
    assert fast.event_time == pytest.approx(slow.event_time, abs=1e-8)
