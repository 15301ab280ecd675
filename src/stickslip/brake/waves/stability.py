"""Do travelling waves persist? A first, numerical approach to their stability.

The paper lists the stability of the waves as open. What is done here is numerical
evidence, not a proof: the reduced equations [12] are integrated on the ring from the
wave itself (sampled on ``N`` nodes) and from the wave plus a small perturbation, with a
Moreau-type time-stepping scheme (method of lines, second-order centred differences in
``theta``; per node a velocity impulse enforces ``U >= delta`` at the end of the step,
so contact is persistent and impacts are perfectly inelastic, and a Coulomb impulse
``|p_T| <= f p_N`` makes the node stick, ``V_t = 1``, or slide). Two numbers are measured
once per wave period:

* ``drift``: distance (after the best shift in ``theta``) between the discrete solution
  started on the wave and the exact travelling wave, relative to the wave's amplitude.
  It stays at the level of the discretisation error if the wave persists;
* ``separation_of_runs``: distance between the perturbed and unperturbed runs (best
  shift), relative to the initial perturbation. Its growth rate estimates the largest
  Lyapunov (Floquet) exponent of the wave, with the translation direction removed.

Units are internal (`zones.Scaling`: coefficients at ``gamma = 1``, time
``tau = t/sqrt(gamma)``, in which the shaft surface speed is still 1).
"""

from __future__ import annotations

from typing import ClassVar

import math
from dataclasses import dataclass

import numpy as np
import lazy_loader as lazy

from ...results import Result
from ...cf import finish
from ...quantities import BRAKE as Q
from ...errors import ParameterError
from .zones import Scaling
from ... import validation as check

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["RingState", "step_ring", "WavePersistence", "wave_persistence"]


@dataclass
class RingState:
    """Nodal displacements and velocities (internal units)."""

    U: np.ndarray
    V: np.ndarray
    dU: np.ndarray
    dV: np.ndarray


def _accel(st, coef, dth):
    lap = lambda W: (np.roll(W, -1) - 2 * W + np.roll(W, 1)) / dth**2  # noqa: E731
    grad = lambda W: (np.roll(W, -1) - np.roll(W, 1)) / (2 * dth)  # noqa: E731
    aU = coef.b * lap(st.U) + coef.D * grad(st.V) - coef.g * st.U
    aV = coef.a * lap(st.V) - coef.D * grad(st.U) - coef.h * st.V
    return aU, aV


def step_ring(st: RingState, coef, delta, friction, dth, dt, nsteps):
    """Advance ``nsteps`` steps in place; returns the node states of the last step.

    States: 0 stick, 1 slip, -1 reverse slip, 2 separation.
    """
    state = np.zeros(st.U.shape, dtype=int)
    for _ in range(nsteps):
        aU, aV = _accel(st, coef, dth)
        vU, vV = st.dU + dt * aU, st.dV + dt * aV
        gap = st.U + dt * vU - delta
        pN = np.where(gap < 0.0, -gap / dt, 0.0)  # velocity impulse: U(t + dt) = delta
        vU = vU + pN
        slip = 1.0 - vV  # slip velocity before friction
        stick = (pN > 0.0) & (np.abs(slip) <= friction * pN)
        vV = np.where(stick, 1.0, vV + friction * pN * np.sign(slip))
        st.U, st.V, st.dU, st.dV = st.U + dt * vU, st.V + dt * vV, vU, vV
        state = np.where(pN > 0.0, np.where(stick, 0, np.sign(slip).astype(int)), 2)
    return state


def _aligned_distance(A, B):
    """``min_s |A(theta) - B(theta - s)|_2`` over whole-node shifts (FFT), and the shift."""
    corr = np.real(np.fft.ifft(np.fft.fft(A) * np.conj(np.fft.fft(B))))
    k = int(np.argmax(corr))
    return float(np.linalg.norm(A - np.roll(B, k))), k


@dataclass(frozen=True, repr=False)
class WavePersistence(Result):
    """Result of `wave_persistence` (internal time ``tau = t/sqrt(gamma)``)."""

    MODEL: ClassVar[str] = "brake"

    time: np.ndarray
    drift: np.ndarray
    separation_of_runs: np.ndarray
    lag: np.ndarray
    stick_fraction: np.ndarray
    wave_stick_fraction: float
    growth_rate: float
    nodes: int

    def to_dict(self) -> dict:
        return {"persists": self.persists, "growth_rate": float(self.growth_rate), "max_drift": float(np.max(self.drift)),
                "wave_stick_fraction": float(self.wave_stick_fraction), "nodes": int(self.nodes),
                "duration": float(self.time[-1]) if self.time.size else 0.0}

    @property
    def persists(self) -> bool:
        """The run stays within 5 % of the exact wave (after the best shift) throughout."""
        return bool(np.max(self.drift) < 0.05)

    def to_xarray(self) -> xr.Dataset:
        ds = xr.Dataset(
            {"drift": ("time", self.drift, {"units": "1", "long_name": "distance to the exact wave / amplitude"}),
             "separation_of_runs": ("time", self.separation_of_runs,
                                    {"units": "1", "long_name": "perturbed - unperturbed (aligned) / initial perturbation"}),
             "lag": ("time", self.lag, {"units": "rad", "long_name": "phase lag behind the exact wave"}),
             "stick_fraction": ("time", self.stick_fraction, {"units": "1",
                                                              "long_name": "fraction of the ring nodes in stick"})},
            coords={"time": ("time", self.time, {"units": "1", "long_name": "time tau = t / sqrt(gamma)"})},
            attrs={"growth_rate": self.growth_rate, "persists": int(self.persists), "nodes": self.nodes,
                   "wave_stick_fraction": self.wave_stick_fraction})
        return finish(ds, "persistence of a travelling wave in the ring", "brake")


