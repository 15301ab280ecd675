"""Mesh of a brake pad on a disc rim (gmsh): an annular sector R < r < R + h, |theta| < phi.

Boundary groups: ``face`` (r = R, on the disc), ``back`` (r = R + h, held by the caliper),
``ends`` (the two sides). Usage: ``python mesh.py [pad.msh] [size] [order]`` (size in m;
order 2: 6-node triangles with their middle nodes on the arcs).
"""

import math
import sys

import gmsh

R, H, PHI = 0.15, 0.012, math.radians(12.0)  # disc radius, pad thickness, half angle


def make(path="pad.msh", size=0.002, order=1):
    gmsh.initialize(["-noenv"])
    gmsh.option.setNumber("General.Terminal", 0)
    try:
        gmsh.model.add("pad")
        occ = gmsh.model.occ
        c = occ.addPoint(0, 0, 0)
        p = [occ.addPoint(r * math.sin(a), r * math.cos(a), 0) for r, a in
             ((R, -PHI), (R, PHI), (R + H, PHI), (R + H, -PHI))]
        face, back = occ.addCircleArc(p[0], c, p[1]), occ.addCircleArc(p[2], c, p[3])
        right, left = occ.addLine(p[1], p[2]), occ.addLine(p[3], p[0])
        surface = occ.addPlaneSurface([occ.addCurveLoop([face, right, back, left])])
        occ.synchronize()
        gmsh.model.addPhysicalGroup(1, [face], name="face")
        gmsh.model.addPhysicalGroup(1, [back], name="back")
        gmsh.model.addPhysicalGroup(1, [left, right], name="ends")
        gmsh.model.addPhysicalGroup(2, [surface], name="pad")
        gmsh.option.setNumber("Mesh.MeshSizeMax", size)
        gmsh.model.mesh.generate(2)
        gmsh.model.mesh.setOrder(order)
        gmsh.write(str(path))
    finally:
        gmsh.finalize()


if __name__ == "__main__":
    make(*(sys.argv[1:2] or ["pad.msh"]), *(float(x) for x in sys.argv[2:3]), *(int(x) for x in sys.argv[3:4]))
