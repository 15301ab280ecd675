"""What a config (`stickslip.fem.config`) says differently for two solids in contact, ``dimension = 3``
(a pad with its backplate on a disc, `stickslip.fem.solid` and `stickslip.fem.pair`)::

    dimension = 3                   # solids: tetrahedra or hexahedra (linear or quadratic)
    units = "mm"                    # the length unit of both meshes' coordinates: "m" or "mm" (no default)
    mesh = "pad.msh"                # face groups (gmsh physical surfaces) where supports and contact act
    clamped = ["piston"]            # face groups held fixed (optional)
    rollers = { side = "x" }        # face groups held along coordinate axes: "x", "y", "z" or several, "xz",
                                    # or along a direction, { flank = [0.6, 0.8, 0.0] } (a symmetry plane, a
                                    # sliding support, at any angle; optional, the partner's too)

    [[material]]                    # one per cell group, or one [material] for the whole body (no plane in 3-D)
    group = "lining"                # isotropic: young, poisson, density, alpha, beta, loss_factor; or orthotropic:
    e1 = 9e9                        # e1, e2, e3, nu12, nu13, nu23, g12, g13, g23 and density, its axes
    axis1 = [1.0, 0.0, 0.0]         # axis1, axis2 = [x, y, z] (default x and y; axis 3 their cross product)

    [[load]]                        # a pressure [Pa] and a traction [tx, ty, tz] [Pa] on a face group
    group = "piston"
    pressure = 1e6

    [[spring]]                      # springs from a face group's nodes to the ground, total [kx, ky, kz] [N/m]
    group = "abutment"
    stiffness = [0.0, 1e7, 0.0]

    [partner]                       # the disc, as in 2-D: mesh, group, clamped, rollers, material(s); it turns
    omega = 30.0                    # at omega [rad/s] about the z axis through center = [x, y] [m], or
                                    # translates at velocity = [vx, vy] [m/s]

    [cea]                           # as in 2-D, and (2-D pairs too) the modally reduced CEA:
    reduced_modes = 60              # real modes of the structure with its contact springs (`stickslip.fem.reduced`)
    augment = "modes"               # its static vectors: "modes" (default), "nodes" or "none"

Not in 3-D yet, refused when written: ``[surface]`` (a rigid counter-surface: give the disc as a
``[partner]``), ``plane``. ``partner.gyroscopic = true``: the turning disc's gyroscopic and transport
terms (`stickslip.fem.turning`).
"""

from __future__ import annotations

from ..errors import ParameterError
from ..quantities import FEM as Q
from .assembly import Material
from .body import body_from_meshio, read_meshio
from .checks import number, problem_text, toml
from .solid import UNITS, VOLUME_KINDS, OrthotropicSolid, solid_from_meshio

__all__ = ["dimension_of", "units_of", "read_mesh", "solid_materials", "rollers_of", "reduced_of", "VOLUME_CELLS"]

#: meshio's volume cells (read or not): a mesh with any of them is 3-D.
VOLUME_CELLS = {"tetra", "tetra10", "hexahedron", "hexahedron20", "hexahedron27", "wedge", "wedge15", "pyramid",
                "pyramid13"}
#: The keys of a solid's isotropic and orthotropic materials.
ISOTROPIC = {"young", "poisson", "density", "alpha", "beta", "loss_factor"}
ORTHOTROPIC = {"e1", "e2", "e3", "nu12", "nu13", "nu23", "g12", "g13", "g23", "density", "axis1", "axis2", "alpha",
               "beta", "loss_factor"}


def dimension_of(problems, data: dict) -> int:
    """The config's ``dimension`` (2 when not written)."""
    value = data.get("dimension", 2)
    if isinstance(value, bool) or value not in (2, 3):
        problems.append(f"dimension = {toml(value)} must be {Q['dimension'].allowed}: 2 (plane bodies, the default) "
                        "or 3 (solids)")
        return 2
    return int(value)


def units_of(problems, data: dict, dimension: int) -> str | None:
    """The meshes' length unit (``units``): required with solids, refused with plane bodies."""
    if dimension == 2:
        if "units" in data:
            problems.append(f"units = {toml(data['units'])} applies with dimension = 3 (a 2-D mesh is read in metres)")
        return None
    value = data.get("units")
    if not isinstance(value, str) or value not in UNITS:  # (a list or a table: no key of UNITS, and unhashable)
        problems.append(f"units = {toml(value)} must be the length unit of the meshes' coordinates, "
                        f"{' or '.join(map(repr, UNITS))} (a CAD model is often in mm; no default)"
                        if value is not None else "units is missing (the length unit of the meshes' coordinates, "
                        f"{' or '.join(map(repr, UNITS))}: a CAD model in mm read as metres is a brake 1000 times "
                        "too large)")
        return None
    return value


