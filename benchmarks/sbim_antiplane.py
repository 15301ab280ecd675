"""The antiplane spectral boundary integral method (`stickslip.sbim`): the cost of a step against the
number of elements N, and against a direct convolution in space and time written here.

A half-space surface free under a traction pulse (a sum of modes), beta = 0.5, each mode's history 4
of its periods. The direct method is the same discrete problem without the FFT: the traction at each
node is the sum over nodes and past steps of a space-time influence matrix (here its modes'
kernels summed into real space once, ``N x N x steps``) times the slip rates, O(N^2 x steps) a step;
the spectral one costs O(N log N) plus each mode's own history, about ``(eta N / beta) ln(N / 2)``.

The in-plane runs' cost a step is printed beside (two components, four convolutions, 16 periods of
history at beta = 0.3; the run's set-up, its kernel table and stability check, not timed).

    .venv/bin/python benchmarks/sbim_antiplane.py [--largest 14] [--steps 200]
    .venv/bin/python benchmarks/sbim_antiplane.py --long   # N = 2^14 over 1e5 steps (issue 46), minutes

``--long`` runs N = 2^14 elements over 10^5 steps, the history filling as it goes (mode 1 keeps 131,072
steps: every mode's whole memory at the end), and prints its wall time against the direct convolution's
projected from its own constant measured in the same run (N = 256, 100 steps: its cost a step grows with
N^2 times the steps behind it, so N^2 steps^2 / 2 in all).
"""

from __future__ import annotations

import argparse
import math
import time

import numpy as np

from stickslip.sbim import AntiplaneProblem, FreeSurface, InplaneProblem, run_antiplane, run_inplane
from stickslip.sbim.kernels import ragged_step_weights

MU, C, L = 3e10, 3000.0, 1000.0


def pulse(x, t):
    return 1e6 * np.exp(-(((x - L / 2) / (L / 20)) ** 2))


def spectral(N, steps):
    from stickslip.sbim.history import KERNELS

    KERNELS.compiled  # noqa: B018 - loaded now: every size timed compiled (a short run would choose Python's loop)
    problem = AntiplaneProblem(MU, C, L, N, pulse, FreeSurface(), beta=0.5, history_periods=4.0)
    run_antiplane(problem, 2)  # compiled and cached on the first size
    t = time.perf_counter()
    run = run_antiplane(problem, steps, every=steps)
    return (time.perf_counter() - t) / steps, run


def direct(N, steps):
    """The same steps by a direct space-time convolution: ``f_i = sum_j sum_l G[l, i - j] V_j(n - 1 - l)``
    with ``G`` the influence of a unit rate held over a step at lag ``l`` (its modes summed into real
    space), the static term ``-mu |k| w`` in real space as a dense matrix too."""
    problem = AntiplaneProblem(MU, C, L, N, pulse, FreeSurface(), beta=0.5, history_periods=4.0)
    k = problem.wavenumbers
    dt = problem.dt
    counts = np.full(k.size, steps)
    counts[0] = 0
    W = np.zeros((k.size, steps))  # the scheme's weights at every lag: the direct method truncates nothing
    W[1:] = ragged_step_weights(k[1:] * C, dt, counts[1:]).reshape(k.size - 1, steps)
    G = np.fft.irfft(MU * k[:, None] * W, N, axis=0).T  # (lags, N): influence at a distance
    S = np.fft.irfft(-MU * k, N)  # static: -mu |k| w in real space
    idx = (np.arange(N)[:, None] - np.arange(N)[None, :]) % N
    Gm = G[:, idx]  # (lags, N, N)
    Sm = S[idx]
    x = problem.x
    rates, slip = [], np.zeros(N)
    t0 = time.perf_counter()
    for n in range(steps + 1):
        f = Sm @ slip
        for lag, v in enumerate(reversed(rates)):
            f += Gm[lag] @ v
        rate = (C / MU) * (pulse(x, n * dt) + f)
        if n == steps:
            break
        slip = slip + dt * rate
        rates.append(rate)
    return (time.perf_counter() - t0) / steps, slip


def inplane(N, steps):
    """In-plane (`stickslip.sbim.inplane`): two components, four convolutions a step, beta = 0.3, 16 periods."""
    problem = InplaneProblem(MU, C, 0.25, L, N, lambda x, t: (pulse(x, t), -pulse(x, t)), FreeSurface(), beta=0.3)
    run_inplane(problem, 2)
    t = time.perf_counter()
    run_inplane(problem, steps, every=steps)
    return (time.perf_counter() - t) / steps


def long_run(N: int = 1 << 14, steps: int = 100_000) -> None:
    """N elements over ``steps`` steps, timed whole, against the direct method's projection."""
    n0, s0 = 256, 100
    t_direct, _ = direct(n0, s0)
    constant = 2.0 * t_direct * s0 / (n0**2 * s0**2)  # seconds per (element pair x lag)
    problem = AntiplaneProblem(MU, C, L, N, pulse, FreeSurface(), beta=0.5, history_periods=4.0)
    run_antiplane(problem, 2)  # compiled
    t = time.perf_counter()
    run = run_antiplane(problem, steps, every=steps // 10)
    wall = time.perf_counter() - t
    projected = constant * N**2 * steps**2 / 2.0
    print(f"N = {N}, {steps} steps: {wall:.1f} s ({wall / steps:.3e} s/step), largest slip rate at the end "
          f"{np.abs(run.slip_rate[-1]).max():.3g} m/s (finite: {bool(np.all(np.isfinite(run.slip_rate)))})")
    print(f"direct convolution: {constant:.3e} s per element pair and lag (measured at N = {n0}, {s0} steps); "
          f"projected for this run {projected:.3e} s; ratio direct / spectral {projected / wall:.3g}")


def main():
    parser = argparse.ArgumentParser()
    parser.add_argument("--largest", type=int, default=14, help="log2 of the largest N")
    parser.add_argument("--steps", type=int, default=200)
    parser.add_argument("--long", action="store_true", help="N = 2^14 over 1e5 steps (minutes)")
    args = parser.parse_args()
    if args.long:
        long_run()
        return
    print("N        s/step (spectral)   per N log2 N [ns]")
    costs = {}
    for p in range(8, args.largest + 1):
        N = 2 ** p
        per_step, _ = spectral(N, args.steps)
        costs[N] = per_step
        print(f"{N:<8} {per_step:<19.3e} {1e9 * per_step / (N * p):.1f}")
    N, steps = 256, 100
    s_direct, slip_direct = direct(N, steps)
    s_spectral, run = spectral(N, steps)
    # the two agree where the spectral history is not truncated (100 steps: every mode's whole history at N = 256
    # up to its 4 periods; the direct one keeps all)
    print(f"direct at N = {N}, {steps} steps: {s_direct:.3e} s/step; spectral {s_spectral:.3e} s/step; "
          f"ratio direct / spectral {s_direct / s_spectral:.1f}")
    for N in (256, 1024, 4096):
        print(f"in-plane at N = {N}: {inplane(N, args.steps):.3e} s/step (antiplane {costs.get(N, float('nan')):.3e})")
    big = max(costs)
    print(f"N = {big}: {costs[big]:.3e} s/step, 1e5 steps would take {1e5 * costs[big]:.0f} s")
    print(f"growth from N = 256 to {big}: {costs[big] / costs[256]:.1f} (N log N alone: "
          f"{big * math.log2(big) / (256 * 8):.1f})")


if __name__ == "__main__":
    main()
