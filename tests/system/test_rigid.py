"""Rigid unilateral contacts (``Contact(..., None, ..., normal_direction=n, rigid=True)``): a block
dropped on a moving belt against the closed forms of its flight, plastic landing, slip and stick;
lift-off under a growing pull at the closed-form instant; the monodromy across impacts and
lift-offs against central differences of whole runs; the refusals."""

from pathlib import Path

import numpy as np
import pytest

from stickslip.errors import NoSolutionError, ParameterError
from stickslip.friction import Coulomb
from stickslip.system import flow as flow_module
from stickslip.system import (Contact, Flow, ForceHistory, Harmonic, System, monodromy, simulate,
                              system_from_dict)

from .test_floquet import end_state

M, K, G, F, V = 2.0, 3.0, 9.81, 0.3, 0.5


def central_differences(system, z0, t_end, h=1e-7):
    """d(x, v)(t_end) / d(x, v)(0) by central differences of whole runs (steps h along each axis)."""
    n = system.dofs
    fd = np.zeros((2 * n, 2 * n))
    for j in range(2 * n):
        d = h * np.eye(2 * n)[j]
        ends = [end_state(simulate(system, (z0 + s * d)[:n], (z0 + s * d)[n:], t_end, samples=2)) for s in (1, -1)]
        fd[:, j] = (ends[0] - ends[1]) / (2 * h)
    return fd


def block(force_history=None, harmonics=(), fs=F, ky=0.0, cy=0.0, lift=0.0):
    """A block (x along the belt, y up) on a spring along x, under its weight, on a belt at y = 0
    moving at V: a rigid contact, n = (0, 1), w = (1, 0)."""
    contact = Contact([1.0, 0.0], None, Coulomb(fs, F), V, normal_direction=[0.0, 1.0], rigid=True)
    return System(np.eye(2) * M, np.diag([K, ky]), [contact], force=[0.0, lift - M * G], damping=np.diag([0.0, cy]),
                  history=force_history, harmonics=harmonics)


def test_a_dropped_block_lands_plastically_with_its_friction_impulse_slips_then_sticks():
    # landing at v_y = -sqrt(2 g y0): the normal impulse M sqrt(2 g y0) stops it, the friction impulse
    # f times that (the belt is faster: forwards) adds f sqrt(2 g y0) to v_x; then the spring-mass slips
    # under the constant friction f M G until x' = V, and sticks
    x0, y0 = 0.1, 0.02
    run = simulate(block(), x0=[x0, y0], v0=[0.0, 0.0], t_end=2.0, samples=2001)
    w = np.sqrt(K / M)
    landing = np.sqrt(2 * y0 / G)  # free fall
    assert run.event_time[0] == pytest.approx(landing, rel=1e-13) and run.event_state[0] == 1  # lands slipping
    flight = run.t < landing
    assert np.allclose(run.x[flight, 1], y0 - G * run.t[flight] ** 2 / 2, rtol=0, atol=1e-14)
    assert np.allclose(run.x[flight, 0], x0 * np.cos(w * run.t[flight]), rtol=0, atol=1e-14)
    assert np.all(run.friction_force[flight, 0] == 0.0)
    x1, v1 = x0 * np.cos(w * landing), -x0 * w * np.sin(w * landing) + F * np.sqrt(2 * G * y0)
    xe = F * M * G / K
    stick = landing + min(t for t in np.linspace(0, 2, 200001)[1:] if  # first time x' = V
                          (x1 - xe) * -w * np.sin(w * t) + v1 * np.cos(w * t) >= V)
    assert run.event_time[1] == pytest.approx(stick, abs=1e-5) and run.event_state[1] == 0
    slip = (run.t > landing) & (run.t < run.event_time[1])
    s = run.t[slip] - landing
    assert np.allclose(run.x[slip, 0], xe + (x1 - xe) * np.cos(w * s) + v1 / w * np.sin(w * s), rtol=0, atol=1e-13)
    assert np.all(run.x[run.t > landing, 1] == pytest.approx(0.0, abs=1e-15))
    assert np.all(run.v[run.t > landing, 1] == pytest.approx(0.0, abs=1e-14))
    assert np.allclose(run.friction_force[slip, 0], F * M * G, rtol=1e-13)
    # stuck on the belt: x' = V, the friction holds the spring, K x < f_s M G
    late = run.t > run.event_time[1]
    assert np.allclose(run.v[late, 0], V, rtol=1e-13) and np.allclose(run.friction_force[late, 0], K * run.x[late, 0],
                                                                        rtol=1e-12)


