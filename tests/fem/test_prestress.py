"""The centrifugal prestress of a turning solid (`stickslip.fem.prestress`, issue 45), against beam
theory.

A steel cantilever (200 x 10 x 10 mm, quadratic tetrahedra) clamped at the axis and turning about z:
* its centrifugal elongation at the tip is the rod's ``rho omega^2 L^3 / (3 E)`` (1 %);
* the stress stiffness on the field ``u = s e_z`` (``s`` along the beam) is the rod's tension
  integrated, ``A rho omega^2 L^3 / 3`` (1 %);
* its first bending modes (across the turning plane and in it, the stress stiffening alone) rise as
  ``omega_1^2 = omega_10^2 + K omega^2`` with Southwell's coefficient ``K = 1.1933`` of a uniform
  cantilever without hub (published, e.g. Hodges and Rutkowski 1981), computed here too from the
  first-order perturbation ``int T phi'^2 / int phi^2`` with the beam's exact mode shape and the
  tension ``T = rho A omega^2 (L^2 - x^2) / 2``: 1 %. Threshold chosen after a first run gave 0.24 %
  (three-dimensional and mesh effects of a beam 20 thick).
"""

import dataclasses

import numpy as np
import pytest
import scipy.sparse as sp
from scipy.integrate import quad
from scipy.sparse.linalg import eigsh

from stickslip.errors import ParameterError
from stickslip.fem import Material
from stickslip.fem.prestress import centrifugal_stiffness
from stickslip.fem.solid import assemble_solid, solid_from_meshio, supported_dofs

from .test_solid import box, quadratic

L, B = 0.2, 0.01
STEEL = Material(2.1e11, 0.3, 7850.0)


def southwell_of_beam_theory() -> float:
    beta = 1.8751040687119611  # cos(b) cosh(b) = -1
    sigma = (np.cosh(beta) + np.cos(beta)) / (np.sinh(beta) + np.sin(beta))

    def phi(x):
        s = beta * x
        return np.cosh(s) - np.cos(s) - sigma * (np.sinh(s) - np.sin(s))

    def slope(x):
        s = beta * x
        return beta * (np.sinh(s) + np.sin(s) - sigma * (np.cosh(s) - np.cos(s)))

    top = quad(lambda x: 0.5 * (1 - x * x) * slope(x) ** 2, 0, 1)[0]
    return top / quad(lambda x: phi(x) ** 2, 0, 1)[0]


@pytest.fixture(scope="module", params=[0.0, 120.0], ids=["along-x", "at-120-degrees"])
def beam(request):
    """The cantilever from the axis, along x or turned about z by the angle."""
    mesh = quadratic(box((L, B, B), (20, 1, 1), "tetra"))
    mesh.points[:, 1:] -= B / 2
    a = np.radians(request.param)
    x, y = mesh.points[:, 0].copy(), mesh.points[:, 1].copy()
    mesh.points[:, 0], mesh.points[:, 1] = np.cos(a) * x - np.sin(a) * y, np.sin(a) * x + np.cos(a) * y
    solid = solid_from_meshio(mesh, "beam", units="m")
    return solid, assemble_solid(solid, STEEL), supported_dofs(solid, ["x0"]), a


def test_southwells_coefficient_of_beam_theory_is_the_published_one():
    assert southwell_of_beam_theory() == pytest.approx(1.1933, abs=1e-4)


def test_a_turning_cantilever_stiffens_as_southwell_says(beam):
    solid, system, held, angle = beam
    free = np.setdiff1d(np.arange(system.n_dofs), held)
    mass = sp.csc_array(system.consistent_mass[free][:, free])

    def lowest(K):
        return np.sort(eigsh(sp.csc_array(K[free][:, free]), k=2, M=mass, sigma=0, which="LM")[0])

    w0 = lowest(system.K)
    omega = np.sqrt(w0[0]) / 3
    K_sigma, u0 = centrifugal_stiffness(system, omega, (0.0, 0.0), held)
    w1 = lowest(system.K + K_sigma)
    assert (w1 - w0) / omega**2 == pytest.approx([southwell_of_beam_theory()] * 2, rel=1e-2)
    tip = np.cos(angle) * u0[3 * solid.nodes("x1")].mean() + np.sin(angle) * u0[3 * solid.nodes("x1") + 1].mean()
    assert tip == pytest.approx(STEEL.density * omega**2 * L**3 / (3 * STEEL.young), rel=1e-2)
    # the form on u = s e_z (s along the beam): int sigma_ss dV = A rho omega^2 L^3 / 3, the rod's tension
    # (transposed gradients would give int sigma_zz dV, about 0)
    along = np.cos(angle) * solid.points[:, 0] + np.sin(angle) * solid.points[:, 1]
    u = np.zeros(system.n_dofs)
    u[2::3] = along
    assert u @ (K_sigma @ u) == pytest.approx(B * B * STEEL.density * omega**2 * L**3 / 3, rel=1e-2)
    twice, _ = centrifugal_stiffness(system, 2 * omega, (0.0, 0.0), held)
    assert abs(twice - 4 * K_sigma).max() <= 1e-9 * abs(K_sigma).max()  # as omega^2


def test_centrifugal_stiffness_refuses_what_it_cannot_take(beam):
    _, system, held, _ = beam
    with pytest.raises(ParameterError, match="system"):
        centrifugal_stiffness("beam", 1.0)
    with pytest.raises(ParameterError, match="held"):
        centrifugal_stiffness(system, 1.0, held=[system.n_dofs])


def test_a_pair_with_prestress_adds_it_to_the_turning_partner_only(tmp_path):
    """Wiring (a consistency check, the operator verified above): a pad on a disc sector turning about z,
    ``prestress=True``: the pair's stiffness is the plain one plus the master's centrifugal stiffness with
    its supports held; refused without a turning solid partner."""
    from stickslip.fem.pair import PairProblem, Rotation, Translation

    pad_mesh = box((0.02, 0.02, 0.008), (2, 2, 1), "hexahedron")
    pad_mesh.points += [0.1, 0.0, 0.01]
    disc_mesh = box((0.06, 0.06, 0.01), (3, 3, 1), "hexahedron")
    disc_mesh.points += [0.08, -0.02, 0.0]
    pad = assemble_solid(solid_from_meshio(pad_mesh, "pad", units="m"), Material(5e9, 0.25, 2500.0))
    disc_solid = solid_from_meshio(disc_mesh, "disc", units="m")
    disc = assemble_solid(disc_solid, STEEL)
    plain = PairProblem(pad, "z0", disc, "z1", Rotation(300.0), friction=0.3, clamped_slave=("z1",),
                        clamped_master=("x0",))
    spun = dataclasses.replace(plain, prestress=True)
    K_sigma, _ = centrifugal_stiffness(disc, 300.0, (0.0, 0.0), supported_dofs(disc_solid, ["x0"]))
    added = (spun.K - plain.K).tocsr()
    assert abs(added[: pad.n_dofs]).max() == 0.0
    assert abs(added[pad.n_dofs:, pad.n_dofs:] - K_sigma).max() <= 1e-14 * abs(plain.K).max()  # round-off of K
    assert abs(K_sigma).max() > 0
    with pytest.raises(ParameterError, match="prestress"):
        dataclasses.replace(plain, motion=Translation((1.0, 0.0)), prestress=True)
