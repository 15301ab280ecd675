"""Rollers along any direction (`stickslip.fem.supports`, issue 45): a box, a prism and a pad on a block
turned as a whole, each on rollers along its turned faces' normals, against the closed forms of the
unturned ones (the turned problem is the same problem: its modes, its linear fields and its uniform
contact pressure are the closed forms', written in the turned axes)."""

import math

import numpy as np
import pytest
from scipy.spatial.transform import Rotation as Turn

from stickslip.errors import ParameterError
from stickslip.fem import Load, Material, solid_supports
from stickslip.fem.pair import PairProblem, Translation, steady_pair
from stickslip.fem.solid import assemble_solid, solid_from_meshio, solid_modes, solid_static
from stickslip.fem.supports import direction_of, supports_from

from .test_solid import STEEL, box, box_frequencies
from .test_solid_quadratic_hex import quadratic_hex

#: A turn that leaves no face of a box normal to a coordinate axis.
TURN = Turn.from_rotvec(0.7 * np.array([1.0, 2.0, 3.0]) / math.sqrt(14.0)).as_matrix()


def turned(mesh):
    mesh.points = mesh.points @ TURN.T
    return mesh


def normal(axis):
    """The turned direction of a coordinate axis, as a roller's direction."""
    return list(TURN[:, "xyz".index(axis)])


@pytest.mark.slow
def test_a_turned_box_on_rollers_along_its_faces_has_the_closed_form_modes_at_order_four():
    """The 1 x 0.83 x 0.45 m box of 27-node hexahedra turned by 0.7 rad about (1, 2, 3), on rollers on every
    face along that face's turned normal: its 8 lowest modes (consistent mass) against the box's closed form
    (`test_solid.box_frequencies`), on 4 x 3 x 2 and 8 x 6 x 4 cells. Thresholds set before the run, the
    unturned box's (`test_solid_quadratic_hex`): each mode's observed order in [3.3, 4.7], the finer within
    0.5 %."""
    lengths = (1.0, 0.83, 0.45)
    exact = box_frequencies(lengths, STEEL, 8)
    everywhere = {f"{a}{end}": normal(a) for a in "xyz" for end in "01"}
    errors = []
    for n in (1, 2):
        solid = solid_from_meshio(turned(quadratic_hex(box(lengths, (4 * n, 3 * n, 2 * n), "hexahedron"), 27)),
                                  units="m")
        held = solid_supports(solid, rollers=everywhere)
        assert held.rotation is not None
        f, _ = solid_modes(assemble_solid(solid, STEEL), held, count=8, mass="consistent")
        errors.append(np.abs(f / exact - 1.0))
    order = np.log2(errors[0] / errors[1])
    assert np.all(errors[1] < 5e-3), errors
    assert np.all((3.3 < order) & (order < 4.7)), order


ROLLERS = {"x0": "x", "y0": "y", "y1": "y", "z0": "z", "z1": "z"}


@pytest.mark.parametrize("kind", ["tetra", "hexahedron"])
def test_a_turned_prism_on_rollers_pressed_at_its_end_shortens_along_its_axis_exactly(kind):
    """The prism on rollers pressed at its end (p = 3 MPa), turned: its displacement is ``-p s / (lambda +
    2 mu)`` along its turned axis, ``s`` the distance along that axis, nothing across (a linear field:
    exact on linear cells, 1e-9)."""
    solid = solid_from_meshio(turned(box((0.5, 0.1, 0.2), (5, 2, 2), kind)), units="m")
    system = assemble_solid(solid, STEEL, loads=[Load("x1", pressure=3e6)])
    u = solid_static(system, solid_supports(solid, rollers={g: normal(a) for g, a in ROLLERS.items()}))
    lam = STEEL.young * STEEL.poisson / ((1 + STEEL.poisson) * (1 - 2 * STEEL.poisson))
    mu = STEEL.young / (2 * (1 + STEEL.poisson))
    local = u.reshape(-1, 3) @ TURN  # in the prism's own axes
    s = solid.points @ TURN[:, 0]
    shortening = -3e6 * s / (lam + 2 * mu)
    assert np.abs(local[:, 0] - shortening).max() <= 1e-9 * np.abs(shortening).max()
    assert np.abs(local[:, 1:]).max() <= 1e-9 * np.abs(shortening).max()


