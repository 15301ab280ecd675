import math

import numpy as np
import pytest

from stickslip.errors import NoSolutionError, ParameterError
from stickslip.friction import Coulomb, LinearWeakening, Stribeck, UserLaw
from stickslip.oscillator import Engine, Oscillator, limit_cycle, return_map
from stickslip.oscillator.baseline import solve_ivp_switches


def _coulomb_closed_form(m, k, N, V, fs, fd):
    w = math.sqrt(k / m)
    dta = 2 * (fs - fd) * N / (k * V)
    dtg = (2 * math.pi - 2 * math.atan(dta * w / 2)) / w
    r = math.hypot((fs - fd) * N / k, V / w)
    return dta, dtg, fd * N / k - r, fd * N / k + r


@pytest.mark.parametrize("m, k, N, V, fs, fd", [(1, 1, 1, 0.2, 0.6, 0.4), (2.0, 50.0, 10.0, 0.05, 0.5, 0.3),
                                                (0.5, 3.0, 2.0, 1.5, 0.9, 0.1), (1, 1, 1, 0.2, 0.4, 0.4)])
def test_coulomb_cycle_matches_closed_form(m, k, N, V, fs, fd):
    cycle = limit_cycle(Oscillator(m, k, N, V, Coulomb(fs, fd)))
    dta, dtg, x_min, x_max = _coulomb_closed_form(m, k, N, V, fs, fd)
    assert cycle.stick_time == pytest.approx(dta, rel=1e-12, abs=1e-14)
    assert cycle.slip_time == pytest.approx(dtg, rel=1e-12)
    assert cycle.period == pytest.approx(dta + dtg, rel=1e-12)
    assert cycle.x_min == pytest.approx(x_min, rel=1e-12) and cycle.x_max == pytest.approx(x_max, rel=1e-12)
    assert cycle.v_max == pytest.approx(V) and cycle.v_min == pytest.approx(-math.sqrt(k / m) * (x_max - x_min) / 2, rel=1e-9)
    if fs == fd:  # the cycle is the ellipse tangent to the stick line: no transversal switch
        assert np.all(np.isnan(cycle.floquet_multipliers)) and cycle.stick_time < 1e-12


def test_printed_slip_time_is_wrong():
    """Erratum E1: 2π arctan(Δt_a w/2)/w disagrees with the simulated cycle; the corrected one agrees."""
    for V in (0.05, 0.2, 1.0):
        osc = Oscillator(1.0, 1.0, 1.0, V, Coulomb(0.6, 0.4))
        cycle = limit_cycle(osc)
        dta = 2 * 0.2 / V
        printed = 2 * math.pi * math.atan(dta / 2)
        corrected = 2 * math.pi - 2 * math.atan(dta / 2)
        assert cycle.slip_time == pytest.approx(corrected, rel=1e-12)
        assert abs(printed / cycle.slip_time - 1) > 0.04
    # as f_s -> f_d the printed formula tends to 0, the true slip time to 2π/w
    cycle = limit_cycle(Oscillator(1.0, 1.0, 1.0, 0.2, Coulomb(0.4 + 1e-4, 0.4)))
    assert cycle.slip_time == pytest.approx(2 * math.pi - 1e-3, rel=1e-6)
    assert 2 * math.pi * math.atan(5e-4) / cycle.slip_time < 1e-2  # printed: almost no slip at all


def test_period_agrees_with_independent_solve_ivp():
    osc = Oscillator(1.0, 4.0, 2.0, 0.3, Stribeck(0.6, 0.4, 0.2), damping=0.1)
    cycle = limit_cycle(osc)
    switches = solve_ivp_switches(osc, osc.stick_limits[1], osc.belt_speed, 12 * cycle.period, rtol=1e-12)
    entries = [t for t, *_, mode in switches if mode == 0]
    assert np.diff(entries)[-3:] == pytest.approx([cycle.period] * 3, rel=1e-9)


