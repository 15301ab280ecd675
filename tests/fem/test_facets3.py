"""A curved 3-D contact meshed with flat faces (issue 45): the faces' deviation from the surface
through their nodes (`stickslip.fem.facets.face_deviation`) and the warning of steady sliding where it
is not small against the interference the contact carries.

* On a faceted cylinder the deviation of every interior face is the exact sagitta of its chord,
  ``R - sqrt(R^2 - h^2 / 4)`` (1e-9; threshold set before the run), triangles (their diagonals too:
  the normal curvature along an edge, Euler's ``cos^2``) and quadrilaterals; on a flat face 0.
* A pad pressed 50 micrometres into a drum (a 3-D drum brake: the drum's inner face the master,
  turning about z): with 7.5-degree faces (sagitta 210 micrometres) steady sliding warns, naming the
  group and the ratio; with 0.94-degree faces (3.4 micrometres) it does not.
"""

import logging

import numpy as np
import pytest

from stickslip.fem import Material
from stickslip.fem.facets import face_deviation
from stickslip.fem.pair import PairProblem, Rotation, steady_pair
from stickslip.fem.solid import assemble_solid, solid_from_meshio

from .test_solid import box


def _strip(R, cells, span=np.pi / 2, width=0.05, across=5):
    th = np.linspace(0, span, cells + 1)
    y = np.linspace(0, width, across + 1)
    T, Y = np.meshgrid(th, y, indexing="ij")
    points = np.column_stack([R * np.cos(T.ravel()), Y.ravel(), R * np.sin(T.ravel())])

    def node(i, j):
        return i * (across + 1) + j

    quads = np.array([[node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)]
                      for i in range(cells) for j in range(across)])
    return points, quads, T, 2 * R * np.sin(span / cells / 2)


@pytest.mark.parametrize("kind", ["quad", "triangle"])
def test_the_faces_of_a_faceted_cylinder_deviate_by_the_chords_sagitta(kind):
    R = 0.1
    points, quads, T, h = _strip(R, 24)
    faces = quads if kind == "quad" else np.vstack([quads[:, [0, 1, 2]], quads[:, [0, 2, 3]]])
    exact = R - np.sqrt(R * R - h * h / 4)
    inner = np.all(np.isin(faces, np.flatnonzero((T.ravel() > 0) & (T.ravel() < np.pi / 2))), axis=1)
    assert np.allclose(face_deviation(points, faces)[inner], exact, rtol=1e-9)  # the ends' normals one-sided
    flat = np.column_stack([T.ravel(), points[:, 1], np.zeros(len(points))])
    assert face_deviation(flat, faces).max() == 0.0


def _ring(r0, thickness, span, cells, start):
    """A box of hexahedra bent into a sector of a ring about z: x the angle, y the height along z, z the
    radius (faces x0/x1 the sector's ends, z0 the inner face at r0, z1 the outer)."""
    mesh = box((span, 0.02, thickness), (cells, 2, 2), "hexahedron")
    theta, height, r = start + mesh.points[:, 0], mesh.points[:, 1], r0 + mesh.points[:, 2]
    mesh.points = np.column_stack([r * np.cos(theta), r * np.sin(theta), height])
    return mesh


@pytest.mark.parametrize("cells, warned", [(12, True), (96, False)])
def test_steady_sliding_warns_where_a_drums_faces_deviate_more_than_the_interference(cells, warned, caplog):
    R, interference, T = 0.1, 5e-5, 0.02
    drum = solid_from_meshio(_ring(R, 0.01, np.pi / 2, cells, 0.0), "drum", units="m")
    pad = solid_from_meshio(_ring(R + interference - T, T, np.pi / 6, 8, np.pi / 6), "pad", units="m")
    steel = Material(2.1e11, 0.3, 7850.0)
    problem = PairProblem(assemble_solid(pad, Material(5e9, 0.25, 2500.0)), "z1", assemble_solid(drum, steel), "z0",
                          Rotation(10.0), clamped_slave=("z0",), clamped_master=("z1",))
    with caplog.at_level(logging.WARNING, logger="stickslip.fem"):
        steady = steady_pair(problem)
    assert steady.normal_force > 0
    assert ("deviate from its curve" in caplog.text) == warned, caplog.text
    if warned:
        assert "'z0'" in caplog.text
