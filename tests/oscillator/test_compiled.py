"""The compiled DOP853 of laws that are not affine (`stickslip.oscillator.slipkernel`): checked
against scipy's DOP853 (the same method, written by others), solve_ivp with events and Liouville's
formula (the closed form of a constant law: tests/oscillator/test_simulate.py); a user's law
compiled by numba or, where numba cannot, run in Python."""

import math

import numpy as np
import pytest

from stickslip.errors import ParameterError
from stickslip.friction import Stribeck, UserLaw
from stickslip.oscillator import Oscillator, limit_cycle, simulate
from stickslip.oscillator.baseline import solve_ivp_switches
from stickslip.oscillator.simulate import Engine

STRIBECK = Oscillator(1.0, 1.0, 1.0, 0.2, Stribeck(0.6, 0.4, 0.1), damping=0.05)


def test_stribeck_runs_compiled_and_switches_where_scipys_dop853_does():
    compiled, python = Engine(STRIBECK), Engine(STRIBECK, "python")
    assert compiled.compiled and not python.compiled
    a = simulate(STRIBECK, 200.0, x0=0.0, v0=0.0)
    b = simulate(STRIBECK, 200.0, x0=0.0, v0=0.0, method="python")
    assert list(a.modes) == list(b.modes) and len(a.modes) > 40
    assert np.max(np.abs(np.asarray(a.t) - np.asarray(b.t))) < 1e-9  # two DOP853 at rtol 1e-12
    sa, sb = a.sample(2001), b.sample(2001)
    assert np.max(np.abs(sa[1] - sb[1])) < 1e-9 and np.max(np.abs(sa[2] - sb[2])) < 1e-9


def test_stribeck_switch_times_against_solve_ivp_with_events():
    traj = simulate(STRIBECK, 30.0, x0=0.0, v0=0.0)
    ref = solve_ivp_switches(STRIBECK, 0.0, 0.0, 30.0, rtol=1e-12)
    assert [int(e[4]) for e in traj.events] == [m for *_, m in ref]
    assert max(abs(e[0] - r[0]) for e, r in zip(traj.events, ref)) < 1e-8


def test_a_compiled_user_laws_multipliers_obey_liouville():
    """A Stribeck law written by a user (numba compiles it; its slope a central difference): an
    unstable pure-slip cycle whose multipliers' product is exp of the trace's integral, the
    trace from the law's slope in closed form."""
    law = UserLaw(lambda v: 0.4 + 0.2 * np.exp(-abs(v) / 0.1), 0.6)
    osc = Oscillator(1.0, 1.0, 1.0, 0.6, law, damping=0.05)
    assert Engine(osc).compiled
    cycle = limit_cycle(osc, x0=osc.equilibrium - 0.45, v0=0.0)
    assert not cycle.touches_stick
    t, x, v, _ = cycle.trajectory.sample(20001)
    slope = Stribeck(0.6, 0.4, 0.1).slope(osc.belt_speed - v)
    trace = -(osc.damping + osc.normal_force * slope) / osc.mass
    assert np.prod(cycle.floquet_multipliers).real == pytest.approx(math.exp(np.trapezoid(trace, t)), rel=1e-6)


class _Table:
    """A law numba cannot compile (a Python object's method)."""

    def __call__(self, v):
        return {True: 0.4, False: 0.45}[abs(v) > 0.1]


def test_a_user_law_numba_cannot_compile_runs_in_python():
    osc = Oscillator(1.0, 1.0, 1.0, 0.2, UserLaw(_Table(), 0.6))
    assert not Engine(osc).compiled
    traj = simulate(osc, 20.0, x0=0.0, v0=0.0)
    assert traj.status == 0 and len(traj.modes) > 3


@pytest.mark.parametrize("mu", [lambda v: -0.1, lambda v: math.nan, lambda v: 1e300, lambda v: 0.5 - 2 * abs(v)],
                         ids=["negative", "nan", "huge", "negative-once-slipping-faster"])
