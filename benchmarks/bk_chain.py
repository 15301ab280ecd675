"""A Burridge-Knopoff chain of 100 blocks: events per second of the exact event-driven run, and
the independent time-stepping scheme of the tests (Moreau's, springs explicit) at the steps that
bring it within 1e-2, 1e-3 ... of the exact end state: its time against ours at equal accuracy.

``python benchmarks/bk_chain.py [BLOCKS] [SECONDS]`` (default 100 blocks, 10 s of motion).
"""

import sys
import time

import numpy as np

from stickslip.friction import Coulomb
from stickslip.system import burridge_knopoff, simulate

M, KP, KC, N, V = 1.0, 1.0, 4.0, 1.0, 0.05


def moreau(x0, v0, t_end, steps):
    h = t_end / steps
    x, v = x0.copy(), v0.copy()
    for _ in range(steps):
        lap = np.zeros_like(x)
        lap[1:] += x[1:] - x[:-1]
        lap[:-1] += x[:-1] - x[1:]
        free = v + h * (-KP * x - KC * lap) / M
        stick = np.abs(M * (-V - free)) <= 0.6 * N * h
        v = np.where(stick, -V, free + np.sign(-V - free) * 0.4 * N * h / M)
        x = x + h * v
    return x


def main():
    blocks = int(sys.argv[1]) if len(sys.argv) > 1 else 100
    t_end = float(sys.argv[2]) if len(sys.argv) > 2 else 10.0
    chain = burridge_knopoff(blocks, Coulomb(0.6, 0.4), mass=M, pull=KP, coupling=KC, normal_force=N, plate_speed=V)
    x0 = np.random.default_rng(3).uniform(-0.3, 0.3, blocks)  # seeded: one fixed start
    v0 = -V * np.ones(blocks)
    t0 = time.perf_counter()
    run = simulate(chain, x0, v0, t_end, samples=2)
    ours = time.perf_counter() - t0
    events = run.event_time.size
    print(f"{blocks} blocks, {t_end:g} s: {events} events in {ours:.2f} s ({events / ours:.1f} events/s)")
    size = np.abs(run.x[-1]).max()
    for steps in (2_000, 8_000, 32_000, 128_000):
        t0 = time.perf_counter()
        x = moreau(x0, v0, t_end, steps)
        spent = time.perf_counter() - t0
        err = np.abs(x - run.x[-1]).max() / size
        print(f"  Moreau {steps:>7} steps: {spent:6.2f} s, relative error {err:.1e} (ours: round-off; "
              f"time ratio Moreau/ours {spent / ours:.2f})")


if __name__ == "__main__":
    main()