@pytest.mark.parametrize("law", [Coulomb(0.6, 0.4), LinearWeakening(0.4, 0.4, 0.5), Stribeck(0.6, 0.4, 0.1)],
                         ids=lambda l: type(l).__name__)
def test_stick_slip_multipliers_are_one_and_zero(law):
    cycle = limit_cycle(Oscillator(1.0, 1.0, 1.0, 0.2, law, damping=0.02))
    mults = np.sort(np.abs(cycle.floquet_multipliers))
    assert mults[0] < 1e-11 and abs(mults[1] - 1) < 1e-10
    assert cycle.touches_stick and cycle.stable


@pytest.mark.parametrize("method", ["numeric", "python"])
def test_nontrivial_multiplier_is_the_slope_of_the_return_map(method):
    """An unstable pure-slip cycle (Stribeck, between Hopf and grazing): the saltation-free
    monodromy multiplier equals P'(x*) measured by finite differences of the return map (on both
    DOP853 paths: compiled with the law, and scipy's in Python)."""
    osc = Oscillator(1.0, 1.0, 1.0, 0.6, Stribeck(0.6, 0.4, 0.1), damping=0.05)
    cycle = limit_cycle(osc, x0=osc.equilibrium - 0.45, v0=0.0, method=method)
    assert not cycle.touches_stick and not cycle.stable
    engine = Engine(osc, method)
    h = 1e-6
    slope = (return_map(engine, cycle.section_x + h).x_next - return_map(engine, cycle.section_x - h).x_next) / (2 * h)
    assert cycle.nontrivial_multiplier.real == pytest.approx(slope, rel=1e-5)
    assert abs(cycle.nontrivial_multiplier.real * 1.0 - np.prod(cycle.floquet_multipliers).real) < 1e-9
    # Liouville: the product of multipliers is exp(-∫ trace) = exp(-∫ (c + N mu'(v_r)) / m dt)
    t, x, v, _ = cycle.trajectory.sample(20001)
    trace = -(osc.damping + osc.normal_force * osc.friction.slope(osc.belt_speed - v)) / osc.mass
    assert np.prod(cycle.floquet_multipliers).real == pytest.approx(math.exp(np.trapezoid(trace, t)), rel=1e-6)


def _anisotropic_mu(v_r):
    """A friction coefficient that depends on the direction of slip (a textured surface): Stribeck
    (0.05 falling to 0.005 over 0.05 m/s) when the belt outruns the mass, 0.005 the other way."""
    return 0.005 + 0.045 * math.exp(-v_r / 0.05) if v_r > 0 else 0.005


def _independent_return_map(x0, V=0.2):
    """The return map on v = 0 (upward) of m = k = N = 1, c = 0 under `_anisotropic_mu`,
    written from the equations of motion: ``x'' = N mu(V - x') - k x`` in slip (v < V),
    ``x'' = -N 0.005 - k x`` in reverse slip (v > V), each integrated by ``solve_ivp`` (DOP853,
    rtol 1e-12) to its event; the mass crosses v = V outside the stick limits ``|x| <= 0.05``
    both ways (checked), so it slips, slips in reverse, and slips again without sticking."""
    from scipy.integrate import solve_ivp

    def slip(t, y):
        return [y[1], 0.005 + 0.045 * math.exp(-max(V - y[1], 0.0) / 0.05) - y[0]]

    def reverse(t, y):
        return [y[1], -0.005 - y[0]]

    def crossing(level, direction):
        event = lambda t, y: y[1] - level  # noqa: E731
        event.terminal, event.direction = True, direction
        return event

    y, switches = [x0, 0.0], []
    for rhs, level, direction in ((slip, V, 1), (reverse, V, -1), (slip, 0.0, 1)):
        sol = solve_ivp(rhs, (0.0, 50.0), y, method="DOP853", rtol=1e-12, atol=1e-14,
                        events=crossing(level, direction))
        assert sol.t_events[0].size == 1
        y = [sol.y_events[0][0][0], level]
        switches.append(y[0])
    assert switches[0] < -0.05 and switches[1] > 0.05  # beyond the stick limits: no sticking
    return switches[-1]


