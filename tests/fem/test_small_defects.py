"""Smaller defects of `stickslip fem` found in issue 24, each failing on the old behaviour: a
CEA band without a mode wrote nothing and exited 2 with an internal message with --xdmf and 0
with no modes and no word without it; results were printed before --out was written."""

import pytest

from stickslip.cli import run
from stickslip.errors import ParameterError

from .test_materials import CONFIG, GOOD
from .meshes import two_layers


@pytest.fixture
def config(tmp_path):
    two_layers(tmp_path / "l.msh")
    path = tmp_path / "c.toml"
    path.write_text(CONFIG.format(materials=GOOD) + "\n[cea]\nband = [0.0, 10.0]\n")
    return path


@pytest.mark.parametrize("files", [[], ["--xdmf", "m.xdmf"], ["--out", "m.nc"]])
def test_a_band_without_a_mode_says_so_and_writes_nothing(config, files, capsys):
    args = [a if not a.startswith("m.") else str(config.parent / a) for a in files]
    assert run(["fem", "cea", str(config), "--json", *args]) == 1
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1 and "no mode of steady sliding has its frequency in cea.band" in err
    assert not list(config.parent.glob("m.*"))


@pytest.mark.parametrize("command", ["steady", "cea"])
def test_nothing_is_printed_when_the_output_cannot_be_written(command, config, tmp_path, monkeypatch, capsys):
    import stickslip.cli.fem as cli_fem

    def refuse(ds, path):
        raise ParameterError("--out", str(path), "a place the file can be written (the disc is full)")

    monkeypatch.setattr(cli_fem, "write_netcdf", refuse)
    if command == "cea":
        config.write_text(config.read_text().replace("band = [0.0, 10.0]", "band = [0.0, 60000.0]"))
    assert run(["fem", command, str(config), "--json", "--out", str(tmp_path / "x.nc")]) == 2
    out, err = capsys.readouterr()
    assert out == "" and "--out" in err


def test_steady_sliding_whose_active_set_cycles_says_so(tmp_path, capsys):
    """The pad example at friction 2: the active sets come round again (the old message: 'did
    not settle in 50 iterations', without a hint), now found at the first repeat and said."""
    import shutil
    import subprocess
    import sys

    from .test_examples import EXAMPLES

    shutil.copy(EXAMPLES / "pad_on_disc" / "pad.toml", tmp_path)
    subprocess.run([sys.executable, str(EXAMPLES / "pad_on_disc" / "mesh.py"), "pad.msh"], cwd=tmp_path, check=True)
    config = tmp_path / "pad.toml"
    config.write_text(config.read_text().replace("friction = 0.5", "friction = 2.0"))
    assert run(["fem", "steady", str(config)]) == 1
    err = capsys.readouterr().err
    assert err.count("\n") == 1 and "the contact's active set cycles through" in err and "contact.friction" in err
