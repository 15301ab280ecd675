"""A body of several materials, one per cell group (issue 24), against what does not lean on
our own assembly: a two-material bar under end traction against its closed form (exact on
any mesh of linear or quadratic cells), the stiffness, mass and damping against a triangle
assembly written out here in numpy (B^T D B A), the stresses of a uniform strain against
Hooke's law of each cell's material; and the refusals of a material on no cell group, a
group without one, a group named twice."""

import numpy as np
import pytest
import scipy.sparse.linalg as sla

from stickslip.errors import ParameterError
from stickslip.fem import Load, Material, assemble, read_body
from stickslip.fem.assembly import cell_stress
from stickslip.fem.config import load_config

from .meshes import two_layers

LINING = Material(1.0e10, 0.25, 2500.0)
STEEL = Material(2.1e11, 0.3, 7850.0)


@pytest.fixture(scope="module", params=[1, 2], ids=["triangle", "triangle6"])
def layers(request, tmp_path_factory):
    path = tmp_path_factory.mktemp("mesh") / "layers.msh"
    two_layers(path, order=request.param)
    return read_body(path)


def test_a_bar_of_two_materials_stretches_as_its_closed_form(layers):
    """nu = 0: end traction sigma on x = L gives the uniaxial stress sigma in both layers, so
    u_x(x) = sigma x / E1 in the first and sigma (L1 / E1 + (x - L1) / E2) in the second,
    u_y = 0: linear in each layer, exact for the finite elements. (One material for both,
    the planted bug, misses it by the ratio of the moduli.)"""
    e1, e2, sigma = 1.0e10, 2.1e11, 1.0e6
    materials = {"a": Material(e1, 0.0, 2500.0), "b": Material(e2, 0.0, 7850.0)}
    s = assemble(layers, materials, loads=[Load("right", 0.0, (sigma, 0.0))])
    fixed = s.dofs(layers.nodes("left"))
    free = np.setdiff1d(np.arange(s.n_dofs), fixed)
    u = np.zeros(s.n_dofs)
    u[free] = sla.spsolve(s.K[free][:, free].tocsc(), s.load[free])
    x = layers.points[:, 0]
    exact = np.where(x < 0.02, sigma * x / e1, sigma * (0.02 / e1 + (x - 0.02) / e2))
    scale = sigma * 0.02 / e1
    assert np.abs(u[0::2] - exact).max() < 1e-9 * scale
    assert np.abs(u[1::2]).max() < 1e-9 * scale


def _triangle_assembly(body, materials, plane="strain"):
    """K, row-sum lumped mass and Rayleigh damping of linear triangles, written out: for each
    cell B (3 x 6) from the corner coordinates, D of its material, K_e = B^T D B A;
    lumped mass rho A / 3 per corner and direction; C_e = alpha M_e + beta K_e."""
    n = 2 * len(body.points)
    K, C, mass = np.zeros((n, n)), np.zeros((n, n)), np.zeros(n)
    owner = {}
    for name, m in materials.items():
        owner.update({int(c): m for c in body.cell_groups[name]})
    for i, cell in enumerate(body.cells):
        m = owner[i]
        (x1, y1), (x2, y2), (x3, y3) = body.points[cell]
        area = 0.5 * ((x2 - x1) * (y3 - y1) - (x3 - x1) * (y2 - y1))
        b = np.array([y2 - y3, y3 - y1, y1 - y2]) / (2 * area)
        c = np.array([x3 - x2, x1 - x3, x2 - x1]) / (2 * area)
        B = np.zeros((3, 6))
        B[0, 0::2], B[1, 1::2], B[2, 0::2], B[2, 1::2] = b, c, c, b
        E, nu = m.young, m.poisson
        if plane == "strain":
            D = E / ((1 + nu) * (1 - 2 * nu)) * np.array([[1 - nu, nu, 0], [nu, 1 - nu, 0], [0, 0, (1 - 2 * nu) / 2]])
        else:
            D = E / (1 - nu**2) * np.array([[1, nu, 0], [nu, 1, 0], [0, 0, (1 - nu) / 2]])
        Ke = B.T @ D @ B * area
        dofs = np.ravel(np.column_stack([2 * cell, 2 * cell + 1]))
        K[np.ix_(dofs, dofs)] += Ke
        Me = np.full(6, m.density * area / 3)
        mass[dofs] += Me
        C[np.ix_(dofs, dofs)] += m.alpha * np.diag(Me) + m.beta * Ke
    return K, mass, C


