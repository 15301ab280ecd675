"""The rate-and-state spring-slider: against closed forms (steady friction, the rigid-slider
velocity step, the critical stiffness and Hopf frequency with and without inertia) and against
an independent stiff solve of the equations written here in the primitive variables (V, theta)."""

import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from stickslip.errors import NoSolutionError, ParameterError
from stickslip.rsf import RateState, SpringSlider, linear_stability, slide

SIGMA, A, B, DC, V0, F0 = 1e7, 0.01, 0.015, 1e-5, 1e-6, 0.6
KC = SIGMA * (B - A) / DC  # quasi-static critical stiffness, written here


def law(evolution="aging", **kw):
    return RateState(A, B, DC, f0=F0, v_ref=V0, evolution=evolution, **kw)


@pytest.mark.parametrize("evolution", ["aging", "slip", "prz"])
def test_steady_friction_is_the_closed_form(evolution):
    for v in (1e-9, 1e-6, 3e-3):
        expected = F0 + (A - B) * math.log(v / V0) + (B * math.log(2.0) if evolution == "prz" else 0.0)
        assert law(evolution).steady_friction(v) == pytest.approx(expected, abs=1e-14)


def _theta_rigid(evolution, theta1, v2, t):
    """The state after a step to v2 at t = 0 of a rigid slider (the slip rate is imposed)."""
    if evolution == "aging":  # theta' = 1 - v2 theta / Dc: linear
        return DC / v2 + (theta1 - DC / v2) * np.exp(-v2 * t / DC)
    # slip: d ln(v2 theta / Dc) / dt = -(v2 / Dc) ln(v2 theta / Dc)
    return DC / v2 * np.exp(math.log(v2 * theta1 / DC) * np.exp(-v2 * t / DC))


@pytest.mark.parametrize("evolution", ["aging", "slip"])
def test_a_velocity_step_of_a_stiff_slider_is_the_rigid_closed_form(evolution):
    """k = 1e6 sigma / Dc: the slip rate follows the load within a/1e6 of Dc / V, and friction is
    mu = f0 + a ln(V2/V0) + b ln(V0 theta/Dc) with the closed-form state."""
    v1, v2, t1 = 1e-6, 1e-5, 5.0
    slider = SpringSlider(law(evolution), SIGMA, 1e6 * SIGMA / DC)
    run = slide(slider, [v1, v2], 20.0, times=[0.0, t1], samples=2001)
    after = run.t > t1 + 1e-3 * DC / v2 * 50  # past the spring's own transient
    theta = _theta_rigid(evolution, DC / v1, v2, run.t[after] - t1)
    mu = F0 + A * math.log(v2 / V0) + B * np.log(V0 * theta / DC)
    np.testing.assert_allclose(run.friction[after], mu, atol=2e-6)
    np.testing.assert_allclose(run.theta[after, 0], theta, rtol=1e-4)
    before = run.t < t1
    np.testing.assert_allclose(run.friction[before], F0 + (A - B) * math.log(v1 / V0), atol=1e-12)


def _primitive(evolution, k, m, v_lp):
    """The slider written in (V, theta, tau, slip), independently of the package."""
    def rhs(t, y):
        v, th, tau, _ = y
        rate = {"aging": 1 - v * th / DC, "slip": -(v * th / DC) * math.log(v * th / DC),
                "prz": 1 - (v * th / (2 * DC)) ** 2}[evolution]
        mu = F0 + A * math.log(v / V0) + B * math.log(V0 * th / DC)
        if m == 0:  # k (V_lp - V) = sigma (a V'/V + b theta'/theta)
            dv = v / A * (k * (v_lp(t) - v) / SIGMA - B * rate / th)
        else:
            dv = (tau - SIGMA * mu) / m
        return [dv, rate, k * (v_lp(t) - v), v]
    return rhs


