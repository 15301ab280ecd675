"""What `stickslip fem` refuses, warns about or records, as a user meets it on the examples:
a surface on the wrong side, a clamped contact line, damping that overdamps the mesh, a run
shorter than its checkpoint, a result file over a run's checkpoint, a CEA that cannot cover
the strip asked for, and the problem written with every result."""

import json
import shutil
import subprocess
import sys
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from stickslip.cli import run

EXAMPLES = Path(__file__).resolve().parents[2] / "examples"


@pytest.fixture(scope="module")
def meshes(tmp_path_factory):
    """The block's and the pad's meshes, made once by their scripts."""
    folder = tmp_path_factory.mktemp("meshes")
    for name, mesh in (("block_on_belt", "block.msh"), ("pad_on_disc", "pad.msh")):
        subprocess.run([sys.executable, str(EXAMPLES / name / "mesh.py"), str(folder / mesh)], check=True)
    return folder


def edited(meshes, tmp_path, name, config, *changes):
    """The example's config beside its mesh, with ``(old, new)`` text replacements."""
    text = (EXAMPLES / name / config).read_text()
    for old, new in changes:
        assert old in text, old
        text = text.replace(old, new)
    mesh = config.replace(".toml", ".msh")
    if not (tmp_path / mesh).exists():
        shutil.copy(meshes / mesh, tmp_path / mesh)
    path = tmp_path / f"{len(list(tmp_path.glob('*.toml')))}-{config}"
    path.write_text(text)
    return path


def refused(capsys, args, *words):
    assert run(args) == 2
    err = capsys.readouterr().err
    assert err.count("\n") == 1, err
    for w in words:
        assert w in err, (w, err)
    return err


def test_a_surface_on_the_wrong_side_is_refused_naming_what_to_change(meshes, tmp_path, capsys):
    drum = edited(meshes, tmp_path, "pad_on_disc", "pad.toml", ("interference = 2e-6", "interference = 2e-6\n"
                                                                 "body_inside = true"))
    refused(capsys, ["fem", "steady", str(drum)], "surface.body_inside = true", "try body_inside = false")
    down = edited(meshes, tmp_path, "block_on_belt", "block.toml", ("normal = [0.0, 1.0]", "normal = [0.0, -1.0]"))
    refused(capsys, ["fem", "cea", str(down)], "surface.normal = [0.0, -1.0]", "try normal = [0, 1]")


def test_a_gap_below_the_block_is_closed_by_its_load(meshes, tmp_path, capsys):
    """The belt 1 micrometre below the block: the load (1e6 Pa on 0.1 m) closes the gap and the
    belt carries all of it; the top moves down by the gap plus the compression."""
    gap = edited(meshes, tmp_path, "block_on_belt", "block.toml", ("point = [0.0, 0.0]", "point = [0.0, -1e-6]"))
    assert run(["fem", "steady", str(gap), "--json"]) == 0
    data = json.loads(capsys.readouterr().out)
    assert data["normal_force"] == pytest.approx(1e5, rel=1e-9) and data["active_nodes"] >= 30


def test_a_clamped_contact_group_and_a_runaway_belt_are_refused(meshes, tmp_path, capsys):
    both = edited(meshes, tmp_path, "pad_on_disc", "pad.toml", ('clamped = ["back"]', 'clamped = ["back", "face"]'))
    refused(capsys, ["fem", "run", str(both)], "must not hold the contact group 'face'")
    fast = edited(meshes, tmp_path, "block_on_belt", "block.toml", ("velocity = [1.0, 0.0]", "velocity = [1e12, 0.0]"))
    refused(capsys, ["fem", "run", str(fast), "--start", "stick"], "surface.velocity = [1000000000000.0, 0.0]",
             "each in [-1e4, 1e4] m/s")
    spin = edited(meshes, tmp_path, "pad_on_disc", "pad.toml", ("omega = 30.0", "omega = 1e9"))
    refused(capsys, ["fem", "cea", str(spin)], "surface.omega = 1000000000.0")


def test_keys_of_the_other_surface_and_a_missing_surface_are_named(meshes, tmp_path, capsys):
    flat = edited(meshes, tmp_path, "block_on_belt", "block.toml", ('kind = "flat"', 'kind = "flat"\nradius = 1.0'))
    refused(capsys, ["fem", "steady", str(flat)], "surface.radius does not apply to kind = 'flat'")
    text = flat.read_text()
    flat.write_text(text[:text.index("[surface]")] + text[text.index("[cea]"):])
    refused(capsys, ["fem", "steady", str(flat)], "[surface] is missing")


def test_damping_that_overdamps_the_mesh_is_refused_before_any_step(meshes, tmp_path, capsys):
    """The block's highest mode is near 9.4e5 rad/s: beta = 0.005 s damps it 2e3 times critically,
    and the explicit step would shrink by as much (the run would crawl for hours): refused for
    a run, with the bound (100 times critical: beta <= 200 / omega_max). alpha = 1e300 is out of
    any range."""
    heavy = edited(meshes, tmp_path, "block_on_belt", "block.toml", ("poisson = 0.3", "poisson = 0.3\nbeta = 0.005"))
    err = refused(capsys, ["fem", "run", str(heavy)], "material.beta = 0.005", "100 times critically damped")
    bound = float(err.split("must be <= ")[1].split()[0])
    assert 200 / 1.1e6 < bound < 200 / 0.8e6
    huge = edited(meshes, tmp_path, "block_on_belt", "block.toml", ("poisson = 0.3", "poisson = 0.3\nalpha = 1e300"))
    refused(capsys, ["fem", "cea", str(huge)], "material.alpha = 1e+300")
    light = edited(meshes, tmp_path, "block_on_belt", "block.toml",
                    ("poisson = 0.3", f"poisson = 0.3\nbeta = {0.5 * bound:.6g}"))
    assert run(["fem", "run", str(light), "--transits", "0.2", "--json"]) == 0


