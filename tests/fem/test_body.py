"""A body from a mesh: groups, orientation, and every bad mesh refused in one line naming it."""

import meshio
import numpy as np
import pytest

from stickslip.errors import ParameterError
from stickslip.fem import body_from_meshio, read_body

from .meshes import rectangle


@pytest.fixture(scope="module")
def rect(tmp_path_factory):
    path = tmp_path_factory.mktemp("mesh") / "rect.msh"
    rectangle(path)
    return path


@pytest.mark.parametrize("quads", [False, True], ids=["triangles", "quads"])
def test_a_gmsh_rectangle_is_read_with_its_groups(quads, tmp_path):
    path = tmp_path / "r.msh"
    rectangle(path, quads=quads)
    body = read_body(path)
    assert body.kind == ("quad" if quads else "triangle")
    assert np.sum(body.areas) == pytest.approx(0.04 * 0.01, rel=1e-12) and np.all(body.areas > 0)
    assert set(body.groups) == {"bottom", "top", "left", "right"}
    assert np.allclose(body.points[body.nodes("bottom"), 1], 0.0) and np.allclose(body.points[body.nodes("top"), 1], 0.01)
    assert body.points[body.nodes("bottom"), 0].min() == 0.0 and body.points[body.nodes("bottom"), 0].max() == 0.04


def test_a_clockwise_mesh_is_turned_round(rect):
    m = meshio.read(rect)
    cells = [meshio.CellBlock(c.type, c.data[:, ::-1] if c.type == "triangle" else c.data) for c in m.cells]
    body = body_from_meshio(meshio.Mesh(m.points, cells, cell_sets=m.cell_sets))
    assert np.all(body.areas > 0)


def _refused(mesh, words):
    with pytest.raises(ParameterError) as err:
        body_from_meshio(mesh, "bad.msh")
    assert err.value.name == "mesh" and words in str(err.value) and "\n" not in str(err.value)


def test_bad_meshes_are_refused_naming_the_problem(rect):
    m = meshio.read(rect)
    tri = [c for c in m.cells if c.type == "triangle"][0].data
    lines = [c for c in m.cells if c.type == "line"]
    points3d = m.points.copy()
    points3d[:, 2] = np.linspace(0, 1, len(points3d))
    _refused(meshio.Mesh(points3d, m.cells), "3-D")
    _refused(meshio.Mesh(m.points, lines), "has none")
    _refused(meshio.Mesh(m.points, [meshio.CellBlock("triangle", tri), meshio.CellBlock("quad", [[0, 1, 2, 3]])]),
             "quad, triangle")
    _refused(meshio.Mesh(m.points, [meshio.CellBlock("quad8", np.zeros((1, 8), int))]), "quad8")  # serendipity: not taken
    inverted = tri.copy()
    inverted[3] = inverted[3, ::-1]
    _refused(meshio.Mesh(m.points, [meshio.CellBlock("triangle", inverted)]), "1 of 68 turn the other way")
    flat = np.vstack([tri, [[0, 0, 1]]])
    _refused(meshio.Mesh(m.points, [meshio.CellBlock("triangle", flat)]), "degenerate")
    inner = tri[:1, :2]  # an edge of a cell, inside the body
    others = [c for c in np.sort(np.vstack([tri[:, :2], tri[:, 1:], tri[:, ::2]]), axis=1).tolist()]
    shared = [e for e in others if others.count(e) == 2][:1]
    mesh = meshio.Mesh(m.points, [meshio.CellBlock("triangle", tri), meshio.CellBlock("line", np.array(shared))],
                       cell_sets={"seal": [np.array([], int), np.array([0])]})
    assert inner.shape == (1, 2)
    _refused(mesh, "inside the body")


def test_an_unknown_group_names_the_option_and_the_groups_there_are(rect):
    body = read_body(rect)
    with pytest.raises(ParameterError) as err:
        body.nodes("contact", option="contact_group")
    assert err.value.name == "contact_group" and "bottom, left, right, top" in str(err.value)


def test_a_missing_or_unreadable_file_is_refused(tmp_path):
    with pytest.raises(ParameterError, match="an existing mesh file"):
        read_body(tmp_path / "none.msh")
    bad = tmp_path / "bad.msh"
    bad.write_text("not a mesh")
    with pytest.raises(ParameterError, match="a mesh file meshio reads"):
        read_body(bad)


