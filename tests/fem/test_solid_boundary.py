"""Springs and tractions on a solid's face groups (issue 45).

* A block on rollers (x = 0 held along x, y = 0 along y) standing on springs of total stiffness k
  along z at its bottom face, pressed by p on its top: the exact state is uniform (uniaxial stress -p,
  the bottom lowered by p A / k, the top by p A / k + p H / E). Threshold, set before the run: 1e-9 of
  the displacement (round-off), on hexahedra, linear and quadratic tetrahedra.
* A uniform traction t on the top face: the nodal forces add up to t A exactly along each axis, and a
  traction -p along the outward normal is the pressure p (1e-12).
* A 3-component spring or traction on a plane body, a 2-component one on a solid: refused, named.
"""

import numpy as np
import pytest
import scipy.sparse.linalg as sla

from stickslip.errors import ParameterError
from stickslip.fem import Load, Material, Spring, assemble, body_from_meshio
from stickslip.fem.solid import assemble_solid, solid_from_meshio, supported_dofs

from .meshes import rectangle
from .test_solid import box, quadratic

L, H, P, K = 0.02, 0.01, 1e6, 5e7
STEEL = Material(2.1e11, 0.3, 7850.0)


def _solid(kind):
    mesh = box((L, L, H), (3, 2, 2), "tetra" if kind == "tetra10" else kind)
    return solid_from_meshio(quadratic(mesh) if kind == "tetra10" else mesh, "block", units="m")


@pytest.mark.parametrize("kind", ["hexahedron", "tetra", "tetra10"])
def test_a_block_on_springs_pressed_on_top_sinks_by_the_springs_and_its_own_compression(kind):
    solid = _solid(kind)
    system = assemble_solid(solid, STEEL, loads=[Load("z1", pressure=P)], springs=[Spring("z0", (0.0, 0.0, K))])
    held = supported_dofs(solid, rollers={"x0": "x", "y0": "y"})
    free = np.setdiff1d(np.arange(system.n_dofs), held)
    u = np.zeros(system.n_dofs)
    u[free] = sla.spsolve(system.K[free][:, free].tocsc(), system.load[free])
    w = u[2::3]
    bottom, top = solid.nodes("z0"), solid.nodes("z1")
    sink = P * L * L / K
    scale = sink + P * H / STEEL.young
    assert np.abs(w[bottom] + sink).max() < 1e-9 * scale
    assert np.abs(w[top] + sink + P * H / STEEL.young).max() < 1e-9 * scale


@pytest.mark.parametrize("kind", ["hexahedron", "tetra10"])
def test_a_traction_adds_up_to_its_total_and_a_normal_one_is_the_pressure(kind):
    solid = _solid(kind)
    t = (2e5, -3e5, 4e5)
    f = assemble_solid(solid, STEEL, loads=[Load("z1", traction=t)]).load
    assert np.allclose([f[d::3].sum() for d in range(3)], np.array(t) * L * L, rtol=1e-12)
    pressed = assemble_solid(solid, STEEL, loads=[Load("z1", pressure=P)]).load
    pulled = assemble_solid(solid, STEEL, loads=[Load("z1", traction=(0.0, 0.0, -P))]).load  # outward normal +z
    assert np.abs(pressed - pulled).max() < 1e-12 * np.abs(pressed).max()


def test_vectors_of_the_other_dimension_are_refused(tmp_path):
    solid = _solid("tetra")
    with pytest.raises(ParameterError, match=r"spring\[0\]\.stiffness.*three numbers"):
        assemble_solid(solid, STEEL, springs=[Spring("z0", (1e6, 1e6))])
    with pytest.raises(ParameterError, match=r"load\[0\]\.traction.*three numbers"):
        assemble_solid(solid, STEEL, loads=[Load("z1", traction=(1e5, 0.0))])
    body = body_from_meshio(rectangle(tmp_path / "r.msh"), "plane")
    with pytest.raises(ParameterError, match=r"spring\[0\]\.stiffness.*two numbers"):
        assemble(body, STEEL, springs=[Spring("bottom", (1e6, 1e6, 1e6))])
    with pytest.raises(ParameterError, match=r"load\[0\]\.traction.*two numbers"):
        assemble(body, STEEL, loads=[Load("top", traction=(1e5, 0.0, 0.0))])
    with pytest.raises(ParameterError, match="spring.stiffness"):
        Spring("z0", (1e6, 1e6, 1e6, 1e6))
