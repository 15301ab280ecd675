"""From CAD to a solid: a STEP file's solids meshed with gmsh's OpenCASCADE kernel.

`mesh_step(step, out, size)` imports the STEP in metres whatever length unit its header states (gmsh's
``Geometry.OCCTargetUnit = M`` converts it: a pad drawn in millimetres is 0.1 m long, not 100 m), fuses
the solids that touch so that they share their interface's nodes (a lining on its backplate: one mesh),
makes each solid a cell group named by its label in the STEP (``solid1``, ``solid2``, ... where it has
none: ``solidK`` is the K-th solid of the file), each face group of ``faces`` the boundary surfaces lying in a plane ``x``, ``y`` or ``z`` = value
[m] or on a cylinder ``r`` = value [m] about the z axis (a disc's bore), and writes a gmsh mesh of tetrahedra (``order`` 1 or 2) for `stickslip.fem.solid.read_solid` with
``units="m"``. ``solids`` meshes only the solids of those names (a STEP of a whole brake: the pad's
lining and backplate in one mesh, the disc in another; bodies in contact are meshed apart, never
fused). gmsh is needed (``pip install gmsh``, in the package's ``examples`` and ``test`` extras).
"""

from __future__ import annotations

import re
from pathlib import Path

from ..errors import ParameterError
from ..quantities import FEM as Q, MAX_MESH_NODES
from ..validation import regular_input

__all__ = ["mesh_step"]

#: The planes a face group may be given by.
PLANES = ("x", "y", "z")
#: A face group on a cylinder about the z axis: ``("r", radius)``.
CYLINDER = "r"


def _name(label: str, k: int, taken: set) -> str:
    """A cell group's name from a STEP label (its last path part, letters, digits and _ - only)."""
    name = re.sub(r"[^A-Za-z0-9_-]+", "_", label.split("/")[-1]).strip("_") if label else ""
    if not name or name in taken or name.startswith("Open_CASCADE"):
        name = f"solid{k}"
    taken.add(name)
    return name


def mesh_step(step, out, size: float, *, faces: dict | None = None, order: int = 1, solids=None) -> Path:
    """Mesh the solids of the STEP file ``step`` into the gmsh file ``out`` (see the module docstring);
    ``size``: the largest cell [m]; ``faces``: ``{name: (axis, value)}`` (``axis`` x, y, z or r);
    ``solids``: the names of the solids to mesh (default all). Returns ``out``."""
    try:
        import gmsh
    except ImportError:
        raise ParameterError("step", str(step), "a STEP file meshed by gmsh, which is not installed (pip install "
                             "gmsh, or the package's examples extra)") from None
    step = regular_input("step", step, "a STEP file")
    out = Path(out)
    if out.suffix != ".msh":
        raise ParameterError("out", str(out), "a gmsh mesh file name ending in .msh")
    size = Q.check("mesh_size", size, "size")
    order = Q.check("element_order", order, "order")
    faces, _select = dict(faces or {}), solids
    for name, where in faces.items():
        if not (isinstance(where, (tuple, list)) and len(where) == 2 and where[0] in PLANES + (CYLINDER,)
                and isinstance(where[1], (int, float)) and not isinstance(where[1], bool)):
            raise ParameterError(f"faces[{name}]", where, "(axis, value): the plane x, y or z = value [m] the "
                                 "group's boundary surfaces lie in, or ('r', radius [m]): a cylinder about z")
    if solids is not None and (isinstance(solids, str) or not all(isinstance(x, str) for x in solids)
                               or not len(solids)):
        raise ParameterError("solids", solids, "the names of the STEP's solids to mesh (a list: their labels, or solid1, solid2, ... by their places in the file)")
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
        taken: set = set()  # each solid's cell group name, by its place in the file whatever is meshed
        names = {tag: _name(gmsh.model.getEntityName(3, tag), k, taken) for k, (_, tag) in enumerate(solids, 1)}
        if _select is not None:
            solids = _keep(gmsh, solids, names, list(_select), str(step))
        if len(solids) > 1:
            _, children = gmsh.model.occ.fragment(solids[:1], solids[1:])
            gmsh.model.occ.synchronize()
            names = {t: names[tag] for (_, tag), kids in zip(solids, children) for _, t in kids}
        volume = sum(gmsh.model.occ.getMass(3, tag) for _, tag in gmsh.model.getEntities(3))
        least = (volume * (8 if order == 2 else 1) / MAX_MESH_NODES) ** (1 / 3)  # about a node per cell size cubed
        if size < least:
            raise ParameterError("size", size, f"at least {least:.3g} m for this STEP's {volume:.3g} m^3 (a finer "
                                 f"mesh would pass the {MAX_MESH_NODES} nodes a mesh may have)")
        for _, tag in gmsh.model.getEntities(3):
            gmsh.model.addPhysicalGroup(3, [tag], name=names[tag])
        lo, hi = gmsh.model.getBoundingBox(-1, -1)[:3], gmsh.model.getBoundingBox(-1, -1)[3:]
        tol = max(1e-6 * max(h - l for l, h in zip(lo, hi)), 1e-6)  # OpenCASCADE pads boxes by 1e-7
        boundary = {abs(t) for _, t in gmsh.model.getBoundary(gmsh.model.getEntities(3), oriented=False)}
        for name, (axis, value) in faces.items():
            if axis == CYLINDER:
                found = [t for t in sorted(boundary) if _on_cylinder(gmsh, t, value, tol)]
                if not found:
                    raise ParameterError(f"faces[{name}]", (axis, value), "a radius [m] where the solids' boundary "
                                         "has a cylindrical surface about the z axis")
                gmsh.model.addPhysicalGroup(2, found, name=name)
                continue
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


def _keep(gmsh, solids, names, wanted, step):
    """Remove the solids whose cell group name (`_name`: the label, or ``solidK`` for the K-th solid of
    the file) is not in ``wanted``."""
    missing = [w for w in wanted if w not in names.values()]
    if missing:
        raise ParameterError("solids", missing[0], f"the name of a solid of {step} ({', '.join(names.values())})")
    drop = [(3, tag) for _, tag in solids if names[tag] not in wanted]
    if drop:
        gmsh.model.occ.remove(drop, recursive=True)
        gmsh.model.occ.synchronize()
    return gmsh.model.getEntities(3)


def _on_cylinder(gmsh, tag: int, radius: float, tol: float) -> bool:
    """Whether surface ``tag`` lies on the cylinder of ``radius`` about the z axis (sampled points)."""
    import numpy as np

    lo, hi = gmsh.model.getParametrizationBounds(2, tag)
    u, v = np.meshgrid(np.linspace(lo[0], hi[0], 5), np.linspace(lo[1], hi[1], 5))
    xyz = np.reshape(gmsh.model.getValue(2, tag, np.column_stack([u.ravel(), v.ravel()]).ravel()), (-1, 3))
    return bool(np.all(np.abs(np.hypot(xyz[:, 0], xyz[:, 1]) - radius) <= max(tol, 1e-9 * radius)))
