"""The stability of a travelling wave: Floquet multipliers of the discrete ring's wave.

The paper leaves the stability of its waves open. Here a wave in permanent contact (stick,
slip and reverse-slip zones, no separation) is followed onto the ring of ``N`` nodes (second-order
centred differences in ``theta``, as `wave_persistence` and `stickslip.brake.ring` discretise
[12]): with ``U = delta`` at every node, each node's ``V_j`` is a degree of freedom,

    V_j'' = a (V_{j+1} - 2 V_j + V_{j-1}) / dtheta^2 - h V_j + Q_j,

and its contact with the shaft (surface speed 1 in internal units) a frictional contact of a
`stickslip.system.System` whose normal force is the reaction of the constraint ``U = delta``,
``P_j = g delta - D (V_{j+1} - V_{j-1}) / (2 dtheta)`` (Coulomb, ``Q_j = s f P_j`` slipping,
``|Q_j| <= f P_j`` sticking). The ring is unchanged by the shift of one node, and the discrete
wave moves by one node in ``tau ~ dtheta/|c|``: it is a relative periodic orbit, found by Newton's
method from the sampled continuous wave (`stickslip.system.relative_cycle`), and its stability
is that of the node-shift map (saltation matrices at every node's switch): a perturbation grows
by ``|mu|^(N/n)`` over a wave period for each multiplier ``mu``. Repeated for growing ``N``, the
discrete wave speed tends to the continuous one (second order) and the leading multipliers
show whether the wave's stability converges (`wave_spectra`).

A wave that leaves the shaft (a separation zone) is followed onto the ring whose nodes may leave
it too (`ring_system(..., separation=True)`: the normal displacements are degrees of freedom, each
node's contact a rigid unilateral constraint that lifts off where its reaction reaches zero and
lands by a plastic impact with its friction impulse); the section is node 0's lift-off. There
the discrete wave lands into slip and sticks briefly where the continuous one lands into stick
(the landing's kink is not resolved by the nodes), and its speed tends to the continuous one at
first order only.

Internal units (`zones.Scaling`): time ``t/sqrt(gamma)``.
"""

from __future__ import annotations

import math
from dataclasses import dataclass
from typing import ClassVar

import numpy as np
import lazy_loader as lazy

from ...cf import finish
from ...errors import NoSolutionError, ParameterError
from ...friction import Coulomb
from ...quantities import BRAKE as Q, SYSTEM as SYSTEM_Q
from ...results import Result
from ...system import Contact, System, relative_cycle, simulate, without_own
from ...system.flow import OPEN
from ..reduced.params import BrakeParams
from .result import TravellingWave
from .stability import RingState, step_ring
from .zones import SEPARATION, STICK, Scaling

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["ring_system", "WaveSpectrum", "wave_spectrum", "wave_spectra", "sampled_ring", "moreau_difference"]


