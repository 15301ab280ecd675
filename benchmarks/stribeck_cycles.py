"""The Stribeck oscillator's cycles and their continuation: DOP853 compiled with the law vs in Python.

Ours: `stickslip.oscillator` with a Stribeck law, the default path (`method="numeric"`: DOP853
compiled with numba together with the law, `stickslip.oscillator.slipkernel`). Baseline: the same
model through scipy's DOP853 in Python (`method="python"`, the path every law that is not affine
took before), at the same tolerance (rtol 1e-12). Both run in this process, after one warm-up
call each (the compilation, timed and printed apart):

1. ``CYCLES`` stick-slip cycles from rest: times, and the mean period of each against a reference
   from `solve_ivp` with events at rtol 1e-13 (`stickslip.oscillator.baseline`, written apart);
2. the limit cycle continued in the belt speed from 0.2 to 0.5 m/s (`continue_cycle`, with its
   Floquet multipliers), five times each way: times, and the largest differences of the branches'
   periods and largest velocities.

Prints the ratios (target, issue 26: >= 50x faster at the same accuracy).
``python benchmarks/stribeck_cycles.py [CYCLES]``.
"""

import sys
import time

import numpy as np

from stickslip.friction import Stribeck
from stickslip.oscillator import Mode, Oscillator, continue_cycle, simulate
from stickslip.oscillator.baseline import solve_ivp_switches

REPEAT = 5  # continuations timed, each way
OSC = Oscillator(mass=1.0, stiffness=1.0, normal_force=1.0, belt_speed=0.2, friction=Stribeck(0.6, 0.4, 0.1),
                 damping=0.05)


def stick_entries_ours(t_end, method):
    traj = simulate(OSC, t_end, x0=0.0, v0=0.0, method=method)
    return np.array([e[0] for e in traj.events if int(e[4]) == int(Mode.STICK)])


def stick_entries_reference(t_end):
    return np.array([t for t, *_, mode in solve_ivp_switches(OSC, 0.0, 0.0, t_end, rtol=1e-13) if mode == 0])


def period(entries, skip=3):
    e = entries[skip:]
    return (e[-1] - e[0]) / (e.size - 1)


def timed(fn, *args, **kwargs):
    t0 = time.perf_counter()
    out = fn(*args, **kwargs)
    return time.perf_counter() - t0, out


def main():
    cycles = int(sys.argv[1]) if len(sys.argv) > 1 else 300
    t_end = 7.1 * cycles  # about one period each
    first, _ = timed(stick_entries_ours, 20.0, "numeric")
    timed(stick_entries_ours, 20.0, "python")
    t_ours, ours = timed(stick_entries_ours, t_end, "numeric")
    t_py, py = timed(stick_entries_ours, t_end, "python")
    ref = stick_entries_reference(t_end)
    p_ref = period(ref)
    print(f"first call of the compiled path (numba compiling, or loading its cache): {first:.2f} s")
    print(f"{ours.size} cycles: compiled {t_ours:.3f} s ({t_ours / ours.size * 1e6:.0f} us a cycle), "
          f"python {t_py:.2f} s ({t_py / py.size * 1e3:.2f} ms a cycle): {t_py / t_ours:.1f}x")
    print(f"period {p_ref:.13f} s (solve_ivp, rtol 1e-13, {ref.size} cycles); error: compiled "
          f"{abs(period(ours) - p_ref):.1e} s, python {abs(period(py) - p_ref):.1e} s")
    kw = dict(parameter="belt_speed", step=0.05, max_step=0.1)
    timed(continue_cycle, OSC, 0.25, method="numeric", **kw)
    t_c, branch = timed(lambda: [continue_cycle(OSC, 0.5, method="numeric", **kw) for _ in range(REPEAT)][-1])
    t_cp, branch_p = timed(lambda: [continue_cycle(OSC, 0.5, method="python", **kw) for _ in range(REPEAT)][-1])
    pc = np.array([c.period for c in branch.cycles])
    pp = np.array([c.period for c in branch_p.cycles])
    same = pc.size == pp.size and np.allclose(branch.values, branch_p.values, rtol=1e-6)
    diff = f"{np.max(np.abs(pc - pp)):.1e} s" if same else "branches differ in their points"
    vc, vp = np.array([c.v_max for c in branch.cycles]), np.array([c.v_max for c in branch_p.cycles])
    vmax = np.max(np.abs(vc - vp)) if same else 0.0
    print(f"continuation in the belt speed, 0.2 to 0.5 m/s ({pc.size} cycles, end: {branch.end_reason}), {REPEAT} "
          f"times: compiled {t_c:.3f} s, python {t_cp:.2f} s: {t_cp / t_c:.1f}x; largest difference of the periods "
          f"{diff}, of v_max {vmax:.1e} m/s")


if __name__ == "__main__":
    main()
