"""Two solids in frictional contact (issue 45): the 3-D mortar (`stickslip.fem.mortar3`) through
`stickslip.fem.pair`, against exact solutions and an independently assembled pencil.

* The contact patch test: a lining on a steel block, their interface meshes not matching (5 x 3
  against 3 x 4 cells; tetrahedra, hexahedra, quadratic tetrahedra and hexahedra of 20 and 27 nodes on
  either side), on rollers and
  pressed by a uniform pressure p: the exact state is uniform, sigma_zz = -p in both, so every
  multiplier is p. Threshold, set before the run: 1e-8 relative (round-off of the solves).
* The CEA of a pad on a block (matching interface, linear tetrahedra) against a dense solve of
  the pencil assembled here without scikit-fem or the mortar: constant-strain tetrahedra written
  out, lumped masses rho V / 4, node-to-node contact with each node's share of the interface's area,
  the friction along x. Threshold, set before the run: eigenvalues equal to 1e-7 of |s|.
"""

import math

import numpy as np
import pytest
import scipy.linalg as la

from stickslip.errors import ParameterError
from stickslip.fem import Load, Material, assemble, body_from_meshio
from stickslip.fem.cea import complex_eigenvalues
from stickslip.fem.pair import PairProblem, Translation, steady_pair
from stickslip.fem.solid import assemble_solid, solid_from_meshio

from .meshes import rectangle
from .test_solid import tet_stiffness, box, quadratic
from .test_solid_quadratic_hex import quadratic_hex

STEEL = Material(young=2.1e11, poisson=0.3, density=7850.0)
LINING = Material(young=5e9, poisson=0.25, density=2500.0)
L, H, T = 0.02, 0.015, 0.008  # the footprint's side, the block's and the lining's thickness [m]


def solid_mesh(cells, kind, height, lift=0.0):
    mesh = box((L, L, height), cells, "tetra" if kind == "tetra10" else kind[:10])
    mesh = quadratic(mesh) if kind == "tetra10" else mesh
    mesh = quadratic_hex(mesh, int(kind[10:])) if kind[10:] else mesh
    mesh.points[:, 2] += lift
    return mesh


@pytest.mark.parametrize("lining, block", [("tetra", "tetra"), ("hexahedron", "tetra"), ("tetra10", "tetra"),
                                           ("tetra", "tetra10"), ("tetra10", "hexahedron"),
                                           ("hexahedron20", "tetra"), ("hexahedron27", "hexahedron20"),
                                           ("tetra10", "hexahedron27")])
def test_a_uniform_pressure_passes_a_non_matching_3d_interface_exactly(lining, block):
    p = 2e6
    pad = solid_from_meshio(solid_mesh((5, 3, 2), lining, T, lift=H), "lining", units="m")
    base = solid_from_meshio(solid_mesh((3, 4, 3), block, H), "block", units="m")
    problem = PairProblem(assemble_solid(pad, LINING, loads=[Load("z1", pressure=p)]), "z0",
                          assemble_solid(base, STEEL), "z1", Translation((1.0, 0.0)),
                          rollers_slave={"x0": "x", "y0": "y"}, rollers_master={"x0": "x", "y0": "y", "z0": "z"})
    steady = steady_pair(problem)
    assert steady.active.all()
    assert np.max(np.abs(steady.pressure / p - 1.0)) < 1e-8
    assert steady.normal_force == pytest.approx(p * L * L, rel=1e-12)
    # free to expand sideways, each body shortens by p / E (the block's bottom held along z)
    block_top = -steady.u[3 * len(pad.points) + 3 * base.nodes("z1") + 2]
    pad_top = -steady.u[3 * pad.nodes("z1") + 2]
    assert np.allclose(block_top, p * H / STEEL.young, rtol=1e-8)
    assert np.allclose(pad_top - block_top.mean(), p * T / LINING.young, rtol=1e-8)


