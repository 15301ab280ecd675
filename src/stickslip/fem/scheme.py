"""A general body on a rigid counter-surface as an explicit contact scheme of `stickslip.contact`.

`ContactProblem` gathers what the scheme needs: the assembled body (`BodySystem`), the
frames of its contact nodes against the surface (`ContactFrames`), the Coulomb coefficient
and the clamped boundary groups. `BodyScheme` is the shared explicit beta2 scheme with
forward-increment multipliers ([22]-[23], `stickslip.contact.kernel`) on the general path:
the operator ``M^{-1} K`` is a sparse matrix on the free dofs, written in the nodal frames
``(n, t)`` at the contact nodes (Cartesian elsewhere), so that the kernel finds each
contact node's normal and tangential dof. The stable step comes from the largest free
frequency of the mesh (Lanczos on ``M^{-1/2} K M^{-1/2}``), the zero of the energy and the
start of a run from steady sliding (`stickslip.fem.static.steady_contact`).

Units are SI: time in s, displacements in m, reactions per unit mass in m/s^2. The
contact line's nodes are placed at ``theta = 2 pi s / L`` (``s`` the arclength, ``L`` the
line's length) for the shared classification; an open line (``frames.closed`` false) is
classified without travelling waves around it (`stickslip.contact.classify`).
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from functools import cached_property
from typing import ClassVar

import numpy as np
import scipy.sparse as sp
import scipy.sparse.linalg as sla

from .. import validation as check
from ..quantities import FEM as Q
from ..contact import ExplicitScheme
from ..errors import ParameterError
from ..contact.kernel import COULOMB, LINEAR_WEAKENING, STRIBECK
from ..friction import Coulomb, FrictionLaw, LinearWeakening, PressurePower, Stribeck
from .assembly import BodySystem
from .boundary import tributary_lengths
from .static import SteadyContact, frame_rotation, problem_attrs, steady_contact
from .surfaces import ContactFrames

__all__ = ["ContactProblem", "FemScheme", "BodyScheme", "MAX_OVERDAMPING", "check_damping", "kernel_friction"]

#: The most an explicit run lets Rayleigh damping overdamp the mesh's highest mode (times critical).
MAX_OVERDAMPING = 100.0


def check_damping(materials: dict, omega_max: float) -> tuple[float, float]:
    """The one Rayleigh damping ``(alpha, beta)`` of an explicit run's ``materials`` (the
    `Material` of each group), refused if it would make the run crawl: the highest mode
    (``omega_max`` [rad/s]) damped more than ``MAX_OVERDAMPING`` times critically, ``alpha + beta
    omega_max^2 > 2 MAX_OVERDAMPING omega_max``. The stable step shrinks about in proportion
    (``beta omega_max = 1e6`` asks for some 1e6 times more steps). The CEA has no step: any
    damping within the material's ranges goes. The explicit scheme damps with one ``(alpha,
    beta)``: materials with different ones are refused here (steady sliding and the CEA take
    them)."""
    lossy = {k: m.loss_factor for k, m in materials.items() if getattr(m, "loss_factor", 0.0)}
    if lossy:
        raise ParameterError("material.loss_factor", ", ".join(f"{k or 'body'}: {v:g}" for k, v in lossy.items()),
                             "0 in an explicit run (a structural loss factor, a stiffness times (1 + i eta), is a "
                             "model of the frequency domain: the CEA takes it; damp a run with alpha and beta)")
    pairs = {(m.alpha, m.beta) for m in materials.values()}
    if len(pairs) > 1:
        names = ", ".join(f"{k}: alpha = {m.alpha:g}, beta = {m.beta:g}" for k, m in materials.items())
        raise ParameterError("material.alpha", names, "one Rayleigh damping (alpha, beta) for every material of an "
                             "explicit run (its scheme damps the whole body with one pair; steady sliding and the "
                             "CEA take one per material)", also=("material.beta",))
    alpha, beta = pairs.pop()
    if alpha == 0.0 and beta == 0.0:
        return (0.0, 0.0)
    w, top = omega_max, 2.0 * MAX_OVERDAMPING * omega_max
    if alpha + beta * w * w > top * (1.0 + 1e-12):
        name, value, most = ("beta", beta, (top - alpha) / (w * w)) if beta > 0 else ("alpha", alpha, top)
        raise ParameterError(name, value, f"<= {max(most, 0.0):.4g} {'s' if name == 'beta' else '1/s'} on this "
                             f"mesh for an explicit run: alpha + beta omega_max^2 <= {2 * MAX_OVERDAMPING:g} "
                             f"omega_max, its highest mode (omega_max = {w:.4g} rad/s) at most {MAX_OVERDAMPING:g} "
                             "times critically damped (the stable step shrinks in proportion)",
                             also=("alpha" if name == "beta" else "beta",))
    return (float(alpha), float(beta))


def kernel_friction(law, friction: float) -> tuple[float, int, float]:
    """``(f_d, kind, parameter)`` of a friction ``law`` for the compiled kernel
    (`stickslip.contact.kernel.kinetic_coefficient`): linear weakening and Stribeck with their own
    kinetic coefficient, Coulomb (or no law) with ``friction``; a user's law is refused (the
    kernel is compiled for these; steady sliding and the CEA take any law)."""
    if isinstance(law, LinearWeakening):
        return (float(law.fd), LINEAR_WEAKENING, float(law.tau))
    if isinstance(law, Stribeck):
        return (float(law.fd), STRIBECK, float(law.vs))
    if law is not None and not isinstance(law, Coulomb):
        raise ParameterError("law", law, "Coulomb, linear weakening or Stribeck in an explicit run (the kernel "
                             "is compiled for these; a user's law is taken by steady sliding and the CEA)")
    return (float(friction), COULOMB, 0.0)


@dataclass(frozen=True, eq=False)
class ContactProblem:
    """A body (``system``), its contact ``frames``, the kinetic Coulomb coefficient
    ``friction``, the names of its ``clamped`` boundary groups and the static coefficient
    ``static_friction >= friction`` (None: the same, plain Coulomb).

    Or a friction ``law`` that depends on the slip speed (`stickslip.friction`: Stribeck,
    linear weakening, a user's law), instead of ``friction`` and ``static_friction``: steady
    sliding slips at the surface's speed ``V`` (the same at every contact node of a rigid
    surface), so ``friction`` becomes ``law.kinetic(V)`` and ``static_friction``
    ``law.static``; the CEA adds the slope ``law.slope(V)`` (a falling law is negative damping,
    `stickslip.fem.cea.linearised`). An explicit run takes each slipping node's kinetic
    coefficient at its own slip speed (`BodyScheme.kinetic_law`), sticking with ``law.static``.

    And ``pressure_law`` (`stickslip.friction.PressurePower`), a coefficient that depends on the
    contact pressure too: each node's coefficients (kinetic and static) are the law's times
    ``(P / reference)^(-exponent)`` at its own pressure ``P`` (its normal force over its
    tributary length), in steady sliding (`steady_contact`), in the CEA (the friction force's
    derivative ``mu (1 - exponent)`` in the tangential rows) and in an explicit run (node by node,
    `BodyScheme.pressure_scaling`)."""

    system: BodySystem
    frames: ContactFrames
    friction: float = 0.0
    clamped: tuple = ()
    static_friction: float | None = None
    law: FrictionLaw | None = None
    pressure_law: PressurePower | None = None

    def __post_init__(self):
        if not isinstance(self.system, BodySystem):
            raise ParameterError("system", self.system, "a BodySystem (see assemble)")
        if not isinstance(self.frames, ContactFrames):
            raise ParameterError("frames", self.frames, "ContactFrames (see contact_frames)")
        if self.law is not None:
            self._from_law()
        if self.pressure_law is not None and not isinstance(self.pressure_law, PressurePower):
            raise ParameterError("pressure_law", self.pressure_law, "a stickslip.friction.PressurePower or None")
        object.__setattr__(self, "friction", Q.check("friction", self.friction))
        fs = self.friction if self.static_friction is None else self.static_friction
        object.__setattr__(self, "static_friction", check.at_least("static_friction", Q.check("static_friction", fs), self.friction, "friction"))
        if self.friction > 0 and not np.all(self.frames.speed > 0):
            raise ParameterError("frames", "of a surface at rest", "the frames of a moving surface when friction > 0 "
                                 "(a surface at rest gives friction no sliding direction)", also=("friction",))
        if isinstance(self.clamped, str) or not isinstance(self.clamped, (list, tuple)) or \
                not all(isinstance(c, str) for c in self.clamped):
            raise ParameterError("clamped", self.clamped, "a list of boundary group names")
        object.__setattr__(self, "clamped", tuple(self.clamped))
        for name in self.clamped:
            self.system.body.nodes(name, "clamped")
        body = self.system.body
        for kind, items in (("spring", self.system.springs), ("load", self.system.loads)):
            for i, item in enumerate(items):
                if np.all(self.fixed[2 * body.nodes(item.group)]):
                    raise ParameterError("clamped", list(self.clamped), f"groups that leave a node of {kind}[{i}] on "
                                         f"{item.group!r} free (they hold all of them: the {kind} would act on "
                                         "nothing)")
        free = int(np.sum(~self.fixed[2 * self.frames.nodes]))
        if free < 2:
            raise ParameterError("clamped", list(self.clamped), f"groups that leave the contact line free (they hold "
                                 f"{len(self.frames.nodes) - free} of its {len(self.frames.nodes)} nodes: a clamped "
                                 "node is held by the clamp, not the contact)")

    def _from_law(self) -> None:
        """``friction`` and ``static_friction`` from ``law`` at the surface's speed."""
        law = self.law
        if not isinstance(law, FrictionLaw):
            raise ParameterError("law", law, "a friction law of stickslip.friction (Stribeck, LinearWeakening, "
                                 "UserLaw, Coulomb) or None")
        if self.friction != 0.0 or self.static_friction is not None:
            raise ParameterError("friction", self.friction, "left out with a law (the law gives the kinetic "
                                 "coefficient at the sliding speed, and the static one)", also=("law",))
        speed = np.asarray(self.frames.speed, dtype=float)
        if speed.size == 0 or np.ptp(speed) > 1e-9 * np.abs(speed).max() or not speed.max() > 0:
            raise ParameterError("frames", "of a surface at rest or of uneven speed", "a surface moving at one "
                                 "speed along the contact line (the law is taken at it)", also=("law",))
        if speed.max() >= law.max_speed:
            raise ParameterError("law", law, f"a law valid at the sliding speed {speed.max():.6g} m/s (this one up "
                                 f"to {law.max_speed:.6g} m/s)")
        object.__setattr__(self, "friction", float(law.kinetic(float(speed.max()))))
        object.__setattr__(self, "static_friction", float(law.static))

    @property
    def friction_slope(self) -> float:
        """``d mu / d v_r`` [s/m] at the sliding speed (0 without a law: Coulomb)."""
        if self.law is None:
            return 0.0
        return float(self.law.slope(float(np.max(self.frames.speed))))

    @cached_property
    def fixed(self) -> np.ndarray:
        """Mask of the clamped dofs (all ``2 n`` of them)."""
        mask = np.zeros(self.system.n_dofs, bool)
        for name in self.clamped:
            mask[self.system.dofs(self.system.body.nodes(name, "clamped"))] = True
        return mask

    @cached_property
    def steady(self) -> SteadyContact:
        return steady_contact(self.system, self.frames, self.friction, self.clamped,
                              static_friction=self.static_friction, pressure_law=self.pressure_law)

    @cached_property
    def tributary(self) -> np.ndarray:
        """Each contact node's tributary length [m] (`stickslip.fem.boundary.tributary_lengths`), in
        the order of ``frames.nodes``: its normal force over it is its pressure."""
        return tributary_lengths(self.system.body, self.frames.group)[self.frames.nodes]

    @cached_property
    def omega_max(self) -> float:
        """Largest free angular frequency [rad/s] of the clamped body (Lanczos; 1e-6 relative
        margin): it sets the stable step of every scheme of this problem."""
        free = ~self.fixed
        scale = sp.diags(1.0 / np.sqrt(self.system.mass[free]))
        A = (scale @ self.system.K[free][:, free] @ scale).tocsc()
        start = np.random.default_rng(0).standard_normal(A.shape[0])  # a fixed start: the same step every time
        lam = sla.eigsh(A, k=1, which="LA", return_eigenvectors=False, tol=1e-10, v0=start)
        return float(np.sqrt(lam[0]) * (1.0 + 1e-6))

    @property
    def materials(self) -> dict:
        """The body's materials (`BodySystem.materials`)."""
        return self.system.materials

    def check_damping(self) -> None:
        """Refuse Rayleigh damping an explicit run cannot take (`check_damping`)."""
        check_damping(self.materials, self.omega_max)

    @cached_property
    def digest(self) -> str:
        """SHA-256 of the mesh, the stiffness (with its springs), the load, the contact frames and
        the clamped dofs: what a checkpoint must share."""
        h = hashlib.sha256()
        body, f = self.system.body, self.frames
        K = self.system.K
        for arr in (body.points, body.cells, f.nodes, f.normal, f.tangent, f.gap, f.speed, self.fixed, K.indptr,
                    K.indices, K.data, self.system.load):
            h.update(np.ascontiguousarray(arr).tobytes())
        if self.pressure_law is not None:
            h.update(repr((self.pressure_law.reference, self.pressure_law.exponent)).encode())
        return h.hexdigest()

    def to_attrs(self) -> dict:
        """The problem as netCDF attributes (`stickslip.fem.static.problem_attrs`) and its digest;
        with a law, its description and slope."""
        law = {} if self.law is None else {"friction_law": repr(self.law), "friction_slope": self.friction_slope}
        if self.pressure_law is not None:
            law |= {"pressure_exponent": self.pressure_law.exponent, "reference_pressure": self.pressure_law.reference}
        return {**problem_attrs(self.system, self.frames, self.friction, self.clamped, self.static_friction),
                **law, "problem_sha256": self.digest}

    def to_dict(self) -> dict:
        return self.to_attrs()


