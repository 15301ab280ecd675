"""The explicit kernel's speed-dependent kinetic friction against an independent solver.

One contact node pressed on a belt (speed V) by a constant load per unit mass g and held by
a spring (omega^2 = 1) along it: the 1-DOF oscillator x'' + omega^2 x = g mu(|V - x'|)
sign(V - x'), sticking while |omega^2 x| <= g f_s. Its stick-slip cycle with a falling law
(Stribeck; linear weakening) is computed by scipy's solve_ivp with an event at the return
to the belt's speed (rtol 1e-12) and the exact stick segment. The scheme must converge to its
period and to its lowest displacement at first order in dt (the stick onset is located to
a step). Thresholds, set before the runs: at dt = T/10000 the period within 1e-3 and the
lowest displacement within 2e-3 of the cycle's amplitude scale g f_s / omega^2; the errors
shrink at least 3-fold when dt is quartered."""

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from stickslip.contact.kernel import LINEAR_WEAKENING, STRIBECK, advance
from stickslip.contact.states import STICK

W2, G, V, FS, FD = 1.0, 1.0, 0.5, 0.6, 0.4
LAWS = {"stribeck": (STRIBECK, 0.2, lambda x: FD + (FS - FD) * np.exp(-x / 0.2)),
        "linear-weakening": (LINEAR_WEAKENING, 0.5, lambda x: max(FD * (1.0 - 0.5 * x), 0.0))}


def _reference(mu):
    """(period, lowest displacement) of the stick-slip cycle: slip from the release at
    x_r = g f_s / omega^2 until x' returns to V (solve_ivp, event), then stick back to x_r."""
    xr = G * FS / W2

    def rhs(t, z):
        return [z[1], -W2 * z[0] + G * mu(abs(V - z[1])) * np.sign(V - z[1])]

    def back(t, z):
        return z[1] - V
    back.terminal, back.direction = True, 1
    sol = solve_ivp(rhs, (0.0, 100.0), [xr, V], events=back, rtol=1e-12, atol=1e-14, dense_output=True)
    t_slip, x_back = sol.t_events[0][0], sol.y_events[0][0][0]
    assert abs(W2 * x_back) <= G * FS  # it sticks again: a stick-slip cycle
    return t_slip + (xr - x_back) / V, sol.sol(np.linspace(0.0, t_slip, 20001))[0].min()


def _scheme(kind, parameter, dt, periods=3.5, cycle=7.0):
    """(period, lowest displacement) of the last full cycle of the scheme, from sticking at x = 0."""
    indptr, indices, data = np.array([0, 0, 1]), np.array([1]), np.array([W2])  # M^{-1} K: the spring on x only
    load = np.array([-G, 0.0])  # presses the normal dof onto the belt at u_n = 0
    u, v, a = np.zeros(2), np.array([0.0, V]), np.zeros(2)
    out = np.zeros(1), np.zeros(1), np.zeros(1, np.int8)
    law = np.array([kind, parameter, 0.0], float)  # no pressure dependence
    n = int(periods * cycle / dt)
    x, state = np.empty(n), np.empty(n, np.int8)
    for k in range(n):
        advance(np.zeros((0, 3, 3, 2, 2)), indptr, indices, data, 1, load, np.zeros(2), u, v, a, np.array([0]),
                np.array([1]), np.zeros(1), np.array([V]), 1, dt, 0.9, FD, FS, True, *out, np.zeros(2), law)
        x[k], state[k] = u[1], out[2][0]
    stick = state == STICK
    release = np.flatnonzero(stick[:-1] & ~stick[1:])
    assert release.size >= 3
    return (release[-1] - release[-2]) * dt, x[release[-2]:release[-1]].min()


@pytest.mark.parametrize("name", sorted(LAWS))
def test_a_falling_law_in_the_kernel_converges_to_the_oscillators_stick_slip_cycle(name):
    kind, parameter, mu = LAWS[name]
    period, lowest = _reference(mu)
    errors = []
    for dt in (period / 2500, period / 10000):
        T, low = _scheme(kind, parameter, dt)
        errors.append((abs(T / period - 1.0), abs(low - lowest) / (G * FS / W2)))
    (eT0, eX0), (eT1, eX1) = errors
    assert eT1 <= 1e-3 and eX1 <= 2e-3, errors
    assert eX0 >= 3.0 * eX1, errors
    assert eT0 >= 3.0 * eT1 or eT0 <= 1e-4, errors


@pytest.mark.parametrize("name", sorted(LAWS))
@pytest.mark.parametrize("cdt, p, excess", [(1e-3, 1.0, 0.7), (1e-3, 1.0, 50.0), (0.5, 2.0, 1.3), (2.0, 3.0, 1.9),
                                            (1e-6, 1e6, 6.1e5), (0.05, 40.0, 100.0)])
def test_the_kinetic_coefficient_is_taken_at_the_slip_speed_it_makes(name, cdt, p, excess):
    """The slip speed of the step, x = cdt (|r*| - mu p), and mu = mu(x) hold together to
    round-off (the cases include steps long enough that h(x) first falls: cdt p (f_s - f_d) / v_s
    up to 6); linear weakening past its zero slips with mu = 0."""
    from stickslip.contact.kernel import kinetic_coefficient

    kind, parameter, mu = LAWS[name]
    got = kinetic_coefficient(kind, parameter, FD, FS, excess, p, cdt)
    x = cdt * (excess - got * p)
    assert x >= 0.0
    assert got == pytest.approx(mu(x), rel=1e-12, abs=1e-14), (got, mu(x), x)
