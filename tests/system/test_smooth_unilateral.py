"""Unilateral contacts (a normal spring: ``N(x) = N_0 - k_n n . x``) under laws of the slip speed: a
block whose tangential and normal motions are coupled by the structure, on a belt, under Stribeck's
law. They move by `rate_state_simulate` (compiled and Radau); checked against integrations written
out here (LSODA with its own events; the stuck coordinate eliminated; the formulas written again):
stick-slip with a normal force that follows the motion, a block that leaves its belt and lands again,
and steady sliding against the Jacobian of the written-out equations by central differences."""

import json
import math
from pathlib import Path

import numpy as np
import pytest
from scipy.integrate import solve_ivp
from scipy.optimize import fsolve

from stickslip.cli import run as cli
from stickslip.errors import NoSolutionError, ParameterError
from stickslip.friction import Coulomb, LinearWeakening, Stribeck
from stickslip.system import (Contact, System, integrated, rate_state_cycle, rate_state_simulate, rate_state_steady,
                              simulate, steady_sliding)

from .pair_reference import stick_slip_pair

M, KX, KZ, KXZ, CX, CZ = 1.0, 1000.0, 2000.0, 800.0, 1.0, 2.0
N0, KN, FS, FD, VS = 20.0, 1000.0, 0.6, 0.4, 0.05


def _block(belt, law=None, pushes=True):
    law = law or Stribeck(FS, FD, VS)
    return System(mass=M * np.eye(2), stiffness=[[KX, KXZ], [KXZ, KZ]], damping=np.diag([CX, CZ]), contacts=[
        Contact([1.0, 0.0], N0, law, surface_speed=belt, normal_direction=[0.0, 1.0], normal_stiffness=KN,
                normal_on_structure=pushes)])


def _mu(v):  # Stribeck's law written again
    return FD + (FS - FD) * math.exp(-abs(v) / VS)


def _slipping_rhs(belt):
    """``y = (z, x, w, u)`` (the normal coordinate first: the pair reference's block 1)."""
    def rhs(t, y, s):
        z, x, w, u = y
        normal = max(N0 - KN * z, 0.0)
        return [w, u, (-KXZ * x - KZ * z - CZ * w + normal) / M,
                (-KX * x - KXZ * z - CX * u + s * normal * _mu(belt - u)) / M]
    return rhs


def _reference(t_eval, x0, v0, belt):
    def stuck(t, y, xs, ts):
        z, w = y
        x = xs + belt * (t - ts)
        return [w, (-KXZ * x - KZ * z - CZ * w + N0 - KN * z) / M]

    def hold(t, y, xs, ts):  # the friction force that keeps u = belt
        return KX * (xs + belt * (t - ts)) + KXZ * y[0] + CX * belt

    def limit(t, y, xs, ts):
        return FS * (N0 - KN * y[0])

    out, events = stick_slip_pair(t_eval, [x0[1], x0[0], v0[1], v0[0]], _slipping_rhs(belt), stuck, hold, belt, limit)
    return out[:, ::-1], events  # (x, z)


@pytest.mark.parametrize("method", ["compiled", "radau"])
@pytest.mark.parametrize("x0", [[0.0, 0.006], [0.02, 0.0]])
def test_stick_slip_under_a_normal_force_that_follows_the_motion_follows_an_integration_written_apart(method, x0):
    system = _block(0.05)
    assert integrated(system)
    run = rate_state_simulate(system, x0=x0, t_end=1.0, samples=1001, method=method)
    ref, events = _reference(run.t, x0, [0.0, 0.0], 0.05)
    assert np.all(np.abs(run.x - ref).max(axis=0) < 1e-7 * np.ptp(ref, axis=0))
    assert len(events) >= 4 and [s for _, s in events] == list(run.event_state)
    assert run.event_time == pytest.approx([t for t, _ in events], abs=1e-9)
    normal = N0 - KN * run.x[:, 1]
    assert np.ptp(normal) > 0.1 * normal.mean()  # the normal force does follow the motion
    slipping = run.states[:, 0] != 0
    mu = FD + (FS - FD) * np.exp(-np.abs(run.slip_rate[slipping, 0]) / VS)
    assert run.friction_force[slipping, 0] == pytest.approx(run.states[slipping, 0] * normal[slipping] * mu, rel=1e-12)
    assert np.all(np.abs(run.friction_force[~slipping, 0]) <= FS * normal[~slipping] * (1 + 1e-9))


