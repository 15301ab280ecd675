"""The command line presents itself as click's best do (issue 27): help when called bare (exit 0
at the top, 2 where a group needs a command), completion, options grouped by topic, one example
per command that parses as written, and ``--plot`` in the format its suffix names."""

import os
import re
import shlex
import subprocess
import sys
from pathlib import Path

import pytest
import typer

from stickslip.cli import app, run
from stickslip.cli.helptext import ARGUMENTS, EXAMPLES, MODEL, PANELS, command_tree

ROOT = Path(__file__).resolve().parents[1]
OSC = ["--mass", "1", "--stiffness", "1", "--normal-force", "1", "--belt-speed", "0.2", "--fs", "0.6", "--fd", "0.4"]


def _leaves(command=None, path=()):
    command = command_tree(app) if command is None else command
    subs = getattr(command, "commands", None)
    if subs is None:
        return [(" ".join(path), command)]
    return [leaf for name, sub in subs.items() for leaf in _leaves(sub, path + (name,))]


def _groups():
    return [name for name, sub in command_tree(app).commands.items() if hasattr(sub, "commands")]


LEAVES = _leaves()


def test_bare_top_level_prints_its_help_and_exits_0(capsys):
    assert run([]) == 0
    out = capsys.readouterr().out
    assert out.startswith("Usage: stickslip") and "Commands:" in out and "oscillator" in out


@pytest.mark.parametrize("group", _groups())
def test_a_bare_group_prints_its_help_and_exits_2(group, capsys):
    assert run([group]) == 2  # click's convention: a group needs a command
    err = capsys.readouterr().err
    assert err.startswith(f"Usage: stickslip {group}") and "Commands:" in err


def test_every_command_has_an_example_and_no_example_names_a_missing_command():
    assert sorted(EXAMPLES) == sorted(path for path, _ in LEAVES)


@pytest.mark.parametrize("path,command", LEAVES, ids=[p for p, _ in LEAVES])
def test_the_example_parses_as_written_and_is_in_the_help(path, command, capsys, monkeypatch):
    monkeypatch.chdir(ROOT)  # the examples name files of examples/ as a clone has them
    words = shlex.split(EXAMPLES[path])
    assert words[0] == "stickslip" and words[1:1 + len(path.split())] == path.split()
    # the options are parsed and checked by their declarations, as the command line would, without running it
    command.make_context(f"stickslip {path}", words[1 + len(path.split()):])
    assert run([*path.split(), "--help"]) == 0
    help_text = " ".join(capsys.readouterr().out.split())
    assert "Example:" in help_text and " ".join(EXAMPLES[path].split()) in help_text


@pytest.mark.parametrize("path,command", LEAVES, ids=[p for p, _ in LEAVES])
def test_every_option_is_listed_once_under_its_heading(path, command, capsys):
    assert run([*path.split(), "--help"]) == 0
    text = capsys.readouterr().out
    headings = [m.group(1) for m in re.finditer(r"^(\S[^:\n]*):$", text, flags=re.M) if m.group(1) != "Example"]
    assert headings == [h for h in [ARGUMENTS, MODEL, *PANELS] if h in headings]  # in the declared order
    sections = dict(zip(headings, re.split(r"^\S[^:\n]*:$", text, flags=re.M)[1:]))
    for param in command.params:
        if param.hidden:
            continue
        argument = param.param_type_name == "argument"
        ctx = command.make_context(path, [], resilient_parsing=True)
        flag = param.get_help_record(ctx)[0].split()[0] if argument else param.opts[0]
        where = [h for h, body in sections.items() if re.search(rf"^\s+{re.escape(flag)}(\s|$)", body, flags=re.M)]
        expected = ARGUMENTS if argument else next((h for h, names in PANELS.items() if param.name in names), MODEL)
        assert where == [expected], (flag, where)