def test_a_block_dropped_from_higher_lands_stuck_its_friction_impulse_more_than_the_slip_needs():
    # f sqrt(2 g y0) = 0.59 m/s > V - v_x: the impulse that stops the slip is within f times the normal one
    x0, y0 = 0.1, 0.2
    run = simulate(block(), x0=[x0, y0], v0=[0.0, 0.0], t_end=0.5, samples=501)
    landing = np.sqrt(2 * y0 / G)
    assert run.event_time[0] == pytest.approx(landing, rel=1e-13) and run.event_state[0] == 0
    late = run.t > landing
    assert np.allclose(run.v[late, 0], V, rtol=1e-13) and np.allclose(run.v[late, 1], 0.0, atol=1e-14)


def test_a_block_pulled_up_by_a_growing_force_lifts_off_when_the_pull_equals_its_weight():
    r = 7.0  # N/s
    lift = M * G / r
    system = block(ForceHistory([0.0, 10.0], [[0.0, 0.0], [0.0, 10.0 * r]]), fs=0.6)
    run = simulate(system, x0=[0.0, 0.0], v0=[V, 0.0], t_end=lift + 1.0, samples=101)
    opened = run.event_time[run.event_state == 2]
    assert opened.size == 1 and opened[0] == pytest.approx(lift, rel=1e-12)
    up = run.t > lift
    assert np.allclose(run.x[up, 1], r * (run.t[up] - lift) ** 3 / (6 * M), rtol=1e-11, atol=1e-15)
    # before: stuck on the belt (x' = V) while K x < f_s (M G - r t), then slipping back
    assert np.all(run.x[~up, 1] == 0.0)


def test_the_monodromy_across_landings_and_lift_offs_matches_finite_differences():
    # a block on a vertical spring pressed onto the belt, lifted by a harmonic force: it lifts off,
    # flies, lands plastically, slips and sticks, several times
    system = block(harmonics=[Harmonic(5.0, sin=[0.0, 1.6 * M * G])], fs=0.5, ky=20.0, cy=0.3)
    z0 = np.array([0.05, 0.01, 0.2, 0.1])
    t_end = 3.0
    run = simulate(system, z0[:2], z0[2:], t_end, samples=2, segments=True)
    kinds = set(run.event_state.tolist())
    assert {2, 1}.issubset(kinds) and (run.event_state == 2).sum() >= 2  # lift-offs and landings
    Phi = monodromy(system, run)
    fd = central_differences(system, z0, t_end)
    assert np.abs(Phi - fd).max() < 1e-5 * np.abs(fd).max()
    assert abs(np.linalg.det(Phi)) < 1e-8  # each landing collapses the normal velocity


def test_a_start_inside_the_surface_or_a_rigid_contact_with_a_normal_force_is_refused():
    with pytest.raises(ParameterError) as err:
        simulate(block(), x0=[0.0, -1e-3], t_end=1.0)
    assert err.value.name == "x0" and "gap" in str(err.value)
    with pytest.raises(ParameterError) as err:
        Contact([1.0, 0.0], 1.0, Coulomb(F, F), V, normal_direction=[0.0, 1.0], rigid=True)
    assert err.value.name == "normal_force"
    with pytest.raises(ParameterError) as err:
        Contact([1.0, 0.0], None, Coulomb(F, F), V, rigid=True)
    assert err.value.name == "normal_direction"
    with pytest.raises(ParameterError) as err:
        Contact([1.0, 0.0], None, Coulomb(F, F), V, normal_direction=[0.0, 1.0], normal_stiffness=2.0, rigid=True)
    assert err.value.name == "normal_stiffness"
    with pytest.raises(ParameterError) as err:
        Contact([1.0, 0.0], None, Coulomb(F, F), V)
    assert err.value.name == "normal_force"