@pytest.mark.parametrize("plane", ["strain", "stress"])
def test_stiffness_mass_and_damping_agree_with_a_triangle_assembly_written_out(tmp_path, plane):
    two_layers(tmp_path / "l.msh")
    body = read_body(tmp_path / "l.msh")
    materials = {"a": Material(1.0e10, 0.25, 2500.0, plane, alpha=30.0, beta=2e-6),
                 "b": Material(2.1e11, 0.3, 7850.0, plane, alpha=5.0, beta=1e-7)}
    s = assemble(body, materials)
    K, mass, C = _triangle_assembly(body, materials, plane)
    assert np.abs(s.K.toarray() - K).max() < 1e-12 * np.abs(K).max()
    assert np.abs(s.mass - mass).max() < 1e-12 * mass.max()
    assert np.abs(s.damping().toarray() - C).max() < 1e-12 * np.abs(C).max()
    assert s.mass[0::2].sum() == pytest.approx(0.01 * (0.02 * 2500.0 + 0.03 * 7850.0), rel=1e-12)


def test_a_uniform_strain_gives_each_cell_its_own_materials_stress(layers):
    s = assemble(layers, {"a": LINING, "b": STEEL})
    exx, eyy, gxy = 1e-4, -3e-5, 2e-5
    x, y = layers.points.T
    u = np.ravel(np.column_stack([exx * x + 0.5 * gxy * y, 0.5 * gxy * x + eyy * y]))
    stress = cell_stress(s, u)
    for name, m in (("a", LINING), ("b", STEEL)):
        lam, mu = m.young * m.poisson / ((1 + m.poisson) * (1 - 2 * m.poisson)), m.young / (2 * (1 + m.poisson))
        exact = [lam * (exx + eyy) + 2 * mu * exx, lam * (exx + eyy) + 2 * mu * eyy, mu * gxy]
        got = stress[layers.cell_groups[name]]
        assert np.abs(got - exact).max() < 1e-9 * np.abs(exact).max(), name


def test_one_material_still_means_the_whole_body(layers):
    one, two = assemble(layers, STEEL), assemble(layers, {"a": STEEL, "b": STEEL})
    assert abs(one.K - two.K).max() < 1e-12 * abs(one.K).max()
    assert np.allclose(one.mass, two.mass, rtol=1e-14, atol=0)


@pytest.mark.parametrize("materials, words", [
    ({"a": LINING}, "none for cell group 'b'"),
    ({"a": LINING, "b": STEEL, "c": STEEL}, "material.group = 'c': must be a cell group of"),
    ({"a": LINING, "b": Material(1e10, 0.25, 2500.0, "stress")}, "one plane"),
    ({}, "a Material or an Orthotropic, or {cell group name: material}"),
])
def test_materials_that_do_not_cover_the_cell_groups_once_are_refused(layers, materials, words):
    with pytest.raises(ParameterError) as err:
        assemble(layers, materials)
    assert words in str(err.value)


CONFIG = """mesh = "l.msh"
clamped = ["left"]
{materials}
[contact]
group = "bottom"
friction = 0.3

[surface]
kind = "flat"
point = [0.0, 0.0]
normal = [0.0, 1.0]
velocity = [1.0, 0.0]
interference = 1e-6
"""
GOOD = """[[material]]
group = "a"
young = 1e10
poisson = 0.25
density = 2500.0
[[material]]
group = "b"
young = 2.1e11
poisson = 0.3
density = 7850.0
"""


@pytest.mark.parametrize("materials, words", [
    (GOOD.replace('group = "b"', 'group = "backplate"'),
     ["material[1].group = 'backplate' is not a cell group of l.msh (it has: a, b)",
      "the cell group 'b' of l.msh has none"]),
    (GOOD.replace('group = "b"', 'group = "a"'), ["material[1].group = 'a' must name each cell group once"]),
    (GOOD.replace('group = "b"\n', ''), ["material[1].group must be the name of a cell group"]),
    (GOOD.replace("young = 2.1e11", "young = 2.1e21"), ["material[1].young = 2.1e+21 must be"]),
    ('[material]\ngroup = "a"\nyoung = 1e10\npoisson = 0.25\ndensity = 2500.0\n',
     ["material.group: a single [material] is the whole body"]),
    (GOOD.replace('group = "b"', 'group = "b"\nplane = "stress"'), ["material.plane must be the same"]),
])
def test_a_config_whose_materials_do_not_match_the_cell_groups_is_one_error(tmp_path, materials, words):
    two_layers(tmp_path / "l.msh")
    (tmp_path / "c.toml").write_text(CONFIG.format(materials=materials))
    with pytest.raises(ParameterError) as err:
        load_config(tmp_path / "c.toml")
    for w in words:
        assert w in str(err.value), str(err.value)


