"""Travelling waves of the reduced model (paper eqs. [14]-[20]).

Every check is against something computed another way: closed-form zone solutions
against `solve_ivp`, the multiple-shooting solution against the event-driven return map,
switching conditions and inequalities on fine grids, the energy balance over a period,
the scaling ``delta/sqrt(gamma)`` and the sign theorem for the direction of stick-slip
waves.
"""

import json
import math

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from stickslip.brake import BrakeParams, coefficients
from stickslip.brake.waves.boundsco import Layout, residual, verify
from stickslip.brake.waves.checks import energy_balance, integrate_wave
from stickslip.brake.waves.shoot import stick_exit_orbit
from stickslip.brake.waves.zones import REVERSE, SEPARATION, SLIP, STICK, Scaling, ZoneFlows
from stickslip.brake.waves.solve import TravellingWave, find_waves, solve_layout, travelling_wave
from stickslip.errors import NoSolutionError, ParameterError

COEF = coefficients(1.5, 0.3, 1.0)  # internal units (gamma = 1)
THICK = dict(xi=1.5, nu=0.3, gamma=1.0)  # D < 0: waves run against the shaft (c < 0)
THIN = dict(xi=1.1, nu=0.4, gamma=1.0)  # D > 0: waves run with the shaft (c > 0)

# (params, n, expected structure): one wave per regime, found by the default scan
CASES = {
    "stick-slip": (BrakeParams(**THICK, delta=1.0, friction=0.2), 4, "stick|slip"),
    "stick-slip-separation": (BrakeParams(**THICK, delta=0.01, friction=0.7), 4, "stick|slip|separation"),
    "reverse": (BrakeParams(**THICK, delta=0.05, friction=0.2), 8, "stick|slip|separation|slip|reverse-slip"),
    "thin": (BrakeParams(**THIN, delta=1.0, friction=0.2), 4, "stick|slip"),
}


@pytest.fixture(scope="module")
def waves():
    return {k: travelling_wave(p, n) for k, (p, n, _) in CASES.items()}


# --- zone closed forms ------------------------------------------------------------------
def _rhs_from_eq15(fl, kind):
    """[15] written out directly (no matrices): U'' and V'' with the zone's P and Q."""
    def rhs(_, y):
        U, dU, V, dV = y
        if kind == SEPARATION:
            P = Q = 0.0
            return [dU, (P + fl.D * dV - fl.g * U) / fl.cb, dV, (Q - fl.D * dU - fl.h * V) / fl.ca]
        if kind == STICK:
            return [0.0, 0.0, dV, 0.0]
        s = 1.0 if kind == SLIP else -1.0
        P = fl.g * U - fl.D * dV  # (c^2 - b) U'' = 0 in contact
        return [0.0, 0.0, dV, (s * fl.f * P - fl.h * V) / fl.ca]
    return rhs


@pytest.mark.parametrize("kind", [STICK, SLIP, REVERSE, SEPARATION])
@pytest.mark.parametrize("c", [-1.3, -1.05, 1.2])
def test_zone_closed_forms_agree_with_solve_ivp(kind, c):
    fl = ZoneFlows(COEF, 0.7, 0.3, c)
    y0 = np.array([0.3, 0.0, 0.12, -1.0 / c]) if kind != SEPARATION else np.array([0.31, 0.02, 0.1, 0.4])
    s = np.linspace(0.0, 0.8, 9)
    for span in (s, -s):  # both directions in phi
        sol = solve_ivp(_rhs_from_eq15(fl, kind), (0.0, span[-1]), y0, method="DOP853", rtol=1e-12, atol=1e-14,
                        t_eval=span)
        closed = fl.flow(kind, y0, span)
        assert np.max(np.abs(sol.y.T - closed)) < 1e-10 * np.max(np.abs(closed))


def test_slip_flow_is_exact_through_its_double_root():
    # (c^2 - a) lambda^2 + f D lambda + h = 0 has a double root where f^2 D^2 = 4 h (c^2 - a)
    f = 0.7
    c = -math.sqrt(COEF.a + (f * COEF.D) ** 2 / (4 * COEF.h))
    y0, s = np.array([0.3, 0.0, 0.1, -1 / c]), np.linspace(0, 1.5, 7)
    for cc in (c, c * (1 + 1e-9), c * (1 - 1e-9)):
        fl = ZoneFlows(COEF, f, 0.3, cc)
        sol = solve_ivp(_rhs_from_eq15(fl, SLIP), (0, 1.5), y0, method="DOP853", rtol=1e-12, atol=1e-14, t_eval=s)
        closed = fl.flow(SLIP, y0, s)
        assert np.max(np.abs(sol.y.T - closed)) < 1e-10 * np.max(np.abs(closed))


