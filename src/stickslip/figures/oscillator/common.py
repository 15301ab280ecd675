"""Shared pieces of the oscillator figures: sampled orbits and section returns."""

from __future__ import annotations

import numpy as np

from ...oscillator import Engine, Oscillator, simulate
from ...oscillator.cycle import return_horizon


PADDED = "NaN past the end of a start's orbit (orbits have different numbers of samples)"


def orbits(osc: Oscillator, starts, t_end: float, num: int):
    """Sample orbits from several starts into NaN-padded ``(start, sample)`` arrays."""
    rows = [simulate(osc, t_end, x0, v0).sample(num) for x0, v0 in starts]
    width = max(r[0].size for r in rows)
    out = {k: np.full((len(rows), width), np.nan) for k in ("t", "x", "v", "mode")}
    for i, r in enumerate(rows):
        for k, arr in zip(("t", "x", "v", "mode"), r):
            out[k][i, : arr.size] = arr
    return out


def section_after(osc: Oscillator, x0: float, v0: float, transient: float) -> float:
    """Where the orbit from ``(x0, v0)`` crosses ``v = 0`` upward after ``transient`` seconds."""
    engine = Engine(osc)
    first = engine.run(x0, v0, transient)
    again = engine.run(float(first.x[-1]), float(first.v[-1]), return_horizon(osc), section=0.0)
    return float(again.x[-1]) if again.status == 1 else np.nan


def osc_attrs(osc: Oscillator) -> dict:
    from ...oscillator.simulate import params_attrs

    return params_attrs(osc)


def osc_from_attrs(attrs) -> Oscillator:
    """Rebuild the oscillator stored in a dataset's attributes (for the checks)."""
    from ... import friction

    law = attrs["friction_law"]
    fs, fd = attrs["friction_fs"], attrs["friction_fd"]
    if law == "Coulomb":
        f = friction.Coulomb(fs, fd)
    elif law == "LinearWeakening":
        f = friction.LinearWeakening(fs, fd, attrs["friction_tau"])
    else:
        f = friction.Stribeck(fs, fd, attrs["friction_vs"])
    return Oscillator(attrs["mass_kg"], attrs["stiffness_N_per_m"], attrs["normal_force_N"],
                      attrs["belt_speed_m_per_s"], f, attrs["damping_N_s_per_m"])