def wave_persistence(wave, nodes: int = 512, periods: int = 30, perturbation: float = 1e-4,
                     cfl: float = 0.25, seed: int = 0) -> WavePersistence:
    """Integrate the ring from a wave, with and without a perturbation (see module doc).

    Parameters
    ----------
    wave : TravellingWave
    nodes : int
        Ring nodes ``N`` (a multiple of ``wave.n``).
    periods : int
        Duration in wave periods ``(2 pi/n)/|c|``.
    perturbation : float
        Size of the random low-mode perturbation of ``V`` and ``V_t``, relative to the
        wave's tangential amplitude.
    cfl : float
        ``dt sqrt(a) / dtheta`` (``<= 0.5``).
    """
    from .result import TravellingWave
    
    check.instance("wave", wave, TravellingWave, "a stickslip.brake.TravellingWave")
    nodes, periods = Q.check("nodes", nodes), Q.check("periods", periods)
    if nodes % wave.n:
        raise ParameterError("nodes", nodes, f"a multiple of the mode number n = {wave.n}")
    cfl = Q.check("cfl", cfl)
    sc = Scaling(wave.params)
    coef, delta, f, c = sc.coefficients, sc.delta, wave.params.friction, wave.x[0]
    r = sc.root_gamma
    theta = 2 * np.pi * np.arange(nodes) / nodes
    dth = theta[1]
    prof = wave.evaluate(theta)
    U, V, dU, dV = (prof[k] / r for k in ("U", "V", "dU", "dV"))
    amp = float(np.ptp(V)) or 1.0
    base = RingState(U.copy(), V.copy(), -c * dU, -c * dV)
    rng = np.random.default_rng(seed)
    pert = sum(rng.normal() * np.sin(m * theta + rng.uniform(0, 2 * np.pi)) for m in (1, 2, 3))
    pert *= perturbation * amp / np.max(np.abs(pert))
    other = RingState(U.copy(), V + pert, -c * dU, -c * dV + c * pert / amp)
    dt = cfl * dth / math.sqrt(coef.a)
    t_wave = (2 * np.pi / wave.n) / abs(c)
    per = max(1, int(round(t_wave / dt)))
    dt = t_wave / per
    eps0 = np.linalg.norm(np.concatenate([other.U - base.U, other.V - base.V])) or 1.0
    times, drift, sep, lag, stick = [0.0], [0.0], [1.0], [0.0], [float("nan")]
    span = nodes // wave.n
    for k in range(1, periods + 1):
        state = step_ring(base, coef, delta, f, dth, dt, per)
        step_ring(other, coef, delta, f, dth, dt, per)
        t = k * t_wave
        exact = wave.evaluate(theta - c * t)["V"] / r  # the exact wave at time t
        d, shift = _aligned_distance(base.V, exact)
        drift.append(d / (amp * math.sqrt(nodes)))
        lag.append((((shift + span // 2) % span) - span // 2) * dth)  # wrapped to half a wavelength
        d2, _ = _aligned_distance(np.concatenate([other.U, other.V]), np.concatenate([base.U, base.V]))
        sep.append(d2 / eps0)
        stick.append(float(np.mean(state == 0)))
        times.append(t)
    times, sep = np.asarray(times), np.asarray(sep)
    # growth phase: after the first period, before the runs differ by 10 % of the wave
    limit = 0.1 * amp * math.sqrt(nodes) / eps0
    grow = (np.arange(len(times)) >= 1) & (sep > 0) & (np.maximum.accumulate(sep) < limit)
    rate = float(np.polyfit(times[grow], np.log(sep[grow]), 1)[0]) if grow.sum() > 2 else float("nan")
    wave_stick = sum(z.length for z in wave.zones if z.kind == "stick") / wave.period
    return WavePersistence(times, np.asarray(drift), sep, np.asarray(lag), np.asarray(stick), wave_stick,
                           rate, nodes)
