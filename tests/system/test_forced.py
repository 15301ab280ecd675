"""Harmonic forces on a system: the motion against closed forms of the linear forced oscillator,
the release of a stuck mass, the periodic response without stops against its piecewise closed
form (Den Hartog's problem, solved here from the equations), the stroboscopic monodromy against
finite differences, and the frequency response along a branch."""

import pathlib

import numpy as np
import pytest
import scipy.linalg
from scipy.optimize import brentq

from stickslip.errors import NoSolutionError, ParameterError
from stickslip.friction import Coulomb
from stickslip.system import (Contact, Harmonic, System, continue_system, forced_response, limit_cycle, monodromy,
                              load_system, simulate, steady_sliding, system_from_dict)
from stickslip.system.continuation import file_parameter
from stickslip.system.forced import stick_basis

from .test_floquet import end_state


def damper(m=1.0, k=1.0, c=0.0, N=1.0, mu=0.2, fs=None, F=1.0, W=0.6, G=0.0, V=0.0):
    """One mass on a spring against a surface moving at V (at rest: a friction damper), driven by
    F cos(W t) + G sin(W t)."""
    law = Coulomb(mu if fs is None else fs, mu)
    return System([[m]], [[k]], [Contact([1.0], N, law, V)], damping=[[c]], harmonics=[Harmonic(W, [F], [G])])


def forced_linear(m, c, k, f0, F, G, W, x0, v0, t):
    """The closed form of m x'' + c x' + k x = f0 + F cos(W t) + G sin(W t) (underdamped)."""
    X = (F - 1j * G) / (k - m * W ** 2 + 1j * c * W)
    xp = (X * np.exp(1j * W * t)).real + f0 / k
    vp = (1j * W * X * np.exp(1j * W * t)).real
    wn = np.sqrt(k / m)
    zeta = c / (2 * np.sqrt(k * m))
    wd = wn * np.sqrt(1 - zeta ** 2)
    a = x0 - (X.real + f0 / k)
    b = (v0 - (1j * W * X).real + zeta * wn * a) / wd
    decay = np.exp(-zeta * wn * t)
    x = decay * (a * np.cos(wd * t) + b * np.sin(wd * t))
    v = decay * ((-zeta * wn * a + wd * b) * np.cos(wd * t) + (-zeta * wn * b - wd * a) * np.sin(wd * t))
    return x + xp, v + vp


def test_an_always_slipping_forced_oscillator_follows_the_closed_form():
    # a belt so fast that the contact never sticks: a constant friction force N fd
    m, c, k, N, fd, F, G, W = 2.0, 0.3, 5.0, 1.5, 0.4, 0.7, -0.2, 1.3
    system = damper(m, k, c, N, fd, fs=0.5, F=F, W=W, G=G, V=1e3)
    run = simulate(system, [0.1], [0.2], 20.0, samples=201)
    assert run.event_time.size == 0
    x, v = forced_linear(m, c, k, N * fd, F, G, W, 0.1, 0.2, run.t)
    assert np.abs(run.x[:, 0] - x).max() < 1e-11
    assert np.abs(run.v[:, 0] - v).max() < 1e-11


def test_two_harmonics_on_two_degrees_of_freedom_add_up():
    # no contact force reaches the structure (a contact whose surface runs away at its own speed): the
    # response to two harmonics on a 2-DOF structure is the sum of the closed forms of its modes
    M = np.diag([1.0, 2.0])
    K = np.array([[3.0, -1.0], [-1.0, 2.0]])
    law = Coulomb(0.3, 0.3)
    contact = Contact([1.0, 0.0], 1e-12, law, 1e3)
    system = System(M, K, [contact], harmonics=[Harmonic(0.7, [0.5, 0.0]), Harmonic(1.9, sin=[0.0, 0.4])])
    run = simulate(system, [0.0, 0.0], [0.0, 0.0], 15.0, samples=151)
    w2, modes = scipy.linalg.eigh(K, M)  # M-orthonormal modes
    x = np.zeros((run.t.size, 2))
    for j in range(2):
        phi = modes[:, j]
        q, _ = forced_linear(1.0, 0.0, w2[j], phi @ [1e-12 * 0.3, 0.0], phi @ [0.5, 0.0], 0.0, 0.7, 0.0, 0.0, run.t)
        q2, _ = forced_linear(1.0, 0.0, w2[j], 0.0, 0.0, phi @ [0.0, 0.4], 1.9, 0.0, 0.0, run.t)
        x += np.outer(q + q2, phi)
    assert np.abs(run.x - x).max() < 1e-11