def test_a_turned_pad_pressed_on_a_turned_block_passes_the_uniform_pressure_exactly():
    """The contact patch test (`test_solid_pair`), the pad (hexahedra) and the block (tetrahedra) turned
    together, their rollers along the turned normals: every multiplier is p (1e-8), the normal force p L^2."""
    L, H, T, p = 0.02, 0.015, 0.008, 2e6
    lining = Material(young=5e9, poisson=0.25, density=2500.0)
    pad_mesh = box((L, L, T), (5, 3, 2), "hexahedron")
    pad_mesh.points[:, 2] += H
    pad = solid_from_meshio(turned(pad_mesh), "lining", units="m")
    base = solid_from_meshio(turned(box((L, L, H), (3, 4, 3), "tetra")), "block", units="m")
    problem = PairProblem(assemble_solid(pad, lining, loads=[Load("z1", pressure=p)]), "z0",
                          assemble_solid(base, STEEL), "z1", Translation((1.0, 0.0)),
                          rollers_slave={"x0": normal("x"), "y0": normal("y")},
                          rollers_master={"x0": normal("x"), "y0": normal("y"), "z0": normal("z")})
    steady = steady_pair(problem)
    assert steady.active.all()
    assert np.max(np.abs(steady.pressure / p - 1.0)) < 1e-8
    assert steady.normal_force == pytest.approx(p * L * L, rel=1e-10)


def test_a_node_held_along_several_directions_is_held_along_their_span():
    """Where two turned faces meet, a node is held along both directions (rank 2: it may move along their
    edge only); a third independent one clamps it; a direction repeated or reversed adds nothing."""
    a, b = np.array([0.6, 0.8, 0.0]), np.array([0.0, 0.6, 0.8])
    sup = supports_from(2, 3, [([0], [a]), ([0], [b]), ([1], [a]), ([1], [-a])])
    assert sup.held.reshape(2, 3).sum(axis=1).tolist() == [2, 1]
    R = sup.rotation.toarray()
    assert np.allclose(R.T @ R, np.eye(6)) and np.linalg.det(R[:3, :3]) > 0
    free = sup.basis.toarray()  # the free motions of node 0: along a x b only
    edge = np.cross(a, b) / np.linalg.norm(np.cross(a, b))
    assert np.allclose(np.abs(free[:3, :1].ravel() @ edge), 1.0)
    assert np.allclose(free[:3].T @ a, 0.0) and np.allclose(free[:3].T @ b, 0.0)
    clamped = supports_from(1, 3, [([0], [a, b, np.array([1.0, 0.0, 0.0])])])
    assert clamped.held.all()


@pytest.mark.parametrize("value", [[0.0, 0.0, 0.0], [1.0, 2.0], [float("nan"), 0.0, 1.0], "w", "xx", "", True,
                                   [True, 0.0, 0.0], [1e-300, 0.0, 0.0], None, {"x": 1}])
def test_a_roller_direction_that_is_none_is_refused_naming_it(value):
    with pytest.raises(ParameterError, match="rollers.flank"):
        direction_of(value, 3, "rollers.flank")


def test_a_direction_of_huge_or_tiny_numbers_is_the_same_direction():
    for scale in (1e300, 1e-140, 1.0):
        d = direction_of([scale, scale, 0.0], 3, "rollers.x0")[0]
        assert np.allclose(d, [2 ** -0.5, 2 ** -0.5, 0.0], rtol=1e-15)


