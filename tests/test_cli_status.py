"""A long command without a terminal (a batch job, a pipe, a log file) says what it does at most
every `STATUS_SECONDS` (issue 47), and a short one says nothing on stderr."""

from __future__ import annotations

import re
import time

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
    assert all(re.match(r"^transits: [\d.]+ of 10 done, about \d+ s left$", line) for line in loop[:-1]), lines


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