@pytest.mark.parametrize("W", [0.8, 40.0])
def test_a_stuck_mass_is_released_when_the_harmonic_force_reaches_fs_N(W):
    # at rest on a surface at rest, under F sin(W t): the sticking force is -F sin(W t), released at
    # F sin(W t) = fs N (a force far faster than the structure sets the event search's step)
    F, fs, N = 2.0, 0.5, 1.5
    system = damper(N=N, mu=0.3, fs=fs, F=0.0, G=F, W=W, k=1e-6)
    run = simulate(system, [0.0], [0.0], 2.4 / W, samples=31)
    released = np.arcsin(fs * N / F) / W
    assert run.event_time[0] == pytest.approx(released, abs=1e-12)
    stuck = run.t < released
    assert np.allclose(run.friction_force[stuck, 0], -F * np.sin(W * run.t[stuck]), atol=1e-12)


def nonstop_amplitude(m, k, c, mu_N, F, W):
    """The periodic response of m x'' + c x' + k x + mu_N sign(x') = F cos(W t) without stops,
    from the equations: on the half period where x' > 0, x = e^(-z wn t)(a cos wd t + b sin wd t)
    + Re(X e^(iWt)) - mu_N/k, with x' = 0 at its ends t0, t0 + T/2 and x(t0 + T/2) = -x(t0)
    (the response is odd over half a period). Returns (t0, amplitude)."""
    T = 2 * np.pi / W
    wn, zeta = np.sqrt(k / m), c / (2 * np.sqrt(k * m))
    wd = wn * np.sqrt(1 - zeta ** 2)
    X = F / (k - m * W ** 2 + 1j * c * W)

    def parts(t):
        e = np.exp(-zeta * wn * t)
        basis_x = e * np.array([np.cos(wd * t), np.sin(wd * t)])
        basis_v = e * np.array([-zeta * wn * np.cos(wd * t) - wd * np.sin(wd * t),
                                -zeta * wn * np.sin(wd * t) + wd * np.cos(wd * t)])
        return basis_x, basis_v, (X * np.exp(1j * W * t)).real - mu_N / k, (1j * W * X * np.exp(1j * W * t)).real

    def odd(t0):
        bx0, bv0, p0, q0 = parts(t0)
        bx1, bv1, p1, q1 = parts(t0 + T / 2)
        ab = np.linalg.solve(np.array([bv0, bv1]), -np.array([q0, q1]))
        return bx1 @ ab + p1 + bx0 @ ab + p0, bx0 @ ab + p0

    grid = np.linspace(0.0, T, 2001)
    vals = [odd(t)[0] for t in grid]
    roots = [brentq(lambda t: odd(t)[0], a, b, xtol=1e-15) for a, b, fa, fb in
             zip(grid, grid[1:], vals, vals[1:]) if fa * fb < 0 and abs(fa - fb) < 1.0]
    t0 = next(t for t in roots if odd(t)[1] < 0)  # x' > 0 from the lowest point
    return t0, -odd(t0)[1]


@pytest.mark.parametrize("c, W", [(0.0, 0.6), (0.05, 0.6), (0.05, 1.4)])
def test_the_response_without_stops_is_the_piecewise_closed_form(c, W):
    m, k, mu, N, F = 1.0, 1.0, 0.2, 1.0, 1.0
    response = forced_response(damper(m, k, c, N, mu, F=F, W=W), [0.0], [0.0], tol=1e-12)
    t0, amplitude = nonstop_amplitude(m, k, c, mu * N, F, W)
    assert response.event_time.size == 2 and set(response.event_state.tolist()) == {-1, 1}  # reversals, no stop
    assert response.amplitude[0] == pytest.approx(amplitude, rel=1e-9)  # the extremes are the reversals
    # the reversal from the lowest point (x' turns positive: the slip velocity -x' negative) is at t0
    rising = response.event_time[response.event_state == -1][0]
    assert rising == pytest.approx(t0, abs=1e-9)
    assert response.stable


