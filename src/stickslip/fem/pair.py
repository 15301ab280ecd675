"""Two deformable bodies in frictional contact: a pad on a disc (steady sliding and the CEA;
their explicit runs: `stickslip.fem.pair_run`).

**Mortar coupling.** The contact is discretised segment to segment (mortar), with one
Lagrange multiplier ``lambda_j`` [Pa] per node ``j`` of the *slave* group (the pad's face),
interpolated along the slave segments by the dual shape functions ``phi_j`` (on a segment
``phi_a = 2 - 3 eta``, ``phi_b = 3 eta - 1``: ``int phi_j N_k = delta_jk int N_j``). With ``N_k``
the slave's and ``N_l`` the master's linear shape functions on their boundary, the master's
mapped onto each slave segment by projection along the segment's normal,

    D_jk = int phi_j N_k ds = delta_jk int N_j ds,     M_jl = int phi_j N_l ds     (slave line),

computed exactly (the overlap of every pair of segments, 2-point Gauss: the integrands are
quadratic). Quadratic cells (curved 3-node segments, on either side) have quadratic dual
multipliers and their own integration (`stickslip.fem.mortar2`). Why mortar and not
node-to-segment: a uniform pressure passes a non-matching interface exactly (the contact
patch test), which one-pass node-to-segment fails. Why dual
multipliers: ``D`` is diagonal, so the contact conditions are node by node (``D_jj lambda_j``
is the node's normal force) as the rigid-surface contact's are, and a stiff partner gives
exactly its active sets (standard multipliers oscillate at the line's ends and lift a
corner the rigid surface holds).

At slave node ``j`` with the nodal normal ``n_j`` (pointing from the master into the slave)
and the tangent ``t_j`` along which the master's surface moves there, the weighted normal gap
and slip are

    g_j(u) = sum_k D_jk n_j . (x_k + u_k) - sum_l M_jl n_j . (x_l + u_l),    (G u)_j, (T u)_j alike,

Signorini reads ``lambda_j >= 0``, ``g_j >= 0``, ``lambda_j g_j = 0``, and in sliding the
slave is dragged along ``t_j`` by ``f lambda_j``: the contact force on both bodies is
``(G + f T)^T lambda`` (slave nodes ``D^T``, master nodes ``-M^T``: action equals reaction).

**Steady sliding** solves ``K u - F = (G + f T)_A^T lambda_A``, ``G_A u = -g_A(0)`` for the active
slave nodes ``A``, the set updated as in `stickslip.fem.static` (tension leaves, penetration
joins). **The CEA** keeps the active constraints (``G_A u = 0`` for the perturbation) and the
multipliers as unknowns without mass: ``(s^2 M + s C + K) u = B^T lambda``, ``G_A u = 0``,
``B = (G + f T)_A``. By default the master's motion enters only through the sliding direction
(the usual engineering treatment of a turning disc). With ``gyroscopic=True`` a turning master
is described in space-fixed (Eulerian) coordinates: its gyroscopic matrix joins the damping
and its transport softening the stiffness (`stickslip.fem.assembly.transport_operators`),
in steady sliding and the CEA; with ``prestress=True`` (solids) the stress stiffening of the
centrifugal prestress too (`stickslip.fem.prestress`).

**Friction laws.** Coulomb ``friction`` (and a ``static_friction`` for explicit runs), or a law of
the slip speed (`stickslip.friction`), each slave node's coefficient ``mu_j = mu(V_j)`` at the
master's sliding speed there: ``B = G + diag(mu) T``; the CEA adds the damping
``T^T diag(lambda g mu'(V) / w) T`` of the relative tangential velocity ``(T u')_j / w_j`` (a
falling law is negative damping); and a coefficient that depends on the pressure
(``pressure_law``, `stickslip.friction.PressurePower`): ``mu_j g(lambda_j)``, found by fixed-point
iteration in steady sliding, ``mu_j g_j (1 - n)`` in the CEA's friction rows.
"""

from __future__ import annotations

import hashlib
import logging
import math
from dataclasses import dataclass, field
from functools import cached_property
from pathlib import Path
from typing import ClassVar

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as sla
import lazy_loader as lazy

from .. import validation as check
from ..cf import finish
from ..errors import NoSolutionError, ParameterError
from ..friction import FrictionLaw, PressurePower
from ..quantities import FEM as Q
from ..results import Result
from .assembly import BodySystem, transport_operators
from .cea import PENALTY
from .facets import face_deviation, facet_deviation
from .mortar2 import quadratic_mortar
from .mortar3 import solid_mortar
from .prestress import centrifugal_stiffness
from .solid import Solid, SolidSystem
from .supports import Supports, direction_of, supports_from
from .static import ITERATIONS, PRESSURE_ITERATIONS, held_factor, settled, within_friction
from .surfaces import MAX_SPEED

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

log = logging.getLogger("stickslip.fem")

__all__ = ["Mortar", "PairProblem", "PairSteady", "Rotation", "Translation", "mortar", "sliding", "steady_pair",
           "facets", "FACETS"]

GAUSS = (0.5 - 0.5 / math.sqrt(3.0), 0.5 + 0.5 / math.sqrt(3.0))
#: Steady sliding warns where the master's facets deviate from its curve by more than this
#: times the interference the contact carries (measured on the pad on the disc of
#: examples/pad_on_disc, 20 micrometres of interference: at 0.37, a 2-mm pad on a 3-mm disc
#: mesh, 21 % of the face's nodes lost their pressure; at 0.31, a 4-mm pad on it, none; at 1.7
#: and 2.1, a 6-mm disc mesh, 41 and 64 %; at 0.07 and 0.09, a 1.5-mm one, none).
FACETS = 1.0 / 3.0
#: The largest overlap of a pair's meshes, over the slave's thickness along the contact normal: a strain
#: scale (issue 45: 2 mm into an 8 mm lining, 0.25, ran at 1.5 GPa).
INTERFERENCE = 0.02
#: Master segments farther than this times the slave line's length (either side) are not its
#: partners; a body farther inside the other is refused (as a rigid surface's, `contact_frames`).
REACH = 0.05


