import math

import numpy as np
import pytest

from stickslip.errors import ParameterError
from stickslip.friction import Coulomb, LinearWeakening, Stribeck, UserLaw
from stickslip.oscillator import Mode, Oscillator, simulate
from stickslip.oscillator.baseline import solve_ivp_switches
from stickslip.oscillator.simulate import Engine

FIG2 = Oscillator(1.0, 1.0, 1.0, 0.2, Coulomb(0.6, 0.4))
PERIOD = 2.0 + (2 * math.pi - 2 * math.atan(1.0))  # Δt_a + Δt_g for FIG2


def test_ten_thousand_cycles_without_drift():
    traj = simulate(FIG2, PERIOD * 10_000 + 1.0, x0=0.6, v0=0.2)
    stick = traj.durations(Mode.STICK)[1:]
    slip = traj.durations(Mode.SLIP_POS)[:-1]
    assert traj.status == 0 and stick.size >= 9_999
    ulp = np.spacing(traj.t_end)  # durations are differences of times of order 7e4 s
    assert np.max(np.abs(stick - 2.0)) <= 4 * ulp
    assert np.max(np.abs(slip - (PERIOD - 2.0))) <= 4 * ulp
    starts = traj.t[:-1][traj.modes == 0][1:]
    assert abs((starts[-1] - starts[0]) / (starts.size - 1) - PERIOD) < 1e-13  # no accumulated time error


def test_energy_is_conserved_on_coulomb_slip_segments():
    traj = simulate(FIG2, 30.0, x0=-1.5, v0=0.0)
    for seg in traj.segments:
        if seg.mode == Mode.STICK:
            continue
        t = np.linspace(seg.t0, seg.t1, 50)
        x, v = seg.sample(t)
        centre = int(seg.mode) * 0.4
        energy = 0.5 * v**2 + 0.5 * (x - centre) ** 2
        assert np.ptp(energy) < 1e-13


def test_switching_states_obey_coulomb_law():
    traj = simulate(FIG2, 60.0, x0=-1.5, v0=0.0)
    x_lo, x_hi = FIG2.stick_limits
    modes = [e[4] for e in traj.events]
    assert Mode.SLIP_NEG in modes and Mode.STICK in modes  # reverse slip, then capture
    for seg in traj.segments:
        if seg.mode == Mode.STICK and seg.duration > 0:
            assert x_lo - 1e-12 <= seg.x0 <= x_hi + 1e-12 and seg.x1 == pytest.approx(x_hi)
        if seg.mode == Mode.SLIP_NEG:
            t = np.linspace(seg.t0, seg.t1, 30)[1:-1]
            assert np.all(seg.sample(t)[1] > 0.2)


def test_switch_times_agree_with_plain_solve_ivp():
    traj = simulate(FIG2, 40.0, x0=-1.5, v0=0.0)
    ref = solve_ivp_switches(FIG2, -1.5, 0.0, 40.0, rtol=1e-12)
    ours = [(e[0], int(e[4])) for e in traj.events]
    assert [m for _, m in ours] == [m for *_, m in ref]
    assert max(abs(a[0] - b[0]) for a, b in zip(ours, ref)) < 1e-8


def _fit_reverse_arc(osc):
    """Centre and damping of the first reverse-slip arc, fitted from the simulated orbit."""
    traj = simulate(osc, 8.0, x0=-1.0, v0=0.0)
    seg = next(s for s in traj.segments if s.mode == Mode.SLIP_NEG)
    t = np.linspace(seg.t0, seg.t1, 400)
    x, v = seg.sample(t)
    acc = np.gradient(v, t)[5:-5]
    # least squares for x'' = -d x' - (x - x_c)  (m = k = 1)
    a = np.column_stack([v[5:-5], x[5:-5], np.ones(acc.size)])
    coef = np.linalg.lstsq(a, acc, rcond=None)[0]
    return coef[2] / -coef[1], -coef[0]


def test_reverse_slip_spiral_centre_and_growth():
    """Erratum E2: eq. [9] as printed contradicts the text; the odd law matches it."""
    fd, tau, V = 0.4, 0.5, 0.2
    odd = Oscillator(1.0, 1.0, 1.0, V, LinearWeakening(0.4, fd, tau))
    centre, damping = _fit_reverse_arc(odd)
    assert centre == pytest.approx(-fd * (1 + tau * V), rel=1e-3)
    assert damping == pytest.approx(-fd * tau, rel=1e-3)  # negative: the divergent spirals of the text
    # [8] and [9] literally: mu(v_r) = f_d (1 - tau v_r) for both signs of v_r
    printed = odd.replace(friction=UserLaw(lambda v: fd * (1 - tau * v), 0.4))
    centre_p, damping_p = _fit_reverse_arc(printed)
    assert centre_p == pytest.approx(-fd * (1 - tau * V), rel=1e-3)
    assert damping_p == pytest.approx(+fd * tau, rel=1e-3)  # positive: converging, unlike the text


