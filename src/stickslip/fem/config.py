"""A general-body problem from a small TOML config, validated with every problem listed at once::

    mesh = "pad.msh"                # any mesh meshio reads; relative to the config file
    clamped = ["top"]               # boundary groups held fixed (optional)

    [material]                      # SI units; the whole body
    young = 2.1e11
    poisson = 0.3
    density = 7850.0
    plane = "strain"                # or "stress"
    alpha = 0.0                     # Rayleigh damping C = alpha M + beta K (optional)
    beta = 0.0
    loss_factor = 0.0               # structural damping: the CEA's stiffness times (1 + i loss_factor)
                                    # (optional; the CEA only, refused by fem run)

    # or one material per cell group of the mesh (gmsh physical surfaces), every group one:
    # [[material]]
    # group = "lining"              # a cell group
    # young = 1.0e10                # ... and the keys above (plane the same for all)
    # [[material]]
    # group = "backplate"
    # young = 2.1e11
    # An orthotropic material (a lining; stickslip.fem.orthotropic) has e1, e2 [Pa], nu12, g12 [Pa]
    # and angle [deg] (axis 1 from x) instead of young and poisson; in plane strain e3 [Pa], nu13,
    # nu23 too.

    [contact]
    group = "bottom"                # the boundary group in contact
    friction = 0.4                  # Coulomb coefficient (kinetic)
    static_friction = 0.5           # static coefficient >= friction (optional; default: friction)
    law = "stribeck"                # optional: friction falling with the slip speed v_r, from
    stribeck_speed = 0.1            # static_friction to friction, mu = f_d + (f_s - f_d) exp(-v_r / v_s) [m/s];
                                    # or law = "linear-weakening", weakening = tau [s/m]: mu = f_d (1 - tau v_r)
                                    # (steady sliding, the CEA and explicit runs, node by node)
    pressure_exponent = 0.1         # optional, with reference_pressure: each node's coefficients times
    reference_pressure = 1e6        # (P / P_ref)^(-n) at its own contact pressure P [Pa] (n in [-1, 1))

    [[spring]]                      # springs from a group's nodes to the ground (optional, repeatable)
    group = "left"
    stiffness = [1e8, 0.0]          # total [kx, ky] of the group [N/m per metre of thickness]

    [[load]]                        # a uniform load on a group (optional, repeatable)
    group = "top"
    pressure = 1e6                  # [Pa], positive pushes into the body
    traction = [0.0, 0.0]           # [tx, ty] [Pa] (optional)

    [surface]                       # the rigid counter-surface, one of:
    kind = "cylinder"               # radius [m], omega [rad/s] (> 0: counter-clockwise), center = [x, y] [m],
                                    # body_inside = false (true: the body inside the cylinder, a drum)
    # kind = "flat"                 # point = [x, y] [m], normal = [nx, ny] (into the body), velocity = [vx, vy] [m/s]
    interference = 1e-5             # how far the surface is pushed into the body [m] (optional, either kind;
                                    # a flat is moved along its normal, a cylinder's radius changed)

    # or, instead of [surface], an elastic counter-body (`stickslip.fem.pair`: steady sliding and
    # the CEA of two bodies; the mesh's group above is the slave, the partner's the master):
    # [partner]
    # mesh = "disc.msh"             # relative to the config file
    # group = "rim"                 # its boundary group facing contact.group
    # clamped = ["hub"]             # its groups held fixed (optional)
    # omega = 30.0                  # it turns at omega [rad/s] about center = [x, y] [m] (a disc),
    # center = [0.0, 0.0]           # or translates at velocity = [vx, vy] [m/s] (a slider)
    # gyroscopic = false            # true: a turning partner's gyroscopic and transport terms (Eulerian)
    # transverse_damping = false    # solids: true puts the friction turning with a slip across in the CEA
    # prestress = false             # a turning solid: true adds its centrifugal prestress's stiffening
    # [partner.material]            # its material(s): as [material] (or [[partner.material]] per cell group)
    # young = 1.25e11

    [cea]                           # for `stickslip fem cea` (optional)
    band = [0.0, 20000.0]           # [Hz] (default [0, 10000])
    count = 30                      # eigenvalues per shift to start with (default 30)
    complete_below = 5e3            # [1/s]: every mode with |growth rate| below it is found
                                    # (default 0.1 x 2 pi x the band's top)
    mass_matrix = "lumped"          # or "consistent" (optional)
    contact_model = "constraint"    # or "penalty": the contact nodes on springs of penalty x the
    penalty = 1e3                   # stiffness' largest diagonal entry (optional; default 1e3)

`load_config(path)` returns a `FemConfig`; `FemConfig.problem()` builds the `ContactProblem` (with a
``[partner]``: the `stickslip.fem.pair.PairProblem`).
"""

from __future__ import annotations

import math
import re
import tomllib

import numpy as np
from dataclasses import dataclass, field
from pathlib import Path

