"""Systems with several frictional contacts, simulated with exact switching: against closed
forms, the 1-DOF oscillator (verified on its own closed forms), and an independent
time-stepping scheme (Moreau's midpoint scheme with contact forces solved per step) whose
error shrinks at its first order."""

import numpy as np
import pytest

from stickslip.errors import NoSolutionError, ParameterError
from stickslip.friction import Coulomb, LinearWeakening
from stickslip.oscillator import Oscillator
from stickslip.oscillator.simulate import simulate as oscillator_simulate
from stickslip.system import Contact, System, simulate


def one_dof(m=1.0, k=1.0, N=2.0, V=0.2, law=None, c=0.0):
    law = law or Coulomb(0.5, 0.3)
    return System([[m]], [[k]], [Contact([1.0], N, law, V)], damping=[[c]])


def test_one_contact_sticks_for_the_closed_form_time():
    """Coulomb, no damping: a stick phase of the limit cycle lasts 2 (fs - fd) N / (k V) (each
    case sticks from rest: sqrt(k/m) fd N / k > V)."""
    for m, k, N, V in [(1.0, 1.0, 2.0, 0.2), (3.0, 50.0, 10.0, 0.2), (0.01, 2e3, 1.0, 1e-3)]:
        t_end = 6 * (2 * np.pi * np.sqrt(m / k) + 0.4 * N / (k * V))  # six periods at least
        run = simulate(one_dof(m, k, N, V), [0.0], [0.0], t_end, samples=11)
        starts = run.event_time[:-1][run.event_state[:-1] == 0]
        ends = run.event_time[1:][run.event_state[:-1] == 0]
        assert starts.size >= 3
        np.testing.assert_allclose((ends - starts)[1:], 2 * 0.2 * N / (k * V), rtol=1e-11)


@pytest.mark.parametrize("law, c", [(Coulomb(0.5, 0.3), 0.0), (Coulomb(0.4, 0.4), 0.05),
                                    (LinearWeakening(0.5, 0.3, 0.3), 0.02)])
def test_one_contact_on_one_dof_is_the_oscillator(law, c):
    osc = Oscillator(1.0, 1.0, 2.0, 0.2, law, damping=c)
    ref = oscillator_simulate(osc, 30.0, 0.1, -0.3)
    assert ref.t[-1] == 30.0  # the reference reached the end
    run = simulate(one_dof(law=law, c=c), [0.1], [-0.3], 30.0, samples=2)
    switches = np.array([e[0] for e in ref.events])
    assert switches.size == run.event_time.size >= 2
    np.testing.assert_allclose(run.event_time, switches, rtol=1e-10, atol=1e-12)
    assert run.x[-1, 0] == pytest.approx(ref.x[-1], abs=1e-9) and run.v[-1, 0] == pytest.approx(ref.v[-1], abs=1e-9)


def test_a_slip_speed_beyond_the_laws_limit_stops_the_run_saying_so():
    """Linear weakening holds for tau |v_r| < 1 only: the run stops where |v_r| reaches 1/tau
    (the oscillator stops there too, at the start of that slip)."""
    law = LinearWeakening(0.4, 0.4, 0.5)
    ref = oscillator_simulate(Oscillator(1.0, 1.0, 1.0, 0.2, law), 50.0, -4.0, 0.0)
    system = System([[1.0]], [[1.0]], [Contact([1.0], 1.0, law, 0.2)])
    with pytest.raises(NoSolutionError, match="limit of its friction law") as err:
        simulate(system, [-4.0], [0.0], 50.0)
    t_stop = float(str(err.value).split("t = ")[1].split(":")[0])
    assert ref.status == -1 and t_stop >= ref.t[-1]
    before = simulate(system, [-4.0], [0.0], t_stop * (1 - 1e-12), samples=2)
    assert abs(0.2 - before.v[-1, 0]) == pytest.approx(2.0, rel=1e-9)


def two_blocks(fs=0.6, fd=0.4):
    """Two blocks, each on its own belt, tied by a spring and to the wall (a 2-block Burridge-
    Knopoff chain): two contacts, each on one degree of freedom."""
    M = np.diag([1.0, 1.5])
    K = np.array([[3.0, -1.0], [-1.0, 2.0]])
    contacts = [Contact([1.0, 0.0], 2.0, Coulomb(fs, fd), 0.3), Contact([0.0, 1.0], 1.0, Coulomb(fs, fd), 0.1)]
    return System(M, K, contacts, damping=0.02 * K)


