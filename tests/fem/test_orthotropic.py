"""An orthotropic material in the plane (a lining), against closed forms.

* Uniaxial stress: a rectangle on rollers (x held on its left side, y on its bottom) pressed by
  p on its right side is in the uniform state sigma_xx = -p, so its right side moves by
  eps_xx L and its top by eps_yy H, with the strains written here from the engineering
  constants: plane stress eps_xx = -p / e1, eps_yy = nu12 p / e1 (axis 1 along x), -p / e2 and
  nu12 p / e1 (axis 1 along y, nu21 / e2 = nu12 / e1); plane strain, eps_33 = 0 adds
  -S_i3 S_j3 / S_33 to the compliance. Every cell's stress is (-p, 0, 0) and its von Mises
  stress has sigma_zz = -p e3 nu13 / e1 (plane strain). To 1e-10 (linear cells pass the patch test).
* An axis turned by 30 degrees: the stiffness of the body equals that of the body turned by
  -30 degrees with the axis along x, its displacements turned back (the rotation of the
  constitutive matrix against scikit-fem's own mapping of a turned mesh), to 1e-12.
* The isotropic case (e1 = e2 = e3, one nu, g12 = E / 2 (1 + nu)) is the isotropic stiffness.
* Compliances that are not positive definite, missing out-of-plane constants: refused, naming them.
"""

import math

import numpy as np
import pytest
import scipy.sparse as sp
import scipy.sparse.linalg as sla

from stickslip.errors import ParameterError
from stickslip.fem import Load, Material, assemble, body_from_meshio
from stickslip.fem.assembly import cell_stress, von_mises
from stickslip.fem.orthotropic import Orthotropic

from .meshes import rectangle

E1, E2, E3, NU12, NU13, NU23, G12 = 2.0e10, 5.0e9, 8.0e9, 0.3, 0.2, 0.35, 3.0e9
L, H, P = 0.04, 0.01, 1.0e6


@pytest.fixture(scope="module")
def plate(tmp_path_factory):
    return body_from_meshio(rectangle(tmp_path_factory.mktemp("ortho") / "plate.msh", L, H, 0.003), "plate.msh")


def _pressed(body, material):
    """Displacements of the plate on rollers pressed by P on its right side (a direct solve)."""
    system = assemble(body, material, loads=[Load("right", P)])
    held = np.zeros(system.n_dofs, bool)
    held[2 * body.nodes("left")] = True
    held[2 * body.nodes("bottom") + 1] = True
    free = np.flatnonzero(~held)
    u = np.zeros(system.n_dofs)
    u[free] = sla.spsolve(system.K[free][:, free].tocsc(), system.load[free])
    return system, u


def _strains(plane, along_x):
    """(eps_xx, eps_yy) per unit sigma_xx, from the engineering constants."""
    a, b = (E1, E2) if along_x else (E2, E1)  # the modulus along x and along y
    nu_xy = NU12 * (1 if along_x else E2 / E1)  # contraction along y per strain along x
    s11, s12 = 1 / a, -nu_xy / a
    if plane == "strain":
        s13 = -(NU13 / E1 if along_x else NU23 / E2)
        s23 = -(NU23 / E2 if along_x else NU13 / E1)
        s33 = 1 / E3
        s11, s12 = s11 - s13 * s13 / s33, s12 - s13 * s23 / s33
    return s11, s12


@pytest.mark.parametrize("plane", ["stress", "strain"])
@pytest.mark.parametrize("angle", [0.0, 90.0])
def test_uniaxial_stress_in_the_material_axes(plate, plane, angle):
    out = dict(e3=E3, nu13=NU13, nu23=NU23) if plane == "strain" else {}
    material = Orthotropic(E1, E2, NU12, G12, 1500.0, angle=angle, plane=plane, **out)
    system, u = _pressed(plate, material)
    exx, eyy = (-P * e for e in _strains(plane, angle == 0.0))
    right, top = plate.nodes("right"), plate.nodes("top")
    assert np.abs(u[2 * right] - exx * L).max() <= 1e-10 * abs(exx) * L
    assert np.abs(u[2 * top + 1] - eyy * H).max() <= 1e-10 * abs(eyy) * H
    sigma = cell_stress(system, u)
    assert np.abs(sigma - [-P, 0.0, 0.0]).max() <= 1e-9 * P
    szz = -P * E3 * (NU13 / E1 if angle == 0.0 else NU23 / E2) if plane == "strain" else 0.0
    exact = math.sqrt(0.5 * ((-P) ** 2 + szz**2 + (szz + P) ** 2))
    assert np.abs(von_mises(system, sigma) - exact).max() <= 1e-9 * P