def test_a_solid_with_a_direction_for_supported_dofs_is_sent_to_solid_supports():
    solid = solid_from_meshio(box((1.0, 1.0, 1.0), (1, 1, 1)), units="m")
    from stickslip.fem.solid import supported_dofs

    with pytest.raises(ParameterError, match="solid_supports"):
        supported_dofs(solid, rollers={"x0": [1.0, 1.0, 0.0]})


def _turned_about_z(mesh, angle):
    c, s = math.cos(angle), math.sin(angle)
    mesh.points = mesh.points @ np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]).T
    return mesh


@pytest.fixture(scope="module")
def slanted():
    return slanted_pair()


def slanted_pair():
    """`test_solid_run`'s pad 2 micrometres into a block sliding under it at f = 0.5, turned 0.5 rad about z
    (the sliding too): the block clamped at its bottom and on rollers on its four sides along their turned
    normals (no contact node among them)."""
    L, H, T, soft = 0.02, 0.01, 0.008, Material(1e8, 0.25, 25.0)
    pm = box((L, L, T), (4, 4, 2), "hexahedron")
    pm.points[:, 2] += H - 2e-6
    bm = box((2 * L, 2 * L, H), (7, 7, 2), "hexahedron")  # its side faces' cells reach no node under the pad
    bm.points[:, :2] -= 0.5 * L
    pad = solid_from_meshio(_turned_about_z(pm, 0.5), "pad", units="m")
    block = solid_from_meshio(_turned_about_z(bm, 0.5), "block", units="m")
    x, y = [math.cos(0.5), math.sin(0.5), 0.0], [-math.sin(0.5), math.cos(0.5), 0.0]
    return PairProblem(assemble_solid(pad, soft), "z0", assemble_solid(block, soft), "z1", Translation(tuple(x[:2])),
                       friction=0.5, clamped_slave=("z1",), clamped_master=("z0",),
                       rollers_master={"x0": x, "x1": x, "y0": y, "y1": y})


def test_steady_sliding_on_slanted_rollers_is_a_state_of_the_explicit_scheme(slanted):
    """The saddle-point steady state (its supports on the free motions ``P q``) left unperturbed in the
    explicit scheme (its supports in the nodes' frames beside the contact frames): 2000 steps keep it to
    1e-12 of its largest displacement, as on coordinate supports (`test_solid_run`)."""
    from stickslip.fem.pair_run3 import SolidPairScheme

    assert slanted.supports.rotation is not None
    scheme = SolidPairScheme(slanted)
    u_e, r_n, r_t = scheme.steady_reference()
    assert (r_n > 0).sum() == scheme.nodes == 25
    state = scheme.initial_state(u_e, np.zeros_like(u_e))
    scheme.advance(state, 2000)
    assert np.abs(state.u - u_e).max() <= 1e-12 * np.abs(u_e).max()
    turned = np.array([[math.cos(0.5), math.sin(0.5), 0.0]])
    sides = slanted.master.solid.nodes("x0")
    cartesian = slanted.steady.u[slanted.n_slave:].reshape(-1, 3)[sides]
    assert np.abs(cartesian @ turned.T).max() <= 1e-12 * np.abs(slanted.steady.u).max()  # held along the normal
    assert np.abs(cartesian).max() > 1e-3 * np.abs(slanted.steady.u).max()  # and free across it


def test_the_energy_books_close_on_slanted_rollers(slanted):
    """From a start violent enough that nodes stick, slip and separate: the books to 1e-10 of the largest
    change of energy per step (`test_solid_run`'s threshold)."""
    from stickslip.contact.energy import energy_books, trace
    from stickslip.fem.pair_run3 import SolidPairScheme
    from stickslip.fem.run import perturbed_steady_body

    scheme = SolidPairScheme(slanted, beta2=0.9)
    start = perturbed_steady_body(scheme, 30.0, 1)
    books = energy_books(trace(scheme, scheme.initial_state(start.u, start.v), 400))
    assert np.abs(books.residual).max() <= 1e-10 * np.abs(np.diff(books.energy)).max()