@dataclass(frozen=True)
class Rotation:
    """The master turns at ``omega`` [rad/s] about ``center`` (a disc; counter-clockwise for > 0)."""

    omega: float
    center: tuple = (0.0, 0.0)

    def __post_init__(self):
        object.__setattr__(self, "omega", Q.check("omega", self.omega))
        object.__setattr__(self, "center", Q["center"].check_pair(self.center, "center"))

    def velocity(self, points: np.ndarray) -> np.ndarray:
        """The velocity at ``points`` (``(n, 2)``, or ``(n, 3)``: a solid turning about the z axis
        through ``center``)."""
        points = np.asarray(points, float)
        r = points[:, :2] - np.asarray(self.center, float)
        v = self.omega * np.column_stack([-r[:, 1], r[:, 0]])
        return v if points.shape[1] == 2 else np.column_stack([v, np.zeros(len(v))])


@dataclass(frozen=True)
class Translation:
    """The master translates at ``velocity`` [m/s] (a belt, a sliding block)."""

    velocity: tuple

    def __post_init__(self):
        object.__setattr__(self, "velocity", Q["velocity"].check_pair(self.velocity))
        if math.hypot(*self.velocity) > MAX_SPEED:
            raise ParameterError("velocity", list(self.velocity), f"at most {MAX_SPEED:g} m/s in size")

    def velocity_at(self, points):
        """The velocity at ``points``: in the x-y plane for a solid's ``(n, 3)``."""
        v = np.tile(np.asarray(self.velocity, float), (len(points), 1))
        return v if np.shape(points)[1] == 2 else np.column_stack([v, np.zeros(len(v))])


def _velocity(motion, points):
    return motion.velocity(points) if isinstance(motion, Rotation) else motion.velocity_at(points)


@dataclass(frozen=True)
class Mortar:
    """The mortar matrices of a slave and a master group: ``D`` (slave nodes x slave mesh
    nodes, diagonal in the slave nodes) and ``M`` (slave nodes x master mesh nodes), sparse; the
    slave nodes (mesh indices), their normals ``n`` (from the master into the slave) and the
    slave line's length per node ``weight = sum_k D_jk`` [m]."""

    slave_nodes: np.ndarray
    normal: np.ndarray
    D: sp.csr_matrix
    M: sp.csr_matrix
    reach: np.ndarray | None = None  # each row's overlap, sum_l M_jl / D_jj, before `consistent` scaled it

    @property
    def weight(self) -> np.ndarray:
        return np.asarray(self.D.sum(axis=1)).ravel()

    @property
    def can_touch(self) -> np.ndarray:
        """Each slave node whose line or face overlaps the master's (its ``M`` row sum at least half its
        weight, `reach`): the others cannot touch."""
        reach = np.asarray(self.M.sum(axis=1)).ravel() / self.weight if self.reach is None else self.reach
        return reach > 0.5

    @classmethod
    def consistent(cls, slave_nodes, normal, D, M) -> "Mortar":
        """The coupling with each row of ``M`` scaled to sum to ``D_jj``, its overlap kept as `reach`.

        Where a slave node's line or face runs past the master's edge, the dual shape function is
        integrated over part of its support only, and its row of ``M`` does not sum to ``D_jj`` (on a
        pad overhanging a block by a cell, 1.06 and -0.16 times it): the weighted gap of that node then
        moves with a rigid translation of both bodies, so contact depended on where the model sat in
        space (refused, running or "not held" by the z of the block's top alone). Scaled, a rigid
        motion moves no gap; a fully covered row sums to ``D_jj`` already and is unchanged."""
        D, M = sp.csr_matrix(D), sp.csr_matrix(M)
        weight = np.asarray(D.sum(axis=1)).ravel()
        total = np.asarray(M.sum(axis=1)).ravel()
        ok = total > 0
        scale = np.zeros(len(total))
        scale[ok] = weight[ok] / total[ok]
        return cls(slave_nodes, normal, D, sp.csr_matrix(sp.diags(scale) @ M), total / weight)

    def gap(self, slave_points: np.ndarray, master_points: np.ndarray) -> np.ndarray:
        """The weighted normal gap of each slave node with the meshes at these points [m^2 on solids, m
        on plane bodies]: ``n_j . (sum_k D_jk x_k - sum_l M_jl x_l)``."""
        return sum(self.normal[:, k] * (self.D @ slave_points[:, k] - self.M @ master_points[:, k])
                   for k in range(slave_points.shape[1]))

    def check_interference(self, slave_points: np.ndarray, master_points: np.ndarray, slave_group: str,
                           also=()) -> None:
        """Refuse meshes (at these points) that overlap along the contact normal, at the deepest slave node
        that can touch, by more than `INTERFERENCE` times the slave's thickness along the mean normal (a
        strain of that size is not a preload: 2 mm into an 8 mm lining ran at 1.5 GPa)."""
        can = self.can_touch
        if not can.any():
            return
        overlap = float(max(0.0, -np.min(self.gap(slave_points, master_points)[can] / self.weight[can])))
        mean = self.normal.mean(axis=0)
        thickness = float(np.ptp(slave_points @ (mean / np.linalg.norm(mean))))
        if overlap > INTERFERENCE * thickness:
            raise ParameterError("slave_group", slave_group, f"a contact whose meshes overlap by at most "
                                 f"{INTERFERENCE:g} x the slave's thickness along the normal ({thickness:.4g} m): they "
                                 f"overlap by {overlap:.4g} m, a strain of {overlap / thickness:.3g} (check the meshes' "
                                 "positions and units; press the bodies together with a load)", also=also)


def _inward(points, edges):
    d = points[edges[:, 1]] - points[edges[:, 0]]
    n = np.column_stack([-d[:, 1], d[:, 0]])
    return n / np.hypot(n[:, 0], n[:, 1])[:, None]


def _linear(body, group, option):
    return body.oriented(group, option)[:, :2]


