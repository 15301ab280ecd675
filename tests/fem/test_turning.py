"""The gyroscopic and transport terms of a turning solid (`stickslip.fem.turning`, issue 45), against
what does not lean on them, as `test_transport` checks the plane bodies':

* On rigid and linear fields of a block of two materials turning about a z axis off the block: the
  turn ``r = e_z x (x - c)``, the in-plane expansion ``e``, the translations ``t_x, t_y, t_z``, whose
  ``(v . grad)`` images are written out, ``G`` and ``B`` equal the closed forms of the block's in-plane
  moment of inertia ``I``, mass and first moment (``r.B r = e.B e = omega^2 I``, ``e.G r = -2 omega I``,
  ...): exact on hexahedra, equal to round-off.
* A thin structured annulus of hexahedra clamped at its bore, turning at 5 % of its first frequency:
  the space-fixed (Eulerian) model's eigenvalues are the turning frame's (``M u'' + 2 Omega J u' +
  (K - Omega^2 M_xy) u = 0``, Coriolis and centrifugal terms as mass-like forms written here) shifted by
  ``-i n Omega`` (``n``: each mode's wave number round the rim), the median mismatch below 1e-3 of
  ``|s|`` on the finer annulus and falling with the mesh, the wrong shift missing by far more.
  Thresholds as the plane test's, set before the run.
"""

import math

import meshio
import numpy as np
import pytest
import scipy.linalg as sla
from skfem import Basis, BilinearForm, asm

from stickslip.fem import Material
from stickslip.fem.solid import assemble_solid, skfem_mesh, solid_from_meshio, supported_dofs
from stickslip.fem.turning import solid_transport_operators

from .test_solid import box
from .test_transport import dense_eig, shifted_mismatch


def _two_materials():
    mesh = box((0.05, 0.01, 0.008), (5, 2, 2), "hexahedron")
    hexes = mesh.cells[0].data
    x = mesh.points[hexes].mean(axis=1)[:, 0]
    mesh.cell_sets.update({"a": [np.flatnonzero(x < 0.02)] + [np.array([], int)] * (len(mesh.cells) - 1),
                           "b": [np.flatnonzero(x >= 0.02)] + [np.array([], int)] * (len(mesh.cells) - 1)})
    del mesh.cell_sets["all"]
    return solid_from_meshio(mesh, "layers", units="m")


def test_the_transport_terms_of_rigid_and_linear_fields_are_their_closed_forms():
    solid = _two_materials()
    system = assemble_solid(solid, {"a": Material(1e10, 0.25, 2500.0), "b": Material(2e11, 0.3, 7850.0)})
    omega, c = 250.0, np.array([0.01, -0.02])
    I = m = 0.0
    first = np.zeros(2)
    for rho, (x0, x1) in ((2500.0, (0.0, 0.02)), (7850.0, (0.02, 0.05))):
        w, h, t = x1 - x0, 0.01, 0.008
        d = np.array([0.5 * (x0 + x1), 0.005]) - c
        I += rho * w * h * t * ((w**2 + h**2) / 12 + d @ d)  # in-plane moment about the axis
        m += rho * w * h * t
        first += rho * w * h * t * d
    G, B = solid_transport_operators(system, omega, tuple(c))
    d = solid.points[:, :2] - c
    one, zero = np.ones(len(d)), np.zeros(len(d))
    pack = lambda fx, fy, fz: np.column_stack([fx, fy, fz]).ravel()  # noqa: E731
    fields = {"r": pack(-d[:, 1], d[:, 0], zero), "e": pack(d[:, 0], d[:, 1], zero), "t_x": pack(one, zero, zero),
              "t_y": pack(zero, one, zero), "t_z": pack(zero, zero, one)}
    exact = {("r", "B", "r"): omega**2 * I, ("e", "B", "e"): omega**2 * I, ("t_x", "B", "t_x"): 0.0,
             ("t_z", "B", "t_z"): 0.0, ("e", "G", "r"): -2 * omega * I, ("t_x", "G", "r"): -omega * first[0],
             ("t_y", "G", "r"): -omega * first[1], ("t_x", "G", "e"): -omega * first[1], ("t_z", "G", "r"): 0.0}
    for (a, which, b), value in exact.items():
        M = {"G": G, "B": B}[which]
        got = fields[a] @ (M @ fields[b])
        roundoff = 1e-12 * (np.abs(fields[a]) @ (abs(M) @ np.abs(fields[b])))
        assert got == pytest.approx(value, rel=1e-10, abs=roundoff), (a, which, b)
    assert abs(G + G.T).max() == 0 and abs(B - B.T).max() <= 1e-12 * abs(B).max()


