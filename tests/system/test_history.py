"""A force given in time (`ForceHistory`, linear between points): a stuck block loaded by a ramp
against the closed form of its release and slip, a piecewise force on a damped two-mass structure
against scipy's DOP853 run piece by piece, a sampled harmonic force converging at second order in
the spacing to the exact harmonic run, and the refusals."""

import numpy as np
import pytest
from scipy.integrate import solve_ivp

from stickslip.errors import ParameterError
from stickslip.friction import Coulomb
from stickslip.system import (Contact, ForceHistory, Harmonic, System, forced_response, limit_cycle, simulate,
                              steady_sliding, system_from_dict)


def ramp_block(m=2.0, N=10.0, fs=0.6, fd=0.4, r=3.0, start=0.0):
    """A block at rest on a fixed surface, pushed by a force growing at r [N/s] from t = start."""
    history = ForceHistory([start, start + 100.0], [[0.0], [100.0 * r]])
    return System([[m]], [[0.0]], [Contact([1.0], N, Coulomb(fs, fd), 0.0)], history=history)


@pytest.mark.parametrize("start", [0.0, 0.7])
def test_a_block_loaded_by_a_ramp_slips_when_the_force_reaches_fs_n(start):
    # stuck until r (t - start) = f_s N; then m v' = r (t - start) - f_d N: both in closed form
    m, N, fs, fd, r = 2.0, 10.0, 0.6, 0.4, 3.0
    run = simulate(ramp_block(m, N, fs, fd, r, start), t_end=start + 4.0, samples=401)
    release = fs * N / r
    assert run.event_time.size == 1 and run.event_state[0] == 1 - 2 * (run.v[-1, 0] > 0)
    assert run.event_time[0] - start == pytest.approx(release, rel=1e-13)
    s = run.t - start
    late = s > release
    u = s[late] - release
    v = (r * (s[late] ** 2 - release ** 2) / 2 - fd * N * u) / m
    x = (r * ((s[late] ** 3 - release ** 3) / 6 - release ** 2 * u / 2) - fd * N * u ** 2 / 2) / m
    assert np.allclose(run.v[late, 0], v, rtol=1e-11, atol=1e-12 * v.max())
    assert np.allclose(run.x[late, 0], x, rtol=1e-11, atol=1e-12 * x.max())
    before = s < release  # stuck, the friction holding the load (the sample at the release slips)
    assert np.all(run.x[before, 0] == 0.0) and np.all(run.friction_force[before, 0] == pytest.approx(
        -np.clip(r * s[before], 0.0, None), abs=1e-12))


def piecewise_system():
    M = np.diag([1.0, 0.7])
    K = np.array([[3.0, -1.2], [-1.2, 2.0]])
    C = 0.05 * K + 0.02 * M
    times = [0.3, 1.1, 2.0, 2.05, 4.4, 6.0]
    forces = [[0.0, 0.1], [1.5, -0.4], [-0.5, 0.8], [-0.5, 0.9], [2.0, 0.0], [0.3, 0.3]]
    # a belt so fast the contact never sticks: its friction is the constant f_d N against the belt
    return System(M, K, [Contact([1.0, -1.0], 0.4, Coulomb(0.5, 0.3), 50.0)], damping=C,
                  history=ForceHistory(times, forces), force=[0.2, 0.0])