from ..quantities import FEM as Q
from ..errors import ParameterError
from ..validation import regular_input
from .assembly import MAX_STRAIN, PLANES, Material, assemble
from .body import read_body
from .config_solid import dimension_of, read_mesh, reduced_of, rollers_of, solid_materials, units_of
from .solid import assemble_solid, read_solid
from .orthotropic import Orthotropic
from .pair import PairProblem, Rotation, Translation, mortar, sliding
from .boundary import LIMIT, Load, Spring
from .checks import (group_list as _group_list, mesh_file as _mesh_file, number as _number, pair as _pair,
                     problem_text as _problem, toml as _toml, vector as _vector)
from .scheme import ContactProblem
from .surfaces import MAX_SPEED, RigidCylinder, RigidFlat, contact_frames

__all__ = ["FemConfig", "Partner", "load_config", "numeric_keys", "read_toml", "resolve_key"]

_KNOWN = {"": {"mesh", "clamped", "material", "contact", "surface", "partner", "cea", "spring", "load", "dimension",
               "units", "rollers"},
          "partner": {"mesh", "group", "clamped", "omega", "center", "velocity", "material", "gyroscopic", "rollers",
                      "transverse_damping", "prestress"},
          "contact": {"group", "friction", "static_friction", "law", "stribeck_speed", "weakening", "pressure_exponent",
                      "reference_pressure"},
          "surface": {"kind", "radius", "omega", "center", "body_inside", "point", "normal", "velocity",
                      "interference"},
          "cea": {"band", "count", "complete_below", "mass_matrix", "contact_model", "penalty", "reduced_modes",
                  "augment"}}
_MATERIAL = {"young", "poisson", "density", "plane", "alpha", "beta", "loss_factor"}
#: The keys of an orthotropic material (`stickslip.fem.orthotropic.Orthotropic`), instead of young and poisson.
_ORTHOTROPIC = {"e1", "e2", "e3", "nu12", "nu13", "nu23", "g12", "angle"}


@dataclass(frozen=True)
class Partner:
    """The ``[partner]`` of a config: an elastic counter-body and its motion."""

    mesh: Path
    group: str
    clamped: tuple
    motion: object
    material: Material | dict
    body: object = field(default=None, repr=False, compare=False)
    gyroscopic: bool = False
    rollers: dict = field(default_factory=dict)  # {face or boundary group: axes}
    transverse_damping: bool = False  # solids: the CEA's damping of the friction turning with a slip across
    prestress: bool = False  # a turning solid: the stress stiffening of its centrifugal prestress


@dataclass(frozen=True)
class FemConfig:
    """A validated config (see the module docstring); ``path`` is the config file."""

    path: Path
    mesh: Path
    clamped: tuple
    material: Material | dict  # one for the whole body, or {cell group: Material}
    group: str
    friction: float
    surface: object
    band: tuple
    count: int
    static_friction: float | None = None
    springs: tuple = ()
    loads: tuple = ()
    body: object = field(default=None, repr=False, compare=False)  # the mesh as read while checking
    complete_below: float | None = None  # [cea] complete_below [1/s] (None: the default of complex_eigenvalues)
    law: object = None  # a friction law of stickslip.friction ([contact] law), or None: Coulomb
    partner: Partner | None = None  # an elastic counter-body ([partner]) instead of the surface
    cea_options: dict = field(default_factory=dict)  # [cea] mass_matrix, contact_model, penalty (as given)
    pressure_law: object = None  # a stickslip.friction.PressurePower ([contact] pressure_exponent), or None
    dimension: int = 2  # 2: plane bodies; 3: solids (stickslip.fem.config_solid)
    units: str | None = None  # the length unit of a 3-D config's meshes
    rollers: dict = field(default_factory=dict)  # {group: axes} of the body (a pair's slave)
    reduced: dict | None = None  # [cea] reduced_modes and augment: the reduced CEA (stickslip.fem.reduced)

    def problem(self) -> ContactProblem | PairProblem:
        """Assemble the body and set the contact up (the mesh is read again if not kept); with a
        ``[partner]``, both bodies and their mortar contact."""
        read = read_body if self.dimension == 2 else lambda path: read_solid(path, self.units)
        body = self.body if self.body is not None else read(self.mesh)
        if self.partner is not None:
            p = self.partner
            other = p.body if p.body is not None else read(p.mesh)
            friction = {"law": self.law} if self.law is not None else {"friction": self.friction,
                                                                         "static_friction": self.static_friction}
            slave, master = ((assemble(body, self.material, self.springs, self.loads), assemble(other, p.material))
                             if self.dimension == 2 else (assemble_solid(body, self.material, self.loads, self.springs),
                                                          assemble_solid(other, p.material)))
            return PairProblem(slave, self.group, master, p.group, p.motion, clamped_slave=self.clamped,
                               clamped_master=p.clamped, gyroscopic=p.gyroscopic, pressure_law=self.pressure_law,
                               transverse_damping=p.transverse_damping, prestress=p.prestress,
                               rollers_slave=self.rollers or None, rollers_master=p.rollers or None, **friction)
        for name in (*self.clamped, self.group):
            body.group(name, "clamped" if name in self.clamped else "contact.group")
        frames = contact_frames(body, self.group, self.surface)
        system = assemble(body, self.material, self.springs, self.loads)
        if self.law is not None:
            return ContactProblem(system, frames, clamped=self.clamped, law=self.law, pressure_law=self.pressure_law)
        return ContactProblem(system, frames, self.friction, self.clamped, self.static_friction,
                              pressure_law=self.pressure_law)