def test_a_file_gives_a_rigid_contact():
    data = {"mass": [[M, 0.0], [0.0, M]], "stiffness": [[K, 0.0], [0.0, 0.0]], "force": [0.0, -M * G],
            "contact": [{"direction": [1.0, 0.0], "normal_direction": [0.0, 1.0], "rigid": True, "fs": F, "fd": F,
                         "surface_speed": V}]}
    run = simulate(system_from_dict(data), x0=[0.1, 0.2], t_end=1.0)
    assert run.event_time[0] == pytest.approx(np.sqrt(0.4 / G), rel=1e-13)
    with pytest.raises(ParameterError) as err:
        system_from_dict({**data, "contact": [{**data["contact"][0], "normal_force": 3.0}]})
    assert err.value.name == "contact[0].normal_force"


def test_a_block_on_the_surface_pulled_harder_than_its_weight_leaves_at_once():
    system = block(ForceHistory([0.0], [[0.0, 2.0 * M * G]]))  # a constant pull of twice its weight
    run = simulate(system, x0=[0.0, 0.0], v0=[0.0, 0.0], t_end=1.0, samples=11)
    assert np.all(run.states == 2) and run.event_time.size == 0
    assert np.allclose(run.x[:, 1], G * run.t ** 2 / 2, rtol=1e-13, atol=0.0)


def test_a_block_let_go_at_rest_hops_and_lands_within_one_step_of_the_search():
    # lifted by F sin(W t), F = 1.001 M G: it leaves where F sin(W t_o) = M G, with no velocity, and lands
    # where the closed-form height comes back to 0, 0.036 s later: within a step of the search (0.05 s)
    # (the search once took the gap's zero slope at the start for a landing at once, and chattered)
    from scipy.optimize import brentq

    from stickslip.system import Flow
    W, Fh = 5.0, 1.001 * M * G
    system = block(harmonics=[Harmonic(W, sin=[0.0, Fh])], fs=0.6)
    run = simulate(system, x0=[0.0, 0.0], v0=[V, 0.0], t_end=1.2, samples=2)
    t_o = np.arcsin(M * G / Fh) / W

    def height(t):
        return -(Fh / (M * W ** 2)) * (np.sin(W * t) - np.sin(W * t_o) - W * np.cos(W * t_o) * (t - t_o)) \
            - G * (t - t_o) ** 2 / 2
    t_l = brentq(height, t_o + 1e-4, t_o + 1.0)
    assert t_l - t_o < Flow(system, (2,)).h
    opened, landed = run.event_time[run.event_state == 2], run.event_time[run.event_state != 2]
    assert opened[0] == pytest.approx(t_o, rel=1e-12) and landed[landed > t_o][0] == pytest.approx(t_l, rel=1e-10)


def test_a_touch_and_go_landing_has_its_impact_in_the_monodromy():
    # a block on a vertical spring whose rest is 0.1 above the belt, thrown down onto it: the landing
    # stops its fall and its friction impulse pushes it along, but the spring pulls it off at once (no
    # change of contact state is recorded); the monodromy still has the impact (finite differences)
    ky = 20.0
    system = block(fs=0.5, ky=ky, cy=0.5, lift=M * G + ky * 0.1)
    z0 = np.array([0.05, 0.05, 0.1, -1.0])
    t_end = 1.0
    run = simulate(system, z0[:2], z0[2:], t_end, samples=2, segments=True)
    assert run.event_time.size == 0 and np.all(run.states == 2)  # open throughout, as the record goes
    assert any(seg.rows for seg in run.segments)  # the landing itself
    assert run.v[-1, 0] != pytest.approx(simulate(system, z0[:2], [0.1, 0.0], t_end).v[-1, 0])
    Phi = monodromy(system, run)
    fd = central_differences(system, z0, t_end)
    assert np.abs(Phi - fd).max() < 1e-5 * np.abs(fd).max()