def test_the_multipliers_of_a_cycle_through_slip_and_reverse_slip_are_those_of_an_independent_return_map():
    """Issue 44: the saltation matrices at the switches between slip and reverse slip (no stick),
    checked on a cycle that has them. On the anisotropic law of `_anisotropic_mu` the oscillator
    (m = k = N = 1, V = 0.2, c = 0) has a stable cycle that slips, overtakes the belt (reverse
    slip) and falls back into slip, never sticking. Its nontrivial Floquet multiplier is the
    slope of the return map on v = 0 at its fixed point: here by central differences
    (h = 1e-5) of the return map integrated independently (`_independent_return_map`), accurate
    to some 1e-7; the package's, from flow Jacobians and saltation matrices, must agree within
    1e-5 (relative), and its other multiplier be 1. With a saltation left out (identity), or with
    the jump of the field reversed, the multiplier that must be 1 came out 1.33 and 1.69; with
    the vector field at the switch evaluated at ``v_r = 0`` itself, where this law takes its
    reverse value, 1.26 (the bug this test found in `Oscillator.acceleration`). (Transposing
    the saltation changes nothing here: on v = V, grad h and the jump of the field are both
    along v.)"""
    from stickslip.oscillator.cycle import characterise

    x, previous, r_previous = -0.26, -0.25, _independent_return_map(-0.25) + 0.25
    for _ in range(20):  # the fixed point of the independent map, by the secant method
        r = _independent_return_map(x) - x
        if abs(r) < 1e-13:
            break
        x, previous, r_previous = x - r * (x - previous) / (r - r_previous), x, r
    assert abs(r) < 1e-13
    osc = Oscillator(1.0, 1.0, 1.0, 0.2, UserLaw(_anisotropic_mu, 0.05))
    engine = Engine(osc, "python", variational=True)
    found = return_map(engine, x)
    assert found.x_next == pytest.approx(x, abs=1e-10)  # the package's map has the same cycle
    cycle = characterise(engine, found)
    assert cycle.stick_time == 0.0 and cycle.reverse_slip_time > 0.5
    assert [int(m) for m in cycle.trajectory.modes] == [1, -1, 1]
    h = 1e-5
    slope = (_independent_return_map(x + h) - _independent_return_map(x - h)) / (2 * h)
    assert 0.5 < slope < 0.95  # a stable cycle, the saltations far from the identity
    mults = np.sort(np.real(cycle.floquet_multipliers))
    assert mults[1] == pytest.approx(1.0, abs=1e-9)
    assert mults[0] == pytest.approx(slope, rel=1e-5)


def test_no_cycle_is_reported_as_no_solution():
    osc = Oscillator(1.0, 1.0, 1.0, 0.2, Coulomb(0.6, 0.4), damping=0.5)
    with pytest.raises(NoSolutionError, match="equilibrium|section"):
        limit_cycle(osc)


def test_cycle_summary_and_dataset():
    cycle = limit_cycle(Oscillator(1.0, 1.0, 1.0, 0.2, Coulomb(0.6, 0.4)))
    d = cycle.to_dict()
    assert {"period", "stick_time", "slip_time", "x_min", "x_max", "floquet_multipliers"} <= set(d)
    ds = cycle.to_xarray(201)
    assert ds.attrs["period"] == pytest.approx(d["period"]) and ds["x"].attrs["units"] == "m"


def test_cycle_validation():
    osc = Oscillator(1.0, 1.0, 1.0, 0.2, Coulomb(0.6, 0.4))
    with pytest.raises(ParameterError, match="x0"):
        limit_cycle(osc, x0=float("nan"))
    with pytest.raises(ParameterError, match="tol"):
        limit_cycle(osc, tol=0.0)