@pytest.mark.parametrize("quads", [False, True], ids=["triangle6", "quad9"])
def test_a_quadratic_mesh_is_read_turned_round_and_its_bad_middle_nodes_refused(quads, tmp_path):
    from stickslip.fem import Material, assemble

    path = tmp_path / "q.msh"
    m = rectangle(path, quads=quads, order=2)
    kind = "quad9" if quads else "triangle6"
    body = read_body(path)
    assert body.kind == kind and body.order == 2 and body.group("bottom").shape[1] == 3
    assert np.sum(body.areas) == pytest.approx(0.04 * 0.01, rel=1e-12) and np.all(body.areas > 0)
    mid = body.group("bottom")[:, 2]
    ends = body.points[body.group("bottom")[:, :2]].mean(axis=1)
    assert np.allclose(body.points[mid], ends)  # gmsh puts them in the middle of straight edges
    seg = body.segments("bottom")
    assert len(seg) == 2 * len(mid) and set(np.unique(seg)) == set(body.nodes("bottom"))
    turn = [3, 2, 1, 0, 6, 5, 4, 7, 8] if quads else [2, 1, 0, 4, 3, 5]
    cells = [meshio.CellBlock(c.type, c.data[:, turn] if c.type == kind else c.data) for c in m.cells]
    turned = body_from_meshio(meshio.Mesh(m.points, cells, cell_sets=m.cell_sets))
    assert np.all(turned.areas > 0)
    s1, s2 = assemble(body, Material(1e9, 0.3, 1e3)), assemble(turned, Material(1e9, 0.3, 1e3))
    assert np.allclose(s1.mass, s2.mass, rtol=1e-12) and abs(s1.K - s2.K).max() < 1e-9 * abs(s1.K).max()
    # a middle node pushed across its cell turns the cell over inside: refused when assembled
    points = m.points.copy()
    c = [b for b in m.cells if b.type == kind][0].data[0]
    k = 4 if quads else 3  # the middle node of the edge from corner 0 to corner 1
    centre = points[c[:k]].mean(axis=0)
    points[c[k]] = centre + 1.5 * (centre - points[c[k]])  # across the cell, beyond its far side
    bad = body_from_meshio(meshio.Mesh(points, m.cells, cell_sets=m.cell_sets), "bad.msh")
    with pytest.raises(ParameterError, match="turn over inside.*cell 0") as err:
        assemble(bad, Material(1e9, 0.3, 1e3))
    assert err.value.name == "mesh"
    # a mapping with a zero Jacobian at a corner (a grading whose slope vanishes at x = y = 0)
    graded = m.points.copy()
    graded[:, 0], graded[:, 1] = 0.04 * (m.points[:, 0] / 0.04) ** 1.5, 0.01 * (m.points[:, 1] / 0.01) ** 2
    with pytest.raises(ParameterError, match="turn over inside"):
        assemble(body_from_meshio(meshio.Mesh(graded, m.cells, cell_sets=m.cell_sets), "bad.msh"), Material(1e9, 0.3, 1e3))
    # boundary groups of 2-node lines on quadratic cells, or with another middle node
    lines = [meshio.CellBlock("line" if b.type == "line3" else b.type, b.data[:, :2] if b.type == "line3" else b.data)
             for b in m.cells]
    _refused(meshio.Mesh(m.points, lines, cell_sets=m.cell_sets), "3-node lines (line3)")
    wrong = [meshio.CellBlock(b.type, b.data[:, [0, 1, 0]] if b.type == "line3" else b.data) for b in m.cells]
    _refused(meshio.Mesh(m.points, wrong, cell_sets=m.cell_sets), "with the middle nodes of its cells' edges")


def _two_squares(joined: bool):
    """A lining (left) and a backplate (right) of one quad each, side by side; their common side
    one pair of nodes (joined) or two pairs at the same places (meshed apart)."""
    import meshio

    points = [[0, 0], [1, 0], [1, 1], [0, 1], [2, 0], [2, 1]]
    right = [1, 4, 5, 2]
    if not joined:
        points += [[1, 0], [1, 1]]
        right = [6, 4, 5, 7]
    cells = [("quad", np.array([[0, 1, 2, 3], right]))]
    return meshio.Mesh(np.array(points, dtype=float), cells,
                       cell_sets={"lining": [np.array([0])], "backplate": [np.array([1])]})


def test_parts_meshed_apart_are_named_not_left_to_cycle():
    """Issue 44: a pad whose lining and backplate were meshed apart (their interface nodes
    duplicated) ended in "the active set cycles"; it is refused naming the parts."""
    from stickslip.fem.body import body_from_meshio

    assert len(body_from_meshio(_two_squares(True)).cells) == 2
    with pytest.raises(ParameterError) as err:
        body_from_meshio(_two_squares(False), "pad.msh")
    text = str(err.value)
    assert err.value.name == "mesh" and "2 parts" in text and "lining (1 cells)" in text and "backplate (1 cells)" in text