def load_config(path, overrides=None) -> FemConfig:
    """Read and check a config; every problem found goes into one `ParameterError`.
    ``overrides``: ``{key: number}`` replacing numbers of the file before the checks, keys as
    `numeric_keys` names them (``contact.friction``, ``material[1].young``, ``load[0].pressure``)."""
    path = Path(path)
    data = read_toml(path)
    if overrides:
        data = _with(data, overrides)
    return _checked(path, data)


def read_toml(path) -> dict:
    """The TOML of a config file, or one `ParameterError` naming it."""
    path = regular_input("config", path, "a readable TOML file")
    try:
        return tomllib.loads(path.read_text(encoding="utf-8"))
    except OSError as err:
        raise ParameterError("config", str(path), f"a readable TOML file ({err.strerror})") from None
    except UnicodeDecodeError as err:
        raise ParameterError("config", str(path), f"a TOML file in UTF-8 (byte {err.start} is not: {err.reason})") \
            from None
    except tomllib.TOMLDecodeError as err:
        raise ParameterError("config", str(path), f"a valid TOML file ({err})") from None
    except RecursionError:
        raise ParameterError("config", str(path), "a TOML file without deeply nested arrays or tables (a config "
                             "nests two levels)") from None


#: One table of a key's path: ``material``, or ``material[1]`` (an entry of an array of tables).
_TABLE = re.compile(r"^([a-z_]+)(?:\[(\d+)\])?$")


def numeric_keys(data: dict) -> list[str]:
    """The keys of a config (its TOML ``data``) that hold one number and may be swept: those
    written, and the contact's coefficients (default 0)."""
    out = ["contact.friction", "contact.static_friction"]

    def tables(name, value):
        """``(path, table)`` of a table or of each entry of an array of tables."""
        if isinstance(value, dict):
            return [(name, value)]
        return [(f"{name}[{i}]", t) for i, t in enumerate(value) if isinstance(t, dict)] \
            if isinstance(value, list) else []

    def walk(where, table, nested):
        for key, x in table.items():
            if nested and isinstance(x, (dict, list)):  # a table within a section: [partner.material]
                for inner, t in tables(f"{where}.{key}", x):
                    walk(inner, t, False)
                continue
            q = Q.get(key)
            if q is not None and q.range is not None and not q.choices and isinstance(x, (int, float)) and \
                    not isinstance(x, bool) and f"{where}.{key}" not in out:
                out.append(f"{where}.{key}")

    for section, value in data.items():
        if section == "cea":  # how the modes are searched for, not the problem
            continue
        for where, table in tables(section, value):
            walk(where, table, True)
    return out


def resolve_key(data: dict, name: str, option: str = "key") -> str:
    """The full key (`numeric_keys`) that ``name`` means: itself, or the one key it ends
    (``friction`` -> ``contact.friction``, ``young`` -> ``material.young`` on one material; the
    body's key before a partner's, which is named in full: ``partner.material.young``)."""
    keys = numeric_keys(data)
    if name in keys:
        return name
    found = [k for k in keys if k.split(".")[-1] == name]
    own = [k for k in found if not k.startswith("partner.")]  # a short name is the body's; the partner's in full
    if len(found) == 1 or len(own) == 1:
        return found[0] if len(found) == 1 else own[0]
    raise ParameterError(option, name, f"a key of the config holding one number ({', '.join(keys)})"
                         + (f"; {name!r} is more than one of them: name it in full" if found else ""))


def _with(data: dict, overrides) -> dict:
    """``data`` with the numbers of ``overrides`` in place (a copy)."""
    import copy

    data = copy.deepcopy(data)
    keys = numeric_keys(data)
    for key, value in dict(overrides).items():
        if key not in keys:
            raise ParameterError("key", key, f"a key of the config holding one number ({', '.join(keys)})")
        *path, name = str(key).split(".")
        table = data
        for part in path:  # numeric_keys wrote the path: each part a table, or an entry of an array of them
            section, index = _TABLE.match(part).groups()
            table = table.setdefault(section, {})
            table = table[int(index)] if index is not None else table
        table[name] = value
    return data


