"""The paper's stick-slip wave (section 4) in time, against a solver that shares nothing with
`stickslip.sbim`: explicit finite elements of a periodic elastic strip on the rigid body
(`tests/sbim/strip_fe.py`), started from the wave's steady elastodynamic field derived there from
Navier's equations.

* The wave is an elastodynamic state: the tractions of the steady field of its own slip are its
  tractions (the shear by a non-local relation mode by mode, the normal by a local one). Its fields are
  singular at the healing edge (exponent -0.44), so the modes' sum converges slowly: a first exploratory
  run (by a helper, before these tests) measured 0.048 and 0.025 (shear) at 1024 and 4096 modes.
  Thresholds from the singularity's exponent rather than from those numbers: the error falls by at least
  1.6 (4^0.44 = 1.84 expected) and is below 0.05 at 4096 modes.
* The strip is right on a smooth travelling mode: its surface tractions converge to the closed form at
  second order (the helper's run: order 2.0); threshold, a fall by at least 3 from N = 32 to 64.
* Both solvers leave the wave alike. The helper measured, at an eighth of the period's transit, the
  strip 0.60 (N = 64) and 0.60 (128) off the wave after starting on it (first half step 0.08, 0.07),
  the boundary integral run 0.64 and 0.63, and the two 0.053 and 0.037 apart. The claim tested is the
  one the documentation makes (the time-dependent problem does not keep the wave; the scheme is not
  what leaves it): each solver more than 0.45 off the wave, the strip starting within 0.15 of it, the two
  solvers within a fifth of the departure (0.12) of each other and closer on the finer grid. Run here
  (N = 64, 128, no filtering): the strip 0.60 and 0.61 off after starting 0.083 and 0.057 off, the
  boundary integral run 0.64 and 0.63, the two 0.060 and 0.051 apart (listed slow by time: about 6 s).
"""

import types

import numpy as np
import pytest

from stickslip.halfspace import decaying_wave
from stickslip.sbim import run_inplane
from stickslip.sbim.waves import WaveOnGrid

from .strip_fe import SteadyField, Strip

G, CS, A = 3e10, 3000.0, 1.0


@pytest.fixture(scope="module")
def field():
    wave = decaying_wave(3.0, -0.5, 1e-4, 1e-3, nu=0.25, mu=0.5, tau_yy=-0.01)
    return SteadyField(wave, G, CS, A, M=2**16)


def _error(a, b, scale):
    return float(np.mean(np.abs(a - b)) / np.mean(np.abs(scale)))


def test_the_waves_tractions_are_the_steady_elastodynamic_field_of_its_slip(field):
    half = field.L / field.M / 2  # mid-points: none on an edge
    X = np.arange(field.M) * field.L / field.M + half
    wave = field.data(X)
    ok = np.isfinite(wave["shear_stress"]) & np.isfinite(wave["normal_traction"])
    shear = wave["shear_stress"][ok] - wave["shear_stress"][ok].mean()
    normal = wave["normal_traction"][ok] - field.sig0[1]
    errors = []
    for modes in (1024, 4096):
        sxy, syy = field.surface_tractions(modes, shift=half)
        errors.append((_error(sxy[ok], wave["shear_stress"][ok], shear),
                       _error(syy[ok], wave["normal_traction"][ok], normal)))
    (s1, n1), (s2, n2) = errors
    assert s2 < 0.05 and n2 < 0.05, errors
    assert s1 / s2 > 1.6 and n1 / n2 > 1.6, errors
    assert abs(np.mean(wave["shear_stress"][ok]) - (field.sig0[0] - G * field.W / CS)) < 1e-3 * abs(field.sig0[0])


def test_the_strip_converges_at_second_order_on_a_smooth_travelling_mode():
    """The surface moved as one travelling mode, ``u_x = U cos(k (x - c t))``, ``u_y = 0``: the strip's
    reactions against ``sigma_xy = C_s |k| U cos``, ``sigma_yy = -C_n k U sin`` at an eighth of the transit."""
    M, U, mode, T = 2**10, 1e-4, 2, 2.5e-4
    modes = np.zeros(M, complex)
    modes[mode] = modes[-mode] = U / 2
    solid = types.SimpleNamespace(b=3.0, cbar=-0.5, nu=0.25, mu=0.5)
    smooth = SteadyField(solid, G, CS, A, M=M, modes=modes)
    k = 2 * np.pi * mode / smooth.L
    errors = []
    for n in (32, 64):
        strip = Strip(smooth, n)
        out = strip.run(T, (T,), kinematic=True)
        X = np.arange(n) * strip.h + strip.h / 2 - smooth.c * out["t"][0]
        sxy, syy = smooth.Cs * k * U * np.cos(k * X), -smooth.Cn * k * U * np.sin(k * X)
        top = max(np.abs(sxy).max(), np.abs(syy).max())
        errors.append(max(np.abs(out["shear"][0] - sxy).max(), np.abs(out["normal"][0] - syy).max()) / top)
    assert errors[0] / errors[1] > 3.0, errors


def test_the_wave_leaves_alike_in_the_boundary_integral_run_and_the_strip(field):
    wave = field.wave
    departures = []
    for n in (64, 128):
        grid = WaveOnGrid(wave, G, CS, A, n)
        problem = grid.problem(beta=0.25)
        eighth = round(grid.length / abs(grid.speed) / 8 / problem.dt)
        run = run_inplane(problem, eighth, every=eighth)
        T = float(run.t[-1])
        strip = Strip(field, n)
        out = strip.run(T, (T,))
        assert abs(out["t"][0] - T) < 1e-3 * T
        x = np.arange(n) * strip.h + strip.h / 2
        exact = field.data(x - field.c * T)["slip_rate"]
        first = field.data(x - field.c * out["dt"] / 2)["slip_rate"]
        start = _error(out["first"], first, first)
        strip_off, sbim_off = _error(out["V"][0], exact, exact), _error(run.slip_rate[-1], exact, exact)
        apart = _error(out["V"][0], run.slip_rate[-1], exact)
        departures.append((start, strip_off, sbim_off, apart))
    for start, strip_off, sbim_off, apart in departures:
        assert start < 0.15 and strip_off > 0.45 and sbim_off > 0.45, departures
        assert apart < 0.12, departures
    assert departures[1][3] < departures[0][3], departures