def mortar(slave_body, slave_group: str, master_body, master_group: str) -> Mortar:
    """The mortar coupling of ``slave_group`` of ``slave_body`` with ``master_group`` of
    ``master_body`` (see the module docstring; with quadratic cells on either side,
    `stickslip.fem.mortar2`); a slave segment that overlaps no master segment
    contributes to ``D`` only (its nodes cannot touch: their ``M`` row sums fall short). Two solids'
    face groups: `stickslip.fem.mortar3`."""
    if isinstance(slave_body, Solid) or isinstance(master_body, Solid):
        nodes, normal, D, M, deep, away, found = solid_mortar(slave_body, slave_group, master_body, master_group,
                                                              REACH)
        seen = slave_body.points[nodes]
        _refuse(deep, away, found, float(np.linalg.norm(np.ptp(seen, axis=0))), slave_group, master_group)
        return Mortar.consistent(nodes, normal, D, M)
    if slave_body.order == 2 or master_body.order == 2:
        s_edges = slave_body.oriented(slave_group, "slave_group")
        m_edges = master_body.oriented(master_group, "master_group")
        span = float(np.sum(np.hypot(*(slave_body.points[s_edges[:, 1], :2] - slave_body.points[s_edges[:, 0], :2]).T)))
        nodes, normal, D, M, deep, away, found = quadratic_mortar(slave_body, s_edges, master_body, m_edges,
                                                                  REACH * span)
        _refuse(deep, away, found, span, slave_group, master_group)
        return Mortar.consistent(nodes, normal, D, M)
    s_edges = _linear(slave_body, slave_group, "slave_group")
    m_edges = _linear(master_body, master_group, "master_group")
    xs, xm = slave_body.points, master_body.points
    seg_n = _inward(xs, s_edges)  # into the slave: from the master towards the slave
    nodes = np.unique(s_edges)
    where = {int(v): k for k, v in enumerate(nodes)}
    lengths = np.hypot(*(xs[s_edges[:, 1]] - xs[s_edges[:, 0]]).T)
    normal = np.zeros((len(nodes), 2))
    for e, (a, b) in enumerate(s_edges):
        normal[where[int(a)]] += lengths[e] * seg_n[e]
        normal[where[int(b)]] += lengths[e] * seg_n[e]
    normal /= np.hypot(normal[:, 0], normal[:, 1])[:, None]
    m_n = _inward(xm, m_edges)  # into the master
    window = REACH * lengths.sum()
    Dr, Dc, Dv, Mr, Mc, Mv = [], [], [], [], [], []
    deep, away, found = 0.0, 0, 0
    for e, (a, b) in enumerate(s_edges):
        pa, pb, n, L = xs[a], xs[b], seg_n[e], lengths[e]
        t = (pb - pa) / L
        for j in (a, b):  # D = int phi_j N_k = delta_jk int N_j: diagonal, half the segment to each end
            Dr.append(where[int(j)])
            Dc.append(int(j))
            Dv.append(L / 2.0)
        # where every master segment's ends fall along the slave segment, projected along n
        # (vectorised: only the segments that overlap it are visited)
        ends = (xm[m_edges] - pa) @ t / L  # (segments, 2)
        overlap = (np.minimum(1.0, ends.max(axis=1)) - np.maximum(0.0, ends.min(axis=1)) > 1e-12) & \
            (ends[:, 0] != ends[:, 1])
        for f in np.flatnonzero(overlap):
            c, d = m_edges[f]
            pc, pd = xm[c], xm[d]
            ec, ed = ends[f]
            lo, hi = max(0.0, min(ec, ed)), min(1.0, max(ec, ed))
            mid = pa + 0.5 * (lo + hi) * (pb - pa)
            m_dir = pd - pc
            along_n = np.column_stack([m_dir, -n])  # x + alpha n = pc + xi m_dir
            xi, alpha = np.linalg.solve(along_n, mid - pc)
            gap = -alpha  # from the master's segment to the slave's, along n
            if abs(gap) > window or not 0.0 <= xi <= 1.0:
                if gap < -window and np.dot(m_n[f], n) < 0.0 and 0.0 <= xi <= 1.0:
                    deep = min(deep, gap)
                continue
            if np.dot(m_n[f], n) >= 0.0:  # a master segment facing away (the far side of a disc, say)
                away += 1
                continue
            found += 1
            for g in GAUSS:
                eta = lo + g * (hi - lo)
                x = pa + eta * (pb - pa)
                xi, _ = np.linalg.solve(along_n, x - pc)
                weight = 0.5 * (hi - lo) * L
                Ns = (2.0 - 3.0 * eta, 3.0 * eta - 1.0)  # the dual shape functions phi_a, phi_b
                Nm = (1.0 - xi, xi)
                for j, nj in zip((a, b), Ns):
                    for l, nl in zip((c, d), Nm):
                        Mr.append(where[int(j)])
                        Mc.append(int(l))
                        Mv.append(weight * nj * nl)
    _refuse(deep, away, found, lengths.sum(), slave_group, master_group)
    D = sp.csr_matrix((Dv, (Dr, Dc)), shape=(len(nodes), len(xs)))
    M = sp.csr_matrix((Mv, (Mr, Mc)), shape=(len(nodes), len(xm)))
    return Mortar.consistent(nodes, normal, D, M)


def _refuse(deep, away, found, span, slave_group, master_group):
    if deep < 0.0:
        raise ParameterError("slave_group", slave_group, f"a group that does not interpenetrate the master's group "
                             f"{master_group!r} (it lies {-deep:.3g} m inside it, more than {REACH:g} x the slave "
                             f"line's length {span:.3g} m)", also=("master_group",))
    if not found:
        why = ("faces away from it (the bodies must lie on either side of the contact)" if away else
               f"is farther than {REACH:g} x its length from it everywhere")
        raise ParameterError("master_group", master_group, f"a boundary group that faces the slave group "
                             f"{slave_group!r} (it {why})", also=("slave_group",))


def sliding(coupling: Mortar, motion, points, required: bool = True) -> tuple[np.ndarray, np.ndarray]:
    """``(t, speed)`` at the slave nodes of ``coupling`` (mesh ``points``): the unit tangent along
    the master's ``motion`` there and its speed [m/s]; a motion faster than the fastest surface is
    refused, and so is one that does not slide the master along the contact at every slave node
    if ``required`` (friction needs a direction; without friction the pair may rest)."""
    n = coupling.normal
    v = _velocity(motion, np.asarray(points)[coupling.slave_nodes])
    if n.shape[1] == 3:  # a solid: the sliding in the tangent plane, its direction the slip's
        v = v - np.sum(v * n, axis=1)[:, None] * n
        along = np.linalg.norm(v, axis=1)
        t0 = v / np.where(along > 0, along, 1.0)[:, None]
    else:
        t0 = np.column_stack([n[:, 1], -n[:, 0]])
        along = np.sum(v * t0, axis=1)
    if np.abs(along).max() > MAX_SPEED:
        raise ParameterError("motion", motion, f"at most {MAX_SPEED:g} m/s of sliding at the contact")
    if required and not np.all(np.abs(along) > 0):
        raise ParameterError("motion", motion, "a motion that slides the master along the contact at every slave "
                             "node (friction needs a sliding direction)")
    return t0 * np.where(along < 0, -1.0, 1.0)[:, None], np.abs(along)