def _checked(path: Path, data: dict) -> FemConfig:
    problems: list[str] = []
    for section, keys in _KNOWN.items():
        table = data if not section else data.get(section, {})
        if not isinstance(table, dict):
            problems.append(f"[{section}] must be a table")
            continue
        extra = sorted(k for k in table if k not in keys and not (section == "" and k in _KNOWN))
        problems += [f"unknown key {'' if not section else section + '.'}{k}" for k in extra]
    dimension = dimension_of(problems, data)
    units = units_of(problems, data, dimension)
    mesh_path = _mesh_file(problems, path, data.get("mesh"), "mesh")
    clamped = _group_list(problems, data.get("clamped", []), "clamped")
    rollers = rollers_of(problems, data.get("rollers"), "rollers", dimension)
    materials = _materials(problems, data.get("material"), "material", dimension)
    young = _stiffest(data.get("material"))
    c = data.get("contact", {}) if isinstance(data.get("contact", {}), dict) else {}
    group = c.get("group")
    if not isinstance(group, str):
        problems.append("contact.group must be the name of a boundary group")
    friction = _number(problems, "contact.friction", c.get("friction", 0.0))
    static = c.get("static_friction")
    if static is not None:
        static = _number(problems, "contact.static_friction", static)
        if None not in (static, friction) and static < friction:
            problems.append(f"contact.static_friction = {static!r} must be >= contact.friction = {friction!r}")
            static = None
    law = _law(problems, c, friction, static)
    pressure_law = _pressure_law(problems, c)
    springs = _springs(problems, data.get("spring", []), dimension)
    loads = _loads(problems, data.get("load", []), dimension)
    partner = None
    if dimension == 3 and "partner" not in data:
        problems.append("[partner] is missing: a config of solids needs its elastic counter-body (a rigid "
                        "[surface] for solids comes in a later release: give the disc as a [partner])")
        surface = None
    elif "partner" in data:
        if "surface" in data:
            problems.append("[surface] and [partner] exclude each other (a rigid counter-surface or an elastic "
                            "counter-body)")
        partner = _partner(problems, path, data["partner"] if isinstance(data["partner"], dict) else {}, dimension,
                           units)
        surface = None
    else:
        surface = _surface(problems, data.get("surface", {}) if isinstance(data.get("surface", {}), dict) else {},
                           friction, "surface" in data)
    e = data.get("cea", {}) if isinstance(data.get("cea", {}), dict) else {}
    band = _pair(problems, "cea.band", e.get("band", [0.0, 1e4]))
    if band is not None and not band[0] < band[1]:
        problems.append(f"cea.band = {list(band)!r} must be [lo, hi] in Hz with lo < hi")
    band = band if band is not None and band[0] < band[1] else (0.0, 1.0)
    count = e.get("count", 30)
    if not isinstance(count, int):  # 30.0 is not a count in TOML
        problems.append(f"cea.count = {_toml(count)} must be {Q['count'].allowed}")
    else:
        count = _number(problems, "cea.count", count)
    below = e.get("complete_below")
    if below is not None:
        below = _number(problems, "cea.complete_below", below)
    options = {}
    for key in ("mass_matrix", "contact_model"):
        if key in e:
            try:
                options[key] = Q.check(key, e[key], f"cea.{key}")
            except ParameterError as err:
                problems.append(_problem(err))
    reduced = reduced_of(problems, e, options)
    if reduced is not None and partner is None and "partner" not in data:
        problems.append("cea.reduced_modes applies to a pair of bodies ([partner]; the reduced CEA of a body on a "
                        "rigid surface comes in a later release)")
    if "penalty" in e:
        options["penalty"] = _number(problems, "cea.penalty", e["penalty"])
        if options.get("contact_model") != "penalty" and reduced is None:
            problems.append('cea.penalty applies with cea.contact_model = "penalty" only (or cea.reduced_modes)')
    if rollers and "partner" not in data:
        problems.append("rollers apply to a pair of bodies ([partner]); a body on a rigid surface is held by clamped "
                        "and springs")
    if young is not None:
        big = MAX_STRAIN * young
        problems += [f"load[{i}].pressure = {x.pressure!r} must be at most {MAX_STRAIN:g} x material.young = {big:.4g} "
                     "Pa in size (linear elasticity holds for small strains)" for i, x in enumerate(loads)
                     if abs(x.pressure) > big]
        problems += [f"load[{i}].traction = {list(x.traction)!r} must be at most {MAX_STRAIN:g} x material.young = "
                     f"{big:.4g} Pa in size (linear elasticity holds for small strains)" for i, x in enumerate(loads)
                     if max(map(abs, x.traction)) > big]
    body = None if mesh_path is None else read_mesh(problems, mesh_path, "mesh", dimension, units)
    if body is not None:
        _body(problems, body, mesh_path, clamped, group, data, surface, rollers)
    if body is not None:
        _cell_groups(problems, body, materials)
    if partner is not None and body is not None and partner.body is not None and isinstance(group, str) \
            and group in body.groups:
        _facing(problems, body, group, partner, friction)
    if problems:
        raise ParameterError("config", str(path), f"a valid config; {len(problems)} problem"
                             f"{'s' if len(problems) > 1 else ''}: " + "; ".join(problems))
    material = materials[""] if list(materials) == [""] else materials
    return FemConfig(path, mesh_path, tuple(clamped), material, group, friction, surface, tuple(band), count,
                     static, springs, loads, body, below, law, partner, options, pressure_law, dimension, units,
                     rollers, reduced)


