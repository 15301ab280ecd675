"""A pad on an elastic disc from a config (``[partner]``) through `stickslip fem steady | cea`, as a
user runs the example (`examples/pad_on_disc/pad_disc.toml`, coarser meshes): the disc drags
the pad along its own turning (the pad's face moves with the disc, the other way when the
disc turns the other way), the CEA finds the disc's modes below the pad's first (rigid disc:
none in the band) and a pad-disc coupling that flutters; refusals in one line."""

import json
import shutil
import subprocess
import sys

import numpy as np
import pytest

from stickslip.cli import run
from stickslip.fem.config import load_config

from .test_examples import EXAMPLES


def pad_disc(folder, disc_size: str = "0.003"):
    """The example `pad_disc.toml` in ``folder`` with its meshes made there (the pad at 4 mm, the
    disc at ``disc_size`` m): a folder as a user has it after the example's two mesh commands."""
    shutil.copy(EXAMPLES / "pad_on_disc" / "pad_disc.toml", folder)
    for script, args in (("mesh.py", ["pad.msh", "0.004"]), ("disc.py", ["disc.msh", disc_size, "2e-5"])):
        subprocess.run([sys.executable, str(EXAMPLES / "pad_on_disc" / script), *args], cwd=folder, check=True)
    return folder


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    return pad_disc(tmp_path_factory.mktemp("pad_disc"))


def _config(folder, old="", new="", name="case.toml"):
    text = (folder / "pad_disc.toml").read_text()
    assert old in text
    (folder / name).write_text(text.replace(old, new))
    return folder / name