def read_mesh(problems, path, where: str, dimension: int, units: str | None):
    """The `stickslip.fem.body.Body` (2-D) or `stickslip.fem.solid.Solid` (3-D) of the mesh at ``where``, or
    None with the problem; a mesh of the other dimension is named as such."""
    try:
        mesh = read_meshio(path)
    except ParameterError as err:
        problems.append(f"{where}: {err}")
        return None
    kinds = sorted({c.type for c in mesh.cells})
    volumes = [k for k in kinds if k in VOLUME_CELLS]
    if dimension == 2 and volumes:
        problems.append(f"{where} = {path.name!r} is a 3-D mesh ({', '.join(volumes)} cells): a config of solids says "
                        "dimension = 3, and units")
        return None
    if dimension == 3 and not volumes:
        problems.append(f"{where} = {path.name!r} is a 2-D mesh ({', '.join(kinds) or 'no'} cells) but dimension = 3: "
                        f"give a mesh of volume cells ({', '.join(VOLUME_KINDS)}), or leave dimension out for a plane "
                        "body")
        return None
    if dimension == 3 and units is None:
        return None  # (its problem said)
    try:
        return body_from_meshio(mesh, str(path)) if dimension == 2 else solid_from_meshio(mesh, path.name, units)
    except ParameterError as err:
        problems.append(f"{where} = {path.name!r} must be {err.allowed}")
        return None


def solid_materials(problems, tables: list, key: str) -> dict:
    """``{cell group: Material or OrthotropicSolid}`` of the material ``tables`` (``(where, table)``,
    where ``"material"`` or ``"material[1]"``), or None for a table with a problem."""
    out = {}
    for where, m in tables:
        ortho = "e1" in m
        allowed = ORTHOTROPIC if ortho else ISOTROPIC
        for k in sorted(m):
            if k in allowed or (k == "group" and "[" in where):
                continue
            problems.append(f"{where}.plane applies to plane bodies (a solid has no plane)" if k == "plane" else
                            f"unknown key {where}.{k}" + (" (an orthotropic solid, with e1, takes e1, e2, e3, nu12, "
                                                          "nu13, nu23, g12, g13, g23)" if ortho else ""))
        name = m.get("group", "") if "[" in where else ""
        if "[" in where and (not isinstance(name, str) or not name):
            problems.append(f"{where}.group must be the name of a cell group of the mesh")
            continue
        if name in out:
            problems.append(f"{where}.group = {name!r} must name each cell group once ({name!r} has a material already)")
            continue
        common = {k: number(problems, f"{where}.{k}", m.get(k, None if k == "density" else 0.0))
                  for k in ("density", "alpha", "beta", "loss_factor")}
        if ortho:
            args = {k: number(problems, f"{where}.{k}", m.get(k)) for k in ("e1", "e2", "e3", "nu12", "nu13", "nu23",
                                                                           "g12", "g13", "g23")}
            args.update({k: m[k] for k in ("axis1", "axis2") if k in m})
            kind = OrthotropicSolid
        else:
            args = {k: number(problems, f"{where}.{k}", m.get(k)) for k in ("young", "poisson")}
            kind = Material
        out[name] = None
        if all(v is not None for v in {**args, **common}.values()):
            try:
                out[name] = kind(**args, **common)
            except ParameterError as err:
                problems.append(f"{where}.{err.name} = {toml(err.value)} must be {err.allowed}")
    return out


def rollers_of(problems, value, where: str, dimension: int) -> dict:
    """``{face group: axes or direction}`` of ``rollers = { group = "x" }`` (each axis once) or
    ``{ group = [dx, dy, dz] }`` (a direction of ``dimension`` numbers, not all 0)."""
    from .supports import direction_of

    if value is None:
        return {}
    if not isinstance(value, dict):
        problems.append(f"{where} = {toml(value)} must be a table of groups and axes, e.g. {where} = {{ side = \"x\" }}")
        return {}
    out = {}
    for group, ax in value.items():
        try:
            direction_of(ax, dimension, f"{where}.{group}")
        except ParameterError:
            example = ", ".join(["0.6", "0.8", "0.0"][:dimension])
            problems.append(f"{where}.{group} = {toml(ax)} must be the axes it is held along, each of "
                            f"{', '.join('xyz'[:dimension])} at most once (\"x\", \"xz\"), or a direction of "
                            f"{dimension} finite numbers, not all 0 ([{example}])")
        else:
            out[group] = list(map(float, ax)) if isinstance(ax, list) else ax
    return out


def reduced_of(problems, e: dict, options: dict) -> dict | None:
    """``{"count", "augment"}`` of ``cea.reduced_modes`` and ``cea.augment``, or None without them."""
    if "reduced_modes" not in e:
        if "augment" in e:
            problems.append("cea.augment applies with cea.reduced_modes (the reduced CEA's basis)")
        return None
    count = e["reduced_modes"]
    if not isinstance(count, int) or isinstance(count, bool):
        problems.append(f"cea.reduced_modes = {toml(count)} must be {Q['reduced_modes'].allowed}")
        count = None
    else:
        count = number(problems, "cea.reduced_modes", count)
    augment = e.get("augment", "modes")
    try:
        augment = Q.check("augment", augment, "cea.augment")
    except ParameterError as err:
        problems.append(problem_text(err))
    if options.get("contact_model") == "constraint":
        problems.append('cea.contact_model = "constraint" does not apply with cea.reduced_modes (the reduced CEA '
                        "holds the contact by penalty springs)")
    if options.get("mass_matrix") == "consistent":
        problems.append('cea.mass_matrix = "consistent" does not apply with cea.reduced_modes (its basis is of the '
                        "lumped mass)")
    return {"count": count, "augment": augment}