def _lifting_reference(t_eval, x0, v0, belt):
    """On a fast belt (it never sticks): the normal force ``max(N0 - kn z, 0)`` is continuous, the
    motion integrated in pieces between its zeros (LSODA, events at ``N = 0``)."""
    rhs = _slipping_rhs(belt)
    edge = lambda t, y, s: N0 - KN * y[0]  # noqa: E731
    edge.terminal = True
    t, y, out, crossings = 0.0, [x0[1], x0[0], v0[1], v0[0]], np.full((t_eval.size, 2), np.nan), []
    while True:
        sel = t_eval >= t
        sol = solve_ivp(rhs, (t, t_eval[-1]), y, t_eval=t_eval[sel], events=edge, args=(1,), method="LSODA",
                        rtol=1e-12, atol=1e-16)
        out[np.flatnonzero(sel)[:sol.t.size]] = sol.y[1::-1].T
        if sol.status == 0:
            return out, crossings
        t, y = sol.t_events[0][0], sol.y_events[0][0].copy()
        crossings.append(t)
        y[0] = (N0 / KN) * (1 + 1e-15 * (1 if y[2] > 0 else -1))  # past the edge, the way it moves


@pytest.mark.parametrize("method", ["compiled", "radau"])
def test_a_block_that_leaves_its_belt_and_lands_again_follows_an_integration_written_apart(method):
    system = _block(1.0)
    x0, v0 = [0.0, 0.03], [0.0, 0.0]  # lifted off its belt (N0 - kn z = -10 N): open, then falls back
    run = rate_state_simulate(system, x0=x0, v0=v0, t_end=0.6, samples=601, method=method)
    ref, crossings = _lifting_reference(run.t, x0, v0, 1.0)
    assert len(crossings) >= 4  # it leaves and lands again, more than once
    assert np.all(np.abs(run.x - ref).max(axis=0) < 1e-7 * np.ptp(ref, axis=0))
    assert run.event_time == pytest.approx(crossings, abs=1e-9)
    assert list(run.event_state) == [1 if k % 2 == 0 else 2 for k in range(len(crossings))]  # lands, leaves, ...
    open_ = run.states[:, 0] == 2
    assert open_.any() and np.all(run.friction_force[open_, 0] == 0.0)
    assert np.all((N0 - KN * run.x[open_, 1]) <= 1e-9 * N0)


def test_steady_sliding_on_a_unilateral_stribeck_contact_against_the_written_out_equations():
    belt = 0.08
    rhs = _slipping_rhs(belt)
    rest = fsolve(lambda q: rhs(0.0, [q[1], q[0], 0.0, belt * 0.0], 1)[2:], [0.0, 0.0], xtol=1e-14)  # (x, z)
    y0 = np.array([rest[1], rest[0], 0.0, 0.0])
    jac = np.empty((4, 4))
    for j in range(4):
        h = 1e-6 * max(1.0, abs(y0[j]))
        e = np.zeros(4)
        e[j] = h
        jac[:, j] = (np.array(rhs(0.0, y0 + e, 1)) - np.array(rhs(0.0, y0 - e, 1))) / (2 * h)
    want = np.sort_complex(np.linalg.eigvals(jac))
    for steady in (steady_sliding(_block(belt)), rate_state_steady(_block(belt))):
        assert steady.x == pytest.approx(rest, rel=1e-10)
        assert np.sort_complex(steady.eigenvalues) == pytest.approx(want, rel=1e-6)
    assert steady_sliding(_block(belt)).friction_force[0] == pytest.approx((N0 - KN * rest[1]) * _mu(belt), rel=1e-12)


