"""The Python examples of the README and the tutorial run as written."""

import re
from pathlib import Path

import numpy as np
import pytest

ROOT = Path(__file__).resolve().parents[1]


def _blocks(name):
    """The Python blocks of a page: ```python, or an executed page's ```{code-cell} python, as
    Python: without a cell's options (``:tags: [...]``) and IPython's magics (``%matplotlib inline``)."""
    blocks = re.findall(r"```(?:python|\{code-cell\} python)\n(.*?)```", (ROOT / name).read_text(), flags=re.S)
    return ["\n".join(line for line in block.splitlines() if not re.match(r"%|:\w+:", line)) for block in blocks]


#: The pages whose examples run when the docs are built (myst-nb), as docs/check_html.py names them.
EXECUTED_PAGES = ("tutorial-oscillator", "tutorial-brake", "tutorial-fem", "tutorial-halfspace", "tutorial-your-body",
                  "systems", "rsf", "sweeps-on-a-cluster", "brakes-3d")
#: A comment saying what a line gives instead of a cell printing it.
RESULT_COMMENT = re.compile(r"#\s*(?:gives|returns|->|=>)")


def executed_page_problems(text: str) -> list[str]:
    """Why a page is not one whose examples run and show their results: not a myst-nb page, no
    code cell, a Python block that is not a cell (unless it says it is not run), a line whose value
    is thrown away (a bare expression before a cell's last line: the page showed "x.y  # 0.4"), a
    comment giving a result."""
    import ast

    found = []
    if not text.startswith("---\nfile_format: mystnb\n"):
        found.append("not a myst-nb page (file_format: mystnb)")
    cells = re.findall(r"```\{code-cell\} (?:python|ipython3)\n(.*?)```", text, flags=re.S)
    if not cells:
        found.append("no code cell")
    for block in re.findall(r"```python\n(.*?)```", text, flags=re.S):
        if not block.startswith("# not run"):
            found.append(f"a Python block that does not run: {block.splitlines()[0]!r}")
    for cell in cells:
        code = "\n".join(line for line in cell.splitlines() if not re.match(r"%|:\w+:", line))
        body = ast.parse(code).body
        lines = code.splitlines()
        for i, statement in enumerate(body):
            if isinstance(statement, ast.Expr) and not isinstance(statement.value, (ast.Call, ast.Constant)):
                if i < len(body) - 1:
                    found.append(f"a value thrown away: {ast.get_source_segment(code, statement)!r}")
                elif "#" in lines[statement.end_lineno - 1]:  # a value shown, and stated again by hand
                    found.append(f"a result in a comment: {lines[statement.end_lineno - 1].strip()!r}")
        found += [f"a result in a comment: {line.strip()!r}" for line in code.splitlines() if RESULT_COMMENT.search(line)]
    return found


def test_every_tutorial_page_runs_its_examples_and_shows_their_results():
    problems = {name: bad for name in EXECUTED_PAGES if (bad := executed_page_problems((ROOT / "docs" / f"{name}.md").read_text()))}
    assert not problems, problems
    html_check = (ROOT / "docs" / "check_html.py").read_text()
    assert all(f'"{name}"' in html_check for name in EXECUTED_PAGES)  # the built pages are checked for output and a picture


def test_a_page_of_comments_instead_of_outputs_is_found():
    old = "# A page\n\n```python\nosc.stick_limits        # (-0.6, 0.6)\nosc.equilibrium  # gives 0.4\n```\n"
    assert executed_page_problems(old) == ["not a myst-nb page (file_format: mystnb)", "no code cell",
                                           "a Python block that does not run: 'osc.stick_limits        # (-0.6, 0.6)'"]
    front = "---\nfile_format: mystnb\n---\n"
    cell = "```{code-cell} python\n%matplotlib inline\ncycle.period, cycle.stick_time   # 6.71, 2.0\nx = f(1)  # -> 0.5\nfig\n```\n"
    assert executed_page_problems(front + cell) == ["a value thrown away: 'cycle.period, cycle.stick_time'",
                                                    "a result in a comment: 'x = f(1)  # -> 0.5'"]
    last = "```{code-cell} python\nprint(1)\nosc.equilibrium  # 0.4: steady sliding\n```\n"
    assert executed_page_problems(front + last) == ["a result in a comment: 'osc.equilibrium  # 0.4: steady sliding'"]
    good = "```{code-cell} python\n:tags: [remove-cell]\nprint(cycle.period)\nfig\n```\n```python\n# not run here: SLURM\nx\n```\n"
    assert executed_page_problems(front + good) == []


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


@pytest.mark.slow  # with the friction damper's frequency response run as a command (about 10 s); `make docs` runs the page too
def test_systems_page_runs(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # its first (hidden) cell copies the repository's examples beside it
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


@pytest.mark.slow  # 7-8 s: the fast set was 265 s of its 240 on a fresh clone (the page runs at make docs too)
def test_brake_tutorial_runs(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    namespace = {}
    for block in _blocks("docs/tutorial-brake.md"):
        exec(block, namespace)
    assert namespace["wave"].regime == "stick-slip-separation" and namespace["s"].p_e > 0
    assert namespace["regime"].regime.startswith("stick")
    # the discrete wave's speed converges at second order on 32 and 64 nodes, and the wave is unstable
    assert not namespace["spectrum"].stable and abs(namespace["table"]["observed_order"].values[-1] - 2) < 0.1


def test_halfspace_tutorial_runs(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)
    namespace = {}
    for block in _blocks("docs/tutorial-halfspace.md"):
        exec(block, namespace)
    assert abs(namespace["wave"].c + 0.7) < 1e-6 and abs(namespace["wave"].b - 2.0) < 1e-6
    assert namespace["f"].slip_residual < 1e-10


@pytest.mark.slow  # 7-8 s: the fast set was 265 s of its 240 on a fresh clone (the page runs at make docs too)
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


@pytest.mark.slow  # 15 s; `make docs` executes the same page (the fast set's budget)
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
def test_rsf_page_runs(tmp_path, monkeypatch):
    monkeypatch.chdir(tmp_path)  # its first (hidden) cell copies the repository's examples beside it
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
