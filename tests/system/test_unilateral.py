"""Unilateral contacts (a normal force N(x) = N0 - k_n n.x that opens and closes): the
mode-coupling model of brake squeal (Hoffmann et al. 2002) against its closed-form flutter
threshold and eigenvalues; opening and closing times against the closed form of a contact
spring; the monodromy across opening and closing against finite differences; the limit cycle
beyond flutter against the finite-difference Jacobian of its return map."""

import math

import numpy as np
import pytest

from stickslip.errors import ParameterError
from stickslip.friction import Coulomb, LinearWeakening
from stickslip.system import Contact, System, limit_cycle, monodromy, simulate, steady_sliding

from .test_floquet import end_state, finite_differences, return_map_moduli

K11, K12, K22, KH = 1.1, -0.3, 0.5, 0.5


def hoffmann(mu, V=0.5, N0=1.0, c=0.0):
    """A mass with a tangential (x) and a normal (y) degree of freedom, coupled springs, pressed
    on a belt through a contact spring k_H: N = N0 - k_H y, friction mu N along x."""
    return System(np.eye(2), [[K11, K12], [K12, K22]],
                  [Contact([1.0, 0.0], N0, Coulomb(1.2 * mu, mu), V, normal_direction=[0.0, 1.0],
                           normal_stiffness=KH)], damping=c * np.eye(2))


#: The flutter threshold, written here: the stiffness [[k11, k12 + mu kH], [k12, k22 + kH]] has a
#: double eigenvalue where (k11 - k22 - kH)^2 + 4 k12 (k12 + mu kH) = 0.
MU_C = (-(K11 - K22 - KH) ** 2 / (4 * K12) - K12) / KH


def _sorted(e):
    return e[np.lexsort((np.round(e.real, 9), np.round(e.imag, 9)))]


@pytest.mark.parametrize("mu", [0.2, 0.5, 0.9, 1.3])
def test_steady_sliding_eigenvalues_are_the_closed_form(mu):
    k22 = K22 + KH
    lam = np.roots([1.0, -(K11 + k22), K11 * k22 - K12 * (K12 + mu * KH)]).astype(complex)  # omega^2
    expected = np.concatenate([1j * np.sqrt(lam), -1j * np.sqrt(lam)])
    result = steady_sliding(hoffmann(mu))
    np.testing.assert_allclose(_sorted(result.eigenvalues), _sorted(expected), atol=1e-12)
    # the resting position: K x = N(x) n + mu N(x) w, written out
    x = result.x
    N = 1.0 - KH * x[1]
    np.testing.assert_allclose([K11 * x[0] + K12 * x[1], K12 * x[0] + K22 * x[1]], [mu * N, N], atol=1e-14)
    assert result.friction_force[0] == pytest.approx(mu * N, rel=1e-14)


def test_flutter_sets_in_at_the_closed_form_friction():
    assert 0.5 < MU_C < 0.7
    below, above = steady_sliding(hoffmann(MU_C * (1 - 1e-6))), steady_sliding(hoffmann(MU_C * (1 + 1e-6)))
    assert below.growth_rate < 1e-12 and above.growth_rate > 1e-4


def test_opening_and_closing_times_are_the_closed_form():
    """No friction coupling into y: y is a harmonic oscillator of k_y + k_H while closed (around
    N0/(k_y + k_H)), of k_y while open; the contact opens at y = N0/k_H and closes there again."""
    ky, kn, N0, v0 = 2.0, 3.0, 1.0, 2.0
    system = System(np.eye(2), np.diag([1.0, ky]), [Contact([1.0, 0.0], N0, Coulomb(0.5, 0.4), 0.3,
                                                            normal_direction=[0.0, 1.0], normal_stiffness=kn)])
    run = simulate(system, [0.0, 0.0], [0.0, v0], 3.0, samples=2)
    opening = run.event_time[run.event_state == 2]
    closing = run.event_time[(run.event_state != 2) & (np.roll(run.event_state, 1) == 2)]
    w1, w0, y_eq, y_open = math.sqrt(ky + kn), math.sqrt(ky), N0 / (ky + kn), N0 / kn
    # closed: y = y_eq - y_eq cos(w1 t) + v0/w1 sin(w1 t) = y_eq + R cos(w1 t - phase), rising to y_open
    amp, phase = math.hypot(y_eq, v0 / w1), math.atan2(v0 / w1, -y_eq)
    t_open = (phase - math.acos((y_open - y_eq) / amp)) / w1
    assert t_open > 0
    vy = y_eq * w1 * math.sin(w1 * t_open) + v0 * math.cos(w1 * t_open)
    # open: y = y_open cos(w0 s) + vy/w0 sin(w0 s) returns to y_open
    t_close = t_open + 2 * math.atan2(vy / w0, y_open) / w0 if vy > 0 else None
    assert opening[0] == pytest.approx(t_open, rel=1e-12)
    assert closing[0] == pytest.approx(t_close, rel=1e-12)