@dataclass(frozen=True, eq=False)
class PairProblem:
    """A ``slave`` body (the pad) on a ``master`` body (the disc), both `BodySystem`: their
    contact groups, the master's ``motion`` (`Rotation` or `Translation`), the Coulomb
    ``friction``, each body's clamped boundary groups and its rollers ``{group: axes}`` (a group's
    nodes held along the coordinate axis ``"x"``, ``"y"`` or, on a solid, ``"z"``: a symmetry plane;
    ``"xy"``: along both, a face held in its plane).
    Two 2-D bodies (`BodySystem`) or two solids (`stickslip.fem.solid.SolidSystem`: a solid turns
    about the z axis through the rotation's centre; its gyroscopic and transport terms:
    `stickslip.fem.turning`).

    As a `stickslip.fem.scheme.ContactProblem`'s: a ``static_friction >= friction`` (explicit
    runs; None: the same), or a friction ``law`` of the slip speed instead of both (each slave
    node's kinetic coefficient at the master's sliding speed there, ``law.slope`` in the CEA's
    damping on the relative tangential velocity), and a ``pressure_law`` (each node's
    coefficients times ``(P / P_ref)^(-n)`` at its multiplier ``P``).

    ``transverse_damping`` (solids only; default false, as commercial CEAs leave it out): in the CEA,
    the friction force turns with a slip velocity across the sliding direction, ``-mu lambda v_b / V``
    along ``b = n x t`` at each active slave node: a damping ``B^T diag(mu g lambda / (w V)) B`` of
    the relative velocity across (``B`` the weighted rows along ``b``). An explicit run's Coulomb
    disc has it always; it damps every motion of the pad across the sliding (a pad on springs
    across decays at ``mu N / (2 m V)``).

    ``prestress`` (a turning solid partner; default false): the master's stiffness includes the stress
    stiffening of its centrifugal prestress (`stickslip.fem.prestress`); with ``gyroscopic``, the
    small vibrations about the turning disc have every term of order ``omega^2``."""

    slave: BodySystem
    slave_group: str
    master: BodySystem
    master_group: str
    motion: Rotation | Translation
    friction: float = 0.0
    clamped_slave: tuple = ()
    clamped_master: tuple = ()
    gyroscopic: bool = False
    static_friction: float | None = None
    law: FrictionLaw | None = None
    pressure_law: PressurePower | None = None
    rollers_slave: dict | None = None
    rollers_master: dict | None = None
    transverse_damping: bool = False
    prestress: bool = False

    def __post_init__(self):
        for name in ("slave", "master"):
            if not isinstance(getattr(self, name), (BodySystem, SolidSystem)):
                raise ParameterError(name, getattr(self, name), "a BodySystem (see assemble) or a SolidSystem "
                                     "(assemble_solid)")
        for name in ("slave_group", "master_group"):
            if not isinstance(getattr(self, name), str):
                raise ParameterError(name, getattr(self, name), "the name of a boundary (or face) group")
        for name in ("clamped_slave", "clamped_master"):
            value = getattr(self, name)
            if isinstance(value, str) or not isinstance(value, (list, tuple)) or \
                    not all(isinstance(g, str) for g in value):
                raise ParameterError(name, value, "a list of boundary (or face) group names")
        if isinstance(self.slave, SolidSystem) != isinstance(self.master, SolidSystem):
            raise ParameterError("master", self.master.body.source, f"a body of the slave's dimension (the slave "
                                 f"{self.slave.body.source} is {self.dimension}-D, the master "
                                 f"{5 - self.dimension}-D)", also=("slave",))
        object.__setattr__(self, "friction", Q.check("friction", self.friction))
        if self.law is not None:
            if not isinstance(self.law, FrictionLaw):
                raise ParameterError("law", self.law, "a friction law of stickslip.friction or None")
            if self.friction != 0.0 or self.static_friction is not None:
                raise ParameterError("friction", self.friction, "left out with a law (the law gives the kinetic "
                                     "coefficient at the sliding speed, and the static one)", also=("law",))
        elif self.static_friction is not None:
            object.__setattr__(self, "static_friction", check.at_least(
                "static_friction", Q.check("static_friction", self.static_friction), self.friction, "friction"))
        if self.pressure_law is not None and not isinstance(self.pressure_law, PressurePower):
            raise ParameterError("pressure_law", self.pressure_law, "a stickslip.friction.PressurePower or None")
        if not isinstance(self.motion, (Rotation, Translation)):
            raise ParameterError("motion", self.motion, "a Rotation or a Translation of the master")
        if not isinstance(self.transverse_damping, bool) or (self.transverse_damping and self.dimension != 3):
            raise ParameterError("transverse_damping", self.transverse_damping, "true or false, true only between "
                                 "solids (plane bodies slide along their one tangent)")
        if not isinstance(self.prestress, bool) or (self.prestress and (self.dimension != 3 or
                                                                         not isinstance(self.motion, Rotation))):
            raise ParameterError("prestress", self.prestress, "true or false, true only with a turning solid partner "
                                 "(a Rotation between solids)")
        if not isinstance(self.gyroscopic, bool) or (self.gyroscopic and not isinstance(self.motion, Rotation)):
            raise ParameterError("gyroscopic", self.gyroscopic, "true or false, true only with a turning master "
                                 "(a Rotation)")
        _ = self.tangent  # the coupling and the sliding direction: a pair that cannot touch is refused here
        _ = self.fixed  # the supports: a group or an axis that is not there is refused here
        self._interference()
        if self.law is not None:
            speed = self.tangent[1]
            if speed.max() >= self.law.max_speed:
                raise ParameterError("law", self.law, f"a law valid at the sliding speed {speed.max():.6g} m/s (this "
                                     f"one up to {self.law.max_speed:.6g} m/s)")
            object.__setattr__(self, "friction", float(np.max(self.law.kinetic(speed))))
            object.__setattr__(self, "static_friction", float(self.law.static))
        elif self.static_friction is None:
            object.__setattr__(self, "static_friction", float(self.friction))

    def _interference(self) -> None:
        """Meshes overlapping by a strain are refused (`Mortar.check_interference`)."""
        self.coupling.check_interference(self.slave.body.points, self.master.body.points, self.slave_group,
                                         also=("master_group",))

    @property
    def can_touch(self) -> np.ndarray:
        """Each slave node that can touch the master (`Mortar.can_touch`)."""
        return self.coupling.can_touch

    def displacements(self, shapes: np.ndarray) -> np.ndarray:
        """Mode shapes on the free dofs (columns: a CEA's, full or reduced; multipliers after them are
        left out) as displacements of every dof of both bodies, the held ones 0."""
        free = self.supports.free
        if shapes.ndim != 2 or shapes.shape[0] < free.size:
            raise ParameterError("modes", f"shapes of {shapes.shape[0]} dofs", f"the modes of this problem "
                                 f"({free.size} free dofs)")
        return self.supports.expand(np.asarray(shapes[:free.size], dtype=complex))

    @property
    def dimension(self) -> int:
        """2 for plane bodies, 3 for solids."""
        return 3 if isinstance(self.slave, SolidSystem) else 2

    @cached_property
    def kinetic(self) -> np.ndarray:
        """Each slave node's kinetic coefficient at the master's sliding speed there (``friction``
        everywhere without a law)."""
        if self.law is None:
            return np.full(len(self.coupling.slave_nodes), float(self.friction))
        return np.asarray(self.law.kinetic(self.tangent[1]), dtype=float)

    @cached_property
    def slopes(self) -> np.ndarray:
        """``d mu / d v_r`` [s/m] at each slave node's sliding speed (0 without a law)."""
        if self.law is None:
            return np.zeros(len(self.coupling.slave_nodes))
        return np.asarray(self.law.slope(self.tangent[1]), dtype=float) + np.zeros(len(self.coupling.slave_nodes))

    def factor(self, pressure: np.ndarray) -> np.ndarray:
        """The pressure law's factor at each slave node's multiplier (1 without one)."""
        if self.pressure_law is None:
            return np.ones(len(pressure))
        return self.pressure_law.factor(pressure)

    @cached_property
    def coupling(self) -> Mortar:
        return mortar(self.slave.body, self.slave_group, self.master.body, self.master_group)

    @property
    def n_slave(self) -> int:
        return self.slave.n_dofs

    @cached_property
    def supports(self) -> Supports:
        """Both bodies' supports (slave first; `stickslip.fem.supports`): clamps, and rollers along
        coordinate axes or along any direction (a node's degrees of freedom then in its own frame)."""
        n_slave = len(self.slave.body.points)
        held = self._held("slave", 0) + self._held("master", n_slave)
        return supports_from(n_slave + len(self.master.body.points), self.dimension, held)

    def _held(self, who: str, offset: int) -> list:
        """``[(nodes + offset, directions)]`` of the body ``who``'s clamps and rollers."""
        system, dim, held = getattr(self, who), self.dimension, []
        for name in getattr(self, f"clamped_{who}"):
            held.append((offset + system.body.nodes(name, f"clamped_{who}"), list(np.eye(dim))))
        rollers = getattr(self, f"rollers_{who}")
        if rollers is None:
            return held
        if not isinstance(rollers, dict):
            raise ParameterError(f"rollers_{who}", rollers, "{face group: axes or a direction} or None")
        for name, axis in rollers.items():
            where = f"rollers_{who}[{name}]"
            held.append((offset + system.body.nodes(name, where), direction_of(axis, dim, where)))
        return held

    @property
    def fixed(self) -> np.ndarray:
        """The held degrees of freedom, each in its node's frame (`supports`)."""
        return self.supports.held

    @cached_property
    def tangent(self) -> tuple[np.ndarray, np.ndarray]:
        """``(t, speed)``: the unit tangent at each slave node along the master's sliding there,
        and that sliding speed [m/s] (`sliding`)."""
        return sliding(self.coupling, self.motion, self.slave.body.points,
                       required=self.friction > 0 or self.law is not None)

    def _rows(self, direction: np.ndarray) -> sp.csr_matrix:
        """``(sum_k D_jk d_j . u_k - sum_l M_jl d_j . u_l)_j`` as a matrix on all dofs."""
        c, dim = self.coupling, self.dimension
        blocks = []
        for A, sign in ((c.D, 1.0), (c.M, -1.0)):
            A = A.tocoo()
            d = direction[A.row]
            rows = np.tile(A.row, dim)
            cols = np.concatenate([dim * A.col + k for k in range(dim)])
            vals = sign * np.concatenate([A.data * d[:, k] for k in range(dim)])
            blocks.append(sp.csr_matrix((vals, (rows, cols)), shape=(A.shape[0], dim * A.shape[1])))
        return sp.hstack(blocks).tocsr()

    @cached_property
    def G(self) -> sp.csr_matrix:
        return self._rows(self.coupling.normal)

    @cached_property
    def T(self) -> sp.csr_matrix:
        return self._rows(self.tangent[0])

    @cached_property
    def gap(self) -> np.ndarray:
        """The weighted normal gap of each slave node in the reference configuration (`Mortar.gap`)."""
        return self.coupling.gap(self.slave.body.points, self.master.body.points)

    @cached_property
    def transport(self):
        """``(G, B)`` of the turning master (`stickslip.fem.assembly.transport_operators`) on all
        dofs, or None without ``gyroscopic``."""
        if not self.gyroscopic:
            return None
        if self.dimension == 3:
            from .turning import solid_transport_operators

            G, B = solid_transport_operators(self.master, self.motion.omega, self.motion.center)
        else:
            G, B = transport_operators(self.master, self.motion.omega, self.motion.center)
        zero = sp.csr_matrix((self.n_slave, self.n_slave))
        return sp.block_diag([zero, G], format="csr"), sp.block_diag([zero, B], format="csr")

    @cached_property
    def K(self) -> sp.csr_matrix:
        """Both stiffnesses; with ``gyroscopic``, the master's less its transport softening ``B``
        (steady in space, the turning material still accelerates through the deformation); with
        ``prestress``, the master's plus the stress stiffness of its centrifugal prestress
        (`stickslip.fem.prestress`, its supports held)."""
        master = self.master.K
        if self.prestress:
            held = supports_from(len(self.master.body.points), 3, self._held("master", 0))
            master = master + centrifugal_stiffness(self.master, self.motion.omega, self.motion.center, held)[0]
        K = sp.block_diag([self.slave.K, master], format="csr")
        return K if self.transport is None else (K - self.transport[1]).tocsr()

    @cached_property
    def S(self):
        """Both bodies' structural damping ``sum eta K`` (their materials' loss factors), or None: the
        CEA's stiffness is ``K + i S``."""
        if self.slave.S is None and self.master.S is None:
            return None
        return sp.block_diag([sp.csr_matrix(s.K.shape) if s.S is None else s.S for s in (self.slave, self.master)],
                             format="csr")

    @cached_property
    def C(self):
        """Both dampings; with ``gyroscopic``, plus the master's gyroscopic matrix ``G``."""
        C = None
        if self.slave.C is not None or self.master.C is not None:
            C = sp.block_diag([sp.csr_matrix(s.K.shape) if s.C is None else s.C for s in (self.slave, self.master)],
                              format="csr")
        if self.transport is not None:
            C = self.transport[0] if C is None else (C + self.transport[0]).tocsr()
        return C

    @property
    def mass(self) -> np.ndarray:
        return np.concatenate([self.slave.mass, self.master.mass])

    @property
    def load(self) -> np.ndarray:
        return np.concatenate([self.slave.load, self.master.load])

    @property
    def materials(self) -> dict:
        """Both bodies' materials, ``slave:GROUP`` and ``master:GROUP``."""
        return {f"{who}:{k}" if k else who: m for who, system in (("slave", self.slave), ("master", self.master))
                for k, m in system.materials.items()}

    @cached_property
    def omega_max(self) -> float:
        """Largest free angular frequency [rad/s] of either body (Lanczos)."""
        sup = self.supports
        scale = sp.diags(1.0 / np.sqrt(sup.mass(self.mass)))
        A = (scale @ sup.restrict(self.K) @ scale).tocsc()
        start = np.random.default_rng(0).standard_normal(A.shape[0])
        lam = sla.eigsh(A, k=1, which="LA", return_eigenvectors=False, tol=1e-10, v0=start)
        return float(np.sqrt(lam[0]) * (1.0 + 1e-6))

    @cached_property
    def steady(self) -> PairSteady:
        return steady_pair(self)

    @cached_property
    def constraint_scale(self) -> float:
        """The constraint rows are scaled by this (and the multipliers by its inverse) to the size
        of the stiffness' entries, so that a pivot's size says whether the pair is held."""
        return float(np.mean(np.abs(self.K.diagonal())) / np.max(self.coupling.weight))

    def linearised(self, mass_matrix: str = "lumped", contact_model: str = "constraint", penalty: float | None = None):
        """``(K_aug, C_aug or None, mass_aug, kept)`` of the CEA about steady sliding: the free dofs
        and the multipliers of the active slave nodes (mass 0), see the module docstring (built
        once per problem and options). ``mass_matrix="consistent"``: both bodies' consistent mass
        matrices (``mass_aug`` a sparse matrix) instead of the lumped masses. ``contact_model=
        "penalty"``: no multipliers; each active slave node's normal force is a spring on its gap,
        ``w_j lambda_j = -k g_j / w_j`` (``g_j / w_j`` the gap [m]), ``k`` = ``penalty`` (default
        `stickslip.fem.cea.PENALTY`) times the stiffness' largest diagonal entry, as for one body
        (`stickslip.fem.cea.linearised`): ``K + k B_A^T W^-2 G_A``, converging to the constraint at
        first order in ``1 / penalty``."""
        mass_matrix = Q.check("mass_matrix", mass_matrix)
        contact_model = Q.check("contact_model", contact_model)
        if contact_model == "penalty":
            penalty = Q.check("penalty", PENALTY if penalty is None else penalty)
        elif penalty is not None:
            raise ParameterError("penalty", penalty, 'left out unless contact_model = "penalty"',
                                 also=("contact_model",))
        key = (mass_matrix, contact_model, penalty)
        if key not in self._linearised:
            self._linearised[key] = self._operators(*key)
        return self._linearised[key]

    @cached_property
    def _linearised(self) -> dict:
        return {}

    def transverse_matrix(self, coefficient: np.ndarray) -> sp.csr_matrix:
        """The damping of the friction force turning with a slip across the sliding direction, on all dofs:
        ``B^T diag(c lambda / (w V)) B`` over steady sliding's active slave nodes (``B`` the weighted rows
        along ``b = n x t``, ``lambda`` the steady pressure, ``c`` each node's ``coefficient``: its friction
        coefficient, 1 for the reduced CEA's per-unit matrix). Solids only."""
        st, c = self.steady, self.coupling
        A = np.flatnonzero(st.active)
        across = self._rows(np.cross(c.normal, self.tangent[0]))[A]
        weights = np.asarray(coefficient, float)[A] * st.pressure[A] / (c.weight[A] * self.tangent[1][A])
        return (across.T @ sp.diags(weights) @ across).tocsr()

    @cached_property
    def consistent_mass(self) -> sp.csr_matrix:
        """Both bodies' consistent mass matrices on all dofs."""
        return sp.block_diag([self.slave.consistent_mass, self.master.consistent_mass], format="csr")

    def _operators(self, mass_matrix, contact_model, penalty):
        st = self.steady
        if not st.loaded:
            raise NoSolutionError("steady sliding of the pair carries no contact force: press the bodies together")
        sup = self.supports
        free = sup.free
        A = np.flatnonzero(st.active)
        c = self.constraint_scale
        g = self.factor(st.pressure[A])
        rate = 1.0 if self.pressure_law is None else self.pressure_law.rate
        # the friction force T^T (mu g lambda): d/d lambda = mu g (1 - n) per node
        B = c * sup.columns(self.G[A] + sp.diags(self.kinetic[A] * g * rate) @ self.T[A])
        G = c * sup.columns(self.G[A])
        K = sup.restrict(self.K)
        k = None if contact_model != "penalty" else penalty * float(np.abs(K.diagonal()).max())
        if self.S is not None:  # loss factors: K + i S (structural damping, in the frequency domain)
            K = (K + 1j * sup.restrict(self.S)).tocsr()
        multipliers = 0 if contact_model == "penalty" else len(A)
        if contact_model == "penalty":  # lambda = -k W^-2 G u: the force B^T lambda on the left as k B^T W^-2 G
            K = (K + (k / c**2) * B.T @ sp.diags(1.0 / self.coupling.weight[A] ** 2) @ G).tocsr()
        else:
            K = sp.bmat([[K, -B.T], [G, None]], format="csr")
        C = None if self.C is None else sup.restrict(self.C)
        if self.law is not None:  # mu(V - (T u')_j / w_j): damping T^T diag(lambda g mu' / w) T (negative if falling)
            T = sup.columns(self.T[A])
            slip = T.T @ sp.diags(st.pressure[A] * g * self.slopes[A] / self.coupling.weight[A]) @ T
            C = slip if C is None else (C + slip).tocsr()
        if self.transverse_damping:  # the force turns with a slip across: -mu g lambda (B u')_j / (w_j V_j) along b
            coefficient = np.zeros(len(self.coupling.weight))
            coefficient[A] = self.kinetic[A] * g
            turn = sup.restrict(self.transverse_matrix(coefficient))
            C = turn if C is None else (C + turn).tocsr()
        if C is not None and multipliers:
            C = sp.block_diag([C, sp.csr_matrix((multipliers, multipliers))], format="csr")
        if mass_matrix == "consistent":
            mass = sup.restrict(self.consistent_mass)
            if multipliers:
                mass = sp.block_diag([mass, sp.csr_matrix((multipliers, multipliers))], format="csr")
        else:
            mass = np.concatenate([sup.mass(self.mass), np.zeros(multipliers)])
        return K, C, mass, free

    @cached_property
    def digest(self) -> str:
        """SHA-256 of both meshes, stiffnesses, loads, the mortar, the sliding and the clamped dofs:
        what a checkpoint of a run must share."""
        h = hashlib.sha256()
        c, (t, speed) = self.coupling, self.tangent
        for system in (self.slave, self.master):
            K = system.K
            for arr in (system.body.points, system.body.cells, K.indptr, K.indices, K.data, system.load, system.mass):
                h.update(np.ascontiguousarray(arr).tobytes())
        for arr in (c.slave_nodes, c.normal, c.D.data, c.M.indptr, c.M.indices, c.M.data, t, speed, self.fixed):
            h.update(np.ascontiguousarray(arr).tobytes())
        if self.supports.rotation is not None:  # rollers along directions: their frames
            h.update(np.ascontiguousarray(self.supports.rotation.data).tobytes())
        h.update(repr((self.friction, self.gyroscopic, self.prestress, self.static_friction, repr(self.law),
                       None if self.pressure_law is None else (self.pressure_law.reference, self.pressure_law.exponent))
                      ).encode())
        return h.hexdigest()

    def to_dict(self) -> dict:
        return self.to_attrs()

    def to_attrs(self) -> dict:
        return {"slave_mesh": Path(str(self.slave.body.source)).name, "master_mesh": Path(str(self.master.body.source)).name,
                "slave_group": self.slave_group, "master_group": self.master_group, "friction": self.friction,
                "motion": repr(self.motion), "clamped_slave": ",".join(self.clamped_slave),
                "clamped_master": ",".join(self.clamped_master), "slave_nodes": len(self.coupling.slave_nodes),
                **{name: ", ".join(f"{g}: {a}" for g, a in getattr(self, name).items())
                   for name in ("rollers_slave", "rollers_master") if getattr(self, name)},
                "gyroscopic": int(self.gyroscopic), "problem_sha256": self.digest,
                **({"transverse_damping": 1} if self.transverse_damping else {}),
                **({"prestress": 1} if self.prestress else {}),
                "static_friction": self.static_friction,
                **({} if self.law is None else {"friction_law": repr(self.law)}),
                **({} if self.pressure_law is None else {"pressure_exponent": self.pressure_law.exponent,
                                                         "reference_pressure": self.pressure_law.reference}),
                "materials": "; ".join(f"{name}: {m.describe(plane=self.dimension == 2)}, density = {m.density:g} kg/m3"
                                       for name, m in self.materials.items())}


