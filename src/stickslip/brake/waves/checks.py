"""Independent checks of a travelling wave: numerical integration and energy balance.

* `integrate_wave` integrates [15] zone by zone with `scipy.integrate.solve_ivp`
  (not the closed forms), in time order, applying the physical switching rules at the
  switching points of the wave (the impact law at landings): it measures how far the
  numerical solution is from the closed form, how well the switching conditions hold
  on it, and whether it closes after one period.
* `energy_balance`: multiplying [15] by ``U'`` and ``V'`` and integrating over a period,
  the elastic and inertia terms cancel (``U, V`` periodic and continuous; the coupling
  ``-D V' U' + D U' V'`` vanishes), which leaves

      int P U' + Q V' dphi + sum_impacts [Pi (U'+ + U'-) + Q_Pi (V'+ + V'-)]/2 = 0:

  the net work of the contact forces on the ring over one period is zero (its energy is
  periodic). With ``w = 1 + c V'`` this is the balance of the shaft's work, the friction
  dissipated by sliding and the energy lost in impacts:

      int Q dphi + sum Q_Pi = int f P |w| dphi + sum [Q_Pi (w+ + w-)/2 + c Pi U'_sep/2],

  every term of the right-hand side being >= 0.
"""

from __future__ import annotations

import numpy as np

from ...quantities import BRAKE as Q
from scipy.integrate import solve_ivp

from .zones import CONTACT, SEPARATION, STICK, slip_sign
from ... import validation as check

__all__ = ["energy_balance", "integrate_wave"]


def _gauss(n=48):
    x, w = np.polynomial.legendre.leggauss(n)
    return 0.5 * (x + 1.0), 0.5 * w


def _landings(wave):
    """``(i, j, y_sep_end, y_contact_start)`` for each landing (``phi`` order indices)."""
    fl, starts = wave._flows(), wave._starts
    m, out = len(wave.zones), []
    for i in range(m):
        j = (i + 1) % m
        k1, k2 = wave.zones[i].kind, wave.zones[j].kind
        early = k1 if wave.layout.direction > 0 else k2
        if early == SEPARATION:
            y1 = fl.flow(k1, starts[i], np.array(wave.zones[i].length))
            out.append((i, j, y1, starts[j]))
    return out


def energy_balance(wave) -> dict:
    """Work and dissipation over one period (paper units, per unit ``phi``-length of wave).

    Returns ``shaft_work`` (``int Q dphi`` plus the friction impulses), ``sliding``
    (``int f P |w| dphi``), ``impacts`` (energy lost in impacts), ``ring_work`` (net work
    of the contact forces on the ring over the sum of the absolute values of its terms, 0
    for a periodic wave) and ``residual``
    (``|shaft_work - sliding - impacts| / shaft_work``).
    """
    from .result import TravellingWave
    
    check.instance("wave", wave, TravellingWave, "a stickslip.brake.TravellingWave")
    fl, starts, r = wave._flows(), wave._starts, wave._scaling.root_gamma
    x, wq = _gauss()
    shaft = sliding = ring = ring_abs = 0.0
    for z, y0 in zip(wave.zones, starts):
        if z.kind == SEPARATION:
            continue
        s = x * z.length
        Y = fl.flow(z.kind, y0, s)
        P, Q = fl.pressure(z.kind, Y), fl.traction(z.kind, Y)
        w = fl.slip_velocity(Y) if z.kind != STICK else np.zeros_like(P)
        shaft += z.length * np.dot(wq, Q)
        sliding += z.length * np.dot(wq, fl.f * P * np.abs(w))
        ring += z.length * np.dot(wq, Q * Y[:, 3])
        ring_abs += z.length * np.dot(wq, np.abs(Q * Y[:, 3]))
    impacts = 0.0
    for i, j, y1, y2 in _landings(wave):
        Pi, Q_Pi = fl.impulses(y1, y2)
        shaft += Q_Pi
        jump = 0.5 * (Pi * (y1[1] + y2[1]) + Q_Pi * (y1[3] + y2[3]))
        ring, ring_abs = ring + jump, ring_abs + abs(jump)
        u_sep = y1[1] + y2[1]  # the contact side has U' = 0
        impacts += 0.5 * Q_Pi * (fl.slip_velocity(y1) + fl.slip_velocity(y2)) + 0.5 * fl.c * Pi * u_sep
    out = {"shaft_work": shaft / r, "sliding": sliding / r, "impacts": impacts / r,
           "ring_work": ring / ring_abs}
    out["residual"] = abs(out["shaft_work"] - out["sliding"] - out["impacts"]) / abs(out["shaft_work"])
    return out


