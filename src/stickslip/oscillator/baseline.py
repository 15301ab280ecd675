"""A deliberately plain reference: the oscillator integrated with `scipy.integrate.solve_ivp`.

Each mode is integrated by ``solve_ivp`` with terminal events (``v = V`` in slip, the
stick limit ``|k x + c V| = f_s N`` in stick), as one would write it by hand. It shares
no code with the event-driven engine, so it serves as an independent check in tests and
figures, and as the baseline of ``benchmarks/oscillator_cycles.py``.
"""

from __future__ import annotations

import numpy as np
from scipy.integrate import solve_ivp

from .model import Oscillator

__all__ = ["solve_ivp_switches"]


def solve_ivp_switches(osc: Oscillator, x0: float, v0: float, t_end: float, *, rtol: float = 1e-10,
                       method: str = "DOP853", max_switches: int = 10**6):
    """Switching events ``(t, x, v, new_mode)`` from a plain solve_ivp integration.

    ``new_mode`` is +1 (slip), 0 (stick) or -1 (reverse slip).
    """
    m, k, c, n, V = osc.mass, osc.stiffness, osc.damping, osc.normal_force, osc.belt_speed
    law, fsn = osc.friction, osc.friction.static * osc.normal_force
    atol = rtol * max(V, osc.omega * fsn / k)

    def slip_rhs(s):
        def rhs(t, y):
            mu = law.kinetic(s * max(abs(V - y[1]), 1e-300))
            return [y[1], (s * n * mu - c * y[1] - k * y[0]) / m]
        return rhs

    def reach_belt(s):
        event = lambda t, y: y[1] - V
        event.terminal, event.direction = True, (1 if s > 0 else -1)
        return event

    def stick_end(t, y):
        return fsn - (k * y[0] + c * V)

    stick_end.terminal, stick_end.direction = True, -1
    t, y = 0.0, np.array([x0, v0], float)
    mode = 1 if v0 < V else (-1 if v0 > V else (0 if abs(k * x0 + c * V) <= fsn else (1 if k * x0 + c * V > 0 else -1)))
    switches = []
    while t < t_end and len(switches) < max_switches:
        if mode == 0:
            sol = solve_ivp(lambda t, y: [V, 0.0], (t, t_end), y, method=method, rtol=rtol, atol=atol,
                            events=stick_end)
        else:
            sol = solve_ivp(slip_rhs(mode), (t, t_end), y, method=method, rtol=rtol, atol=atol,
                            events=reach_belt(mode), first_step=None)
        event_times = sol.t_events[0]
        if event_times.size == 0:
            break
        t, y = float(event_times[0]), sol.y_events[0][0].copy()
        if mode == 0:
            mode = 1
        else:
            y[1] = V
            force = k * y[0] + c * V
            mode = 0 if abs(force) <= fsn else (1 if force > 0 else -1)
        switches.append((t, float(y[0]), float(y[1]), mode))
    return switches