def _partner(problems, path: Path, p: dict, dimension: int = 2, units: str | None = None) -> Partner | None:
    """The ``[partner]`` table: its mesh (read), group, clamps, motion and materials."""
    group = p.get("group")
    mesh_path = _mesh_file(problems, path, p.get("mesh"), "partner.mesh")
    if not isinstance(group, str):
        problems.append("partner.group must be the name of a boundary group of partner.mesh")
    clamped = _group_list(problems, p.get("clamped", []), "partner.clamped")
    motion = None
    if ("omega" in p) == ("velocity" in p):
        problems.append("partner: give omega (it turns about center) or velocity (it translates), one of them")
    elif "omega" in p:
        omega, center = _number(problems, "partner.omega", p["omega"]), _pair(problems, "partner.center",
                                                                              p.get("center", [0.0, 0.0]))
        motion = None if None in (omega, center) else Rotation(omega, center)
    else:
        velocity = _pair(problems, "partner.velocity", p["velocity"])
        motion = None if velocity is None else Translation(velocity)
        if "center" in p:
            problems.append("partner.center applies with partner.omega only (a translating partner has no centre)")
    materials = _materials(problems, p.get("material"), "partner.material", dimension)
    rollers = rollers_of(problems, p.get("rollers"), "partner.rollers", dimension)
    gyroscopic = p.get("gyroscopic", False)
    if not isinstance(gyroscopic, bool) or (gyroscopic and "omega" not in p):
        problems.append(f"partner.gyroscopic = {_toml(gyroscopic)} must be true or false, true only with "
                        "partner.omega (a turning partner)")
        gyroscopic = False
    transverse = p.get("transverse_damping", False)
    if not isinstance(transverse, bool) or (transverse and dimension != 3):
        problems.append(f"partner.transverse_damping = {_toml(transverse)} must be true or false, true only in a "
                        "config of solids (dimension = 3)")
        transverse = False
    prestress = p.get("prestress", False)
    if not isinstance(prestress, bool) or (prestress and (dimension != 3 or "omega" not in p)):
        problems.append(f"partner.prestress = {_toml(prestress)} must be true or false, true only with a turning "
                        "partner (partner.omega) in a config of solids (dimension = 3)")
        prestress = False
    body = None if mesh_path is None else read_mesh(problems, mesh_path, "partner.mesh", dimension, units)
    if body is not None:
        have = ", ".join(sorted(body.groups)) or "none"
        problems += [f"{where} = {name!r} is not a boundary group of {mesh_path.name} (it has: {have})"
                     for where, name in [("partner.group", group)] + [(f"partner.clamped[{i}]", c)
                                                                      for i, c in enumerate(clamped)]
                     + [(f"partner.rollers.{r}", r) for r in rollers]
                     if isinstance(name, str) and name not in body.groups]
        _cell_groups(problems, body, materials, "partner.material")
        if isinstance(motion, Rotation):  # a disc turns about its own axis: a centre far off is a unit slip
            xy = np.asarray(body.points)[:, :2]
            lo, hi = xy.min(axis=0), xy.max(axis=0)
            size = float(np.max(hi - lo))
            off = np.maximum(np.maximum(lo - np.asarray(motion.center), np.asarray(motion.center) - hi), 0.0)
            if float(np.hypot(*off)) > size:
                problems.append(f"partner.center = {list(motion.center)} must be within the partner's size "
                                f"({size:.4g} m) of its mesh, which spans x {lo[0]:.4g} to {hi[0]:.4g} m and y "
                                f"{lo[1]:.4g} to {hi[1]:.4g} m (the centre is in metres: units apply to the mesh "
                                "files only)")
    if None in (motion, body) or not materials or not isinstance(group, str) or group not in body.groups \
            or any(m is None for m in materials.values()):
        return None
    return Partner(mesh_path, group, tuple(clamped), motion, materials[""] if list(materials) == [""] else materials,
                   body, gyroscopic, rollers, transverse, prestress)


def _facing(problems, body, group: str, partner: Partner, friction) -> None:
    """The contact group and the partner's group face each other within reach, and the partner's
    motion slides along the contact."""
    try:
        coupling = mortar(body, group, partner.body, partner.group)
        sliding(coupling, partner.motion, body.points, required=bool(friction))
        coupling.check_interference(body.points, partner.body.points, group)
    except ParameterError as err:
        where = {"slave_group": "contact.group", "master_group": "partner.group", "motion": "partner motion"}
        problems.append(f"{where.get(err.name, err.name)} = {_toml(err.value) if err.name != 'motion' else ''} must "
                        f"be {err.allowed}".replace(" =  must", " must"))


def _law(problems, c: dict, friction, static):
    """The friction law of ``[contact] law`` (None without one): ``friction`` is its kinetic
    coefficient f_d, ``static_friction`` its static one f_s (required), ``stribeck_speed`` or
    ``weakening`` its own parameter."""
    from ..friction import make_law

    name = c.get("law")
    extra = [k for k in ("stribeck_speed", "weakening") if k in c]
    if name is None:
        problems += [f"contact.{k} needs contact.law (stribeck or linear-weakening)" for k in extra]
        return None
    choices = Q["law"].choices
    if name not in choices:
        problems.append(f"contact.law = {_toml(name)} must be one of {', '.join(choices)}")
        return None
    needs = {"coulomb": None, "linear-weakening": "weakening", "stribeck": "stribeck_speed"}[name]
    problems += [f"contact.{k} must be left out with contact.law = {name!r}" for k in extra if k != needs]
    if c.get("static_friction") is None:
        problems.append(f"contact.static_friction is missing (the static coefficient f_s of contact.law = {name!r})")
    value = None
    if needs is not None:
        value = _number(problems, f"contact.{needs}", c.get(needs))
    if None in (friction, static) or (needs is not None and value is None):
        return None
    return make_law(name, fs=static, fd=friction, **({"vs": value} if needs == "stribeck_speed" else
                                                     {"tau": value} if needs == "weakening" else {}))