def test_a_turned_axis_is_the_turned_body(plate):
    """K(angle 30) on the plate = R^T K(angle 0) R on the plate turned by -30 degrees."""
    theta = math.radians(30.0)
    c, s = math.cos(theta), math.sin(theta)
    out = dict(e3=E3, nu13=NU13, nu23=NU23)
    K = assemble(plate, Orthotropic(E1, E2, NU12, G12, 1500.0, angle=30.0, **out)).K
    turned = _turned(plate, -theta)
    K0 = assemble(turned, Orthotropic(E1, E2, NU12, G12, 1500.0, angle=0.0, **out)).K
    n = len(plate.points)
    R = sp.kron(sp.identity(n), sp.csr_matrix([[c, s], [-s, c]]))  # displacement in the turned body's axes
    diff = (R.T @ K0 @ R - K).toarray()
    assert np.abs(diff).max() <= 1e-12 * np.abs(K.toarray()).max()


def _turned(body, theta):
    import meshio

    c, s = math.cos(theta), math.sin(theta)
    points = body.points @ np.array([[c, s], [-s, c]])
    mesh = meshio.Mesh(np.column_stack([points, np.zeros(len(points))]), [(body.kind, body.cells)])
    return body_from_meshio(mesh, "turned")


@pytest.mark.parametrize("plane", ["stress", "strain"])
def test_the_isotropic_case_is_the_isotropic_stiffness(plate, plane):
    E, nu = 2.1e11, 0.3
    out = dict(e3=E, nu13=nu, nu23=nu) if plane == "strain" else {}
    a = assemble(plate, Material(E, nu, 7850.0, plane)).K
    b = assemble(plate, Orthotropic(E, E, nu, E / (2 * (1 + nu)), 7850.0, angle=17.0, plane=plane, **out)).K
    assert abs(a - b).max() <= 1e-12 * abs(a).max()


@pytest.mark.parametrize("kwargs, name", [
    (dict(e1=1e9, e2=1e10, nu12=0.5), "nu12"),      # nu12^2 > e1 / e2
    (dict(nu13=0.9, nu23=0.9), "nu12"),              # the out-of-plane ratios make S indefinite
    (dict(e3=None), "e3"), (dict(plane="stress"), "e3"),
    (dict(angle=400.0), "angle"), (dict(g12=0.0), "g12"), (dict(nu12=float("nan")), "nu12"),
])
def test_bad_orthotropic_constants_are_refused(kwargs, name):
    given = dict(e1=E1, e2=E2, nu12=NU12, g12=G12, density=1500.0, e3=E3, nu13=NU13, nu23=NU23)
    given.update(kwargs)
    with pytest.raises(ParameterError) as err:
        Orthotropic(**given)
    assert err.value.name == name


LINED = '''mesh = "pad_layers.msh"
clamped = ["back"]
[[material]]
group = "lining"
e1 = 9.0e9
e2 = 3.0e9
e3 = 9.0e9
nu12 = 0.1
nu13 = 0.25
nu23 = 0.05
g12 = 2.0e9
density = 2500.0
[[material]]
group = "backplate"
young = 2.1e11
poisson = 0.3
density = 7850.0
[contact]
group = "face"
friction = 0.5
[surface]
kind = "cylinder"
radius = 0.15
omega = 30.0
interference = 2e-6
'''


@pytest.fixture(scope="module")
def lined(tmp_path_factory):
    import shutil
    import subprocess
    import sys

    from .test_examples import EXAMPLES

    folder = tmp_path_factory.mktemp("lined")
    shutil.copy(EXAMPLES / "pad_on_disc" / "mesh.py", folder)
    subprocess.run([sys.executable, "mesh.py", "pad_layers.msh", "0.002", "1", "0.004"], cwd=folder, check=True)
    return folder


def test_an_orthotropic_lining_in_a_config(lined, capsys):
    """The lining's constants reach the body (its stiffness differs from an isotropic lining's,
    steady sliding balances) and the run's attributes describe them."""
    import json

    from stickslip.cli import run
    from stickslip.fem.config import load_config

    (lined / "lined.toml").write_text(LINED)
    cfg = load_config(lined / "lined.toml")
    assert isinstance(cfg.material["lining"], Orthotropic) and cfg.material["lining"].e2 == 3.0e9
    assert run(["fem", "steady", str(lined / "lined.toml"), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert "lining: orthotropic: e1 = 9e+09 Pa" in data["params"]["orthotropic"]
    assert data["friction_force"] == pytest.approx(0.5 * data["normal_force"], rel=1e-12)


@pytest.mark.parametrize("old, new, words", [
    ("e3 = 9.0e9\n", "", "material[0].e3 is missing"),
    ("nu12 = 0.1", "nu12 = 1.9", "material[0].nu12 = 1.9 must be Poisson's ratios that make the compliance"),
    ("g12 = 2.0e9", "g12 = 2.0e9\nyoung = 1e10", "unknown key material[0].young (an orthotropic material"),
    ("angle", "angle", ""),
])
def test_an_orthotropic_table_written_wrong_is_named_in_the_one_error(lined, old, new, words):
    from stickslip.fem.config import load_config

    if not words:
        text = LINED.replace("g12 = 2.0e9", "g12 = 2.0e9\nangle = 1000.0")
        words = "material[0].angle = 1000.0 must be in [-360, 360]"
    else:
        text = LINED.replace(old, new)
    (lined / "bad.toml").write_text(text)
    with pytest.raises(ParameterError) as err:
        load_config(lined / "bad.toml")
    assert words in str(err.value), str(err.value)
