"""In-plane runs from a state with a past (`stickslip.sbim.initial.InitialState`), and the paper's
stick-slip waves as such states (`stickslip.sbim.waves.WaveOnGrid`).

* A free surface under a shear load travelling at ``c = -c_s / 2`` (one Fourier mode, `mode_load` with its
  ``load_speed``), started in its
  steady state (written here from Lamé's potentials, not from the code's stiffness), stays in it over
  the load's transit of the period: largest errors 5.1 % (slip rate) and 6.1 % (opening rate) in a first
  exploratory run (N = 64, mode 3, beta = 0.25; the scheme is first order and the start is the continuous
  steady state), threshold 8 % set after it. Started from rest, the same run is off by more than half.
* The paper's wave (section 4, `stickslip.halfspace.decaying_wave`) as the state: the run's first step
  gives back the wave's slip rate and tractions. The slip rate's L1 error was 0.275, 0.212 and 0.158
  on N = 64, 128 and 256 in a first exploratory run (the slip rate is singular at the slip->stick point
  with the exponent alpha - 1/2 = -0.44: order about 0.44 expected); thresholds 0.35 and a fall by at
  least 1.4 from 64 to 256 set after it.
"""

import math

import numpy as np
import pytest

from stickslip.errors import ParameterError
from stickslip.halfspace import decaying_wave
from stickslip.sbim import CoulombFriction, FreeSurface, InplaneProblem, run_inplane
from stickslip.sbim.initial import InitialState
from stickslip.sbim.inplane import mode_load
from stickslip.sbim.waves import WaveOnGrid

MU, CS, NU, L = 3e10, 3000.0, 0.25, 1.0


def _moving_load_response(p, nu):
    """The surface displacement ``(u_x, u_y)`` (per ``tau / (mu k)``) of a free half-space under a unit
    shear load ``e^{i k x + s t}``, ``p = s / (k c_s)``: potentials ``A e^{-alpha y}``, ``B e^{-beta y}``
    (k = c_s = mu = 1) whose surface tractions balance the load."""
    eta2 = 2 * (1 - nu) / (1 - 2 * nu)
    lam = eta2 - 2.0
    alpha, beta = np.sqrt(1 + p * p / eta2), np.sqrt(1 + p * p)
    M = np.array([[-2j * alpha, beta**2 + 1], [lam * (alpha**2 - 1) + 2 * alpha**2, 2j * beta]])
    A, B = np.linalg.solve(M, np.array([-1.0, 0.0]))
    return 1j * A - beta * B, -alpha * A - 1j * B