@pytest.mark.parametrize("vx", [0.3, 0.5])
def test_a_contact_landing_into_stick_and_pulled_off_at_once_is_no_paradox(vx):
    # the friction impulse stops the slip (it lands stuck) and the spring pulls it off at once: an open
    # contact, not one released to slip (the simulation once stopped with a Painleve-like paradox here)
    ky = 20.0
    system = block(fs=0.5, ky=ky, cy=0.5, lift=M * G + ky * 0.1)
    run = simulate(system, [-0.05, 0.05], [vx, -1.0], 1.0, samples=101, segments=True)
    assert np.all(run.states == 2) and run.segments[0].rows
    # just after the touch: no normal velocity, and the belt's speed along x (the impulse stuck it)
    after = run.segments[1].z
    assert after[3] == 0.0 and after[2] == pytest.approx(V, rel=1e-13)


def test_a_block_starting_on_the_surface_and_moving_into_it_lands_at_once():
    # on the floor (belt at rest) moving down at 1 m/s and along it at 0.5 m/s: the plastic impact at t = 0
    # stops the fall and its friction impulse (f times M * 1 m/s) leaves 0.5 - f m/s; then friction f G
    # stops the slide at t = (0.5 - f) / (f G) (a run once went through the floor here, without an error)
    floor = Contact([1.0, 0.0], None, Coulomb(0.3, 0.3), 0.0, normal_direction=[0.0, 1.0], rigid=True)
    system = System(np.eye(2), np.zeros((2, 2)), [floor], force=[0.0, -G])
    run = simulate(system, x0=[0.0, 0.0], v0=[0.5, -1.0], t_end=0.2, samples=5)
    assert np.all(run.x[:, 1] == 0.0) and np.all(run.v[:, 1] == 0.0)
    assert run.v[0, 0] == pytest.approx(0.2, rel=1e-14)
    assert run.event_time[0] == pytest.approx(0.2 / (0.3 * G), rel=1e-12) and run.event_state[0] == 0


def _bar(tilt=0.0):
    """A bar (x, y, its rotation) with two feet at -+0.5 on a belt at 0.6 m/s, under its weight: the feet's
    normals couple y and the rotation through the bar's inertia."""
    feet = [Contact([1.0, 0.0, 0.0], None, Coulomb(0.5, 0.4), 0.6, normal_direction=[0.0, 1.0, s * 0.5], rigid=True)
            for s in (-1, 1)]
    return System(np.diag([1.0, 1.0, 0.2]), np.diag([1.0, 0.0, 2.0]), feet, force=[0.0, -G, 0.0])


def test_two_feet_coupled_through_the_inertia_landing_together_have_the_monodromy_of_their_runs():
    # dropped flat, both feet land at once: the second landing's reset keeps the first one's constraint
    # (the monodromy was 1.2 off before)
    system, t_end = _bar(), 0.4
    z0 = np.array([0.0, 0.05, 0.0, 0.0, 0.0, 0.0])
    run = simulate(system, z0[:3], z0[3:], t_end, samples=2, segments=True)
    assert run.event_time[0] == run.event_time[1] == pytest.approx(np.sqrt(0.1 / G), rel=1e-13)
    Phi = monodromy(system, run)
    fd = central_differences(system, z0, t_end)
    assert np.abs(Phi - fd).max() < 1e-5 * np.abs(fd).max()


def test_a_landing_does_not_pull_on_a_contact_resting_nearby():
    # two normal dofs coupled through M (M12 = -0.5): y2 lands at speed u while y1 rests on its surface.
    # Keeping both closed would need a pulling impulse on y1; with impulses >= 0, P1 = 0 and y1 lifts off
    # at -M^-1_12 / M^-1_22 u, the kinetic energy after the impact 0.15 J (not 0)
    M = np.diag([1.0, 1.0, 1.0])
    M[1:, 1:] = [[1.0, -0.5], [-0.5, 1.0]]
    feet = [Contact([1.0, 0.0, 0.0], None, Coulomb(0.2, 0.2), 0.0, normal_direction=np.eye(3)[k], rigid=True)
            for k in (1, 2)]
    system = System(M, np.zeros((3, 3)), feet, force=[0.0, -1.0, -1.0])
    run = simulate(system, [0.0, 0.0, 0.1], [0.0, 0.0, -1.0], 1.0, samples=2, segments=True)
    landing = next(seg for seg in run.segments if seg.t > 0)
    v = landing.z[3:6]
    u = -simulate(system, [0.0, 0.0, 0.1], [0.0, 0.0, -1.0], landing.t * (1 - 1e-13), samples=2).v[-1, 2]
    Minv = np.linalg.inv(M[1:, 1:])
    assert landing.states[0] == 2 and v[2] == pytest.approx(0.0, abs=1e-14)
    assert v[1] == pytest.approx(Minv[0, 1] / Minv[1, 1] * u, rel=1e-12)
    assert 0.5 * v @ M @ v == pytest.approx(0.15, rel=1e-12)