def test_a_piecewise_force_moves_the_structure_as_an_independent_integrator_does():
    system = piecewise_system()
    run = simulate(system, x0=[0.1, -0.2], v0=[0.0, 0.3], t_end=8.0, samples=161)
    assert run.event_time.size == 0 and np.all(run.states == 1)
    M, K, C = system.mass, system.stiffness, system.damping
    h = system.history
    friction = np.array([1.0, -1.0]) * 0.3 * 0.4  # slipping forwards: F = +f_d N along w

    def rhs(t, y):
        f = system.force + np.array([np.interp(t, h.times, col) for col in h.forces.T]) + friction
        return np.concatenate([y[2:], np.linalg.solve(M, f - K @ y[:2] - C @ y[2:])])

    edges = [0.0, *h.times, 8.0]
    y, want = np.array([0.1, -0.2, 0.0, 0.3]), []
    for a, b in zip(edges[:-1], edges[1:]):  # piece by piece: the force's kinks are the pieces' ends
        ts = run.t[(run.t >= a) & (run.t < b)] if b < 8.0 else run.t[run.t >= a]
        sol = solve_ivp(rhs, (a, b), y, method="DOP853", rtol=1e-13, atol=1e-14, t_eval=ts)
        want.append(sol.y.T)
        y = solve_ivp(rhs, (a, b), y, method="DOP853", rtol=1e-13, atol=1e-14).y[:, -1]
    want = np.vstack(want)
    assert np.abs(run.x - want[:, :2]).max() < 1e-10 * np.abs(want[:, :2]).max()
    assert np.abs(run.v - want[:, 2:]).max() < 1e-10 * np.abs(want[:, 2:]).max()


def test_a_sampled_harmonic_force_converges_at_second_order_with_stick_slip():
    # one mass on a spring against a belt, driven by 0.8 sin(1.3 t): stick-slip events; the force
    # sampled every dt and followed linearly converges to the exact harmonic run as dt^2
    def system(history=None, harmonic=True):
        return System([[1.0]], [[1.0]], [Contact([1.0], 1.0, Coulomb(0.5, 0.35), 0.2)], damping=[[0.05]],
                      harmonics=[Harmonic(1.3, sin=[0.8])] if harmonic else (), history=history)

    exact = simulate(system(), t_end=20.0, samples=2)
    assert exact.event_time.size >= 6  # sticks and slips within the run
    errors = []
    for dt in (0.04, 0.02, 0.01):
        t = np.arange(0.0, 20.0 + dt, dt)
        run = simulate(system(ForceHistory(t, 0.8 * np.sin(1.3 * t)[:, None]), harmonic=False), t_end=20.0, samples=2)
        assert run.event_time.size == exact.event_time.size
        errors.append(max(abs(run.x[-1, 0] - exact.x[-1, 0]), abs(run.v[-1, 0] - exact.v[-1, 0])))
    orders = np.log2(np.array(errors[:-1]) / np.array(errors[1:]))
    assert np.all((orders > 1.8) & (orders < 2.2)), (errors, orders)


def test_before_the_first_time_and_after_the_last_the_force_is_held():
    # a free block on a fast belt: m v' = h(t) + f_d N; h = 1 before t = 1, -2 after t = 2, linear between
    system = System([[1.0]], [[0.0]], [Contact([1.0], 1.0, Coulomb(0.3, 0.3), 1e3)],
                    history=ForceHistory([1.0, 2.0], [[1.0], [-2.0]]))
    run = simulate(system, t_end=3.0, samples=4)
    impulse = np.array([0.0, 1.0, 1.0 - 0.5, 1.0 - 0.5 - 2.0])  # integral of h over [0, t]
    assert np.allclose(run.v[:, 0], impulse + 0.3 * run.t, rtol=0, atol=1e-13)


def test_a_force_in_time_is_refused_where_the_force_must_be_constant_or_periodic():
    system = piecewise_system()
    for call in (lambda: steady_sliding(system), lambda: limit_cycle(system), lambda: forced_response(system),
                 lambda: simulate(system, t_end=1.0, segments=True)):
        with pytest.raises(ParameterError) as err:
            call()
        assert err.value.name == "history" and "6 points" in str(err.value)


