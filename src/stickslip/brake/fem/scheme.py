"""The FE annulus as an explicit contact scheme ([21]-[23]): the general body's, with the stencil.

Semi-discrete problem ([21]): ``gamma M u_tt + K u = C^T lambda`` with the lumped (diagonal)
mass ``M``, the stiffness ``K`` of `mesh.assemble` and reactions ``lambda`` on the contact
dofs only (polar frames: ``lambda_n`` on the radial dof, ``lambda_t`` on the hoop dof of each
node at ``r = 1``). `FemScheme` is the general body's scheme (`stickslip.fem.scheme.BodyScheme`)
on the annulus's problem (`problem.annulus_problem`: its steady sliding, contact frames,
reactions, damping and friction), written in polar frames at every node, where the structured
mesh makes ``(gamma M)^{-1} K`` a block-circulant stencil (the fast path; the general sparse
matrix, in the same frames, is the other path). The shaft is the rigid surface, at
``u_r = delta``, moving at ``R Omega`` = 1; the reactions are per unit mass, ``r = lambda /
(gamma m_c)`` (``m_c`` the contact node's lumped mass). See ``docs/theory/brake-fem.md``.
"""

from __future__ import annotations

from dataclasses import dataclass
from functools import cached_property, lru_cache
from typing import ClassVar

import numpy as np

from ...contact import ExplicitScheme
from ...fem.scheme import BodyScheme
from ..reduced import BrakeParams, ReducedCoefficients, elastic_moduli
from .mesh import FemSystem, annulus_mesh, assemble
from .modes import max_frequency
from .problem import annulus_problem
from .static import FemSteady, steady_state

__all__ = ["FemScheme"]


@lru_cache(maxsize=8)
def _system(n_theta: int, n_r: int, xi: float, nu: float) -> FemSystem:
    """Assembled systems are shared by the schemes of one mesh and material (they are not mutated)."""
    return assemble(annulus_mesh(n_theta, n_r, xi), nu)


@dataclass(frozen=True, eq=False, init=False)
class FemScheme(BodyScheme):
    """The FE discretisation of [10] on an ``n_theta x n_r`` mesh and its explicit time step.

    Parameters
    ----------
    params : BrakeParams
        Dimensionless parameters (``xi``, ``nu`` set the mesh and the material).
    n_theta, n_r : int
        Mesh (`annulus_mesh`): nodes around (a multiple of 8, >= 16) and layers across.
    beta2 : float
        ``gamma`` of the explicit Newmark scheme [22], in [1/2, 1]: 1/2 is central
        differences; the paper uses 0.9 (numerical damping of high frequencies).
    courant : float
        ``dt / dt_max`` in (0, 1], ``dt_max = sqrt(2 / beta2) / omega_max`` (``omega_max``
        the largest free frequency of the mesh: the CFL limit set by the P-wave speed).
    time_step : float, optional
        The step in paper time instead of ``courant * dt_max`` (at most ``dt_max``).
    """

    PARAMS: ClassVar[type] = BrakeParams
    params: BrakeParams
    n_theta: int = 256
    n_r: int = 16

    def __init__(self, params: BrakeParams, n_theta: int = 256, n_r: int = 16, beta2: float = 0.9,
                 courant: float = 0.9, time_step: float | None = None):
        for name, value in (("params", params), ("n_theta", n_theta), ("n_r", n_r), ("beta2", beta2),
                            ("courant", courant), ("time_step", time_step)):
            object.__setattr__(self, name, value)
        self.__post_init__()

    def __post_init__(self):
        self.validate_common()
        self.check_time_step()
        annulus_mesh(self.n_theta, self.n_r, self.params.xi)  # validates n_theta, n_r
        object.__setattr__(self, "n_theta", int(self.n_theta))
        object.__setattr__(self, "n_r", int(self.n_r))

    @cached_property
    def problem(self):
        """The annulus as a problem of the general body (`annulus_problem`)."""
        return annulus_problem(self.params, self.n_theta, self.n_r)

    @cached_property
    def system(self) -> FemSystem:
        return _system(self.n_theta, self.n_r, self.params.xi, self.params.nu)

    @cached_property
    def steady(self) -> FemSteady:
        return steady_state(self.params, self.system)

    # --- where the annulus differs from the general body ----------------------------------
    @cached_property
    def rotation(self):
        """Polar frames at every node (at the bore, the contact frames ``(n, t) = (e_r, e_theta)``):
        the frames in which the structured mesh's operator is block circulant."""
        return self.system.mesh.polar_rotation

    @cached_property
    def stencil(self) -> np.ndarray:
        """Stencil of ``(gamma M)^{-1} K`` (row layer ``i`` divided by its mass)."""
        m = self.params.gamma * self.system.mass[::2 * self.n_theta]
        return np.ascontiguousarray(self.system.stencil / m[:, None, None, None, None])

    def operator_matrix(self):
        """The stencil as a sparse matrix (the same operator as the fast path, summed in another
        order; the general assembly in these frames, ``stiffness / mass``, equals it to 1e-13 of its
        largest entry, tested)."""
        return ExplicitScheme.operator_matrix(self)

    @property
    def mass(self) -> np.ndarray:
        """Physical lumped mass ``gamma M`` of the free dofs (one value per ring of nodes, exactly)."""
        return self.params.gamma * self.system.mass

    @cached_property
    def surface(self) -> tuple[np.ndarray, np.ndarray]:
        """The shaft: ``u_r >= delta``, surface speed ``R Omega`` = 1 (the paper's numbers, exactly)."""
        return np.full(self.n_theta, self.params.delta), np.ones(self.n_theta)

    @property
    def theta(self) -> np.ndarray:
        return self.system.mesh.theta

    @cached_property
    def omega_max(self) -> float:
        return max_frequency(self.system) / np.sqrt(self.params.gamma)

    @property
    def transit_time(self) -> float:
        """``2 pi / (c_p / (R Omega))``: a P-wave once around the contact circle (paper time)."""
        return 2.0 * np.pi / self.p_wave_speed

    @property
    def speed_scales(self) -> dict:
        return {"sqrt_a": float(np.sqrt(self.coefficients.a)), "cp": self.p_wave_speed}

    # --- the annulus ---------------------------------------------------------------------
    @cached_property
    def coefficients(self) -> ReducedCoefficients:
        """Reduced-model coefficients [13] (for speeds in units of its ``sqrt(a)``)."""
        return self.params.coefficients()

    @property
    def p_wave_speed(self) -> float:
        """``c_p / (R Omega) = sqrt(ã / gamma)``: angular speed of a P-wave along ``r = R``."""
        return float(np.sqrt(float(elastic_moduli(self.params.nu)[0]) / self.params.gamma))

    @property
    def traction_scale(self) -> float:
        """Reaction per unit mass -> traction in units of ``E`` (``gamma m_c / h_theta``)."""
        return float(self.mass[0] / self.system.mesh.h_theta)

    def key(self) -> dict:
        return {"n_theta": self.n_theta, "n_r": self.n_r, "beta2": self.beta2, "courant": self.courant}
