"""The energy books of in-plane runs on a rigid body (`stickslip.sbim.energy.energy_book`) against closed
forms: the plane S and P waves' energy fluxes under uniform steps, steady Coulomb sliding's friction and
radiation, slip-weakening's fracture energy, a slowly loaded surface storing the loading's work (and the
static energy the equilibrium's half of load . U), a suddenly loaded frictionless contact radiating half
of it as it settles; a killed run's books resume to the bit.

Thresholds: the closed forms of uniform steps at round-off (the rates are the radiation limit's from the
first step); the others set after a first look at the values, said at each."""

import math

import numpy as np
import pytest

from stickslip.errors import ParameterError
from stickslip.halfspace import decaying_wave
from stickslip.sbim import (CoulombFriction, FreeSurface, InplaneProblem, SlipWeakeningFriction, Solid,
                            run_inplane)
from stickslip.sbim.energy import energy_book
from stickslip.sbim.inplane import mode_load, uniform_load

MU, C, NU, L = 3e10, 3000.0, 0.25, 1.0
ETA = math.sqrt(2 * (1 - NU) / (1 - 2 * NU))


def _book(load, law, steps=200, every=50, elements=16, **kw):
    run = run_inplane(InplaneProblem(MU, C, NU, L, elements, load, law, beta=0.25, **kw), steps, every=every)
    return run, energy_book(run)


def test_uniform_steps_radiate_the_plane_waves_flux():
    # a free surface under a shear step moves at tau c_s / mu: the S wave carries (rho c_s) v^2 = tau^2 c_s / mu
    run, b = _book(uniform_load(1e6, 0.0), FreeSurface())
    assert b.wave_energy[-1] == pytest.approx(1e12 * C / MU * L * run.t[-1], rel=1e-12)
    # under tension it opens at sigma c_s / (eta mu): the P wave carries sigma^2 c_s / (eta mu)
    run, b = _book(uniform_load(0.0, 1e6), FreeSurface())
    assert b.wave_energy[-1] == pytest.approx(1e12 * C / (ETA * MU) * L * run.t[-1], rel=1e-12)
    assert np.all(b.static_energy == 0) and np.all(b.dissipation == 0)


def test_steady_coulomb_sliding_dissipates_f_p_v_and_radiates_the_excess():
    f, p, tau = 0.5, 1e6, 0.8e6
    run, b = _book(uniform_load(tau, -p), CoulombFriction(0.6, f))
    v, t = (tau - f * p) * C / MU, run.t[-1]
    assert b.friction_energy[-1] == pytest.approx(f * p * v * L * t, rel=1e-12)
    assert b.fracture_energy[-1] == pytest.approx(0.0, abs=1e-12 * b.friction_energy[-1])
    assert b.wave_energy[-1] == pytest.approx((tau - f * p) ** 2 * C / MU * L * t, rel=1e-12)
    assert b.load_work[-1] == pytest.approx(tau * v * L * t, rel=1e-12)


def test_slip_weakening_leaves_its_fracture_energy_once_weakened():
    """Uniform sliding weakens every node together: (f_s - f_d) p D_c / 2 per unit area, to the step's first
    order (threshold 1 % and a fall to at most 0.6 when the step halves, set before; measured 0.42 % and
    0.21 %; a first version of this test did not refine its step)."""
    fs, fd, dc, p = 0.6, 0.4, 1e-4, 1e6
    tau = 0.7e6  # above the static strength: sliding from the first step
    errors = []
    for beta in (0.25, 0.125):
        problem = InplaneProblem(MU, C, NU, L, 4, uniform_load(tau, -p), SlipWeakeningFriction(fs, fd, dc),
                                 beta=beta)
        steps = int(0.02 / problem.dt)  # twice D_c over the first rate
        run = run_inplane(problem, steps, every=steps)
        assert run.slip[-1].min() > dc
        errors.append(abs(energy_book(run).fracture_energy[-1] / ((fs - fd) * p * dc / 2 * L) - 1))
    assert errors[0] < 0.01 and errors[1] < 0.6 * errors[0]