def test_the_forced_monodromy_matches_finite_differences():
    # two contacts on a belt, two harmonics, stick phases: the switching functions of a sticking contact
    # move with the force, so the saltation matrices need their rate in time too
    M = np.diag([1.0, 1.5])
    K = np.array([[3.0, -1.0], [-1.0, 2.0]])
    C = np.array([[0.06, -0.02], [-0.02, 0.04]])
    contacts = [Contact([1.0, 0.0], 2.0, Coulomb(0.6, 0.4), 0.3), Contact([0.0, 1.0], 1.0, Coulomb(0.5, 0.3), 0.3)]
    system = System(M, K, contacts, damping=C, harmonics=[Harmonic(1.1, [0.5, 0.0], [0.0, 0.2]),
                                                          Harmonic(2.2, [0.1, 0.1])])
    response = forced_response(system, tol=1e-12)
    assert 0 in response.event_state  # a stick phase in the period
    run = simulate(system, response.x0, response.v0, response.period, samples=2, segments=True,
                   states=response.states)
    y = np.concatenate([response.x0, response.v0])
    fd = np.zeros((4, 4))
    for j in range(4):
        d = np.zeros(4)
        d[j] = 1e-7
        fd[:, j] = (end_state(simulate(system, (y + d)[:2], (y + d)[2:], response.period, samples=2))
                    - end_state(simulate(system, (y - d)[:2], (y - d)[2:], response.period, samples=2))) / 2e-7
    assert np.abs(monodromy(system, run) - fd).max() < 1e-6
    assert np.allclose(np.sort(np.abs(response.multipliers)), np.sort(np.abs(np.linalg.eigvals(fd))), atol=1e-6)


def test_a_response_that_sticks_at_phase_zero_has_a_zero_multiplier_and_finite_differences_along_the_stick():
    system = damper(c=0.05, mu=0.5, fs=0.6, W=0.3, G=0.3)
    response = forced_response(system, tol=1e-12)
    assert response.states == (0,)
    run = simulate(system, response.x0, response.v0, response.period, samples=2, segments=True,
                   states=response.states)
    y = np.concatenate([response.x0, response.v0])
    d = np.array([1e-7, 0.0])  # along the stick (a change of velocity would be a start that slips)
    fd = (end_state(simulate(system, (y + d)[:1], (y + d)[1:], response.period, samples=2, states=(0,)))
          - end_state(simulate(system, (y - d)[:1], (y - d)[1:], response.period, samples=2, states=(0,)))) / 2e-7
    assert np.abs(monodromy(system, run)[:, 0] - fd).max() < 1e-6
    assert np.abs(response.multipliers).min() < 1e-12


def test_a_subharmonic_search_finds_the_response_repeated_with_its_multipliers_squared():
    system = damper(c=0.05, W=0.6)
    one = forced_response(system)
    two = forced_response(system, periods=2)
    assert two.period == pytest.approx(2 * one.period, rel=1e-15)
    assert np.allclose(two.x0, one.x0, atol=1e-8) and np.allclose(two.v0, one.v0, atol=1e-8)
    assert np.allclose(np.sort(np.abs(two.multipliers)), np.sort(np.abs(one.multipliers) ** 2), atol=1e-10)


FILE = {"mass": [[1.0]], "stiffness": [[1.0]], "damping": [[0.02]],
        "contact": [{"direction": [1.0], "normal_force": 1.0, "fs": 0.2, "fd": 0.2}],
        "harmonic": [{"frequency": 0.55, "cos": [1.0]}]}


def test_a_frequency_response_along_the_forcing_frequency_has_the_closed_form_without_stops():
    build, start = file_parameter(FILE, "harmonic[0].frequency")
    branch = continue_system(build, start, 1.45, points=5, parameter="harmonic[0].frequency")
    assert branch.forced and branch.stopped.startswith("reached")
    for W, amplitude in zip(branch.values, branch.amplitude[:, 0]):
        # the fixed point to tol = 1e-10 of |y| (37 at resonance), its error amplified by 1/(1 - |mu|) ~ 8 there
        assert amplitude == pytest.approx(nonstop_amplitude(1.0, 1.0, 0.02, 0.2, 1.0, W)[1], rel=1e-8)
    assert branch.to_xarray()["amplitude"].attrs["units"] == "m"