def test_a_contact_with_a_finite_normal_force_takes_no_impulse_at_a_landing():
    # x stuck on a fixed surface (N = 10, not rigid), coupled through M to y, which lands on a frictionless
    # floor: the impulse is all normal, P_y = -v_y / M^-1_yy, and x jumps to M^-1_xy P_y and slips
    M = np.array([[1.0, 0.3], [0.3, 1.0]])
    stuck = Contact([1.0, 0.0], 10.0, Coulomb(0.5, 0.5), 0.0)
    floor = Contact([1.0, 0.0], None, Coulomb(0.0, 0.0), 0.0, normal_direction=[0.0, 1.0], rigid=True)
    system = System(M, np.zeros((2, 2)), [stuck, floor], force=[0.0, -1.0])
    run = simulate(system, [0.0, 0.1], [0.0, -1.0], 0.5, samples=2, segments=True)
    seg = next(s for s in run.segments if s.t > 0)
    before = simulate(system, [0.0, 0.1], [0.0, -1.0], seg.t * (1 - 1e-12), samples=2)
    Minv = np.linalg.inv(M)
    P = -before.v[-1, 1] / Minv[1, 1]
    assert seg.states[0] != 0 and seg.z[2] == pytest.approx(Minv[0, 1] * P, rel=1e-9)


def test_a_ramp_at_the_top_of_its_range_releases_at_the_closed_form_instant():
    # 1e15 N/s on a block held by f_s N = 6 N: released at 6e-15 s (the search once put it at 0 and stopped)
    system = System([[2.0]], [[0.0]], [Contact([1.0], 10.0, Coulomb(0.6, 0.4), 0.0)],
                    history=ForceHistory([0.0, 1.0], [[0.0], [1e15]]))
    run = simulate(system, t_end=2.0, samples=2)
    assert run.event_time[0] == pytest.approx(6e-15, rel=1e-12)


def test_a_file_whose_rigid_is_not_true_or_false_names_it():
    data = {"mass": [[1.0, 0.0], [0.0, 1.0]], "stiffness": [[0.0, 0.0], [0.0, 0.0]],
            "contact": [{"direction": [1.0, 0.0], "normal_direction": [0.0, 1.0], "rigid": "yes", "fs": F, "fd": F}]}
    with pytest.raises(ParameterError) as err:
        system_from_dict(data)
    assert err.value.name == "contact[0].rigid" and "true or false" in str(err.value)


# A review's cases (each failed before its fix): landings at t = 0, Coulomb at every closed contact of an
# impact, a start whose given states a gap contradicts, and a landing with nothing pressing on the surface.
def _floor(w=(1.0, 0.0), n=(0.0, 1.0), law=None):
    return Contact(list(w), None, law or Coulomb(0.6, 0.4), 0.0, normal_direction=list(n), rigid=True)


@pytest.mark.parametrize("vy", [-0.1, -0.7, -1.5, -3.0])
def test_a_block_dropped_on_the_floor_at_the_start_stays_on_it(vy):
    """Its mass matrix couples x and y, so round-off leaves n . v ~ 1e-16 after the impact: that is not
    a lift-off (it went through the floor for a whole search step)."""
    s = System([[1.0, 0.3], [0.3, 1.0]], np.diag([1.0, 0.0]), [_floor()], force=[0.0, -9.81])
    run = simulate(s, [0.0, 0.0], [0.5, vy], 0.3, samples=31)
    assert run.x[:, 1].min() >= -1e-12 and np.all(run.states != 2)


