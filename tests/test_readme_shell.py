"""Every shell line of the README runs (issue 10): each `stickslip ...` line of its ``sh``
blocks is run as written, in a fresh interpreter in an empty folder, and must exit 0. ``...`` stands for the oscillator options of the first oscillator line.
Progress and logs may go to stderr, warnings and errors may not. A line marked "hours" (the
FE campaign) is checked for its options only."""

import re
import shlex
import subprocess
import sys
from pathlib import Path

import pytest

README = Path(__file__).resolve().parents[1] / "README.md"
#: Lines that take more than a few seconds run in the slow set.
SLOW = ("brake integrate", "brake fem", "brake map", "oscillator map", "reproduce --quick", "brake continue")


def _lines() -> list[str]:
    text = README.read_text()
    blocks = re.findall(r"```sh\n(.*?)```", text, flags=re.S)
    return [line.strip() for block in blocks for line in block.splitlines() if line.startswith("stickslip ")]


def _expand(line: str, lines: list[str]) -> list[str]:
    command = line.split("  #")[0].strip()
    if "..." in command:
        first = next(x for x in lines if x.startswith("stickslip oscillator ") and "..." not in x)
        options = [t for t in shlex.split(first)[3:] if t != "--json"]
        command = command.replace("...", shlex.join(options))
    return shlex.split(command)[1:]


LINES = _lines()


def test_the_readme_has_shell_lines():
    assert len(LINES) >= 18 and any("..." in line for line in LINES)


@pytest.mark.parametrize("line", [pytest.param(line, marks=pytest.mark.slow) if any(s in line for s in SLOW)
                                  or "hours" in line else line for line in LINES], ids=lambda line: line[:60])
def test_a_readme_shell_line_runs(line, tmp_path):
    args = _expand(line, LINES)
    if "hours" in line:
        args = args + ["--help"]  # hours of compute: its options must exist (--help parses them first)
    done = subprocess.run([sys.executable, "-m", "stickslip", *args], cwd=tmp_path, capture_output=True, text=True,
                          timeout=900)
    assert done.returncode == 0, done.stderr[-1000:]
    assert not any(word in done.stderr for word in ("Traceback", "Warning", "error")), done.stderr[-1000:]