def independent_pencil(pad, base, friction, interference):
    """``(K_r, M_r)``: the pencil of the pad (top clamped) on the block (bottom clamped), matching interface,
    assembled here: constant-strain tetrahedra, masses rho V / 4, node-to-node contact rows
    ``a_j n . (u_pad - u_block)`` (n = +z, a_j the node's share of the interface's area) and the
    friction ``f lambda_j`` on the pad along +x (the block moves along +x), on the block along -x."""
    parts = [(pad, LINING, 0), (base, STEEL, 3 * len(pad.points))]
    n = sum(3 * len(s.points) for s, _, _ in parts)
    K, mass = np.zeros((n, n)), np.zeros(n)
    for solid, m, off in parts:
        for cell in solid.cells:
            dofs = off + (3 * cell[:, None] + np.arange(3)).ravel()
            K[np.ix_(dofs, dofs)] += tet_stiffness(solid.points[cell], m)
            volume = abs(np.linalg.det(np.column_stack([np.ones(4), solid.points[cell]]))) / 6.0
            mass[dofs] += m.density * volume / 4.0
    held = np.zeros(n, bool)
    held[(3 * pad.nodes("z1")[:, None] + np.arange(3)).ravel()] = True
    held[3 * len(pad.points) + (3 * base.nodes("z0")[:, None] + np.arange(3)).ravel()] = True
    bottom = pad.nodes("z0")
    area = np.zeros(len(pad.points))
    for tri in pad.faces["z0"]:
        a = 0.5 * np.linalg.norm(np.cross(*(pad.points[tri[1:]] - pad.points[tri[0]])))
        area[tri] += a / 3.0
    rows_g, rows_b = np.zeros((len(bottom), n)), np.zeros((len(bottom), n))
    for j, node in enumerate(bottom):
        xy = pad.points[node, :2]
        partner = int(np.argmin(np.linalg.norm(base.points[:, :2] - xy, axis=1) + np.abs(base.points[:, 2] - H)))
        assert np.allclose(base.points[partner], [*xy, H])
        for sign, dof in ((1.0, 3 * node), (-1.0, 3 * len(pad.points) + 3 * partner)):
            rows_g[j, dof + 2] = sign * area[node]
            rows_b[j, dof + 2] = sign * area[node]
            rows_b[j, dof] = sign * friction * area[node]
    free = ~held
    # M u'' + K u = B^T lambda, G u = 0: u = Z q (Z spanning G's null space), and Y^T B^T = 0 (Y spanning B's)
    Z, Y = la.null_space(rows_g[:, free]), la.null_space(rows_b[:, free])
    return Y.T @ K[free][:, free] @ Z, Y.T @ (mass[free][:, None] * Z), (Z, K, mass, free)


def test_the_3d_cea_of_a_pad_on_a_block_is_the_dense_solve_of_an_independently_assembled_pencil():
    friction, interference = 0.6, 2e-7
    pad = solid_from_meshio(solid_mesh((2, 2, 1), "tetra", T, lift=H - interference), "pad", units="m")
    base = solid_from_meshio(solid_mesh((2, 2, 2), "tetra", H), "block", units="m")
    problem = PairProblem(assemble_solid(pad, LINING), "z0", assemble_solid(base, STEEL), "z1",
                          Translation((1.0, 0.0)), friction=friction, clamped_slave=("z1",), clamped_master=("z0",))
    assert problem.steady.active.all()
    band = (0.0, 60e3)
    modes = complex_eigenvalues(problem, band, count=20)
    Kr, Mr, (Z, K, mass, free) = independent_pencil(pad, base, friction, interference)
    mu, q = la.eig(Kr, Mr)
    s = np.sqrt(-mu.astype(complex))  # K_r q = -s^2 M_r q
    s = np.where(s.imag < 0, -s, s)
    inside = (s.imag / (2 * math.pi) >= band[0]) & (s.imag / (2 * math.pi) <= band[1])
    s, q = s[inside], q[:, inside]
    assert len(s) == len(modes.s) > 5
    for value in modes.s:
        assert np.min(np.abs(s - value)) < 1e-7 * abs(value)
    assert np.any(modes.unstable)  # friction 0.6 couples two of the pad's modes: flutter
    # each mode's energy in the pad, from the independent pencil's eigenvectors, the masses and K written here
    from stickslip.fem.shares import energy_shares

    modes = complex_eigenvalues(problem, band, count=20, mode_shapes=True)
    shares = energy_shares(problem, modes)
    pad_dofs = 3 * len(pad.points)
    for k, value in enumerate(modes.s):
        j = int(np.argmin(np.abs(s - value)))
        if np.sort(np.abs(s - value))[1] < 1e-6 * abs(value):
            continue  # a repeated eigenvalue: its shapes are not unique
        u = np.zeros(len(mass), complex)
        u[free] = Z @ q[:, j]
        kinetic = mass * np.abs(u) ** 2
        strain = [np.vdot(u[part], K[part][:, part] @ u[part]).real for part in (slice(0, pad_dofs),
                                                                                  slice(pad_dofs, None))]
        assert shares.kinetic_share.sel(part="slave").values[k] == pytest.approx(kinetic[:pad_dofs].sum() /
                                                                                  kinetic.sum(), abs=1e-6)
        assert shares.strain_share.sel(part="slave").values[k] == pytest.approx(strain[0] / sum(strain), abs=1e-6)


