"""A config of two solids (``dimension = 3``, `stickslip.fem.config_solid`) and the `stickslip fem`
commands on it (issue 45).

* The contact patch test through a config whose meshes are in millimetres (``units = "mm"``): a
  lining (hexahedra) pressed by a uniform pressure p on a block (tetrahedra), the interface meshes
  not matching, both on rollers given by the config: every multiplier is p and the normal load
  p L^2 [N] (the exact state is uniform). Thresholds, set before the run: 1e-8 relative. Read in
  metres, the load would be 1e6 times larger; without the rollers the pair would be free to move.
* Springs on the pad's pressed face (``[[spring]]`` of three components): the contact pressure is the
  closed form's share of the load (1e-8).
* Bad input: a 2-D mesh given to a 3-D config and the reverse, no units, a rigid surface with solids,
  springs and tractions of two components, a plane, an interference beyond 2 % of the pad's
  thickness, a tangled mesh; each one line naming the key, exit 2, nothing written.
"""

import json

import meshio
import numpy as np
import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from stickslip.cli import run
from stickslip.errors import ParameterError
from stickslip.fem.config import load_config
from stickslip.fem.pair import steady_pair

from ..budget import examples
from .meshes import rectangle
from .test_solid import box

L, H, T = 20.0, 15.0, 8.0  # mm: the footprint's side, the block's and the lining's thickness
P = 2e6

CONFIG = """
dimension = 3
units = "mm"
mesh = "pad.msh"
rollers = {{ x0 = "x", y0 = "y" }}
{extra}
[material]
young = 5e9
poisson = 0.25
density = 2500.0

[contact]
group = "z0"
friction = 0.3

[[load]]
group = "z1"
pressure = 2e6

[partner]
mesh = "block.msh"
group = "z1"
velocity = [1.0, 0.0]
rollers = {{ x0 = "x", y0 = "y", z0 = "z" }}
[partner.material]
young = 2.1e11
poisson = 0.3
density = 7850.0

[cea]
band = [0.0, 150000.0]
{cea}
"""


def to_msh(mesh, path):
    """``mesh`` with its cell sets as gmsh physical groups, written as a .msh (format 2.2)."""
    tags, field = [], {}
    for k, block in enumerate(mesh.cells):
        tag = np.zeros(len(block.data), dtype=int)
        for name, per_block in mesh.cell_sets.items():
            if k < len(per_block) and per_block[k] is not None and len(per_block[k]):
                number = field.setdefault(name, [len(field) + 1, 3 if block.type in ("tetra", "hexahedron") else 2])[0]
                tag[np.asarray(per_block[k])] = number
        tags.append(tag)
    out = meshio.Mesh(mesh.points, [(b.type, b.data) for b in mesh.cells],
                      cell_data={"gmsh:physical": tags, "gmsh:geometrical": tags}, field_data=field)
    meshio.write(path, out, file_format="gmsh22", binary=False)


def write(folder, extra="", cea="", lift=H, pad_kind="hexahedron"):
    pad = box((L, L, T), (5, 3, 2), pad_kind)
    pad.points[:, 2] += lift
    to_msh(pad, folder / "pad.msh")
    to_msh(box((L, L, H), (3, 4, 3)), folder / "block.msh")
    path = folder / "brake.toml"
    path.write_text(CONFIG.format(extra=extra, cea=cea))
    return path


def test_a_config_in_millimetres_passes_the_patch_test_with_its_rollers(tmp_path):
    config = write(tmp_path)
    cfg = load_config(config, {"contact.friction": 0.0})  # without friction's moment the state is uniform
    assert cfg.dimension == 3 and cfg.units == "mm"
    steady = steady_pair(cfg.problem())
    assert steady.active.all()
    assert np.max(np.abs(steady.pressure / P - 1.0)) < 1e-8
    assert steady.normal_force == pytest.approx(P * (L / 1000) ** 2, rel=1e-8)
    sliding = steady_pair(load_config(config).problem())  # friction 0.3: every node slides, the load's 0.3
    assert sliding.friction_force == pytest.approx(0.3 * P * (L / 1000) ** 2, rel=1e-8)