def test_completion_scripts_and_answers():
    env = dict(os.environ, COMP_WORDS="stickslip oscillator simulate --ma", COMP_CWORD="3",
               _STICKSLIP_COMPLETE="complete_bash")
    done = subprocess.run([sys.executable, "-m", "stickslip"], env=env, capture_output=True, text=True, timeout=120)
    assert done.returncode == 0 and done.stdout.split() == ["--mass"], done.stdout + done.stderr
    # the script for a named shell (typer's switch for tests: the shell is not detected from the parent process,
    # which under CI is sh, a shell typer has no script for)
    script = subprocess.run([sys.executable, "-m", "stickslip", "--show-completion", "bash"], capture_output=True,
                            text=True, timeout=120,
                            env=dict(os.environ, _TYPER_COMPLETE_TEST_DISABLE_SHELL_DETECTION="1"))
    assert script.returncode == 0 and "_STICKSLIP_COMPLETE" in script.stdout


@pytest.mark.parametrize("suffix,magic", [(".png", b"\x89PNG"), (".svg", b"<svg"), (".pdf", b"%PDF")])
def test_plot_writes_the_format_its_suffix_names(suffix, magic, tmp_path):
    path = tmp_path / f"run{suffix.upper() if suffix == '.pdf' else suffix}"
    assert run(["oscillator", "simulate", *OSC, "--t-end", "5", "--plot", str(path)]) == 0
    assert magic in path.read_bytes()[:2000]


def test_plot_to_another_format_is_refused_before_any_work(tmp_path, capsys):
    path = tmp_path / "run.jpg"
    assert run(["oscillator", "simulate", *OSC, "--t-end", "5", "--plot", str(path)]) == 2
    err = capsys.readouterr().err.strip()
    assert err.count("\n") == 0 and "--plot" in err and "run.jpg" in err and ".png, .svg or .pdf" in err
    assert not path.exists()


def test_typer_app_and_the_command_tree_agree():
    """`command_tree` adds examples, not commands: the same names as typer's own command."""
    assert sorted(p for p, _ in _leaves(typer.main.get_command(app))) == sorted(p for p, _ in LEAVES)


def test_the_cli_reference_in_the_docs_is_current():
    """docs/cli/ is what `stickslip.cli.reference` writes from the commands (regenerate it with
    ``python -m stickslip.cli.reference docs/cli``): a new option or command shows in the docs."""
    from stickslip.cli.reference import pages

    folder = ROOT / "docs" / "cli"
    written = {p.name: p.read_text() for p in folder.glob("*.md")}
    assert written == pages(), "docs/cli is stale: python -m stickslip.cli.reference docs/cli"


def test_the_cli_reference_lists_every_option_and_example():
    from stickslip.cli.reference import pages

    text = "\n".join(pages().values())
    for path, command in LEAVES:
        assert f"`stickslip {path}`" in text and EXAMPLES[path] in text
        for param in command.params:
            if param.param_type_name == "option" and not param.hidden:
                assert f"`{param.opts[0]}" in text, (path, param.opts[0])
    # a cell holding "|" (a choice's metavar) does not split its row
    rows = [line for line in text.splitlines() if line.startswith("| `")]
    assert rows and all(len(re.findall(r"(?<!\\)\|", row)) == 3 for row in rows)


def test_options_that_choose_the_run_are_not_model_parameters_or_parallelism():
    """Issue 44: reproduce's --force was listed under Model, --quick and --only under Parallel runs and sweeps."""
    for name in ("force", "quick", "only"):
        assert [h for h, names in PANELS.items() if name in names] == ["Run and numerics"], name


@pytest.mark.parametrize("path,command", LEAVES, ids=[p for p, _ in LEAVES])
def test_help_points_to_what_an_installed_package_has_not_to_repository_paths(path, command, capsys):
    """Issue 44: `--help` pointed to docs/systems.md, which a wheel user does not have; a module it
    names for `python -m pydoc` is one the package holds."""
    import importlib

    assert run([*path.split(), "--help"]) == 0
    text = " ".join(capsys.readouterr().out.split())
    help_text = text.split(" Example: ")[0]  # the example runs in a clone (its examples/ files)
    assert not re.search(r"(?<![\w.])(docs|examples|tests|src)/", help_text) and "see the docs" not in text, text
    for module in re.findall(r"python -m pydoc ([\w.]+?)\.?(?:\)|\s|$)", text):
        assert importlib.import_module(module).__doc__, module