def test_a_compiled_user_law_out_of_range_is_refused_as_in_python(mu):
    osc = Oscillator(1.0, 1.0, 1.0, 0.2, UserLaw(mu, 0.6))
    assert Engine(osc).compiled
    with pytest.raises(ParameterError, match=r"mu\(v_r\)") as compiled:
        simulate(osc, 10.0, x0=-1.0, v0=0.0)
    with pytest.raises(ParameterError, match=r"mu\(v_r\)") as python:
        simulate(osc, 10.0, x0=-1.0, v0=0.0, method="python")
    assert str(compiled.value).split("=")[0] == str(python.value).split("=")[0]


def test_an_end_a_few_ulps_after_an_accepted_step_is_reached_as_in_python():
    """A run whose t_end falls within round-off of a step's start (found on the kernel's steps)."""
    from stickslip.lawkernel import compiled
    from stickslip.oscillator import slipkernel

    mu, slope, numbers = compiled(STRIBECK.friction)
    p = np.array([1.0, 1.0, 0.05, 1.0, 0.2, 1.0, 0.0, 10.0])
    out = slipkernel.segment(mu, slope, np.array(numbers), p, np.zeros(2), 5.0, np.array([0.2]),  # as Engine does
                             np.array([1]), 1e-12, 1e-14 * 0.2, 16 * np.finfo(float).eps * 0.2, 0.01, 64)
    t_end = np.nextafter(np.nextafter(out[5][3], 1.0), 1.0)
    a = simulate(STRIBECK, t_end, x0=0.0, v0=0.0)
    b = simulate(STRIBECK, t_end, x0=0.0, v0=0.0, method="python")
    assert a.status == b.status == 0 and a.x[-1] == pytest.approx(b.x[-1], abs=1e-14)


def test_a_user_law_that_raises_is_refused_as_in_python_not_taken_for_zero():
    def mu(v):
        if abs(v) > 0.3:
            raise ValueError("too fast")
        return 0.4

    osc = Oscillator(1.0, 1.0, 1.0, 0.2, UserLaw(mu, 0.6))
    assert Engine(osc).compiled
    with pytest.raises(ParameterError, match="too fast"):
        simulate(osc, 20.0, x0=-2.0)


def test_a_user_law_reading_a_global_that_changed_is_compiled_again():
    """numba freezes the globals a function reads when it compiles it: a run after the global changed
    must see the new value, as the Python path does."""
    global _SHIFT
    _SHIFT = 0.0
    shifted = lambda v: 0.4 + _SHIFT + 0.1 * math.exp(-abs(v) / 0.1)  # noqa: E731
    first = simulate(Oscillator(1.0, 1.0, 1.0, 0.2, UserLaw(shifted, 0.6)), 20.0, x0=-1.0).t[1]
    _SHIFT = 0.05
    osc = Oscillator(1.0, 1.0, 1.0, 0.2, UserLaw(shifted, 0.6))
    again, python = simulate(osc, 20.0, x0=-1.0).t[1], simulate(osc, 20.0, x0=-1.0, method="python").t[1]
    assert again == pytest.approx(python, rel=1e-9) and abs(again - first) > 1e-3


_SHIFT = 0.0


def test_a_sharp_law_switches_where_an_independent_fine_step_solver_does():
    """A Stribeck speed of 1e-4 m/s: the friction rises from f_d to f_s within a thousandth of a
    second before the block reaches the belt's speed. The step that holds the crossing was once
    accepted on its whole length and the crossing found inside it 2.7e-4 s early; the events are
    checked against Radau with steps of at most 1e-3 s (scipy, the equations written here)."""
    from scipy.integrate import solve_ivp

    osc = Oscillator(1.0, 1.0, 1.0, 0.2, Stribeck(0.6, 0.4, 1e-4))
    reach = lambda t, y: y[1] - 0.2  # noqa: E731
    reach.terminal, reach.direction = True, 1
    ref = solve_ivp(lambda t, y: [y[1], -y[0] + 0.4 + 0.2 * math.exp(-abs(0.2 - y[1]) / 1e-4)], (0, 3), [0.0, 0.0],
                    method="Radau", rtol=1e-13, atol=1e-16, events=reach, max_step=1e-3)
    for t_end in (3.0, 50.0):
        first = simulate(osc, t_end, x0=0.0, v0=0.0).events[0][0]
        assert first == pytest.approx(ref.t_events[0][0], abs=1e-8)