def test_a_config_turned_about_z_with_its_rollers_along_the_turned_faces_passes_the_patch_test(tmp_path):
    """Both meshes turned 0.6 rad about z, the sliding too, each roller given as the turned normal of its
    face (``rollers = { x0 = [c, s, 0] }``): every multiplier is p (1e-8), the normal load p L^2."""
    c, s = float(np.cos(0.6)), float(np.sin(0.6))
    config = write(tmp_path)
    for name in ("pad.msh", "block.msh"):
        mesh = meshio.read(tmp_path / name)
        turned = mesh.points @ np.array([[c, -s, 0.0], [s, c, 0.0], [0.0, 0.0, 1.0]]).T
        mesh = meshio.read(tmp_path / name)
        mesh.points = turned
        meshio.write(tmp_path / name, mesh, file_format="gmsh22", binary=False)
    x, y = f"[{c!r}, {s!r}, 0.0]", f"[{-s!r}, {c!r}, 0.0]"
    text = (config.read_text().replace('x0 = "x", y0 = "y", z0 = "z" }', f'x0 = {x}, y0 = {y}, z0 = "z" }}')
            .replace('x0 = "x", y0 = "y" }', f"x0 = {x}, y0 = {y} }}")
            .replace("velocity = [1.0, 0.0]", f"velocity = [{c!r}, {s!r}]"))
    config.write_text(text)
    assert text.count("x0 = [") == 2
    steady = steady_pair(load_config(config, {"contact.friction": 0.0}).problem())
    assert steady.active.all()
    assert np.max(np.abs(steady.pressure / P - 1.0)) < 1e-8
    assert steady.normal_force == pytest.approx(P * (L / 1000) ** 2, rel=1e-8)


def test_springs_on_the_pressed_face_take_their_share_of_the_load_as_the_closed_form_says(tmp_path):
    """Springs of total stiffness k along z on the pad's pressed face (with the pressure p): the state stays
    uniform, the contact pressure p_c = p / (1 + k (T / E_pad + H / E_block) / A), the springs carrying
    the rest (uniaxial stress: the sides are free). Threshold, set before the run: 1e-8."""
    k = 1e8
    config = write(tmp_path, extra='[[spring]]\ngroup = "z1"\nstiffness = [0.0, 0.0, 1e8]\n')
    steady = steady_pair(load_config(config, {"contact.friction": 0.0}).problem())
    area, compliance = (L / 1000) ** 2, (T / 1000) / 5e9 + (H / 1000) / 2.1e11
    expected = P / (1 + k * compliance / area)
    assert 0.3 < expected / P < 0.9
    assert np.max(np.abs(steady.pressure / expected - 1.0)) < 1e-8


def test_fem_steady_and_cea_take_a_config_of_solids(tmp_path, capsys):
    config = write(tmp_path, cea="count = 20")
    assert run(["fem", "steady", str(config), "--json"]) == 0
    steady = json.loads(capsys.readouterr().out)
    assert steady["normal_load"] == pytest.approx(P * (L / 1000) ** 2, rel=1e-8)
    assert steady["units"]["normal_load"]["units"] == "N" and "normal_force" not in steady
    assert "plane" not in steady["params"]["materials"]
    uff = tmp_path / "modes.uff"
    assert run(["fem", "cea", str(config), "--json", "--uff", str(uff), "--xdmf", str(tmp_path / "m.xdmf")]) == 0
    modes = json.loads(capsys.readouterr().out)["modes"]
    assert len(modes) >= 20 and uff.stat().st_size > 0


@pytest.mark.slow
def test_the_reduced_cea_of_a_config_with_every_vector_is_the_full_one(tmp_path, capsys):
    """With as many vectors as free dofs (modes and their static vectors span everything), the
    reduced CEA is the full one with penalty contact (1e-6 of |s|, threshold set before the run)."""
    config = write(tmp_path, cea='contact_model = "penalty"\ncount = 40')
    assert run(["fem", "cea", str(config), "--json"]) == 0
    full = json.loads(capsys.readouterr().out)["modes"]
    free = int(np.sum(~load_config(config).problem().fixed))
    config.write_text(config.read_text().replace('contact_model = "penalty"\ncount = 40',
                                                 f"reduced_modes = {free - 2}\naugment = \"none\""))
    assert run(["fem", "cea", str(config), "--json"]) == 0
    reduced = json.loads(capsys.readouterr().out)["modes"]
    f_full = np.array(sorted(m["frequency"] for m in full))[:20]
    f_red = np.array(sorted(m["frequency"] for m in reduced))[:20]
    assert np.allclose(f_red, f_full, rtol=1e-6)


