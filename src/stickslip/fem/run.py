"""Runs of a general body: the shared run books of `stickslip.contact.runs` in SI units.

`integrate_body(problem, transits=...)` advances `BodyScheme` from steady sliding plus a
perturbation (`perturbed_steady_body`) and keeps the books of every contact model: series
of energy and node-state fractions, snapshots of the contact nodes, checkpoints (written
every ``every`` seconds, on interruption and at the end, resumed if they hold this run;
the mesh is not stored, so a checkpoint is resumed with its problem, whose digest must
match), and `classify_body` reads the limit regime on the contact nodes.

Units: time [s]; displacements [m]; reactions ``P, Q`` [N per unit thickness] per node;
energies [J per unit thickness]; ``theta = 2 pi s / L`` along the contact line (``s`` the
arclength, stored too as the coordinate ``arclength`` [m]; on an open line the modes ``modes_*``
are the Fourier coefficients of a line that is not periodic: a description, not waves).
"""

from __future__ import annotations

import hashlib
from dataclasses import dataclass
from typing import Callable, ClassVar

import numpy as np

from ..quantities import COMMON, FEM as Q
from ..contact import ExplicitScheme, classify
from ..contact.runs import RunFormat, RunRecord, prepare, run_explicit
from ..errors import ParameterError
from .scheme import BodyScheme, ContactProblem
from .static import steady_contact
from .. import validation as check

__all__ = ["BodyInitial", "BodyRun", "perturbed_steady_body", "preload_body", "integrate_body", "classify_body"]


@dataclass(frozen=True, eq=False)
class BodyInitial:
    """A start: free-dof displacement ``u`` and velocity ``v`` of a `BodyScheme`, and a ``label``."""

    u: np.ndarray
    v: np.ndarray
    label: str

    def digest(self) -> str:
        return hashlib.sha1(np.ascontiguousarray(self.u).tobytes() + np.ascontiguousarray(self.v).tobytes()).hexdigest()


def perturbed_steady_body(scheme: BodyScheme, amplitude: float = 1e-3, seed: int = 0) -> BodyInitial:
    """Steady sliding plus white noise on the contact nodes' tangential displacements, at rest
    (of a `BodyScheme`, or of a `stickslip.fem.pair_run.PairScheme`: its slave's contact nodes).

    The noise has RMS ``amplitude`` (in [0, 100]) times the largest steady displacement of the
    contact line.
    """
    if not isinstance(scheme, ExplicitScheme):
        raise ParameterError("scheme", scheme, "a BodyScheme or a PairScheme")
    amplitude = COMMON.check("amplitude", amplitude)  # beyond, the start is no longer near steady sliding
    seed = COMMON.check("seed", seed)
    u_e, _, _ = scheme.steady_reference()
    normal, tangent = scheme.contact_dofs
    size = float(np.abs(u_e[np.concatenate([normal, tangent])]).max()) or 1.0
    white = np.random.default_rng(int(seed)).standard_normal(tangent.size)
    white /= np.sqrt(np.mean(white**2))
    u = u_e.copy()
    u[tangent] += amplitude * size * white
    return BodyInitial(u, np.zeros_like(u), f"steady sliding + {amplitude:g} noise(seed={int(seed)})")


def preload_body(scheme: BodyScheme, velocity=(0.0, 0.0)) -> BodyInitial:
    """The static preload (frictionless contact, `stickslip.fem.static.steady_contact` with
    ``friction = 0``) with every free node moving at the uniform ``velocity = (vx, vy)`` [m/s]:
    at rest by default (the surface then drags the body), or moving with a flat surface
    (``velocity`` its velocity: the body starts sticking, as the 1-DOF oscillator on its stick segment)."""
    if not isinstance(scheme, BodyScheme):
        raise ParameterError("scheme", scheme, "a BodyScheme")
    vx, vy = Q["velocity"].check_pair(velocity)
    p = scheme.params
    pre = steady_contact(p.system, p.frames, 0.0, p.clamped)
    v = np.zeros(p.system.n_dofs)
    v[0::2], v[1::2] = vx, vy
    v[p.fixed] = 0.0
    to_scheme = scheme.rotation.T
    return BodyInitial((to_scheme @ pre.u)[scheme.free], (to_scheme @ v)[scheme.free],
                       f"preload, moving at ({vx:g}, {vy:g}) m/s")