def test_the_file_names_harmonics_and_their_numbers():
    system = system_from_dict(FILE)
    assert system.forcing_period == pytest.approx(2 * np.pi / 0.55)
    for key, value, allowed in [("frequency", 0.0, "(0, 1e15]"), ("frequency", 1e300, "(0, 1e15]"),
                                ("cos", [1.0, 2.0], "1 numbers"), ("cos", [float("nan")], ""), ("size", 1.0, "key")]:
        bad = {**FILE, "harmonic": [{**FILE["harmonic"][0], key: value}]}
        with pytest.raises(ParameterError) as err:
            system_from_dict(bad)
        assert err.value.name == f"harmonic[0].{key}" and allowed in str(err.value)
    with pytest.raises(ParameterError, match="harmonic\\[0\\].frequency"):
        system_from_dict({**FILE, "harmonic": [{"cos": [1.0]}]})
    with pytest.raises(ParameterError, match="harmonic\\[0\\].cos"):
        system_from_dict({**FILE, "harmonic": [{"frequency": 1.0}]})
    with pytest.raises(ParameterError, match="parameter"):
        file_parameter(FILE, "harmonic[0].cos")  # a vector: which entry?
    assert file_parameter(FILE, "harmonic[0].cos[0]")[1] == 1.0


def test_what_needs_a_constant_force_says_so_and_an_aperiodic_force_has_no_response():
    system = damper(c=0.05)
    for call in (lambda: limit_cycle(system), lambda: steady_sliding(damper(V=1.0))):
        with pytest.raises(ParameterError) as err:
            call()
        assert err.value.name == "harmonics" and "forced_response" in str(err.value)
    law = Coulomb(0.2, 0.2)
    aperiodic = System([[1.0]], [[1.0]], [Contact([1.0], 1.0, law)],
                       harmonics=[Harmonic(1.0, [1.0]), Harmonic(np.sqrt(2.0), [1.0])])
    with pytest.raises(ParameterError, match="whole multiples"):
        forced_response(aperiodic)
    with pytest.raises(ParameterError, match="at least one Harmonic"):
        forced_response(System([[1.0]], [[1.0]], [Contact([1.0], 1.0, law)]))
    with pytest.raises(ParameterError) as err:
        System([[1.0]], [[1.0]], [Contact([1.0], 1.0, law)], harmonics=[Harmonic(1.0, [1.0])] * 65)
    assert err.value.name == "harmonics"
    with pytest.raises(ParameterError) as err:
        forced_response(system, periods=0)
    assert err.value.name == "periods"


def test_no_response_near_the_motion_says_what_was_tried():
    # an undamped resonance: the amplitude grows without bound, the map never returns
    system = damper(c=0.0, mu=0.01, W=1.0)
    with pytest.raises(NoSolutionError, match="stroboscopic map"):
        forced_response(system, max_iter=5, transient=10.0)


EXAMPLE = pathlib.Path(__file__).resolve().parents[2] / "examples" / "friction_damper" / "friction_damper.toml"


def test_a_damper_stuck_through_the_period_leaves_its_structure_linear_and_its_position_neutral():
    # the example's damper block sticks at 0.8 rad/s: the structure moves as m x'' + c x' + (k + k_d) x = F
    # cos(W t), whose multipliers are exp(lambda T) of s^2 + 0.01 s + 1.5; the block's position is free
    # (a multiplier 1, neutral) and its velocity is no state (a multiplier 0)
    response = forced_response(load_system(EXAMPLE))
    assert response.event_time.size == 0 and response.states == (0,)
    lam = np.roots([1.0, 0.01, 1.5])
    expected = np.sort(np.abs(np.exp(lam * response.period)))
    mult = np.sort(np.abs(response.multipliers))
    assert mult[0] < 1e-12 and abs(mult[3] - 1.0) < 1e-12
    assert np.allclose(mult[1:3], expected, rtol=1e-10)
    assert response.stable and response.neutral
    X = 0.1 / abs(1.5 - 0.8 ** 2 + 0.01j * 0.8)
    assert response.amplitude[0] == pytest.approx(X, rel=2e-6)  # 2001 samples of a smooth peak: (2 pi / 2000)^2 / 8


