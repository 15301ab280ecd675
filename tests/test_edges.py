"""The unusual inputs of issue 23, one by one, each tried as a new user would: results are never
replaced without --overwrite, paths the file system cannot take, damaged and foreign stores, a
map of the same axis twice or of 1e8 points, options given without the one they need, a second
writer, and configs that are not UTF-8 or nest too deeply. Each is one line on stderr naming the
option as typed, exit 2, and nothing written."""

from __future__ import annotations

from pathlib import Path

import pytest

from stickslip.cli import run
from stickslip.files import exclusive

from .fuzz_harness import SYSTEM_FILE, example_config

OSC = ["--mass", "1", "--stiffness", "1", "--normal-force", "1", "--belt-speed", "0.2", "--fs", "0.6", "--fd", "0.4"]
MAP = ["oscillator", "map", "--mass", "1", "--stiffness", "1", "--normal-force", "1", "--fs", "0.6", "--fd", "0.4",
       "--x", "belt_speed=0.2:0.3:2", "--y", "damping=0.01:0.02:2", "--workers", "1"]


def refused(capsys, args, *words):
    assert run(args) == 2, args
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1 and "Traceback" not in err, err
    for w in words:
        assert w in err, (w, err)
    return err


#: ``(command args, output option, suffix)`` of every command that writes a result file.
WRITERS = [
    (["oscillator", "simulate", *OSC, "--t-end", "2"], "--out", ".nc"),
    (["oscillator", "simulate", *OSC, "--t-end", "2"], "--plot", ".png"),
    (["oscillator", "cycle", *OSC], "--out", ".nc"),
    (["oscillator", "continue", *OSC, "--stop", "0.25"], "--out", ".nc"),
    (["halfspace", "fields", "--b", "11.358", "--c", "-0.7", "--v-star", "0.001", "--points", "101"], "--out", ".nc"),
    (["brake", "wave", "--omega", "50", "--mismatch", "1e-4", "--friction", "0.7", "--wave-number", "8"], "--out",
     ".nc"),
    (["fem", "steady", "{config}"], "--out", ".nc"),
    (["fem", "cea", "{config}"], "--xdmf", ".xdmf"),
    (["system", "stability", SYSTEM_FILE], "--out", ".nc"),
]


@pytest.mark.parametrize("args, option, suffix", WRITERS, ids=[f"{' '.join(a[:2])} {o}" for a, o, _ in WRITERS])
def test_no_command_replaces_an_existing_file_without_overwrite(args, option, suffix, tmp_path, capsys):
    args = [example_config() if a == "{config}" else a for a in args]
    target = tmp_path / f"result{suffix}"
    target.write_text("someone's result")
    refused(capsys, [*args, option, str(target)], option, "exists", "--overwrite")
    assert target.read_text() == "someone's result"
    assert run([*args, option, str(target), "--overwrite", "--json"]) == 0
    capsys.readouterr()
    assert target.read_bytes() != b"someone's result"


def test_overwrite_without_an_output_is_refused(capsys):
    refused(capsys, ["oscillator", "cycle", *OSC, "--overwrite"], "--overwrite", "--out or --plot")


@pytest.mark.parametrize("args, option", [
    (["oscillator", "simulate", *OSC, "--t-end", "1", "--out"], "--out"),
    (["oscillator", "cycle", *OSC, "--plot"], "--plot"),
    (MAP + ["--out"], "--out"),
])
def test_a_name_longer_than_the_file_system_takes_is_refused_before_any_work(args, option, tmp_path, capsys):
    suffix = {"--plot": ".png"}.get(option, ".zarr" if "map" in args else ".nc")
    long = tmp_path / ("a" * 300 + suffix)
    refused(capsys, [*args, str(long)], option, "at most 255 bytes")
    assert list(tmp_path.iterdir()) == []


def test_a_store_with_a_damaged_axis_is_said_to_be_damaged(tmp_path, capsys):
    store = tmp_path / "m.zarr"
    assert run(MAP + ["--out", str(store), "--json"]) == 0
    capsys.readouterr()
    (store / "belt_speed" / "0").write_bytes(b"garbage bytes here!!")
    refused(capsys, MAP + ["--out", str(store)], "--out", "damaged", "overwrite")
    assert run(MAP + ["--out", str(store), "--overwrite", "--json"]) == 0