_FORMAT = RunFormat(
    units={"length": "m", "velocity": "m/s", "traction": "N/m"},
    notes={"P": "normal contact force on the node per unit thickness",
           "Q": "friction force on the node per unit thickness, along the surface motion",
           **{f"vol_{x}": f"{what} of every free dof (volume snapshot) in the scheme's frames: normal and tangent "
                          "at the contact nodes, x and y elsewhere (BodyScheme.cartesian gives x and y everywhere)"
              for x, what in (("u", "displacement"), ("v", "velocity"))}},
    energy_units="J/m", energy_note="energy of the deviation from steady sliding (per unit thickness)",
    node_label="contact node",
    source="general 2-D body, explicit beta2 scheme [22] with multipliers [23] on sparse matrices (stickslip.fem)",
    key_attrs=("beta2", "courant", "step_given"), scheme=BodyScheme, params_type=ContactProblem,
    traction_scale=lambda s: s.mass[s.contact_dofs[0]],
    extra_attrs=lambda s: {"line_length": s.line_length, "p_wave_speed": s.p_wave_speed},
    title="run of a general body on a rigid counter-surface", time_units="s", time_note="time", model="fem",
    position_note="position of the contact node along the contact line as an angle, 2 pi s / L (s its arclength "
                  "from the first node, L the line's length, attribute line_length)",
    mode_note="Fourier mode in theta along the contact line (periodic only on a closed line)",
    extra_coords=lambda s: {"arclength": (s.params.frames.arclength[s.contact_nodes],
                                          {"units": "m", "long_name": "arclength of the contact node along the "
                                                                      "contact line from its first node"})})


@dataclass(frozen=True, eq=False, repr=False)
class BodyRun(RunRecord):
    """Result of `integrate_body` (see the module docstring for the units)."""

    FORMAT: ClassVar[RunFormat] = _FORMAT

    @classmethod
    def from_xarray(cls, ds, scheme: BodyScheme | None = None):
        """The run in ``ds``, with its ``scheme`` (a mesh is not stored in the run)."""
        if not isinstance(scheme, BodyScheme):
            raise ParameterError("scheme", scheme, "the BodyScheme of the run (its mesh is not in the file)")
        from ..contact.runs import dataset_to_run

        return dataset_to_run(cls, ds, scheme)


def integrate_body(problem: ContactProblem, t_end: float | None = None, *, transits: float | None = None,
                   initial: BodyInitial | None = None, beta2: float = 0.9, courant: float = 0.9,
                   time_step: float | None = None, samples_per_transit: int = 32, snapshot_every: float = 1.0,
                   tail: float = 2.0, modes: int = 32, contact: bool = True, checkpoint=None,
                   every: float | None = None, progress: Callable[[float, float], None] | None = None,
                   overwrite: bool = False, volume_every: float | None = None) -> BodyRun:
    """Integrate ``problem`` up to ``t_end`` [s] (or ``transits`` of a P-wave along the contact line).

    ``initial`` defaults to `perturbed_steady_body`; ``beta2``, ``courant``, ``time_step``
    set `BodyScheme`; the books and ``checkpoint`` behave as in `stickslip.brake.fem.integrate_fem`;
    ``volume_every`` [transits] keeps volume snapshots (one at ``t = 0`` too) for `stickslip.fem.paraview.write_run_xdmf`.
    """
    check.instance("problem", problem, ContactProblem, "a stickslip.fem.ContactProblem")
    scheme = BodyScheme(problem, beta2, courant, time_step)
    initial = perturbed_steady_body(scheme) if initial is None else initial
    if not isinstance(initial, BodyInitial) or initial.u.shape != (scheme.free.size,):
        raise ParameterError("initial", initial, f"a BodyInitial with {scheme.free.size} dofs")
    t_end, settings = prepare(scheme, t_end=t_end, transits=transits, samples_per_transit=samples_per_transit,
                              snapshot_every=snapshot_every, tail=tail, modes=modes, contact=contact,
                              initial=initial, progress=progress, volume_every=volume_every)
    return run_explicit(BodyRun, scheme, initial.u, initial.v, settings, t_end, checkpoint=checkpoint, every=every,
                        progress=progress, overwrite=overwrite)


def classify_body(run: BodyRun, transits: float | None = None, **options):
    """The limit regime of a run on its contact nodes (`stickslip.contact.classify`; of a pair
    of bodies, on the slave's)."""
    if not isinstance(run, RunRecord) or run.FORMAT.model != "fem":
        raise ParameterError("run", run, "a BodyRun or a PairRun (see integrate_body, integrate_pair)")
    return classify(run, transits, **options)