def test_a_force_too_slow_for_a_run_names_its_frequency():
    with pytest.raises(ParameterError) as err:
        forced_response(damper(W=1e-300))
    assert err.value.name == "harmonics" and "lowest frequency of at least" in str(err.value)


def test_the_command_line_refuses_a_bad_harmonic_in_one_line(tmp_path, capsys):
    from stickslip.cli import run
    text = EXAMPLE.read_text().replace("frequency = 0.8", "frequency = -0.8")
    path = tmp_path / "bad.toml"
    path.write_text(text)
    assert run(["system", "cycle", str(path)]) == 2
    err = capsys.readouterr().err.strip()
    assert len(err.splitlines()) == 1 and "harmonic[0].frequency" in err and "-0.8" in err
    assert run(["system", "cycle", str(EXAMPLE), "--periods", "0"]) == 2
    assert "--periods" in capsys.readouterr().err


def test_a_contact_released_because_another_sticks_has_its_saltation():
    # two contacts share the load: when contact 0 sticks, the force moves to contact 1, which is released at
    # the same instant without a switching function of its own reaching zero; the field after the event is
    # that of both changes (finite differences of whole runs on the stick of the start)
    M = np.diag([1.0, 0.5])
    K = np.array([[2.0, -1.0], [-1.0, 1.0]])
    contacts = [Contact([0.0, 1.0], 0.3, Coulomb(0.35, 0.3)), Contact([1.0, -1.0], 0.2, Coulomb(0.4, 0.3))]
    system = System(M, K, contacts, damping=0.01 * K + 0.005 * M, harmonics=[Harmonic(0.7, [0.15, 0.0], [0.0, 0.05])])
    response = forced_response(system, tol=1e-12)
    run = simulate(system, response.x0, response.v0, response.period, samples=2, segments=True, states=response.states)
    flows = {}
    from stickslip.system import Flow
    consequential = [seg for seg in run.segments if seg.rows and any(
        a != b and i not in {int(Flow.cached(system, seg.states, flows).owners[r]) for r in seg.rows}
        for i, (a, b) in enumerate(zip(seg.states, seg.after)))]
    assert consequential  # the case this test is about
    Q = stick_basis(system, response.states)
    y = np.concatenate([response.x0, response.v0])
    fd = np.zeros((4, Q.shape[1]))
    for j in range(Q.shape[1]):
        ends = [end_state(simulate(system, (y + s * 1e-6 * Q[:, j])[:2], (y + s * 1e-6 * Q[:, j])[2:], response.period,
                                   samples=2, states=response.states)) for s in (1, -1)]
        fd[:, j] = (ends[0] - ends[1]) / 2e-6
    assert np.abs(monodromy(system, run) @ Q - fd).max() < 1e-6
    expected = np.sort(np.abs(np.linalg.eigvals(Q.T @ fd)))[::-1]
    assert np.allclose(np.abs(response.multipliers[:expected.size]), expected, atol=1e-6)


def test_the_response_scales_with_the_forces():
    # Coulomb contacts and a linear structure: forces (harmonic and normal) scaled by s scale the response by s
    # exactly, down to sizes far below one (the tolerance is relative to the orbit's own size)
    M = np.diag([1.0, 0.5])
    K = np.array([[2.0, -1.0], [-1.0, 1.0]])

    def build(s):
        contacts = [Contact([0.0, 1.0], 0.3 * s, Coulomb(0.35, 0.3)), Contact([1.0, -1.0], 0.2 * s, Coulomb(0.4, 0.3))]
        return System(M, K, contacts, damping=0.01 * K + 0.005 * M,
                      harmonics=[Harmonic(0.85, [0.2 * s, 0.0], [0.0, 0.05 * s])])
    one = forced_response(build(1.0))
    for s in (1e-4, 1e-8):
        small = forced_response(build(s))
        assert np.abs(small.x0 / s - one.x0).max() < 1e-8 * np.abs(one.x0).max()
        assert np.allclose(np.abs(small.multipliers), np.abs(one.multipliers), atol=1e-8)


