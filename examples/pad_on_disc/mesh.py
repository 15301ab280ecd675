"""Mesh of a brake pad on a disc rim (gmsh): an annular sector R < r < R + h, |theta| < phi.

Boundary groups: ``face`` (r = R, on the disc), ``back`` (r = R + h, held by the caliper),
``ends`` (the two sides). Usage: ``python mesh.py [pad.msh] [size] [order] [backplate]`` (size
in m; order 2: 6-node triangles with their middle nodes on the arcs). Cell groups: ``pad``;
with a ``backplate`` thickness [m] > 0, the friction ``lining`` (R < r < R + h - backplate)
and the steel ``backplate`` behind it instead, meshed together (`pad_layers.toml` gives
each its material).
"""

import math
import sys

import gmsh

R, H, PHI = 0.15, 0.012, math.radians(12.0)  # disc radius, pad thickness, half angle


def make(path="pad.msh", size=0.002, order=1, backplate=0.0):
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
        if backplate > 0:  # cut the pad along the arc r = R + H - backplate
            cut = occ.addCircle(0, 0, 0, R + H - backplate)
            occ.fragment([(2, surface)], [(1, cut)])
        occ.synchronize()
        curves = [c for _, c in gmsh.model.getEntities(1) if gmsh.model.getAdjacencies(1, c)[0].size]
        radius = {c: _radius(gmsh, c) for c in curves}
        arcs = {c: r for c, r in radius.items() if r is not None}
        gmsh.model.addPhysicalGroup(1, [c for c, r in arcs.items() if abs(r - R) < 1e-9], name="face")
        gmsh.model.addPhysicalGroup(1, [c for c, r in arcs.items() if abs(r - R - H) < 1e-9], name="back")
        gmsh.model.addPhysicalGroup(1, [c for c in curves if radius[c] is None], name="ends")
        surfaces = sorted((occ.getCenterOfMass(2, s)[1], s) for _, s in gmsh.model.getEntities(2))
        if backplate > 0:
            gmsh.model.addPhysicalGroup(2, [surfaces[0][1]], name="lining")
            gmsh.model.addPhysicalGroup(2, [surfaces[1][1]], name="backplate")
        else:
            gmsh.model.addPhysicalGroup(2, [s for _, s in surfaces], name="pad")
        gmsh.option.setNumber("Mesh.MeshSizeMax", size)
        gmsh.model.mesh.generate(2)
        gmsh.model.mesh.setOrder(order)
        gmsh.write(str(path))
    finally:
        gmsh.finalize()


def _radius(gmsh, curve):
    """The radius of a circular arc about the origin, or None for a straight side."""
    lo, hi = gmsh.model.getParametrizationBounds(1, curve)
    points = [gmsh.model.getValue(1, curve, [t]) for t in (lo[0], 0.5 * (lo[0] + hi[0]), hi[0])]
    r = [math.hypot(p[0], p[1]) for p in points]
    return r[0] if max(r) - min(r) < 1e-9 else None


if __name__ == "__main__":
    make(*(sys.argv[1:2] or ["pad.msh"]), *(float(x) for x in sys.argv[2:3]), *(int(x) for x in sys.argv[3:4]),
         *(float(x) for x in sys.argv[4:5]))