def test_zone_matrices_are_the_zone_equations():
    fl = ZoneFlows(COEF, 0.7, 0.3, -1.2)
    y = np.array([0.31, 0.02, 0.1, 0.4])
    for kind in (SLIP, REVERSE, SEPARATION):
        dy = fl.matrix(kind) @ y
        d2U, d2V = fl.second_derivatives(kind, y)
        assert dy[1] == pytest.approx(d2U if kind == SEPARATION else 0.0) and dy[3] == pytest.approx(d2V)


def test_stick_pressure_is_constant_and_traction_linear():
    fl = ZoneFlows(COEF, 0.7, 0.3, -1.2)
    Y = fl.flow(STICK, np.array([0.3, 0.0, 0.1, -1 / -1.2]), np.linspace(0, 1, 11))
    assert np.ptp(fl.pressure(STICK, Y)) < 1e-14 and fl.pressure(STICK, Y)[0] == pytest.approx(fl.stick_pressure())
    assert np.ptp(np.diff(fl.traction(STICK, Y))) < 1e-14


# --- the waves ------------------------------------------------------------------------------
@pytest.mark.parametrize("case", list(CASES))
def test_default_scan_finds_one_wave_per_regime(waves, case):
    w = waves[case]
    assert w.structure == CASES[case][2]
    assert w.valid and w.residual < 1e-10
    assert w.zones[0].kind == STICK and w.zones[0].start == 0.0  # the phase condition
    assert w.zones[-1].end == pytest.approx(2 * math.pi / w.n, abs=1e-12)
    assert all(z1.end == pytest.approx(z2.start) for z1, z2 in zip(w.zones, w.zones[1:]))


@pytest.mark.parametrize("case", list(CASES))
def test_switching_conditions_hold_at_the_switching_points(waves, case):
    w = waves[case]
    fl, starts = w._flows(), w._starts
    P_st = fl.stick_pressure()
    for i, z in enumerate(w.zones):
        y_end = fl.flow(z.kind, starts[i], np.array(z.length))
        nxt = w.zones[(i + 1) % len(w.zones)]
        time_forward = w.layout.direction > 0
        early, late = (z.kind, nxt.kind) if time_forward else (nxt.kind, z.kind)
        y_early = y_end if time_forward else starts[(i + 1) % len(w.zones)]
        if early == STICK:  # stick -> slip: Q = f P
            assert fl.h * y_early[2] == pytest.approx(fl.f * P_st, rel=1e-10)
        elif early in (SLIP, REVERSE) and late == SEPARATION:  # lift-off: P = 0, U' = 0
            assert abs(fl.pressure(early, y_early)) < 1e-10 * P_st
        elif early in (SLIP, REVERSE):  # slip velocity reaches 0
            assert abs(fl.slip_velocity(y_early)) < 1e-10
        else:  # landing: U = delta
            assert y_early[0] == pytest.approx(fl.delta, rel=1e-11)


@pytest.mark.parametrize("case", list(CASES))
def test_inequalities_hold_on_a_fine_grid_in_paper_units(waves, case):
    w = waves[case]
    phi = np.linspace(0, w.period, 20001)
    prof = w.evaluate(phi)
    kinds = np.array([w.zones[i].kind for i in prof["zone"]])
    delta, f = w.params.delta, w.params.friction
    contact = kinds != SEPARATION
    P, Q, U = prof["P"], prof["Q"], prof["U"]
    assert np.all(U[contact] == pytest.approx(delta, rel=1e-12))
    assert np.all(U[~contact] >= delta * (1 - 1e-12))
    assert np.all(P[contact] >= -1e-9 * P.max()) and np.all(P[~contact] == 0)
    assert np.all(np.abs(Q[kinds == STICK]) <= f * P[kinds == STICK] * (1 + 1e-12))
    w_slip = prof["slip_velocity"]
    assert np.all(w_slip[kinds == SLIP] >= -1e-9) and np.all(w_slip[kinds == REVERSE] <= 1e-9)
    dV = prof["dV"][kinds == STICK]  # stick: V_t = -c V' = 1 (the shaft surface speed)
    assert np.allclose(-w.c * dV, 1.0, rtol=1e-12)


