"""Generated values in every numeric key of a config (the block on a belt): `stickslip fem steady`
either prints finite numbers (exit 0), or one line naming the key (exit 2), or one line saying
the problem has no solution (exit 1: a body a spring too weak to hold); never a traceback."""

import json
import math
import re
import shutil
import subprocess
import sys
from pathlib import Path

import pytest
from hypothesis import HealthCheck, given, settings
from hypothesis import strategies as st

from stickslip.cli import run

from ..budget import examples

EXAMPLE = Path(__file__).resolve().parents[2] / "examples" / "block_on_belt"

#: key -> (its line in block.toml, the TOML to put there with {v} the value)
KEYS = {"material.young": ("young = 1.0e9", "young = {v}"),
        "material.poisson": ("poisson = 0.3", "poisson = {v}"),
        "material.density": ("density = 1000.0", "density = {v}"),
        "contact.friction": ("friction = 0.4", "friction = {v}"),
        "contact.static_friction": ("static_friction = 0.6", "static_friction = {v}"),
        "spring[0].stiffness": ("stiffness = [9.5e5, 0.0]", "stiffness = [{v}, 0.0]"),
        "load[0].pressure": ("pressure = 1.0e6", "pressure = {v}"),
        "surface.velocity": ("velocity = [1.0, 0.0]", "velocity = [{v}, 0.0]"),
        "surface.normal": ("normal = [0.0, 1.0]", "normal = [{v}, 1.0]"),
        "surface.interference": ("kind = \"flat\"", "kind = \"flat\"\ninterference = {v}")}

VALUES = st.one_of(st.sampled_from(["0", "-1", "1e300", "-1e300", "1e-300", "nan", "inf", "-inf", '"abc"', "true",
                                    "[]"]),
                   st.floats(allow_nan=False, allow_infinity=False).map(repr))


@pytest.fixture(scope="module")
def folder(tmp_path_factory):
    path = tmp_path_factory.mktemp("block")
    shutil.copy(EXAMPLE / "block.toml", path)
    subprocess.run([sys.executable, str(EXAMPLE / "mesh.py"), "block.msh", "0.005"], cwd=path, check=True)
    return path


def _finite(x) -> bool:
    if isinstance(x, dict):
        return all(_finite(v) for v in x.values())
    if isinstance(x, list):
        return all(_finite(v) for v in x)
    return not isinstance(x, float) or math.isfinite(x)


@settings(max_examples=examples(60), suppress_health_check=[HealthCheck.function_scoped_fixture])
@given(key=st.sampled_from(sorted(KEYS)), value=VALUES)
def test_a_generated_value_in_any_key_gives_finite_numbers_or_one_line(folder, key, value, capsys):
    old, new = KEYS[key]
    text = (folder / "block.toml").read_text()
    assert old in text
    config = folder / "fuzz.toml"
    config.write_text(text.replace(old, new.format(v=value), 1))
    try:
        code = run(["fem", "steady", str(config), "--json"])
    except SystemExit as exit_:  # typer's own exits
        code = exit_.code
    out, err = capsys.readouterr()
    assert code in (0, 1, 2), (key, value, code, err)
    if code == 0:
        assert _finite(json.loads(out)), (key, value, out)
    elif code == 1:
        assert err.count("\n") == 1 and err.startswith("no solution"), (key, value, err)
    else:
        assert err.count("\n") == 1 and "Traceback" not in err, (key, value, err)
        short = key.split(".")[-1].split("[")[0]
        assert re.search(re.escape(short) + r"|config|mesh|group|surface|body|contact", err), (key, value, err)
