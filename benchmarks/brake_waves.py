"""Benchmark: travelling waves of the brake-like system (issue 3 budgets).

Budgets: one travelling wave found from scratch in <= 1 s; a 50-point continuation family
in <= 30 s. Also the ratio of one multiple-shooting residual with the closed-form zone
solutions to the same propagation done numerically (`solve_ivp`, DOP853, rtol 1e-11).

Run: ``.venv/bin/python benchmarks/brake_waves.py``. All numbers are measured in this run.
"""

from __future__ import annotations


import numpy as np

from stickslip.brake import BrakeParams
from stickslip.brake.waves.boundsco import residual
from stickslip.brake.waves.checks import integrate_wave
from stickslip.brake.waves.continuation import continue_waves
from stickslip.brake.waves.zones import Scaling
from stickslip.brake.waves.solve import travelling_wave
from timing import best_of

# the three regimes of the paper's section 3.1 (default steel ring), and the Fig. 12 wave
CASES = [("4-mode, f = 0.2, d = 0.4 mm, 1 rad/s", (1.0, 4e-4, 0.2), 4),
         ("8-mode, f = 0.7, d = 0.1 mm, 50 rad/s", (50.0, 1e-4, 0.7), 8),
         ("2-mode, f = 2, d = 0.4 mm, 80 rad/s", (80.0, 4e-4, 2.0), 2),
         ("Fig. 12, f = 0.2, d = 10 um, 100 rad/s", (100.0, 1e-5, 0.2), 8)]



def main():
    print("one travelling wave from scratch (scan of c, return map, multiple shooting, checks):")
    worst = 0.0
    for label, phys, n in CASES:
        p = BrakeParams.from_physical(*phys)
        t, w = best_of(lambda: travelling_wave(p, n))
        worst = max(worst, t)
        print(f"  {label:40s} {t * 1e3:7.1f} ms  {w.structure:45s} c = {w.c:.6g}")
    print(f"  worst {worst:.3f} s  (budget 1 s: {'OK' if worst <= 1.0 else 'OVER'})")

    p0 = BrakeParams.from_physical(50.0, 1e-5, 0.7)
    t, br = best_of(lambda: continue_waves(p0, 4, "delta", 2.5e-6, num=50, spacing="log"), repeat=1)
    print(f"\n50-point continuation in d (f = 0.7, n = 4, 50 rad/s, d from 10 um to 0.25 um): {t:.2f} s "
          f"(budget 30 s: {'OK' if t <= 30 else 'OVER'}), {len(br.events)} zone events, "
          f"{len(set(w.structure for w in br.waves))} zone sequences")
    p1 = BrakeParams.from_physical(40.0, 1e-6, 0.7)
    t, br = best_of(lambda: continue_waves(p1, 4, "omega", 100.0, num=50), repeat=1)
    print(f"50-point continuation in Omega (40 -> 100 rad/s, d = 1 um): {t:.2f} s, {len(br.events)} zone events")

    w = travelling_wave(BrakeParams.from_physical(100.0, 1e-5, 0.2), 8)
    sc = Scaling(w.params)
    args = (w.layout, sc.coefficients, w.params.friction, sc.delta, w.period)
    t_closed, _ = best_of(lambda: [residual(w.x, *args) for _ in range(200)])
    t_ivp, _ = best_of(lambda: [integrate_wave(w, num=2) for _ in range(5)])
    t_closed, t_ivp = t_closed / 200, t_ivp / 5
    print(f"\none period of {w.structure}: closed forms {t_closed * 1e6:.0f} us, solve_ivp {t_ivp * 1e3:.1f} ms "
          f"-> ratio {t_ivp / t_closed:.0f}x")
    np.testing.assert_array_less(0, t_closed)


if __name__ == "__main__":
    main()
