"""Mesh of an elastic block on a belt (gmsh): a W x H rectangle of quadrilaterals.

Boundary groups: ``bottom`` (on the belt), ``top`` (pressed and driven), ``left`` and
``right`` (free). Usage: ``python mesh.py [block.msh] [size]`` (size in m).
"""

import sys

import gmsh

W, H = 0.1, 0.01  # length and thickness of the block [m]


def make(path="block.msh", size=0.0025):
    gmsh.initialize(["-noenv"])
    gmsh.option.setNumber("General.Terminal", 0)
    try:
        gmsh.model.add("block")
        occ = gmsh.model.occ
        p = [occ.addPoint(x, y, 0) for x, y in ((0, 0), (W, 0), (W, H), (0, H))]
        sides = [occ.addLine(p[i], p[(i + 1) % 4]) for i in range(4)]  # bottom, right, top, left
        surface = occ.addPlaneSurface([occ.addCurveLoop(sides)])
        occ.synchronize()
        for name, line in zip(("bottom", "right", "top", "left"), sides):
            gmsh.model.addPhysicalGroup(1, [line], name=name)
            gmsh.model.mesh.setTransfiniteCurve(line, max(2, round((W if name in ("bottom", "top") else H) / size) + 1))
        gmsh.model.addPhysicalGroup(2, [surface], name="block")
        gmsh.model.mesh.setTransfiniteSurface(surface)
        gmsh.model.mesh.setRecombine(2, surface)
        gmsh.model.mesh.generate(2)
        gmsh.write(str(path))
    finally:
        gmsh.finalize()


if __name__ == "__main__":
    make(*(sys.argv[1:2] or ["block.msh"]), *(float(x) for x in sys.argv[2:3]))