def ring_system(params, nodes: int, *, separation: bool = False) -> System:
    """The ring of ``nodes`` nodes in contact with the shaft (see the module), internal units.

    With ``separation`` the ring may leave the shaft: every node's normal displacement is a
    degree of freedom too, its gap ``u_j = U_j - delta`` (the first ``nodes`` of ``x``; the ``V_j``
    follow), with ``u_j'' = b (u_{j+1} - 2 u_j + u_{j-1}) / dtheta^2 + D (V_{j+1} - V_{j-1}) / (2 dtheta)
    - g (u_j + delta) + P_j``, and each node's contact a rigid unilateral constraint ``u_j >= 0``
    whose reaction is ``P_j`` (`stickslip.system.Contact` with ``rigid=True``): it lifts off where
    ``P_j`` reaches zero and lands by a plastic impact with its Coulomb friction impulse, as the
    Moreau runs of `wave_persistence` have it."""
    if not isinstance(params, BrakeParams):
        raise ParameterError("params", params, "BrakeParams (stickslip.brake.BrakeParams)")
    nodes = Q.check("spectrum_nodes", nodes, "nodes")
    if not isinstance(separation, (bool, np.bool_)):
        raise ParameterError("separation", separation, "True or False")
    sc = Scaling(params)
    co = sc.coefficients
    dth = 2.0 * math.pi / nodes
    eye = np.eye(nodes)
    laplacian = 2.0 * eye - np.roll(eye, 1, axis=1) - np.roll(eye, -1, axis=1)
    pressure = co.g * sc.delta
    if not pressure > 0:
        raise ParameterError("delta", params.delta, "> 0 (a ring pressed on the shaft)")
    law = Coulomb(params.friction, params.friction)
    if separation:
        grad = (np.roll(eye, 1, axis=1) - np.roll(eye, -1, axis=1)) / (2.0 * dth)  # (grad W)_j: centred
        K = np.block([[co.b * laplacian / dth**2 + co.g * eye, -co.D * grad],
                      [co.D * grad, co.a * laplacian / dth**2 + co.h * eye]])
        unit = np.eye(2 * nodes)
        contacts = [Contact(unit[nodes + j], None, law, 1.0, name=f"node {j}", normal_direction=unit[j], rigid=True)
                    for j in range(nodes)]
        return System(unit, K, contacts, force=np.concatenate([np.full(nodes, -pressure), np.zeros(nodes)]))
    sign = 1.0 if co.D >= 0 else -1.0
    contacts = []
    for j in range(nodes):
        grad = sign * (eye[(j + 1) % nodes] - eye[j - 1])  # P_j = g delta - |D| grad . V / (2 dtheta)
        contacts.append(Contact(eye[j], pressure, law, 1.0, name=f"node {j}", normal_direction=grad,
                                normal_stiffness=abs(co.D) / (2.0 * dth), normal_on_structure=False))
    return System(eye, co.a * laplacian / dth**2 + co.h * eye, contacts)


def sampled_ring(wave, nodes: int) -> tuple[np.ndarray, np.ndarray, np.ndarray]:
    """``(x0, v0, off)``: the continuous ``wave`` sampled at the middles of ``nodes`` cells, as the
    state of `ring_system` (with the gaps ``u = U - delta`` first when the wave separates: 0 in
    contact) and which nodes are in its separation zones."""
    nodes = _checked(wave, nodes)
    sc = Scaling(wave.params)
    c, r = float(wave.x[0]), sc.root_gamma
    dth = 2.0 * math.pi / nodes
    prof = wave.evaluate(dth * np.arange(nodes) + 0.5 * dth)  # off the switching point at phi = 0
    off = np.isin(prof["zone"], [i for i, z in enumerate(wave.zones) if z.kind == SEPARATION])
    x0, v0 = prof["V"] / r, -c * prof["dV"] / r
    if any(z.kind == SEPARATION for z in wave.zones):
        x0 = np.concatenate([np.where(off, np.maximum(prof["U"] / r - sc.delta, 0.0), 0.0), x0])
        v0 = np.concatenate([np.where(off, -c * prof["dU"] / r, 0.0), v0])
    return x0, v0, off


def moreau_difference(wave, nodes: int = 64, steps=(4000, 8000, 16000), fraction: float = 0.5) -> np.ndarray:
    """The ring whose nodes may leave the shaft, from the sampled separating ``wave`` over ``fraction``
    of a wave period, event-driven against the Moreau stepper of `wave_persistence` (`step_ring`,
    written apart) with each of ``steps``: the largest difference of the end states, relative to
    the largest entry of the event-driven one."""
    nodes = _checked(wave, nodes)
    sc = Scaling(wave.params)
    if not any(z.kind == SEPARATION for z in wave.zones):
        raise ParameterError("wave", wave.structure, "a wave that separates from the shaft")
    if isinstance(steps, (str, bytes)) or not hasattr(steps, "__len__") or not 1 <= len(steps) <= 16 or not all(
            isinstance(k, (int, np.integer)) and not isinstance(k, bool) and 1 <= k <= 10**7 for k in steps):
        raise ParameterError("steps", steps, "a list of 1 to 16 whole numbers of Moreau steps, each 1 to 1e7")
    if isinstance(fraction, bool) or not isinstance(fraction, (int, float)) or not 0 < fraction <= 10:
        raise ParameterError("fraction", fraction, "in (0, 10] wave periods")
    x0, v0, _ = sampled_ring(wave, nodes)
    t_end = fraction * (2.0 * math.pi / wave.n) / abs(float(wave.x[0]))
    run = simulate(ring_system(wave.params, nodes, separation=True), x0, v0, t_end, samples=2)
    exact = np.concatenate([run.x[-1], run.v[-1]])
    out = []
    for k in steps:
        st = RingState(x0[:nodes] + sc.delta, x0[nodes:].copy(), v0[:nodes].copy(), v0[nodes:].copy())
        step_ring(st, sc.coefficients, sc.delta, wave.params.friction, 2.0 * math.pi / nodes, t_end / k, k)
        out.append(np.abs(np.concatenate([st.U - sc.delta, st.V, st.dU, st.dV]) - exact).max() / np.abs(exact).max())
    return np.array(out)