@pytest.mark.parametrize("omega", [30.0, -30.0])
def test_the_disc_drags_the_pad_along_its_turning(folder, omega, capsys):
    path = _config(folder, "omega = 30.0", f"omega = {omega}")
    assert run(["fem", "steady", str(path), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["active_nodes"] == data["contact_nodes"] > 0 and data["loaded"]
    assert data["friction_force"] == pytest.approx(0.5 * data["normal_force"], rel=1e-12)
    problem = load_config(path).problem()
    st = problem.steady
    pts = problem.slave.body.points[problem.coupling.slave_nodes]
    u = st.u[: problem.slave.n_dofs].reshape(-1, 2)[problem.coupling.slave_nodes]
    e_theta = np.column_stack([-pts[:, 1], pts[:, 0]]) / np.hypot(pts[:, 0], pts[:, 1])[:, None]
    along = np.sum(u * e_theta, axis=1)  # the face's displacement along the counter-clockwise direction
    assert np.all(np.sign(along) == np.sign(omega))


def test_the_cea_finds_disc_modes_and_a_pad_disc_flutter(folder, capsys):
    assert run(["fem", "cea", str(folder / "pad_disc.toml"), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert len(data["modes"]) >= 10 and data["unstable"] >= 1  # the rigid disc gives none below 20 kHz
    assert data["params"]["master_mesh"] == "disc.msh" and data["units"]["modes.growth_rate"]["units"] == "1/s"
    frozen = _config(folder, "friction = 0.5", "friction = 0.0", "frictionless.toml")
    assert run(["fem", "cea", str(frozen), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["unstable"] == 0 and data["neutral"] == len(data["modes"])  # undamped, no friction: conservative


@pytest.mark.parametrize("old, new, words", [
    ("[partner]\n", '[surface]\nkind = "flat"\npoint = [0, 0]\nnormal = [0, 1]\nvelocity = [1, 0]\n[partner]\n',
     "exclude each other"),
    ('group = "rim"', 'group = "hub"', "partner.group"),
    ('clamped = ["hub"]', 'clamped = ["hub", "hub"]', "partner.clamped = ['hub', 'hub'] must name each group once"),
    ('group = "rim"', 'group = "spoke"', "partner.group = 'spoke' is not a boundary group"),
    ("omega = 30.0", "omega = 30.0\nvelocity = [1.0, 0.0]", "one of them"),
    ("young = 1.25e11", "young = -1.0", "partner.material.young"),
    ('mesh = "disc.msh"', 'mesh = "nowhere.msh"', "partner.mesh"),
    ("omega = 30.0", "velocity = [1.0, 0.0]", "partner.center applies with partner.omega only"),
    ("omega = 30.0", "velocity = [1.0, 0.0]\ngyroscopic = true", "true only with partner.omega"),
    ("count = 30", "count = 30\npenalty = 1e3", 'cea.penalty applies with cea.contact_model = "penalty" only'),
])
def test_a_bad_partner_is_refused_in_one_line(folder, old, new, words, capsys):
    path = _config(folder, old, new, "bad.toml")
    assert run(["fem", "steady", str(path)]) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and words in err, err


def test_gyroscopic_runs_are_refused_and_mode_shapes_of_a_pair_written(folder, tmp_path, capsys):
    """An explicit run takes the turning disc's transport terms (gyroscopic = true; their check
    against the exact motion is in test_pair_gyroscopic.py) and says so in its file. The mode file holds both bodies; each shape keeps the pad's face on the disc's rim (the
    held mortar constraints ``G_A u = 0`` of the written displacements, to 1e-8 of ``|G| |u|``)."""
    import meshio

    turning = _config(folder, "center = [0.0, 0.0]", "center = [0.0, 0.0]\ngyroscopic = true", "gyro.toml")
    ran = tmp_path / "turning.nc"
    assert run(["fem", "run", str(turning), "--transits", "1", "--out", str(ran)]) == 0
    capsys.readouterr()
    import xarray as xr
    with xr.open_dataset(ran) as ds:
        assert ds.attrs["gyroscopic"] == 1
    path = tmp_path / "modes.xdmf"
    assert run(["fem", "cea", str(folder / "pad_disc.toml"), "--xdmf", str(path), "--json"]) == 0
    count = len(json.loads(capsys.readouterr().out)["modes"])
    problem = load_config(folder / "pad_disc.toml").problem()
    held = problem.G[np.flatnonzero(problem.steady.active)]
    with meshio.xdmf.TimeSeriesReader(path) as reader:
        points, cells = reader.read_points_cells()
        assert reader.num_steps == count and len(points) == len(problem.slave.body.points) + len(
            problem.master.body.points)
        for k in range(reader.num_steps):
            _, data, _ = reader.read_data(k)
            u = (data["mode_real"][:, :2] + 1j * data["mode_imag"][:, :2]).ravel()
            assert np.abs(held @ u).max() <= 1e-8 * abs(held).max() * np.abs(u).max()
            assert set(np.unique(data["body"])) == {0, 1} and np.abs(u).max() == pytest.approx(1.0)


@pytest.mark.slow
def test_the_turning_discs_gyroscopic_terms(folder, capsys):
    """With ``gyroscopic = true`` (Eulerian disc): without friction still conservative (every mode
    neutral); with friction, the disc's doublets that were neutral become a growing and a
    decaying wave whose growth vanishes with the speed, in proportion (a tenfold slower disc,
    a growth rate 5 to 20 times smaller; first-order perturbation of a split doublet), while
    the strongest flutter moves by less than 2 % (thresholds before the run)."""
    def cea(omega, friction, gyroscopic="true"):
        path = _config(folder, "omega = 30.0", f"omega = {omega}", "gyro.toml")
        path.write_text(path.read_text().replace("friction = 0.5", f"friction = {friction}").replace(
            "center = [0.0, 0.0]\n", f"center = [0.0, 0.0]\ngyroscopic = {gyroscopic}\n"))
        assert run(["fem", "cea", str(path), "--json"]) == 0
        data = json.loads(capsys.readouterr().out)
        assert data["params"]["gyroscopic"] == int(gyroscopic == "true")
        return np.array([m["growth_rate"] + 2j * np.pi * m["frequency"] for m in data["modes"]]), data

    s, data = cea(30.0, 0.0)
    assert data["unstable"] == 0 and data["neutral"] == len(s) > 10
    plain, data = cea(30.0, 0.5, "false")
    neutral = np.abs(plain.real) <= 1e-7 * np.abs(plain)
    assert neutral.sum() >= 4
    slow, _ = cea(0.3, 0.5)
    fast, _ = cea(3.0, 0.5)
    ratios = []
    for x in plain[neutral]:
        a, b = slow[np.argmin(np.abs(slow - x))], fast[np.argmin(np.abs(fast - x))]
        ratios.append(abs(b.real) / abs(a.real))
    assert np.all((np.array(ratios) > 5) & (np.array(ratios) < 20)), ratios
    top = plain[np.argmax(plain.real)]
    assert abs(fast[np.argmin(np.abs(fast - top))] - top) < 0.02 * abs(top)


def test_a_pad_on_the_disc_takes_a_law_of_the_slip_speed_and_of_the_pressure(folder, capsys, tmp_path):
    """`[contact] law` and `pressure_exponent` with a `[partner]`: steady sliding's friction force is
    the sum over the slave nodes of the law at the disc's sliding speed times the pressure factor
    at each node's own pressure (computed here from the multipliers and the mortar weights), and
    the CEA and a short run go through, their attributes naming the laws."""
    from stickslip.friction import PressurePower, Stribeck

    path = _config(folder, "friction = 0.5", 'friction = 0.5\nstatic_friction = 0.6\nlaw = "stribeck"\n'
                   "stribeck_speed = 2.0\npressure_exponent = 0.2\nreference_pressure = 1e6")
    assert run(["fem", "steady", str(path), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    problem = load_config(path).problem()
    st, w = problem.steady, problem.coupling.weight
    speed = problem.tangent[1]
    mu = Stribeck(0.6, 0.5, 2.0).kinetic(speed) * PressurePower(1e6, 0.2).factor(st.pressure)
    assert data["friction_force"] == pytest.approx(float(np.sum(w * mu * st.pressure)), rel=1e-12)
    assert np.ptp(st.pressure[st.active]) > 0.05 * st.pressure.max()  # each node its own coefficient
    assert data["params"]["friction_law"].startswith("Stribeck") and data["params"]["pressure_exponent"] == 0.2
    assert run(["fem", "cea", str(path), "--json"]) == 0
    assert json.loads(capsys.readouterr().out)["modes"]
    out = tmp_path / "run.nc"
    assert run(["fem", "run", str(path), "--transits", "1", "--out", str(out), "--json"]) == 0
    import xarray as xr
    with xr.open_dataset(out) as ds:
        assert "Stribeck" in ds.attrs["friction_law"] and ds.attrs["reference_pressure"] == 1e6


def test_the_partners_material_is_set_from_the_command_line_as_in_its_file(folder, capsys):
    """Issue 44: `--set partner.material.young=...` was refused (only one level of tables was a key);
    it gives what the edited file gives, and a short name stays the body's own key."""
    from stickslip.fem.config import numeric_keys, read_toml, resolve_key

    data = read_toml(folder / "pad_disc.toml")
    assert {"partner.material.young", "partner.material.density"} <= set(numeric_keys(data))
    assert resolve_key(data, "young") == "material.young"
    edited = _config(folder, "young = 1.25e11", "young = 6.0e10", name="soft_disc.toml")
    results = []
    for args in ([str(folder / "pad_disc.toml"), "--set", "partner.material.young=6e10"], [str(edited)],
                 [str(folder / "pad_disc.toml")]):
        assert run(["fem", "steady", *args, "--json"]) == 0
        results.append(json.loads(capsys.readouterr().out))
    assert results[0] == results[1] and results[0]["normal_force"] != results[2]["normal_force"]
