"""A thin free annular disc's bending modes against Kirchhoff plate theory (issue 45): the solid's
out-of-plane bending, which no plane model has, and every doublet twice.

The plate's frequencies are the roots of the 4 x 4 determinant of the free edges' conditions (bending
moment and Kirchhoff shear, both zero at r = a and r = b) on ``W = A J_n(kr) + B Y_n(kr) + C I_n(kr) +
D K_n(kr)`` (the modes ``W(r) cos n theta``), ``omega = k^2 sqrt(D / (rho h))``: written here from the
plate equations, not from the package. The disc: steel, a = 100 mm, b = 40 mm, h = 2 mm (a / h = 50),
quadratic tetrahedra of 5 mm, free. Threshold, set before the run: the 12 lowest bending frequencies
within 2 % of the plate's, sorted (each n >= 1 twice); measured -0.54 % to +0.01 % (the solid below the
plate, as shear and rotary inertia make it). Known: a coarser mesh (8 mm) splits the doublets by up to
40 % and is not used.
"""

import math

import numpy as np
import pytest
from scipy import special
from scipy.optimize import brentq

from stickslip.fem import Material
from stickslip.fem.solid import assemble_solid, read_solid, solid_modes

A, B, THICK = 0.1, 0.04, 0.002
STEEL = Material(young=2.1e11, poisson=0.3, density=7850.0)
BESSEL = ((special.jv, special.jvp, -1), (special.yv, special.yvp, -1), (special.iv, special.ivp, 1),
          (special.kv, special.kvp, 1))


def plate_frequencies(n: int, count: int) -> list:
    """The lowest ``count`` frequencies [Hz] of n nodal diameters of the free annular Kirchhoff plate."""
    E, nu, rho = STEEL.young, STEEL.poisson, STEEL.density
    D = E * THICK**3 / (12 * (1 - nu**2))

    def det(lam):
        k, rows = lam / A, []
        for r in (A, B):
            x, moment, shear = k * r, [], []
            for F, dF, sign in BESSEL:
                W, W1, W2 = F(n, x), k * dF(n, x, 1), k**2 * dF(n, x, 2)
                moment.append(W2 + nu * (W1 / r - n**2 * W / r**2))
                shear.append(sign * k**3 * dF(n, x, 1) - (1 - nu) * n**2 * (W1 - W / r) / r**2)  # d(lap W)/dr + twist
            rows += [moment, shear]
        rows = np.array(rows)
        return np.linalg.det(rows / np.linalg.norm(rows, axis=0))

    grid, roots = np.linspace(0.3, 40.0, 4000), []
    values = [det(x) for x in grid]
    for lo, hi, f0, f1 in zip(grid[:-1], grid[1:], values[:-1], values[1:]):
        if np.sign(f0) != np.sign(f1):
            root = brentq(det, lo, hi)
            if abs(det(root)) < 1e-6:  # a root, not a pole of Y or K
                roots.append(root)
        if len(roots) == count:
            break
    return [(x / A) ** 2 * math.sqrt(D / (rho * THICK)) / (2 * math.pi) for x in roots]


@pytest.mark.slow
def test_a_thin_free_annular_disc_bends_at_the_plate_frequencies_each_doublet_twice(tmp_path):
    gmsh = pytest.importorskip("gmsh")
    gmsh.initialize(["-noenv"])
    try:
        gmsh.option.setNumber("General.Terminal", 0)
        outer = gmsh.model.occ.addCylinder(0, 0, 0, 0, 0, THICK, A)
        inner = gmsh.model.occ.addCylinder(0, 0, 0, 0, 0, THICK, B)
        gmsh.model.occ.cut([(3, outer)], [(3, inner)])
        gmsh.model.occ.synchronize()
        gmsh.model.addPhysicalGroup(3, [t for _, t in gmsh.model.getEntities(3)], name="disc")
        gmsh.option.setNumber("Mesh.MeshSizeMax", 0.005)
        gmsh.option.setNumber("Mesh.ElementOrder", 2)
        gmsh.model.mesh.generate(3)
        gmsh.write(str(tmp_path / "disc.msh"))
    finally:
        gmsh.finalize()
    disc = read_solid(tmp_path / "disc.msh", "m")
    f, _ = solid_modes(assemble_solid(disc, STEEL), count=18, mass="consistent")
    assert np.all(f[:6] < 1e-3 * f[6])  # six rigid motions
    plate = sorted(x for n in range(7) for x in plate_frequencies(n, 2) for _ in range(1 if n == 0 else 2))[:12]
    assert np.max(np.abs(f[6:] / np.array(plate) - 1.0)) < 0.02
    doublets = f[6:][[0, 1, 3, 4, 5, 6, 7, 8, 9, 10]]  # n = 2, 3, 1, 4, 2 (one circle): twice each
    assert np.allclose(doublets[0::2], doublets[1::2], rtol=1e-3)
