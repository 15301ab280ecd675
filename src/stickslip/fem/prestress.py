"""The centrifugal prestress of a solid turning about the z axis and the stiffness it adds.

A solid turning at ``omega`` about the z axis through ``c`` carries the centrifugal body force
``rho omega^2 (x - c)`` in the x-y plane. Its static displacement ``u0`` (the solid's supports
held) and stress ``sigma0 = D eps(u0)`` stiffen small motions about it by the geometric (stress)
stiffness

    K_sigma(u, v) = int sigma0_ij (d u_k / d x_i) (d v_k / d x_j) dV,

the second variation of the work of the prestress on the Green strain. It grows as ``omega^2``. With
the gyroscopic and transport terms (`stickslip.fem.turning`: spin softening ``B``) the small
vibrations about the turning solid obey ``M u'' + G u' + (K + K_sigma - B) u = f``. The static
displacement itself (a strain of ``rho omega^2 R^2 / E``) is not added to the geometry.
"""

from __future__ import annotations

import numpy as np
import scipy.sparse as sp

from ..errors import ParameterError
from ..quantities import FEM as Q
from .solid import VOIGT, SolidSystem, cell_quadrature, skfem_mesh, split_held
from .solid_stress import voigt_stiffness

__all__ = ["centrifugal_stiffness"]


def centrifugal_stiffness(system: SolidSystem, omega: float, center=(0.0, 0.0), held=()) -> tuple:
    """``(K_sigma, u0)``: the stress stiffness (CSR, on the dofs ``3 i + c``) of ``system`` turning at
    ``omega`` [rad/s] about the z axis through ``center = (x, y)`` [m], and the centrifugal static
    displacement [m] it comes from, with the degrees of freedom ``held`` at zero (its supports; see
    the module docstring)."""
    from scipy.sparse.linalg import splu
    from skfem import Basis, BilinearForm, LinearForm, asm

    omega = Q.check("omega", omega)
    cx, cy = Q["center"].check_pair(center, "center")
    n, sup = split_held(system, held)
    solid = system.solid
    mesh, element, ours, _ = skfem_mesh(solid)
    to_ours = sp.csr_array((np.ones(n), (ours, np.arange(n))), shape=(n, n))
    parts = []
    force = np.zeros(n)
    for name, m in system.materials.items():
        cells = np.arange(len(solid.cells)) if name == "" else np.asarray(solid.cell_groups[name])
        basis = Basis(mesh, element, elements=cells, **cell_quadrature(solid))
        rho = float(m.density)

        @LinearForm
        def spun(v, w):
            return rho * omega**2 * ((w.x[0] - cx) * v[0] + (w.x[1] - cy) * v[1])

        force += to_ours @ asm(spun, basis)
        parts.append((basis, m))
    u0 = np.zeros(n)
    count = int(sup.held.sum())
    if omega != 0.0:
        try:
            u0 = sup.expand(splu(sp.csc_array(sup.restrict(system.K))).solve(sup.load(force)))
        except RuntimeError:
            raise ParameterError("held", f"{count} degrees of freedom", "supports that hold the turning solid "
                                 "(its stiffness is singular without them)") from None
        if not np.all(np.isfinite(u0)) or np.abs(u0).max() > 1e6 * float(np.ptp(solid.points)):
            raise ParameterError("held", f"{count} degrees of freedom", "supports that hold every rigid motion "
                                 "of the turning solid (some are free)")
    K = sp.csr_array((n, n))
    for basis, m in parts:
        grad = basis.interpolate(u0[ours]).grad
        strain = np.stack([(grad[i, j] + grad[j, i]) * (0.5 if i == j else 1.0) for i, j in VOIGT])
        voigt = np.einsum("IJ,J...->I...", voigt_stiffness(m), strain)
        sigma = np.empty((3, 3) + voigt.shape[1:])
        for I, (i, j) in enumerate(VOIGT):
            sigma[i, j] = sigma[j, i] = voigt[I]

        @BilinearForm
        def geometric(u, v, w):
            s = w["s"]
            return sum(s[i, j] * (u.grad[k, i] * v.grad[k, j]) for i in range(3) for j in range(3) for k in range(3))

        K = K + to_ours @ asm(geometric, basis, s=sigma) @ to_ours.T
    return sp.csr_matrix(K), u0