@pytest.mark.parametrize("case", list(CASES))
def test_closed_forms_agree_with_solve_ivp_across_the_zones(waves, case):
    r = integrate_wave(waves[case])
    assert r["profile_error"] < 1e-7 and r["switching"] < 1e-8 and r["periodicity"] < 1e-8


@pytest.mark.parametrize("case", list(CASES))
def test_energy_balance_over_a_period(waves, case):
    e = energy_balance(waves[case])
    assert e["residual"] < 1e-10 and abs(e["ring_work"]) < 1e-10
    assert e["sliding"] > 0 and e["impacts"] >= 0
    assert (e["impacts"] > 0) == ("separation" in waves[case].structure)


def test_energy_balance_detects_a_wrong_wave(waves):
    w = waves["stick-slip-separation"]
    bad = TravellingWave(w.params, w.n, w.c, w.zones, w.residual, w.margins, w.layout, w.x * (1 + 1e-3))
    assert energy_balance(bad)["residual"] > 1e-4
    assert integrate_wave(bad)["switching"] > 1e-5


@pytest.mark.parametrize("case", list(CASES))
def test_return_map_and_multiple_shooting_agree(waves, case):
    w = waves[case]
    sc = Scaling(w.params)
    orbit = stick_exit_orbit(ZoneFlows(sc.coefficients, w.params.friction, sc.delta, w.x[0]), 3 * w.period)
    assert orbit.closed and orbit.period == pytest.approx(w.period, rel=1e-10)
    kinds = [k for k, *_ in orbit.zones]
    assert sorted(kinds) == sorted(z.kind for z in w.zones)


@pytest.mark.parametrize("case", ["stick-slip-separation", "reverse", "thin"])
def test_result_does_not_depend_on_the_phase_condition(waves, case):
    w = waves[case]
    c, lengths, starts = w.layout.unpack(w.x, Scaling(w.params).delta)
    m = len(w.zones)
    for k in range(1, m):
        lay = w.layout.rotate(k)
        x0 = lay.pack(c, list(lengths[k:]) + list(lengths[:k]), starts[k:] + starts[:k])
        x0 = x0 * (1 + 1e-4 * np.cos(np.arange(x0.size)))  # start off the solution
        other = solve_layout(w.params, w.n, lay, x0)
        assert other.valid and other.c == pytest.approx(w.c, rel=1e-11)
        assert [z.length for z in other.zones] == pytest.approx(list(lengths[k:]) + list(lengths[:k]), abs=1e-10)
        phi = np.linspace(0, w.period, 101)
        a, b = w.evaluate(phi + w.zones[k].start), other.evaluate(phi)
        assert np.max(np.abs(a["V"] - b["V"])) < 1e-9 * np.max(np.abs(a["V"]))


def test_waves_depend_on_delta_over_sqrt_gamma_only():
    p1 = BrakeParams(**{**THICK, "gamma": 1.0}, delta=0.05, friction=0.2)
    p2 = BrakeParams(**{**THICK, "gamma": 4e-6}, delta=0.05 * 2e-3, friction=0.2)
    w1, w2 = travelling_wave(p1, 8), travelling_wave(p2, 8)
    assert w1.structure == w2.structure
    assert w2.c * math.sqrt(p2.gamma) == pytest.approx(w1.c, rel=1e-10)
    phi = np.linspace(0, w1.period, 50)
    assert w2.evaluate(phi)["V"] / 2e-3 == pytest.approx(w1.evaluate(phi)["V"], rel=1e-8, abs=1e-12)
    assert w2.evaluate(phi)["P"] * 2e-3 == pytest.approx(w1.evaluate(phi)["P"], rel=1e-8, abs=1e-9)


def test_stick_slip_waves_do_not_depend_on_the_mismatch(waves):
    w = waves["stick-slip"]
    other = travelling_wave(w.params.replace(delta=3.0), w.n, guess=w)
    assert other.structure == "stick|slip" and other.c == pytest.approx(w.c, rel=1e-12)
    phi = np.linspace(0, w.period, 50)
    shift = w.params.friction * (3.0 - 1.0) * COEF.g / COEF.h  # V_e = f g delta / h moves, nothing else
    assert other.evaluate(phi)["V"] - w.evaluate(phi)["V"] == pytest.approx(np.full(50, shift), rel=1e-10)