@pytest.mark.parametrize("evolution, mass, k", [("aging", 0.0, 1.5 * KC), ("slip", 0.0, 3.0 * KC),
                                                ("prz", 0.0, 5.0 * KC), ("aging", 1e9, 0.95 * KC),
                                                ("slip", 1e9, 1.1 * KC)])
def test_slide_hold_slide_against_an_independent_stiff_solve(evolution, mass, k):
    """Slide at 1 um/s, step to 10 um/s at 20 s, hold at 60 s, slide again at 100 s: the slip rate,
    friction and slip of the package against LSODA on the primitive equations (rtol 1e-11)."""
    times, speeds = [0.0, 20.0, 60.0, 100.0], [1e-6, 1e-5, 0.0, 1e-6]
    slider = SpringSlider(law(evolution), SIGMA, k, mass=mass)
    run = slide(slider, speeds, 160.0, times=times, samples=801)

    def v_lp(t):
        return speeds[int(np.searchsorted(times, t, side="right")) - 1]

    rhs = _primitive(evolution, k, mass, v_lp)
    theta0 = (2 if evolution == "prz" else 1) * DC / 1e-6
    y = [1e-6, theta0, SIGMA * law(evolution).steady_friction(1e-6), 0.0]
    v_ref, slip_ref = [], []
    for t0, t1 in zip(times, times[1:] + [160.0]):
        grid = run.t[(run.t >= t0) & (run.t < t1)] if t1 < 160.0 else run.t[run.t >= t0]
        sol = solve_ivp(rhs, (t0, t1), y, method="LSODA", rtol=1e-11, atol=[1e-22, 1e-12, 1e-6, 1e-16],
                        t_eval=grid, first_step=1e-6)
        assert sol.status == 0
        v_ref += list(sol.y[0])
        slip_ref += list(sol.y[3])
        y = solve_ivp(rhs, (t0, t1), y, method="LSODA", rtol=1e-11, atol=[1e-22, 1e-12, 1e-6, 1e-16],
                      first_step=1e-6).y[:, -1]
    np.testing.assert_allclose(np.log(run.slip_rate), np.log(v_ref), atol=2e-5)
    np.testing.assert_allclose(run.slip, slip_ref, rtol=1e-5, atol=1e-12)


@pytest.mark.parametrize("evolution", ["aging", "slip", "prz"])
@pytest.mark.parametrize("mass", [0.0, 1e9, 1e12])
def test_critical_stiffness_and_hopf_frequency_are_the_closed_forms(evolution, mass):
    """k_c = sigma (b - a)/Dc (1 + m V^2/(sigma a Dc)), omega_c = (V/Dc) sqrt((b - a)/a)."""
    v = 1e-6
    result = linear_stability(SpringSlider(law(evolution), SIGMA, KC, mass=mass), v)
    assert result.critical_stiffness == pytest.approx(KC * (1 + mass * v**2 / (SIGMA * A * DC)), rel=1e-9)
    assert result.hopf_frequency == pytest.approx(v / DC * math.sqrt((B - A) / A), rel=1e-9)


def test_velocity_strengthening_is_stable_at_every_stiffness():
    result = linear_stability(SpringSlider(RateState(0.02, 0.01, DC), SIGMA, 1.0), 1e-6)
    assert result.stable and result.critical_stiffness == 0.0


def test_steady_sliding_is_stable_above_and_unstable_below_the_critical_stiffness_in_a_run():
    """A 1 % kick of the slip rate decays above k_c and grows below it, at the linear rate's sign,
    oscillating at the linear frequency (1e-3)."""
    for k, decays in ((1.02 * KC, True), (0.98 * KC, False)):
        slider = SpringSlider(law(), SIGMA, k)
        lin = linear_stability(slider, 1e-6)
        period = 2 * math.pi / abs(lin.eigenvalues[0].imag)
        run = slide(slider, 1e-6, 6 * period, v_init=1.01e-6, samples=6001)
        r = np.log(run.slip_rate / 1e-6)
        up = np.nonzero((r[:-1] < 0) & (r[1:] >= 0))[0]
        crossings = run.t[up] - r[up] * (run.t[up + 1] - run.t[up]) / (r[up + 1] - r[up])
        assert np.diff(crossings) == pytest.approx(period, rel=1e-3)
        first, last = np.abs(r[run.t < period]).max(), np.abs(r[run.t > 5 * period]).max()
        assert (last < first) == decays