def test_a_solid_with_a_plane_body_and_surfaces_that_face_away_are_refused(tmp_path):
    pad = assemble_solid(solid_from_meshio(solid_mesh((2, 2, 1), "tetra", T, lift=H), "pad", units="m"), LINING)
    base = assemble_solid(solid_from_meshio(solid_mesh((2, 2, 2), "tetra", H), "block", units="m"), STEEL)
    plane = assemble(body_from_meshio(rectangle(tmp_path / "plane.msh")), STEEL)
    with pytest.raises(ParameterError, match="slave's dimension"):
        PairProblem(pad, "z0", plane, "top", Translation((1.0, 0.0)))
    with pytest.raises(ParameterError, match="faces the slave group"):
        PairProblem(pad, "z0", base, "z0", Translation((1.0, 0.0)))  # the block's bottom faces away from the pad
    with pytest.raises(ParameterError, match=r"rollers_slave\[x0\].*x or y or z, or several"):
        PairProblem(pad, "z0", base, "z1", Translation((1.0, 0.0)), rollers_slave={"x0": "w"})


def test_a_pad_pressed_deep_into_the_block_or_held_far_from_it_or_overlapping_it_by_a_strain_is_refused_saying_which():
    base = assemble_solid(solid_from_meshio(solid_mesh((2, 2, 2), "tetra", H), "block", units="m"), STEEL)
    for lift, said in ((H - 0.004, "does not interpenetrate"), (H + 0.004, "farther than"),
                       (H - 0.0003, r"overlap by 0\.0003 m, a strain of 0\.0375")):  # 0.3 mm into 8 mm
        pad = assemble_solid(solid_from_meshio(solid_mesh((2, 2, 1), "tetra", T, lift=lift), "pad", units="m"), LINING)
        with pytest.raises(ParameterError, match=said):
            PairProblem(pad, "z0", base, "z1", Translation((1.0, 0.0)))


def test_on_a_side_face_the_sliding_is_the_master_velocity_less_its_normal_part():
    """A pad against the block's face x = L, the block moving at (1, 1, 0) m/s: the slip is along y at
    1 m/s (the normal part of the velocity, along x, does not slide)."""
    base = assemble_solid(solid_from_meshio(solid_mesh((2, 2, 2), "tetra", H), "block", units="m"), STEEL)
    side = solid_mesh((2, 2, 1), "tetra", T)
    side.points[:, 0] += L
    pad = assemble_solid(solid_from_meshio(side, "pad", units="m"), LINING)
    problem = PairProblem(pad, "x0", base, "x1", Translation((1.0, 1.0)), friction=0.3)
    t, speed = problem.tangent
    assert np.allclose(problem.coupling.normal, [1.0, 0.0, 0.0])
    assert np.allclose(t, [0.0, 1.0, 0.0]) and np.allclose(speed, 1.0)


def _halves(mesh):
    """``mesh`` (hexahedra) with the cell groups ``left`` (x < its middle) and ``right``."""
    hexes = mesh.cells[0].data
    x = mesh.points[hexes].mean(axis=1)[:, 0]
    middle = 0.5 * (mesh.points[:, 0].min() + mesh.points[:, 0].max())
    for name, cells in (("left", np.flatnonzero(x < middle)), ("right", np.flatnonzero(x > middle))):
        mesh.cell_sets[name] = [cells] + [np.array([], dtype=int)] * (len(mesh.cells) - 1)
    del mesh.cell_sets["all"]
    return mesh


def test_a_pair_symmetric_about_its_interface_and_its_middle_puts_a_quarter_of_each_modes_energy_in_each_part():
    """Two equal steel blocks of hexahedra, one on the other (mirror images about the interface), each
    clamped at its far face, each of two halves along x (cell groups): every mode is symmetric or
    antisymmetric about both planes (the footprint 20 x 14 mm, so that no two modes of the other
    symmetries share a frequency), so each quarter holds a quarter of its kinetic and strain energy."""
    from stickslip.fem.shares import energy_shares

    size, cells = (0.02, 0.014, 0.01), (4, 2, 2)
    low = _halves(box(size, cells, "hexahedron"))
    high = _halves(box(size, cells, "hexahedron"))
    high.points[:, 2] = 0.02 - high.points[:, 2] - 1e-8  # mirrored, pressed 10 nm into the lower block
    high.cells[0].data[:] = high.cells[0].data[:, [4, 5, 6, 7, 0, 1, 2, 3]]
    halves = {"left": STEEL, "right": STEEL}
    a = assemble_solid(solid_from_meshio(high, "upper", units="m"), halves)
    b = assemble_solid(solid_from_meshio(low, "lower", units="m"), halves)
    # mirrored, the upper block's group z1 is its lower face, z0 its upper one
    problem = PairProblem(a, "z1", b, "z1", Translation((1.0, 0.0)), clamped_slave=("z0",), clamped_master=("z0",))
    modes = complex_eigenvalues(problem, (0.0, 150e3), count=20, mode_shapes=True)
    shares = energy_shares(problem, modes)
    assert len(modes.s) >= 8 and sorted(shares.part.values) == ["master:left", "master:right", "slave:left",
                                                                "slave:right"]
    assert np.allclose(shares.kinetic_share, 0.25, atol=1e-6)
    assert np.allclose(shares.strain_share, 0.25, atol=1e-6)


