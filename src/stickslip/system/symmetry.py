"""Waves on structures of identical cells: relative periodic orbits and their stability.

A structure unchanged when its degrees of freedom are renumbered by a permutation ``G`` (a
ring of ``N`` identical nodes and its shift by one node; a periodic chain) can carry a wave: a
motion that, a time ``tau`` later, is the same motion moved by one cell, ``z(t + tau) = G z(t)``.
Such a wave is a fixed point of the map from an event of one contact (entering a state) to the
same event of its image under ``G``, the state there mapped back by ``G^-1``; `relative_cycle`
finds it by Newton's method on that map (`return_fixed_point`). Its stability is that of the map:
the multipliers ``mu`` of ``G^-1 Phi(tau)``, with ``Phi`` the monodromy over ``tau`` (saltation
matrices at every event, the events of contacts the symmetry switches together included), one
of them 1 (the wave's own motion), a 0 per contact that sticks. A perturbation then grows at
the rate ``ln|mu| / tau`` per unit time: the Floquet exponents of the wave, whose whole period
(a wavelength of ``m`` cells) has the multipliers ``mu^m`` up to phases, at a cost of ``1/m``
of it. The wave is stable when every multiplier but the one at 1 lies inside the unit circle.
"""

from __future__ import annotations

import math
from dataclasses import dataclass

import numpy as np
import lazy_loader as lazy

from ..errors import NoSolutionError, ParameterError
from ..quantities import SYSTEM as Q
from ..results import Result
from .floquet import cycle_dataset, entries, monodromy, period_events, return_fixed_point, without_own
from .flow import shares_flows
from .model import System
from .simulate import simulate

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["cell_symmetry", "RelativeCycle", "relative_cycle"]


def cell_symmetry(system: System, shift) -> np.ndarray:
    """The contacts' permutation under the renumbering ``shift`` of the degrees of freedom (dof
    ``i`` becomes ``shift[i]``): contact ``i`` becomes contact ``image[i]``. A `ParameterError`
    naming ``shift`` if it is not a permutation or the system is not unchanged by it (its
    matrices, force and contacts)."""
    if not isinstance(system, System):
        raise ParameterError("system", system, "a stickslip.system.System")
    n = system.dofs
    try:
        p = np.asarray(shift)
        ok = p.shape == (n,) and np.issubdtype(p.dtype, np.integer) and np.array_equal(np.sort(p), np.arange(n))
    except (TypeError, ValueError):
        ok = False
    if not ok:
        raise ParameterError("shift", shift, f"a permutation of the {n} degrees of freedom (0 to {n - 1}, each once)")
    inv = np.argsort(p)
    for name in ("mass", "stiffness", "damping"):
        m = getattr(system, name)
        if not np.allclose(m[np.ix_(p, p)], m, rtol=1e-12, atol=1e-12 * (np.abs(m).max() or 1.0)):
            raise ParameterError("shift", _short(p), f"a symmetry of the system (its {name} matrix changes)")
    if not np.allclose(system.force[p], system.force, rtol=1e-12, atol=0.0):
        raise ParameterError("shift", _short(p), "a symmetry of the system (its force changes)")
    image = np.full(len(system.contacts), -1)
    for i, c in enumerate(system.contacts):
        moved = c.direction[inv], None if c.normal_direction is None else c.normal_direction[inv]
        for j, d in enumerate(system.contacts):
            if _same(c, d) and np.array_equal(d.direction, moved[0]) and (
                    (d.normal_direction is None) == (moved[1] is None)) and (
                    moved[1] is None or np.array_equal(d.normal_direction, moved[1])):
                image[i] = j
                break
        else:
            raise ParameterError("shift", _short(p), f"a symmetry of the system (contact {i} has no identical "
                                                     "contact where the renumbering moves it)")
    return image


def _same(c, d) -> bool:
    return (c.friction == d.friction and c.normal_force == d.normal_force and c.surface_speed == d.surface_speed
            and c.normal_stiffness == d.normal_stiffness and c.normal_on_structure == d.normal_on_structure
            and c.rigid == d.rigid)