def test_the_cycle_of_the_block_with_a_normal_force_that_follows_it_closes_under_the_integration_written_apart():
    cycle = rate_state_cycle(_block(0.05), x0=[0.0, 0.006], transient=3.0)
    t = np.linspace(0.0, cycle.period, 2001)
    ref, events = _reference(t, cycle.x0, cycle.v0, 0.05)
    assert any(s == 0 for _, s in events)
    assert np.abs(ref[-1] - cycle.x0).max() < 1e-6 * np.ptp(ref, axis=0).max()


def test_what_the_unilateral_contacts_under_laws_of_the_slip_speed_do_not_take_is_named():
    with pytest.raises(ParameterError) as err:  # the exact flows: Coulomb only on a unilateral contact
        simulate(_block(0.05, LinearWeakening(0.6, 0.5, 0.2)), t_end=0.1)
    assert err.value.name == "contacts[0].friction" and "rate_state_simulate" in str(err.value)
    run = rate_state_simulate(_block(0.05, LinearWeakening(0.6, 0.5, 0.2)), x0=[0.0, 0.006], t_end=0.2)
    assert np.all(np.isfinite(run.x))
    rigid = Contact([0.0, 1.0], None, Coulomb(0.5, 0.4), normal_direction=[1.0, 0.0], rigid=True)
    system = System(mass=np.eye(2), stiffness=np.eye(2) * 1e3, contacts=[_block(0.05).contacts[0], rigid])
    with pytest.raises(ParameterError) as err:
        rate_state_simulate(system, t_end=0.1)
    assert err.value.name == "contacts[1].rigid"
    with pytest.raises(NoSolutionError, match="normal_on_structure"):  # an eliminated constraint letting go
        rate_state_simulate(_block(1.0, pushes=False), x0=[0.0, 0.0], v0=[0.0, 2.0], t_end=0.5)


def test_the_command_line_takes_the_pressed_block_example(capsys):
    file = Path(__file__).resolve().parents[2] / "examples" / "stribeck" / "pressed_block.toml"
    assert cli(["system", "simulate", str(file), "--t-end", "0.5", "--x0", "0,0.006", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["events"] >= 2 and all(math.isfinite(v) for v in out["x_end"])
    assert cli(["system", "cycle", str(file), "--transient", "3", "--x0", "0,0.006", "--json"]) == 0
    cycle = json.loads(capsys.readouterr().out)
    assert cycle["slip_rate_min"][0] == 0.0 and all(math.isfinite(m) for m in cycle["multipliers_abs"])  # stick-slip
    assert cli(["system", "stability", str(file), "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["stable"] is False  # Stribeck's falling law: steady sliding unstable


@pytest.mark.parametrize("lift", [0.030, 0.031, 0.032, 0.034])
def test_a_block_dropped_on_a_belt_at_rest_lands_stuck_and_both_methods_agree(lift):
    """No tangential load: the block stays where it is (x = 0 exactly), sticking each time it lands.
    The landing's event may put N(x) a round-off below zero: its stick limit is then zero, not negative
    (a negative one released it at zero slip rate, again and again: 'chattering')."""
    system = System(mass=M * np.eye(2), stiffness=[[KX, 0.0], [0.0, KZ]], damping=np.diag([CX, CZ]), contacts=[
        Contact([1.0, 0.0], N0, Stribeck(FS, FD, VS), surface_speed=0.0, normal_direction=[0.0, 1.0],
                normal_stiffness=KN)])
    runs = [rate_state_simulate(system, x0=[0.0, lift], t_end=0.3, samples=301, method=m) for m in ("compiled", "radau")]
    for run in runs:
        assert np.all(np.abs(run.x[:, 0]) <= 1e-12) and set(run.event_state) == {0, 2}  # lands stuck, leaves
    assert runs[0].event_time == pytest.approx(runs[1].event_time, abs=1e-9)
