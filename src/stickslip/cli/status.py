"""Status lines of a long command without a terminal (a pipe, a log file, a batch job).

A command run by `stickslip.cli.run` with stderr not a terminal keeps a `Heartbeat`: at most
every `STATUS_SECONDS` it writes one line on stderr saying what the command is doing and for
how long, or, while a loop reports its progress (`progress`), how far it is and the time left::

    fem run: steady sliding, 2 min so far
    general body: 6.1 of 20 done, 2 min so far, about 3 min left
    branch points: 12 of 10000 done, 60 s so far, about 15.1 h left

A command that ends within `STATUS_SECONDS` writes none. On a terminal the commands show rich's
progress bars instead (`stickslip.cli.common.progress_bar`), and no heartbeat runs.
"""

from __future__ import annotations

import contextlib
import sys
import threading
import time

__all__ = ["STATUS_SECONDS", "Heartbeat", "heartbeat", "phase", "progress", "duration"]

#: The least time between two status lines [s].
STATUS_SECONDS = 60.0

_ACTIVE: list["Heartbeat"] = []


def duration(seconds: float) -> str:
    """``seconds`` for people: 45 s, 12 min, 3.2 h."""
    return f"{seconds:.0f} s" if seconds < 120 else (f"{seconds / 60:.0f} min" if seconds < 7200 else
                                                     f"{seconds / 3600:.1f} h")


class Heartbeat:
    """The status of one command: its phase, the progress of its current loop, and a thread that
    writes a line when `STATUS_SECONDS` have passed since the last one."""

    def __init__(self, command: str):
        self.command = command
        self._phase, self._since = "running", time.monotonic()
        self._loop = None  # (label, first time, first done, done, total) of the loop reporting progress
        self._last = time.monotonic()  # when the last line was written (or the command started)
        self._lock = threading.Lock()
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._beat, name="stickslip-status", daemon=True)

    def start(self) -> "Heartbeat":
        self._thread.start()
        return self

    def stop(self) -> None:
        self._stop.set()
        self._thread.join(timeout=1.0)

    def phase(self, text: str) -> None:
        with self._lock:
            self._phase, self._since, self._loop = text, time.monotonic(), None

    def progress(self, label: str, done: float, total: float) -> None:
        """A loop's ``done`` of ``total``; its last call (``done == total``) writes a closing line if
        the loop wrote any."""
        now = time.monotonic()
        with self._lock:
            if self._loop is None or self._loop[0] != label or done < self._loop[3]:
                self._loop = (label, now, done, done, total, False)
            label, t0, d0, _, _, wrote = self._loop
            self._loop = (label, t0, d0, done, total, wrote)
            finished = done >= total * (1 - 1e-9)
        if finished and wrote:
            self._write(f"{label}: {min(done, total):.6g} of {total:.6g} done")
            with self._lock:
                self._loop = None

    def line(self) -> str:
        """What a status line written now would say."""
        now = time.monotonic()
        with self._lock:
            if self._loop is not None:
                label, t0, d0, done, total, _ = self._loop
                rate = (done - d0) / (now - t0) if done > d0 and now > t0 else None
                left = f", about {duration((total - done) / rate)} left" if rate else ""
                return f"{label}: {min(done, total):.6g} of {total:.6g} done, {duration(now - t0)} so far{left}"
            return f"{self.command}: {self._phase}, {duration(now - self._since)} so far"

    def _write(self, text: str) -> None:
        print(text, file=sys.stderr, flush=True)
        self._last = time.monotonic()

    def _beat(self) -> None:
        while not self._stop.wait(timeout=max(0.01, self._last + STATUS_SECONDS - time.monotonic())):
            if time.monotonic() - self._last >= STATUS_SECONDS:
                self._write(self.line())
                with self._lock:  # the loop has written: it closes with a line when it ends
                    if self._loop is not None:
                        self._loop = (*self._loop[:5], True)


def _a_file(stream) -> bool:
    try:
        stream.fileno()
    except (AttributeError, OSError, ValueError):  # io.UnsupportedOperation is an OSError and a ValueError
        return False
    return True


@contextlib.contextmanager
def heartbeat(command: str, terminal: bool):
    """A `Heartbeat` for the block when stderr is a file but not a terminal (``terminal`` False):
    a pipe, a log file, a batch job's output. None inside another command's heartbeat (a sweep's
    points) or when stderr is not a file (a point's captured output)."""
    if terminal or _ACTIVE or not _a_file(sys.stderr):
        yield None
        return
    beat = Heartbeat(command).start()
    _ACTIVE.append(beat)
    try:
        yield beat
    finally:
        _ACTIVE.remove(beat)
        beat.stop()


def phase(text: str) -> None:
    """Say what the running command does now (no effect without a heartbeat)."""
    if _ACTIVE:
        _ACTIVE[-1].phase(text)


def progress(label: str):
    """A library's ``progress(done, total)`` callback feeding the heartbeat (None without one)."""
    if not _ACTIVE:
        return None
    beat = _ACTIVE[-1]
    return lambda done, total: beat.progress(label, done, total)
