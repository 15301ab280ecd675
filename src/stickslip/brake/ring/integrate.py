"""Time integration of the reduced model [12] on the ring, from a perturbed steady state.

`integrate` advances the explicit scheme of `brake.ring.scheme` (centred differences in
``theta``, explicit Newmark / central differences in time, forward-increment Lagrange
multipliers for contact and Coulomb friction, node by node) and records, with the run
books of `stickslip.contact.runs`,

* a time series every ``1/samples_per_transit`` of a wave transit: energy, the fraction
  of nodes in each state (stick, slip, reverse slip, separation), Fourier modes of U, V;
* snapshots of the fields every ``snapshot_every`` transits, and at every sample during
  the last ``tail`` transits (for the classification of the limit regime, `classify`).

Runs are budgeted in wave transits ``2 pi / sqrt(a)`` (the step is set by the CFL
condition, so one transit is about ``nodes`` steps). With ``checkpoint=path`` the run is
saved to netCDF every ``every`` time units, on interruption, and at the end; calling
`integrate` again with the same arguments resumes from the file (bitwise the same
result as an uninterrupted run).
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from typing import Callable, ClassVar

import numpy as np

from ...quantities import BRAKE as Q
from ...contact import RunFormat, RunRecord, prepare, run_explicit
from ...errors import ParameterError
from ..reduced import BrakeParams
from .scheme import RingScheme
from ... import validation as check

__all__ = ["InitialCondition", "RingRun", "integrate", "perturbed_steady", "transit_time", "initial_from_wave"]


def transit_time(params: BrakeParams) -> float:
    """``2 pi / sqrt(a)``: one trip of a P-wave around the ring (paper time ``Omega t``)."""
    check.instance("params", params, BrakeParams, "a stickslip.brake.BrakeParams")
    return float(2.0 * np.pi / np.sqrt(params.coefficients().a))


@dataclass(frozen=True, eq=False)
class InitialCondition:
    """``U, V`` and their time derivatives at the nodes at ``t = 0``."""

    U: np.ndarray
    V: np.ndarray
    Ud: np.ndarray
    Vd: np.ndarray
    label: str = "user"

    def __post_init__(self):
        arrays = [check.finite_array(k, getattr(self, k), empty=True) for k in ("U", "V", "Ud", "Vd")]
        n = arrays[0].shape
        for name, arr in zip(("U", "V", "Ud", "Vd"), arrays):
            if arr.ndim != 1 or arr.shape != n or not np.all(np.isfinite(arr)):
                raise ParameterError(name, f"array of shape {arr.shape}", f"finite, 1-D, shape {n}")
            object.__setattr__(self, name, arr)

    @property
    def nodes(self) -> int:
        return self.U.size

    def digest(self) -> str:
        return hashlib.sha1(b"".join(a.tobytes() for a in (self.U, self.V, self.Ud, self.Vd))).hexdigest()


def perturbed_steady(params: BrakeParams, nodes: int = 512, amplitude: float = 1e-3, mode: int | None = None,
                     seed: int = 0, phase: float = 0.0, noise: float = 0.0) -> InitialCondition:
    """Steady sliding [16] with ``V`` perturbed by ``delta * pattern(theta)``, at rest.

    ``pattern = amplitude cos(mode theta + phase) + noise xi(theta)`` if ``mode`` is given,
    else ``amplitude xi(theta)``; ``xi`` is white noise (normal, unit RMS, from ``seed``).
    ``U = delta`` and the velocities are zero.
    """
    scheme = RingScheme(params, nodes)
    # relative to the interference delta; 100 delta is far from any steady sliding already
    amplitude, noise = Q.check("amplitude", amplitude), Q.check("noise", noise)
    seed, phase = Q.check("seed", seed), Q.check("phase", phase)
    white = np.random.default_rng(seed).standard_normal(scheme.nodes)
    white /= np.sqrt(np.mean(white**2))
    if mode is None:
        pattern, label = amplitude * white, f"{amplitude:g} delta noise(seed={seed})"
    else:
        if Q.check("mode", mode) > scheme.nodes // 2:
            raise ParameterError("mode", mode, f"an integer in [0, {scheme.nodes // 2}] (half the nodes around)",
                                 also=("nodes",))
        pattern = amplitude * np.cos(mode * scheme.theta + phase) + noise * white
        label = f"{amplitude:g} delta mode {mode}" + (f" + {noise:g} delta noise(seed={seed})" if noise else "")
    U_e, V_e = scheme.fields(scheme.steady_reference()[0])
    zero = np.zeros(scheme.nodes)
    return InitialCondition(U_e, V_e + params.delta * pattern, zero, zero.copy(), "steady sliding + " + label)


def initial_from_wave(wave, nodes: int) -> InitialCondition:
    """The wave sampled on ``nodes`` points at ``t = 0`` (``U_t = -c U'``, ``V_t = -c V'``)."""
    if not all(hasattr(wave, name) for name in ("evaluate", "c", "n")):  # the ring does not import the waves
        raise ParameterError("wave", type(wave).__name__, "a stickslip.brake.TravellingWave")
    nodes = Q.check("nodes", nodes)
    theta = 2 * np.pi * np.arange(nodes) / nodes
    e = wave.evaluate(theta)
    return InitialCondition(e["U"], e["V"], -wave.c * e["dU"], -wave.c * e["dV"], label=f"wave n={wave.n}")


_FORMAT = RunFormat(
    units={"length": "R", "velocity": "R Omega", "traction": "E / M"},
    notes={"P": "contact pressure per unit modal mass (p = M P)", "Q": "friction traction per unit modal mass (q = M Q)"},
    energy_units="E R^2 / M", energy_note="energy of the scheme", node_label="node",
    source="reduced model [12] (corrected), explicit scheme of docs/theory/brake-ring.md",
    key_attrs=("nodes", "beta2", "courant"), scheme=RingScheme, params_type=BrakeParams,
    title="run of the ring (reduced model) on the rotating shaft",
    scales=lambda s: {} if s.params.physical is None else {
        "R": s.params.physical.inner_radius, "Omega": s.params.physical.omega, "E": s.params.physical.young, "M": s.coefficients.modal_mass})


@dataclass(frozen=True, eq=False, repr=False)
class RingRun(RunRecord):
    """Result of `integrate` (all times in the paper's ``t = Omega t̄``).

    Series (one row per sample): ``t``, ``energy`` (the scheme's energy of the deviation
    from steady sliding, ``|w|^2/2 + (u_m - u_e) K (u_{m+1} - u_e)/2`` integrated over
    theta, ``w`` the step velocity; ``u_e = 0`` when contact is off),
    ``kinetic``, ``fractions`` (columns `STATE_NAMES`), ``modes_U``, ``modes_V`` (complex
    Fourier coefficients ``rfft / nodes``, modes ``0..K``). Snapshots: ``snap_t`` and the
    fields ``U, V, Ud, Vd`` (``Ud, Vd`` the step velocities ``(u_{m+1} - u_m)/dt``),
    ``P, Q`` (reactions per unit modal mass), ``gap`` and ``state`` (codes of
    `stickslip.contact.states`). ``kernel``: the scheme state (dofs ``U_0, V_0, U_1, ...``).
    """

    FORMAT: ClassVar[RunFormat] = _FORMAT


def integrate(params: BrakeParams, nodes: int = 512, t_end: float | None = None, *, transits: float | None = None,
              initial: InitialCondition | None = None, beta2: float = 0.5, courant: float = 0.9,
              samples_per_transit: int = 32, snapshot_every: float = 1.0, tail: float = 2.0, modes: int = 32,
              contact: bool = True, checkpoint=None, every: float | None = None,
              progress: Callable[[float, float], None] | None = None, overwrite: bool = False) -> RingRun:
    """Integrate [12] on ``nodes`` points from ``initial`` up to ``t_end`` (or ``transits``).

    Parameters
    ----------
    params : BrakeParams
        Dimensionless parameters.
    nodes : int
        Nodes around the ring (>= 8).
    t_end, transits : float
        Duration in paper time, or in wave transits ``2 pi/sqrt(a)``; give exactly one.
    initial : InitialCondition, optional
        Default: `perturbed_steady` with white noise of amplitude ``1e-3 delta``.
    beta2, courant : float
        Scheme parameters (`RingScheme`): ``beta2 = 1/2`` central differences.
    samples_per_transit : int
        Series samples per transit (>= 4); also the snapshot rate in the tail.
    snapshot_every, tail : float
        Snapshot interval and the length of the densely sampled tail, in transits.
    modes : int
        Fourier modes ``0..modes`` of U and V kept in the series.
    contact : bool
        False switches contact and friction off (free linear problem).
    checkpoint : path, optional
        netCDF file: resumed from if it exists, written every ``every`` time units
        (default ``t_end/10``), on interruption and at the end. A checkpoint of another
        run (or a damaged one) is refused with a `ParameterError`.
    progress : callable, optional
        ``progress(t, t_end)`` after every sample.
    overwrite : bool
        Start afresh, replacing the checkpoint, instead of resuming from it.
    """
    scheme = RingScheme(params, nodes, beta2, courant)
    initial = perturbed_steady(params, scheme.nodes) if initial is None else initial
    if not isinstance(initial, InitialCondition) or initial.nodes != scheme.nodes:
        raise ParameterError("initial", initial, f"an InitialCondition with {scheme.nodes} nodes")
    t_end, settings = prepare(scheme, t_end=t_end, transits=transits, samples_per_transit=samples_per_transit,
                              snapshot_every=snapshot_every, tail=tail, modes=modes, contact=contact,
                              initial=initial, progress=progress)
    return run_explicit(RingRun, scheme, scheme.dofs(initial.U, initial.V), scheme.dofs(initial.Ud, initial.Vd),
                        settings, t_end, checkpoint=checkpoint, every=every, progress=progress,
                        overwrite=overwrite)
