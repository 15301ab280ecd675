"""The Burridge-Knopoff chain: one block is the oscillator's closed form; a chain of 12 blocks
against an independent time-stepping scheme written here (Moreau's scheme with the springs
explicit, so that each block's contact is decided on its own), whose difference from the
event-driven run falls at its first order."""

import numpy as np
import pytest

from stickslip.errors import ParameterError
from stickslip.friction import Coulomb
from stickslip.system import burridge_knopoff, simulate


def test_one_block_sticks_for_the_closed_form_time():
    """One block: the Coulomb oscillator; a stick phase lasts 2 (fs - fd) N / (k_p V)."""
    V, kp, N = 0.05, 2.0, 1.5
    chain = burridge_knopoff(1, Coulomb(0.6, 0.4), pull=kp, normal_force=N, plate_speed=V)
    run = simulate(chain, [0.0], [-V], 200.0, samples=2)
    starts = run.event_time[:-1][run.event_state[:-1] == 0]
    ends = run.event_time[1:][run.event_state[:-1] == 0]
    assert starts.size >= 3
    np.testing.assert_allclose((ends - starts)[1:], 2 * 0.2 * N / (kp * V), rtol=1e-11)


def explicit_moreau(m, kp, kc, N, fs, fd, V, x0, v0, t_end, steps):
    """Per step: the spring forces at the start of the step (explicit), then for each block the
    friction impulse that makes it stick (slip velocity -V - v = 0) if that impulse is within
    f_s N h, else f_d N h against its slip."""
    h = t_end / steps
    x, v = np.array(x0, float), np.array(v0, float)
    n = x.size
    for _ in range(steps):
        lap = np.zeros(n)
        lap[1:] += x[1:] - x[:-1]
        lap[:-1] += x[:-1] - x[1:]
        free = v + h * (-kp * x - kc * lap) / m
        needed = m * (-V - free)  # the impulse that brings the block to the ground's speed
        stick = np.abs(needed) <= fs * N * h
        v = np.where(stick, -V, free + np.sign(-V - free) * fd * N * h / m)
        x = x + h * v
    return x, v


@pytest.mark.slow  # 9 s (the fast set's budget)
def test_a_chain_against_an_independent_time_stepping_scheme():
    """12 blocks, seeded random start (rng seed 3), 20 s: 82 events, every block slipping and
    sticking; the scheme's distance to the event-driven end state shrinks with its step as a first
    order scheme's does, noisily (a block's switch lands on one step or the next): 4.0e-4, 1.5e-4,
    4.9e-5 at 2e4, 8e4, 3.2e5 steps. Asserted: at least 4x smaller on a 16x finer step, and below
    2e-4 of the displacements' size at the finest."""
    n, m, kp, kc, N, V = 12, 1.0, 1.0, 4.0, 1.0, 0.05
    chain = burridge_knopoff(n, Coulomb(0.6, 0.4), mass=m, pull=kp, coupling=kc, normal_force=N, plate_speed=V)
    x0 = np.random.default_rng(3).uniform(-0.3, 0.3, n)
    v0 = -V * np.ones(n)
    run = simulate(chain, x0, v0, 20.0, samples=2)
    assert run.event_time.size > 40 and len(set(run.event_contact.tolist())) == n
    errors = []
    for steps in (20_000, 320_000):
        x, _ = explicit_moreau(m, kp, kc, N, 0.6, 0.4, V, x0, v0, 20.0, steps)
        errors.append(np.abs(x - run.x[-1]).max())
    assert errors[1] < 2e-4 * np.abs(run.x[-1]).max()
    assert errors[0] / errors[1] > 4.0  # first order: 16 on a 16-times finer step


@pytest.mark.parametrize("kwargs, name", [({"blocks": 0}, "blocks"), ({"blocks": 2.5}, "blocks"),
                                          ({"mass": 0.0}, "mass"), ({"pull": float("nan")}, "pull"),
                                          ({"coupling": 1e300}, "coupling")])
def test_bad_chains_are_refused_naming_the_parameter(kwargs, name):
    with pytest.raises(ParameterError) as err:
        burridge_knopoff(**{"blocks": 3, "friction": Coulomb(0.6, 0.4), **kwargs})
    assert err.value.name == name
