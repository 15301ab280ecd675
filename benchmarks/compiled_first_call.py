"""The first and second call of the compiled paths, in a first process and in a second one.

numba compiles a kernel at its first call and keeps it on disk (``cache=True``): only the first
process after an install or a change of the kernel pays the compilation, every later process
loads it. Each path below runs in a first process on an empty numba cache (``NUMBA_CACHE_DIR``:
a new folder, as after an install), then in a second process on the cache the first one wrote;
each process times its first call and a second call of the same work.

    .venv/bin/python benchmarks/compiled_first_call.py
"""

from __future__ import annotations

import json
import os
import subprocess
import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]

#: name -> code run twice in a process (``work()``), after its imports (``setup``).
PATHS = {
    "system limit cycle (two blocks, Coulomb; the event search)": (
        f"from stickslip.system import load_system, limit_cycle\n"
        f"system = load_system({str(ROOT / 'examples/two_blocks/two_blocks.toml')!r})\n",
        "limit_cycle(system, transient=60.0)"),
    "oscillator limit cycle (Stribeck law: DOP853 compiled with the law)": (
        "from stickslip.friction import Stribeck\n"
        "from stickslip.oscillator import Oscillator, limit_cycle\n"
        "osc = Oscillator(1.0, 1.0, 1.0, 0.2, Stribeck(0.6, 0.4, 0.1), 0.05)\n",
        "limit_cycle(osc)"),
    "system run under smooth laws (Stribeck pair: DOP853 compiled with the laws)": (
        f"from stickslip.system import load_system, rate_state_simulate\n"
        f"system = load_system({str(ROOT / 'examples/stribeck/two_blocks.toml')!r})\n",
        "rate_state_simulate(system, t_end=3.0, method='compiled')"),
    "FE annulus, 2 transits (the explicit contact kernel)": (
        "from stickslip.brake import BrakeParams\n"
        "from stickslip.brake.fem import integrate_fem\n"
        "params = BrakeParams.from_physical(50.0, 1e-4, 0.7)\n",
        "integrate_fem(params, 64, 4, transits=2.0)"),
}

CHILD = """
import json, sys, time
{setup}
def work():
    {work}
times = []
for _ in range(2):
    start = time.perf_counter()
    work()
    times.append(time.perf_counter() - start)
print(json.dumps(times))
"""


def in_a_process(setup: str, work: str, cache: str) -> list[float]:
    env = {**os.environ, "NUMBA_CACHE_DIR": cache}
    out = subprocess.run([sys.executable, "-c", CHILD.format(setup=setup, work=work)], env=env, check=True,
                         capture_output=True, text=True)
    return json.loads(out.stdout.strip().splitlines()[-1])


def main() -> None:
    for name, (setup, work) in PATHS.items():
        with tempfile.TemporaryDirectory(prefix="numba-cache-") as cache:
            first = in_a_process(setup, work, cache)
            second = in_a_process(setup, work, cache)
        print(f"{name}:\n  first process (empty cache): first call {first[0]:.2f} s, second call {first[1]:.3f} s\n"
              f"  second process (cache on disk): first call {second[0]:.2f} s, second call {second[1]:.3f} s\n"
              f"  compiling / loading from the cache: {first[0] / second[0]:.0f}x")


if __name__ == "__main__":
    main()