@pytest.mark.parametrize("kwargs, name", [({"a": 0.0}, "a"), ({"a": -0.01}, "a"), ({"dc": 0.0}, "dc"),
                                          ({"evolution": "ageing"}, "evolution"), ({"b2": 0.01}, "b2"),
                                          ({"v_ref": 1e300}, "v_ref")])
def test_bad_laws_are_refused_naming_the_parameter(kwargs, name):
    with pytest.raises(ParameterError) as err:
        RateState(**{"a": A, "b": B, "dc": DC, **kwargs})
    assert err.value.name == name


def test_a_history_that_does_not_increase_in_time_is_refused():
    slider = SpringSlider(law(), SIGMA, 2 * KC)
    for times in ([0.0, 10.0, 10.0], [0.0, 10.0, 5.0], [1.0, 2.0, 3.0]):
        with pytest.raises(ParameterError, match="increasing") as err:
            slide(slider, [1e-6, 1e-5, 1e-6], 20.0, times=times)
        assert err.value.name == "times"
    with pytest.raises(ParameterError) as err:
        slide(slider, [0.0, 1e-6], 20.0, times=[0.0, 10.0])
    assert err.value.name == "v_init"


def test_an_unbounded_quasi_static_slip_rate_is_said():
    """Quasi-static, well below k_c: the slip rate runs away in finite time (no inertia to bound it)."""
    with pytest.raises(NoSolutionError, match="slip rate"):
        slide(SpringSlider(law(), SIGMA, 0.3 * KC), 1e-6, 2000.0, v_init=1.2e-6)


def _primitive_general(k, b2, dc2, regularized, v_lp, f0):
    """Aging law, two state variables and the regularised law, quasi-static, in (V, theta1, theta2, slip)."""
    def rhs(t, y):
        v, th1, th2, _ = y
        r1, r2 = 1 - v * th1 / DC, 1 - v * th2 / dc2
        psi = f0 + B * math.log(V0 * th1 / DC) + b2 * math.log(V0 * th2 / dc2)
        if regularized:  # mu = a asinh(z), z = V/(2 V0) exp(Psi/a)
            z = v / (2 * V0) * math.exp(psi / A)
            s = z / math.sqrt(1 + z * z)
            mu_v, mu_psi = A * s / v, s
        else:
            mu_v, mu_psi = A / v, 1.0
        dv = (k * (v_lp(t) - v) / SIGMA - mu_psi * (B * r1 / th1 + b2 * r2 / th2)) / mu_v
        return [dv, r1, r2, v]
    return rhs