def moreau(system, x0, v0, t_end, steps):
    """An independent scheme: M (v1 - v0) = h (f - K x_mid - C v_mid) + W P with x1 = x0 + h (v0 + v1)/2,
    and per step the contact forces
    (impulses) that make each contact stick if its impulse stays within f_s N h, else slip at
    f_d N h against its end-of-step slip velocity, solved by enumerating the contact states."""
    import itertools

    h = t_end / steps
    M, K, C, W = system.mass, system.stiffness, system.damping, system.directions
    N = np.array([c.normal_force for c in system.contacts])
    V = np.array([c.surface_speed for c in system.contacts])
    fs = np.array([c.friction.fs for c in system.contacts])
    fd = np.array([c.friction.fd for c in system.contacts])
    A = M + 0.5 * h * C + 0.25 * h * h * K
    x, v = np.array(x0, float), np.array(v0, float)
    for _ in range(steps):
        free = M @ v - h * K @ (x + 0.25 * h * v) - 0.5 * h * C @ v + h * system.force  # midpoint x and v
        best = None
        for states in itertools.product((0, 1, -1), repeat=len(N)):
            s = np.array(states)
            stuck = s == 0
            # impulses: slipping ones known, sticking ones by V - W^T v_new = 0
            P = np.where(stuck, 0.0, s * fd * N * h)
            if stuck.any():
                Ai = np.linalg.inv(A)
                Ws = W[:, stuck]
                rhs = V[stuck] - Ws.T @ Ai @ (free + W[:, ~stuck] @ P[~stuck])
                P[stuck] = np.linalg.solve(Ws.T @ Ai @ Ws, rhs)
            v_new = np.linalg.solve(A, free + W @ P)
            vr = V - W.T @ v_new
            if np.all(np.abs(P[stuck]) <= fs[stuck] * N[stuck] * h * (1 + 1e-12)) and \
                    np.all(s[~stuck] * vr[~stuck] >= -1e-14):
                best = v_new
                break
        assert best is not None
        x, v = x + 0.5 * h * (v + best), best
    return x, v


def test_two_blocks_against_an_independent_time_stepping_scheme():
    """The end state after 12 s (several stick-slip events on both blocks) agrees with Moreau's
    scheme; the scheme's difference from it falls at least as its first order with the step
    (the event-driven one is exact to round-off, so it is the scheme's error)."""
    system, t_end = two_blocks(), 12.0
    run = simulate(system, [0.0, 0.0], [0.0, 0.0], t_end, samples=2)
    assert {0, 1} <= set(run.event_contact.tolist()) and run.event_time.size >= 6
    errors = []
    for steps in (4000, 16000):
        x, v = moreau(system, [0.0, 0.0], [0.0, 0.0], t_end, steps)
        errors.append(np.abs(x - run.x[-1]).max())
    assert errors[1] < 1e-3 * np.abs(run.x).max() * 10
    assert errors[0] / errors[1] > 3.0  # first order: 4 on a four-times finer step


def test_energy_balance_of_two_blocks():
    """Between two samples, the change of kinetic plus strain energy is the work of the damping
    and friction forces (their power integrated over the samples by Simpson's rule, with the
    samples fine enough that its error is below the check's threshold)."""
    system = two_blocks()
    run = simulate(system, [0.0, 0.0], [0.0, 0.0], 6.0, samples=60001)
    M, K, C, W = system.mass, system.stiffness, system.damping, system.directions
    E = 0.5 * np.einsum("ti,ij,tj->t", run.v, M, run.v) + 0.5 * np.einsum("ti,ij,tj->t", run.x, K, run.x)
    power = np.einsum("ti,ti->t", run.v, run.friction_force @ W.T) - np.einsum("ti,ij,tj->t", run.v, C, run.v)
    work = np.concatenate([[0.0], np.cumsum(0.5 * (power[1:] + power[:-1]) * np.diff(run.t))])
    scale = np.abs(E).max()
    assert np.abs(E - E[0] - work).max() < 1e-4 * scale