@dataclass(frozen=True, eq=False, repr=False)
class PairSteady(Result):
    """Steady sliding of a pair: the displacements of both bodies ``u`` [m] (slave dofs first),
    per slave node the contact ``pressure`` [Pa] (the multiplier), ``active``, and the forces
    on the slave's mesh nodes ``slave_force`` [N/m]; ``normal_force`` and ``friction_force`` the totals
    [N/m; N between solids]."""

    MODEL: ClassVar[str] = "fem"

    u: np.ndarray
    pressure: np.ndarray
    active: np.ndarray
    iterations: int
    normal_force: float
    friction_force: float
    load_floor: float = 0.0
    params: dict = field(default_factory=dict)
    points: np.ndarray | None = None  # the slave nodes' reference positions [m] (for to_xarray)
    gap: np.ndarray | None = None  # each slave node's normal gap in steady sliding [m]
    coefficients: np.ndarray | None = None  # each slave node's friction coefficient (law and pressure)
    dimension: int = 2  # 3: solids, whose forces are in N (normal_load, friction_load), not N/m

    def to_xarray(self) -> xr.Dataset:
        """The slave's contact nodes (in mesh order): position, pressure, state, gap."""
        N = "slave_node"
        data = {"pressure": (N, self.pressure, {"units": "Pa", "long_name": "contact pressure at the slave node "
                                                                             "(the mortar multiplier)"}),
                "active": (N, self.active.astype(np.int8), {"units": "1", "long_name": "slave node in contact (1) "
                                                                                        "or lifted off (0)"})}
        if self.gap is not None:
            data["gap"] = (N, self.gap, {"units": "m", "long_name": "normal gap to the master in steady sliding"})
        if self.points is not None:
            for k, axis in enumerate("xyz"[: self.points.shape[1]]):
                data[axis] = (N, self.points[:, k], {"units": "m", "long_name": f"{axis} of the slave node "
                                                                                "(reference configuration)"})
        ds = xr.Dataset(data, coords={N: (N, np.arange(len(self.pressure)), {"units": "1", "long_name":
                                                                                "index of the slave contact node"})})
        d = {k: v for k, v in self.to_dict().items() if k != "params"}
        return finish(ds, "steady sliding of two bodies in contact (mortar)", "fem",
                      params={**d, **self.params, "loaded": int(self.loaded)})

    @property
    def loaded(self) -> bool:
        return bool(self.normal_force > self.load_floor)

    def to_dict(self) -> dict:
        """The forces as ``normal_force`` and ``friction_force`` [N/m] of plane bodies, ``normal_load`` and
        ``friction_load`` [N] of solids."""
        forces = ("normal_force", "friction_force") if self.dimension == 2 else ("normal_load", "friction_load")
        return {"contact_nodes": len(self.pressure), "active_nodes": int(self.active.sum()),
                forces[0]: self.normal_force, forces[1]: self.friction_force,
                "max_pressure": float(self.pressure.max()), "iterations": int(self.iterations),
                "loaded": self.loaded, "params": self.params}


