"""The modally reduced CEA of a pair (`stickslip.fem.reduced`, issue 45) against the full CEA.

A lining (3 x 3 x 2 cubes of tetrahedra) pressed on a steel block, friction 0.6, penalty contact;
240 free dofs. Measured before the thresholds below were set (the exploration run, 2026-11-28):

| basis | critical friction, relative to the full CEA's bisection (0.5035126) |
| --- | ---: |
| 20 / 40 / 80 / 160 modes (commercial tools' reduction) | 3.3e-2 / 4.8e-2 / -8.8e-3 / -2.5e-2 |
| the same with the nodes' 32 static vectors (``augment="nodes"``) | -3.0e-3 / 2.8e-3 / 1.3e-4 / 1.7e-5 |
| the same with the modes' static vectors (``augment="modes"``, measured after the thresholds) | -4.3e-1 / 2.2e-3 / 1.2e-4 / 1.5e-6 |

(With 20 modes the modes' static vectors give a spurious instability at friction 0.285: too few
modes for their forces to span the contact's; from 40 on they converge as the nodes' do.)

The thresholds: with the nodes' static vectors 1e-3 at 80 modes and 1e-4 at 160; with the modes'
(``augment="modes"``, the default, two per mode; set before its critical friction was computed,
its eigenvalues at 80 modes having been as close as the nodes') 1e-3 at 80; without, 80 modes at
least 10 times farther off than with (the truncation's error is real, and the static vectors
remove it); a complete basis equal to the full CEA to 1e-7 of |s|.
"""

import dataclasses
import math

import numpy as np
import pytest

from stickslip.errors import ParameterError
from stickslip.fem.cea import complex_eigenvalues
from stickslip.fem.pair import PairProblem, Translation
from stickslip.fem.reduced import modal_basis, reduced_modes, reduced_sweep
from stickslip.fem.solid import assemble_solid, solid_from_meshio

from .test_solid_pair import LINING, STEEL, H, T, solid_mesh

BAND = (0.0, 40e3)


@pytest.fixture(scope="module")
def problem():
    pad = solid_from_meshio(solid_mesh((3, 3, 2), "tetra", T, lift=H - 2e-7), "pad", units="m")
    base = solid_from_meshio(solid_mesh((3, 3, 3), "tetra", H), "block", units="m")
    return PairProblem(assemble_solid(pad, LINING), "z0", assemble_solid(base, STEEL), "z1", Translation((1.0, 0.0)),
                       friction=0.6, clamped_slave=("z1",), clamped_master=("z0",))


def test_with_a_complete_basis_the_reduced_cea_is_the_full_one(problem):
    full = complex_eigenvalues(problem, BAND, count=20, contact_model="penalty", mode_shapes=True)
    assert full.unstable.sum() == 1  # the doublet near 27 kHz has coupled at friction 0.6
    basis = modal_basis(problem, int((~problem.fixed).sum()) - 2, augment="none")
    reduced = reduced_modes(basis, band=BAND, mode_shapes=True)
    assert len(reduced.s) == len(full.s)
    for k, z in enumerate(full.s):
        j = int(np.argmin(np.abs(reduced.s - z)))
        assert abs(reduced.s[j] - z) < 1e-7 * abs(z)
        a, b = full.shapes[:, k], reduced.shapes[:, j]  # the same shape (MAC 1): right eigenvectors, not left
        assert abs(np.vdot(a, b)) ** 2 / (np.vdot(a, a).real * np.vdot(b, b).real) > 1 - 1e-8


def _critical(problem, lo=0.45, hi=0.55, steps=14):
    """The full (penalty) CEA's critical friction by bisection."""
    grows = lambda mu: bool(complex_eigenvalues(dataclasses.replace(problem, friction=mu), BAND, count=20,  # noqa: E731
                                                contact_model="penalty").unstable.any())
    assert not grows(lo) and grows(hi)
    for _ in range(steps):
        lo, hi = (lo, 0.5 * (lo + hi)) if grows(0.5 * (lo + hi)) else (0.5 * (lo + hi), hi)
    return 0.5 * (lo + hi)


@pytest.mark.slow
def test_the_reduced_sweeps_critical_friction_converges_to_the_full_ceas_with_the_static_vectors(problem):
    exact = _critical(problem)
    frictions = np.linspace(0.0, 1.0, 41)
    off = {}
    for augment, count in (("nodes", 80), ("nodes", 160), ("modes", 80), ("none", 80)):
        tracked = reduced_sweep(modal_basis(problem, count, augment=augment), frictions, band=BAND)
        critical = tracked.critical[~np.isnan(tracked.critical)]
        assert critical.size == 1 and tracked.turn[~np.isnan(tracked.critical)][0] == 1
        off[augment, count] = abs(critical[0] / exact - 1.0)
    assert off["nodes", 80] < 1e-3 and off["nodes", 160] < 1e-4 and off["modes", 80] < 1e-3
    assert off["none", 80] > 10 * max(off["nodes", 80], off["modes", 80])


def test_the_reduced_modes_of_a_pair_at_rest_and_with_a_law_are_refused(problem):
    from stickslip.friction import Coulomb

    with pytest.raises(ParameterError, match="augment"):
        modal_basis(problem, 10, augment="static")
    with pytest.raises(ParameterError, match="frictions"):
        reduced_sweep(modal_basis(problem, 10), [0.5, 0.4])
    with pytest.raises(ParameterError, match="count"):
        modal_basis(problem, 10**6)
    lawful = dataclasses.replace(problem, friction=0.0, static_friction=None, law=Coulomb(0.6, 0.5))
    with pytest.raises(ParameterError, match="Coulomb friction"):
        modal_basis(lawful, 10)
    assert math.isfinite(modal_basis(problem, 4).top)