@pytest.mark.parametrize("mass, stiffness, normal_force, option", [
    (1e-320, 1.0, 1.0, "mass"),  # subnormal (was: k / m overflowed and `oscillator cycle` spun for ever)
    (1e300, 1e-150, 1.0, "mass"),  # (was: k / m underflowed to 1e-450)
    (1.0, 1e-100, 1e150, "stiffness"),  # (was: N / k = 1e250)
    (1.0, 1.0, 1e16, "normal_force"),
])
def test_scales_beyond_the_declared_ranges_are_refused(mass, stiffness, normal_force, option):
    from stickslip.errors import ParameterError
    from stickslip.friction import Coulomb
    from stickslip.oscillator import Oscillator

    with pytest.raises(ParameterError) as err:
        Oscillator(mass, stiffness, normal_force, 0.2, Coulomb(0.6, 0.4))
    assert err.value.name == option


def test_every_corner_of_the_declared_ranges_gives_a_finite_cycle_or_no_solution():
    """The ranges of m, k, N and V are physical, and every combination of their ends is a problem
    the cycle search answers in finite numbers (or says it has no cycle): the combinations of
    extremes that overflowed double precision before the ranges were declared are gone."""
    import itertools
    import math

    from stickslip.errors import NoSolutionError
    from stickslip.friction import Coulomb
    from stickslip.oscillator import Oscillator
    from stickslip.quantities import OSCILLATOR as Q

    ends = [(Q[n].range.lo, Q[n].range.hi) for n in ("mass", "stiffness", "normal_force", "belt_speed")]
    for m, k, N, V in itertools.product(*ends):
        osc = Oscillator(m, k, N, V, Coulomb(0.6, 0.4))
        try:
            cycle = limit_cycle(osc)
        except NoSolutionError:
            continue
        assert all(math.isfinite(x) for x in (cycle.period, cycle.amplitude, cycle.stick_time)), (m, k, N, V)


def test_a_subnormal_mass_on_the_command_line_is_one_line_exit_2(capsys):
    from stickslip.cli import run

    args = ["oscillator", "cycle", "--stiffness", "1", "--normal-force", "1", "--belt-speed", "0.2", "--fs", "0.6",
            "--fd", "0.4", "--mass", "1e-320", "--json"]
    assert run(args) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "--mass = 1e-320" in err, err


@pytest.mark.slow  # 3 s
def test_a_cycle_with_reverse_slip_counts_it_in_its_slip_time():
    """A Stribeck cycle (f_s = 0.9, f_d = 0.02, v_s = 0.1, V = 0.5; m = k = N = 1) overshoots the
    belt's speed into reverse slip each period: the period is stick plus slip, forward and reverse
    (the slip time without the reverse slip falls short of it by the reverse slip time, 2.25 here)."""
    cycle = limit_cycle(Oscillator(1.0, 1.0, 1.0, 0.5, Stribeck(0.9, 0.02, 0.1)))
    assert cycle.reverse_slip_time > 0.1 * cycle.period
    assert cycle.stick_time + cycle.slip_time == pytest.approx(cycle.period, rel=1e-12)
    assert cycle.v_max > 0.5  # faster than the belt: reverse slip


def test_under_strong_damping_the_default_start_is_the_models_own_not_an_x0_refused_as_the_users():
    """The default start of a cycle search is the stick segment's upper end ``(f_s N - c V) / k``: with
    c V >> f_s N it lies c V / k from steady sliding, and the start's bound (a multiple of the model's
    length scale) refused it as ``invalid x0 = -599999.6``, an option the user never gave (found by the
    deep fuzz: `oscillator continue --damping 3000001`). The length scale holds c V / k: the search runs
    and says what it finds (here no cycle: the orbit is overdamped)."""
    osc = Oscillator(1.0, 1.0, 1.0, 0.2, Coulomb(0.6, 0.4), damping=3000001.0)
    x0, v0 = osc.start(osc.stick_limits[1], osc.belt_speed)
    assert x0 == osc.stick_limits[1]
    with pytest.raises(NoSolutionError):
        limit_cycle(osc)
    with pytest.raises(ParameterError, match="x0"):  # a start the user gives far beyond every scale is still refused
        osc.start(osc.equilibrium - 1e15, osc.belt_speed)
