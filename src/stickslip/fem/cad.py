"""From CAD to a solid: a STEP file's solids meshed with gmsh's OpenCASCADE kernel.

`mesh_step(step, out, size)` imports the STEP in metres whatever length unit its header states (gmsh's
``Geometry.OCCTargetUnit = M`` converts it: a pad drawn in millimetres is 0.1 m long, not 100 m), fuses
the solids that touch so that they share their interface's nodes (a lining on its backplate: one mesh),
makes each solid a cell group named by its label in the STEP (``solid1``, ``solid2``, ... where it has
none), each face group of ``faces`` the boundary surfaces lying in a plane ``x``, ``y`` or ``z`` = value
[m], and writes a gmsh mesh of tetrahedra (``order`` 1 or 2) for `stickslip.fem.solid.read_solid` with
``units="m"``. gmsh is needed (``pip install gmsh``, in the package's ``examples`` and ``test`` extras).
"""

from __future__ import annotations

import re
from pathlib import Path

from ..errors import ParameterError
from ..validation import regular_input

__all__ = ["mesh_step"]

#: The planes a face group may be given by.
PLANES = ("x", "y", "z")


def _name(label: str, k: int, taken: set) -> str:
    """A cell group's name from a STEP label (its last path part, letters, digits and _ - only)."""
    name = re.sub(r"[^A-Za-z0-9_-]+", "_", label.split("/")[-1]).strip("_") if label else ""
    if not name or name in taken or name.startswith("Open_CASCADE"):
        name = f"solid{k}"
    taken.add(name)
    return name


def mesh_step(step, out, size: float, *, faces: dict | None = None, order: int = 1) -> Path:
    """Mesh the solids of the STEP file ``step`` into the gmsh file ``out`` (see the module docstring);
    ``size``: the largest cell [m]; ``faces``: ``{name: (axis, value)}``. Returns ``out``."""
    try:
        import gmsh
    except ImportError:
        raise ParameterError("step", str(step), "a STEP file meshed by gmsh, which is not installed (pip install "
                             "gmsh, or the package's examples extra)") from None
    step = regular_input("step", step, "a STEP file")
    out = Path(out)
    if out.suffix != ".msh":
        raise ParameterError("out", str(out), "a gmsh mesh file name ending in .msh")
    if not isinstance(size, (int, float)) or isinstance(size, bool) or not 0 < size < 1e3:
        raise ParameterError("size", size, "the largest cell in metres, in (0, 1000)")
    if order not in (1, 2):
        raise ParameterError("order", order, "1 (linear tetrahedra) or 2 (quadratic)")
    faces = dict(faces or {})
    for name, where in faces.items():
        if not (isinstance(where, (tuple, list)) and len(where) == 2 and where[0] in PLANES
                and isinstance(where[1], (int, float)) and not isinstance(where[1], bool)):
            raise ParameterError(f"faces[{name}]", where, "(axis, value): the plane x, y or z = value [m] the "
                                 "group's boundary surfaces lie in")
    gmsh.initialize(interruptible=False)
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        gmsh.option.setString("Geometry.OCCTargetUnit", "M")
        try:
            gmsh.model.occ.importShapes(str(step))
        except Exception as err:  # noqa: BLE001 - gmsh raises a bare Exception
            raise ParameterError("step", str(step), f"a STEP file gmsh's OpenCASCADE kernel reads ({err})") from None
        gmsh.model.occ.synchronize()
        solids = gmsh.model.getEntities(3)
        if not solids:
            raise ParameterError("step", str(step), "a STEP file with at least one solid (it has none: surfaces "
                                 "only?)")
        labels = {tag: gmsh.model.getEntityName(3, tag) for _, tag in solids}
        if len(solids) > 1:
            gmsh.model.occ.fragment(solids[:1], solids[1:])
            gmsh.model.occ.synchronize()
        taken: set = set()
        for k, (_, tag) in enumerate(gmsh.model.getEntities(3), 1):
            gmsh.model.addPhysicalGroup(3, [tag], name=_name(labels.get(tag, ""), k, taken))
        lo, hi = gmsh.model.getBoundingBox(-1, -1)[:3], gmsh.model.getBoundingBox(-1, -1)[3:]
        tol = 1e-6 * max(h - l for l, h in zip(lo, hi))
        boundary = {abs(t) for _, t in gmsh.model.getBoundary(gmsh.model.getEntities(3), oriented=False)}
        for name, (axis, value) in faces.items():
            a = PLANES.index(axis)
            found = [t for t in sorted(boundary) if abs(gmsh.model.getBoundingBox(2, t)[a] - value) <= tol
                     and abs(gmsh.model.getBoundingBox(2, t)[a + 3] - value) <= tol]
            if not found:
                raise ParameterError(f"faces[{name}]", (axis, value), f"a plane {axis} = value [m] where the solids' "
                                     f"boundary has a surface (they span {axis} from {lo[a]:.6g} to {hi[a]:.6g} m)")
            gmsh.model.addPhysicalGroup(2, found, name=name)
        gmsh.option.setNumber("Mesh.MeshSizeMax", float(size))
        gmsh.option.setNumber("Mesh.ElementOrder", order)
        gmsh.model.mesh.generate(3)
        gmsh.write(str(out))
    finally:
        gmsh.finalize()
    return out
