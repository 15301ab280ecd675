"""The ring with contact: switched off it penetrates freely; through stick and separation events
the scheme converges at first order in ``dt``.

The contact and Coulomb conditions and the energy balance are tested for both models in
tests/contact/test_conditions.py."""

import numpy as np

from stickslip.brake import BrakeParams
from stickslip.brake.ring import InitialCondition, RingScheme, integrate, perturbed_steady

from .test_scheme import start

# coefficients of order 1; delta / sqrt(gamma) = 0.03 is small enough for separation
PARAMS = BrakeParams(xi=1.5, nu=0.3, gamma=1.0, delta=0.03, friction=0.7)


def test_contact_off_means_no_reactions():
    ini = perturbed_steady(PARAMS, 32, amplitude=5.0, mode=2)
    out = integrate(PARAMS, 32, transits=3, initial=ini, contact=False, samples_per_transit=8)
    assert np.all(out.P == 0) and np.all(out.Q == 0) and out.U.min() < PARAMS.delta  # penetrates freely


def test_convergence_in_dt_is_first_order_through_stick_and_separation_events():
    """Non-smooth regime (stick, slip, reverse slip and separation all occur before ``t = 3``):
    the self-convergence of ``V`` at a fixed time is first order in ``dt`` (the switching
    events are located to within a step), against second order in the smooth linear regime
    (`tests/brake/ring/test_scheme.py::test_observed_order_in_time`)."""
    N, t_end = 64, 3.0
    theta = 2 * np.pi * np.arange(N) / N
    c = PARAMS.coefficients()
    V = PARAMS.delta * (PARAMS.friction * c.g / c.h + 10 * np.cos(3 * theta) + 3 * np.sin(5 * theta))
    ini = InitialCondition(np.full(N, PARAMS.delta), V, np.zeros(N), np.zeros(N))
    finals, seen = [], np.zeros(4)
    for M in (1000, 2000, 4000, 8000):
        scheme = RingScheme(PARAMS, N, 0.5, t_end / (M * RingScheme(PARAMS, N, 0.5, 1.0).dt_max))
        k = start(scheme, ini, True)
        for _ in range(10):
            seen += np.bincount(scheme.advance(k, M // 10).state, minlength=4)
        finals.append(scheme.fields(k.u)[1].copy())
    assert np.all(seen > 0)
    e = [np.abs(finals[i] - finals[i + 1]).max() for i in range(3)]
    orders = np.log2(np.array(e[:-1]) / e[1:])
    assert e[0] > e[1] > e[2] and 0.8 < orders.mean() < 1.5, orders