def _pressure_law(problems, c: dict):
    """``[contact] pressure_exponent`` and ``reference_pressure`` (both or neither) as a
    `stickslip.friction.PressurePower`, or None."""
    from ..friction import PressurePower

    given = [k for k in ("pressure_exponent", "reference_pressure") if k in c]
    if not given:
        return None
    if len(given) == 1:
        other = ({"pressure_exponent", "reference_pressure"} - set(given)).pop()
        problems.append(f"contact.{other} is missing (contact.{given[0]} needs it)")
        return None
    n = _number(problems, "contact.pressure_exponent", c["pressure_exponent"])
    reference = _number(problems, "contact.reference_pressure", c["reference_pressure"])
    return None if None in (n, reference) else PressurePower(reference, n)


def _materials(problems, raw, key: str = "material", dimension: int = 2) -> dict:
    """``{cell group: Material or Orthotropic}`` of ``[material]`` (the whole body, group "") or of
    ``[[material]]`` tables, each with its ``group`` (None for a table with a problem); problems
    named as written (``material.young``, ``material[1].young``). A table with ``e1`` is
    orthotropic (`stickslip.fem.orthotropic.Orthotropic`: ``e1, e2, nu12, g12``, ``angle``, and
    ``e3, nu13, nu23`` in plane strain) instead of ``young`` and ``poisson``."""
    if raw is None:
        raw = {}
    if isinstance(raw, dict):
        tables = [(key, raw)]
        if "group" in raw:
            problems.append(f"{key}.group: a single [{key}] is the whole body; one per cell group is written "
                            f"[[{key}]], a table for each group")
    elif isinstance(raw, list) and raw and all(isinstance(t, dict) for t in raw):
        tables = [(f"{key}[{i}]", t) for i, t in enumerate(raw)]
    else:
        problems.append(f"{key} must be a table [{key}] (the whole body) or tables [[{key}]] with a group "
                        "each")
        return {}
    if dimension == 3:
        return solid_materials(problems, tables, key)
    out = {}
    for where, m in tables:
        ortho = "e1" in m
        allowed = (_MATERIAL - {"young", "poisson"} | _ORTHOTROPIC) if ortho else _MATERIAL
        problems += [f"unknown key {where}.{k}" + (" (an orthotropic material, with e1, takes e1, e2, nu12, g12 "
                                                   "instead of young and poisson)" if ortho and k in _MATERIAL else "")
                     for k in sorted(m) if k not in allowed | ({"group"} if "[" in where else set())]
        name = ""
        if "[" in where:
            name = m.get("group")
            if not isinstance(name, str) or not name:
                problems.append(f"{where}.group must be the name of a cell group of the mesh")
                continue
            if name in out:
                problems.append(f"{where}.group = {name!r} must name each cell group once ({name!r} has a material "
                                "already)")
                continue
        plane = m.get("plane", "strain")
        if plane not in PLANES:
            problems.append(f"{where}.plane = {_toml(plane)} must be one of {', '.join(PLANES)}")
        common = {"density": _number(problems, f"{where}.density", m.get("density")), "plane": plane,
                  "alpha": _number(problems, f"{where}.alpha", m.get("alpha", 0.0)),
                  "beta": _number(problems, f"{where}.beta", m.get("beta", 0.0)),
                  "loss_factor": _number(problems, f"{where}.loss_factor", m.get("loss_factor", 0.0))}
        if ortho:
            given = {k: _number(problems, f"{where}.{k}", m.get(k)) for k in ("e1", "e2", "nu12", "g12")}
            given["angle"] = _number(problems, f"{where}.angle", m.get("angle", 0.0))
            given.update({k: _number(problems, f"{where}.{k}", m[k]) for k in ("e3", "nu13", "nu23") if k in m})
            if plane == "strain":
                problems += [f"{where}.{k} is missing (an orthotropic material in plane strain needs e3, nu13, nu23)"
                             for k in ("e3", "nu13", "nu23") if k not in m]
            kind, args = Orthotropic, {**given, **common}
        else:
            kind, args = Material, {"young": _number(problems, f"{where}.young", m.get("young")),
                                    "poisson": _number(problems, f"{where}.poisson", m.get("poisson")), **common}
        out[name] = None
        if plane in PLANES and all(v is not None for v in args.values()):
            try:
                out[name] = kind(**args)
            except ParameterError as err:
                problems.append(f"{where}.{err.name} = {_toml(err.value)} must be {err.allowed}")
    planes = {v.plane for v in out.values() if v is not None}
    if len(planes) > 1:
        problems.append(f"{key}.plane must be the same for every material (they have {', '.join(sorted(planes))})")
    return out


def _stiffest(raw):
    """The largest valid modulus (``young``, ``e1``, ``e2``, ``e3``) written in the material
    tables, None without one: the scale the loads are checked against, even when another key
    of a table has a problem."""
    tables = [raw] if isinstance(raw, dict) else raw if isinstance(raw, list) else []
    found = []
    for t in (t for t in tables if isinstance(t, dict)):
        for k in ("young", "e1", "e2", "e3"):
            try:
                found.append(Q[k].check(t[k], k))
            except (KeyError, ParameterError):
                pass
    return max(found, default=None)