@pytest.mark.slow
def test_slanted_rollers_give_the_same_steady_sliding_full_and_reduced_cea_as_the_unturned_pair(slanted):
    """The slanted pair is the unturned pair (rollers along coordinate axes, the path the dense independent
    pencil of `test_solid_pair` verifies) turned: the same steady pressures (1e-9), the same full CEA
    (eigenvalues to 1e-8 of |s|) and the same reduced CEA (60 modes).

    The reduced CEA's threshold first set, 1e-6 with the default basis (``augment="modes"``), failed at
    5.4e-6: that basis drops nearly dependent static vectors at an SVD cut that falls differently in the
    two frames (138 vectors against 139), a property of the reduction, not of the supports. The bases
    of ``augment="none"`` and ``"nodes"`` depend on no such cut; they gave 2.4e-13 and 1.1e-11, and are
    held to 1e-9 (set after seeing them)."""
    from stickslip.fem.cea import complex_eigenvalues
    from stickslip.fem.reduced import modal_basis, reduced_modes

    L, H, T, soft = 0.02, 0.01, 0.008, Material(1e8, 0.25, 25.0)
    pm = box((L, L, T), (4, 4, 2), "hexahedron")
    pm.points[:, 2] += H - 2e-6
    bm = box((2 * L, 2 * L, H), (7, 7, 2), "hexahedron")
    bm.points[:, :2] -= 0.5 * L
    straight = PairProblem(assemble_solid(solid_from_meshio(pm, "pad", units="m"), soft), "z0",
                           assemble_solid(solid_from_meshio(bm, "block", units="m"), soft), "z1",
                           Translation((1.0, 0.0)), friction=0.5, clamped_slave=("z1",), clamped_master=("z0",),
                           rollers_master={"x0": "x", "x1": "x", "y0": "y", "y1": "y"})
    assert straight.supports.rotation is None
    p1, p2 = straight.steady.pressure, slanted.steady.pressure
    assert np.abs(p1 - p2).max() <= 1e-9 * np.abs(p1).max()
    band = (3.4e4, 4.2e4)  # the lowest modes (35.5 kHz up)
    by_frequency = lambda s: s[np.argsort(s.imag)]  # noqa: E731 (the growth rates are ~0: sorting by them is noise)
    s1 = by_frequency(complex_eigenvalues(straight, band, count=20).s)
    s2 = by_frequency(complex_eigenvalues(slanted, band, count=20).s)
    assert len(s1) >= 4 and len(s1) == len(s2) and np.abs(s1 - s2).max() <= 1e-8 * np.abs(s1).max()
    for augment in ("none", "nodes"):
        r1 = reduced_modes(modal_basis(straight, 60, augment=augment), band=band)
        r2 = reduced_modes(modal_basis(slanted, 60, augment=augment), band=band)
        a, b = by_frequency(r1.s), by_frequency(r2.s)
        assert len(a) >= 4 and len(a) == len(b) and np.abs(a - b).max() <= 1e-9 * np.abs(a).max(), augment


def test_two_plane_bodies_turned_in_their_plane_on_slanted_rollers_pass_the_uniform_pressure(tmp_path):
    """2-D: `test_pair`'s stack (triangles on quadrilaterals, not matching) turned 0.4 rad in its plane, the
    upper body on rollers on its left side, the lower on its left side and its bottom, each along the turned
    normal (two numbers): every multiplier is p (1e-9), the normal force p times the width."""
    from stickslip.fem import assemble, body_from_meshio

    from .meshes import rectangle

    c, s = math.cos(0.4), math.sin(0.4)
    turn = np.array([[c, -s], [s, c]])
    bodies = []
    for name, lift, size, quads in (("upper.msh", 0.01, 0.004, False), ("lower.msh", 0.0, 0.0027, True)):
        mesh = rectangle(tmp_path / name, width=0.04, height=0.01, size=size, quads=quads)
        mesh.points[:, 1] += lift
        mesh.points[:, :2] = mesh.points[:, :2] @ turn.T
        bodies.append(body_from_meshio(mesh, name))
    p, x, y = 2e6, [c, s], [-s, c]
    slave = assemble(bodies[0], Material(1e9, 0.3, 1000.0), loads=[Load("top", p)])
    master = assemble(bodies[1], Material(5e9, 0.25, 2000.0))
    problem = PairProblem(slave, "bottom", master, "top", Translation((c, s)), 0.0, rollers_slave={"left": x},
                          rollers_master={"left": x, "bottom": y})
    st = steady_pair(problem)
    assert problem.supports.rotation is not None and st.active.all()
    assert np.abs(st.pressure - p).max() < 1e-9 * p
    assert st.normal_force == pytest.approx(p * 0.04, rel=1e-10)