@pytest.mark.parametrize("method", ["closed-form", "python"])
def test_a_mass_moving_with_the_belt_exactly_at_a_stick_limit_sticks(method):
    """Issue 44: Coulomb's law holds the mass while the force it needs, |k x + c V|, is at most
    f_s N: at equality too. With numbers exact in binary (k = N = m = 1, f_s = 1/2, f_d = 1/4,
    V = 1/4: the stick limits are -1/2 and 1/2), a mass at x = -1/2 moving with the belt sticks
    and rides it to x = 1/2 (for 2 f_s N / (k V) = 4 s), then slips on the arc about
    x_c = f_d N / k: x = x_c + (1/2 - x_c) cos t + V sin t; a mass at x = 1/2 slips on that arc
    at once. A mode choice that slips at the limit (< for <=) sends the first into reverse slip."""
    osc = Oscillator(1.0, 1.0, 1.0, 0.25, Coulomb(0.5, 0.25))
    assert osc.stick_limits == (-0.5, 0.5)
    xc = 0.25

    def arc(t):
        return xc + (0.5 - xc) * np.cos(t) + 0.25 * np.sin(t), -(0.5 - xc) * np.sin(t) + 0.25 * np.cos(t)

    low = simulate(osc, 6.0, x0=-0.5, v0=0.25, method=method)
    stuck = [s for s in low.segments if s.mode == Mode.STICK]
    assert Mode.SLIP_NEG not in set(low.modes) and len(stuck) == 1
    assert stuck[0].t0 == 0.0 and stuck[0].duration == pytest.approx(4.0, rel=1e-12)
    assert (low.x[-1], low.v[-1]) == pytest.approx(arc(2.0), abs=1e-10)
    high = simulate(osc, 2.0, x0=0.5, v0=0.25, method=method)
    assert Mode.SLIP_NEG not in set(high.modes) and high.durations(Mode.STICK).sum() == 0.0
    assert (high.x[-1], high.v[-1]) == pytest.approx(arc(2.0), abs=1e-10)


def test_tangential_departure_does_not_chatter():
    """Erratum E3 / f_s = f_d: the slip arc leaves the stick segment with zero acceleration."""
    for law in (Coulomb(0.4, 0.4), LinearWeakening(0.4, 0.4, 0.5), Stribeck(0.6, 0.4, 0.1)):
        osc = Oscillator(1.0, 1.0, 1.0, 0.2, law)
        traj = simulate(osc, 200.0, x0=0.0, v0=0.0)
        assert traj.status == 0
        slip = traj.durations(Mode.SLIP_POS)[1:-1]
        assert slip.size > 10 and slip.min() > 1.0  # every slip arc is a full arc: no Zeno, no chatter


@pytest.mark.parametrize("method", ["numeric", "python"])
def test_numeric_flow_converges_to_closed_form(method):
    """The DOP853 paths (law as a callable: compiled by numba, or scipy's in Python) agree with the
    closed form, better with tighter rtol."""
    user = FIG2.replace(friction=UserLaw(lambda v: 0.4, 0.6))
    assert Engine(user, method).compiled == (method == "numeric")
    exact = simulate(FIG2, 30.0, x0=-0.5, v0=0.0)
    errors = []
    for rtol in (1e-6, 1e-9, 1e-12):
        approx = simulate(user, 30.0, x0=-0.5, v0=0.0, rtol=rtol, method=method)
        assert list(approx.modes) == list(exact.modes)
        errors.append(np.max(np.abs(approx.t - exact.t)))
    assert errors[2] < (1e-10 if method == "numeric" else 1e-9) and errors[0] > errors[1] > errors[2]


def test_linear_law_validity_is_enforced():
    osc = Oscillator(1.0, 1.0, 1.0, 0.2, LinearWeakening(0.4, 0.4, 0.5))
    traj = simulate(osc, 50.0, x0=-4.0, v0=0.0)
    assert traj.status == -1 and "validity" in traj.message


