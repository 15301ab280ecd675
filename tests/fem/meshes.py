"""Small meshes for the tests of `stickslip.fem`, made with gmsh's Python API at test time."""

from __future__ import annotations

import contextlib

import meshio


@contextlib.contextmanager
def _gmsh(name: str):
    import gmsh

    gmsh.initialize(["-noenv"])
    gmsh.option.setNumber("General.Terminal", 0)
    gmsh.model.add(name)
    try:
        yield gmsh
    finally:
        gmsh.finalize()


def rectangle(path, width: float = 0.04, height: float = 0.01, size: float = 0.004, quads: bool = False,
              order: int = 1, origin=(0.0, 0.0)) -> meshio.Mesh:
    """A ``width x height`` rectangle from ``origin`` with boundary groups bottom, top, left,
    right; ``order`` 2: 6-node triangles or 9-node quadrilaterals."""
    x0, y0 = origin
    with _gmsh("rectangle") as gmsh:
        r = gmsh.model.occ.addRectangle(x0, y0, 0, width, height)
        gmsh.model.occ.synchronize()
        where = {"bottom": (x0 + width / 2, y0), "top": (x0 + width / 2, y0 + height), "left": (x0, y0 + height / 2),
                 "right": (x0 + width, y0 + height / 2)}
        for name, (x, y) in where.items():
            tag = [c for _, c in gmsh.model.getBoundary([(2, r)], oriented=False)
                   if max(abs(a - b) for a, b in zip(gmsh.model.occ.getCenterOfMass(1, c)[:2], (x, y))) < 1e-9]
            gmsh.model.addPhysicalGroup(1, tag, name=name)
        gmsh.model.addPhysicalGroup(2, [r], name="body")
        gmsh.option.setNumber("Mesh.MeshSizeMax", size)
        if quads:  # a structured grid of quadrilaterals
            for _, c in gmsh.model.getBoundary([(2, r)], oriented=False):
                box = gmsh.model.occ.getBoundingBox(1, abs(c))
                length = max(box[3] - box[0], box[4] - box[1])
                gmsh.model.mesh.setTransfiniteCurve(abs(c), max(2, round(length / size) + 1))
            gmsh.model.mesh.setTransfiniteSurface(r)
            gmsh.model.mesh.setRecombine(2, r)
        gmsh.model.mesh.generate(2)
        gmsh.model.mesh.setOrder(order)
        gmsh.write(str(path))
    return meshio.read(path)


def annulus(path, inner: float = 1.0, outer: float = 1.5, size: float = 0.1, order: int = 1) -> meshio.Mesh:
    """An annulus ``inner < r < outer`` with boundary groups bore (r = inner) and rim (r = outer);
    ``order`` 2: 6-node triangles with their middle nodes on the circles."""
    with _gmsh("annulus") as gmsh:
        a = gmsh.model.occ.addDisk(0, 0, 0, outer, outer)
        b = gmsh.model.occ.addDisk(0, 0, 0, inner, inner)
        (ring,), _ = gmsh.model.occ.cut([(2, a)], [(2, b)])
        gmsh.model.occ.synchronize()
        curves = [c for _, c in gmsh.model.getBoundary([ring], oriented=False)]
        radius = {c: abs(gmsh.model.occ.getBoundingBox(1, c)[3]) for c in curves}
        gmsh.model.addPhysicalGroup(1, [c for c in curves if abs(radius[c] - inner) < 1e-6], name="bore")
        gmsh.model.addPhysicalGroup(1, [c for c in curves if abs(radius[c] - outer) < 1e-6], name="rim")
        gmsh.model.addPhysicalGroup(2, [ring[1]], name="body")
        gmsh.option.setNumber("Mesh.MeshSizeMax", size)
        gmsh.model.mesh.generate(2)
        gmsh.model.mesh.setOrder(order)
        gmsh.write(str(path))
    return meshio.read(path)


def two_layers(path, first: float = 0.02, second: float = 0.03, height: float = 0.01, size: float = 0.003,
               order: int = 1, names=("a", "b")) -> meshio.Mesh:
    """A rectangle ``(first + second) x height`` of two cell groups, ``names[0]`` for ``x < first``
    and ``names[1]`` beyond, meshed together (their interface is a mesh line); boundary groups
    left (x = 0), right, bottom and top (both layers)."""
    with _gmsh("two_layers") as gmsh:
        occ = gmsh.model.occ
        a = occ.addRectangle(0, 0, 0, first, height)
        b = occ.addRectangle(first, 0, 0, second, height)
        occ.fragment([(2, a)], [(2, b)])
        occ.synchronize()
        width = first + second
        curves = [c for _, c in gmsh.model.getEntities(1)]
        box = {c: occ.getBoundingBox(1, c) for c in curves}
        pick = {"left": lambda b: b[3] < 1e-6, "right": lambda b: b[0] > width - 1e-6,
                "bottom": lambda b: b[4] < 1e-6, "top": lambda b: b[1] > height - 1e-6}
        for name, test in pick.items():
            gmsh.model.addPhysicalGroup(1, [c for c in curves if test(box[c])], name=name)
        surfaces = sorted(gmsh.model.getEntities(2), key=lambda e: occ.getCenterOfMass(2, e[1])[0])
        for (_, tag), name in zip(surfaces, names):
            gmsh.model.addPhysicalGroup(2, [tag], name=name)
        gmsh.option.setNumber("Mesh.MeshSizeMax", size)
        gmsh.model.mesh.generate(2)
        gmsh.model.mesh.setOrder(order)
        gmsh.write(str(path))
    return meshio.read(path)


def ring(n_theta: int = 32, n_r: int = 3, inner: float = 0.1, outer: float = 0.15) -> meshio.Mesh:
    """A structured ring of ``n_theta x n_r`` quadrilaterals, exactly symmetric under turns by
    ``2 pi / n_theta`` (to round-off), with boundary groups bore (r = inner) and rim."""
    import numpy as np

    theta = 2 * np.pi * np.arange(n_theta) / n_theta
    r = np.linspace(inner, outer, n_r + 1)
    points = np.array([(ri * np.cos(t), ri * np.sin(t)) for ri in r for t in theta])
    node = lambda i, j: j * n_theta + i % n_theta  # noqa: E731
    quads = [[node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)] for j in range(n_r) for i in range(n_theta)]
    bore = [[node(i, 0), node(i + 1, 0)] for i in range(n_theta)]
    rim = [[node(i, n_r), node(i + 1, n_r)] for i in range(n_theta)]
    cells = [meshio.CellBlock("quad", np.array(quads)), meshio.CellBlock("line", np.array(bore + rim))]
    return meshio.Mesh(points, cells, cell_sets={"bore": [np.array([], int), np.arange(n_theta)],
                                                 "rim": [np.array([], int), np.arange(n_theta, 2 * n_theta)]})