@pytest.mark.parametrize("b2, regularized, v_hold", [(0.004, False, 0.0), (0.0, True, 0.0), (0.004, True, 1e-12)])
def test_two_state_variables_and_the_regularised_law_against_an_independent_stiff_solve(b2, regularized, v_hold):
    """A step up, a hold (or a crawl) of 40 s and a step back. With f_0 = 0.02 the regularised law
    departs from the plain one below about V_0 exp(-f_0/a) = 1.4e-7 m/s, which the hold reaches."""
    dc2, f0 = 1e-3, (0.02 if regularized else F0)
    times, speeds = [0.0, 20.0, 60.0, 100.0], [1e-6, 1e-5, v_hold, 1e-6]
    rs = RateState(A, B, DC, f0=f0, v_ref=V0, b2=b2, dc2=dc2, regularized=regularized)
    k = 3 * SIGMA * (B + b2 - A) / DC
    run = slide(SpringSlider(rs, SIGMA, k), speeds, 160.0, times=times, samples=801)

    def v_lp(t):
        return speeds[int(np.searchsorted(times, t, side="right")) - 1]

    rhs = _primitive_general(k, b2, dc2, regularized, v_lp, f0)
    y = [1e-6, DC / 1e-6, dc2 / 1e-6, 0.0]
    v_ref = []
    for t0, t1 in zip(times, times[1:] + [160.0]):
        grid = run.t[(run.t >= t0) & (run.t < t1)] if t1 < 160.0 else run.t[run.t >= t0]
        opts = dict(method="LSODA", rtol=1e-11, atol=[1e-22, 1e-12, 1e-10, 1e-16], first_step=1e-6)
        v_ref += list(solve_ivp(rhs, (t0, t1), y, t_eval=grid, **opts).y[0])
        y = solve_ivp(rhs, (t0, t1), y, **opts).y[:, -1]
    np.testing.assert_allclose(np.log(run.slip_rate), np.log(v_ref), atol=2e-5)
    if regularized:
        assert run.slip_rate.min() < 0.1 * V0 * math.exp(-f0 / A)  # where the two laws differ
    if b2:
        np.testing.assert_allclose(run.theta[:, 1][-1], y[2], rtol=1e-6)


@pytest.mark.parametrize("history, part", [("0:1e-6,0:1e-5", "its times"), ("5:1e-6", "its times"),
                                           ("0:1e-6,20:1e-5,10:1e-6", "its times"), ("0:1e-6,10:-1", "its velocities"),
                                           ("0:1e-6,10:1e99", "its velocities")])
def test_a_bad_history_on_the_command_line_is_named_as_typed(history, part, capsys):
    """Issue 44: a geophysicist's bad --history was named `times` or `--load-velocity` (not typed)."""
    from stickslip.cli import run

    code = run(["rsf", "slide", "--a", "0.01", "--b", "0.015", "--dc", "1e-5", "--normal-stress", "1e7",
                "--stiffness", "1e10", "--t-end", "30", "--history", history])
    out, err = capsys.readouterr()
    assert code == 2 and out == "" and err.count("\n") == 1
    assert f"--history = {history!r}" in err and part in err and "load-velocity" not in err and " times " not in err


@pytest.mark.slow  # 20 s: the independent Radau solve in Python
def test_a_light_slider_that_stops_lsoda_is_solved_by_radau_against_an_independent_solve(monkeypatch):
    """Inertia of 1e3 kg/m^2 at half the critical stiffness: stick-slip with the slip rate falling to
    1e-13 m/s, where LSODA's trial steps leave the range of the numbers and its error test (NaN)
    does not refuse them; the piece is solved again by Radau IIA. Against LSODA on the primitive
    equations written here."""
    from stickslip.rsf import pieces

    taken = []
    radau = pieces.solve_ivp
    monkeypatch.setattr(pieces, "solve_ivp", lambda *a, **k: taken.append(1) or radau(*a, **k))
    slider = SpringSlider(law(), SIGMA, 0.5 * KC, mass=1e3)
    run = slide(slider, 1e-6, 2000.0, v_init=1.1e-6)
    assert taken, "LSODA ran through: this case no longer tests the fallback"
    rhs = _primitive("aging", 0.5 * KC, 1e3, lambda t: 1e-6)
    y0 = [1.1e-6, DC / 1.1e-6, SIGMA * law().steady_friction(1.1e-6), 0.0]
    with np.errstate(all="ignore"):  # its trial steps too go out of range; Radau refuses them
        sol = solve_ivp(rhs, (0.0, 2000.0), y0, method="Radau", rtol=1e-11, atol=[1e-24, 1e-12, 1e-6, 1e-16],
                        t_eval=run.t)
    assert sol.status == 0
    assert run.slip_rate.min() < 1e-11  # the stick phase that stops LSODA
    np.testing.assert_allclose(run.slip, sol.y[3], rtol=1e-5, atol=1e-12)
    np.testing.assert_allclose(np.log(run.slip_rate), np.log(sol.y[0]), atol=1e-3)