@pytest.mark.parametrize("times, forces, name, words", [
    ([0.0, 1.0, 1.0], [[0.0], [1.0], [2.0]], "times", "increasing (times[2] = 1 follows times[1] = 1)"),
    ([0.0, 2.0, 1.0], [[0.0], [1.0], [2.0]], "times", "increasing"),
    ([-1.0, 1.0], [[0.0], [1.0]], "times", "[0, 1e15]"),
    ([0.0, 1e300], [[0.0], [1.0]], "times", "[0, 1e15]"),
    ([0.0, float("nan")], [[0.0], [1.0]], "times", "nan"),
    ([0.0, 1.0], [[0.0], [1e300]], "forces", "[-1e15, 1e15]"),
    ([0.0, 1.0], [[0.0]], "forces", "one list of forces per time"),
    ([], [], "times", "a list of 1 to"),
    ([[0.0, 1.0]], [[0.0], [1.0]], "times", "a list of 1 to"),
])
def test_a_bad_history_is_refused_naming_it(times, forces, name, words):
    with pytest.raises(ParameterError) as err:
        ForceHistory(times, forces)
    assert err.value.name == name and words in str(err.value)


def test_a_history_with_the_wrong_count_of_forces_names_the_system_field():
    with pytest.raises(ParameterError) as err:
        System(np.eye(2), np.eye(2), [Contact([1.0, 0.0], 1.0, Coulomb(0.3, 0.3))],
               history=ForceHistory([0.0, 1.0], [[0.0], [1.0]]))
    assert err.value.name == "history.forces" and "2 numbers per time" in str(err.value)
    with pytest.raises(ParameterError) as err:
        System(np.eye(1), np.eye(1), [Contact([1.0], 1.0, Coulomb(0.3, 0.3))], history=[[0.0, 1.0]])
    assert err.value.name == "history"


def test_a_file_gives_its_history_and_names_its_keys():
    base = {"mass": [[1.0]], "stiffness": [[0.0]],
            "contact": [{"direction": [1.0], "normal_force": 10.0, "fs": 0.6, "fd": 0.4}]}
    system = system_from_dict({**base, "history": {"times": [0.0, 100.0], "forces": [[0.0], [300.0]]}})
    assert simulate(system, t_end=4.0).event_time[0] == pytest.approx(2.0, rel=1e-13)
    for history, name in (({"times": [0.0, 1.0]}, "history.forces"), ({"times": [1.0, 0.0], "forces": [[0.0], [1.0]]},
                                                                        "history.times"),
                          ({"times": [0.0], "forces": [[0.0]], "rate": 1.0}, "history.rate"), ([1.0], "history")):
        with pytest.raises(ParameterError) as err:
            system_from_dict({**base, "history": history})
        assert err.value.name == name


def test_the_command_line_follows_a_history_and_refuses_a_bad_one_in_one_line(tmp_path, capsys):
    import json

    from stickslip.cli import run
    text = """mass = [[2.0]]
stiffness = [[0.0]]
[[contact]]
direction = [1.0]
normal_force = 10.0
fs = 0.6
fd = 0.4
[history]
times = [0.0, 100.0]
forces = [[0.0], [300.0]]
"""
    path = tmp_path / "ramp.toml"
    path.write_text(text)
    assert run(["system", "simulate", str(path), "--t-end", "4", "--json"]) == 0
    out = json.loads(capsys.readouterr().out)
    assert out["events"] == 1 and out["v_end"][0] == pytest.approx(5.0, rel=1e-12)
    path.write_text(text.replace("times = [0.0, 100.0]", "times = [100.0, 0.0]"))
    assert run(["system", "simulate", str(path), "--t-end", "4"]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "history.times" in err and "increasing" in err


def test_a_rate_and_state_system_takes_the_history_into_its_force():
    # consistency (two paths of our own): a history held at 0.3 N is the constant force 0.3 N
    from stickslip.rsf import RateState
    from stickslip.system import rate_state_simulate
    contact = Contact([1.0], 10.0, RateState(a=0.01, b=0.015, dc=1e-5, f0=0.6, evolution="slip"), 1e-6)
    held = System([[1000.0]], [[4504.5]], [contact], history=ForceHistory([0.0, 5.0], [[0.3], [0.3]]))
    constant = System([[1000.0]], [[4504.5]], [contact], force=[0.3])
    a, b = (rate_state_simulate(s, t_end=20.0, samples=3) for s in (held, constant))
    assert np.abs(a.x - b.x).max() <= 1e-9 * np.abs(b.x).max() and abs(b.x[-1, 0]) > 1e-5