def test_a_landing_at_the_start_lifts_a_resting_foot_off_as_its_closed_form():
    """Foot 2 lands at t = 0; through the inertia (M_12 = -0.5) foot 1 leaves at 0.5 m/s and flies,
    with foot 2 held, y1 = 0.5 t - t^2 / 2."""
    M = np.eye(3)
    M[1:, 1:] = [[1.0, -0.5], [-0.5, 1.0]]
    feet = [_floor((1.0, 0.0, 0.0), np.eye(3)[k], Coulomb(0.2, 0.2)) for k in (1, 2)]
    run = simulate(System(M, np.zeros((3, 3)), feet, force=[0.0, -1.0, -1.0]), np.zeros(3), [0.0, 0.0, -1.0], 0.4,
                   samples=5)
    assert run.x[:, 1] == pytest.approx(0.5 * run.t - 0.5 * run.t ** 2, abs=1e-12)
    assert np.all(run.states[:, 0] == 2) and np.all(run.states[:, 1] == 0) and np.all(run.x[:, 2] == 0)


def test_friction_at_a_landing_at_the_start_makes_no_motion_from_nothing():
    """Neither foot slides (x' = 0) and a landing foot's impulse does not push x: the resting foot is
    stuck, not in reverse slip (its friction impulse drove x' to -0.32)."""
    M = np.array([[1.0, 0, 0], [0, 4.0, 1.8], [0, 1.8, 1.0]])
    feet = [_floor((1, 0, 0), (0, 1, 0)), _floor((1, 0, 0), (0, 0, 1))]
    for force in ([0.0, 0.0, 0.0], [0.0, -5.8, -2.8]):
        run = simulate(System(M, np.diag([1.0, 0.0, 0.0]), feet, force=force), np.zeros(3), [0, 0, -1.0], 0.5,
                       samples=3)
        assert np.abs(run.v).max() <= 1e-12 and run.x[:, 1:].min() >= -1e-12


def test_a_foot_without_a_normal_impulse_takes_no_friction_impulse_at_a_landing():
    """Foot a stands stuck under its weight; foot b, coupled to x through M, lands and foot a takes
    no normal impulse, so Coulomb gives it no friction impulse either: the velocity after is foot b's
    impact alone, slipping (s = 1), M dv = (n_b + s f_d w) P_b with n_b . (v + dv) = 0 (it took a
    friction impulse of 0.99 at foot a, which had none to give, and stopped x)."""
    M = np.array([[1.0, 0, 0.7], [0, 1.0, 0], [0.7, 0, 1.0]])
    w, na, nb = np.array([1.0, 0, 0]), np.array([0, 1.0, 0]), np.array([0, 0, 1.0])
    s = System(M, np.diag([1.0, 0, 0]), [_floor(w, na), _floor(w, nb)], force=M @ [0, -9.81, -9.81])
    run = simulate(s, [0, 0, 0.2], [0, 0, -2.0], 0.2, samples=3, segments=True)
    before, after = run.segments[0], run.segments[1]
    v_minus = Flow(s, before.states).propagate(before.z, before.duration)[3:6]
    push = np.linalg.solve(M, nb + 0.4 * w)
    v_plus = v_minus - push * (nb @ v_minus) / (nb @ push)
    assert -w @ v_plus > 0  # it slips the way it was taken to
    assert after.z[3:6] == pytest.approx(v_plus, abs=1e-12)
    assert after.states == (1, 1)  # both slip the way their slip velocities go (foot a released by the impact)