def test_a_config_with_a_material_per_group_assembles_them(tmp_path):
    two_layers(tmp_path / "l.msh")
    (tmp_path / "c.toml").write_text(CONFIG.format(materials=GOOD))
    problem = load_config(tmp_path / "c.toml").problem()
    s = problem.system
    assert set(s.materials) == {"a", "b"} and s.materials["b"].young == 2.1e11
    young = s.cell_values("young")
    assert np.all(young[s.body.cell_groups["a"]] == 1e10) and np.all(young[s.body.cell_groups["b"]] == 2.1e11)
    ds = problem.steady.to_xarray()
    assert ds.attrs["material_groups"] == "a b" and list(ds.attrs["young"]) == [1e10, 2.1e11]


@pytest.mark.parametrize("plane", ["strain", "stress"])
def test_the_contact_lines_transit_is_at_the_fastest_p_wave_of_the_materials_along_it(tmp_path, plane):
    """Issue 44: a run's length in transits is the contact line's length over the fastest P-wave
    of the materials along it. Lining (E 1e10 Pa, nu 0.25, 2500 kg/m^3, x < 2 cm) and steel
    (2.1e11 Pa, 0.3, 7850 kg/m^3, beyond) side by side, the contact line the bottom (5 cm,
    along both): the longitudinal plane wave's modulus is E (1 - nu) / ((1 + nu)(1 - 2 nu)) in
    plane strain, E / (1 - nu^2) in plane stress, so c_p = 6001.0 m/s (strain) or 5422.0 m/s
    (stress), the steel's; along the left side (lining cells only) the lining's: 2190.9 or
    2065.6 m/s. Written from E and nu, not from the code's Lame parameters."""
    from stickslip.fem.scheme import BodyScheme

    def c_p(young, nu, rho):
        modulus = young * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) if plane == "strain" else young / (1 - nu**2)
        return np.sqrt(modulus / rho)

    two_layers(tmp_path / "l.msh")
    materials = GOOD.replace("density = 2500.0", f'density = 2500.0\nplane = "{plane}"').replace(
        "density = 7850.0", f'density = 7850.0\nplane = "{plane}"')
    (tmp_path / "c.toml").write_text(CONFIG.format(materials=materials))
    problem = load_config(tmp_path / "c.toml").problem()
    steel, lining = c_p(2.1e11, 0.3, 7850.0), c_p(1.0e10, 0.25, 2500.0)
    assert steel == pytest.approx(6001.0 if plane == "strain" else 5422.0, abs=0.1)
    scheme = BodyScheme(problem)
    assert scheme.line_length == pytest.approx(0.05, rel=1e-12)
    assert scheme.p_wave_speed == pytest.approx(steel, rel=1e-12)
    assert scheme.transit_time == pytest.approx(0.05 / steel, rel=1e-12)
    s = problem.system
    assert s.p_wave_speed(s.body.cells_along("left")) == pytest.approx(lining, rel=1e-12)
    assert s.p_wave_speed(s.body.cells_along("right")) == pytest.approx(steel, rel=1e-12)


def test_an_explicit_run_refuses_materials_damped_differently_and_the_cea_takes_them(tmp_path, capsys):
    """The explicit scheme damps the whole body with one (alpha, beta): a run with two is refused
    in one line naming material.alpha; the CEA linearises each material's own damping."""
    from stickslip.cli import run
    from stickslip.fem.cea import linearised

    two_layers(tmp_path / "l.msh")
    damped = GOOD.replace("density = 7850.0", "density = 7850.0\nalpha = 10.0")
    (tmp_path / "c.toml").write_text(CONFIG.format(materials=damped))
    assert run(["fem", "run", str(tmp_path / "c.toml"), "--transits", "1"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "material.alpha" in err and "one Rayleigh damping" in err, err
    K, C, mass, kept = linearised(load_config(tmp_path / "c.toml").problem())
    assert C is not None and C.nnz > 0


def test_the_damping_linearised_is_the_materials_rayleigh_damping_when_they_share_it(tmp_path):
    """Consistency (not verification): one (alpha, beta) for both materials gives the CEA's damping
    alpha M + beta K_eff of the linearised stiffness, as the explicit scheme damps."""
    from stickslip.fem.cea import linearised

    two_layers(tmp_path / "l.msh")
    damped = GOOD.replace("density = 7850.0", "density = 7850.0\nalpha = 10.0\nbeta = 1e-7").replace(
        "density = 2500.0", "density = 2500.0\nalpha = 10.0\nbeta = 1e-7")
    (tmp_path / "c.toml").write_text(CONFIG.format(materials=damped))
    K, C, mass, _ = linearised(load_config(tmp_path / "c.toml").problem())
    expected = 10.0 * np.diag(mass) + 1e-7 * K.toarray()
    assert np.abs(C.toarray() - expected).max() < 1e-12 * np.abs(expected).max()
