"""Cell stresses of a solid (`stickslip.fem.solid.SolidSystem`) at a displacement, for ParaView.

`solid_stress(system, u)` gives each cell's mean stress ``sigma = D eps(u)`` [Pa] over its
quadrature points (scikit-fem's interpolation of ``u`` on the solid's elements, weighted by the
points' volumes), in Voigt order ``xx, yy, zz, yz, xz, xy`` (`stickslip.fem.solid.VOIGT`), each
cell with its own material (isotropic: ``lambda tr(eps) I + 2 mu eps``; orthotropic: its ``D`` on
the engineering strains); `solid_von_mises` the equivalent stress of those means.
"""

from __future__ import annotations

import numpy as np

from ..errors import ParameterError
from .solid import VOIGT, OrthotropicSolid, SolidSystem, cell_quadrature, skfem_mesh

__all__ = ["solid_stress", "solid_von_mises", "solid_cell_material", "voigt_stiffness"]


def voigt_stiffness(m) -> np.ndarray:
    """``D`` [Pa] (6 x 6, Voigt with engineering shear strains) of a material of a solid."""
    if isinstance(m, OrthotropicSolid):
        return m.stiffness
    lam = m.young * m.poisson / ((1 + m.poisson) * (1 - 2 * m.poisson))
    mu = m.young / (2 * (1 + m.poisson))
    D = np.zeros((6, 6))
    D[:3, :3] = lam
    D[[0, 1, 2], [0, 1, 2]] += 2 * mu
    D[[3, 4, 5], [3, 4, 5]] = mu
    return D


def solid_stress(system: SolidSystem, u: np.ndarray) -> np.ndarray:
    """``(cells, 6)``: each cell's mean stress [Pa] at the displacement ``u`` (``3 n`` Cartesian dofs [m])."""
    from skfem import Basis

    if not isinstance(system, SolidSystem):
        raise ParameterError("system", system, "a SolidSystem (assemble_solid)")
    try:
        u = np.asarray(u, dtype=float)
    except (TypeError, ValueError):
        raise ParameterError("u", u, f"the {system.n_dofs} displacements of the solid [m]") from None
    if u.shape != (system.n_dofs,) or not np.all(np.isfinite(u)):
        raise ParameterError("u", f"an array of shape {u.shape}", f"the {system.n_dofs} finite displacements of the "
                             "solid [m]")
    solid = system.solid
    mesh, element, ours, _ = skfem_mesh(solid)
    out = np.zeros((len(solid.cells), 6))
    for name, m in system.materials.items():
        cells = np.arange(len(solid.cells)) if name == "" else np.asarray(solid.cell_groups[name])
        basis = Basis(mesh, element, elements=cells, **cell_quadrature(solid))
        grad = basis.interpolate(u[ours]).grad  # (3, 3, cells, points): d u_i / d x_j
        strain = np.stack([(grad[i, j] + grad[j, i]) * (0.5 if i == j else 1.0) for i, j in VOIGT])
        weights = basis.dx / basis.dx.sum(axis=1, keepdims=True)
        out[cells] = np.einsum("IJ,Jcq,cq->cI", voigt_stiffness(m), strain, weights)
    return out


def solid_von_mises(sigma: np.ndarray) -> np.ndarray:
    """The von Mises stress [Pa] of Voigt stresses ``(cells, 6)``."""
    s = np.asarray(sigma, dtype=float)
    xx, yy, zz, yz, xz, xy = s.T
    return np.sqrt(0.5 * ((xx - yy) ** 2 + (yy - zz) ** 2 + (zz - xx) ** 2) + 3.0 * (yz**2 + xz**2 + xy**2))


def solid_cell_material(system: SolidSystem) -> np.ndarray:
    """Each cell's material: its position in ``system.materials``."""
    out = np.zeros(len(system.solid.cells), dtype=np.int32)
    for k, name in enumerate(system.materials):
        if name:
            out[np.asarray(system.solid.cell_groups[name])] = k
    return out