def test_a_second_writer_of_a_store_is_told_about_out(tmp_path, capsys):
    store = tmp_path / "m.zarr"
    with exclusive(store, "store"):
        refused(capsys, MAP + ["--out", str(store)], "--out", "no other run is writing")


@pytest.mark.parametrize("x, y, option, words", [
    ("belt_speed=0.2:0.3:2", "belt_speed=0.4:0.5:3", "--y", "another parameter than --x"),
    ("belt_speed=0.2:0.3:10000", "damping=0.01:0.02:10000", "--y", "1e+06 points"),
])
def test_a_map_of_one_parameter_twice_or_of_1e8_points_is_refused(x, y, option, words, tmp_path, capsys):
    args = [a for a in MAP if a not in ("--x", "--y", "belt_speed=0.2:0.3:2", "damping=0.01:0.02:2")]
    refused(capsys, args + ["--x", x, "--y", y, "--out", str(tmp_path / "m.zarr")], option, words)
    assert not (tmp_path / "m.zarr").exists()


def test_a_brake_map_axis_out_of_the_waves_range_names_the_axis_and_leaves_no_store(tmp_path, capsys):
    store = tmp_path / "b.zarr"
    base = ["brake", "map", "--out", str(store), "--workers", "1"]
    refused(capsys, base + ["--x", "friction=0:2:2", "--y", "mismatch=1e-7:1e-5:2:log"], "--x = 'friction=0:2:2'",
            "with --kind waves")
    refused(capsys, base + ["--x", " friction=0.2:2:2", "--y", "mismatch=1e-7:1:2:log"], "--y", "0.01 x")
    assert not store.exists()


def test_the_material_without_the_shaft_speed_names_the_missing_option(capsys):
    refused(capsys, ["brake", "coefficients", "--young", "2e11"], "missing --omega", "--young")
    refused(capsys, ["brake", "wave", "--xi", "1.5", "--gamma", "1e-6", "--friction", "0.7"], "missing --delta")


@pytest.mark.parametrize("text, words", [
    (b"# caf\xe9\n", "UTF-8"),
    (("x = " + "[" * 3000 + "1" + "]" * 3000 + "\n").encode(), "nested"),
    (("x = " + "{a=" * 3000 + "1" + "}" * 3000 + "\n").encode(), "nested"),
])
def test_a_config_that_is_not_utf8_or_nests_too_deeply_is_named(text, words, tmp_path, capsys):
    config = tmp_path / "c.toml"
    config.write_bytes(text + Path(example_config()).read_bytes())
    refused(capsys, ["fem", "steady", str(config)], "config", "c.toml", words)


def test_an_absurd_interference_is_named_as_such_not_as_the_speed(tmp_path, capsys):
    text = Path(example_config()).read_text()
    # 2 mm into a pad 15.3 mm wide at its narrowest: a strain of 0.13 (issue 44: it ran at GPa without a word)
    for value, words in (("1e10", "in [-1000, 1000] m"), ("1e-2", "0.1 x the length of the contact group"),
                         ("2e-3", "implies a strain of about 0.13"), ("-2e-3", "linear elasticity is a model of small")):
        config = tmp_path / "i.toml"
        config.write_text(text.replace("interference = 2e-6", f"interference = {value}").replace(
            'mesh = "pad.msh"', f'mesh = "{example_config().replace("pad.toml", "pad.msh")}"'))
        err = refused(capsys, ["fem", "steady", str(config)], "surface.interference", words)
        assert "omega" not in err


def _pad_config(tmp_path, old, new):
    text = Path(example_config()).read_text()
    assert old in text, old
    config = tmp_path / "p.toml"
    config.write_text(text.replace(old, new).replace('mesh = "pad.msh"',
                                                     f'mesh = "{example_config().replace("pad.toml", "pad.msh")}"'))
    return config