class FemScheme(ExplicitScheme):
    """What the explicit schemes of `stickslip.fem` share (SI units): an optional ``time_step``
    [s] instead of ``courant * dt_max`` (at most ``dt_max``), the transit time of a P-wave along
    the contact line (``line_length / p_wave_speed``) and the run key."""

    time_step: float | None

    @property
    def problem(self):
        """The problem the scheme discretises in time (its ``params``; a specialisation such as
        the paper's annulus, whose ``params`` are its own, gives its general problem here)."""
        return self.params

    def check_time_step(self) -> None:
        """Refuse a ``time_step`` beyond the stable step (call in ``__post_init__``)."""
        if self.time_step is not None:
            step = Q.check("time_step", self.time_step)
            if step > self.dt_max:
                raise ParameterError("time_step", step, f"<= the stable step {self.dt_max:.6g} s of this mesh "
                                     f"(its highest mode: omega_max = {self.omega_max:.6g} rad/s, with its damping)")

    @property
    def omega_max(self) -> float:
        """Largest free angular frequency [rad/s] of the problem (its ``omega_max``)."""
        return self.problem.omega_max

    @cached_property
    def damping(self) -> tuple[float, float]:
        """The one Rayleigh damping ``(alpha [1/s], beta [s])`` of the problem's materials,
        refused if an explicit run cannot take it (`check_damping`)."""
        return check_damping(self.problem.materials, self.omega_max)

    @cached_property
    def dt_max(self) -> float:
        """The stable step (`ExplicitScheme.dt_max`), once the damping is checked (`damping`)."""
        _ = self.damping
        return ExplicitScheme.dt_max.func(self)

    @property
    def dt(self) -> float:
        """``time_step`` if given (at most the stable step), else ``courant * dt_max``."""
        if self.time_step is not None:
            return float(self.time_step)
        return self.courant * self.dt_max

    @property
    def transit_time(self) -> float:
        """The contact line's length over the P-wave speed [s] (the fastest of the materials along it)."""
        return self.line_length / self.p_wave_speed

    @property
    def speed_scales(self) -> dict:
        """The P-wave speed and the surface's mean speed along the line, in ``theta`` per second."""
        return {"cp": 2.0 * np.pi / self.transit_time,
                "surface": 2.0 * np.pi * float(np.mean(self.surface[1])) / self.line_length}

    @property
    def step_given(self) -> float:
        """The user's ``time_step``, 0 if none (stored with a run's settings)."""
        return float(self.time_step or 0.0)

    def key(self) -> dict:
        return {"beta2": self.beta2, "courant": self.courant, "step_given": self.step_given}


