"""The annulus as a problem of the general body: `stickslip.fem.ContactProblem` in the paper's units.

The structured mesh (`AnnulusMesh.body`, boundary groups ``bore`` at ``r = 1`` and ``rim`` at
``r = xi``) with the material ``E = 1``, ``nu``, density ``gamma`` (lengths in ``R``,
stresses in ``E``, time in ``1/Omega``: ``rho R^2 Omega^2 / E = gamma``), clamped on ``rim``,
in contact along ``bore`` with the shaft: a `stickslip.fem.RigidCylinder` of radius ``1 +
delta`` turning at ``1 / (1 + delta)``, so that its surface moves at ``R Omega = 1`` and
every node of the bore starts ``delta`` inside it. Steady sliding, the explicit scheme's
frames, damping, reactions and the ParaView fields of the annulus are those of this problem
(`stickslip.fem`); what the annulus adds is its own: the block-circulant stencil of the
structured mesh (the fast path), the Fourier-block modes and the paper's units.
"""

from __future__ import annotations

from functools import lru_cache

import numpy as np

from ...errors import ParameterError
from ..reduced import BrakeParams
from .mesh import annulus_mesh

__all__ = ["annulus_problem"]


@lru_cache(maxsize=8)
def _problem(n_theta: int, n_r: int, xi: float, nu: float, gamma: float, delta: float, friction: float):
    from ...fem import ContactProblem, Material, RigidCylinder, assemble, contact_frames

    mesh = annulus_mesh(n_theta, n_r, xi)
    system = assemble(mesh.body, Material(1.0, nu, gamma, scaled=True))
    shaft = RigidCylinder(1.0 + delta, 1.0 / (1.0 + delta))  # surface speed R Omega = 1
    # every bore node starts delta inside the shaft: within the tolerance whatever delta is
    frames = contact_frames(mesh.body, "bore", shaft, tolerance=0.05 + delta / 6.0)
    if not np.array_equal(frames.nodes, np.arange(n_theta)):  # the stencil's order: node j at 2 pi j / n_theta
        raise AssertionError("the bore's contact nodes are not in the mesh's order")
    return ContactProblem(system, frames, friction, ("rim",))


def annulus_problem(params: BrakeParams, n_theta: int = 256, n_r: int = 16) -> "ContactProblem":  # noqa: F821
    """The annulus of ``params`` on an ``n_theta x n_r`` mesh as a `stickslip.fem.ContactProblem`
    (see the module docstring; problems are cached per mesh and parameters, and not mutated)."""
    if not isinstance(params, BrakeParams):
        raise ParameterError("params", params, "a stickslip.brake.BrakeParams")
    mesh = annulus_mesh(n_theta, n_r, params.xi)  # validates the mesh
    return _problem(mesh.n_theta, mesh.n_r, float(params.xi), float(params.nu), float(params.gamma),
                    float(params.delta), float(params.friction))

