"""An integration written apart for two blocks whose second one sticks and slips on a belt (the
reference of `test_rate_state_mixed` and `test_smooth_laws`): LSODA with its own event location,
block 2's coordinate eliminated while it sticks (``x2 = x2s + V2 (t - ts)``). The caller writes the
equations: ``slipping(t, y, s)`` in ``y = (x1, x2, v1, v2, *extra)``, ``stuck(t, y, x2s, ts)`` in
``y = (x1, v1, *extra)`` and ``hold(t, y, x2s, ts)``, the friction force that keeps block 2 stuck."""

import numpy as np
from scipy.integrate import solve_ivp


def stick_slip_pair(t_eval, y0, slipping, stuck, hold, belt, limit, held=False):
    """Block 2's positions ``x`` at ``t_eval`` (NaN beyond where it got) and the switches ``[(t, state)]``
    (0 stuck, +-1 slipping) from ``y0`` (``(x1, x2, v1, v2, *extra)``), block 2 slipping unless ``held``;
    ``belt`` its belt's speed, ``limit`` ``f_s N``: a number, or ``limit(t, y, x2s, ts)`` (as ``hold``)."""
    bound = limit if callable(limit) else (lambda t, y, x2s, ts: limit)
    out = np.full((t_eval.size, 2), np.nan)
    t, y, events = 0.0, list(y0), []
    s = 1 if belt > y0[3] else -1
    if held:
        s, ts, x2s, y = 0, 0.0, y0[1], [y0[0], y0[2], *y0[4:]]
    opts = dict(method="LSODA", rtol=1e-12, atol=1e-16)
    while t < t_eval[-1]:
        sel = t_eval >= t
        if s != 0:
            reach = lambda t, y, s: belt - y[3]  # noqa: E731
            reach.terminal, reach.direction = True, -s
            sol = solve_ivp(slipping, (t, t_eval[-1]), y, t_eval=t_eval[sel], events=reach, args=(s,), **opts)
            out[np.flatnonzero(sel)[:sol.t.size]] = sol.y[:2].T
            if sol.status == 0:
                break
            t, y = sol.t_events[0][0], sol.y_events[0][0]
            ts, x2s = t, y[1]
            z = [y[0], y[2], *y[4:]]
            s = 0 if abs(hold(t, z, x2s, t)) <= bound(t, z, x2s, t) else -s
            events.append((t, s))
            if s == 0:
                y = [y[0], y[2], *y[4:]]
        else:
            up = lambda t, y, x2s, ts: hold(t, y, x2s, ts) - bound(t, y, x2s, ts)  # noqa: E731
            down = lambda t, y, x2s, ts: hold(t, y, x2s, ts) + bound(t, y, x2s, ts)  # noqa: E731
            up.terminal = down.terminal = True
            up.direction, down.direction = 1, -1
            sol = solve_ivp(stuck, (t, t_eval[-1]), y, t_eval=t_eval[sel], events=[up, down], args=(x2s, ts), **opts)
            out[np.flatnonzero(sel)[:sol.t.size]] = np.column_stack([sol.y[0], x2s + belt * (sol.t - ts)])
            if sol.status == 0:
                break
            which = 0 if sol.t_events[0].size else 1
            t, z = sol.t_events[which][0], sol.y_events[which][0]
            s = 1 if which == 0 else -1
            y = [z[0], x2s + belt * (t - ts), z[1], belt, *z[2:]]
            events.append((t, s))
    return out, events