@dataclass(frozen=True, repr=False)
class WaveSpectrum(Result):
    """The multipliers of a wave's node-shift map on a ring of ``nodes`` nodes.

    ``shift_time`` (internal time for one node), ``continuous_shift_time`` (``dtheta/|c|`` of
    the continuous wave), ``multipliers`` (by decreasing size; one is 1, the wave's own motion),
    and ``n`` waves around the ring."""

    MODEL: ClassVar[str] = "brake"

    nodes: int
    n: int
    shift_time: float
    continuous_shift_time: float
    multipliers: np.ndarray
    events_per_shift: int
    separation: bool = False

    @property
    def leading(self) -> complex:
        """The largest multiplier but the wave's own (the one nearest 1)."""
        return complex(without_own(self.multipliers)[0])

    @property
    def growth_per_period(self) -> float:
        """``ln|mu| N/n`` of the leading multiplier: the log of a perturbation's growth over one
        wave period (> 0: unstable)."""
        return math.log(abs(self.leading)) * self.nodes / self.n if self.leading else -math.inf

    @property
    def stable(self) -> bool:
        return abs(self.leading) < 1.0

    def to_dict(self) -> dict:
        return {"nodes": self.nodes, "n": self.n, "stable": self.stable, "growth_per_period": self.growth_per_period,
                "leading_abs": abs(self.leading), "shift_time": self.shift_time,
                "continuous_shift_time": self.continuous_shift_time, "events_per_shift": self.events_per_shift,
                "separates": self.separation,
                "multipliers_abs": np.abs(self.multipliers[:12]).tolist()}

    def to_xarray(self) -> xr.Dataset:
        m = self.multipliers
        ds = xr.Dataset({"multiplier_real": ("multiplier", m.real, {"units": "1", "long_name": "multiplier (real part)"}),
                         "multiplier_imag": ("multiplier", m.imag, {"units": "1",
                                                                    "long_name": "multiplier (imaginary part)"})},
                        coords={"multiplier": ("multiplier", np.arange(m.size), {"units": "1",
                                                                               "long_name": "multiplier number"})},
                        attrs={"nodes": self.nodes, "n": self.n, "shift_time": self.shift_time,
                               "continuous_shift_time": self.continuous_shift_time, "stable": int(self.stable),
                               "separates": int(self.separation),
                               "growth_per_period": self.growth_per_period})
        return finish(ds, "multipliers of a travelling wave's node-shift map on the discrete ring", "brake")


def _checked(wave, nodes) -> int:
    """``nodes`` checked for ``wave`` (a `TravellingWave`): a declared count, a multiple of its mode number."""
    if not isinstance(wave, TravellingWave):
        raise ParameterError("wave", wave, "a TravellingWave (stickslip.brake.travelling_wave)")
    nodes = Q.check("spectrum_nodes", nodes, "nodes")
    if nodes % wave.n:
        raise ParameterError("nodes", nodes, f"a multiple of the mode number n = {wave.n}")
    return nodes