def test_a_slowly_loaded_surface_stores_the_loadings_work():
    """Shear and normal modes ramped smoothly over 20 periods: the static energy is half of load . U at the
    end (5e-6; threshold 1e-4) and little is radiated (4e-4 of it; threshold 2e-3): the coupling S12 in the
    static stiffness matters, both components moving."""
    k = 2 * math.pi * 2 / L
    period = 2 * math.pi / (k * C)

    def ramp(t):
        r = min(max(t / (20 * period), 0.0), 1.0)
        return r * r * (3 - 2 * r)

    def load(x, t):
        return 1e5 * np.cos(k * x) * ramp(t), 2e5 * np.sin(k * x + 0.3) * ramp(t)

    problem = InplaneProblem(MU, C, NU, L, 16, load, FreeSurface(), beta=0.25)
    run = run_inplane(problem, int(30 * period / problem.dt), every=20)
    b = energy_book(run)
    tx, ty = load(problem.x, run.t[-1])
    half = 0.5 * problem.dx * np.sum(tx * run.slip[-1] + ty * run.opening[-1])
    assert np.abs(run.opening[-1]).max() > 0.5 * np.abs(run.slip[-1]).max()  # both components move
    assert b.static_energy[-1] == pytest.approx(half, rel=1e-4)
    assert abs(b.wave_energy[-1]) < 2e-3 * b.static_energy[-1]


def test_a_suddenly_loaded_frictionless_contact_radiates_half_the_work_as_it_settles():
    """A shear mode applied at once on a frictionless contact (no surface wave there): at rest the loading
    has done twice the static energy, the rest radiated (0.1 to 0.2 % from 30 periods to 40; threshold 1 %,
    set after that look; 5 % off at 5 periods, still ringing)."""
    k = 2 * math.pi * 2 / L
    period = 2 * math.pi / (k * C)

    def load(x, t):
        return 1e5 * np.cos(k * x), np.full(x.shape, -1e6)

    problem = InplaneProblem(MU, C, NU, L, 16, load, CoulombFriction(0.0, 0.0), beta=0.25)
    run = run_inplane(problem, int(40 * period / problem.dt), every=20)
    b = energy_book(run)
    late = run.t > 30 * period
    assert np.all(run.opening == 0)
    assert np.max(np.abs(b.wave_energy[late] / b.static_energy[late] - 1)) < 0.01
    assert np.max(np.abs(b.load_work[late] / b.static_energy[late] - 2)) < 0.02


def test_a_killed_runs_books_resume_to_the_bit(tmp_path):
    from .resume import killed_and_resumed

    def problem():
        return InplaneProblem(MU, C, NU, L, 16, uniform_load(0.7e6, -1e6), SlipWeakeningFriction(0.6, 0.4, 1e-6),
                              beta=0.25)

    whole, resumed = killed_and_resumed(problem, 120, 10, 57, tmp_path / "run.nc")
    for name in whole.BOOKS:
        assert np.array_equal(getattr(resumed, name), getattr(whole, name)), name
    assert whole.dissipation[-1] > 0


LOWER = Solid(0.5 * MU, 0.8 * C, 0.3)  # another density and Poisson's ratio


def test_steady_sliding_between_two_materials_books_each_sides_radiation():
    """Uniform Coulomb sliding between two materials: the slip rate is the radiation limit of both sides in
    series, (tau - f p) (c+ / mu+ + c- / mu-); each side radiates its plane S wave; nothing is stored."""
    f, p, tau = 0.5, 1e6, 0.8e6
    run, b = _book(uniform_load(tau, -p), CoulombFriction(0.6, f), lower=LOWER)
    v, t = (tau - f * p) * (C / MU + LOWER.shear_wave_speed / LOWER.shear_modulus), run.t[-1]
    assert run.slip_rate[-1] == pytest.approx(np.full(16, v), rel=1e-12)
    assert b.friction_energy[-1] == pytest.approx(f * p * v * L * t, rel=1e-12)
    assert b.wave_energy[-1] == pytest.approx((tau - f * p) * v * L * t, rel=1e-12)
    assert b.load_work[-1] == pytest.approx(tau * v * L * t, rel=1e-12)
    assert np.all(b.static_energy == 0)


