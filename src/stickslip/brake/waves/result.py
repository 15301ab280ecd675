"""The result object of the travelling-wave solver: zones, profiles, exports.

A `TravellingWave` holds the solution of the multiple-shooting system (`boundsco`)
for one zone sequence, in internal units (`zones.Scaling`), and converts to the
paper's dimensionless units on output (``evaluate``, ``to_dict``, ``to_xarray``).
"""

from __future__ import annotations

from typing import ClassVar

import math
from dataclasses import dataclass, field

import numpy as np
import lazy_loader as lazy

from ...results import Result
from ...cf import finish
from ...validation import real_array
from ..reduced.params import BrakeParams
from .boundsco import Layout, passed
from .zones import KINDS, REVERSE, SEPARATION, SLIP, STICK, Scaling, ZoneFlows
from ...errors import ParameterError

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["Zone", "TravellingWave", "REGIMES", "regime_name"]

#: Regime names (the set of zone kinds in a period), as in the paper.
REGIMES = {
    frozenset({STICK, SLIP}): "stick-slip",
    frozenset({STICK, SLIP, SEPARATION}): "stick-slip-separation",
    frozenset({STICK, SEPARATION}): "stick-separation",
    frozenset({STICK, SLIP, REVERSE}): "stick-slip-reverse-slip",
    frozenset({STICK, SLIP, SEPARATION, REVERSE}): "stick-slip-separation-reverse-slip",
}


def regime_name(kinds) -> str:
    """Paper's name of a regime from its zone kinds (order-free)."""
    try:
        kinds = frozenset(kinds) if not isinstance(kinds, (str, bytes)) else None
    except TypeError:
        kinds = None
    if kinds is None:
        raise ParameterError("kinds", kinds, "a collection of zone kinds (" + ", ".join(KINDS) + ")")
    key = frozenset(kinds)
    return REGIMES.get(key, "-".join(k for k in KINDS if k in key))


@dataclass(frozen=True, repr=False)
class Zone(Result):
    """One zone of a period: ``kind`` on ``start <= phi < end``."""

    MODEL: ClassVar[str] = "brake"

    kind: str
    start: float
    end: float

    @property
    def length(self) -> float:
        return self.end - self.start

    def to_dict(self) -> dict:
        return {"kind": self.kind, "start": float(self.start), "end": float(self.end)}


