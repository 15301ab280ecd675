"""The gyroscopic and transport terms of a solid turning about the z axis (a disc), in space-fixed
(Eulerian) coordinates: `stickslip.fem.assembly.transport_operators` of the plane bodies, in three
dimensions.

With the solid's velocity ``v = omega e_z x (x - c)`` (no component along z) and
``A_ij = int rho N_i . (v . grad) N_j``, the gyroscopic matrix is ``G = A - A^T`` (skew) [kg/s] and
the transport softening ``B = int rho ((v . grad) N_i) . ((v . grad) N_j)`` [kg/s^2]: small
vibrations ``u`` about the turning solid obey ``M u'' + G u' + (K - B) u = f`` (the kinetic energy of
``v + u' + (v . grad) u``). ``B`` holds the spin softening (a rigid turn's ``omega^2 I``); the
stress stiffening of the centrifugal prestress is `stickslip.fem.prestress` (a pair's ``prestress``);
the prestress's static strain, ``rho omega^2 R^2 / E`` (1e-8 for a cast-iron disc of 0.14 m at
10 rad/s), is not added to the geometry.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from ..errors import ParameterError
from ..quantities import FEM as Q
from .solid import SolidSystem, cell_quadrature, skfem_mesh

__all__ = ["solid_transport_operators"]


def solid_transport_operators(system: SolidSystem, omega: float, center=(0.0, 0.0)):
    """``(G, B)`` (CSR, on the dofs ``3 i + c``) of ``system`` turning at ``omega`` [rad/s] about the
    z axis through ``center = (x, y)`` [m] (see the module docstring), each material's density on its
    cells."""
    from skfem import Basis, BilinearForm, asm
    from skfem.helpers import dot

    if not isinstance(system, SolidSystem):
        raise ParameterError("system", system, "a SolidSystem (assemble_solid)")
    omega = Q.check("omega", omega)
    cx, cy = Q["center"].check_pair(center, "center")
    solid = system.solid
    mesh, element, ours, _ = skfem_mesh(solid)
    n = 3 * len(solid.points)
    to_ours = sp.csr_array((np.ones(n), (ours, np.arange(n))), shape=(n, n))

    def along(u, w):  # (v . grad) u at the quadrature points
        return u.grad[:, 0] * (-omega * (w.x[1] - cy)) + u.grad[:, 1] * (omega * (w.x[0] - cx))

    A, B = sp.csr_array((n, n)), sp.csr_array((n, n))
    for name, m in system.materials.items():
        cells = np.arange(len(solid.cells)) if name == "" else solid.cell_groups[name]
        basis = Basis(mesh, element, elements=cells, **cell_quadrature(solid))
        rho = float(m.density)
        A = A + to_ours @ asm(BilinearForm(lambda u, v, w: rho * dot(along(u, w), v)), basis) @ to_ours.T
        B = B + to_ours @ asm(BilinearForm(lambda u, v, w: rho * dot(along(u, w), along(v, w))), basis) @ to_ours.T
    return sp.csr_matrix(A - A.T), sp.csr_matrix(B)