def test_stick_slip_waves_run_in_the_direction_of_D():
    # energy: (1/c) int_stick (f g delta - h V) = f D int_slip V'^2, and |h V| < f P in stick
    for params in (CASES["stick-slip"][0], CASES["thin"][0]):
        D = params.coefficients().D
        a = math.sqrt(params.coefficients().a)
        wrong = -math.copysign(1.0, D) * a * np.array([1.001, 6.0])
        assert find_waves(params, 4, c_range=tuple(wrong), num=60) == []
        assert all(np.sign(w.c) == np.sign(D) for w in find_waves(params, 4))


def test_slip_zone_exponents_solve_the_flutter_dispersion_relation(waves):
    # e^{lambda phi} = e^{i k theta + s t} with k = -i lambda, s = -lambda c: [12] linearised
    w = waves["stick-slip"]
    co, f, c = w.params.coefficients(), w.params.friction, w.c
    M = w._flows().matrix(SLIP)[2:, 2:] / np.sqrt(w.params.gamma)  # phi-rates are unit-free
    for lam in np.linalg.eigvals(M):
        k, s = -1j * lam, -lam * c
        assert abs(s**2 + co.a * k**2 + co.h + 1j * k * f * co.D) < 1e-9 * abs(co.a * k**2)


def test_stick_separation_waves_do_not_exist():
    """W5. In stick U = delta and V' = -1/c, so the radial equation (c^2 - b) U'' - D V' + g U = P
    gives the constant P = g delta + D/c. Lift-off straight from stick needs P = 0 at the stick
    exit, hence over the whole zone (c = c* = -D/(g delta)); there Coulomb's |Q| <= f P = 0 needs
    Q = h V + D U' = h V to vanish on an interval, while V' = -1/c != 0. So the solver must refuse
    the regime, and a stick zone of positive length with P -> 0 must fail the inequalities."""
    p = CASES["stick-slip-separation"][0]
    with pytest.raises(NoSolutionError, match="no stick-separation wave"):
        travelling_wave(p, 4, regime="stick-separation")
    sc = Scaling(p)
    co = sc.coefficients
    s = np.linspace(0.0, 0.5, 11)
    for c in (-1.3, -2.0, 1.7):  # P is constant along any stick zone, from the radial equation with U'' = 0
        fl = ZoneFlows(co, p.friction, sc.delta, c)
        Y = fl.flow(STICK, [sc.delta, 0.0, 0.2, -1.0 / c], s)
        assert np.allclose(fl.pressure(STICK, Y), co.g * sc.delta + co.D / c, rtol=1e-13, atol=0)
        assert fl.stick_pressure() == pytest.approx(co.g * sc.delta + co.D / c, rel=1e-14)
    c_star = -co.D / (co.g * sc.delta)
    fl = ZoneFlows(co, p.friction, sc.delta, c_star)
    y0 = [sc.delta, 0.0, 0.2, -1.0 / c_star]
    Q = fl.traction(STICK, fl.flow(STICK, y0, s))
    assert abs(fl.stick_pressure()) < 1e-12 * co.g * sc.delta
    assert np.allclose(np.diff(Q), -co.h / c_star * np.diff(s), rtol=1e-10)  # Q = h V moves: |Q| <= 0 fails
    # near c*, Coulomb allows a stick zone of length at most 2 f P |c| / h (-> 0 at c*): a longer
    # stick zone followed by separation is rejected by the checks of [17]-[20]
    c = 1.05 * c_star
    fl = ZoneFlows(co, p.friction, sc.delta, c)
    longest = 2 * p.friction * fl.stick_pressure() * abs(c) / co.h
    L = 2.0 * longest
    y0 = [sc.delta, 0.0, L / (2 * c), -1.0 / c]  # the best placed zone: Q = h V runs from -hL/2c to hL/2c
    lay = Layout((STICK, SEPARATION), direction=int(np.sign(c)))
    x = lay.pack(c, [L, 1.0], [y0, fl.flow(STICK, y0, L)])
    assert 0 < longest < 0.01 and verify(lay, x, co, p.friction, sc.delta)["stick_friction"] < -0.5


