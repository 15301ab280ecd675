"""Every shell line of the README runs as written (issues 10 and 27): each `stickslip ...` line of
its ``sh`` blocks is given to ``sh`` exactly as it stands, with the ``stickslip`` of this
interpreter's environment first on the ``PATH``, in an empty folder, and must exit 0. A line may
not abbreviate options with ``...`` (a reader pastes it). Progress and logs may go to stderr,
warnings and errors may not. A line marked "hours" (the FE campaign) is checked for its options
only."""

import os
import re
import shlex
import subprocess
import sys
from pathlib import Path

import pytest

README = Path(__file__).resolve().parents[1] / "README.md"
#: Lines that take more than a few seconds run in the slow set.
SLOW = ("brake integrate", "brake fem", "brake map", "oscillator map", "reproduce --quick", "brake continue")
#: The folder of this interpreter's scripts, where the ``stickslip`` command is installed.
BIN = Path(sys.executable).parent


def _blocks(text: str) -> list[list[str]]:
    """The ``stickslip`` lines of each ``sh`` block that has any."""
    blocks = [[line.strip() for line in block.splitlines() if line.startswith("stickslip ")]
              for block in re.findall(r"```sh\n(.*?)```", text, flags=re.S)]
    return [block for block in blocks if block]


def _lines(text: str) -> list[str]:
    return [line for block in _blocks(text) for line in block]


def _shell_line(line: str) -> str:
    """What ``sh`` is given: the line itself, or for a line of hours its command with ``--help``."""
    if "hours" in line:  # hours of compute: its options must exist (--help parses them first)
        return shlex.join(shlex.split(line, comments=True) + ["--help"])
    return line


LINES = _lines(README.read_text())
#: A file a line writes (an output option's value).
_WRITES = re.compile(r"--(?:out|plot|xdmf|checkpoint|store|export)\s+(\S+)")


def written_twice(lines: list[str]) -> list[str]:
    """Files that two lines of one block write (the second refused: it exists), unless it says --overwrite."""
    seen, twice = set(), []
    for line in lines:
        for name in _WRITES.findall(line):
            if name in seen and "--overwrite" not in line:
                twice.append(name)
            seen.add(name)
    return twice


def test_the_readme_has_shell_lines():
    assert len(LINES) >= 18


def test_no_readme_shell_line_abbreviates():
    """``...`` in a line fails as written (``Missing option '--mass'``): every option is spelled out."""
    assert [line for line in LINES if "..." in line] == []


def test_the_guard_finds_an_abbreviated_line():
    text = "```sh\nstickslip --version\nstickslip oscillator simulate ... --t-end 50\n```\n"
    assert [line for line in _lines(text) if "..." in line] == ["stickslip oscillator simulate ... --t-end 50"]
    hours = "stickslip brake campaign --workers 2   # hours: x"
    assert _shell_line(hours) == "stickslip brake campaign --workers 2 --help"


def test_no_two_lines_of_a_block_write_one_file():
    """Issue 44: pasted whole into one folder, the block stopped at `brake integrate --out run.nc`
    (an earlier line had written run.nc)."""
    assert [written_twice(block) for block in _blocks(README.read_text())] == [[] for _ in _blocks(README.read_text())]


def test_the_guard_finds_a_file_written_twice():
    lines = ["stickslip a --out run.nc --plot a.png", "stickslip b --plot b.png --out run.nc", "stickslip c --out x.nc",
             "stickslip d --out x.nc --overwrite"]
    assert written_twice(lines) == ["run.nc"]


@pytest.mark.slow
def test_each_command_block_runs_pasted_whole_into_an_empty_folder(tmp_path):
    env = {**os.environ, "PATH": f"{BIN}{os.pathsep}{os.environ.get('PATH', '')}"}
    for i, block in enumerate(_blocks(README.read_text())):
        folder = tmp_path / str(i)
        folder.mkdir()
        done = subprocess.run(["sh", "-e", "-c", "\n".join(block)], cwd=folder, env=env, capture_output=True,
                              text=True, timeout=1800)
        assert done.returncode == 0, (i, done.stderr[-1000:])
        assert not any(word in done.stderr for word in ("Traceback", "Warning", "error")), done.stderr[-1000:]


def test_the_stickslip_command_is_installed_beside_this_interpreter():
    assert (BIN / "stickslip").exists(), f"no `stickslip` script in {BIN}: install the package (make test does)"


@pytest.mark.parametrize("line", [pytest.param(line, marks=pytest.mark.slow) if any(s in line for s in SLOW)
                                  or "hours" in line else line for line in LINES], ids=lambda line: line[:60])
def test_a_readme_shell_line_runs(line, tmp_path):
    assert "..." not in line, "spell the options out: the line must run when pasted"
    env = {**os.environ, "PATH": f"{BIN}{os.pathsep}{os.environ.get('PATH', '')}"}
    done = subprocess.run(["sh", "-c", _shell_line(line)], cwd=tmp_path, env=env, capture_output=True, text=True,
                          timeout=900)
    assert done.returncode == 0, done.stderr[-1000:]
    assert not any(word in done.stderr for word in ("Traceback", "Warning", "error")), done.stderr[-1000:]