def _patch_pair(angle):
    """`test_solid_pair`'s patch-test pair (hexahedra on tetrahedra) turned ``angle`` about z, sliding along
    its turned x at f = 0.3, on rollers along its turned faces: through its contact face's edges too."""
    c, s = math.cos(angle), math.sin(angle)
    turn = np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]])
    L, H, T = 0.02, 0.015, 0.008
    pm = box((L, L, T), (5, 3, 2), "hexahedron")
    pm.points[:, 2] += H
    pm.points = pm.points @ turn.T
    bm = box((L, L, H), (3, 4, 3), "tetra")
    bm.points = bm.points @ turn.T
    x, y = (list(turn[:, 0]), list(turn[:, 1])) if angle else ("x", "y")
    return PairProblem(assemble_solid(solid_from_meshio(pm, "pad", units="m"), Material(5e9, 0.25, 2500.0),
                                      loads=[Load("z1", pressure=2e6)]), "z0",
                       assemble_solid(solid_from_meshio(bm, "block", units="m"), STEEL), "z1", Translation((c, s)),
                       friction=0.3, rollers_slave={"x0": x, "y0": y}, rollers_master={"x0": x, "y0": y, "z0": "z"})


def test_slanted_rollers_through_the_contact_face_give_the_unturned_pairs_ceas():
    """Rollers through the contact face's edges put contact nodes in frames of their own (the explicit
    runs refuse them; steady sliding and the CEAs take them): the pair turned 0.5 rad about z has the
    unturned pair's steady pressures (1e-9), full CEA below 30 kHz (1e-8 of |s|) and reduced CEA (30 modes,
    bases without an SVD cut, 1e-9)."""
    from stickslip.fem.cea import complex_eigenvalues
    from stickslip.fem.reduced import modal_basis, reduced_modes

    straight, slanted = _patch_pair(0.0), _patch_pair(0.5)
    c = slanted.coupling
    held = slanted.fixed[3 * c.slave_nodes[:, None] + np.arange(3)]
    assert held.any(axis=1).sum() >= 4 and slanted.supports.rotation is not None
    p1, p2 = straight.steady.pressure, slanted.steady.pressure
    assert np.abs(p1 - p2).max() <= 1e-9 * np.abs(p1).max()
    by_frequency = lambda s: s[np.argsort(s.imag)]  # noqa: E731
    s1 = by_frequency(complex_eigenvalues(straight, (0.0, 3e4), count=10).s)
    s2 = by_frequency(complex_eigenvalues(slanted, (0.0, 3e4), count=10).s)
    assert len(s1) >= 4 and len(s1) == len(s2) and np.abs(s1 - s2).max() <= 1e-8 * np.abs(s1).max()
    for augment in ("none", "nodes"):
        a = by_frequency(reduced_modes(modal_basis(straight, 30, augment=augment), band=(0.0, 2e4)).s)
        b = by_frequency(reduced_modes(modal_basis(slanted, 30, augment=augment), band=(0.0, 2e4)).s)
        assert len(a) >= 3 and len(a) == len(b) and np.abs(a - b).max() <= 1e-9 * np.abs(a).max(), augment