@dataclass(frozen=True, eq=False)
class BodyScheme(FemScheme):
    """The explicit scheme of a `ContactProblem` (``beta2`` in [1/2, 1], ``courant`` in (0, 1]);
    ``time_step`` [s], if given, replaces ``courant * dt_max`` and may not exceed ``dt_max``."""

    PARAMS: ClassVar[type] = ContactProblem
    params: ContactProblem
    beta2: float = 0.9
    courant: float = 0.9
    time_step: float | None = None

    def __post_init__(self):
        self.validate_common()
        self.check_time_step()
        _ = self.kinetic_law  # a law the kernel is not compiled for is refused here, before anything runs

    # --- dofs: the free ones, in nodal frames at the contact nodes --------------------
    @cached_property
    def rotation(self) -> sp.csr_matrix:
        """``T`` with Cartesian ``u = T w`` (all dofs)."""
        return frame_rotation(self.problem.system.n_dofs, self.problem.frames)

    @cached_property
    def free(self) -> np.ndarray:
        """The free dofs (not clamped), indices into all ``2 n``."""
        return np.flatnonzero(~self.problem.fixed)

    @cached_property
    def contact_nodes(self) -> np.ndarray:
        """Positions in ``frames.nodes`` of the contact nodes that are not clamped."""
        return np.flatnonzero(~self.problem.fixed[2 * self.problem.frames.nodes])

    def cartesian(self, w: np.ndarray) -> np.ndarray:
        """Free-dof vector(s) of the scheme -> Cartesian displacements of every dof."""
        full = np.zeros(np.shape(w)[:-1] + (self.problem.system.n_dofs,))
        full[..., self.free] = w
        return full @ self.rotation.T

    # --- the interface of stickslip.contact ----------------------------------------------
    @cached_property
    def mass(self) -> np.ndarray:
        return self.problem.system.mass[self.free]

    @cached_property
    def stiffness(self) -> sp.csr_matrix:
        """``K`` on the free dofs in the scheme's frames (nodal frames at the contact nodes)."""
        return (self.rotation.T @ self.problem.system.K @ self.rotation).tocsr()[self.free][:, self.free]

    def operator_matrix(self):
        return (sp.diags(1.0 / self.mass) @ self.stiffness).tocsr()

    @property
    def static_friction(self) -> float:
        return float(self.problem.static_friction)

    @property
    def kinetic_law(self) -> tuple[float, int, float]:
        """``(f_d, kind, parameter)`` of the problem's law for the kernel (`kernel_friction`)."""
        return kernel_friction(self.problem.law, self.problem.friction)

    @cached_property
    def pressure_scaling(self) -> tuple[float, np.ndarray]:
        """With the problem's ``pressure_law``: its exponent and, per contact node, ``m / (L P_ref)``
        (the node's lumped mass over its tributary length and the reference pressure: the kernel's
        reaction per unit mass times it is ``P / P_ref``); else none."""
        law = self.problem.pressure_law
        if law is None:
            return (0.0, np.zeros(0))
        m = self.mass[self.contact_dofs[0]]
        return (float(law.exponent), m / (self.problem.tributary[self.contact_nodes] * law.reference))

    @property
    def closed_line(self) -> bool:
        return bool(self.problem.frames.closed)

    @cached_property
    def load(self) -> np.ndarray | None:
        """The boundary load per unit mass on the free dofs, in the scheme's frames (None: no load)."""
        F = self.problem.system.load
        return None if not F.any() else (self.rotation.T @ F)[self.free] / self.mass

    @cached_property
    def contact_dofs(self) -> tuple[np.ndarray, np.ndarray]:
        where = np.full(self.problem.system.n_dofs, -1, dtype=np.int64)
        where[self.free] = np.arange(self.free.size)
        nodes = self.problem.frames.nodes[self.contact_nodes]
        return where[2 * nodes], where[2 * nodes + 1]

    @cached_property
    def surface(self) -> tuple[np.ndarray, np.ndarray]:
        f = self.problem.frames
        return -f.gap[self.contact_nodes], f.speed[self.contact_nodes]

    def steady_reference(self) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
        st = self.problem.steady
        w = (self.rotation.T @ st.u)[self.free]
        m = self.mass[self.contact_dofs[0]]
        return w, st.pressure[self.contact_nodes] / m, st.shear[self.contact_nodes] / m

    @cached_property
    def line_length(self) -> float:
        """Length of the contact line [m] (closed lines include the closing edge)."""
        f = self.problem.frames
        pts = self.problem.system.body.points[f.nodes]
        return float(f.arclength[-1] + (np.hypot(*(pts[0] - pts[-1])) if f.closed else 0.0))

    @cached_property
    def theta(self) -> np.ndarray:
        return 2.0 * np.pi * self.problem.frames.arclength[self.contact_nodes] / self.line_length

    @cached_property
    def p_wave_speed(self) -> float:
        """The P-wave speed [m/s] of the material along the contact line (the fastest, if several)."""
        system = self.problem.system
        return system.p_wave_speed(system.body.cells_along(self.problem.frames.group))