def test_a_run_too_short_or_a_step_too_small_names_the_option_as_typed(meshes, tmp_path, capsys):
    block = edited(meshes, tmp_path, "block_on_belt", "block.toml")
    err = refused(capsys, ["fem", "run", str(block), "--transits", "1e-9"], "--transits = 1e-09", "3 snapshots")
    least = float(err.split("must be > ")[1].split()[0])
    assert run(["fem", "run", str(block), "--transits", f"{least * 1.05:.4g}", "--json"]) == 0  # the bound is right
    capsys.readouterr()
    refused(capsys, ["fem", "run", str(block), "--time-step", "1e-300"], "--time-step = 1e-300")


def test_a_checkpoint_is_not_cut_short_nor_replaced_by_a_result(meshes, tmp_path, capsys):
    block = edited(meshes, tmp_path, "block_on_belt", "block.toml")
    out = tmp_path / "run.nc"
    assert run(["fem", "run", str(block), "--transits", "0.5", "--out", str(out), "--json"]) == 0
    first = json.loads(capsys.readouterr().out)
    assert first["params"]["mesh"] == "block.msh" and first["params"]["surface"].startswith("flat through (0, 0) m")
    refused(capsys, ["fem", "run", str(block), "--transits", "0.25", "--out", str(out)], "no longer than",
             "overwrite it to start afresh")
    assert run(["fem", "run", str(block), "--transits", "0.5", "--out", str(out), "--json"]) == 0  # the same run
    assert json.loads(capsys.readouterr().out) == first
    err = refused(capsys, ["fem", "run", str(block), "--transits", "0.5", "--beta2", "0.8", "--out", str(out)],
                   "beta2: stored 0.9, now 0.8")
    assert "overwrite=True" not in err
    for command in ("steady", "cea"):
        refused(capsys, ["fem", command, str(block), "--out", str(out)], "holds a run", "--overwrite")
    assert run(["fem", "steady", str(block), "--out", str(out), "--overwrite"]) == 0
    capsys.readouterr()
    junk = tmp_path / "junk.nc"
    junk.write_text("not netCDF")
    refused(capsys, ["fem", "run", str(block), "--out", str(junk)], "not netCDF")


def test_a_cea_that_cannot_cover_the_strip_asked_for_says_so(meshes, tmp_path, capsys):
    pad = edited(meshes, tmp_path, "pad_on_disc", "pad.toml")
    modes = tmp_path / "modes.nc"
    assert run(["fem", "cea", str(pad), "--json", "--out", str(modes)]) == 0
    captured = capsys.readouterr()
    data = json.loads(captured.out)
    assert "warning" not in captured.err
    assert data["asked_below"] == pytest.approx(0.1 * 2 * np.pi * 150000.0, rel=1e-12)
    assert data["complete_below"] >= data["asked_below"] and data["shift_count"] >= 2
    assert data["units"]["shift_count"]["units"] == "1"
    with xr.open_dataset(modes) as ds:
        assert ds.attrs["surface"].startswith("cylinder of radius") and ds.attrs["young"] == 1e10
    tight = edited(meshes, tmp_path, "pad_on_disc", "pad.toml", ("count = 30", "count = 2\ncomplete_below = 1e9"))
    assert run(["fem", "cea", str(tight), "--json"]) == 0
    captured = capsys.readouterr()
    data = json.loads(captured.out)
    assert data["complete_below"] < 1e9 == data["asked_below"]
    assert captured.err.count("\n") == 1 and captured.err.startswith("warning: modes growing or decaying faster")


def test_a_load_beyond_small_strains_names_the_load_and_the_modulus(meshes, tmp_path, capsys):
    """1e6 Pa on a block of modulus 1e6 Pa (with 1e-300 Pa, now out of the declared range, it was:
    'the body is not held', exit 1)."""
    soft = edited(meshes, tmp_path, "block_on_belt", "block.toml", ("young = 1.0e9 ", "young = 1e6 "))
    refused(capsys, ["fem", "steady", str(soft)], "load[0].pressure = 1000000.0 must be at most 0.1 x material.young")
    from stickslip.errors import ParameterError
    from stickslip.fem import Material, assemble, read_body
    from stickslip.fem.boundary import Load

    body = read_body(meshes / "block.msh")
    assemble(body, Material(1e8, 0.3, 1e3), loads=[Load("top", 1e7)])
    with pytest.raises(ParameterError, match="invalid load.pressure = 10000000.0.*the bound depends on young"):
        assemble(body, Material(1e8 * 0.99, 0.3, 1e3), loads=[Load("top", 1e7)])
