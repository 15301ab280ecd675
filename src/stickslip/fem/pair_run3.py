"""Explicit runs of two solids in contact: a 3-D pad on a sliding or turning 3-D partner.

`SolidPairScheme` is `stickslip.fem.pair_run.PairScheme` with a third dof per node: the
slave's contact nodes in their frames ``(n, t, b)`` (the normal, the master's sliding direction
there and ``b = n x t`` across it), Cartesian elsewhere, and the multipliers of
`stickslip.contact.coupled3`, whose friction force lies in a disc of radius ``mu P`` and points
along the slip of the step (a Coulomb disc per node, not a square of two one-dimensional laws).
Everything else is the plane pair's: the mortar's weights, steady sliding as a state of the
scheme, the partner's motion in space-fixed (Eulerian) coordinates with its gyroscopic terms
optional, the energy books with the force across the sliding direction in the friction's
dissipation, the run books (`integrate_pair` dispatches here for a pair of solids).

**The contact surface as a line.** The run books of `stickslip.contact.runs` keep the contact
nodes along a line; here the nodes are ordered by their position along the master's motion
(the angle about the turning axis times the mean radius for a `Rotation`, the distance along
the velocity for a `Translation`, stored as the coordinate ``arclength``) and ``theta = 2 pi k / N``
by rank (nodes across the width share a position). The transit time is the span ``L`` of the
positions over the slave's P-wave speed. The Fourier modes of the books and the classification's
zones and waves along ``theta`` are a description of the ranked nodes, not waves on the face.

Snapshots add ``W`` (the contact node's displacement along ``b``) and ``Q_cross`` (the friction
force along ``b`` [N]) to the plane fields (``Q`` along ``t``); ``P, Q`` are forces [N] per node.
A contact node held along some axes but not all (rollers through the contact surface) is refused:
its frame would mix held and free directions.
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from functools import cached_property
from typing import ClassVar

import numpy as np
import scipy.sparse as sp

from ..contact.coupled3 import coupled_advance3
from ..contact.scheme import StepOutput, StepState
from ..errors import ParameterError
from ..quantities import COMMON
from .pair import Rotation
from .pair_run import MAX_SWEEPS, SOLVERS, PairRun, PairScheme, check_supports

__all__ = ["SolidPairScheme", "SolidStepOutput", "SolidPairRun"]


@dataclass(eq=False)
class SolidStepOutput(StepOutput):
    """`StepOutput` with the force across the sliding direction: ``lam_b`` (per unit mass of the slave
    node, as ``lam_n, lam_t``); the three are columns of ``forces`` (``(nodes, 3)``, the kernel's)."""

    lam_b: np.ndarray | None = None
    forces: np.ndarray | None = None

    @classmethod
    def empty(cls, n_dofs: int, nodes: int) -> "SolidStepOutput":
        forces = np.zeros((nodes, 3))
        return cls(np.zeros(n_dofs), forces[:, 0], forces[:, 1], np.zeros(nodes, np.int8), forces[:, 2], forces)


def _p_wave_speed(system) -> float:
    """The fastest P-wave speed [m/s] of a solid's materials (an orthotropic one's stiffest axis)."""
    speeds = []
    for m in system.materials.values():
        if hasattr(m, "stiffness"):
            speeds.append(np.sqrt(float(np.max(np.diag(m.stiffness)[:3])) / m.density))
        else:
            speeds.append(m.p_wave_speed)
    return float(max(speeds))


@dataclass(frozen=True, eq=False)
class SolidPairScheme(PairScheme):
    """The explicit scheme of a `PairProblem` of two solids (see the module docstring; ``beta2``,
    ``courant`` and ``time_step`` as `PairScheme`'s)."""

    def __post_init__(self):
        if not hasattr(self.params, "dimension") or self.params.dimension != 3:
            raise ParameterError("params", self.params, "a PairProblem of two solids (plane bodies: PairScheme)")
        self.validate_common()
        check_supports(self.params)
        self.check_time_step()
        _ = self.kinetic_law
        _ = self._rows

    # --- the contact nodes and their frames ---------------------------------------------------
    @cached_property
    def _position(self) -> np.ndarray:
        """Each slave node's position along the master's motion [m] (see the module docstring)."""
        p = self.params
        pts = p.slave.body.points[p.coupling.slave_nodes]
        if isinstance(p.motion, Rotation):
            r = pts[:, :2] - np.asarray(p.motion.center, float)
            angle = np.arctan2(r[:, 1], r[:, 0])
            middle = np.angle(np.exp(1j * angle).sum())  # angles from the face's mean direction: no wrap inside
            turn = np.sign(p.motion.omega) or 1.0
            return turn * np.angle(np.exp(1j * (angle - middle))) * float(np.mean(np.hypot(r[:, 0], r[:, 1])))
        v = np.asarray(p.motion.velocity, float)
        return pts[:, :2] @ (v / (np.linalg.norm(v) or 1.0))

    @cached_property
    def _rows(self) -> np.ndarray:
        """Rows of the mortar that take part (facing the master over at least half their share, not held),
        ordered along the motion; a node held along some axes only is refused."""
        p = self.params
        c = p.coupling
        held = p.fixed[3 * c.slave_nodes[:, None] + np.arange(3)]
        reach = c.reach * c.weight  # the overlap before the rows were made consistent
        rows = np.flatnonzero(~held.all(axis=1) & (reach > 0.5 * c.weight))
        if len(rows) < 2:
            raise ParameterError("clamped_slave", list(p.clamped_slave), "groups that leave the slave's contact face "
                                 "free where it faces the master (at least two nodes)")
        return rows[np.argsort(self._position[rows], kind="stable")]

    @cached_property
    def frames(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(n, t, b)`` of every contact node (Cartesian unit vectors, ``b = n x t``)."""
        n, t = self.params.coupling.normal[self._rows], self.params.tangent[0][self._rows]
        return n, t, np.cross(n, t)

    @cached_property
    def _frame(self) -> np.ndarray:
        """``(nodes, 3, 3)``: rows ``n, t, b`` of each contact node's frame (for the kernel)."""
        return np.ascontiguousarray(np.stack(self.frames, axis=1))

    @cached_property
    def rotation(self) -> sp.csr_matrix:
        """``T`` with Cartesian ``u = T w`` on all dofs: ``w`` in ``(n, t, b)`` at the contact nodes."""
        n_all = self.params.fixed.size
        nodes = self.contact_nodes
        keep = np.ones(n_all, bool)
        for c in range(3):
            keep[3 * nodes + c] = False
        rows, cols, vals = [np.flatnonzero(keep)], [np.flatnonzero(keep)], [np.ones(int(keep.sum()))]
        for k, vec in enumerate(self.frames):  # column 3 i + k of w is along vec
            for comp in range(3):
                rows.append(3 * nodes + comp)
                cols.append(3 * nodes + k)
                vals.append(vec[:, comp])
        R = sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), shape=(n_all, n_all))
        turned = self.params.supports.rotation  # rollers along directions: their nodes' own frames (never contact nodes)
        return R if turned is None else sp.csr_matrix(turned @ R)

    @cached_property
    def partners(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(ptr, dof, weight)`` as `PairScheme.partners`, the x dof of each master node ``3 l``."""
        c, p = self.params.coupling, self.params
        M = c.M[self._rows].tocsr()
        M.sort_indices()
        weights = M.data / np.repeat(c.weight[self._rows], np.diff(M.indptr))
        dof = self._where[p.n_slave + 3 * M.indices[:, None] + np.arange(3)]  # -1 where held
        return M.indptr.astype(np.int64), np.ascontiguousarray(dof, dtype=np.int64), weights.astype(float)

    @cached_property
    def _dofs(self) -> np.ndarray:
        """``(nodes, 3)``: each contact node's dofs ``n, t, b`` in the scheme."""
        nodes = self.contact_nodes
        return np.ascontiguousarray(np.column_stack([self._where[3 * nodes + c] for c in range(3)]))

    @cached_property
    def contact_dofs(self) -> tuple[np.ndarray, np.ndarray]:
        return self._dofs[:, 0].copy(), self._dofs[:, 1].copy()

    @cached_property
    def cross_dofs(self) -> np.ndarray:
        """Each contact node's dof along ``b`` (across the sliding direction)."""
        return self._dofs[:, 2].copy()

    @cached_property
    def contact_matrix(self) -> sp.csr_matrix:
        """``R`` (free dofs x 3 contact nodes): column ``k nc + j`` the unit force of node ``j`` along
        ``n, t, b`` (``k = 0, 1, 2``) on every dof: ``R^T u`` is the relative motion ``(d_n, d_t, d_b)``."""
        ptr, dof, w = self.partners
        nc = self.nodes
        node = np.repeat(np.arange(nc), np.diff(ptr))
        rows, cols, vals = [], [], []
        for k, vec in enumerate(self.frames):
            rows.append(self._dofs[:, k])
            cols.append(k * nc + np.arange(nc))
            vals.append(np.ones(nc))
            for comp in range(3):
                held = dof[:, comp] >= 0
                rows.append(dof[held, comp])
                cols.append(k * nc + node[held])
                vals.append(-w[held] * vec[node[held], comp])
        return sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                             shape=(self.free.size, 3 * nc))

    # --- the interface of stickslip.contact ------------------------------------------------
    def new_output(self) -> SolidStepOutput:
        return SolidStepOutput.empty(self.free.size, self.nodes)

    def contact_work(self, lam_n, lam_t, du, lam_b=None):
        """As `PairScheme.contact_work`, with the force across the sliding direction ``lam_b`` in the
        frictional dissipation (against the relative motion ``d_b``; None: left out)."""
        m = self.mass[self.contact_dofs[0]]
        nc, speed = self.nodes, self.surface[1]
        rel = du @ self.contact_matrix
        F_t = m * lam_t
        drive = np.sum(F_t * speed * self.dt, axis=-1)
        friction = -np.sum(F_t * (rel[..., nc:2 * nc] - speed * self.dt), axis=-1)
        if lam_b is not None:
            friction = friction - np.sum(m * lam_b * rel[..., 2 * nc:], axis=-1)
        return drive, friction, np.sum(m * lam_n * rel[..., :nc], axis=-1)

    def steady_reactions(self, u: np.ndarray) -> np.ndarray:
        _, r_n, r_t = self.steady_reference()
        m, touching = self.mass[self.contact_dofs[0]], self.touching(u)
        forces = np.concatenate([touching * r_n * m, touching * r_t * m, np.zeros(self.nodes)])
        return (self.contact_matrix @ forces) / self.mass

    def snapshot_fields(self, out: SolidStepOutput, u: np.ndarray) -> dict:
        """The fields across the sliding direction of a snapshot at ``u``: ``W`` [m], ``Q_cross`` [N]."""
        m = self.mass[self.contact_dofs[0]]
        return {"W": u[self.cross_dofs], "Q_cross": m * out.lam_b}

    def advance(self, state: StepState, nsteps: int = 1, contact: bool = True, out: SolidStepOutput | None = None,
                *, sparse: bool = False) -> SolidStepOutput:
        nsteps = COMMON.check("nsteps", nsteps)
        out = self.new_output() if out is None else out
        gap0, speed = self.surface
        indptr, indices, data, block = self.kernel_operator
        ptr, dof, w = self.partners
        load = np.zeros(0) if self.load is None else np.ascontiguousarray(self.load, dtype=float)
        f, _, _ = self.kinetic_law
        sweeps = coupled_advance3(
            indptr, indices, data, block, load, np.array(self.damping, dtype=float), *self.gyroscopic_operator,
            state.u, state.v, state.a, self._dofs, self._frame, ptr, dof, w, 1.0 / self.mass, gap0, speed, nsteps,
            self.dt, self.beta2, f, self.static_friction, self.kernel_law, bool(contact), out.forces, out.state,
            out.u_prev, MAX_SWEEPS)
        self.check_sweeps(sweeps)
        return out

    # --- the contact surface as a line (see the module docstring) ----------------------------
    @cached_property
    def arclength(self) -> np.ndarray:
        s = self._position[self._rows]
        return s - s.min()

    @cached_property
    def theta(self) -> np.ndarray:
        """``2 pi k / N`` for the ``k``-th of the ``N`` contact nodes along the motion (their positions are
        in `arclength`; nodes across the width would share a position, and the classification steps by
        the spacing of ``theta``)."""
        count = len(self._rows)
        return 2.0 * np.pi * np.arange(count) / count

    @property
    def line_length(self) -> float:
        return float(self.arclength[-1]) or float(np.ptp(self.params.slave.body.points[self.contact_nodes], axis=0).max())

    @cached_property
    def p_wave_speed(self) -> float:
        return _p_wave_speed(self.params.slave)