def annulus(n_theta, n_r, inner=0.1, outer=0.15, thick=0.004):
    """A structured annulus of hexahedra (one layer), face groups ``bore`` and ``rim``."""
    r = np.linspace(inner, outer, n_r + 1)
    phi = 2 * math.pi * np.arange(n_theta) / n_theta
    z = np.array([0.0, thick])
    R, P, Z = np.meshgrid(r, phi, z, indexing="ij")
    points = np.column_stack([(R * np.cos(P)).ravel(), (R * np.sin(P)).ravel(), Z.ravel()])
    node = lambda i, j, k: (i * n_theta + j % n_theta) * 2 + k  # noqa: E731
    hexes = [[node(i, j, 0), node(i + 1, j, 0), node(i + 1, j + 1, 0), node(i, j + 1, 0), node(i, j, 1),
              node(i + 1, j, 1), node(i + 1, j + 1, 1), node(i, j + 1, 1)] for i in range(n_r) for j in range(n_theta)]
    bore = [[node(0, j, 0), node(0, j + 1, 0), node(0, j + 1, 1), node(0, j, 1)] for j in range(n_theta)]
    rim = [[node(n_r, j, 0), node(n_r, j, 1), node(n_r, j + 1, 1), node(n_r, j + 1, 0)] for j in range(n_theta)]
    cells = [("hexahedron", np.array(hexes)), ("quad", np.array(bore)), ("quad", np.array(rim))]
    empty = np.array([], dtype=int)
    sets = {"bore": [empty, np.arange(n_theta), empty], "rim": [empty, empty, np.arange(n_theta)]}
    return solid_from_meshio(meshio.Mesh(points, cells, cell_sets=sets), "annulus", units="m")


RHO = 7800.0


