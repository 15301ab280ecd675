"""The block on the belt against the 1-DOF friction oscillator with the same m, k, N, V, fs, fd.

Usage: ``python compare.py [block.toml] [cycles]`` (after ``python mesh.py block.msh``).
Runs the block from sticking at its preload for ``cycles`` oscillator periods (default 4)
and prints, for every slip event of the block, its start time, the friction coefficient it
started at (``k x / N``, ``x`` the mean tangential displacement of the contact line) and the
time since the previous one, beside the oscillator's period and static coefficient, and
the oscillator's period with the block's mean onset coefficient as its static one.
"""

import sys

import numpy as np

from stickslip.fem import BodyScheme, integrate_body
from stickslip.fem.config import load_config
from stickslip.fem.run import preload_body
from stickslip.friction import Coulomb
from stickslip.oscillator import Oscillator, limit_cycle


def compare(config="block.toml", cycles=4.0):
    cfg = load_config(config)
    problem = cfg.problem()
    body = problem.system.body
    m = cfg.material.density * float(np.sum(body.areas))  # kg per metre of thickness
    k = sum(s.stiffness[0] for s in cfg.springs)
    N = float(problem.steady.pressure.sum())
    V = cfg.surface.velocity[0]
    fs, fd = cfg.static_friction, cfg.friction
    cycle = limit_cycle(Oscillator(m, k, N, V, Coulomb(fs, fd)))
    print(f"1-DOF oscillator: m = {m:g} kg/m, k = {k:g} N/m^2, N = {N:g} N/m, V = {V:g} m/s")
    print(f"  period {cycle.period * 1e3:.3f} ms (stick {cycle.stick_time * 1e3:.3f}, slip "
          f"{cycle.slip_time * 1e3:.3f}); slip starts at k x / N = fs = {fs:g}")
    scheme = BodyScheme(problem)
    run = integrate_body(problem, cycles * cycle.period, initial=preload_body(scheme, (V, 0.0)),
                         snapshot_every=1e9, tail=0.0)
    ds = run.to_xarray()
    t, stick = ds.t.values, ds.fraction.sel(kind="stick").values
    x = ds.modes_V_re.sel(mode=0).values
    starts = np.flatnonzero((stick[:-1] >= 0.5) & (stick[1:] < 0.5)) + 1
    starts = [i for j, i in enumerate(starts) if j == 0 or t[i] - t[starts[j - 1]] > 0.2 * cycle.period]
    print(f"block ({len(body.points)} nodes, step {scheme.dt:.3g} s): slip events")
    for j, i in enumerate(starts):
        gap = "" if j == 0 else f", {(t[i] - t[starts[j - 1]]) * 1e3:.3f} ms after the previous one"
        print(f"  t = {t[i] * 1e3:8.3f} ms, k x / N = {k * x[i] / N:.3f}{gap}")
    sep = ds.fraction.sel(kind="separation").values
    print(f"  largest fraction of contact nodes separated at once: {sep.max():.2f}")
    later = [k * x[i] / N for i in starts[1:]]
    if later and np.mean(later) > fd:
        fs_eff = float(np.mean(later))
        eff = limit_cycle(Oscillator(m, k, N, V, Coulomb(fs_eff, fd)))
        spans = np.diff([t[i] for i in starts])
        print(f"1-DOF oscillator with the block's mean onset coefficient {fs_eff:.3f} as fs: period "
              f"{eff.period * 1e3:.3f} ms; the block's mean period {np.mean(spans) * 1e3:.3f} ms")


if __name__ == "__main__":
    compare(*(sys.argv[1:2] or ["block.toml"]), *(float(c) for c in sys.argv[2:3]))
