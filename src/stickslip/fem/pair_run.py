"""Explicit runs of two deformable bodies in contact: a pad on a sliding or turning partner.

`PairScheme` is the shared explicit beta2 scheme (`stickslip.contact`) on a `PairProblem`:
both bodies' free dofs in one vector (the slave's first), the slave's contact nodes in their
frames ``(n, t)`` (Cartesian elsewhere), and the forward-increment multipliers between the
bodies of `stickslip.contact.coupled` on the mortar's weights ``w_jl = M_jl / D_jj``: the same
contact conditions as steady sliding and the CEA (`stickslip.fem.pair`), so that steady
sliding is a state of the scheme.

**The partner's motion is Eulerian.** The master's mesh stays where it is and its material
slides through it at the motion's speed (``t_j`` and ``speed`` at each slave node, as in steady
sliding): its displacements are the deformation seen in space-fixed coordinates, which suits
a disc turning under a pad (no contact search; the contact line does not move). By default
the scheme leaves out the transport terms of the turning material (the usual engineering
treatment, whose effect on the CEA is measured in ``docs/tutorial-your-body.md``); with
``gyroscopic=True`` they are in: the transport softening in the stiffness (the problem's
``K``) and the gyroscopic matrix on the velocity ``v_{m-1}``, as the Rayleigh damping
(`PairScheme.gyroscopic_operator`; first order in the step, as that damping).

`integrate_pair` runs it with every book of `stickslip.contact.runs` (series, snapshots of
the slave's contact nodes, volume snapshots, checkpoints, the limit regime), and
`PairScheme.contact_work` splits the contact forces' work into the drive's work, the
frictional dissipation and the normal work on the *relative* motion of the bodies, so that
the energy books (`stickslip.contact.energy_books`) check that the forces act equal and
opposite on both bodies.

Units SI: time [s], displacements [m], ``P, Q`` [N/m] per slave node (the normal and friction
force on it per unit thickness).
"""

from __future__ import annotations

import dataclasses
from dataclasses import dataclass
from functools import cached_property
from typing import Callable, ClassVar

import numpy as np
import scipy.sparse as sp

from ..contact.coupled import coupled_advance
from ..contact.runs import RunRecord, prepare, run_explicit
from ..contact.scheme import StepOutput, StepState
from ..errors import NoSolutionError, ParameterError
from ..quantities import COMMON
from .pair import PairProblem
from .run import BodyRun, perturbed_steady_body
from .scheme import FemScheme, kernel_friction
from .surfaces import order_along

__all__ = ["PairScheme", "PairRun", "integrate_pair", "MAX_SWEEPS", "SOLVERS", "check_supports"]

#: Gauss-Seidel sweeps over the contact nodes per step, at most (`stickslip.contact.coupled`).
MAX_SWEEPS = 1000


def check_supports(problem: PairProblem) -> None:
    """Refuse a contact node (the slave's, or a master's node facing it) held along some axes but not
    all (rollers through a contact face): the explicit scheme writes each slave contact node in its
    own frame and solves the forces node by node on nodes free or clamped."""
    c, dim = problem.coupling, problem.dimension
    facing = np.unique(c.M.tocoo().col)
    for who, nodes, offset in (("slave", c.slave_nodes, 0), ("master", facing, problem.n_slave)):
        held = problem.fixed[offset + dim * np.asarray(nodes)[:, None] + np.arange(dim)]
        partly = held.any(axis=1) & ~held.all(axis=1)
        if partly.any():
            group = problem.slave_group if who == "slave" else problem.master_group
            raise ParameterError(f"rollers_{who}", getattr(problem, f"rollers_{who}"), f"rollers that hold no node of "
                                 f"the contact group {group!r} along some axes only in an explicit run (node "
                                 f"{int(np.asarray(nodes)[partly][0])} is: each contact node is free or clamped)")