def steady_pair(problem: PairProblem, max_iterations: int | None = None) -> PairSteady:
    """Steady sliding of ``problem`` (see the module docstring)."""
    if not isinstance(problem, PairProblem):
        raise ParameterError("problem", problem, "a PairProblem")
    c = problem.coupling
    weight = c.weight
    max_iterations = max(ITERATIONS, 2 * len(weight)) if max_iterations is None else \
        Q.check("max_iterations", max_iterations)
    sup = problem.supports
    free = sup.free
    K, F, G, T = sup.restrict(problem.K), sup.load(problem.load), sup.columns(problem.G), sup.columns(problem.T)
    g0 = problem.gap
    can = problem.can_touch  # a slave node whose line overlaps no master cannot touch
    size = max(float(np.ptp(problem.slave.body.points)), float(np.ptp(problem.master.body.points)))
    tol = 1e-12 * size * weight  # a gap of 1e-12 of the bodies' size is touching [m^2]
    nearest = max(0.0, float(np.min(g0[can] / weight[can]))) if can.any() else 0.0
    active = can & (g0 <= nearest * (1 + 1e-9) * weight + tol)
    seen = []
    young = max(m.young for m in problem.materials.values())
    scale = problem.constraint_scale
    for iteration in range(1, max_iterations + 1):
        A = np.flatnonzero(active)
        mu = problem.kinetic.copy()
        last = np.inf
        for _ in range(PRESSURE_ITERATIONS):  # with a pressure law: each node's coefficient at its pressure
            x = _solve_pair(K, F, G[A], G[A] + sp.diags(mu[A]) @ T[A], scale, -scale * g0[A])
            lam = np.zeros(len(weight))
            lam[A] = scale * x[free.size:]
            if problem.pressure_law is None:
                break
            new = problem.kinetic[A] * problem.factor(np.maximum(lam[A], 0.0))
            within_friction(new, problem.pressure_law)
            change, top = float(np.max(np.abs(new - mu[A]), initial=0.0)), float(np.max(problem.kinetic))
            mu[A] = new
            if settled(change, last, top):
                x = _solve_pair(K, F, G[A], G[A] + sp.diags(mu[A]) @ T[A], scale, -scale * g0[A])
                lam[A] = scale * x[free.size:]
                break
            last = change
        else:
            raise NoSolutionError(f"steady sliding of the pair with friction depending on the pressure (exponent "
                                  f"{problem.pressure_law.exponent:g}) did not settle in {PRESSURE_ITERATIONS} "
                                  "iterations (a smaller pressure_exponent)")
        u = sup.expand(x[: free.size])
        gap = g0 + problem.G @ u
        penetrating = can & ~active & (gap < -tol)
        new = (active & (lam >= 0.0)) | penetrating
        if np.array_equal(new, active):
            _facets(problem, active, g0 / weight)
            normal = float(weight @ lam)  # the multiplier is the pressure, interpolated along the slave line
            return PairSteady(u, lam, active.copy(), iteration, normal, float(weight @ (mu * lam)),
                              1e-10 * young * size ** (problem.dimension - 1), problem.to_attrs(),
                              problem.slave.body.points[c.slave_nodes], gap / weight, mu, problem.dimension)
        if any(np.array_equal(old, new) for old in seen):
            raise NoSolutionError(f"no steady sliding of the pair at friction {problem.friction:g}: the active set "
                                  "cycles")
        seen.append(active.copy())
        active = new
    raise NoSolutionError(f"the pair's active set did not settle in {max_iterations} iterations")


