"""Cycles of a system along a parameter (`continue_system`), against closed forms and against
conditions computed here from the orbits themselves.

* the Coulomb oscillator's period along the belt speed, 2 (f_s - f_d) N/(k V) + (2 pi - 2
  arctan(dt_a w / 2))/w (erratum E1);
* the damped oscillator's stick-slip cycle exists while the slip from the release point comes
  back to the belt's speed: the speed where it only just does is found here with brentq on the
  closed-form damped motion, and the branch must be lost there;
* a stick phase born along the two-block branch: on its other side the orbit's smallest slip
  velocity of that contact falls linearly to zero at the located value (a tangency).
"""

from __future__ import annotations

import math
import tomllib
from pathlib import Path

import numpy as np
import pytest
from scipy.optimize import brentq

from stickslip.errors import ParameterError
from stickslip.system import continue_system, file_parameter, simulate

ROOT = Path(__file__).resolve().parents[2]


def _oscillator(damping: float) -> dict:
    return {"mass": [[1.0]], "stiffness": [[1.0]], "damping": [[damping]],
            "contact": [{"direction": [1.0], "normal_force": 1.0, "surface_speed": 0.1, "fs": 0.6, "fd": 0.4}]}


def test_the_coulomb_period_along_the_belt_speed_is_the_closed_form():
    build, start = file_parameter(_oscillator(0.0), "contact[0].surface_speed")
    branch = continue_system(build, start, 0.5, points=9, x0=[0.0], v0=[0.0], transient=40.0)
    assert branch.values.size == 9 and branch.stopped.startswith("reached")
    V = branch.values
    stick = 2 * (0.6 - 0.4) / V
    expected = stick + 2 * math.pi - 2 * np.arctan(stick / 2)
    np.testing.assert_allclose(branch.period, expected, rtol=1e-9)
    assert len(set(branch.sequence)) == 1 and branch.stable.all() and not branch.events


def test_the_coulomb_period_along_the_static_friction_is_the_closed_form():
    """A parameter that moves the section (the release at f_s N): each start of Newton's method
    lies off the new section and is brought onto it."""
    build, start = file_parameter(_oscillator(0.0), "contact[0].fs")
    branch = continue_system(build, start, 0.9, points=7, x0=[0.0], v0=[0.0], transient=40.0)
    stick = 2 * (branch.values - 0.4) / 0.1
    np.testing.assert_allclose(branch.period, stick + 2 * math.pi - 2 * np.arctan(stick / 2), rtol=1e-9)


def _critical_speed(c: float) -> float:
    """The belt speed where the slip from the release point x_a = (f_s N - c V)/k, at v = V, comes
    back to v = V only tangentially: m = k = N = 1, f_s = 0.6, f_d = 0.4, y = x - f_d N/k damped."""
    zeta, wd = c / 2, math.sqrt(1 - c * c / 4)

    def top(V):  # the first maximum of the velocity after the release, minus V
        y0 = 0.2 - c * V
        A, B = y0, (V + zeta * y0) / wd
        vel = lambda t: math.exp(-zeta * t) * ((B * wd - zeta * A) * math.cos(wd * t)  # noqa: E731
                                              - (A * wd + zeta * B) * math.sin(wd * t))
        acc = lambda t: (vel(t + 1e-7) - vel(t - 1e-7)) / 2e-7  # noqa: E731
        ts = np.linspace(1e-3, 2 * math.pi / wd, 2001)
        a = np.array([acc(t) for t in ts])
        ups = np.nonzero((a[:-1] > 0) & (a[1:] <= 0))[0]  # the velocity's maximum: acceleration falls through 0
        t_max = brentq(acc, ts[ups[0]], ts[ups[0] + 1], xtol=1e-14)
        return vel(t_max) - V
    return brentq(top, 0.05, 2.0, xtol=1e-13)