def _moving_load_run(start_steady: bool, N=64, mode=3, tau=1e6):
    k, c = 2 * math.pi * mode / L, -0.5 * CS
    s = -1j * k * c
    ux, uy = (tau / (MU * k)) * np.array(_moving_load_response(s / (k * CS), NU))
    x = np.arange(N) * L / N

    def steady(t):
        phase = np.exp(1j * k * (x - c * t))
        return (ux * phase).real, (uy * phase).real, (s * ux * phase).real, (s * uy * phase).real

    load = mode_load(tau, 0.0, mode, L, load_speed=c)  # the package's moving load
    initial = InitialState(*steady(0.0)[:2], lambda t: steady(t)[2:]) if start_steady else None
    problem = InplaneProblem(MU, CS, NU, L, N, load, FreeSurface(), beta=0.25, initial=initial)
    steps = int(L / abs(c) / problem.dt)
    run = run_inplane(problem, steps, every=steps // 8)
    errors = []
    for i, t in enumerate(run.t):
        _, _, vx, vy = steady(t)
        errors.append((np.abs(run.slip_rate[i] - vx).max() / np.abs(vx).max(),
                       np.abs(run.opening_rate[i] - vy).max() / np.abs(vy).max()))
    return np.array(errors)


def test_a_free_surface_under_a_moving_load_stays_in_its_steady_state():
    errors = _moving_load_run(start_steady=True)
    assert errors.max() < 0.08, errors


def test_a_moving_patch_is_the_standing_one_carried_at_its_speed():
    from stickslip.sbim.inplane import patch_load

    x = np.arange(64) / 64.0
    moving, standing = patch_load(1.0, -2.0, 5.0, 0.1, 0.25, load_speed=-3.0), patch_load(1.0, -2.0, 5.0, 0.1, 0.875)
    for a, b in zip(moving(x, 0.125), standing(x, 0.0)):  # 0.25 - 3 / 8 = -0.125, that is 0.875 on the period
        assert np.array_equal(a, b)


def test_from_rest_the_same_run_is_far_from_the_steady_state():
    assert _moving_load_run(start_steady=False)[1:].max() > 0.5


def _wave():
    return decaying_wave(3.0, -0.5, 1e-4, 1e-3, nu=NU, mu=0.5, tau_yy=-0.01)


def _first_step_errors(N):
    grid = WaveOnGrid(_wave(), MU, CS, 1.0, N)
    run = run_inplane(grid.problem(beta=0.25), 1)
    exact = grid.exact(0.0)
    out = {}
    for name in ("slip_rate", "shear_stress", "normal_traction"):
        e, r = exact[name], getattr(run, name)[0]
        out[name] = np.mean(np.abs(r - e)) / np.mean(np.abs(e - (0.0 if name == "slip_rate" else e.mean())))
    return out


def test_the_papers_wave_as_the_state_gives_back_its_slip_rate_converging_with_the_grid():
    errors = {N: _first_step_errors(N) for N in (64, 256)}
    assert errors[64]["slip_rate"] < 0.35 and errors[256]["slip_rate"] < 0.35, errors
    assert errors[64]["slip_rate"] / errors[256]["slip_rate"] > 1.4, errors


def test_the_papers_wave_as_the_state_gives_back_its_tractions():
    """Thresholds set with the slip rate's (a first look: shear 0.06-0.13, normal 0.03-0.08 of their
    variation, N = 64 to 256)."""
    errors = _first_step_errors(128)
    assert errors["shear_stress"] < 0.2 and errors["normal_traction"] < 0.2, errors


def test_the_wave_on_a_grid_is_in_the_run_frame():
    """Reflected and seen from the rigid body: backward slip on the slip zone, held on the stick zone,
    the paper's Coulomb condition there, the remote stresses as the tractions' means (closed forms)."""
    w = _wave()
    grid = WaveOnGrid(w, MU, CS, 1.0, 300)
    e = grid.exact(0.0)
    xi = np.mod((grid.x + grid.dx / 2) / 1.0, w.b)
    slip = xi >= 1.0
    assert np.all(e["slip_rate"][slip] < 0) and np.all(e["slip_rate"][~slip] == 0)
    assert np.allclose(e["shear_stress"][slip], w.mu * e["normal_traction"][slip], rtol=1e-9, atol=1e-3)
    assert grid.speed == pytest.approx(-0.5 * CS)
    assert np.median(e["normal_traction"]) == pytest.approx(MU * w.tau_yy, rel=0.05)


@pytest.mark.parametrize("make, name", [
    (lambda: InitialState(np.zeros(4), np.zeros(5), lambda t: (np.zeros(4), np.zeros(4))), "opening"),
    (lambda: InitialState([0, np.nan, 0, 0], np.zeros(4), lambda t: 0), "slip"),
    (lambda: InitialState(np.zeros((2, 2)), np.zeros(4), lambda t: 0), "slip"),
    (lambda: InitialState(np.zeros(4), np.zeros(4), "rates"), "rates"),
    (lambda: InplaneProblem(MU, CS, NU, L, 8, lambda x, t: (0 * x, 0 * x), initial="state"), "initial"),
    (lambda: InplaneProblem(MU, CS, NU, L, 8, lambda x, t: (0 * x, 0 * x),
                            initial=InitialState(np.zeros(4), np.zeros(4), lambda t: (0, 0))), "initial"),
    (lambda: InplaneProblem(MU, CS, NU, L, 4, lambda x, t: (0 * x, 0 * x), CoulombFriction(0.5, 0.5),
                            initial=InitialState(np.zeros(4), -np.ones(4), lambda t: (0, 0))), "opening"),
    (lambda: run_inplane(InplaneProblem(MU, CS, NU, L, 4, lambda x, t: (0 * x, 0 * x),
                                        initial=InitialState(np.zeros(4), np.zeros(4),
                                                             lambda t: (np.zeros(3), np.zeros(4)))), 2), "rates"),
    (lambda: run_inplane(InplaneProblem(MU, CS, NU, L, 4, lambda x, t: (0 * x, 0 * x),
                                        initial=InitialState(np.zeros(4), np.zeros(4),
                                                             lambda t: (np.full(4, np.inf), np.zeros(4)))), 2),
     "rates"),
    (lambda: run_inplane(InplaneProblem(MU, CS, NU, L, 4, lambda x, t: (0 * x, 0 * x),
                                        initial=InitialState(np.zeros(4), np.zeros(4), lambda t: 1 / 0)), 2),
     "rates"),
    (lambda: WaveOnGrid(_wave(), MU, CS, 1e9, 4, periods=4096), "stick_length"),
    (lambda: WaveOnGrid("wave", MU, CS, 1.0, 64), "wave"),
    (lambda: WaveOnGrid(decaying_wave(3.0, -0.5, 1e-4, 1e-3, nu=0.0, mu=0.5), MU, CS, 1.0, 64), "tau_yy"),
    (lambda: WaveOnGrid(_wave(), MU, CS, 0.0, 64), "stick_length"),
    (lambda: WaveOnGrid(_wave(), MU, CS, 1.0, 64, periods=0), "periods"),
    (lambda: WaveOnGrid(_wave(), MU, CS, 1.0, 64).problem(law="coulomb"), "law"),
    (lambda: WaveOnGrid(_wave(), MU, CS, 1.0, 64).initial(beta=1.0), "beta"),
    (lambda: WaveOnGrid(_wave(), MU, CS, 1.0, 64).initial(perturbation=math.inf), "perturbation"),
])
def test_bad_input_is_named(make, name):
    with pytest.raises(ParameterError) as err:
        make()
    assert err.value.name == name