def test_the_modes_of_a_pair_of_solids_go_to_paraview_and_to_a_universal_file_as_computed(tmp_path):
    """Read back by meshio's XDMF reader and by pyuff (dataset 2411, then a 55 per mode): the
    eigenvalue and the complex shape at each node, to the file format's six digits."""
    import meshio
    import pyuff

    from stickslip.fem.paraview import write_modes_xdmf
    from stickslip.fem.uff import write_modes_uff

    pad = solid_from_meshio(solid_mesh((2, 2, 1), "tetra", T, lift=H - 2e-7), "pad", units="m")
    base = solid_from_meshio(solid_mesh((2, 2, 2), "tetra", H), "block", units="m")
    problem = PairProblem(assemble_solid(pad, LINING), "z0", assemble_solid(base, STEEL), "z1",
                          Translation((1.0, 0.0)), friction=0.6, clamped_slave=("z1",), clamped_master=("z0",))
    modes = complex_eigenvalues(problem, (0.0, 60e3), count=20, mode_shapes=True)
    free = np.flatnonzero(~problem.fixed)
    n = len(pad.points) + len(base.points)
    first = np.zeros(3 * n, complex)
    first[free] = modes.shapes[:free.size, 0]
    first = (first / np.abs(first).max()).reshape(-1, 3)
    sets = pyuff.UFF(str(write_modes_uff(problem, modes, tmp_path / "modes.uff"))).read_sets()
    assert [d["type"] for d in sets] == [2411] + [55] * len(modes.s)
    assert np.allclose(sets[0]["z"], np.concatenate([pad.points[:, 2], base.points[:, 2]]), rtol=1e-5)
    assert abs(sets[1]["eig"] - modes.s[0]) < 1e-5 * abs(modes.s[0])
    got = np.column_stack([sets[1]["r1"], sets[1]["r2"], sets[1]["r3"]])
    assert np.allclose(got, first, atol=1e-5)
    with meshio.xdmf.TimeSeriesReader(write_modes_xdmf(problem, modes, tmp_path / "modes.xdmf")) as reader:
        points, cells = reader.read_points_cells()
        _, data, _ = reader.read_data(0)
    assert points.shape == (n, 3) and cells[0].type == "tetra"
    assert np.allclose(data["mode_real"] + 1j * data["mode_imag"], first, atol=1e-12)


@pytest.mark.slow
def test_a_stiffening_block_tends_to_a_rigid_counter_surface_in_proportion_to_its_compliance():
    """The pad on a block whose Young's modulus grows (1e12, 1e13 Pa) against the block held rigid (every
    face clamped: the pad then slides on a rigid surface): each of the rigid limit's modes (friction 0.6,
    one of them flutter) is at a distance falling as the block's compliance, 1 / E. Thresholds, set before
    the run: the distance's ratio over the last decade in [8, 13] for every mode, and within 1e-4 of |s|
    at 1e13 Pa."""
    pad = solid_from_meshio(solid_mesh((2, 2, 1), "tetra", T, lift=H - 2e-7), "pad", units="m")
    base = solid_from_meshio(solid_mesh((2, 2, 1), "tetra", H), "block", units="m")  # no node inside it

    def modes(young, rigid=False):
        held = ("x0", "x1", "y0", "y1", "z0", "z1") if rigid else ("z0",)
        problem = PairProblem(assemble_solid(pad, LINING), "z0", assemble_solid(base, Material(young, 0.3, 7850.0)),
                              "z1", Translation((1.0, 0.0)), friction=0.6, clamped_slave=("z1",),
                              clamped_master=held)
        return complex_eigenvalues(problem, (0.0, 60e3), count=20).s

    rigid = modes(1e12, rigid=True)
    assert np.any(rigid.real > 1e-3 * np.abs(rigid))  # the rigid limit flutters
    near = [np.array([np.min(np.abs(modes(young) - s)) for s in rigid]) / np.abs(rigid) for young in (1e12, 1e13)]
    assert np.all((8.0 < near[0] / near[1]) & (near[0] / near[1] < 13.0)), near[0] / near[1]
    assert np.all(near[1] < 1e-4), near[1]