def test_a_slipping_foot_whose_impulse_would_reverse_it_sticks_at_a_landing():
    """Foot a slides slowly (v_r about -0.08) when foot b lands hard and presses it through the inertia:
    foot a's friction impulse would reverse its slip (before: to +0.59, then undone by events at the
    same instant), so it sticks at the impact itself."""
    M = np.array([[1.0, 0, 0], [0, 4.0, 1.8], [0, 1.8, 1.0]])  # foot b's landing presses foot a
    w = np.array([1.0, 0, 0])
    s = System(M, np.zeros((3, 3)), [_floor(w, (0, 1, 0)), _floor(w, (0, 0, 1))], force=M @ [0, -9.81, -9.81])
    run = simulate(s, [0, 0, 0.1343], [0.2, 0, -2.0], 0.1, samples=3, segments=True)
    k = next(j for j, seg in enumerate(run.segments) if seg.states[1] != 2)
    assert run.segments[k - 1].states[0] == -1 and run.segments[k].states[0] == 0
    assert run.segments[k].z[3] == pytest.approx(0.0, abs=1e-12)


def test_given_states_a_gap_contradicts_are_refused():
    s = System([[1.0, 0.0], [0.0, 1.0]], np.diag([1.0, 0.0]), [_floor()], force=[0.0, -9.81])
    with pytest.raises(ParameterError, match=r"states = \[0\].*2 \(open\) for contact 0"):
        simulate(s, [0.0, 0.1], [0.0, 0.0], 1.0, samples=3, states=(0,))


@pytest.mark.parametrize("coupling", [0.0, 0.7])
def test_a_block_landing_with_nothing_pressing_it_on_the_surface_rests_there(coupling):
    """No force: after its plastic impact the block stays on the floor with a reaction of 0 (the
    reaction's row and the gap's row stay 0: not an event; it chattered open-closed)."""
    M = np.array([[1.0, coupling], [coupling, 1.0]])
    run = simulate(System(M, np.zeros((2, 2)), [_floor()]), [0.0, 0.1], [0.0, -1.0], 1.0, samples=11)
    assert run.event_time == pytest.approx([0.1], abs=1e-12) and run.event_time.size == 1
    assert np.all(run.x[2:, 1] == 0.0) and np.all(run.states[2:, 0] != 2)


def test_a_gap_rising_off_its_line_at_another_contacts_event_is_no_landing():
    """A start of the Figure 12 wave's ring (256 nodes, whose normal motion is free; saved from a return
    map's iteration): seven copies of node 0 have just lifted off (gap rising as t^3), the eighth lifts
    off 2e-12 later. At that event the seven gaps, -1e-36 by round-off, were taken for landings, and
    the landings and lift-offs that followed chattered at that instant. Now the run reaches node 255's
    lift-off."""
    from stickslip.brake import BrakeParams
    from stickslip.brake.waves import ring_system
    d = np.load(Path(__file__).parent / "data" / "ring_lift_off_start.npz")
    system = ring_system(BrakeParams.from_physical(100.0, 1e-5, 0.2), 256, separation=True)
    run = simulate(system, d["x0"], d["v0"], float(d["t_end"]), samples=2, segments=True,
                   states=tuple(int(s) for s in d["states"]), stop_at=tuple(int(s) for s in d["stop_at"]))
    assert run.event_contact[-1] == 255 and run.event_state[-1] == 2
    first = run.event_time[0]
    assert first == pytest.approx(2.16e-12, rel=0.01) and np.count_nonzero(run.event_time == first) <= 8


def test_a_cache_holding_one_flow_gives_the_same_run_and_monodromy(monkeypatch):
    # consistency of the bounded flow cache (not physics): flows dropped and built again where met again
    system = block(harmonics=[Harmonic(5.0, sin=[0.0, 1.6 * M * G])], fs=0.5, ky=20.0, cy=0.3)
    z0 = np.array([0.05, 0.01, 0.2, 0.1])
    full = simulate(system, z0[:2], z0[2:], 3.0, samples=2, segments=True)
    monkeypatch.setattr(flow_module, "CACHE_BYTES", 1)
    one = simulate(system, z0[:2], z0[2:], 3.0, samples=2, segments=True)
    assert {1, 0, 2}.issubset(set(one.event_state.tolist()))  # slip, stick and flight met
    assert np.array_equal(full.event_time, one.event_time) and np.array_equal(full.x, one.x)
    assert np.array_equal(monodromy(system, full), monodromy(system, one))
