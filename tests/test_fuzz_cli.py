"""Fuzzing harness over the command line (issue 9): every numeric option of every command,
one bad value at a time, on an otherwise valid and cheap invocation.

The contract checked: the command exits 2 and prints nothing on stdout and exactly one
line on stderr naming the option as the user types it (``--t-end``, not ``t_end``); never
a traceback, an internal error (exit 3), a result, or a hang (each trial has a time limit).
Values that are never valid for a number: NaN, infinities, text, the empty string. (The
wider battery of extreme but finite values, where a result must be finite or refused, is
not here yet.)
"""

from __future__ import annotations

import contextlib
import signal
import typing

import pytest
import typer.main

from stickslip.cli import app, run

OSC = ["--mass", "1", "--stiffness", "1", "--normal-force", "1", "--belt-speed", "0.2", "--fs", "0.6", "--fd", "0.4"]
BRAKE = ["--omega", "50", "--mismatch", "1e-4", "--friction", "0.7"]
#: A valid, fast invocation of every command ({tmp} is a fresh folder).
BASE = {
    "oscillator cycle": OSC,
    "oscillator simulate": OSC + ["--t-end", "5"],
    "oscillator stability": OSC,
    "oscillator continue": OSC + ["--stop", "0.3"],
    "oscillator map": OSC + ["--x", "belt_speed=0.2:0.3:2", "--y", "damping=0.01:0.02:2", "--out", "{tmp}/m.zarr",
                             "--workers", "1"],
    "brake coefficients": ["--xi", "1.5", "--nu", "0.3", "--gamma", "1e-6"],
    "brake steady": ["--xi", "1.5", "--nu", "0.3", "--delta", "0.004", "--friction", "0.2"],
    "brake stability": ["--xi", "1.5", "--nu", "0.3", "--gamma", "1e-6", "--delta", "0.004", "--friction", "0.2",
                        "--modes", "1-3"],
    "brake integrate": BRAKE + ["--nodes", "32", "--transits", "1"],
    "brake wave": BRAKE + ["--modes", "8"],
    "brake continue": ["--omega", "50", "--mismatch", "1e-5", "--friction", "0.7", "--modes", "4", "--stop", "9e-6",
                       "--points", "3"],
    "brake map": ["--out", "{tmp}/w.zarr", "--frictions", "0.2:0.7:2", "--mismatches", "1e-5:1e-4:2", "--workers", "1"],
    "brake fem": BRAKE + ["--n-theta", "16", "--n-r", "1", "--transits", "1"],
    "brake campaign": ["--out", "{tmp}/c", "--seeds", "1"],
    "halfspace inverse": ["--b", "2", "--c", "-0.7", "--v-star", "0.001"],
    "halfspace direct": ["--T", "9.52e-4", "--v", "3.514e-3", "--v-star", "0.001"],
    "halfspace fields": ["--b", "11.358", "--c", "-0.7", "--v-star", "0.001", "--points", "101"],
    "reproduce": ["--only", "fig2", "--out", "{tmp}/r"],
}
NEVER_NUMBERS = ["nan", "inf", "-inf", "abc", ""]


def _numeric_options():
    """``(command, option)`` for every option typed float or int."""
    out = []

    def walk(cmd, path):
        if hasattr(cmd, "commands"):
            for name, sub in cmd.commands.items():
                walk(sub, path + [name])
            return
        hints = typing.get_type_hints(cmd.callback, include_extras=True)
        for param in cmd.params:
            hint = hints.get(param.name)
            base = typing.get_args(hint)[0] if typing.get_origin(hint) is typing.Annotated else hint
            args = [a for a in typing.get_args(base) if a is not type(None)] or [base]
            if args[0] in (float, int):
                out.append((" ".join(path), param.opts[0]))

    walk(typer.main.get_command(app), [])
    return out


OPTIONS = _numeric_options()


def test_every_command_has_a_base_invocation():
    assert {c for c, _ in OPTIONS} <= set(BASE) and len(OPTIONS) > 60


class Hang(Exception):
    pass


@contextlib.contextmanager
def time_limit(seconds):
    def alarm(signum, frame):
        raise Hang(f"no answer after {seconds} s")
    old = signal.signal(signal.SIGALRM, alarm)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)


def _args(command, option, value, tmp):
    base = [a.replace("{tmp}", str(tmp)) for a in BASE[command]]
    if option in base:
        i = base.index(option)
        base = base[:i] + base[i + 2:]
    return command.split() + base + [option, value]


@pytest.mark.parametrize("command, option", OPTIONS, ids=[f"{c} {o}" for c, o in OPTIONS])
def test_a_value_that_is_no_number_is_refused_in_one_line_naming_the_option(command, option, tmp_path, capsys):
    for value in NEVER_NUMBERS:
        with time_limit(120):  # a hang guard, not a timing check: each trial is refused in milliseconds
            code = run(_args(command, option, value, tmp_path))
        out, err = capsys.readouterr()
        assert code == 2 and out == "", (value, code, out, err)
        assert err.count("\n") == 1 and option in err and "Traceback" not in err, (value, err)