def test_the_damped_cycle_is_lost_where_the_slip_no_longer_returns_to_the_belt_speed():
    c = 0.05
    build, start = file_parameter(_oscillator(c), "contact[0].surface_speed")
    branch = continue_system(build, start, 1.0, points=19, x0=[0.0], v0=[0.0], transient=60.0,
                             parameter="contact[0].surface_speed")
    lost = [e for e in branch.events if e["change"] == "cycle lost"]
    assert len(lost) == 1 and "no cycle beyond" in branch.stopped
    assert abs(lost[0]["value"] - _critical_speed(c)) < 1e-7


def test_a_stick_phase_is_born_where_the_orbit_touches_zero_slip_velocity():
    data = tomllib.loads((ROOT / "examples" / "two_blocks" / "two_blocks.toml").read_text())
    build, start = file_parameter(data, "contact[0].surface_speed")
    branch = continue_system(build, start, 0.12, points=8, x0=[0.1, 0.0], v0=[0.0, 0.0], transient=60.0)
    born = [e for e in branch.events if e["change"] == "event sequence"]
    assert born and born[0]["before"] == "1:slip 1:stick" and "0:stick" in born[0]["after"]
    p_star = born[0]["value"]
    lows = []
    for d in (4e-3, 2e-3, 1e-3):  # the side where block 0 never sticks: its smallest slip velocity
        near = continue_system(build, start, p_star + d, points=6, x0=[0.1, 0.0], v0=[0.0, 0.0], transient=60.0)
        system = build(p_star + d)
        orbit = simulate(system, near.x0[-1], near.v0[-1], near.period[-1], samples=40001, states=near.states[-1])
        lows.append(np.min(system.contacts[0].surface_speed - orbit.v[:, 0]))
    slope, at_p_star = np.polyfit([4e-3, 2e-3, 1e-3], lows, 1)
    assert all(x > 0 for x in lows) and slope > 0
    assert abs(at_p_star) < 1e-6 * slope  # zero at the located value: within 1e-6 in the parameter


def test_a_period_doubling_is_located_where_a_multiplier_reaches_minus_one():
    """Along the coupling stiffness K[0][1] of the two-block chain a multiplier leaves the unit circle
    at -1: on each side of the located value the return map differentiated by central differences of
    whole runs (`return_map_moduli`) has its largest modulus below and above 1, by about the slope."""
    from types import SimpleNamespace

    from stickslip.system import limit_cycle

    from .test_floquet import return_map_moduli

    data = tomllib.loads((ROOT / "examples" / "two_blocks" / "two_blocks.toml").read_text())
    build, start = file_parameter(data, "stiffness[0][1]")
    branch = continue_system(build, start, 0.5, points=9, x0=[0.1, 0.0], v0=[0.0, 0.0], transient=60.0)
    changes = [e for e in branch.events if e["change"] == "stability"]
    assert len(changes) == 1 and changes[0]["before"] == "stable" and "period doubling" in changes[0]["crossing"]
    p_star = changes[0]["value"]
    first = limit_cycle(build(start), [0.1, 0.0], [0.0, 0.0], transient=60.0)
    largest = {}
    for d in (-2e-3, 2e-3):
        near = continue_system(build, start, p_star + d, points=9, x0=[0.1, 0.0], v0=[0.0, 0.0], transient=60.0)
        cycle = SimpleNamespace(x0=near.x0[-1], v0=near.v0[-1], states=near.states[-1], period=near.period[-1],
                                contact=first.contact, state=first.state)
        largest[d] = return_map_moduli(build(p_star + d), cycle, [0, 1, 2])[-1]
    assert largest[-2e-3] < 1.0 < largest[2e-3]
    assert abs(largest[2e-3] + largest[-2e-3] - 2.0) < 0.1 * (largest[2e-3] - largest[-2e-3])  # 1 at the middle


@pytest.mark.parametrize("key, message", [("contact[0].colour", "parameter = 'contact\\[0\\].colour'"),
                                          ("contact[3].fs", "not in it"), ("stiffness[0]", "a number of the file"),
                                          ("contact[0].direction", "a number of the file"), (3, "parameter = 3")])
