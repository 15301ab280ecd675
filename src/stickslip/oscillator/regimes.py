"""Regime maps of the oscillator: which long-time behaviours coexist at each parameter point.

At every point of a grid (any two parameters of `Oscillator.parameter_names`):

* is steady sliding (the equilibrium) linearly stable?
* does a stick-slip cycle exist? It must pass through the end of the stick segment, so
  shooting from there decides it;
* if neither, is there a pure-slip cycle (shooting from near the equilibrium)?

Regime codes: 0 steady sliding only, 1 stick-slip only, 2 both (bistable),
3 pure-slip oscillation, 4 nothing attracting found. The grid runs through
`stickslip.sweep.run_sweep`: resumable, and parallel with Dask.
"""

from __future__ import annotations

import functools
import math

from ..errors import NoSolutionError
from ..sweep import run_sweep
from .cycle import limit_cycle
from .model import Oscillator
from .simulate import params_attrs
from .stability import equilibrium_stability

__all__ = ["REGIMES", "classify", "regime_map"]

REGIMES = {0: "steady sliding", 1: "stick-slip", 2: "bistable: steady sliding or stick-slip",
           3: "pure-slip oscillation", 4: "none found"}
OUTPUTS = {"regime": {v: k for k, v in REGIMES.items()}, "equilibrium_stable": "1", "amplitude": "m", "period": "s",
           "stick_time": "s"}


def classify(osc: Oscillator) -> dict:
    """The regime of one oscillator (see the module docstring)."""
    stable = equilibrium_stability(osc).stable
    out = {"equilibrium_stable": float(stable), "amplitude": math.nan, "period": math.nan, "stick_time": math.nan}
    try:
        cycle = limit_cycle(osc)
        sticks = cycle.touches_stick and cycle.stable
    except NoSolutionError:
        cycle, sticks = None, False
    if sticks:
        out.update(amplitude=cycle.amplitude, period=cycle.period, stick_time=cycle.stick_time)
        out["regime"] = 2.0 if stable else 1.0
        return out
    if stable:
        out["regime"] = 0.0
        return out
    try:  # unstable equilibrium and no stick-slip: a small pure-slip cycle (supercritical Hopf)?
        eps = 1e-3 * osc.friction.static * osc.normal_force / osc.stiffness
        cycle = limit_cycle(osc, osc.equilibrium - eps, 0.0)
        out.update(amplitude=cycle.amplitude, period=cycle.period, stick_time=0.0, regime=3.0)
    except NoSolutionError:
        out["regime"] = 4.0
    return out


def _point(base: Oscillator, **params) -> dict:
    osc = base
    for name, value in params.items():
        osc = osc.with_parameter(name, value)
    return classify(osc)


def regime_map(osc: Oscillator, axes: dict, store, **options):
    """Classify every point of ``axes`` (parameter name -> values) around ``osc``.

    ``store`` is the Zarr directory (resumable); ``options`` go to `run_sweep`
    (``scheduler``, ``batch``, ``progress``).
    """
    for name in axes:
        osc.parameter(name)
    attrs = {**params_attrs(osc), "friction_law": type(osc.friction).__name__}
    return run_sweep(functools.partial(_point, osc), axes, store, outputs=OUTPUTS, attrs=attrs,
                     title="regimes of the friction oscillator", model="oscillator", **options)