def test_the_monodromy_across_opening_closing_and_sticking_is_the_derivative_of_the_run():
    """Beyond flutter the motion of the Hoffmann model opens and closes the contact and sticks:
    the product of exponentials and saltation matrices against central differences."""
    system = hoffmann(0.7, V=0.1, c=0.01)
    warm = simulate(system, [0.5, 0.1], [0.0, 0.0], 150.0, samples=2)
    z0 = end_state(warm)
    run = simulate(system, z0[:2], z0[2:], 12.0, samples=2, segments=True)
    kinds = {(a, b) for seg in run.segments for a, b in zip(seg.states, seg.after) if a != b}
    # opening from slip, closing into reverse slip, reversal, stick onset from reverse slip, release
    assert {(1, 2), (2, -1), (-1, 1), (-1, 0), (0, 1)} <= kinds, kinds
    M = monodromy(system, run)
    FD = finite_differences(system, z0, 12.0)
    assert np.abs(M - FD).max() < 1e-6 * max(1.0, np.abs(M).max())
    assert np.abs(M - np.eye(4)).max() > 0.1


def test_the_cycle_beyond_flutter_closes_and_its_multipliers_are_those_of_its_return_map():
    system = hoffmann(0.7, c=0.01)
    cycle = limit_cycle(system, [0.5, 0.1], [0.0, 0.0], transient=300.0)
    again = simulate(system, cycle.x0, cycle.v0, cycle.period, samples=2, states=cycle.states)
    np.testing.assert_allclose(end_state(again), np.concatenate([cycle.x0, cycle.v0]), atol=1e-8)
    assert np.min(np.abs(cycle.multipliers - 1.0)) < 1e-8
    assert cycle.state == 2 or cycle.state == 1  # its section: the contact opening or closing
    poincare = return_map_moduli(system, cycle, [0, 2, 3])  # on the section N(x) = 0 (y fixed): x, vx, vy
    others = np.delete(cycle.multipliers, np.argmin(np.abs(cycle.multipliers - 1.0)))
    np.testing.assert_allclose(np.sort(np.abs(others)), poincare, atol=1e-6)


@pytest.mark.parametrize("kwargs, name", [({"normal_stiffness": 1.0}, "normal_stiffness"),
                                          ({"normal_direction": [0.0, 0.0], "normal_stiffness": 1.0},
                                           "normal_direction"),
                                          ({"normal_direction": [0.0, 1.0], "normal_stiffness": -1.0},
                                           "normal_stiffness"),
                                          ({"normal_direction": [0.0, 1.0], "normal_force": None, "rigid": True,
                                            "friction": LinearWeakening(0.5, 0.4, 0.1)}, "friction")])
def test_bad_unilateral_contacts_are_refused_naming_the_parameter(kwargs, name):
    with pytest.raises(ParameterError) as err:
        Contact(**{"direction": [1.0, 0.0], "normal_force": 1.0, "friction": Coulomb(0.5, 0.4), **kwargs})
    assert err.value.name == name
    with pytest.raises(ParameterError, match="normal_direction = .*2 numbers"):
        System(np.eye(2), np.eye(2), [Contact([1.0, 0.0], 1.0, Coulomb(0.5, 0.4), normal_direction=[0.0, 1.0, 0.0],
                                              normal_stiffness=1.0)])
