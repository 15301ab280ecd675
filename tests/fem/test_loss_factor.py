"""A structural loss factor (issue 45): each material's stiffness times ``1 + i eta`` in the CEA.

* A pad on a block (3-D, friction 0.6: flutter) with one loss factor on both: the CEA equals the dense
  solve of the pencil assembled independently in `test_solid_pair` with its stiffness times
  ``1 + i eta`` (its modes those of ``s^2 = -(1 + i eta) mu`` above the real axis: below it
  ``K (1 + i eta)`` is no model of a material, and its eigenvalues there would grow). Threshold, set
  before the run: 1e-7 of ``|s|``.
* A plane body on a rigid flat with friction and one loss factor: every eigenvalue of the CEA is
  ``sqrt((1 + i eta) s0^2)`` of an undamped one ``s0`` (the friction acts on the rows of the stiffness,
  so the damped pencil is the undamped one times ``1 + i eta``). Threshold: 1e-8 of ``|s|``.
* Two materials of different loss factors: each mode's growth rate is ``-omega / 2`` times its strain
  energy's shares weighted by their loss factors (the modal strain energy method, first order in
  ``eta``; the error is third order in the growth rate). Threshold: 1 % of the rate.
* The reduced CEA with a complete basis equals the full one with loss factors (1e-7); an explicit run
  refuses a loss factor (a model of the frequency domain).
"""

import math

import numpy as np
import pytest
import scipy.linalg as la

from stickslip.errors import ParameterError
from stickslip.fem import Material, RigidFlat, assemble, body_from_meshio, contact_frames
from stickslip.fem.cea import complex_eigenvalues
from stickslip.fem.pair import PairProblem, Translation
from stickslip.fem.reduced import modal_basis, reduced_modes
from stickslip.fem.scheme import BodyScheme, ContactProblem
from stickslip.fem.shares import energy_shares
from stickslip.fem.solid import assemble_solid, solid_from_meshio

from .meshes import rectangle
from .test_solid_pair import H, LINING, STEEL, T, independent_pencil, solid_mesh

ETA = 0.08


def lossy(material, eta):
    return Material(material.young, material.poisson, material.density, loss_factor=eta)


def _pad_on_block(eta_pad, eta_block, friction=0.6, interference=2e-7):
    pad = solid_from_meshio(solid_mesh((2, 2, 1), "tetra", T, lift=H - interference), "pad", units="m")
    base = solid_from_meshio(solid_mesh((2, 2, 2), "tetra", H), "block", units="m")
    problem = PairProblem(assemble_solid(pad, lossy(LINING, eta_pad)), "z0", assemble_solid(base, lossy(STEEL, eta_block)),
                          "z1", Translation((1.0, 0.0)), friction=friction, clamped_slave=("z1",),
                          clamped_master=("z0",))
    return problem, pad, base


def test_the_3d_cea_with_a_loss_factor_is_the_dense_solve_of_theindependent_pencil_times_one_plus_i_eta():
    problem, pad, base = _pad_on_block(ETA, ETA)
    band = (0.0, 60e3)
    modes = complex_eigenvalues(problem, band, count=20)
    Kr, Mr, _ = independent_pencil(pad, base, 0.6, 2e-7)
    mu = la.eigvals(Kr, Mr)
    s = np.sqrt(-(1 + 1j * ETA) * mu.astype(complex))
    s = np.where(s.imag < 0, -s, s)  # of the two roots, the one above the axis
    s = s[(s.imag / (2 * math.pi) >= band[0]) & (s.imag / (2 * math.pi) <= band[1])]
    assert len(s) == len(modes.s) > 5
    for value in modes.s:
        assert np.min(np.abs(s - value)) < 1e-7 * abs(value)
    # below the axis the pencil's eigenvalues mirror those above, growing: none of them may be taken
    assert np.all(modes.s.imag >= 0) and not np.any(modes.growth_rate > 0.1 * ETA * np.abs(modes.s))


def test_a_plane_body_on_a_rigid_flat_with_a_loss_factor_has_each_eigenvalue_times_the_root_of_one_plus_i_eta(tmp_path):
    body = body_from_meshio(rectangle(tmp_path / "b.msh", 0.04, 0.01, 0.004), "block")
    band = (0.0, 150e3)

    def cea(eta):
        system = assemble(body, Material(1e10, 0.3, 2500.0, loss_factor=eta))
        frames = contact_frames(body, "bottom", RigidFlat((0.0, 1e-6), (0.0, 1.0), (1.0, 0.0)))
        return complex_eigenvalues(ContactProblem(system, frames, 0.5, ("top",)), band, count=30).s

    undamped, damped = cea(0.0), cea(ETA)
    expected = np.sqrt((1 + 1j * ETA) * undamped**2)
    expected = np.where(expected.imag < 0, -expected, expected)
    inside = damped.imag / (2 * math.pi) <= band[1] * 0.99  # (the band's edge moves with the frequencies)
    assert inside.sum() > 10
    for value in damped[inside]:
        assert np.min(np.abs(expected - value)) < 1e-8 * abs(value)


def test_two_loss_factors_damp_each_mode_by_its_strain_energy_shares():
    eta_pad, eta_block = 0.02, 0.005
    undamped, _, _ = _pad_on_block(0.0, 0.0, friction=0.0)
    problem, _, _ = _pad_on_block(eta_pad, eta_block, friction=0.0)
    band = (0.0, 60e3)
    reference = complex_eigenvalues(undamped, band, count=20, mode_shapes=True)
    shares = energy_shares(undamped, reference)
    damped = complex_eigenvalues(problem, band, count=20).s
    checked = 0
    for k, s0 in enumerate(reference.s):
        if np.sort(np.abs(reference.s - s0))[1] < 1e-6 * abs(s0):
            continue  # a repeated mode: its shares are not unique
        share = shares.strain_share.values[k]  # (slave, master)
        rate = -abs(s0) / 2 * (eta_pad * share[0] + eta_block * share[1])
        j = int(np.argmin(np.abs(damped.imag - s0.imag)))
        assert damped[j].real == pytest.approx(rate, rel=1e-2)
        checked += 1
    assert checked > 5


def test_the_reduced_cea_with_a_complete_basis_keeps_the_loss_factors():
    problem, _, _ = _pad_on_block(ETA, 0.5 * ETA)
    free = int(np.sum(~problem.fixed))
    basis = modal_basis(problem, free - 2, augment="nodes")
    band = (0.0, 60e3)
    reduced = reduced_modes(basis, band=band).s
    full = complex_eigenvalues(problem, band, count=20, contact_model="penalty").s
    assert len(full) > 5
    for value in full:
        assert np.min(np.abs(reduced - value)) < 1e-7 * abs(value)


def test_an_explicit_run_refuses_a_loss_factor(tmp_path):
    body = body_from_meshio(rectangle(tmp_path / "b.msh", 0.04, 0.01, 0.004), "block")
    system = assemble(body, Material(1e10, 0.3, 2500.0, loss_factor=0.1))
    frames = contact_frames(body, "bottom", RigidFlat((0.0, 1e-6), (0.0, 1.0), (1.0, 0.0)))
    with pytest.raises(ParameterError, match="loss factor.*frequency domain"):
        BodyScheme(ContactProblem(system, frames, 0.5, ("top",))).dt_max  # (the CEA builds the scheme too)
    with pytest.raises(ParameterError, match="loss_factor"):
        Material(1e10, 0.3, 2500.0, loss_factor=1.5)
