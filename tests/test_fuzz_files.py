"""Files that are corrupt or of another kind, wherever a command reads one (issue 23): a config,
the mesh a config names, a run's checkpoint resumed from ``--out``, a map's store. Each is one
line on stderr naming what was read (the option as typed, or the config), exit 2, no traceback,
and the file is left as it was."""

from __future__ import annotations

import shutil
from pathlib import Path

import numpy as np
import pytest
import xarray as xr

from stickslip.cli import run

from .fuzz_harness import BASE, example_config

#: What a file may turn out to hold: ``name -> writer(path)``.
KINDS = {
    "empty": lambda p: p.write_bytes(b""),
    "random bytes": lambda p: p.write_bytes(np.random.default_rng(0).bytes(4096)),
    "text": lambda p: p.write_text("this is not what you think it is\n" * 20),
    "a PNG": lambda p: p.write_bytes(b"\x89PNG\r\n\x1a\n" + bytes(200)),
    "another netCDF": lambda p: xr.Dataset({"x": ("n", np.arange(3.0))}).to_netcdf(p),
    "a truncated netCDF": lambda p: (xr.Dataset({"x": ("n", np.arange(1000.0))}).to_netcdf(p),
                                     p.write_bytes(p.read_bytes()[:1500])),
}

#: ``(command, the option that reads a file, its suffix)``; ``{config}`` is the pad example.
READERS = [
    ("fem steady", "config", ".toml"),
    ("fem steady", "mesh", ".msh"),
    ("brake integrate", "--out", ".nc"),
    ("brake fem", "--out", ".nc"),
    ("fem run", "--out", ".nc"),
]
CASES = [(c, o, s, k) for c, o, s in READERS for k in KINDS]


def _args(command, option, target, tmp_path):
    base = [a.replace("{tmp}", str(tmp_path)) for a in BASE[command]]
    if option == "config":
        return command.split() + [str(target)] + base[1:] + ["--json"]
    if option == "mesh":
        config = tmp_path / "pad.toml"
        config.write_text(Path(example_config()).read_text().replace('mesh = "pad.msh"', f'mesh = "{target.name}"'))
        return command.split() + [str(config)] + base[1:] + ["--json"]
    base = [example_config() if a == "{config}" else a for a in base]
    i = base.index(option)
    return command.split() + base[:i] + [option, str(target)] + base[i + 2:] + ["--json"]


@pytest.mark.parametrize("command, option, suffix, kind", CASES, ids=[f"{c} {o} {k}" for c, o, _, k in CASES])
def test_a_corrupt_or_foreign_file_is_named_in_one_line(command, option, suffix, kind, tmp_path, capsys):
    target = tmp_path / f"read{suffix}"
    KINDS[kind](target)
    before = target.read_bytes()
    code = run(_args(command, option, target, tmp_path))
    out, err = capsys.readouterr()
    assert code == 2 and out == "" and err.count("\n") == 1 and "Traceback" not in err, (code, err)
    named = {"config": "config", "mesh": "mesh"}.get(option, option)
    assert named in err and target.name in err, err
    assert target.read_bytes() == before  # refused, not replaced


STORES = [("oscillator map", "--out"), ("brake map", "--out")]


@pytest.mark.parametrize("command, option", STORES)
@pytest.mark.parametrize("kind", ["a folder of other files", "another map's store", "a store without metadata"])
def test_a_folder_that_is_not_this_maps_store_is_refused(command, option, kind, tmp_path, capsys):
    base = [a.replace("{tmp}", str(tmp_path)) for a in BASE[command]]
    store = Path(base[base.index(option) + 1])
    if kind == "a folder of other files":
        store.mkdir()
        (store / "notes.txt").write_text("mine")
    else:
        other = [a.replace("{tmp}", str(tmp_path / "o")) for a in BASE["oscillator map"]]
        (tmp_path / "o").mkdir()
        assert run(["oscillator", "map", *other, "--json"]) == 0
        shutil.copytree(Path(other[other.index("--out") + 1]), store, dirs_exist_ok=True)
        if kind == "a store without metadata":
            for meta in store.rglob(".z*"):
                meta.unlink()
        if command == "oscillator map" and kind == "another map's store":
            base[base.index("--x") + 1] = "belt_speed=0.2:0.4:2"  # the same map but another axis
    capsys.readouterr()
    assert run(command.split() + base + ["--json"]) == 2
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1 and option in err and "Traceback" not in err, err
