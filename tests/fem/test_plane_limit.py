"""The plane-strain limit of the 3-D pair (issue 45): a slab of a 2-D pad on a 2-D block, one layer of
hexahedra thick, held along z on both faces (symmetry planes), has the 2-D pair's CEA.

Why exactly and not only within the discretisation error: with u_z = 0 at every node, a mode in which
both faces move alike has the strains of the bilinear quadrilaterals in plane strain (times the
thickness), the same lumped masses, and, the dual functions of a rectangular face being the products
of the 1-D ones along x and z, contact rows that are the 2-D mortar's times half the thickness, twice.
Threshold, set before the run: every 2-D eigenvalue in 0-120 kHz among the 3-D ones to 1e-9 of |s|;
the 3-D modes without a 2-D one are those whose faces move oppositely (a shear through the thickness).
"""

import meshio
import numpy as np

from stickslip.fem import Material, assemble, body_from_meshio
from stickslip.fem.cea import complex_eigenvalues
from stickslip.fem.pair import PairProblem, Translation
from stickslip.fem.solid import assemble_solid, solid_from_meshio

L, H, T, SLAB = 0.02, 0.015, 0.008, 0.001
LINING = Material(young=5e9, poisson=0.25, density=2500.0)
STEEL = Material(young=2.1e11, poisson=0.3, density=7850.0)


def _sets(blocks: int, names: list, sizes: list) -> dict:
    """meshio cell_sets: group k the whole block k + 1 (block 0 the cells)."""
    return {name: [np.array([], int)] * (1 + k) + [np.arange(n)] + [np.array([], int)] * (len(names) - 1 - k)
            for k, (name, n) in enumerate(zip(names, sizes))}


def grid(x0, y0, width, height, nx, ny) -> meshio.Mesh:
    """A rectangle of nx x ny quadrilaterals with the boundary groups ``bottom`` and ``top``."""
    xs, ys = np.linspace(x0, x0 + width, nx + 1), np.linspace(y0, y0 + height, ny + 1)
    points = np.array([[x, y] for y in ys for x in xs])
    node = lambda i, j: j * (nx + 1) + i  # noqa: E731
    quads = np.array([[node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)]
                      for j in range(ny) for i in range(nx)])
    lines = {"bottom": np.array([[node(i, 0), node(i + 1, 0)] for i in range(nx)]),
             "top": np.array([[node(i + 1, ny), node(i, ny)] for i in range(nx)])}
    return meshio.Mesh(points, [("quad", quads)] + [("line", v) for v in lines.values()],
                       cell_sets=_sets(3, list(lines), [len(v) for v in lines.values()]))


def extrude(mesh: meshio.Mesh, thickness: float) -> meshio.Mesh:
    """One layer of hexahedra over ``mesh``: its groups as faces, and ``front`` (z = 0), ``back``."""
    n = len(mesh.points)
    points = np.vstack([np.column_stack([mesh.points, np.zeros(n)]), np.column_stack([mesh.points, np.full(n, thickness)])])
    quads = mesh.cells[0].data
    faces = {name: np.column_stack([mesh.cells[1 + k].data, mesh.cells[1 + k].data[:, ::-1] + n])
             for k, name in enumerate(["bottom", "top"])}
    faces["front"], faces["back"] = quads[:, ::-1], quads + n
    return meshio.Mesh(points, [("hexahedron", np.hstack([quads, quads + n]))] + [("quad", f) for f in faces.values()],
                       cell_sets=_sets(len(faces) + 1, list(faces), [len(f) for f in faces.values()]))


def test_a_slab_on_symmetry_planes_has_the_plane_strain_pairs_complex_modes():
    pad, block = grid(0.0, H - 2e-7, L, T, 5, 2), grid(0.0, 0.0, L, H, 4, 3)  # non-matching, pressed 0.2 um
    plane = PairProblem(assemble(body_from_meshio(pad), LINING), "bottom", assemble(body_from_meshio(block), STEEL),
                        "top", Translation((1.0, 0.0)), friction=0.6, clamped_slave=("top",), clamped_master=("bottom",))
    held = {"front": "z", "back": "z"}
    slab = PairProblem(assemble_solid(solid_from_meshio(extrude(pad, SLAB), "pad", units="m"), LINING), "bottom",
                       assemble_solid(solid_from_meshio(extrude(block, SLAB), "block", units="m"), STEEL), "top",
                       Translation((1.0, 0.0)), friction=0.6, clamped_slave=("top",), clamped_master=("bottom",),
                       rollers_slave=held, rollers_master=held)
    band = (0.0, 120e3)
    two = complex_eigenvalues(plane, band, count=20)
    three = complex_eigenvalues(slab, band, count=20, mode_shapes=True)
    assert len(two.s) > 15 and two.unstable.sum() >= 2
    matched = set()
    for z in two.s:
        k = int(np.argmin(np.abs(three.s - z)))
        assert abs(three.s[k] - z) < 1e-9 * abs(z)
        matched.add(k)
    free = np.flatnonzero(~slab.fixed)
    layer = len(pad.points)
    for k in set(range(len(three.s))) - matched:  # faces moving oppositely: u(z = 0) = -u(z = SLAB)
        u = np.zeros(slab.slave.n_dofs + slab.master.n_dofs, complex)
        u[free] = three.shapes[:free.size, k]
        pad_u = u[:slab.slave.n_dofs].reshape(-1, 3)
        assert np.allclose(pad_u[:layer], -pad_u[layer:], atol=1e-9 * np.abs(pad_u).max())