@dataclass(frozen=True, repr=False)
class TravellingWave(Result):
    """A travelling wave of [15] and its verification.

    Attributes
    ----------
    params : BrakeParams
    n : int
        Number of waves around the ring (period ``2 pi/n`` in ``phi``).
    c : float
        Wave speed (``theta`` per unit ``t = Omega t̄``); ``phi = theta - c t``.
    zones : tuple of Zone
        The zones of one period in ``phi`` order; ``phi = 0`` is the start of a stick zone.
    residual : float
        Largest absolute residual of the multiple-shooting equations (internal units).
    margins : dict
        Worst relative margin of each inequality on a fine grid (see `boundsco.verify`).
    """

    MODEL: ClassVar[str] = "brake"

    params: BrakeParams
    n: int
    c: float
    zones: tuple
    residual: float
    margins: dict
    layout: Layout = field(repr=False)
    x: np.ndarray = field(repr=False)

    # --- summary -----------------------------------------------------------------------
    @property
    def regime(self) -> str:
        return regime_name(z.kind for z in self.zones)

    @property
    def structure(self) -> str:
        """Zone sequence in ``phi`` order, e.g. ``"stick|slip|separation|slip"``."""
        return "|".join(z.kind for z in self.zones)

    @property
    def period(self) -> float:
        return 2.0 * math.pi / self.n

    @property
    def valid(self) -> bool:
        return passed(self.margins)

    @property
    def wave_speed_si(self) -> float:
        """Angular phase speed ``c Omega`` [rad/s] (``nan`` without physical parameters)."""
        return self.c * self.params.omega

    @property
    def _scaling(self) -> Scaling:
        return Scaling(self.params)

    def _flows(self) -> ZoneFlows:
        sc = self._scaling
        return ZoneFlows(sc.coefficients, self.params.friction, sc.delta, self.x[0])

    @property
    def _starts(self):
        return self.layout.unpack(self.x, self._scaling.delta)[2]

    # --- profiles ----------------------------------------------------------------------
    def evaluate(self, phi) -> dict:
        """The wave at ``phi`` (any real values; the wave is ``2 pi/n``-periodic).

        Returns a dict of arrays: ``U, V, dU, dV`` (``U' = dU/dphi``, ...), ``P, Q``,
        ``slip_velocity`` (``1 - V_t = 1 + c V'``; 0 in stick), ``zone`` (index into
        ``zones``). At a switching point the zone that starts there is used.
        """
        phi = real_array("phi", phi)
        local = np.mod(phi, self.period)
        bounds = np.array([z.start for z in self.zones])
        idx = np.clip(np.searchsorted(bounds, local, side="right") - 1, 0, len(self.zones) - 1)
        fl, starts, r = self._flows(), self._starts, self._scaling.root_gamma
        Y = np.empty(local.shape + (4,))
        P, Q = np.empty(local.shape), np.empty(local.shape)
        for i, (z, y0) in enumerate(zip(self.zones, starts)):
            sel = idx == i
            if np.any(sel):
                Yi = fl.flow(z.kind, y0, local[sel] - z.start)
                Y[sel], P[sel], Q[sel] = Yi, fl.pressure(z.kind, Yi), fl.traction(z.kind, Yi)
        w = fl.slip_velocity(Y)
        w = np.where(np.isin(idx, [i for i, z in enumerate(self.zones) if z.kind == STICK]), 0.0, w)
        return {"U": r * Y[..., 0], "dU": r * Y[..., 1], "V": r * Y[..., 2], "dV": r * Y[..., 3],
                "P": P / r, "Q": Q / r, "slip_velocity": w, "zone": idx}

    def impacts(self) -> list[dict]:
        """Landings (end of a separation zone in time order): position and impulses.

        ``normal_impulse = (c^2 - b)[U']`` and ``tangential_impulse = (c^2 - a)[V']``
        (jumps in ``phi`` order; Dirac masses of ``P`` and ``Q`` in ``phi``).
        """
        fl, starts, r = self._flows(), self._starts, self._scaling.root_gamma
        out, m = [], len(self.zones)
        for i in range(m):
            j = (i + 1) % m
            k1, k2 = self.zones[i].kind, self.zones[j].kind
            early = k1 if self.layout.direction > 0 else k2
            if SEPARATION in (k1, k2) and early == SEPARATION:
                y1 = fl.flow(k1, starts[i], np.array(self.zones[i].length))
                Pi, Q_Pi = fl.impulses(y1, starts[j])
                out.append({"phi": float(self.zones[i].end % self.period), "normal_impulse": float(Pi / r),
                            "tangential_impulse": float(Q_Pi / r), "into": (k2 if early == k1 else k1)})
        return out

    def to_dict(self) -> dict:
        """JSON-ready summary (keys ``c``, ``regime``, ``zones``, ``n``, ...)."""
        prof = self.evaluate(np.linspace(0.0, self.period, 2001))
        out = {"c": float(self.c), "regime": self.regime, "zones": [z.to_dict() for z in self.zones],
               "n": int(self.n), "period": self.period, "structure": self.structure,
               "valid": bool(self.valid), "residual": float(self.residual),
               "checks": {k: float(v) for k, v in self.margins.items()},
               "U_max": float(prof["U"].max()), "P_max": float(prof["P"].max()),
               "V_min": float(prof["V"].min()), "V_max": float(prof["V"].max()),
               "impacts": self.impacts(), "params": self.params.to_dict()}
        if math.isfinite(self.wave_speed_si):
            out["wave_speed_si"] = float(self.wave_speed_si)
        return out

    def to_xarray(self, num: int = 2001) -> xr.Dataset:
        """Profiles over one period, with ``phi`` as the dimension and units in attrs."""
        phi = np.linspace(0.0, self.period, int(num))
        prof = self.evaluate(phi)
        meta = {"U": ("radial displacement U at r = 1", "R"), "V": ("tangential displacement V at r = 1", "R"),
                "dU": ("dU/dphi", "R/rad"), "dV": ("dV/dphi", "R/rad"),
                "P": ("contact pressure P = p/M (eq. [12])", "E/M"), "Q": ("friction traction Q = q/M", "E/M"),
                "slip_velocity": ("slip velocity 1 - V_t over the shaft speed", "1"),
                "zone": ("index of the zone", "1")}
        ds = xr.Dataset({k: ("phi", prof[k], {"long_name": ln, "units": u}) for k, (ln, u) in meta.items()},
                        coords={"phi": ("phi", phi, {"long_name": "phi = theta - c t", "units": "rad"})})
        ds["zone"].attrs.update({"long_name": "index of the zone (zone_index)"})
        ds["zone_kind"] = ("zone_index", [z.kind for z in self.zones], {"long_name": "kind of the zone"})
        ds["zone_start"] = ("zone_index", [z.start for z in self.zones], {"units": "rad"})
        ds["zone_end"] = ("zone_index", [z.end for z in self.zones], {"units": "rad"})
        ds.coords["zone_index"] = ("zone_index", np.arange(len(self.zones)), {"units": "1",
                                                                            "long_name": "zone number"})
        ds.attrs.update({"c": float(self.c), "n": int(self.n), "regime": self.regime,
                         "structure": self.structure, "residual": float(self.residual), "valid": int(self.valid),
                         "source": "paper eqs. [14]-[20], closed-form zones + multiple shooting"})
        return finish(ds, "travelling stick-slip wave of the reduced model", "brake", params=self.params.to_attrs())
