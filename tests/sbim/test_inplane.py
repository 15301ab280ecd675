"""The spectral boundary integral method in-plane (`stickslip.sbim.inplane`, issue 46's second increment)
against elastodynamics solved here, not by the code.

* The stiffness of the surface (`inplane_stiffness`): its static limit is the elastostatic half-space's,
  ``2 mu |k| / (3 - 4 nu) [[2 (1 - nu), (1 - 2 nu)], ...]`` (1e-12), and its determinant vanishes at the
  Rayleigh wave speed, the root of Rayleigh's equation ``(2 - x)^2 = 4 sqrt(1 - x) sqrt(1 - x / eta^2)``
  (``x = c_R^2 / c_s^2``) solved here (the free surface's pole; 1e-6 against 1 at 0.8 c_R).
* The kernels (`inplane_kernels`): their Laplace transforms by quadrature here equal ``(S(0) + r p - S(p))
  / p`` (1e-6), ``h(0)`` the stiffness's jump at infinity and ``A(infinity) = r`` (1e-4).
* One Fourier mode of the free surface under a normal traction ``T0 cos(k x)`` applied at ``t = 0``
  against a finite-difference solution of the half-space written here (displacements ``a(y, t) sin kx``,
  ``b(y, t) cos kx``, Navier's equations in depth, second order, its own two grids agreeing to 0.3 %):
  over three shear periods the opening and the slip within 1 % of the static opening at beta = 0.025
  with 32 periods of history, and the error falling with beta. The thresholds were set after a first
  exploratory run (0.34 % and 0.21 %); the error's plateau at fewer periods is the faded history's
  (`hann_taper`; 2.4 % at 8 periods, 0.7 % at 16).
* The radiation limit: uniform steps open the surface at ``c_s sigma0 / (eta mu)`` and slide it at
  ``c_s tau0 / mu`` at once (1e-12); Coulomb contact slides at ``c_s (tau0 - f_d N) / mu`` under
  compression, sticks below ``f_s N`` and opens freely under tension.
"""

import math

import numpy as np
import pytest
from scipy.integrate import quad
from scipy.optimize import brentq

from stickslip.errors import ParameterError
from stickslip.sbim import (CoulombFriction, FreeSurface, InplaneProblem, SlipWeakeningFriction,
                            inplane_kernel_integrals, inplane_stiffness, mode_load, run_inplane, uniform_load)
from stickslip.sbim.inplane_kernels import inplane_kernels

MU, C, L, NU = 3e10, 3000.0, 1000.0, 0.25
ETA = math.sqrt(2 * (1 - NU) / (1 - 2 * NU))


def test_the_static_stiffness_is_the_elastostatic_half_spaces():
    for nu in (0.0, 0.25, 0.4):
        s11, s22, s12 = (v[0].real for v in inplane_stiffness(np.array([1e-7 + 0j]), nu))
        assert s11 == pytest.approx(4 * (1 - nu) / (3 - 4 * nu), rel=1e-10)
        assert s22 == pytest.approx(4 * (1 - nu) / (3 - 4 * nu), rel=1e-10)
        assert s12 == pytest.approx(2 * (1 - 2 * nu) / (3 - 4 * nu), rel=1e-10)


def test_the_free_surface_has_its_pole_at_the_rayleigh_speed():
    for nu in (0.1, 0.25, 0.45):
        eta = math.sqrt(2 * (1 - nu) / (1 - 2 * nu))
        x = brentq(lambda x: (2 - x) ** 2 - 4 * math.sqrt(1 - x) * math.sqrt(1 - x / eta**2), 0.3, 0.999)

        def det(y):
            s11, s22, s12 = (v[0] for v in inplane_stiffness(np.array([1e-12 + 1j * y]), nu))
            return s11 * s22 - s12 * s12

        assert abs(det(math.sqrt(x))) <= 1e-6 * abs(det(0.8 * math.sqrt(x)))


