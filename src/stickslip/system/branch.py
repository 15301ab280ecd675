"""The result of a continuation: cycles along a parameter (`SystemBranch`), and a file key's units."""

from __future__ import annotations

import re
from dataclasses import dataclass

import numpy as np
import lazy_loader as lazy

from ..cf import finish
from ..quantities import OSCILLATOR, SYSTEM as Q
from ..results import Result

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["SystemBranch", "parameter_units"]

#: Uniform samples of each orbit of a branch from which its amplitude is taken.
AMPLITUDE_SAMPLES = 401


def parameter_units(key: str) -> str:
    """The units of the number a file key names (``contact[0].surface_speed``: ``m/s``), from the
    declarations; ``1`` for a name that is not a file key."""
    match = re.fullmatch(r"contact\[\d+\]\.(\w+)|(mass|stiffness|damping|force)\[.*|harmonic(?:\[\d+\])?\.(\w+).*",
                         str(key))
    if match is None:
        return "1"
    name = match[1] or ({"frequency": "forcing_frequency"}.get(match[3], "harmonic_force") if match[3] else
                        {"mass": "mass_matrix", "stiffness": "stiffness_matrix", "damping": "damping_matrix",
                         "force": "force"}[match[2]])
    domain = OSCILLATOR if name in ("fs", "fd", "tau") else Q
    return domain[name].units if name in domain else "1"


@dataclass(frozen=True, eq=False, repr=False)
class SystemBranch(Result):
    """Cycles at the ``values`` of ``parameter``: their ``period``, start ``x0``, ``v0`` (one row a
    value; with the contact ``states`` there, a `simulate` of one period draws the orbit), the moduli of their largest
    ``multipliers`` (the flow's own 1 removed; NaN-padded), ``stable`` and the sequence of
    contact events of each (``"0:stick 1:slip ..."``); ``events``, the changes located along
    the branch (dicts with ``change``, ``value``, ``before``, ``after``; a stability change also says
    its multiplier's ``crossing``), and why it ``stopped``; ``amplitude``, half the peak-to-peak
    displacement of each degree of freedom over each orbit (from `AMPLITUDE_SAMPLES` samples and its
    events). A forced system's branch (``forced``) starts its orbits at phase zero of the force and
    keeps every multiplier."""

    parameter: str
    values: np.ndarray
    period: np.ndarray
    x0: np.ndarray
    v0: np.ndarray
    states: tuple
    multipliers: np.ndarray
    stable: np.ndarray
    sequence: tuple
    events: tuple
    stopped: str
    amplitude: np.ndarray
    forced: bool = False
    psi0: np.ndarray | None = None
    MODEL = "system"

    def to_dict(self) -> dict:
        return {"parameter": self.parameter, "values": self.values.tolist(), "period": self.period.tolist(),
                "stable": [bool(s) for s in self.stable], "events": [dict(e) for e in self.events],
                "stopped": self.stopped, "points": int(self.values.size), "forced": self.forced,
                "amplitude": self.amplitude.tolist()}

    def to_xarray(self) -> xr.Dataset:
        ds = xr.Dataset(
            {"period": ("point", self.period), "stable": ("point", self.stable.astype(np.int8)),
             "x0": (("point", "dof"), self.x0), "v0": (("point", "dof"), self.v0),
             "amplitude": (("point", "dof"), self.amplitude),
             "multiplier_abs": (("point", "multiplier"), self.multipliers),
             "sequence": ("point", np.array(self.sequence, dtype=str)),
             "event_value": ("event", np.array([e["value"] for e in self.events], dtype=float),
                             {"units": parameter_units(self.parameter)}),
             "event_kind": ("event", np.array([e["change"] for e in self.events], dtype=str))},
            coords={"value": ("point", self.values, {"units": parameter_units(self.parameter),
                                                     "long_name": f"value of {self.parameter}"}),
                    "point": np.arange(self.values.size),
                    "dof": np.arange(self.x0.shape[1]),
                    "multiplier": np.arange(self.multipliers.shape[1]), "event": np.arange(len(self.events))},
            attrs={"parameter": self.parameter, "stopped": self.stopped, "forced": int(self.forced)})
        if self.psi0 is not None:
            ds["psi0"] = (("point", "state_variable"), self.psi0,
                          {"units": "1", "long_name": "state variable ln(V_0 theta / D_c) of each rate-and-state "
                                                      "contact, in order, at the start of the cycle"})
        return finish(ds, "system with frictional contacts: limit cycles along a parameter", "system")