def facets(problem: PairProblem) -> float:
    """The largest deviation of the master's segments (faces, between solids) under the slave from the
    curve (surface) through their nodes [m] (`stickslip.fem.facets`): 0 for a straight or flat master,
    and for quadratic cells (their curved segments follow a circle to ``h^4 / R^3``, not ``h^2 / R``)."""
    touched = np.zeros(len(problem.master.body.points), bool)
    touched[np.unique(problem.coupling.M.tocoo().col)] = True
    if problem.dimension == 3:
        if problem.master.body.kind in ("tetra10", "hexahedron20", "hexahedron27"):
            return 0.0
        faces = problem.master.body.faces[problem.master_group]
        under = touched[faces].all(axis=1)
        # the normals from the whole group (a subset's edge would take one-sided ones), the faces under the slave's
        return float(face_deviation(problem.master.body.points, faces)[under].max(initial=0.0))
    if problem.master.body.order == 2:
        return 0.0
    edges = problem.master.body.oriented(problem.master_group, "master_group")[:, :2]
    under = touched[edges[:, 0]] & touched[edges[:, 1]]
    return float(facet_deviation(problem.master.body.points, edges[under]).max(initial=0.0))


def _facets(problem: PairProblem, active: np.ndarray, gap: np.ndarray) -> None:
    """Warn (``stickslip.fem``) where the master's facets deviate from its curve by more than
    `FACETS` times the interference the active nodes carry (their largest overlap)."""
    overlap = float(np.max(-gap[active], initial=0.0))
    if overlap <= 0.0:  # pressed by loads, not by an interference: the facets are not compared
        return
    deviation = facets(problem)
    if deviation > FACETS * overlap:
        log.warning("the straight segments (flat faces) of the partner's group %r deviate from its curve by up to %.3g m, "
                    "%.2f times the %.3g m of interference the contact carries: the contact pressure alternates "
                    "between zero and about twice its mean from node to node (a segment of length h on a radius R "
                    "deviates by h^2 / (8 R)); refine the partner's mesh along the contact until the deviation is "
                    "below %.2g of the interference, or mesh it with quadratic cells (curved segments)",
                    problem.master_group, deviation, deviation / overlap, overlap, FACETS)


def _solve_pair(K, F, G_A, B_A, scale, rhs):
    """``(u_free, lambda_A / scale)`` of ``K u - scale B_A^T l = F``, ``scale G_A u = rhs``; a pair
    a rigid motion moves freely is a `NoSolutionError` (`stickslip.fem.static.held_factor`)."""
    S = sp.bmat([[K, -scale * B_A.T], [scale * G_A, None]], format="csc")
    not_held = NoSolutionError("the pair is not held (a rigid motion is free): clamp a group of each body or press "
                               "them together")
    return held_factor(S, not_held).solve(np.concatenate([F, rhs]))