def test_the_kernels_transform_back_to_the_stiffness():
    r = (1.0, ETA, 0.0)
    s0 = [v[0].real for v in inplane_stiffness(np.array([1e-9 + 0j]), NU)]
    for p in (0.4, 1.7):
        S = [v[0] for v in inplane_stiffness(np.array([p + 0j]), NU)]
        for i in range(3):
            transform = quad(lambda T: inplane_kernels(np.array([T]), NU)[i][0] * math.exp(-p * T), 0, 80,
                             limit=400)[0]
            assert transform == pytest.approx(((s0[i] + r[i] * p - S[i]) / p).real, abs=1e-6)
    h0 = inplane_kernels(np.array([0.0]), NU)[:, 0]
    assert h0 == pytest.approx([s0[0], s0[1], s0[2] - (2 - ETA)], abs=1e-9)  # S(inf) = r p + (2 - eta) for S12
    assert inplane_kernel_integrals(np.array([3000.0]), NU)[:, 0] == pytest.approx(r, abs=1e-4)


def finite_differences(k, S, P, t_out, per_wave):
    """The surface's ``a(0, t), b(0, t)`` of ``u_x = a sin kx``, ``u_y = b cos kx`` in ``y > 0`` with
    ``mu (a_y - k b) = S`` and ``lambda k a + (lambda + 2 mu) b_y = P`` at ``y = 0`` (ghost nodes), leapfrog,
    clamped deep enough that no reflection returns."""
    rho = MU / C**2
    cp = C * ETA
    lam = rho * cp**2 - 2 * MU
    M = lam + 2 * MU
    h = 2 * math.pi / k / per_wave
    J = int((0.6 * cp * t_out[-1] + 10 * h) / h) + 1
    n = int(math.ceil(t_out[-1] / (0.4 * h / cp)))
    dt = t_out[-1] / n

    def acc(a, b):
        a[0] = a[2] - 2 * h * (S / MU + k * b[1])
        b[0] = b[2] - 2 * h * (P - lam * k * a[1]) / M
        ay, by = (a[2:] - a[:-2]) / (2 * h), (b[2:] - b[:-2]) / (2 * h)
        ayy, byy = (a[2:] - 2 * a[1:-1] + a[:-2]) / h**2, (b[2:] - 2 * b[1:-1] + b[:-2]) / h**2
        fa = (MU * ayy - M * k * k * a[1:-1] - (lam + MU) * k * by) / rho
        fb = (M * byy - MU * k * k * b[1:-1] + (lam + MU) * k * ay) / rho
        fa[-1] = fb[-1] = 0.0
        return fa, fb

    a, b = np.zeros(J + 2), np.zeros(J + 2)
    fa, fb = acc(a, b)
    a_new, b_new = a.copy(), b.copy()
    a_new[1:-1] += 0.5 * dt * dt * fa
    b_new[1:-1] += 0.5 * dt * dt * fb
    a_old, a, b_old, b = a, a_new, b, b_new
    surface = [(0.0, 0.0), (a[1], b[1])]
    for _ in range(1, n):
        fa, fb = acc(a, b)
        a_new, b_new = a.copy(), b.copy()
        a_new[1:-1] = 2 * a[1:-1] - a_old[1:-1] + dt * dt * fa
        b_new[1:-1] = 2 * b[1:-1] - b_old[1:-1] + dt * dt * fb
        a_old, a, b_old, b = a, a_new, b, b_new
        surface.append((a[1], b[1]))
    surface = np.array(surface)
    times = dt * np.arange(n + 1)
    return np.interp(t_out, times, surface[:, 0]), np.interp(t_out, times, surface[:, 1])


