"""Start-up of the command line: the README's first command in a fresh process against a bare
``python -c "import numpy"``, and what the command spends beyond its computation.

Each round starts both processes one after the other (pairs keep the ratio meaningful when the
machine's speed drifts); the computation itself (`limit_cycle` and its table, in this process,
warm) is subtracted from the command's time to give its start-up. Target (issue 47): the
command's start-up at most 1 s on an idle machine.

    .venv/bin/python benchmarks/startup.py [--rounds 7]
"""

from __future__ import annotations

import argparse
import statistics
import subprocess
import sys
import time

FIRST = ["oscillator", "cycle", "--mass", "1", "--stiffness", "1", "--normal-force", "1", "--belt-speed", "0.2",
         "--fs", "0.6", "--fd", "0.4"]


def wall(args: list[str]) -> float:
    start = time.perf_counter()
    subprocess.run(args, check=True, stdout=subprocess.DEVNULL)
    return time.perf_counter() - start


def computation(repeat: int = 20) -> float:
    """The command's own work, warm, in this process: the cycle and its JSON."""
    import io
    from contextlib import redirect_stdout

    from stickslip.cli import run

    with redirect_stdout(io.StringIO()):
        run(FIRST + ["--json"])
        start = time.perf_counter()
        for _ in range(repeat):
            run(FIRST + ["--json"])
    return (time.perf_counter() - start) / repeat


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--rounds", type=int, default=7)
    rounds = parser.parse_args().rounds
    command = [sys.executable, "-m", "stickslip", *FIRST]
    numpy = [sys.executable, "-c", "import numpy"]
    wall(command)  # numba's caches and the OS's file cache warm, as on a second call
    pairs = [(wall(command), wall(numpy)) for _ in range(rounds)]
    cmd, base = statistics.median(p[0] for p in pairs), statistics.median(p[1] for p in pairs)
    ratio = statistics.median(a / b for a, b in pairs)
    work = computation()
    print(f"`stickslip {' '.join(FIRST)}`: median {cmd:.3f} s over {rounds} fresh processes")
    print(f"`python -c 'import numpy'`: median {base:.3f} s")
    print(f"ratio (pairwise median): {ratio:.1f}")
    print(f"the computation itself (warm, in-process, table as JSON): {work * 1e3:.1f} ms")
    print(f"start-up beyond the computation: {cmd - work:.3f} s (target <= 1 s, idle machine)")


if __name__ == "__main__":
    main()