def _cell_groups(problems, body, materials: dict, key: str = "material") -> None:
    """Every cell group of the mesh with a material and every material on a cell group of it."""
    names = [k for k in materials if k]
    if not names:
        return
    have = ", ".join(sorted(body.cell_groups)) or "none"
    problems += [f"{key}[{i}].group = {name!r} is not a cell group of {Path(str(body.source)).name} (it has: "
                 f"{have})" for i, name in enumerate(names) if name not in body.cell_groups]
    problems += [f"{key}: the cell group {name!r} of {Path(str(body.source)).name} has none (every cell group "
                 f"needs its [[{key}]], or one [{key}] for the whole body)" for name in sorted(body.cell_groups)
                 if name not in materials]
    owner = np.full(len(body.cells), -1)
    for i, name in enumerate(names):
        cells = body.cell_groups.get(name, np.zeros(0, dtype=np.int64))
        twice = cells[owner[cells] >= 0]
        if twice.size:
            problems.append(f"{key}[{i}].group = {name!r} shares {twice.size} cells with "
                            f"{names[int(owner[twice[0]])]!r}: a cell has one material")
        owner[cells] = i
    if all(name in body.cell_groups for name in names) and np.any(owner < 0):
        problems.append(f"{key}: {int(np.sum(owner < 0))} cells of {Path(str(body.source)).name} are in no cell "
                        f"group with a material ({have})")


def _body(problems, body, mesh_path, clamped, group, data, surface, rollers=None) -> None:
    """Every group name checked against the mesh read, and the surface against the contact group (so
    that these problems join the others in one message)."""
    have = ", ".join(sorted(body.groups)) or "none"
    named = [(f"clamped[{i}]", name) for i, name in enumerate(clamped)] + [("contact.group", group)]
    named += [(f"rollers.{name}", name) for name in rollers or {}]
    named += [(f"{kind}[{i}].group", t["group"]) for kind in ("spring", "load")
              for i, t in enumerate(data.get(kind, []) if isinstance(data.get(kind, []), list) else [])
              if isinstance(t, dict) and isinstance(t.get("group"), str)]
    if isinstance(group, str) and group in clamped:
        problems.append(f"clamped = {clamped!r} must not hold the contact group {group!r} (a clamped node is held "
                        "by the clamp, not the contact)")
    held = {int(i) for name in clamped if name in body.groups for i in body.nodes(name)}
    problems += [f"{where} = {name!r}: every node of it is clamped (clamped = {clamped!r}), so the "
                 f"{where.split('[')[0]} would act on nothing" for where, name in named[len(clamped) + 1:]
                 if name in body.groups and set(body.nodes(name).tolist()) <= held]
    missing = [(where, name) for where, name in named if isinstance(name, str) and name not in body.groups]
    problems += [f"{where} = {name!r} is not a boundary group of {mesh_path.name} (it has: {have})"
                 for where, name in missing]
    push = data.get("surface", {}).get("interference", 0.0) if isinstance(data.get("surface"), dict) else 0.0
    if isinstance(group, str) and group in body.groups and not _interference(problems, body, group, push):
        return
    if surface is not None and isinstance(group, str) and group in body.groups:
        try:
            contact_frames(body, group, surface)
        except ParameterError as err:
            where = "surface" if err.name == "surface" else f"surface.{err.name} = {_toml(err.value)}"
            problems.append(f"{where} must be {err.allowed}")


def _made(problems, kind, *args):
    """The surface, or None with its refusal among the problems (named as the config names it)."""
    try:
        return kind(*args)
    except ParameterError as err:
        problems.append(f"surface.{err.name} = {_toml(err.value)} must be {err.allowed} (with the interference "
                        "applied)")
        return None


#: The largest interference over the contact group's length: a strain scale, as for the loads.
MAX_INTERFERENCE = 0.1


def _narrowest(points: np.ndarray) -> float:
    """The body's width at its narrowest: the least extent of its points over 180 directions."""
    angles = np.linspace(0.0, np.pi, 180, endpoint=False)
    return float(np.ptp(points @ np.array([np.cos(angles), np.sin(angles)]), axis=0).min())


def _interference(problems, body, group, push) -> bool:
    """An interference of at most `MAX_INTERFERENCE` times the contact group's length in size, and
    of at most `MAX_STRAIN` (the loads' bound, `stickslip.fem.assembly`) times the body's narrowest
    width: a strain that linear elasticity describes (a pad pushed 2 mm into its 8 mm lining ran at
    1.5 GPa without a word)."""
    if not isinstance(push, (int, float)) or isinstance(push, bool) or not math.isfinite(push) \
            or push not in Q["interference"].range or push == 0:
        return True  # (refused as a number already, or nothing pushed)
    points = body.points[body.nodes(group)]
    length = float(np.ptp(points, axis=0).max()) if len(points) > 1 else 0.0
    if abs(push) > MAX_INTERFERENCE * length:
        problems.append(f"surface.interference = {push!r} must be at most {MAX_INTERFERENCE:g} x the length of the "
                        f"contact group {group!r} ({length:.4g} m) in size: {Q['interference'].why}")
        return False
    width = _narrowest(body.points)
    if abs(push) > MAX_STRAIN * width:
        problems.append(f"surface.interference = {push!r} implies a strain of about {abs(push) / width:.2g} across the "
                        f"body ({width:.4g} m wide at its narrowest): at most {MAX_STRAIN:g} x that width, "
                        f"{MAX_STRAIN * width:.4g} m (linear elasticity is a model of small strains)")
        return False
    return True