@pytest.mark.slow
def test_one_mode_of_the_free_surface_follows_elastodynamics_solved_in_depth():
    T0, m, N = 1e6, 2, 32
    k = 2 * math.pi * m / L
    period = 2 * math.pi / (k * C)
    t = np.linspace(0.0, 3 * period, 61)
    a1, b1 = finite_differences(k, 0.0, -T0, t, 200)  # the free surface: the body's stress cancels the load
    a2, b2 = finite_differences(k, 0.0, -T0, t, 400)
    static = T0 / (MU * k)
    assert np.abs(b1 - b2).max() <= 0.003 * static and np.abs(a1 - a2).max() <= 0.003 * static
    errors = []
    for beta in (0.1, 0.025):
        problem = InplaneProblem(MU, C, NU, L, N, mode_load(0.0, T0, m, L), beta=beta, history_periods=32)
        run = run_inplane(problem, int(round(3 * period / problem.dt)))
        opening = 2.0 / N * (run.opening @ np.cos(k * problem.x))
        slip = 2.0 / N * (run.slip @ np.sin(k * problem.x))
        assert np.abs(run.opening - np.outer(opening, np.cos(k * problem.x))).max() <= 1e-9 * static  # one mode
        errors.append((np.abs(np.interp(t, run.t, opening) - b2).max(), np.abs(np.interp(t, run.t, slip) - a2).max()))
    assert max(errors[1]) <= 0.01 * static, (errors, static)
    assert errors[0][0] >= 1.5 * errors[1][0] and errors[0][1] >= 1.5 * errors[1][1], errors


def test_the_kernel_table_is_the_kernels_between_its_points():
    from stickslip.sbim.inplane_kernels import kernel_table

    table = kernel_table(NU, 0.003, 20000)  # 60 dimensionless times in steps of 0.003: interpolated
    j = np.array([1, 777, 4321, 12345, 19999])
    assert np.abs(table[:, j] - inplane_kernels(0.003 * j, NU)).max() <= 1e-7 * 1.5


def test_one_mode_within_two_percent_at_a_coarse_step():
    """The same comparison, short: beta = 0.1, 16 periods of history, the reference at 200 points per
    wavelength (1.2 % and 0.8 % measured in the exploratory run; 2 % set then)."""
    T0, m, N = 1e6, 2, 16
    k = 2 * math.pi * m / L
    t = np.linspace(0.0, 3 * 2 * math.pi / (k * C), 31)
    a, b = finite_differences(k, 0.0, -T0, t, 200)
    problem = InplaneProblem(MU, C, NU, L, N, mode_load(0.0, T0, m, L), beta=0.1, history_periods=16)
    run = run_inplane(problem, int(round(t[-1] / problem.dt)))
    opening = np.interp(t, run.t, 2.0 / N * (run.opening @ np.cos(k * problem.x)))
    slip = np.interp(t, run.t, 2.0 / N * (run.slip @ np.sin(k * problem.x)))
    static = T0 / (MU * k)
    assert np.abs(opening - b).max() <= 0.02 * static and np.abs(slip - a).max() <= 0.02 * static


def test_uniform_steps_move_the_free_surface_at_the_radiation_rates():
    run = run_inplane(InplaneProblem(MU, C, NU, L, 16, uniform_load(2e6, 1e6)), 20)
    assert np.abs(run.slip_rate - C * 2e6 / MU).max() <= 1e-12 * C * 2e6 / MU
    assert np.abs(run.opening_rate - C * 1e6 / (ETA * MU)).max() <= 1e-12 * C * 1e6 / (ETA * MU)
    assert np.abs(run.shear_stress).max() <= 1e-6 and np.abs(run.normal_traction).max() <= 1e-6


