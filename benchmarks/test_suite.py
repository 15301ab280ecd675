"""The test suite's time per test set: `make test`'s set (not slow) and the slow set, each as
`make` runs it (two xdist workers), with the files that cost most and the ratio to the target.

Targets (issue 47), idle on the 2-core machine: `make test` at most 4 minutes; `.ci/run` (both
sets, the docs and the wheel) at most 30.

    .venv/bin/python benchmarks/test_suite.py [--set fast|slow|both]
"""

from __future__ import annotations

import argparse
import collections
import os
import re
import subprocess
import sys
import time
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
SETS = {"fast": ("not slow", 240.0), "slow": ("slow", None)}
LINE = re.compile(r"^([\d.]+)s (call|setup|teardown)\s+(\S+?)(::|\s|$)")


def run_set(name: str) -> tuple[float, str, collections.Counter]:
    marker, _ = SETS[name]
    env = {k: v for k, v in os.environ.items() if k != "PYTHONDONTWRITEBYTECODE"}  # as `make` runs it
    start = time.perf_counter()
    out = subprocess.run([sys.executable, "-m", "pytest", "-q", "-n", "2", "--dist", "worksteal", "-m", marker,
                          "-p", "no:cacheprovider", "--durations=0"], cwd=ROOT, env=env, capture_output=True, text=True)
    seconds = time.perf_counter() - start
    per_file = collections.Counter()
    for line in out.stdout.splitlines():
        m = LINE.match(line)
        if m:
            per_file[m.group(3)] += float(m.group(1))
    summary = next((line for line in reversed(out.stdout.splitlines()) if " in " in line and "passed" in line),
                   out.stdout.strip().splitlines()[-1] if out.stdout.strip() else "no output")
    return seconds, summary, per_file


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--set", choices=("fast", "slow", "both"), default="both")
    chosen = ("fast", "slow") if parser.parse_args().set == "both" else (parser.parse_args().set,)
    for name in chosen:
        seconds, summary, per_file = run_set(name)
        target = SETS[name][1]
        print(f"{name} set: {seconds:.0f} s wall ({summary})"
              + (f"; target {target:.0f} s: ratio {seconds / target:.2f}" if target else ""))
        total = sum(per_file.values())
        print(f"  test time summed over both workers: {total:.0f} s; the costliest files:")
        for path, s in per_file.most_common(12):
            print(f"    {s:7.1f} s  {path}")


if __name__ == "__main__":
    main()