def _tables(problems, name, value, keys):
    if not (isinstance(value, list) and all(isinstance(t, dict) for t in value)):
        problems.append(f"{name} must be written [[{name}]] (a list of tables)")
        return []
    for i, table in enumerate(value):
        problems += [f"unknown key {name}[{i}].{k}" for k in sorted(table) if k not in keys]
        if not isinstance(table.get("group"), str):
            problems.append(f"{name}[{i}].group must be the name of a boundary group")
    return [(f"{name}[{i}]", t) for i, t in enumerate(value) if isinstance(t.get("group"), str)]


def _springs(problems, value, dimension: int = 2):
    out = []
    for where, t in _tables(problems, "spring", value, {"group", "stiffness"}):
        k = _vector(problems, f"{where}.stiffness", t.get("stiffness"), dimension)
        if k is not None and max(k) == 0:
            problems.append(f"{where}.stiffness = {list(k)!r} must be {dimension} numbers in [0, {LIMIT:g}], not all "
                            "zero")
        elif k is not None:
            out.append(Spring(t["group"], k))
    return tuple(out)


def _loads(problems, value, dimension: int = 2):
    out = []
    for where, t in _tables(problems, "load", value, {"group", "pressure", "traction"}):
        p = _number(problems, f"{where}.pressure", t.get("pressure", 0.0))
        q = _vector(problems, f"{where}.traction", t.get("traction", [0.0] * dimension), dimension)
        if None not in (p, q):
            out.append(Load(t["group"], p, q))
    return tuple(out)


_SURFACE_KEYS = {"cylinder": {"radius", "omega", "center", "body_inside"}, "flat": {"point", "normal", "velocity"}}


def _surface(problems, s, friction, given=True):
    kind = s.get("kind")
    if not given:
        problems.append('[surface] is missing (the rigid counter-surface: kind = "cylinder" or "flat")')
        return None
    if kind in _SURFACE_KEYS:
        other = "flat" if kind == "cylinder" else "cylinder"
        problems += [f"surface.{k} does not apply to kind = {kind!r} (it belongs to {other!r})"
                     for k in sorted(_SURFACE_KEYS[other] & set(s))]
    rubs = friction is not None and friction > 0  # a surface at rest gives friction no direction
    push = _number(problems, "surface.interference", s.get("interference", 0.0))
    if kind == "cylinder":
        radius = _number(problems, "surface.radius", s.get("radius"))
        omega = _number(problems, "surface.omega", s.get("omega"))
        center = _pair(problems, "surface.center", s.get("center", [0.0, 0.0]))
        inside = s.get("body_inside", False)
        if not isinstance(inside, bool):
            problems.append(f"surface.body_inside = {inside!r} must be true or false")
        if rubs and omega == 0:
            problems.append("surface.omega = 0.0 must be non-zero when contact.friction > 0 (a surface at rest "
                            "gives friction no sliding direction)")
            return None
        if None in (radius, omega, center, push) or not isinstance(inside, bool):
            return None
        if abs(omega) * radius > MAX_SPEED:
            problems.append(f"surface.omega = {omega!r} must be at most {MAX_SPEED / radius:.4g} rad/s in size "
                            f"(the surface at most {MAX_SPEED:g} m/s)")
            return None
        radius = radius - push if inside else radius + push  # pushed into the body
        if radius <= 0:
            problems.append("surface.interference leaves the cylinder no radius")
            return None
        return _made(problems, RigidCylinder, radius, omega, center, inside)
    if kind == "flat":
        point = _pair(problems, "surface.point", s.get("point"))
        normal = _pair(problems, "surface.normal", s.get("normal"))
        velocity = _pair(problems, "surface.velocity", s.get("velocity"))
        if None in (point, normal, velocity, push):
            return None
        if math.hypot(*velocity) > MAX_SPEED:  # each component is declared, the speed too
            problems.append(f"surface.velocity = {list(velocity)!r} must be at most {MAX_SPEED:g} m/s in size")
            return None
        if rubs and velocity == (0.0, 0.0):
            problems.append("surface.velocity = [0.0, 0.0] must be non-zero when contact.friction > 0 (a surface "
                            "at rest gives friction no sliding direction)")
            return None
        size = math.hypot(*normal)
        if size == 0:
            problems.append("surface.normal must not be zero")
            return None
        if abs(normal[0] * velocity[0] + normal[1] * velocity[1]) > 1e-12 * size * max(1.0, math.hypot(*velocity)):
            problems.append("surface.velocity must lie along the flat (no component along its normal)")
            return None
        shifted = (point[0] + push * normal[0] / size, point[1] + push * normal[1] / size)
        return _made(problems, RigidFlat, shifted, normal, velocity)
    problems.append('surface.kind is missing ("cylinder" or "flat")' if kind is None
                    else f'surface.kind = {kind!r} must be "cylinder" or "flat"')
    return None