def _short(p: np.ndarray) -> str:
    text = ", ".join(map(str, p[:6]))
    return f"[{text}{', ...' if p.size > 6 else ''}]"


@dataclass(frozen=True, eq=False, repr=False)
class RelativeCycle(Result):
    """A wave moving by one cell in ``shift_time``: the state ``x0``, ``v0`` just after contact
    ``contact`` entered ``state`` (every contact's state ``states``), the ``multipliers`` of the
    map over one cell (by decreasing size) and the events within it."""

    shift_time: float
    x0: np.ndarray
    v0: np.ndarray
    contact: int
    state: int
    states: tuple
    multipliers: np.ndarray
    event_time: np.ndarray
    event_contact: np.ndarray
    event_state: np.ndarray
    MODEL = "system"

    @property
    def growth_rates(self) -> np.ndarray:
        """``ln|mu| / tau`` of each multiplier [1/s] (``-inf`` for a multiplier 0)."""
        with np.errstate(divide="ignore"):
            return np.log(np.abs(self.multipliers)) / self.shift_time

    @property
    def leading(self) -> complex:
        """The largest multiplier but the wave's own (the one nearest 1)."""
        others = without_own(self.multipliers)
        return complex(others[0]) if others.size else 0.0

    @property
    def stable(self) -> bool:
        return abs(self.leading) < 1.0

    def to_dict(self) -> dict:
        return {"shift_time": self.shift_time, "stable": self.stable, "leading_abs": abs(self.leading),
                "leading_growth_rate": math.log(abs(self.leading)) / self.shift_time if self.leading else -math.inf,
                "multipliers_abs": np.abs(self.multipliers[:16]).tolist(), "events": int(self.event_time.size)}

    def to_xarray(self) -> xr.Dataset:
        return cycle_dataset(self, {"shift_time": self.shift_time},
                             "system with frictional contacts: wave moving by one cell, its multipliers")


@shares_flows
def relative_cycle(system: System, x0, v0, shift, *, contact: int, state: int, states=None, horizon: float,
                   tol: float = 1e-10, max_iter: int = 50) -> RelativeCycle:
    """The wave near the motion from ``(x0, v0)`` (contact ``states`` as `simulate` takes them)
    that moves by one cell of the symmetry ``shift`` (see `cell_symmetry`) between two events
    of contact ``contact`` entering ``state`` and of its image. The first such event within
    ``horizon`` seconds of the start is the section; Newton's method on the map (a near guess
    is needed: an unstable wave repels the iterates) until it returns to ``tol`` (relative)."""
    image = cell_symmetry(system, shift)
    system.unforced("a wave moving by one cell")
    n = system.dofs
    k = len(system.contacts)
    if isinstance(contact, bool) or not isinstance(contact, (int, np.integer)) or not 0 <= contact < k:
        raise ParameterError("contact", contact, f"a contact number from 0 to {k - 1}")
    if state not in (-1, 0, 1, 2) or (state == 2 and not system.contacts[contact].unilateral):
        raise ParameterError("state", state, "-1 (reverse slip), 0 (stick), 1 (slip) or, for a unilateral contact, "
                             "2 (open)")
    horizon, tol, max_iter = Q.check("transient", horizon, "horizon"), Q.check("tol", tol), Q.check("max_iter", max_iter)
    run = simulate(system, x0, v0, horizon, samples=2, segments=True, states=states, stop_at=(contact, state))
    first = entries(run, (contact, state))
    if not first:
        raise NoSolutionError(f"contact {contact} did not enter state {state} within horizon = {horizon:g} s")
    p = np.asarray(shift)
    back = np.concatenate([p, n + p])
    tau, z, start, segments = return_fixed_point(system, first[0][1], first[0][3], (int(contact), int(state)), horizon,
                                                 tol, max_iter, symmetry=(int(image[contact]), back, image),
                                                 newton_after=0)
    mult = np.linalg.eigvals(monodromy(system, segments)[back])
    mult = mult[np.argsort(-np.abs(mult))]
    return RelativeCycle(tau, z[:n], z[n:2 * n], int(contact), int(state), start, mult,
                         *period_events(system, z, start, tau))
