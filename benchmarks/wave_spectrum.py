"""The stability of a travelling wave on the discrete ring (`stickslip.brake.waves.wave_spectrum`):
the time to find the ring's wave and the multipliers of its node-shift map at N = 64 ... 512,
how it grows with N (the exponent of N between successive sizes), and, for scale, the time of
one wave period of the same ring by the event-driven run the node-shift map replaces (N/n
shifts: what the symmetry saves). Figure 5's wave at Omega = 100 rad/s.

``python benchmarks/wave_spectrum.py [NMAX] [--separating]`` (default 512). With ``--separating``
the wave is the one of Figure 11's branch at d = 1.2 um that leaves the shaft (the ring whose nodes
may leave it too: 2N degrees of freedom, a rigid unilateral contact per node), the row the report's
figure stops at 256 nodes for (at 512 it takes about 20 minutes and 2.5 GB).
"""

import math
import resource
import sys
import time

import numpy as np

from stickslip.brake import BrakeParams, travelling_wave
from stickslip.brake.waves import Scaling, ring_system, wave_spectrum
from stickslip.figures.brake.paper import FIG11
from stickslip.system import monodromy, simulate


def main():
    args = [a for a in sys.argv[1:] if a != "--separating"]
    top = int(args[0]) if args else 512
    if "--separating" in sys.argv[1:]:
        params = BrakeParams.from_physical(FIG11["omega"], 1.2e-6, FIG11["friction"])
        wave = travelling_wave(params, FIG11["modes"])
    else:
        params = BrakeParams.from_physical(100.0, 1e-4, 0.2)
        wave = travelling_wave(params, 4)
    sizes = [k for k in (64, 128, 256, 512, 1024) if k <= top]
    times = []
    for k in sizes:
        t0 = time.perf_counter()
        sp = wave_spectrum(wave, k)
        times.append(time.perf_counter() - t0)
        grow = "" if len(times) < 2 else f", time ~ N^{math.log2(times[-1] / times[-2]):.2f}"
        peak = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 2**20
        print(f"N = {k:4d}: {times[-1]:7.2f} s{grow}; leading |mu| = {abs(sp.leading):.7f}, ln growth per period "
              f"{sp.growth_per_period:.5f}, {sp.events_per_shift} events per node shift; peak memory {peak:.2f} GB",
              flush=True)
    if "--separating" in sys.argv[1:]:
        return
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
