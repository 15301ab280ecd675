"""The stability of a travelling wave on the discrete ring (`stickslip.brake.waves.wave_spectrum`):
the time to find the ring's wave and the multipliers of its node-shift map at N = 64 ... 512,
how it grows with N (the exponent of N between successive sizes), and, for scale, the time of
one wave period of the same ring by the event-driven run the node-shift map replaces (N/n
shifts: what the symmetry saves). Figure 5's wave at Omega = 100 rad/s.

``python benchmarks/wave_spectrum.py [NMAX]`` (default 512).
"""

import math
import sys
import time

import numpy as np

from stickslip.brake import BrakeParams, travelling_wave
from stickslip.brake.waves import Scaling, ring_system, wave_spectrum
from stickslip.system import monodromy, simulate


def main():
    top = int(sys.argv[1]) if len(sys.argv) > 1 else 512
    params = BrakeParams.from_physical(100.0, 1e-4, 0.2)
    wave = travelling_wave(params, 4)
    sizes = [k for k in (64, 128, 256, 512, 1024) if k <= top]
    times = []
    for k in sizes:
        t0 = time.perf_counter()
        sp = wave_spectrum(wave, k)
        times.append(time.perf_counter() - t0)
        grow = "" if len(times) < 2 else f", time ~ N^{math.log2(times[-1] / times[-2]):.2f}"
        print(f"N = {k:4d}: {times[-1]:7.2f} s{grow}; leading |mu| = {abs(sp.leading):.7f}, ln growth per period "
              f"{sp.growth_per_period:.5f}, {sp.events_per_shift} events per node shift", flush=True)
    k = sizes[min(1, len(sizes) - 1)]
    sp = wave_spectrum(wave, k)
    system, r, c = ring_system(params, k), Scaling(params).root_gamma, float(wave.x[0])
    theta = 2 * math.pi * (np.arange(k) + 0.5) / k
    prof = wave.evaluate(theta)
    t0 = time.perf_counter()
    run = simulate(system, prof["V"] / r, -c * prof["dV"] / r, (k // wave.n) * sp.shift_time, samples=2, segments=True)
    monodromy(system, run)
    whole = time.perf_counter() - t0
    print(f"one wave period of the {k}-node ring with its monodromy (no Newton, no symmetry): {whole:.2f} s, "
          f"{whole / times[min(1, len(times) - 1)]:.1f}x the node-shift computation with its Newton iterations")


if __name__ == "__main__":
    main()