def test_two_stuck_contacts_are_released_each_when_its_own_harmonic_force_reaches_its_limit():
    # two masses, uncoupled, each stuck on its own surface at rest under its own F_i sin(W t): released at
    # arcsin(fs_i N_i / F_i) / W, the sticking forces -F_i sin(W t) before
    contacts = [Contact([1.0, 0.0], 1.0, Coulomb(0.5, 0.3)), Contact([0.0, 1.0], 2.0, Coulomb(0.4, 0.3))]
    F, W = np.array([1.5, 1.2]), 0.9
    system = System(np.eye(2), 1e-6 * np.eye(2), contacts, harmonics=[Harmonic(W, sin=F)])
    run = simulate(system, [0.0, 0.0], [0.0, 0.0], 2.0 / W, samples=41)
    released = np.arcsin(np.array([0.5 * 1.0, 0.4 * 2.0]) / F) / W
    for i in range(2):
        assert run.event_time[run.event_contact == i][0] == pytest.approx(released[i], abs=1e-12)
        stuck = run.t < released.min()
        assert np.allclose(run.friction_force[stuck, i], -F[i] * np.sin(W * run.t[stuck]), atol=1e-12)


def test_a_subharmonic_longer_than_a_run_names_the_force_and_its_periods():
    with pytest.raises(ParameterError) as err:
        forced_response(damper(W=1e-3), periods=1000)
    assert err.value.name == "harmonics" and "periods" in err.value.also


def test_a_branch_that_makes_the_force_aperiodic_stops_saying_so():
    table = {**FILE, "harmonic": FILE["harmonic"] + [{"frequency": 1.1, "sin": [0.05]}]}
    build, start = file_parameter(table, "harmonic[0].frequency")
    branch = continue_system(build, start, 0.6, points=3, parameter="harmonic[0].frequency")
    assert branch.values.size == 1 and "whole multiples" in branch.stopped and branch.events[0]["change"] == "refused"


def test_engine_orders_scale_every_harmonic_with_the_lowest_along_the_branch():
    # a belt so fast the contact always slips (a constant friction N fd): the periodic response to
    # 0.5 cos(W t) + 0.3 sin(2 W t) is the sum of the linear closed forms at W and 2 W, with W the parameter
    m, c, k, N, fd = 1.0, 0.1, 1.0, 0.5, 0.3
    data = {"mass": [[m]], "stiffness": [[k]], "damping": [[c]],
            "contact": [{"direction": [1.0], "normal_force": N, "fs": 0.4, "fd": fd, "surface_speed": 1e3}],
            "harmonic": [{"frequency": 1.4, "sin": [0.3]}, {"frequency": 0.7, "cos": [0.5]}]}
    build, start = file_parameter(data, "harmonic.frequency")
    assert start == 0.7
    branch = continue_system(build, start, 1.3, points=4, parameter="harmonic.frequency")
    assert branch.forced and branch.stopped.startswith("reached") and branch.values.size == 4
    for W, x0, v0 in zip(branch.values, branch.x0[:, 0], branch.v0[:, 0]):
        one = 0.5 / (k - m * W ** 2 + 1j * c * W)
        two = -0.3j / (k - m * (2 * W) ** 2 + 1j * c * 2 * W)
        assert x0 == pytest.approx(one.real + two.real + N * fd / k, rel=1e-9)
        assert v0 == pytest.approx((1j * W * one).real + (2j * W * two).real, rel=1e-9)
    assert branch.to_xarray()["value"].attrs["units"] == "rad/s"
    with pytest.raises(ParameterError) as err:
        file_parameter({**data, "harmonic": [{"cos": [1.0]}]}, "harmonic.frequency")
    assert err.value.name == "harmonic[0].frequency"
    for bad in (0.0, "1.5", True):  # each frequency checked under its own key, as the file gives it
        with pytest.raises(ParameterError) as err:
            file_parameter({**data, "harmonic": [{"frequency": 2.0, "cos": [1.0]}, {"frequency": bad, "cos": [1.0]}]},
                           "harmonic.frequency")
        assert err.value.name == "harmonic[1].frequency" and err.value.value == bad
    for bad in ([], {**data, "harmonic": []}, {**data, "harmonic": "x"}):
        with pytest.raises(ParameterError) as err:
            file_parameter(bad, "harmonic.frequency")
        assert err.value.name == "parameter"