def _mismatch(n_theta, n_r, sign=1.0):
    solid = annulus(n_theta, n_r)
    system = assemble_solid(solid, Material(2e11, 0.3, RHO))
    free = np.setdiff1d(np.arange(system.n_dofs), supported_dofs(solid, clamped="bore"))
    sub = np.ix_(free, free)
    K, M = system.K.toarray()[sub], system.consistent_mass.toarray()[sub]
    mesh, element, ours, _ = skfem_mesh(solid)
    n = system.n_dofs
    import scipy.sparse as sp

    to_ours = sp.csr_array((np.ones(n), (ours, np.arange(n))), shape=(n, n))
    basis = Basis(mesh, element)
    J = (to_ours @ asm(BilinearForm(lambda u, v, w: RHO * (-u[1] * v[0] + u[0] * v[1])), basis) @ to_ours.T)
    Mxy = (to_ours @ asm(BilinearForm(lambda u, v, w: RHO * (u[0] * v[0] + u[1] * v[1])), basis) @ to_ours.T)
    J, Mxy = J.toarray()[sub], Mxy.toarray()[sub]
    w1 = float(np.sqrt(sla.eigh(K, M, eigvals_only=True, subset_by_index=[0, 0])[0]))
    omega = 0.05 * w1
    G, B = (x.toarray()[sub] for x in solid_transport_operators(system, omega))
    turning, fixed = dense_eig(M, 2 * omega * J, K - omega**2 * Mxy), dense_eig(M, G, K - B)
    rim = solid.nodes("rim")
    where = {int(d): k for k, d in enumerate(free)}
    x, y = solid.points[rim, 0], solid.points[rim, 1]
    phi = np.arctan2(y, x)

    def wave_number(v):
        """The ``n`` of ``e^{i n phi}`` carrying most of the shape on the rim (all three components)."""
        u = [v[[where[3 * int(r) + c] for r in rim]] for c in range(3)]
        power = np.zeros(n_theta)
        for comp in (u[0] * np.cos(phi) + u[1] * np.sin(phi), -u[0] * np.sin(phi) + u[1] * np.cos(phi), u[2]):
            spectrum = np.zeros(n_theta, complex)
            for k in range(n_theta):  # the rim's nodes are at phi_j (two layers): a transform at n = k
                spectrum[k] = np.sum(comp * np.exp(-1j * (k if k <= n_theta // 2 else k - n_theta) * phi))
            power += np.abs(spectrum) ** 2
        m = int(np.argmax(power))
        return m if m <= n_theta // 2 else m - n_theta

    return shifted_mismatch(turning, fixed, wave_number, omega, w1, sign)


@pytest.mark.slow
def test_the_space_fixed_model_of_a_turning_annulus_is_the_turning_frames_shifted_by_n_omega():
    coarse, fine = np.median(_mismatch(24, 1)), np.median(_mismatch(36, 2))
    assert fine < 1e-3 and coarse > 1.5 * fine, (coarse, fine)
    wrong = np.median(_mismatch(24, 1, sign=-1.0))
    assert wrong > 10 * coarse, (wrong, coarse)


def test_a_pair_with_a_turning_solid_takes_its_gyroscopic_and_transport_terms():
    """A pad on the turning annulus with ``gyroscopic=True``: the pair's damping is the disc's ``G`` and
    its stiffness the disc's ``K - B`` on the disc's dofs (the wiring of `stickslip.fem.pair`), and
    refused for a translating partner."""
    from stickslip.errors import ParameterError
    from stickslip.fem import Load
    from stickslip.fem.pair import PairProblem, Rotation, Translation

    disc = annulus(24, 1)
    pad_mesh = box((0.02, 0.02, 0.005), (2, 2, 1), "hexahedron")
    pad_mesh.points[:, 0] += 0.115
    pad_mesh.points[:, 2] += 0.004
    pad = solid_from_meshio(pad_mesh, "pad", units="m")
    steel = Material(2e11, 0.3, RHO)
    slave, master = assemble_solid(pad, steel, loads=[Load("z1", pressure=1e6)]), assemble_solid(disc, steel)
    # the disc's top face: a face group of its own
    problem = PairProblem(slave, "z0", _with_top(disc, master), "top", Rotation(10.0), friction=0.3,
                          clamped_master=("bore",), rollers_slave={"z1": "xy"}, gyroscopic=True)
    G, B = solid_transport_operators(problem.master, 10.0)
    n = slave.n_dofs
    assert abs(problem.C[n:, n:] - G).max() == 0 and abs(problem.C[:n, :n]).max() == 0
    assert abs(problem.K[n:, n:] - (problem.master.K - B)).max() <= 1e-12 * abs(problem.master.K).max()
    with pytest.raises(ParameterError, match="gyroscopic"):
        PairProblem(slave, "z0", problem.master, "top", Translation((1.0, 0.0)), gyroscopic=True)


def _with_top(solid, system):
    """``system`` of ``solid`` with its upper face (z = its top) as the face group ``top``."""
    from dataclasses import replace

    top = float(solid.points[:, 2].max())
    faces = [f for f in _boundary_quads(solid) if np.all(np.abs(solid.points[f, 2] - top) < 1e-12)]
    return replace(system, solid=replace(solid, faces={**solid.faces, "top": np.array(faces)}))


def _boundary_quads(solid):
    """The outward quadrilateral faces of a hexahedral solid's boundary."""
    local = [[0, 3, 2, 1], [4, 5, 6, 7], [0, 1, 5, 4], [1, 2, 6, 5], [2, 3, 7, 6], [3, 0, 4, 7]]
    faces = solid.cells[:, local].reshape(-1, 4)
    key = np.sort(faces, axis=1)
    _, inverse, counts = np.unique(key, axis=0, return_inverse=True, return_counts=True)
    return faces[counts[inverse.ravel()] == 1]
