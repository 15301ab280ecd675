"""Stick-slip cycles of a 2-DOF system with two Coulomb contacts: exact switching vs solve_ivp.

Ours: `stickslip.system.simulate` on the two-block chain of `examples/two_blocks/two_blocks.toml`
(closed-form flows between events; the search for each event compiled, the choice of states at
it in Python). Baseline: `scipy.integrate.solve_ivp` (DOP853, rtol 1e-10) with terminal events at
every switch, one call per segment, the equations of this chain written here (each contact on its own block, so a sticking block moves with its
belt and its friction force is the rest of the forces on it). Both run the same cycles from the
same start in this process; the period (mean time between the stick onsets of block 2) of each
is compared with a baseline at rtol 1e-13. Prints both times and both ratios (target: >= 100x
faster, >= 100x smaller period error). ``python benchmarks/system_cycles.py [CYCLES]``.
"""

import sys
import time
from pathlib import Path

import numpy as np
from scipy.integrate import solve_ivp

from stickslip.system import load_system, simulate

SYSTEM = load_system(Path(__file__).resolve().parents[1] / "examples" / "two_blocks" / "two_blocks.toml")
M, K, C = np.diag(SYSTEM.mass), SYSTEM.stiffness, SYSTEM.damping
V = np.array([c.surface_speed for c in SYSTEM.contacts])
N = np.array([c.normal_force for c in SYSTEM.contacts])
FS = np.array([c.friction.fs for c in SYSTEM.contacts])
FD = np.array([c.friction.fd for c in SYSTEM.contacts])


def _rhs(states):
    def f(t, y):
        x, v = y[:2], y[2:]
        rest = -(K @ x) - C @ v
        a = np.where(states == 0, 0.0, (rest + states * FD * N) / M)
        return np.concatenate([np.where(states == 0, V, v), a])
    return f


def _events(states):
    out = []
    for i in range(2):
        if states[i] == 0:
            def ev(t, y, i=i):
                return FS[i] * N[i] - abs((K @ y[:2] + C @ y[2:])[i])
        else:
            def ev(t, y, i=i, s=states[i]):
                return s * (V[i] - y[2 + i])
        ev.terminal, ev.direction = True, -1
        out.append(ev)
    return out


def baseline(t_end, rtol):
    """Stick onsets of block 2 (the times it starts sticking) from an event-driven solve_ivp."""
    y, t = np.zeros(4), 0.0
    states = np.where(V - y[2:] > 0, 1, -1)
    onsets = []
    while t < t_end:
        sol = solve_ivp(_rhs(states), (t, t_end), y, method="DOP853", rtol=rtol, atol=rtol * 1e-3,
                        events=_events(states))
        t, y = sol.t[-1], sol.y[:, -1]
        if sol.status != 1:
            break
        hit = [i for i in range(2) if sol.t_events[i].size]
        for i in hit:
            if states[i] == 0:  # released in the direction of the friction force it needed
                states[i] = 1 if (K @ y[:2] + C @ y[2:])[i] > 0 else -1
            else:
                force = (K @ y[:2] + C @ y[2:])[i]
                if abs(force) <= FS[i] * N[i]:
                    states[i] = 0
                    y[2 + i] = V[i]
                    if i == 1:
                        onsets.append(t)
                else:
                    states[i] = -states[i]
    return np.array(onsets)


def ours(t_end):
    run = simulate(SYSTEM, [0.0, 0.0], [0.0, 0.0], t_end, samples=2)
    return run.event_time[(run.event_contact == 1) & (run.event_state == 0)]


def period(onsets, skip=5):
    o = onsets[skip:]
    return (o[-1] - o[0]) / (o.size - 1)


def main():
    cycles = int(sys.argv[1]) if len(sys.argv) > 1 else 1000
    t_end = 6.6916 * cycles
    ours(20.0)
    t0 = time.perf_counter()
    mine = ours(t_end)
    t_ours = time.perf_counter() - t0
    t0 = time.perf_counter()
    base = baseline(t_end, 1e-10)
    t_base = time.perf_counter() - t0
    ref = baseline(t_end, 1e-13)
    p_ref = period(ref)
    e_ours, e_base = abs(period(mine) - p_ref), abs(period(base) - p_ref)
    print(f"cycles: ours {mine.size}, baseline {base.size}, reference (rtol 1e-13) {ref.size}")
    print(f"time: ours {t_ours:.3f} s ({t_ours / mine.size * 1e3:.3f} ms a cycle), "
          f"solve_ivp+events {t_base:.2f} s ({t_base / base.size * 1e3:.2f} ms a cycle)")
    print(f"period {p_ref:.15f} s; error against the reference: ours {e_ours:.2e} s, baseline {e_base:.2e} s")
    print(f"speed-up: {t_base / t_ours:.2f}x   error ratio: {e_base / max(e_ours, np.spacing(p_ref)):.2e}x "
          "(ours bounded by the reference's own error)")


if __name__ == "__main__":
    main()
