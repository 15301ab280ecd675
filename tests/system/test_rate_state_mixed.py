"""Systems mixing rate-and-state contacts with contacts that stick (`stickslip.system.rate_state_modes`):
the motion against the exact stick-slip of a block set apart (closed form), against an
integration written out here (the stuck block's coordinate eliminated, the state as theta, LSODA),
and steady sliding's eigenvalues against the roots of its characteristic polynomial."""

import math

import numpy as np
import pytest

from stickslip.errors import NoSolutionError, ParameterError
from stickslip.friction import Coulomb, LinearWeakening, UserLaw
from stickslip.rsf import RateState
from stickslip.system import Contact, System, rate_state_cycle, rate_state_simulate, rate_state_steady

from .pair_reference import stick_slip_pair

N, A, B, DC, F0, V0 = 10.0, 0.01, 0.015, 1e-5, 0.6, 1e-6
FS, FD, V2 = 0.6, 0.4, 0.05


def _coulomb_block(t, x0, k=1000.0, m=1.0):
    """The block on a belt at V2 from rest at x0 < fd N / k, Coulomb (fs, fd), in closed form: slip to
    the belt's speed, stick until the spring holds fs N, slip ... (a list of the events too)."""
    w = math.sqrt(k / m)
    xe, xs = FD * N / k, FS * N / k
    out, events = np.empty_like(t), []
    t0, x, v, stuck = 0.0, x0, 0.0, False
    while t0 < t[-1]:
        if stuck:  # x = x + V2 (t - t0) until k x = fs N
            t1 = t0 + (xs - x) / V2
            sel = (t >= t0) & (t <= t1)
            out[sel] = x + V2 * (t[sel] - t0)
            t0, x, v, stuck = t1, xs, V2, False
        else:  # x = xe + R cos(w (t - t0) + phi) until v = V2 again (from below)
            R, phi = math.hypot(x - xe, v / w), math.atan2(-v / w, x - xe)
            # v = -R w sin(w s + phi) = V2, rising through it (cos < 0): w s + phi = -pi + asin(V2/(R w)) mod 2 pi
            s = (-math.pi + math.asin(V2 / (R * w)) - phi) % (2 * math.pi)
            if s < 1e-12:
                s += 2 * math.pi
            t1 = t0 + s / w
            sel = (t >= t0) & (t <= t1)
            out[sel] = xe + R * np.cos(w * (t[sel] - t0) + phi)
            t0, x, v, stuck = t1, xe + R * math.cos(s + phi), V2, True
        events.append(t0)
    return out, np.array(events)


def test_two_contacts_along_one_direction_stick_and_slip_as_one_with_their_summed_normal_force():
    """Block 2 pressed by two Coulomb contacts of N/2 each, along the same direction: held, their forces
    are not determined apart (a singular system, which crashed); the motion is the closed form of one
    contact with N."""
    law = RateState(a=A, b=B, dc=DC, f0=F0, v_ref=V0)
    half = [Contact([0.0, 1.0], N / 2, Coulomb(FS, FD), surface_speed=V2) for _ in range(2)]
    system = System(mass=np.eye(2), stiffness=np.diag([3000.0, 1000.0]),
                    contacts=[Contact([1.0, 0.0], N, law, surface_speed=1e-6), *half])
    run = rate_state_simulate(system, x0=[2e-3 * 1.001, 0.0], v0=[0.0, 0.0], t_end=1.0, samples=2001)
    exact, _ = _coulomb_block(run.t, 0.0)
    assert np.abs(run.x[:, 1] - exact).max() < 1e-9 * np.abs(exact).max()
    stuck = run.states[:, 1] == 0
    assert np.all(run.states[:, 1] == run.states[:, 2]) and np.any(stuck)
    assert run.friction_force[stuck, 1] + run.friction_force[stuck, 2] == pytest.approx(1000.0 * run.x[stuck, 1])