def test_a_slowly_loaded_interface_between_two_materials_stores_the_loadings_work():
    """The slowly loaded surface's test with a lower half-space of other stiffness, speed and Poisson's ratio,
    the interface free (each surface loaded by the tractions, opposite): the two surfaces' static energies sum
    to half of load . U, U the relative displacement (Clapeyron; both components and both surfaces move; the
    lower surface's coupling has the other sign). Thresholds the rigid body's (1e-4 and 2e-3)."""
    k = 2 * math.pi * 2 / L
    period = 2 * math.pi / (k * LOWER.shear_wave_speed)

    def ramp(t):
        r = min(max(t / (20 * period), 0.0), 1.0)
        return r * r * (3 - 2 * r)

    def load(x, t):
        return 1e5 * np.cos(k * x) * ramp(t), 2e5 * np.sin(k * x + 0.3) * ramp(t)

    problem = InplaneProblem(MU, C, NU, L, 16, load, FreeSurface(), beta=0.25, lower=LOWER)
    run = run_inplane(problem, int(30 * period / problem.dt), every=20)
    b = energy_book(run)
    tx, ty = load(problem.x, run.t[-1])
    half = 0.5 * problem.dx * np.sum(tx * run.slip[-1] + ty * run.opening[-1])
    assert np.abs(run.opening[-1]).max() > 0.5 * np.abs(run.slip[-1]).max()  # both components move
    assert np.abs(run.lower_displacement_y[-1]).max() > 0.5 * np.abs(run.lower_displacement_x[-1]).max() > 0
    assert b.static_energy[-1] == pytest.approx(half, rel=1e-4)
    assert abs(b.wave_energy[-1]) < 2e-3 * b.static_energy[-1]


def test_the_lower_surfaces_displacement_is_in_the_dataset_and_absent_on_a_rigid_body():
    run = run_inplane(InplaneProblem(MU, C, NU, L, 16, mode_load(1e5, 1e5, 1, L), FreeSurface(), lower=LOWER), 10)
    ds = run.to_xarray()
    assert ds["lower_displacement_y"].attrs["units"] == "m"
    assert np.array_equal(ds["lower_displacement_x"].values, run.lower_displacement_x)
    rigid = run_inplane(InplaneProblem(MU, C, NU, L, 16, mode_load(1e5, 1e5, 1, L), FreeSurface()), 10)
    assert rigid.lower_displacement_x is None and "lower_displacement_x" not in rigid.to_xarray()


def test_gaps_closed_within_a_step_are_booked_as_contact_energy_and_coulomb_leaves_no_fracture_energy():
    """Steady sliding perturbed until it opens and lands again (f = 2, Coulomb, an overstress of 10): the
    normal traction works only on the gaps the scheme closes within a step (impacts), which dissipate;
    a Coulomb law with one coefficient has no fracture energy (found by a review: the impacts were booked
    as fracture energy)."""
    from stickslip.figures.beyond import regimes

    problem = regimes.problem(2.0, 10.0, 64, regularised=False)
    run = run_inplane(problem, int(1.0 * L / C / problem.dt), every=8)
    b = energy_book(run)
    assert run.opening.max() > 0
    assert b.contact_energy[-1] > 1e-3 * b.dissipation[-1]
    assert abs(b.fracture_energy[-1]) < 1e-9 * b.dissipation[-1]


def test_a_run_from_an_initial_state_is_refused_naming_run():
    from stickslip.sbim.waves import WaveOnGrid

    grid = WaveOnGrid(decaying_wave(3.0, -0.5, 1e-4, 1e-3, nu=NU, mu=0.5, tau_yy=-0.01), MU, C, 1.0, 32)
    run = run_inplane(grid.problem(), 4)
    with pytest.raises(ParameterError, match="initial state"):
        energy_book(run)