@dataclass(frozen=True, eq=False)
class PairScheme(FemScheme):
    """The explicit scheme of a `PairProblem` (``beta2`` in [1/2, 1], ``courant`` in (0, 1];
    ``time_step`` [s], if given, replaces ``courant * dt_max`` and may not exceed it)."""

    PARAMS: ClassVar[type] = PairProblem
    params: PairProblem
    beta2: float = 0.9
    courant: float = 0.9
    time_step: float | None = None

    def __post_init__(self):
        if isinstance(self.params, PairProblem) and self.params.dimension == 3:
            raise ParameterError("params", "a pair of solids", "a pair of plane bodies (a pair of solids: "
                                 "stickslip.fem.pair_run3.SolidPairScheme)")
        self.validate_common()
        check_supports(self.params)
        self.check_time_step()
        _ = self.kinetic_law  # a law the kernel is not compiled for is refused here, before anything runs

    # --- friction: the problem's law, static coefficient and pressure law -------------------
    @property
    def kinetic_law(self) -> tuple[float, int, float]:
        """``(f_d, kind, parameter)`` of the problem's law for the kernel (`kernel_friction`)."""
        return kernel_friction(self.params.law, self.params.friction)

    @property
    def static_friction(self) -> float:
        return float(self.params.static_friction)

    @cached_property
    def pressure_scaling(self) -> tuple[float, np.ndarray]:
        """With the problem's ``pressure_law``: its exponent and, per contact node, ``1 / (D_jj P_ref)``
        (the coupled kernel's normal force over it is ``P / P_ref``); else none."""
        law = self.params.pressure_law
        if law is None:
            return (0.0, np.zeros(0))
        return (float(law.exponent), 1.0 / (self.params.coupling.weight[self._rows] * law.reference))

    # --- the dofs ------------------------------------------------------------------------
    @cached_property
    def free(self) -> np.ndarray:
        """The free dofs of the pair (slave first), indices into all of them."""
        return np.flatnonzero(~self.params.fixed)

    @cached_property
    def _rows(self) -> np.ndarray:
        """Rows of the mortar (slave nodes) that take part, in order along the slave line: not
        clamped, and facing the master over at least half their share of the line."""
        p = self.params
        c = p.coupling
        edges = p.slave.body.segments(p.slave_group, "slave_group")
        along = order_along(p.slave.body.points, edges, np.unique(edges))
        row_of = {int(v): k for k, v in enumerate(c.slave_nodes)}
        reach = c.reach * c.weight  # the overlap before the rows were made consistent
        rows = [row_of[int(v)] for v in along]
        rows = [r for r in rows if not p.fixed[2 * c.slave_nodes[r]] and reach[r] > 0.5 * c.weight[r]]
        if len(rows) < 2:
            raise ParameterError("clamped_slave", list(p.clamped_slave), "groups that leave the slave's contact line "
                                 "free where it faces the master (at least two nodes)")
        return np.asarray(rows)

    @cached_property
    def contact_nodes(self) -> np.ndarray:
        """The slave's contact nodes of the scheme (its mesh indices), in order along the line."""
        return self.params.coupling.slave_nodes[self._rows]

    @cached_property
    def frames(self) -> tuple[np.ndarray, np.ndarray]:
        """``(n, t)`` of every contact node (Cartesian unit vectors)."""
        return self.params.coupling.normal[self._rows], self.params.tangent[0][self._rows]

    @cached_property
    def rotation(self) -> sp.csr_matrix:
        """``T`` with Cartesian ``u = T w`` on all dofs: ``w`` in ``(n, t)`` at the contact nodes."""
        n_all = self.params.fixed.size
        nodes = self.contact_nodes
        (nv, tv), keep = self.frames, np.ones(n_all, bool)
        keep[2 * nodes], keep[2 * nodes + 1] = False, False
        rows, cols, vals = [np.flatnonzero(keep)], [np.flatnonzero(keep)], [np.ones(int(keep.sum()))]
        for comp in (0, 1):
            rows += [2 * nodes + comp, 2 * nodes + comp]
            cols += [2 * nodes, 2 * nodes + 1]
            vals += [nv[:, comp], tv[:, comp]]
        R = sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))), shape=(n_all, n_all))
        turned = self.params.supports.rotation  # rollers along directions: their nodes' own frames (never contact nodes)
        return R if turned is None else sp.csr_matrix(turned @ R)

    def cartesian(self, w: np.ndarray) -> np.ndarray:
        """Free-dof vector(s) of the scheme -> Cartesian displacements of all dofs (slave first)."""
        full = np.zeros(np.shape(w)[:-1] + (self.params.fixed.size,))
        full[..., self.free] = w
        return full @ self.rotation.T

    @cached_property
    def _where(self) -> np.ndarray:
        where = np.full(self.params.fixed.size, -1, dtype=np.int64)
        where[self.free] = np.arange(self.free.size)
        return where

    @cached_property
    def partners(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``(ptr, dof, weight)``: for contact node ``j``, entries ``ptr[j]:ptr[j + 1]`` give the x
        dof (scheme numbering; -1 if clamped) of each master node facing it and its weight
        ``M_jl / D_jj``."""
        c, p = self.params.coupling, self.params
        M = c.M[self._rows].tocsr()
        M.sort_indices()
        weights = M.data / np.repeat(c.weight[self._rows], np.diff(M.indptr))
        dof = self._where[p.n_slave + 2 * M.indices]
        return M.indptr.astype(np.int64), dof.astype(np.int64), weights.astype(float)

    @cached_property
    def contact_matrix(self) -> sp.csr_matrix:
        """``R`` (free dofs x 2 contact nodes): column ``j`` the normal force of node ``j`` on
        every dof (+1 on its normal dof, ``-w_jl n_j`` on the master nodes), column ``nc + j`` the
        tangential one: ``R^T u`` is the relative motion ``(d_n, d_t)``."""
        normal, tangent = self.contact_dofs
        ptr, dof, w = self.partners
        nv, tv = self.frames
        nc = normal.size
        node = np.repeat(np.arange(nc), np.diff(ptr))
        held = dof >= 0
        rows, cols, vals = [normal, tangent], [np.arange(nc), nc + np.arange(nc)], [np.ones(nc), np.ones(nc)]
        for col0, vec in ((0, nv), (nc, tv)):
            for comp in (0, 1):
                rows.append(dof[held] + comp)
                cols.append(col0 + node[held])
                vals.append(-w[held] * vec[node[held], comp])
        return sp.csr_matrix((np.concatenate(vals), (np.concatenate(rows), np.concatenate(cols))),
                             shape=(self.free.size, 2 * nc))

    # --- the interface of stickslip.contact ----------------------------------------------
    @cached_property
    def mass(self) -> np.ndarray:
        return self.params.mass[self.free]

    @cached_property
    def stiffness(self) -> sp.csr_matrix:
        return (self.rotation.T @ self.params.K @ self.rotation).tocsr()[self.free][:, self.free]

    def operator_matrix(self):
        return (sp.diags(1.0 / self.mass) @ self.stiffness).tocsr()

    @cached_property
    def gyroscopic_operator(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        """``M^{-1} G`` in CSR ``(indptr, indices, data)`` on the free dofs in the scheme's frames:
        the turning master's gyroscopic matrix (with ``gyroscopic``; its transport softening is in
        `stiffness`, through the problem's ``K``), or empty (``indptr = [0]``)."""
        if self.params.transport is None:
            return np.zeros(1, np.int64), np.zeros(0, np.int64), np.zeros(0)
        G = (self.rotation.T @ self.params.transport[0] @ self.rotation).tocsr()[self.free][:, self.free]
        A = (sp.diags(1.0 / self.mass) @ G).tocsr()
        A.sort_indices()
        return A.indptr.astype(np.int64), A.indices.astype(np.int64), A.data.astype(float)

    @property
    def closed_line(self) -> bool:
        return False

    @cached_property
    def load(self) -> np.ndarray | None:
        F = self.params.load
        return None if not F.any() else (self.rotation.T @ F)[self.free] / self.mass

    @cached_property
    def contact_dofs(self) -> tuple[np.ndarray, np.ndarray]:
        nodes = self.contact_nodes
        return self._where[2 * nodes], self._where[2 * nodes + 1]

    @cached_property
    def surface(self) -> tuple[np.ndarray, np.ndarray]:
        """``(gap0, speed)``: ``d_n >= gap0 = -g_j / D_jj`` (the reference gap) and the master's speed."""
        p, r = self.params, self._rows
        return -p.gap[r] / p.coupling.weight[r], p.tangent[1][r].astype(float)

    def steady_reference(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        st, p, r = self.params.steady, self.params, self._rows
        w = (self.rotation.T @ st.u)[self.free]
        force = p.coupling.weight[r] * st.pressure[r]  # D_jj lambda_j [N/m]
        r_n = force / self.mass[self.contact_dofs[0]]
        return w, r_n, st.coefficients[r] * r_n

    def gaps(self, u: np.ndarray) -> np.ndarray:
        return (self.contact_matrix[:, : self.nodes].T @ u) - self.surface[0]

    def touching(self, u: np.ndarray) -> np.ndarray:
        """``d_n <= gap0`` to a picometre (steady sliding's active nodes, to round-off)."""
        return self.gaps(u) <= 1e-12

    def contact_work(self, lam_n, lam_t, du):
        m = self.mass[self.contact_dofs[0]]
        nc, speed = self.nodes, self.surface[1]
        rel = du @ self.contact_matrix
        F_n, F_t = m * lam_n, m * lam_t
        drive = np.sum(F_t * speed * self.dt, axis=-1)
        return drive, -np.sum(F_t * (rel[..., nc:] - speed * self.dt), axis=-1), np.sum(F_n * rel[..., :nc], axis=-1)

    def steady_reactions(self, u: np.ndarray) -> np.ndarray:
        """The steady forces per unit mass on both bodies (equal and opposite) where the slave
        touches at ``u`` (``d_n <= gap0``)."""
        _, r_n, r_t = self.steady_reference()
        m, touching = self.mass[self.contact_dofs[0]], self.touching(u)
        return (self.contact_matrix @ np.concatenate([touching * r_n * m, touching * r_t * m])) / self.mass

    def advance(self, state: StepState, nsteps: int = 1, contact: bool = True, out: StepOutput | None = None, *,
                sparse: bool = False) -> StepOutput:
        nsteps = COMMON.check("nsteps", nsteps)
        out = self.new_output() if out is None else out
        (normal, tangent), (gap0, speed) = self.contact_dofs, self.surface
        indptr, indices, data, block = self.kernel_operator
        ptr, dof, w = self.partners
        nv, tv = self.frames
        load = np.zeros(0) if self.load is None else np.ascontiguousarray(self.load, dtype=float)
        f, _, _ = self.kinetic_law
        sweeps = coupled_advance(
            indptr, indices, data, block, load, np.array(self.damping, dtype=float), *self.gyroscopic_operator,
            state.u, state.v, state.a,
            normal, tangent, np.ascontiguousarray(nv), np.ascontiguousarray(tv), ptr, dof, w, 1.0 / self.mass, gap0,
            speed, nsteps, self.dt, self.beta2, f, self.static_friction, self.kernel_law,
            bool(contact), out.lam_n, out.lam_t, out.state, out.u_prev, MAX_SWEEPS)
        self.check_sweeps(sweeps)
        return out

    def check_sweeps(self, sweeps: int) -> None:
        """Keep the most Gauss-Seidel sweeps a step of the last call took (``last_sweeps``); refuse a step
        whose contact forces did not converge."""
        object.__setattr__(self, "last_sweeps", int(sweeps))
        if sweeps > MAX_SWEEPS:
            raise NoSolutionError(f"the contact forces between the bodies did not converge in {MAX_SWEEPS} "
                                  "Gauss-Seidel sweeps in a step (a partner far lighter than the pad's nodes, or a "
                                  "step too long for the contact's stiffness); a run's checkpoint keeps its last "
                                  "good sample")

    # --- time and the contact line ---------------------------------------------------------
    @cached_property
    def arclength(self) -> np.ndarray:
        pts = self.params.slave.body.points[self.contact_nodes]
        return np.concatenate([[0.0], np.cumsum(np.hypot(*np.diff(pts, axis=0).T))])

    @property
    def line_length(self) -> float:
        return float(self.arclength[-1])

    @cached_property
    def theta(self) -> np.ndarray:
        return 2.0 * np.pi * self.arclength / self.line_length

    @cached_property
    def p_wave_speed(self) -> float:
        slave = self.params.slave
        return slave.p_wave_speed(slave.body.cells_along(self.params.slave_group))



_FORMAT = dataclasses.replace(
    BodyRun.FORMAT,
    notes={"P": "normal contact force on the slave node per unit thickness",
           "Q": "friction force on the slave node per unit thickness, along the master's motion",
           "gap": "normal gap of the slave node to the master at t_{m+1}",
           **{f"vol_{x}": f"{what} of every free dof of both bodies (slave first; volume snapshot) in the scheme's "
                          "frames: normal and tangent at the slave's contact nodes, x and y elsewhere "
                          "(PairScheme.cartesian gives x and y everywhere)"
              for x, what in (("u", "displacement"), ("v", "velocity"))}},
    energy_note="energy of both bodies' deviation from steady sliding (per unit thickness)",
    node_label="slave contact node",
    source="two 2-D bodies in contact (mortar), explicit beta2 scheme [22] with multipliers [23] between the bodies "
           "(stickslip.fem.pair_run)",
    scheme=PairScheme, params_type=PairProblem, title="run of two bodies in frictional contact",
    position_note="position of the slave contact node along the slave's contact line as an angle, 2 pi s / L "
                  "(s its arclength from the first node, L the line's length, attribute line_length)",
    mode_note="Fourier mode in theta along the contact line (not periodic: a description, not waves)",
    extra_coords=lambda s: {"arclength": (s.arclength, {"units": "m", "long_name": "arclength of the slave contact "
                                                                                 "node from the line's first node"})})


@dataclass(frozen=True, eq=False, repr=False)
class PairRun(RunRecord):
    """Result of `integrate_pair` (see the module docstring for the units)."""

    FORMAT: ClassVar = _FORMAT
    MODEL: ClassVar[str] = "fem"


#: The scheme and the record of a pair's run by its dimension (3: `stickslip.fem.pair_run3`, which
#: adds itself when `stickslip.fem` is imported).
SOLVERS: dict = {2: (PairScheme, PairRun)}


def integrate_pair(problem: PairProblem, t_end: float | None = None, *, transits: float | None = None,
                   amplitude: float = 1e-3, seed: int = 0, beta2: float = 0.9, courant: float = 0.9,
                   time_step: float | None = None, samples_per_transit: int = 32, snapshot_every: float = 1.0,
                   tail: float = 2.0, modes: int = 32, contact: bool = True, checkpoint=None,
                   every: float | None = None, progress: Callable[[float, float], None] | None = None,
                   overwrite: bool = False, volume_every: float | None = None) -> PairRun:
    """Run ``problem`` from steady sliding, its slave's contact nodes perturbed tangentially by
    white noise of RMS ``amplitude`` times the largest steady displacement there (``seed``), up
    to ``t_end`` [s] or ``transits`` of a P-wave along the slave's contact line; the other
    options as `stickslip.fem.integrate_body`'s. A pair of solids runs `stickslip.fem.pair_run3.SolidPairScheme`
    and returns a `stickslip.fem.pair_run3.SolidPairRun`."""
    if not isinstance(problem, PairProblem):
        raise ParameterError("problem", problem, "a PairProblem")
    scheme_type, cls = SOLVERS[problem.dimension]
    scheme = scheme_type(problem, beta2, courant, time_step)
    initial = perturbed_steady_body(scheme, amplitude, seed)
    t_end, settings = prepare(scheme, t_end=t_end, transits=transits, samples_per_transit=samples_per_transit,
                              snapshot_every=snapshot_every, tail=tail, modes=modes, contact=contact,
                              initial=initial, progress=progress, volume_every=volume_every)
    return run_explicit(cls, scheme, initial.u, initial.v, settings, t_end, checkpoint=checkpoint, every=every,
                        progress=progress, overwrite=overwrite)