def wave_spectrum(wave, nodes: int = 128, tol: float = 1e-10, max_iter: int = 200) -> WaveSpectrum:
    """The discrete ring's wave near ``wave`` (a `TravellingWave`; one that separates from the shaft
    on the ring whose nodes may leave it too) on ``nodes`` nodes (a multiple of ``wave.n``) and the
    multipliers of its node-shift map; ``max_iter`` returns of the map at most (iterations and
    Newton steps: a marginal wave near a grazing contact may take dozens, a minute each at 128 nodes)."""
    nodes, tol = _checked(wave, nodes), SYSTEM_Q.check("tol", tol)
    max_iter = Q.check("max_iter", max_iter)
    separates = any(z.kind == SEPARATION for z in wave.zones)
    if not separates and not any(z.kind == STICK for z in wave.zones):
        raise ParameterError("wave", wave.structure, "a wave with a stick zone (its onset is the map's section) or "
                             "a separation zone (its lift-off is)")
    system = ring_system(wave.params, nodes, separation=separates)
    c = float(wave.x[0])
    dth = 2.0 * math.pi / nodes
    direction = 1 if c > 0 else -1  # the wave moves to larger theta for c > 0
    shift = (np.arange(nodes) + direction) % nodes
    period = (2.0 * math.pi / wave.n) / abs(c)
    x0, v0, _ = sampled_ring(wave, nodes)
    section = OPEN if separates else 0  # a separating wave: node 0's lift-off; else its stick onset
    if separates:
        shift = np.concatenate([shift, nodes + shift])
    try:
        cycle = relative_cycle(system, x0, v0, shift, contact=0, state=section, horizon=1.5 * period, tol=tol,
                               max_iter=max_iter)
    except NoSolutionError as err:
        raise NoSolutionError(f"no wave of the ring of {nodes} nodes near the continuous one ({err})") from None
    if not separates and np.any(cycle.event_state == OPEN):
        raise NoSolutionError(f"the ring's wave on {nodes} nodes leaves the shaft (a normal force reached zero) "
                              "although the continuous one does not")
    return WaveSpectrum(nodes, int(wave.n), cycle.shift_time, dth / abs(c), cycle.multipliers,
                        int(cycle.event_time.size), separates)


def wave_spectra(wave, nodes=(64, 128, 256), tol: float = 1e-10) -> xr.Dataset:
    """`wave_spectrum` for each of ``nodes``: the convergence table (shift time against the
    continuous wave's, leading multiplier, growth per period, observed order of the shift
    time's error), as a dataset over ``nodes``."""
    if isinstance(nodes, (str, bytes)) or not hasattr(nodes, "__len__") or not 1 <= len(nodes) <= 16:
        raise ParameterError("nodes", nodes, "a list of 1 to 16 node counts")
    out = [wave_spectrum(wave, k, tol) for k in nodes]
    err = np.array([abs(s.shift_time / s.continuous_shift_time - 1.0) for s in out])
    order = np.full(len(out), np.nan)
    for i in range(1, len(out)):
        if err[i] > 0 and err[i - 1] > 0:
            order[i] = math.log(err[i - 1] / err[i]) / math.log(out[i].nodes / out[i - 1].nodes)
    lead = np.array([s.leading for s in out])
    ds = xr.Dataset(
        {"shift_time": ("nodes", [s.shift_time for s in out], {"units": "1", "long_name": "time to move one node"}),
         "speed_error": ("nodes", err, {"units": "1", "long_name": "|shift time / (dtheta/|c|) - 1|"}),
         "observed_order": ("nodes", order, {"units": "1", "long_name": "observed order of the speed error"}),
         "leading_abs": ("nodes", np.abs(lead), {"units": "1", "long_name": "|leading multiplier|"}),
         "leading_angle": ("nodes", np.angle(lead), {"units": "rad", "long_name": "argument of the leading multiplier"}),
         "growth_per_period": ("nodes", [s.growth_per_period for s in out],
                               {"units": "1", "long_name": "log growth of a perturbation over a wave period"}),
         "stable": ("nodes", np.array([s.stable for s in out], dtype=np.int8), {"units": "1",
                                                                                "long_name": "1 if stable"})},
        coords={"nodes": ("nodes", np.array([s.nodes for s in out]), {"units": "1", "long_name": "ring nodes"})},
        attrs={"c": float(wave.c), "n": int(wave.n), "structure": wave.structure})
    return finish(ds, "convergence of a travelling wave's multipliers with the ring's nodes", "brake",
                  params=wave.params.to_attrs())
