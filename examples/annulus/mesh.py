"""Mesh of the paper's annulus (gmsh): R < r < xi R, boundary groups ``bore`` and ``rim``.

Usage: ``python mesh.py [annulus.msh] [size]`` (size in m).
"""

import sys

import gmsh

R, XI = 0.1, 1.5


def make(path="annulus.msh", size=0.01):
    gmsh.initialize(["-noenv"])
    gmsh.option.setNumber("General.Terminal", 0)
    try:
        gmsh.model.add("annulus")
        occ = gmsh.model.occ
        (ring,), _ = occ.cut([(2, occ.addDisk(0, 0, 0, XI * R, XI * R))], [(2, occ.addDisk(0, 0, 0, R, R))])
        occ.synchronize()
        curves = [c for _, c in gmsh.model.getBoundary([ring], oriented=False)]
        inner = [c for c in curves if occ.getBoundingBox(1, c)[3] < 1.01 * R]
        gmsh.model.addPhysicalGroup(1, inner, name="bore")
        gmsh.model.addPhysicalGroup(1, [c for c in curves if c not in inner], name="rim")
        gmsh.model.addPhysicalGroup(2, [ring[1]], name="annulus")
        gmsh.option.setNumber("Mesh.MeshSizeMax", size)
        gmsh.model.mesh.generate(2)
        gmsh.write(str(path))
    finally:
        gmsh.finalize()


if __name__ == "__main__":
    make(*(sys.argv[1:2] or ["annulus.msh"]), *(float(x) for x in sys.argv[2:3]))