def test_a_parameter_the_file_does_not_have_is_refused(key, message):
    data = tomllib.loads((ROOT / "examples" / "two_blocks" / "two_blocks.toml").read_text())
    with pytest.raises(ParameterError, match=message):
        file_parameter(data, key)


def test_a_stop_the_system_cannot_take_is_refused_before_the_work():
    build, start = file_parameter(_oscillator(0.0), "contact[0].fs")
    with pytest.raises(ParameterError, match="contact\\[0\\]"):
        continue_system(build, start, 0.1, points=5)  # f_s < f_d at the end


def test_the_command_line_continues_a_file_and_refuses_what_it_cannot(tmp_path, capsys):
    import json

    from stickslip.cli import run

    path = str(ROOT / "examples" / "two_blocks" / "two_blocks.toml")
    out = tmp_path / "branch.nc"
    assert run(["system", "continue", path, "--parameter", "contact[0].surface_speed", "--stop", "0.12", "--points",
                "8", "--x0", "0.1,0", "--json", "--out", str(out)]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["points"] == 8 and [e["change"] for e in data["events"]] == ["event sequence"] and out.exists()
    from stickslip.cf import load_result

    assert load_result(out)["value"].attrs["units"] == "m/s"  # the units of the number the key names
    for args, name in ((["--parameter", "contact[0].fs", "--stop", "0.1"], "--stop = 0.1"),
                       (["--parameter", "mass[0]", "--stop", "1"], "--parameter"),
                       (["--parameter", "contact[0].fs", "--stop", "0.9", "--x0", "1"], "--x0"),
                       (["--parameter", "contact[0].fs", "--stop", "0.9", "--points", "1"], "--points = 1")):
        assert run(["system", "continue", path, *args, "--json"]) == 2
        captured = capsys.readouterr()
        assert captured.out == "" and captured.err.count("\n") == 1 and name in captured.err, captured.err


def test_a_motion_that_settles_is_said_to_have_settled():
    """Block 2's belt at 0.32 m/s: from this start the chain settles on steady sliding (the
    stick-slip cycle exists too, found by continuation, but does not attract it)."""
    from stickslip.errors import NoSolutionError
    from stickslip.system import limit_cycle

    data = tomllib.loads((ROOT / "examples" / "two_blocks" / "two_blocks.toml").read_text())
    build, _ = file_parameter(data, "contact[1].surface_speed")
    with pytest.raises(NoSolutionError, match="the motion settled"):
        limit_cycle(build(0.32), [0.1, 0.0], [0.0, 0.0], transient=200.0)
    branch = continue_system(build, 0.1, 0.32, points=6, x0=[0.1, 0.0], v0=[0.0, 0.0], transient=60.0)
    assert branch.stopped.startswith("reached") and branch.values[-1] == 0.32


@pytest.mark.slow  # 4 s
def test_the_coulomb_amplitude_along_the_belt_speed_is_the_closed_form_radius():
    """m = k = N = 1, f_s = 0.6, f_d = 0.4, no damping: the mass sticks up to x_a = f_s = 0.6 and
    slips about x_c = f_d = 0.4 on the circle of radius r = sqrt((x_a - x_c)^2 + V^2) in (x, v),
    from (x_a, V) clockwise to (2 x_c - x_a, V): an arc through both v = 0 points, so x runs from
    x_c - r to x_c + r and half the swing is r (401 samples of a period T < 11 miss an extreme by
    at most r (1 - cos(T/800)) < 1e-4 r)."""
    build, start = file_parameter(_oscillator(0.0), "contact[0].surface_speed")
    branch = continue_system(build, start, 0.3, points=3, x0=[0.0], v0=[0.0], transient=40.0)
    np.testing.assert_allclose(branch.amplitude[:, 0], np.hypot(0.2, branch.values), rtol=2e-4)
