"""A long command without a terminal (a batch job, a pipe, a log file) says what it does at most
every `STATUS_SECONDS` (issue 47), and a short one says nothing on stderr."""

from __future__ import annotations

import re
import time
import types

import pytest

from stickslip.cli import run, status

OSC = ["oscillator", "cycle", "--mass", "1", "--stiffness", "1", "--normal-force", "1", "--belt-speed", "0.2",
       "--fs", "0.6", "--fd", "0.4", "--json"]
PHASE = re.compile(r"^stickslip oscillator cycle: running, \d+ s so far$")


def test_a_long_command_without_a_terminal_says_what_it_does_at_most_every_period(capfd, monkeypatch):
    """capfd leaves stderr a file that is not a terminal, as a batch job's log is."""
    import stickslip.oscillator

    real = stickslip.oscillator.limit_cycle

    def slow(*args, **kwargs):
        time.sleep(1.0)
        return real(*args, **kwargs)

    monkeypatch.setattr(status, "STATUS_SECONDS", 0.2)
    monkeypatch.setattr(stickslip.oscillator, "limit_cycle", slow)
    start = time.monotonic()
    assert run(OSC) == 0
    elapsed = time.monotonic() - start
    out, err = capfd.readouterr()
    lines = err.splitlines()
    assert '"period"' in out and lines and all(PHASE.match(line) for line in lines), err
    assert len(lines) <= elapsed / 0.2 + 1, (len(lines), elapsed)  # at most one a period


def test_a_short_command_writes_nothing_on_stderr(capfd):
    assert run(OSC) == 0
    assert capfd.readouterr().err == ""


def test_a_loop_says_how_far_it_is_and_the_time_left_then_that_it_is_done(capfd, monkeypatch):
    monkeypatch.setattr(status, "STATUS_SECONDS", 0.05)
    with status.heartbeat("stickslip fem run", terminal=False) as beat:
        assert beat is not None
        status.phase("integrating")
        tick = status.progress("transits")
        for i in range(21):
            tick(0.5 * i, 10.0)
            time.sleep(0.01)
    lines = capfd.readouterr().err.splitlines()
    loop = [line for line in lines if line.startswith("transits:")]
    assert loop and loop[-1] == "transits: 10 of 10 done", lines
    assert all(re.match(r"^transits: [\d.]+ of 10 done, \d+ s so far, about \d+ s left$", line) for line in loop[:-1]), lines


def test_no_heartbeat_on_a_terminal_inside_another_or_into_a_captured_stream(capsys):
    with status.heartbeat("stickslip x", terminal=True) as beat:
        assert beat is None
    with status.heartbeat("stickslip x", terminal=False) as beat:  # capsys: stderr is no file (a sweep's point)
        assert beat is None


def test_a_sweeps_points_run_inside_its_heartbeat(capfd):
    with status.heartbeat("stickslip sweep", terminal=False) as outer:
        with status.heartbeat("stickslip oscillator cycle", terminal=False) as inner:
            assert outer is not None and inner is None
            status.phase("a point")
        assert outer.line().startswith("stickslip sweep: a point, ")


@pytest.mark.parametrize("seconds, text", [(45, "45 s"), (600, "10 min"), (3 * 3600, "3.0 h")])
def test_durations_read_as_people_say_them(seconds, text):
    assert status.duration(seconds) == text


def test_a_loops_line_says_the_time_so_far_and_left_from_the_points_done(monkeypatch):
    """A fake clock: 11 points in the 60 s after the first leave 9988 of 10000 at 11/60 points a
    second, 54480 s = 15.1 h (the first point alone gives no rate: no time left yet)."""
    clock = [0.0]
    monkeypatch.setattr(status, "time", types.SimpleNamespace(monotonic=lambda: clock[0]))
    beat = status.Heartbeat("stickslip system continue")
    beat.progress("branch points", 1, 10000)
    assert beat.line() == "branch points: 1 of 10000 done, 0 s so far"
    clock[0] = 60.0
    beat.progress("branch points", 12, 10000)
    assert beat.line() == "branch points: 12 of 10000 done, 60 s so far, about 15.1 h left"


@pytest.mark.slow  # 1.6 s: three cycles of the two blocks
def test_system_continue_reports_each_point_of_the_branch_to_the_status_line(capfd, monkeypatch):
    """`system continue --points 10000` said "60 s so far" and never how long it would take: its
    loop now reports each value done, from which the heartbeat's line says the time left."""
    from stickslip.cli import common

    from .fuzz_harness import SYSTEM_FILE

    calls = []
    monkeypatch.setattr(common.status, "progress", lambda label: lambda done, total: calls.append((label, done, total)))
    assert run(["system", "continue", SYSTEM_FILE, "--parameter", "contact[0].surface_speed", "--stop", "0.25",
                "--points", "3", "--json"]) == 0
    assert calls == [("branch points", k, 3) for k in (1, 2, 3)], calls
