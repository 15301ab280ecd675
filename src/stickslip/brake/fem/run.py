"""Time integration of the FE brake model from perturbed steady sliding (paper section 3.1).

`integrate_fem` advances the explicit scheme of `fem.scheme` and records, with the run
books of `stickslip.contact.runs` that the ring integrator uses too (same schedule, same
checkpoint guarantees):

* every ``1/samples_per_transit`` of a P-wave transit: the energy of the deviation from
  FE steady sliding, the fraction of contact nodes in each state (stick, slip, reverse
  slip, separation) and Fourier modes of ``u_r, u_theta`` along ``r = R``;
* snapshots of the contact nodes (``U = u_r``, ``V = u_theta``, step velocities, pressure
  ``P = p`` and shear ``Q = q`` in units of ``E``, states) every ``snapshot_every`` transits
  and at every sample of the last ``tail`` transits (for `classify_fem`);
* with ``volume_every``: volume snapshots (displacement and velocity of every free dof,
  reactions and states of the contact nodes) at the start, every ``volume_every`` transits
  and at the end, kept in the run (and its checkpoint) for `write_xdmf` (ParaView).

A run is budgeted in transits ``2 pi R / c_p`` (the step is set by the CFL limit, so a
transit costs about ``1.4 n_theta`` steps for the default mesh shape and ``beta2 = 0.9``). With
``checkpoint=path`` the run is written to netCDF every ``every`` time units, on any
exception (Ctrl-C, the progress callback raising) and at the end; calling again with the
same arguments resumes from the file, bitwise identical to an uninterrupted run.
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from typing import Callable, ClassVar

import numpy as np

from ...quantities import BRAKE as Q
from ...contact import RunFormat, RunRecord, prepare, run_explicit
from ...contact.runs import MAX_VOLUME
from ... import validation as check
from ...errors import ParameterError
from ..reduced import BrakeParams
from .scheme import FemScheme

__all__ = ["FemInitial", "FemRun", "integrate_fem", "perturbed_steady", "MAX_VOLUME"]


@dataclass(frozen=True, eq=False)
class FemInitial:
    """Displacement ``u`` and velocity ``v`` of the free dofs at ``t = 0`` (polar frames)."""

    u: np.ndarray
    v: np.ndarray
    label: str = "user"

    def __post_init__(self):
        u, v = (check.finite_array(name, x, empty=True) for name, x in (("u", self.u), ("v", self.v)))
        for name, x in (("u", u), ("v", v)):
            if x.ndim != 1 or x.shape != u.shape or not np.all(np.isfinite(x)):
                raise ParameterError(name, f"array of shape {x.shape}", f"finite, 1-D, shape {u.shape}")
        object.__setattr__(self, "u", u)
        object.__setattr__(self, "v", v)

    def digest(self) -> str:
        return hashlib.sha1(self.u.tobytes() + self.v.tobytes()).hexdigest()


def perturbed_steady(scheme: FemScheme, amplitude: float = 1e-3, mode: int | None = None, seed: int = 0,
                     phase: float = 0.0, noise: float = 0.0) -> FemInitial:
    """FE steady sliding plus a hoop perturbation ``delta X(r) pattern(theta)``, at rest.

    ``pattern = amplitude cos(mode theta + phase) + noise w(theta)`` if ``mode`` is given,
    else ``amplitude w(theta)``, ``w`` white noise (unit RMS, from ``seed``), and
    ``X(r) = (xi^2/r - r)/(xi^2 - 1)`` the static profile (as `stickslip.brake.ring.perturbed_steady`).
    """
    if not isinstance(scheme, FemScheme):
        raise ParameterError("scheme", scheme, "a FemScheme")
    amplitude, noise = Q.check("amplitude", amplitude), Q.check("noise", noise)
    seed, phase = Q.check("seed", seed), Q.check("phase", phase)
    N = scheme.n_theta
    white = np.random.default_rng(seed).standard_normal(N)
    white /= np.sqrt(np.mean(white**2))
    if mode is None:
        pattern, label = amplitude * white, f"{amplitude:g} delta noise(seed={seed})"
    else:
        if Q.check("mode", mode) > N // 2:
            raise ParameterError("mode", mode, f"an integer in [0, {N // 2}] (half the nodes around, n_theta = {N})",
                                 also=("n_theta",))
        pattern = amplitude * np.cos(mode * scheme.theta + phase) + noise * white
        label = f"{amplitude:g} delta mode {mode}" + (f" + {noise:g} delta noise(seed={seed})" if noise else "")
    xi, r = scheme.params.xi, scheme.system.mesh.radii[:-1, None]
    X = (xi**2 / r - r) / (xi**2 - 1.0)
    u = scheme.steady.u + scheme.system.from_fields(0.0 * X * pattern, scheme.params.delta * X * pattern)
    return FemInitial(u, np.zeros_like(u), "FE steady sliding + " + label)


_FORMAT = RunFormat(
    units={"length": "R", "velocity": "R Omega", "traction": "E"},
    notes={"P": "contact pressure p = lambda_n / (R dtheta)", "Q": "friction shear q = lambda_t / (R dtheta)"},
    energy_units="E R^2", energy_note="energy of the deviation from FE steady sliding (per unit length in z)",
    node_label="contact node",
    source="FE model of eq. [10], explicit beta2 scheme [22] with multipliers [23] (docs/theory/brake-fem.md)",
    key_attrs=("n_theta", "n_r", "beta2", "courant"), scheme=FemScheme, params_type=BrakeParams,
    traction_scale=lambda s: s.traction_scale,
    extra_attrs=lambda s: {"p_wave_speed": s.p_wave_speed, "mesh": s.system.mesh.describe()},
    title="run of the FE annulus on the rotating shaft",
    scales=lambda s: {} if s.params.physical is None else {
        "R": s.params.physical.inner_radius, "Omega": s.params.physical.omega, "E": s.params.physical.young})


@dataclass(frozen=True, eq=False, repr=False)
class FemRun(RunRecord):
    """Result of `integrate_fem` (times in the paper's ``t = Omega t̄``).

    Series: ``t``, ``energy`` (of the deviation from FE steady sliding: ``w^T M w/2 +
    (u_m - u_e)^T K (u_{m+1} - u_e)/2``), ``kinetic``, ``fractions`` (columns `STATE_NAMES`),
    ``modes_U``, ``modes_V`` (``rfft/n_theta`` of ``u_r``, ``u_theta`` at ``r = R``).
    Snapshots at the contact nodes: ``snap_t``, ``U``, ``V``, ``Ud``, ``Vd`` (step
    velocities, shaft surface speed = 1), ``P``, ``Q`` (pressure and shear, units of ``E``),
    ``gap`` (``u_r - delta`` at ``t_{m+1}``, where the constraint of step ``m`` acts), ``state``. ``kernel``: the scheme state ``u, v, a`` (all free dofs) and ``ref`` (``u_e``).
    Volume snapshots (with ``volume_every``): ``vol_t``, ``vol_u``, ``vol_v`` (total
    displacement and velocity ``v_m`` of every free dof, polar frames), ``vol_P``, ``vol_Q``,
    ``vol_state`` (contact nodes).
    """

    FORMAT: ClassVar[RunFormat] = _FORMAT



def integrate_fem(params: BrakeParams, n_theta: int = 256, n_r: int = 16, t_end: float | None = None, *,
                  transits: float | None = None, initial: FemInitial | None = None, beta2: float = 0.9,
                  courant: float = 0.9, samples_per_transit: int = 32, snapshot_every: float = 1.0,
                  tail: float = 2.0, modes: int = 32, contact: bool = True, checkpoint=None,
                  every: float | None = None, progress: Callable[[float, float], None] | None = None,
                  overwrite: bool = False, volume_every: float | None = None) -> FemRun:
    """Integrate the FE model of [10] from ``initial`` up to ``t_end`` (or ``transits``).

    Parameters
    ----------
    params : BrakeParams
        Dimensionless parameters (``delta > 0`` for contact).
    n_theta, n_r : int
        Mesh: nodes around (multiple of 8, >= 16) and element layers across.
    t_end, transits : float
        Duration in paper time, or in P-wave transits ``2 pi R / c_p``; give exactly one.
    initial : FemInitial, optional
        Default: `perturbed_steady` with white noise ``1e-3 delta``.
    beta2, courant : float
        Scheme (`FemScheme`); the paper uses ``beta2 = 0.9``, ``1/2`` is central differences.
    samples_per_transit : int
        Series samples per transit (>= 4); also the snapshot rate in the tail.
    snapshot_every, tail : float
        Snapshot interval and length of the densely sampled tail, in transits.
    modes : int
        Fourier modes ``0..modes`` kept in the series.
    contact : bool
        False: no contact and no friction (free vibrations, inner surface free).
    checkpoint : path, optional
        netCDF file: resumed from if it exists; written every ``every`` time units
        (default ``t_end/10``), on interruption and at the end. A checkpoint of another
        run (or a damaged one) is refused with a `ParameterError`.
    progress : callable, optional
        ``progress(t, t_end)`` after every sample.
    overwrite : bool
        Start afresh, replacing the checkpoint, instead of resuming from it.
    volume_every : float, optional
        Keep volume snapshots every ``volume_every`` transits (> 0, rounded to whole samples)
        and at the end, for `write_xdmf`; part of the run's settings (a checkpoint with
        another interval is refused). At most `MAX_VOLUME` numbers in all.
    """
    scheme = FemScheme(params, n_theta, n_r, beta2, courant)
    initial = perturbed_steady(scheme) if initial is None else initial
    if not isinstance(initial, FemInitial) or initial.u.size != scheme.system.n_free:
        raise ParameterError("initial", initial, f"a FemInitial with {scheme.system.n_free} dofs")
    t_end, settings = prepare(scheme, t_end=t_end, transits=transits, samples_per_transit=samples_per_transit,
                              snapshot_every=snapshot_every, tail=tail, modes=modes, contact=contact,
                              initial=initial, progress=progress, volume_every=volume_every)
    return run_explicit(FemRun, scheme, initial.u, initial.v, settings, t_end, checkpoint=checkpoint, every=every,
                        progress=progress, overwrite=overwrite)