#: The fields across the sliding direction a run of solids adds to the plane ones (`SolidPairScheme.snapshot_fields`).
ACROSS = {"W": ("length", "displacement of the slave contact node across the sliding direction (along b = n x t)"),
          "Q_cross": ("traction", "friction force on the slave contact node across the sliding direction (along "
                                  "b = n x t)")}

_FORMAT = dataclasses.replace(
    PairRun.FORMAT,
    units={"length": "m", "velocity": "m/s", "traction": "N"},
    notes={**PairRun.FORMAT.notes,
           "P": "normal contact force on the slave node", "Q": "friction force on the slave node along the master's "
           "motion (along t)", "gap": "normal gap of the slave node to the master at t_{m+1}",
           **{f"vol_{x}": f"{what} of every free dof of both solids (slave first; volume snapshot) in the scheme's "
                          "frames: n, t, b at the slave's contact nodes, x, y, z elsewhere (SolidPairScheme.cartesian "
                          "gives x, y, z everywhere)" for x, what in (("u", "displacement"), ("v", "velocity"))}},
    energy_units="J", energy_note="energy of both solids' deviation from steady sliding",
    source="two solids in contact (3-D mortar), explicit beta2 scheme [22] with multipliers [23] between the bodies, "
           "a Coulomb disc per node (stickslip.fem.pair_run3)",
    scheme=SolidPairScheme, title="run of two solids in frictional contact",
    position_note="rank k of the slave contact node along the master's motion as an angle, 2 pi k / N (its position "
                  "is the coordinate arclength; the span is the attribute line_length)",
    extra_fields=lambda s: ACROSS,
    extra_coords=lambda s: {"arclength": (s.arclength, {"units": "m", "long_name": "position of the slave contact "
                                                                                 "node along the master's motion"})})


@dataclass(frozen=True, eq=False, repr=False)
class SolidPairRun(PairRun):
    """Result of `stickslip.fem.pair_run.integrate_pair` for two solids (see the module docstring)."""

    FORMAT: ClassVar = _FORMAT


SOLVERS[3] = (SolidPairScheme, SolidPairRun)
