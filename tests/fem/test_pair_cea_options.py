"""The CEA options of one body with a partner (issue 44: they were refused with a [partner]).

* Penalty contact between the two bodies converges to the mortar constraint at first order in
  the penalty: the pad pressed on a block of its own stiffness at f = 0.5 (modes of both bodies
  in the band, several fluttering); each tenfold stiffer spring cuts the largest eigenvalue
  difference by 5 to 20 (theory: 10), and at 1e4 it is below 1e-4 of |s| (thresholds from the
  first-order theory, as for one body in test_cea_options, set before the run).
* Consistent mass, frictionless (a symmetric problem): the pad on a block of half its stiffness
  (modes of both bodies in the band): the frequencies of scipy's dense ``eigh`` of both
  stiffnesses and consistent masses assembled here with scikit-fem, on the null space of the
  active mortar rows, equal the CEA's with ``mass_matrix="consistent"`` (every mode of the band,
  1e-8 of its top).
* Consistent mass with friction: the pad on a partner 1e2 and 1e3 times stiffer, both bodies' consistent
  mass, reproduces the pad on a rigid flat with its consistent mass (the one-body option that
  test_cea_options checks against a dense solver): every eigenvalue of the band to 10 x the
  compliance ratio, the error first order in it (at 1e2 at least 5 times that at 1e3), and the
  lumped pair is farther from it than that (it is another mass).
"""

import numpy as np
import pytest
import scipy.linalg as sla
import scipy.sparse as sp

from stickslip.fem import ContactProblem, Material, RigidFlat, assemble, contact_frames
from stickslip.fem.cea import complex_eigenvalues
from stickslip.fem.pair import PairProblem, Translation

from .test_pair import pad  # noqa: F401 - the fixture

BAND = (0.0, 150000.0)


def _pair(pad, ratio, friction=0.5):  # noqa: F811
    system, under = pad
    partner = assemble(under, Material(1e10 * ratio, 0.25, 2500.0))
    return PairProblem(system, "bottom", partner, "top", Translation((1.0, 0.0)), clamped_slave=("top",),
                       clamped_master=("bottom",), friction=friction)


def _distance(a, b):
    """The largest relative distance of an eigenvalue of ``a`` to the nearest of ``b``."""
    return max(np.min(np.abs(b - x)) / abs(x) for x in a)


@pytest.mark.slow
def test_penalty_contact_of_two_bodies_converges_to_the_mortar_constraint_at_first_order(pad):  # noqa: F811
    pair = _pair(pad, 1.0)
    exact = complex_eigenvalues(pair, BAND, count=30)
    assert exact.unstable.sum() >= 3
    errors = []
    for penalty in (1e2, 1e3, 1e4):
        s = complex_eigenvalues(pair, BAND, count=30, contact_model="penalty", penalty=penalty).s
        assert len(s) == len(exact.s)
        errors.append(_distance(exact.s, s))
    ratios = np.array(errors[:-1]) / np.array(errors[1:])
    assert np.all((ratios > 5) & (ratios < 20)) and errors[-1] < 1e-4, (errors, ratios)


@pytest.mark.slow
def test_the_consistent_mass_of_two_bodies_gives_the_frequencies_of_a_dense_solver(pad):  # noqa: F811
    from skfem import BilinearForm, asm
    from skfem.helpers import dot

    band = (0.0, 60000.0)
    pair = _pair(pad, 0.5, friction=0.0)
    assert pair.steady.active.all()
    masses = []
    for system in (pair.slave, pair.master):
        basis, order = system.basis
        masses.append(asm(BilinearForm(lambda u, v, w: 2500.0 * dot(u, v)), basis)[order][:, order])
    free = ~pair.fixed
    M = sp.block_diag(masses).toarray()[np.ix_(free, free)]
    K = pair.K.toarray()[np.ix_(free, free)]
    Z = sla.null_space(pair.G.toarray()[:, free])  # the active mortar rows: every slave node in contact
    lam = sla.eigh(Z.T @ K @ Z, Z.T @ M @ Z, eigvals_only=True)
    dense = np.sqrt(np.abs(lam)) / (2 * np.pi)
    dense = dense[(dense >= band[0]) & (dense <= band[1])]
    modes = complex_eigenvalues(pair, band, count=30, mass_matrix="consistent")
    found = np.sort(modes.frequency)
    assert len(found) == len(dense) >= 10 and np.all(modes.neutral)
    assert np.abs(found - dense).max() < 1e-8 * band[1]


@pytest.mark.slow
def test_the_consistent_mass_of_a_stiff_partner_reproduces_the_rigid_surfaces(pad):  # noqa: F811
    system, _ = pad
    rigid = ContactProblem(system, contact_frames(system.body, "bottom", RigidFlat((0, 2e-6), (0, 1), (1.0, 0))),
                           clamped=("top",), friction=0.5)
    reference = complex_eigenvalues(rigid, BAND, count=30, mass_matrix="consistent").s
    errors = []
    for ratio in (1e2, 1e3):
        s = complex_eigenvalues(_pair(pad, ratio), BAND, count=30, mass_matrix="consistent").s
        assert len(s) == len(reference)
        errors.append(max(_distance(reference, s), _distance(s, reference)))
    assert errors[1] < 10 / 1e3 and errors[0] > 5 * errors[1], errors
    lumped = complex_eigenvalues(_pair(pad, 1e3), BAND, count=30).s
    assert len(lumped) != len(reference) or _distance(reference, lumped) > 3 * errors[1]