def test_to_dict_is_json_ready_and_to_xarray_has_units(waves):
    w = waves["reverse"]
    d = json.loads(json.dumps(w.to_dict()))
    assert {"c", "regime", "zones", "n"} <= set(d)
    assert d["regime"] == "stick-slip-separation-reverse-slip" and d["n"] == 8
    assert [z["kind"] for z in d["zones"]] == w.structure.split("|")
    assert d["impacts"] and d["impacts"][0]["normal_impulse"] > 0
    ds = w.to_xarray(201)
    assert ds["U"].attrs["scale"] == "R" and ds["phi"].attrs["units"] == "rad" and ds.attrs["n"] == 8
    assert ds.sizes["phi"] == 201


def test_evaluate_is_periodic(waves):
    w = waves["reverse"]
    phi = np.linspace(0.01, 0.7, 13)
    a, b = w.evaluate(phi), w.evaluate(phi + 3 * w.period)
    assert np.allclose(a["V"], b["V"], rtol=1e-12, atol=0)


def test_physical_parameters_give_the_wave_speed_in_rad_per_s():
    p = BrakeParams.from_physical(50.0, 1e-4, 0.2)
    w = travelling_wave(p, 4)
    assert w.wave_speed_si == pytest.approx(w.c * 50.0)
    assert "wave_speed_si" in w.to_dict()


@pytest.mark.parametrize("kwargs, name", [
    (dict(modes=0), "modes"), (dict(modes=2.5), "modes"), (dict(modes=True), "modes"),
    (dict(regime="stick-stick"), "regime"), (dict(params="p"), "params"),
    (dict(params=BrakeParams(**THICK, delta=1.0, friction=0.0)), "friction"),
    (dict(c_range=(-1.2, 1.2)), "c_range"), (dict(c_range=(-1.2, -1.2)), "c_range")])
def test_bad_input_raises_parameter_error(kwargs, name):
    args = dict(params=CASES["stick-slip"][0], modes=4) | kwargs
    with pytest.raises(ParameterError, match=name):
        travelling_wave(args.pop("params"), args.pop("modes"), **args)


def test_layout_validation():
    with pytest.raises(ParameterError):
        Layout((STICK, STICK), 1)
    with pytest.raises(ParameterError):
        Layout((STICK,), 1)
    with pytest.raises(ParameterError):
        Layout((STICK, "glide"), 1)
    with pytest.raises(ParameterError):
        Layout((STICK, SLIP), 0)


def test_several_waves_per_mode_number_and_the_default_choice():
    # f = 2: the principal (stick-slip) lobe and near-sonic stick-slip-separation lobes
    p = BrakeParams(**THICK, delta=2.586, friction=2.0)
    ws = find_waves(p, 2)
    assert len(ws) >= 3 and [abs(w.c) for w in ws] == sorted((abs(w.c) for w in ws), reverse=True)
    assert ws[0].structure == "stick|slip" and {w.regime for w in ws[1:]} == {"stick-slip-separation"}
    assert all(w.valid for w in ws) and len({round(w.c, 8) for w in ws}) == len(ws)
    assert travelling_wave(p, 2).c == ws[0].c
    assert travelling_wave(p, 2, regime="stick-slip-separation").c == ws[1].c


def test_no_wave_is_a_clear_error():
    with pytest.raises(NoSolutionError, match="scanned .* wave speeds"):
        travelling_wave(CASES["stick-slip"][0], 200)


def test_guess_from_a_speed_and_from_a_wave(waves):
    w = waves["stick-slip-separation"]
    assert travelling_wave(w.params, w.n, guess=w.c).c == pytest.approx(w.c, rel=1e-12)
    near = travelling_wave(w.params.replace(delta=0.0101), w.n, guess=w)
    assert near.structure == w.structure and near.c == pytest.approx(w.c, rel=1e-2)
    with pytest.raises(NoSolutionError, match="guess"):
        travelling_wave(w.params, w.n, guess=w, regime="stick-slip")


def test_residual_vanishes_only_at_the_solution(waves):
    w = waves["stick-slip"]
    sc = Scaling(w.params)
    args = (w.layout, sc.coefficients, w.params.friction, sc.delta, w.period)
    assert np.max(np.abs(residual(w.x, *args))) < 1e-12
    assert np.max(np.abs(residual(w.x * (1 + 1e-6), *args))) > 1e-8