def test_a_reduced_friction_sweep_runs_from_the_config_without_a_store(tmp_path, capsys):
    config = write(tmp_path, cea="reduced_modes = 30")
    out = tmp_path / "sweep.nc"
    assert run(["fem", "cea", str(config), "--sweep", "friction=0:0.6:7", "--out", str(out), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["swept_key"] == "contact.friction" and data["reduced_modes"] == 30 and out.exists()
    assert run(["fem", "cea", str(config), "--sweep", "young=1e9:2e9:3"]) == 2
    assert "contact.friction with cea.reduced_modes" in capsys.readouterr().err


def _refused(tmp_path, capsys, config, *fragments):
    assert run(["fem", "steady", str(config), "--out", str(tmp_path / "s.nc")]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1, err
    for fragment in fragments:
        assert fragment in err, (fragment, err)
    assert not (tmp_path / "s.nc").exists()


def test_a_2d_mesh_in_a_3d_config_and_a_3d_mesh_in_a_2d_config_are_named(tmp_path, capsys):
    config = write(tmp_path)
    rectangle(tmp_path / "flat.msh")
    config.write_text(config.read_text().replace('mesh = "pad.msh"', 'mesh = "flat.msh"'))
    _refused(tmp_path, capsys, config, "mesh = 'flat.msh' is a 2-D mesh", "dimension = 3")
    config.write_text(config.read_text().replace('mesh = "flat.msh"', 'mesh = "pad.msh"')
                      .replace("dimension = 3\n", "").replace('units = "mm"\n', ""))
    _refused(tmp_path, capsys, config, "mesh = 'pad.msh' is a 3-D mesh", "dimension = 3")


@pytest.mark.parametrize("change, fragments", [
    (('units = "mm"\n', ""), ["units is missing"]),
    (('units = "mm"', 'units = "inch"'), ["units = 'inch' must be"]),
    (("dimension = 3", "dimension = 4"), ["dimension = 4 must be"]),
    (("[contact]", "[surface]\nkind = \"flat\"\n[contact]"), ["[surface] and [partner] exclude each other"]),
    (("poisson = 0.25", "poisson = 0.25\nplane = \"strain\""), ["material.plane applies to plane bodies"]),
    (("[contact]", "[[spring]]\ngroup = \"z1\"\nstiffness = [1e6, 0.0]\n[contact]"), ["spring[0].stiffness",
                                                                                    "three numbers"]),
    (("pressure = 2e6", "pressure = 2e6\ntraction = [1e5, 0.0]"), ["load[0].traction", "three numbers"]),
    (('x0 = "x", y0 = "y" }', 'x0 = "w", y0 = "y" }'), ["rollers.x0 = 'w' must be"]),
    (('x0 = "x", y0 = "y" }', 'x0 = "x", side = "y" }'), ["rollers.side = 'side' is not a boundary group"]),
    (('x0 = "x", y0 = "y" }', 'x0 = [0.0, 0.0, 0.0], y0 = "y" }'), ["rollers.x0 = [0.0, 0.0, 0.0] must be",
                                                                    "a direction of 3 finite numbers"]),
    (('x0 = "x", y0 = "y" }', 'x0 = [1.0, 2.0], y0 = "y" }'), ["rollers.x0 = [1.0, 2.0] must be"]),
    (("[cea]", "[cea]\nreduced_modes = 10\ncontact_model = \"constraint\""), ["contact_model = \"constraint\""]),
])
def test_bad_3d_configs_are_refused_in_one_line_naming_the_key(tmp_path, capsys, change, fragments):
    config = write(tmp_path)
    assert change[0] in config.read_text()
    config.write_text(config.read_text().replace(*change, 1))
    _refused(tmp_path, capsys, config, *fragments)


def test_an_interference_beyond_two_percent_of_the_pad_is_refused_before_assembly(tmp_path, capsys):
    config = write(tmp_path, lift=H - 0.03 * T)  # the lining 3 % of its thickness into the block
    _refused(tmp_path, capsys, config, "contact.group", "overlap by at most 0.02")
    write(tmp_path, lift=H - 0.01 * T)  # 1 %: taken
    assert load_config(tmp_path / "brake.toml").dimension == 3


def test_a_tangled_mesh_is_refused(tmp_path, capsys):
    config = write(tmp_path, pad_kind="tetra")
    pad = box((L, L, T), (5, 3, 2), "tetra")
    pad.points[:, 2] += H
    inner = np.flatnonzero(np.all((pad.points[:, :2] > 1.0) & (pad.points[:, :2] < L - 1.0), axis=1)
                           & (pad.points[:, 2] > H + 1.0) & (pad.points[:, 2] < H + T - 1.0))[0]
    pad.points[inner, 0] += 0.9 * L / 5 * 1.5  # pushed through its neighbours' faces
    to_msh(pad, tmp_path / "pad.msh")
    _refused(tmp_path, capsys, config, "mesh = 'pad.msh' must be a mesh without inverted cells")


def test_fem_run_refuses_rollers_through_the_contact_face_in_one_line(tmp_path, capsys):
    config = write(tmp_path)  # the pad's rollers on x0 hold its contact face's edge along x only
    assert run(["fem", "run", str(config), "--transits", "1"]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "invalid rollers = " in err and "along some axes only" in err


def test_load_config_names_every_problem_of_a_3d_config_at_once(tmp_path):
    config = write(tmp_path)
    config.write_text(config.read_text().replace('units = "mm"\n', "").replace("young = 5e9", "young = -1.0"))
    with pytest.raises(ParameterError) as err:
        load_config(config)
    assert "units is missing" in str(err.value) and "material.young = -1.0" in str(err.value)


#: key -> (its text in CONFIG, the TOML to put there with {v} the value): every number and the 3-D keys
FUZZ = {"dimension": ("dimension = 3", "dimension = {v}"), "units": ('units = "mm"', "units = {v}"),
        "rollers": ('rollers = { x0 = "x", y0 = "y" }', "rollers = {v}"),
        "material.young": ("young = 5e9", "young = {v}"), "material.poisson": ("poisson = 0.25", "poisson = {v}"),
        "material.density": ("density = 2500.0", "density = {v}"),
        "material.loss_factor": ("density = 2500.0", "density = 2500.0\nloss_factor = {v}"),
        "contact.friction": ("friction = 0.3", "friction = {v}"),
        "load[0].pressure": ("pressure = 2e6", "pressure = {v}"),
        "partner.velocity": ("velocity = [1.0, 0.0]", "velocity = [{v}, 0.0]"),
        "partner.transverse_damping": ("velocity = [1.0, 0.0]", "velocity = [1.0, 0.0]\ntransverse_damping = {v}"),
        "partner.prestress": ("velocity = [1.0, 0.0]", "omega = 10.0\nprestress = {v}"),
        "partner.material.young": ("young = 2.1e11", "young = {v}"),
        "cea.reduced_modes": ("[cea]", "[cea]\nreduced_modes = {v}")}


@settings(max_examples=examples(40), suppress_health_check=[HealthCheck.function_scoped_fixture], deadline=None)
@given(key=st.sampled_from(sorted(FUZZ)), value=st.one_of(
    st.sampled_from(["0", "-1", "1e300", "-1e300", "1e-300", "5e-324", "nan", "inf", '"abc"', "true", "[]", "{}",
                     "10000000000000000000000"]), st.floats(allow_nan=False, allow_infinity=False).map(repr)))
def test_a_generated_value_in_a_3d_key_gives_finite_numbers_or_one_line(tmp_path_factory, key, value, capsys):
    if not _FUZZ_FOLDER:  # the meshes written once for every example
        _FUZZ_FOLDER.append(tmp_path_factory.mktemp("fuzz3"))
        write(_FUZZ_FOLDER[0])
    folder = _FUZZ_FOLDER[0]
    old, new = FUZZ[key]
    text = CONFIG.format(extra="", cea="")
    assert old in text
    config = folder / "fuzz.toml"
    config.write_text(text.replace(old, new.format(v=value), 1))
    code = run(["fem", "steady", str(config), "--json"])
    out, err = capsys.readouterr()
    assert code in (0, 1, 2), (key, value, code, err)
    if code == 0:
        assert np.all(np.isfinite([v for v in json.loads(out).values() if isinstance(v, float)])), (key, value, out)
    else:
        assert err.count("\n") == 1 and "Traceback" not in err, (key, value, err)


_FUZZ_FOLDER: list = []
SPECIAL = ["0", "-1", "1e300", "-1e300", "1e-300", "5e-324", "nan", "inf", '"abc"', "true", "[]", "{}",
           "10000000000000000000000"]


@pytest.mark.slow
@pytest.mark.parametrize("key", ["dimension", "units", "rollers", "material.loss_factor", "cea.reduced_modes"])
def test_every_special_value_in_a_3d_key_gives_finite_numbers_or_one_line(tmp_path, key, capsys):
    """The generated test's special values, each of them, in each key only a 3-D config has (the sample
    of the generated test missed `units = []`, which crashed)."""
    write(tmp_path)
    old, new = FUZZ[key]
    for value in SPECIAL:
        config = tmp_path / "special.toml"
        config.write_text(CONFIG.format(extra="", cea="").replace(old, new.format(v=value), 1))
        code = run(["fem", "steady", str(config), "--json"])
        out, err = capsys.readouterr()
        assert code in (0, 1, 2), (key, value, code, err)
        if code != 0:
            assert err.count("\n") == 1 and "Traceback" not in err and "internal error" not in err, (key, value, err)