def test_a_cea_band_beyond_the_mesh_and_too_many_eigenvalues_are_refused_up_front(tmp_path, capsys):
    """A band to 1e9 Hz on a mesh whose highest mode is near 280 kHz ran for minutes (to 1e300
    it never ended); 1000 eigenvalues per shift on a fine mesh likewise."""
    config = _pad_config(tmp_path, "band = [0.0, 150000.0]", "band = [0.0, 1e9]")
    refused(capsys, ["fem", "cea", str(config)], "cea.band", "the mesh's highest frequency")
    config = _pad_config(tmp_path, "count = 30", "count = 1000")
    refused(capsys, ["fem", "cea", str(config)], "cea.count = 1000", "[2, 200]")


def test_damping_that_overdamps_the_whole_band_is_no_solution_at_once(tmp_path, capsys):
    """alpha = 1e9 1/s overdamps every mode below 80 MHz: no mode oscillates, exit 1 in a second
    (the search ground for 2.5 minutes before giving up)."""
    config = _pad_config(tmp_path, "poisson = 0.25", "poisson = 0.25\nalpha = 1e9")
    assert run(["fem", "cea", str(config)]) == 1
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1 and "overdamps every mode of the band" in err


def test_an_annulus_mesh_beyond_the_memory_budget_is_refused_before_it_is_built(capsys):
    refused(capsys, ["brake", "fem", "--xi", "1.5", "--gamma", "0.01", "--delta", "0.001", "--friction", "0.3",
                     "--n-theta", "65536", "--n-r", "4096", "--transits", "1"], "--n-r = 4096", "at most 15 ",
            "1048576 nodes")


def test_a_group_clamped_twice_is_named(tmp_path, capsys):
    config = _pad_config(tmp_path, 'clamped = ["back"]', 'clamped = ["back", "back"]')
    refused(capsys, ["fem", "steady", str(config)], "clamped = ['back', 'back']", "'back' twice")


@pytest.mark.parametrize("c, v_star, words", [("-0.7", "1", "T = 2.466, outside (0, 1]"),
                                              ("-0.7", "0.5", "T = 1.233, outside (0, 1]")])
def test_a_wave_whose_traction_leaves_the_elastic_range_is_no_solution(c, v_star, words, tmp_path, capsys):
    """b = 5 with a slip speed near the shear wave speed asks a traction over the shear modulus of
    the inverse problem: no wave (exit 1, one line naming T and its range), no file written — it
    used to print T = 2.5 as a result."""
    out_file = tmp_path / "w.nc"
    assert run(["halfspace", "fields", "--b", "5", "--c", c, "--v-star", v_star, "--points", "11",
                "--out", str(out_file)]) == 1
    out, err = capsys.readouterr()
    assert out == "" and err.count("\n") == 1 and words in err, err
    assert not out_file.exists()


def test_a_tiny_mass_costs_no_more_memory_than_its_cycle_needs(tmp_path):
    """A 5e-12 kg block (angular frequency 4.5e5 rad/s) on a stick-slip cycle of a handful of
    segments: the closed-form integrator allocated segments for t_end x omega (1e7 of them,
    6.4 GB, 45 s; found by the drawn fuzz battery as a hang) instead of growing to what a run
    uses. Peak memory of the child under 1 GB (about 0.27 GB now)."""
    import subprocess
    import sys

    command = ["oscillator", "continue", "--stiffness", "1", "--normal-force", "1", "--belt-speed", "0.2", "--fs",
               "0.6", "--fd", "0.4", "--stop", "0.3", "--mass", "4.97e-12", "--json"]
    # a wrapper of its own measures its one child (this process's other children do not count)
    wrapper = ("import resource, subprocess, sys; done = subprocess.run([sys.executable, '-m', 'stickslip', "
               f"*{command!r}], capture_output=True); "
               "print(done.returncode, resource.getrusage(resource.RUSAGE_CHILDREN).ru_maxrss)")
    done = subprocess.run([sys.executable, "-c", wrapper], cwd=tmp_path, capture_output=True, text=True, timeout=600)
    code, peak_kb = map(int, done.stdout.split())
    assert code == 0 and peak_kb < 1_000_000, (code, peak_kb, done.stderr)
