"""The Python examples of the README and the tutorial run as written."""

import re
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[1]


def _blocks(name):
    """The Python blocks of a page: ```python, or an executed page's ```{code-cell} python."""
    return re.findall(r"```(?:python|\{code-cell\} python)\n(.*?)```", (ROOT / name).read_text(), flags=re.S)


def test_readme_example_runs(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    namespace = {}
    for block in _blocks("README.md"):
        exec(block, namespace)
    assert abs(namespace["cycle"].period - 6.712388980384690) < 1e-12
    assert (tmp_path / "run.nc").exists()


@pytest.mark.slow
def test_tutorial_examples_run(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    namespace = {}
    for block in _blocks("docs/tutorial-oscillator.md"):
        exec(block, namespace)
    assert namespace["hopf"].criticality == "subcritical"
    assert any(e["kind"] == "grazing" for e in namespace["stick_slip"].events)


def test_systems_page_runs(monkeypatch):
    monkeypatch.chdir(ROOT)  # it reads the example file by its path in the repository, and writes nothing
    namespace = {}
    for block in _blocks("docs/systems.md"):
        exec(block, namespace)
    assert list(namespace["run"].event_contact) == [1, 0, 0, 0, 0, 1, 1]
    assert list(namespace["ramp_run"].event_time) == [2.0]
    assert namespace["drop"].event_time[0] == pytest.approx((0.04 / 9.81) ** 0.5, rel=1e-13) and list(namespace["drop"].event_state) == [1, 0]
    assert namespace["ds"]["friction_force"].dims == ("t", "contact")
    cycle = namespace["cycle"]
    assert round(cycle.period, 2) == 6.69 and cycle.stable
    assert round(namespace["squeal_cycle"].period, 2) == 6.20 and list(namespace["squeal_cycle"].event_state) == [2, 1]
    assert namespace["slips"].event_time.size == 82
    assert abs(namespace["wave32"].shift_time - 0.1577) < 1e-4 and not namespace["wave32"].stable
    assert [(e["change"], round(e["value"], 4)) for e in namespace["branch"].events] == [("event sequence", 0.1494)]


def test_brake_tutorial_runs(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    namespace = {}
    for block in _blocks("docs/tutorial-brake.md"):
        exec(block, namespace)
    assert namespace["wave"].regime == "stick-slip-separation" and namespace["s"].p_e > 0
    assert namespace["regime"].regime.startswith("stick")
    assert not namespace["spectrum"].stable and namespace["table"]["speed_error"].values[-1] < 1e-3


def test_halfspace_tutorial_runs(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    namespace = {}
    for block in _blocks("docs/tutorial-halfspace.md"):
        exec(block, namespace)
    assert abs(namespace["wave"].c + 0.7) < 1e-6 and abs(namespace["wave"].b - 2.0) < 1e-6
    assert namespace["f"].slip_residual < 1e-10


def test_fem_tutorial_runs(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    namespace = {}
    for block in _blocks("docs/tutorial-fem.md"):
        exec(block, namespace)
    assert namespace["steady"].errors()["p"] < 1e-3 and namespace["rates"].growth_rate.max() > 0
    assert namespace["regime"].regime == "stick-slip" and namespace["regime"].n_zones == 7
    assert not namespace["partial"].complete and namespace["resumed"].complete
    assert (namespace["resumed"].U == namespace["whole"].U).all() and round(namespace["longer"].transits) == 150
    assert "checkpoint" in str(namespace["refused"]) and (tmp_path / "fem.nc").exists()


def test_your_body_tutorial_runs(tmp_path, monkeypatch):
    import subprocess
    import sys

    monkeypatch.chdir(tmp_path)  # the tutorial reads the example's mesh, made as it says
    subprocess.run([sys.executable, str(ROOT / "examples" / "block_on_belt" / "mesh.py"), "block.msh"], check=True)
    namespace = {}
    for block in _blocks("docs/tutorial-your-body.md"):
        exec(block, namespace)
    modes, run = namespace["modes"], namespace["run"]
    assert modes.growth_rate[0] > 0 and modes.frequency.max() <= 4e4
    assert run.to_xarray().fraction.sel(kind="stick").values[0] == 1.0  # it starts sticking on the belt


def test_readme_command_lines_use_only_options_their_commands_have():
    """Each `stickslip ...` line of the README and of the docs names a command that exists and
    only its options (a line once showed `brake steady --omega`, which the command does not
    take). The README's lines also run, in `test_readme_shell.py`."""
    import shlex

    import typer.main

    from stickslip.cli import app

    root = typer.main.get_command(app)
    root_dir = Path(__file__).resolve().parents[1]
    text = "\n".join(block for p in [root_dir / "README.md", *sorted((root_dir / "docs").rglob("*.md"))]
                     for block in re.findall(r"```sh\n(.*?)```", p.read_text(), flags=re.S))
    lines = [line.split("#")[0].strip().rstrip("\\").strip() for line in text.splitlines()
             if line.startswith("stickslip ") and line.strip() != "stickslip --version"]
    assert len(lines) > 20
    for line in lines:
        command, tokens = root, shlex.split(line)[1:]
        while tokens and hasattr(command, "commands") and tokens[0] in command.commands:
            command = command.commands[tokens.pop(0)]
        assert not hasattr(command, "commands"), line
        known = {opt for p in command.params for opt in p.opts}
        unknown = [t for t in tokens if t.startswith("--") and t not in known]
        assert not unknown, (line, unknown)


@pytest.mark.slow  # two rate-and-state cycles and a branch of four (Radau): the slowest test of the fast set, 112 s
def test_rsf_page_runs(monkeypatch):
    monkeypatch.chdir(ROOT)  # it reads an example file by its path in the repository
    namespace = {}
    for block in _blocks("docs/rsf.md"):
        exec(block, namespace)
    assert round(namespace["stability"].critical_stiffness / 5e9, 9) == 1.0 and namespace["stability"].stable
    assert round(namespace["cycle"].period) == 181
    assert set(namespace["ds"].data_vars) >= {"slip_rate", "theta", "friction", "shear_stress", "slip", "load_point"}
    assert not namespace["steady"].stable and round(namespace["steady"].growth_rate, 5) == 0.00308
    assert namespace["hopf"].criticality == "degenerate" and abs(namespace["hopf"].l1) < 1e-6
    assert namespace["burst"].slip_rate.max() > 1.2e-6
    branch = namespace["branch"]
    assert branch.stopped.startswith("reached") and np.all(np.diff(branch.amplitude[:, 0]) < 0)
    assert round(branch.period[-1], 1) == 88.9
    assert list(namespace["run"].event_state[:4]) == [0, 1, 0, 1] and namespace["run"].slip_rate[:, 0].max() > 5e-3