def test_a_falling_law_run_is_not_stopped_by_the_speed_its_closed_form_reaches_after_the_segment():
    """Linear weakening (limit |v_r| < 1.25): the slip after the first release peaks at
    |v_r| = 1.02 and ends at a stick (solve_ivp with events: at t = 9.8326126); the closed form
    continued past that stick exceeds the limit, which once stopped the run there."""
    from scipy.integrate import solve_ivp

    osc = Oscillator(1.0, 1.0, 2.0, 0.2, LinearWeakening(0.5, 0.3, 0.8), damping=0.02)
    traj = simulate(osc, 30.0, x0=0.1, v0=-0.3)
    assert traj.status == 0 and len(traj.events) >= 3
    t_rel, x_rel = traj.events[1][0], traj.events[1][1]  # the release: slip from (x, V)

    def rhs(t, y):
        vr = 0.2 - y[1]
        return [y[1], 2.0 * 0.3 * (1 - 0.8 * abs(vr)) * np.sign(vr) - 0.02 * y[1] - y[0]]

    stick = lambda t, y: y[1] - 0.2  # noqa: E731
    stick.terminal, stick.direction = True, 1
    ref = solve_ivp(rhs, [0, 20], [x_rel, 0.2 - 1e-13], events=stick, rtol=1e-12, atol=1e-14)
    assert traj.events[2][0] == pytest.approx(t_rel + ref.t_events[0][0], rel=1e-8)


def test_simulate_against_damped_solve_ivp_with_stribeck():
    osc = Oscillator(1.0, 1.0, 1.0, 0.2, Stribeck(0.6, 0.4, 0.1), damping=0.05)
    traj = simulate(osc, 30.0, x0=0.0, v0=0.0)
    ref = solve_ivp_switches(osc, 0.0, 0.0, 30.0, rtol=1e-12)
    assert [int(e[4]) for e in traj.events] == [m for *_, m in ref]
    assert max(abs(e[0] - r[0]) for e, r in zip(traj.events, ref)) < 1e-7


@pytest.mark.parametrize("kwargs, name", [
    (dict(mass=0.0), "mass"), (dict(stiffness=-1.0), "stiffness"), (dict(normal_force=float("nan")), "normal_force"),
    (dict(belt_speed=0.0), "belt_speed"), (dict(damping=-0.1), "damping"), (dict(friction="coulomb"), "friction"),
])
def test_oscillator_validation(kwargs, name):
    with pytest.raises(ParameterError) as err:
        FIG2.replace(**kwargs)
    assert err.value.name == name


@pytest.mark.parametrize("kwargs, name", [(dict(t_end=-1.0), "t_end"), (dict(t_end=1.0, x0=float("inf")), "x0"),
                                          (dict(t_end=1.0, rtol=0.1), "rtol"), (dict(t_end=1.0, method="rk4"), "method")])
def test_simulate_validation(kwargs, name):
    with pytest.raises(ParameterError) as err:
        simulate(FIG2, **kwargs)
    assert err.value.name == name


def test_trajectory_dataset_has_units():
    ds = simulate(FIG2, 20.0, x0=-0.5).to_xarray(101)
    assert ds["x"].attrs["units"] == "m" and ds["t"].attrs["units"] == "s" and ds["v"].attrs["units"] == "m/s"
    assert set(np.unique(ds["mode"].values)) <= {-1, 0, 1}
    assert ds.attrs["friction_law"] == "Coulomb"


@pytest.mark.parametrize("args, kwargs, name", [(("a", 0.0, 1.0), {}, "x0"), ((0.0, float("nan"), 1.0), {}, "v0"),
                                                ((0.0, 0.0, -1.0), {}, "t_end"), ((0.0, 0.0, 1.0), {"section": "x"}, "section"),
                                                ((0.0, 0.0, 1.0), {"max_events": 0}, "max_events")])
def test_engine_run_refuses_bad_arguments_naming_them(args, kwargs, name):
    """Issue 44: `Engine.run` is public; its arguments were passed on unchecked (a string x0 was numpy's error)."""
    from stickslip.errors import ParameterError
    from stickslip.friction import Coulomb
    from stickslip.oscillator import Oscillator
    from stickslip.oscillator.simulate import Engine

    with pytest.raises(ParameterError) as err:
        Engine(Oscillator(1.0, 1.0, 1.0, 0.2, Coulomb(0.6, 0.4))).run(*args, **kwargs)
    assert err.value.name == name