def test_a_block_set_apart_sticks_and_slips_as_its_closed_form():
    law = RateState(a=A, b=B, dc=DC, f0=F0, v_ref=V0)
    system = System(mass=np.eye(2), stiffness=np.diag([3000.0, 1000.0]), contacts=[
        Contact([1.0, 0.0], N, law, surface_speed=1e-6), Contact([0.0, 1.0], N, Coulomb(FS, FD), surface_speed=V2)])
    run = rate_state_simulate(system, x0=[2e-3 * 1.001, 0.0], v0=[0.0, 0.0], t_end=1.0, samples=2001)
    exact, events = _coulomb_block(run.t, 0.0)
    assert np.abs(run.x[:, 1] - exact).max() < 1e-9 * np.abs(exact).max()
    # the events: slip -> stick at the belt's speed, stick -> slip where the spring holds fs N
    assert run.event_time == pytest.approx(events[:run.event_time.size], abs=1e-9)
    assert list(run.event_state) == [0, 1] * (run.event_time.size // 2) + [0] * (run.event_time.size % 2)
    assert run.event_time.size == np.count_nonzero(events < 1.0)
    stuck = run.states[:, 1] == 0
    assert np.abs(run.slip_rate[stuck, 1]).max() < 1e-9 * V2
    assert np.all(np.abs(run.friction_force[stuck, 1]) <= FS * N * (1 + 1e-9))
    assert np.allclose(run.friction_force[~stuck, 1], FD * N)  # slipping forward


# The coupled pair: a rate-and-state block (stiff enough to slide steadily alone) pulled by a block that
# sticks and slips on a belt, through a spring.
M1, M2, K1, K2, KC, V1, TAU = 1.0, 0.5, 2e4, 1e3, 300.0, 1e-3, 1.0


def _pair(law1, law2, k1=K1):
    K = [[k1 + KC, -KC], [-KC, K2 + KC]]
    return System(mass=np.diag([M1, M2]), stiffness=K, contacts=[
        Contact([1.0, 0.0], N, law1, surface_speed=V1), Contact([0.0, 1.0], N, law2, surface_speed=V2)])


def _reference(t_eval, x0, v0, theta0, evolution, held=False, k1=K1):
    """The pair written out apart: the state variable as theta (aging: theta' = 1 - v theta / D_c; slip:
    theta' = -(v theta / D_c) ln(v theta / D_c)), block 2's coordinate eliminated while it sticks
    (x2 = x2(t_s) + V2 (t - t_s)), LSODA with its own event location. Returns x at t_eval."""
    def mu1(v, th):
        return F0 + A * np.log(v / V0) + B * np.log(V0 * th / DC)

    def dtheta(v, th):
        return 1.0 - v * th / DC if evolution == "aging" else -(v * th / DC) * np.log(v * th / DC)

    def slipping(t, y, s):  # y = x1, x2, v1, v2, theta
        x1, x2, u1, u2, th = y
        f1 = N * mu1(V1 - u1, th)
        f2 = s * N * FD * (1.0 - TAU * abs(V2 - u2))
        return [u1, u2, (-(k1 + KC) * x1 + KC * x2 + f1) / M1, (KC * x1 - (K2 + KC) * x2 + f2) / M2,
                dtheta(V1 - u1, th)]

    def stuck(t, y, x2s, ts):  # y = x1, v1, theta; x2 = x2s + V2 (t - ts)
        x1, u1, th = y
        x2 = x2s + V2 * (t - ts)
        return [u1, (-(k1 + KC) * x1 + KC * x2 + N * mu1(V1 - u1, th)) / M1, dtheta(V1 - u1, th)]

    def hold(t, y, x2s, ts):  # the friction force that keeps block 2 on the belt: its spring forces
        return -(KC * y[0] - (K2 + KC) * (x2s + V2 * (t - ts)))

    return stick_slip_pair(t_eval, [x0[0], x0[1], v0[0], v0[1], theta0], slipping, stuck, hold, V2, FS * N, held)


@pytest.mark.parametrize("evolution, x2, v2", [("aging", 0.0, 0.0), pytest.param("slip", 0.0, 0.0, marks=pytest.mark.slow),
                                               pytest.param("aging", 0.0, 4.0 * V2, marks=pytest.mark.slow),
                                               ("slip", 0.01, 4.0 * V2)])  # both laws, at rest and moving: the fast set
def test_the_coupled_pair_follows_an_integration_written_apart(evolution, x2, v2):
    law = RateState(a=A, b=B, dc=DC, f0=F0, v_ref=V0, evolution=evolution)
    system = _pair(law, LinearWeakening(FS, FD, TAU))
    # block 2 at rest, or faster than its belt (reverse slip) and far out (slipping on through zero slip)
    x0, v0 = [(F0 * N + KC * x2) / (K1 + KC), x2], [0.0, v2]
    run = rate_state_simulate(system, x0=x0, v0=v0, t_end=0.6, samples=601)
    ref, events = _reference(run.t, x0, v0, DC / V1, evolution)
    scale = np.ptp(ref, axis=0)
    assert np.all(np.abs(run.x - ref).max(axis=0) < 1e-6 * scale)
    assert [s for _, s in events] == list(run.event_state)
    assert run.event_time == pytest.approx([t for t, _ in events], abs=1e-8)
    assert np.ptp(run.slip_rate[:, 0]) > 0.1 * V1  # the rate-and-state block is shaken: not a trivial check
    slipping = run.states[:, 1] != 0
    law = LinearWeakening(FS, FD, TAU)
    assert run.friction_force[slipping, 1] == pytest.approx(
        run.states[slipping, 1] * N * law.kinetic(run.slip_rate[slipping, 1]), rel=1e-12)


@pytest.mark.parametrize("evolution, belt", [("aging", V2), ("slip", V2), ("aging", -V2)])
@pytest.mark.parametrize("k", [3e3, 6e3, 2e4])
def test_steady_sliding_on_two_belts_has_the_roots_of_its_characteristic_polynomial(evolution, belt, k):
    """One block on a rate-and-state contact (speed V1) and on a linearly weakening one (speed V2): about
    steady sliding, (m s^2 + c' s + k)(V1 + s D_c) + N s (a (V1 + s D_c) / V1 - b) = 0 with the weakening
    contact's negative damping in c' = c - N fd tau (whichever way its belt moves)."""
    m, c = 0.2, 0.5
    law = RateState(a=A, b=B, dc=DC, f0=F0, v_ref=V0, evolution=evolution)
    system = System(mass=[[m]], stiffness=[[k]], damping=[[c]], contacts=[
        Contact([1.0], N, law, surface_speed=V1), Contact([1.0], N, LinearWeakening(FS, FD, TAU), surface_speed=belt)])
    steady = rate_state_steady(system)
    ce = c - N * FD * TAU
    roots = np.roots([m * DC, m * V1 + ce * DC + N * A * DC / V1, ce * V1 + k * DC + N * (A - B), k * V1])
    roots = roots[np.lexsort((-roots.imag, -roots.real))]
    assert steady.eigenvalues == pytest.approx(roots, rel=1e-9)
    mu_ss = F0 + (A - B) * math.log(V1 / V0)
    weak = math.copysign(N * FD * (1 - TAU * V2), belt)
    assert steady.x[0] == pytest.approx((N * mu_ss + weak) / k, rel=1e-12)
    assert steady.friction_force == pytest.approx([N * mu_ss, weak], rel=1e-12)
    assert steady.effective_damping[0, 0] == pytest.approx(c + N * A / V1 - N * FD * TAU, rel=1e-9)


def test_what_a_mixed_system_cannot_do_is_refused_naming_it():
    law = RateState(a=A, b=B, dc=DC, f0=F0, v_ref=V0)
    pair = _pair(law, Coulomb(FS, FD))
    pressed = System(mass=np.eye(2), stiffness=np.eye(2) * 1e3, contacts=[
        Contact([1.0, 0.0], N, law, surface_speed=V1),
        Contact([0.0, 1.0], N, Coulomb(FS, FD), surface_speed=V2, normal_direction=[0.0, 1.0], normal_stiffness=1.0)])
    with pytest.raises(ParameterError, match=r"contacts\[1\]\.normal_direction"):
        rate_state_simulate(pressed, t_end=0.1)
    for bad in ([0.1, 0.2], [[0.1, 0.2]], []):  # one entry per rate-and-state contact: here one
        with pytest.raises(ParameterError, match="psi0.*one per rate-and-state contact"):
            rate_state_simulate(pair, t_end=0.1, psi0=bad)
    run = rate_state_simulate(pair, t_end=0.01, psi0=[0.3], samples=3)
    assert run.psi[0, 0, 0] == 0.3 and np.isnan(run.psi[0, 1, 0])
    # two samples with switches between them (segments with no sample: it crashed)
    x0 = [F0 * N / K1, 0.0]
    few, many = (rate_state_simulate(pair, x0=x0, t_end=0.6, samples=k) for k in (2, 601))
    assert few.event_time.size == many.event_time.size >= 6
    assert few.x[-1] == pytest.approx(many.x[-1], rel=1e-7, abs=1e-12)
    fast = _pair(law, LinearWeakening(FS, FD, 2.0))  # swings beyond |v_r| = 1 / tau = 0.5 m/s, the law's end
    with pytest.raises(NoSolutionError, match=r"contact 1 reached the limit of its friction law.*0\.5"):
        rate_state_simulate(fast, x0=[(F0 * N + KC * 0.02) / (K1 + KC), 0.02], v0=[0.0, 4 * V2], t_end=0.1)
    beyond = _pair(law, LinearWeakening(FS, FD, 10.0))  # its law ends at 0.1 m/s; the belt runs at 0.05
    with pytest.raises(NoSolutionError, match=r"contact 1 is beyond the limit of its friction law.*0\.1"):
        rate_state_simulate(beyond, x0=[F0 * N / K1, 0.0], v0=[0.0, -0.1], t_end=0.1)
    fast_belt = System([[1.0]], [[1e3]], [Contact([1.0], N, law, surface_speed=V1),
                                          Contact([1.0], N, LinearWeakening(FS, FD, 10.0), surface_speed=0.2)])
    with pytest.raises(ParameterError, match=r"contacts\[1\]\.surface_speed = 0\.2.*below the speed 0\.1"):
        rate_state_steady(fast_belt)
    steep = _pair(law, UserLaw(lambda v: 0.4 + 100 * abs(v), fs=0.6))  # 15 at the start: beyond a coefficient's range
    with pytest.raises(ParameterError, match=r"mu\(v_r\)"):  # the law's own error, not Radau's
        rate_state_simulate(steep, x0=[F0 * N / K1, 0.0], v0=[0.0, 0.2], t_end=0.1)
    resting = System(mass=[[1.0]], stiffness=[[1e3]], contacts=[
        Contact([1.0], N, law, surface_speed=V1), Contact([1.0], N, Coulomb(FS, FD), surface_speed=0.0)])
    with pytest.raises(ParameterError, match=r"contacts\[1\]\.surface_speed"):
        rate_state_steady(resting)


@pytest.mark.slow
def test_a_cycle_of_the_coupled_pair_closes_under_the_integration_written_apart():
    """The pair's limit cycle (contact 1 sticking and slipping every period; Newton's method on runs with
    their switches, the monodromy by central differences): the integration written apart, from the
    cycle's start, comes back to it after the period, and run on for 40 periods its switches keep
    that period."""
    law = RateState(a=A, b=B, dc=DC, f0=F0, v_ref=V0)
    system = _pair(law, LinearWeakening(FS, FD, TAU))
    cycle = rate_state_cycle(system, x0=[F0 * N / K1, 0.0], v0=[0.0, 0.0], transient=6.0)
    stuck = abs(V2 - cycle.v0[1]) < 1e-12 * V2
    theta0 = DC / V0 * math.exp(cycle.psi0[0][0])
    t = np.linspace(0.0, 41 * cycle.period, 41 * 200 + 1)
    ref, events = _reference(t, cycle.x0, cycle.v0, theta0, "aging", held=stuck)
    scale = np.ptp(ref[:201], axis=0)
    assert np.all(np.abs(ref[200] - cycle.x0) < 1e-6 * scale)
    onsets = np.array([te for te, s in events if s == 0])
    assert onsets.size >= 40 and np.diff(onsets) == pytest.approx(cycle.period, rel=1e-6)
    assert cycle.stable and np.sum(np.abs(cycle.multipliers) > 1e-6) < cycle.multipliers.size  # a stick: a 0


@pytest.mark.slow
def test_the_pairs_cycle_followed_along_a_stiffness_closes_under_the_integration_written_apart():
    """`continue_system` on the pair (its cycles found by Newton on runs with their switches) along the
    rate-and-state block's stiffness: at the last value the cycle closes under the integration
    written apart with that stiffness."""
    from stickslip.system import continue_system
    law = RateState(a=A, b=B, dc=DC, f0=F0, v_ref=V0)
    branch = continue_system(lambda k: _pair(law, LinearWeakening(FS, FD, TAU), k), K1, 1.2 * K1, points=3,
                             x0=[F0 * N / K1, 0.0], v0=[0.0, 0.0], transient=6.0, parameter="k1")
    assert branch.stopped.startswith("reached") and branch.values.size == 3
    x0, v0, psi0 = branch.x0[-1], branch.v0[-1], branch.psi0[-1, 0]
    t = np.linspace(0.0, branch.period[-1], 201)
    ref, _ = _reference(t, x0, v0, DC / V0 * math.exp(psi0), "aging", held=abs(V2 - v0[1]) < 1e-12 * V2,
                        k1=1.2 * K1)
    assert np.all(np.abs(ref[-1] - x0) < 1e-6 * np.ptp(ref, axis=0))
    assert np.all(np.diff(branch.period) != 0)  # the cycle changes along the branch