def test_coulomb_contact_sticks_slides_and_opens():
    law = CoulombFriction(0.6, 0.4)
    stuck = run_inplane(InplaneProblem(MU, C, NU, L, 16, uniform_load(5e6, -10e6), law), 20)
    assert not stuck.slip.any() and not stuck.opening.any() and np.allclose(stuck.shear_stress, 5e6)
    sliding = run_inplane(InplaneProblem(MU, C, NU, L, 16, uniform_load(7e6, -10e6), law), 20)
    assert np.abs(sliding.slip_rate - C * 3e6 / MU).max() <= 1e-12 * C * 3e6 / MU
    assert np.allclose(sliding.normal_traction, -10e6) and not sliding.opening.any()
    opened = run_inplane(InplaneProblem(MU, C, NU, L, 16, uniform_load(2e6, 1e6), law), 20)
    assert np.abs(opened.opening_rate - C * 1e6 / (ETA * MU)).max() <= 1e-12 * C * 1e6 / (ETA * MU)
    assert np.abs(opened.slip_rate - C * 2e6 / MU).max() <= 1e-12 * C * 2e6 / MU  # open: no friction
    weakening = run_inplane(InplaneProblem(MU, C, NU, L, 16, uniform_load(7e6, -10e6),
                                           SlipWeakeningFriction(0.6, 0.4, 0.05)), 300)
    assert weakening.slip_rate[-1].min() == pytest.approx(C * 3e6 / MU, rel=1e-9)
    assert weakening.slip_rate[1].max() < C * 1.1e6 / MU


def test_a_gap_closes_exactly_and_the_impact_compresses():
    """Opened by tension, then pressed: the gap closes to 0 (not below) and the normal traction is
    compressive from then on; the opening never negative and always the sum of its rates."""
    load = lambda x, t: (np.zeros_like(x), np.where(t < 0.01, 1e6, -5e6) + 0 * x)  # noqa: E731
    run = run_inplane(InplaneProblem(MU, C, NU, L, 16, load, CoulombFriction(0.5, 0.5)), 200)
    assert run.opening.min() >= 0.0 and run.opening[-1].max() == 0.0
    assert run.opening.max() > 0.0 and (run.normal_traction[-1] <= 0.0).all()
    dt = run.problem.dt  # the opening is its rate's sum: the closing step stops at contact, not beyond
    assert np.abs(np.cumsum(run.opening_rate[:-1], axis=0) * dt - run.opening[1:]).max() <= 1e-12 * run.opening.max()


def test_a_run_is_a_cf_dataset():
    ds = run_inplane(InplaneProblem(MU, C, NU, L, 16, uniform_load(1e6, -2e6), CoulombFriction(0.6, 0.5)),
                     5).to_xarray()
    assert ds["opening"].attrs["units"] == "m" and ds["normal_traction"].attrs["units"] == "Pa"
    assert ds.sizes["t"] == 6 and ds.attrs["poisson"] == NU


@pytest.mark.parametrize("change, name", [
    (dict(beta=0.7), "beta"), (dict(beta=0.0), "beta"), (dict(poisson=0.5), "poisson"),
    (dict(poisson=-0.1), "poisson"), (dict(elements=2), "elements"), (dict(load=3.0), "load"),
    (dict(law=FreeSurface), "law"), (dict(history_periods=0.1), "history_periods"),
])
def test_bad_input_is_refused_naming_it(change, name):
    args = dict(shear_modulus=MU, shear_wave_speed=C, poisson=NU, length=L, elements=16, load=uniform_load(1e6, 0.0))
    with pytest.raises(ParameterError, match=name):
        InplaneProblem(**{**args, **change})


def test_a_kinetic_friction_above_the_static_one_is_refused():
    with pytest.raises(ParameterError, match="kinetic_friction"):
        CoulombFriction(0.4, 0.6)


@pytest.mark.parametrize("load", [lambda x, t: x, lambda x, t: (1.0, "a"), lambda x, t: (np.ones(3), 0.0)])
def test_a_load_giving_other_than_two_tractions_per_node_is_refused(load):
    with pytest.raises(ParameterError, match="load"):
        run_inplane(InplaneProblem(MU, C, NU, L, 16, load, CoulombFriction(0.5, 0.4)), 5)