def _rhs(fl, kind):
    c2a, c2b = fl.ca, fl.cb
    s = slip_sign(kind)

    def rhs(_, y):
        U, dU, V, dV = y
        if kind == SEPARATION:  # [15] with P = Q = 0
            return [dU, (fl.D * dV - fl.g * U) / c2b, dV, (-fl.D * dU - fl.h * V) / c2a]
        if kind == STICK:  # U = delta, V' = -1/c
            return [0.0, 0.0, dV, 0.0]
        P = fl.g * U - fl.D * dV  # [15] with U'' = 0
        return [0.0, 0.0, dV, (s * fl.f * P - fl.h * V) / c2a]
    return rhs


def integrate_wave(wave, rtol: float = 1e-11, atol: float = 1e-13, num: int = 50) -> dict:
    """Integrate [15] numerically through one period, in time order, from the stick exit.

    Only the switching points ``phi_k`` and the start state of the stick zone are taken
    from ``wave``. At each switching point the physical rule is applied to the numerical
    state (landing: ``U = delta``, ``U' = 0``, tangential impulse of Coulomb's law;
    entering stick: ``V' = -1/c``). Returns, in internal units relative to the wave's
    scales: ``profile_error`` (max over ``num`` points per zone of ``|y_num - y_closed|``),
    ``switching`` (the worst mismatch of a switching condition on the numerical state),
    ``periodicity`` (``|y(after one period) - y(start)|``) and ``zones`` (time order).
    """
    from .result import TravellingWave
    
    check.instance("wave", wave, TravellingWave, "a stickslip.brake.TravellingWave")
    rtol, atol, num = Q.check("rtol", rtol), Q.check("atol", atol), Q.check("points", num, "num")
    fl, starts, m = wave._flows(), wave._starts, len(wave.zones)
    direction = wave.layout.direction
    order = [0] + (list(range(1, m)) if direction > 0 else list(range(m - 1, 0, -1)))
    scale = np.array([max(abs(fl.delta), 1e-300), 1.0, 1.0, 1.0])
    P_st = fl.stick_pressure()

    def span(i):  # zone i from its time-start to its time-end, in phi relative to its start
        L = wave.zones[i].length
        return (0.0, L) if direction > 0 else (L, 0.0)

    y0 = fl.flow(STICK, starts[0], np.array(span(0)[0]))
    y, err, mismatch = y0.copy(), 0.0, {}
    for pos, i in enumerate(order):
        kind = wave.zones[i].kind
        a, b = span(i)
        t_eval = np.linspace(a, b, num)
        sol = solve_ivp(_rhs(fl, kind), (a, b), y, method="DOP853", rtol=rtol, atol=atol, t_eval=t_eval)
        closed = fl.flow(kind, starts[i], t_eval)
        err = max(err, float(np.max(np.abs(sol.y.T - closed) / scale)))
        y_end = sol.y[:, -1]
        nxt = order[(pos + 1) % m]
        knext = wave.zones[nxt].kind
        y = y_end.copy()
        if kind in CONTACT and knext in CONTACT:
            if kind == STICK:  # leaving stick: Q = f P
                mismatch["stick_exit"] = abs(fl.h * y_end[2] - slip_sign(knext) * fl.f * P_st) / (fl.f * P_st)
            else:  # slip velocity reaches 0
                mismatch[f"{kind}_end"] = abs(fl.slip_velocity(y_end))
            if knext == STICK:
                y[3] = -1.0 / fl.c
        elif knext == SEPARATION:  # lift-off: P -> 0
            mismatch["lift_off"] = abs(fl.pressure(kind, y_end)) / abs(P_st)
        else:  # landing: impact law
            mismatch["landing"] = abs(y_end[0] - fl.delta) / scale[0]
            y[0], y[1] = fl.delta, 0.0
            Pi = -direction * fl.cb * y_end[1]
            q_stop = direction * fl.ca * (-1.0 / fl.c - y_end[3])
            if abs(q_stop) <= fl.f * Pi:  # the impulse stops the sliding
                y[3] = -1.0 / fl.c
            else:
                s = np.sign(fl.slip_velocity(y_end))
                y[3] = y_end[3] + direction * s * fl.f * Pi / fl.ca
    periodicity = float(np.max(np.abs(y - y0) / scale))
    return {"profile_error": err, "switching": max(mismatch.values()), "mismatch": mismatch,
            "periodicity": periodicity, "zones": [wave.zones[i].kind for i in order]}
