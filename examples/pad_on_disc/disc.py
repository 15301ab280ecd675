"""Mesh of an elastic brake disc (gmsh), in its plane: an annulus HUB < r < RIM + interference.

Boundary groups: ``rim`` (the outer circle, under the pad of ``mesh.py``: the pad's face lies
at r = 0.15 m, so the rim at 0.15 m + interference presses into it) and ``hub`` (the inner
circle, bolted to the axle: clamped). Cell group ``disc``. The mesh is finest along the rim
(``size`` [m], so that its chords sag far less than the interference: size^2 / (8 R)) and
coarser towards the hub. Usage: ``python disc.py [disc.msh] [size] [interference]``.
"""

import sys

import gmsh

HUB, RIM = 0.06, 0.15  # [m]


def make(path="disc.msh", size=0.0015, interference=2e-5):
    gmsh.initialize(["-noenv"])
    gmsh.option.setNumber("General.Terminal", 0)
    try:
        gmsh.model.add("disc")
        occ = gmsh.model.occ
        outer = occ.addDisk(0, 0, 0, RIM + interference, RIM + interference)
        inner = occ.addDisk(0, 0, 0, HUB, HUB)
        (annulus, *_), _ = occ.cut([(2, outer)], [(2, inner)])
        occ.synchronize()
        radius = {c: max(abs(v) for v in occ.getBoundingBox(1, c)[:2]) for _, c in gmsh.model.getEntities(1)}
        rim = [c for c, r in radius.items() if r > 0.5 * (HUB + RIM)]
        hub = [c for c, r in radius.items() if r <= 0.5 * (HUB + RIM)]
        gmsh.model.addPhysicalGroup(1, rim, name="rim")
        gmsh.model.addPhysicalGroup(1, hub, name="hub")
        gmsh.model.addPhysicalGroup(2, [annulus[1]], name="disc")
        field = gmsh.model.mesh.field
        distance = field.add("Distance")
        field.setNumbers(distance, "CurvesList", rim)
        field.setNumber(distance, "Sampling", 2000)
        threshold = field.add("Threshold")
        field.setNumber(threshold, "InField", distance)
        field.setNumber(threshold, "SizeMin", size)
        field.setNumber(threshold, "SizeMax", 8 * size)
        field.setNumber(threshold, "DistMin", 0.01)
        field.setNumber(threshold, "DistMax", 0.06)
        field.setAsBackgroundMesh(threshold)
        gmsh.option.setNumber("Mesh.MeshSizeExtendFromBoundary", 0)
        gmsh.option.setNumber("Mesh.MeshSizeFromPoints", 0)
        gmsh.option.setNumber("Mesh.MeshSizeFromCurvature", 0)
        gmsh.model.mesh.generate(2)
        gmsh.write(str(path))
    finally:
        gmsh.finalize()


if __name__ == "__main__":
    make(*(sys.argv[1:2] or ["disc.msh"]), *(float(x) for x in sys.argv[2:4]))