def test_the_forces_of_sticking_contacts_stay_within_the_static_limit_and_slip_forces_are_kinetic():
    system = two_blocks()
    run = simulate(system, [0.0, 0.0], [0.0, 0.0], 12.0, samples=4001)
    N = np.array([2.0, 1.0])
    stuck = run.states == 0
    assert stuck.any() and (~stuck).any()
    assert np.all(np.abs(run.friction_force[stuck]) <= (0.6 * N * np.ones_like(run.friction_force))[stuck] + 1e-12)
    slip = ~stuck
    np.testing.assert_allclose(np.abs(run.friction_force[slip]), (0.4 * N * np.ones_like(run.friction_force))[slip])
    np.testing.assert_array_equal(np.sign(run.friction_force[slip]), run.states[slip])


@pytest.mark.parametrize("kwargs, name", [
    ({"mass": [[1.0, 0.5], [0.4, 1.0]]}, "mass"), ({"mass": [[1.0, 0.0], [0.0, -1.0]]}, "mass"),
    ({"stiffness": np.eye(3)}, "stiffness"), ({"damping": [[np.nan, 0], [0, 0]]}, "damping"),
    ({"force": [1.0]}, "force"), ({"contacts": []}, "contacts"),
    ({"contacts": [Contact([1.0, 0.0, 0.0], 1.0, Coulomb(0.5, 0.3))]}, "contacts[0].direction")])
def test_bad_systems_are_refused_naming_the_parameter(kwargs, name):
    base = {"mass": np.eye(2), "stiffness": np.eye(2), "contacts": [Contact([1.0, 0.0], 1.0, Coulomb(0.5, 0.3))]}
    with pytest.raises(ParameterError) as err:
        System(**{**base, **kwargs})
    assert err.value.name == name


@pytest.mark.parametrize("args, name", [
    (([0.0, 0.0], 1.0, Coulomb(0.5, 0.3)), "direction"), (([1.0], 0.0, Coulomb(0.5, 0.3)), "normal_force"),
    (([1.0], 1.0, "coulomb"), "friction"), (([1.0], 1.0, Coulomb(0.5, 0.3), 1e300), "surface_speed")])
def test_bad_contacts_are_refused_naming_the_parameter(args, name):
    with pytest.raises(ParameterError) as err:
        Contact(*args)
    assert err.value.name == name


def test_fs_below_fd_is_refused():
    with pytest.raises(ParameterError) as err:
        Contact([1.0], 1.0, Coulomb(0.2, 0.3))
    assert err.value.name == "fs"


def test_max_events_stops_a_run_with_a_no_solution_error():
    with pytest.raises(NoSolutionError, match="max_events"):
        simulate(one_dof(), [0.0], [0.0], 100.0, max_events=3)


def test_a_stuck_contacts_start_is_the_smallest_change_of_velocity_in_the_metric_of_the_mass():
    """`zero_slip` (a Newton start taken from a neighbouring system): the velocity nearest the given
    one in kinetic energy, (v' - v)^T M (v' - v) least, with W^T v' = V for the stuck contacts:
    the Lagrange system [[M, W], [W^T, 0]] (dv, -lam) = (0, V - W^T v), solved here; a mass far
    from the identity (off-diagonal too) tells the metric of M from the plain one."""
    from stickslip.system.simulate import zero_slip
    M = np.array([[3.0, 0.5, 0.0], [0.5, 1.0, 0.2], [0.0, 0.2, 0.25]])
    K = np.diag([2.0, 1.0, 3.0])
    contacts = [Contact([1.0, -1.0, 0.0], 1.0, Coulomb(0.5, 0.5), 0.3),
                Contact([0.0, 1.0, 2.0], 2.0, Coulomb(0.4, 0.4), -0.1)]
    system = System(M, K, contacts)
    v = np.array([0.2, -0.4, 0.7])
    z = zero_slip(system, system.state(np.zeros(3), v), [0, 1])
    W, V = np.array([c.direction for c in contacts]).T, np.array([0.3, -0.1])
    kkt = np.block([[M, W], [W.T, np.zeros((2, 2))]])
    dv = np.linalg.solve(kkt, np.concatenate([np.zeros(3), V - W.T @ v]))[:3]
    np.testing.assert_allclose(z[3:6], v + dv, rtol=0, atol=1e-14)
    np.testing.assert_allclose(W.T @ z[3:6], V, rtol=0, atol=1e-14)
