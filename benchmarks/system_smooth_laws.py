"""Systems whose laws are not affine in the slip speed, compiled against Radau in Python
(`stickslip.system.rate_state_simulate`, ``method="compiled"`` and ``"radau"``): the example
``examples/stribeck/two_blocks.toml`` (a Stribeck block stick-slipping beside a Coulomb one).

Prints, measured in this run: the time of a 3 s run (36 switches) by each at rtol 1e-10 and their
ratio, each one's error in its last switch time against a run of the other at rtol 1e-12 (the two
integrators are independent of each other but for the switching rules), and the compiled one at
rtol 1e-12 against Radau at 1e-10 (equal accuracy or better); then the limit cycle
(`rate_state_cycle`, transient 3 s) by each: time, ratio, and the two periods and leading multipliers.

``python benchmarks/system_smooth_laws.py``
"""

import time
from pathlib import Path

import numpy as np

from stickslip.system import load_system, rate_state_cycle, rate_state_simulate

FILE = Path(__file__).resolve().parents[1] / "examples" / "stribeck" / "two_blocks.toml"
X0 = [0.0017, 0.0]


def timed(f, *args, **kw):
    t0 = time.perf_counter()
    out = f(*args, **kw)
    return out, time.perf_counter() - t0


def main():
    system = load_system(FILE)
    rate_state_simulate(system, X0, t_end=0.1, method="compiled")  # compile (cached on disk after the first)
    fine = {m: rate_state_simulate(system, X0, t_end=3.0, samples=2, rtol=1e-12, method=m).event_time[-1]
            for m in ("compiled", "radau")}
    runs = {}
    for m in ("compiled", "radau"):
        runs[m] = timed(rate_state_simulate, system, X0, t_end=3.0, samples=301, rtol=1e-10, method=m)
    other = {"compiled": "radau", "radau": "compiled"}
    for m, (run, dt) in runs.items():
        err = abs(run.event_time[-1] - fine[other[m]])
        print(f"3 s run, {m:8s}: {dt:8.3f} s, {run.event_time.size} switches, last switch time off by {err:.1e} s "
              f"(against {other[m]} at rtol 1e-12)")
    print(f"ratio Radau / compiled (3 s run): {runs['radau'][1] / runs['compiled'][1]:.0f}x")
    tight, dt = timed(rate_state_simulate, system, X0, t_end=3.0, samples=301, rtol=1e-12, method="compiled")
    err = abs(tight.event_time[-1] - fine["radau"])
    print(f"3 s run, compiled at rtol 1e-12: {dt:8.3f} s, last switch time off by {err:.1e} s; Radau at rtol 1e-10 / "
          f"this: {runs['radau'][1] / dt:.0f}x at equal or better accuracy")
    cycles = {m: timed(rate_state_cycle, system, X0, transient=3.0, method=m) for m in ("compiled", "radau")}
    for m, (c, dt) in cycles.items():
        print(f"cycle, {m:8s}: {dt:8.3f} s, period {c.period:.10f} s, |multipliers| "
              f"{np.array2string(np.abs(c.multipliers[:3]), precision=6)}")
    print(f"ratio Radau / compiled (cycle): {cycles['radau'][1] / cycles['compiled'][1]:.0f}x; periods differ by "
          f"{abs(cycles['radau'][0].period - cycles['compiled'][0].period):.1e} s")


if __name__ == "__main__":
    main()
