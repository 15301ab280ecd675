"""The energy books of an antiplane or in-plane run (`energy_book`): where the loading's work went.

Per metre along z [J/m], summed over the interface and the steps before each sample (the rates held
over each step, as the scheme holds them):

- ``load_work``: the loading's work on the slip, ``int int tau_0 V dx dt`` (``tau_0`` the traction
  with the surface held, `stickslip.sbim.antiplane`); in-plane on the slip and the opening,
  ``int int (tau_0 V_x + sigma_0 V_y) dx dt``;
- ``static_energy``: the strain energy the slip would hold at rest, ``(1/2) int w K[w] dx`` with ``K`` the
  static stiffness ``mu |k|`` mode by mode; in-plane ``(1/2) int U . K[U] dx`` with the surface's static
  stiffness matrix ``mu |k| [[S11, -i S12], [i S12, S22]]`` (`stickslip.sbim.inplane_kernels`); between two
  materials the sum of both surfaces', each with its own displacement and solid (the lower one's, the
  upper's reflected, with the coupling's sign turned);
- ``released_energy = load_work - static_energy``: the energy the slip has released (for a constant loading
  ``int (tau_0 + tau_1) / 2 dw dx``, the seismologists' budget);
- ``dissipation``: the interface's, ``int int tau V dx dt`` (in-plane ``sigma_xy V_x + sigma_yy V_y``: the
  normal traction does no work in contact, nor on an open node, but does on a gap the scheme closes within
  a step, an impact: ``contact_energy``, zero antiplane); the rest split into ``friction_energy``, the kinetic
  strength times the slip's path, and ``fracture_energy``, the rest (slip-weakening: the strength above the
  kinetic one, ``(tau_s - tau_d) D_c / 2`` per unit area once weakened). Coulomb's dissipation is all
  friction; rate-and-state's split is not unique and is all counted as friction here;
- ``wave_energy = released_energy - dissipation``: the kinetic and strain energy of the waves in the
  body, radiated away once the surface is at rest (it can only grow then: nothing comes back from
  depth).

The books close by construction; what they say is checked against closed forms in the tests (a free
surface's radiated energy from the frequency domain, a plane wave's flux, slip-weakening's fracture
energy; in-plane: the plane S and P waves' fluxes, a slowly loaded surface's work stored, half a suddenly
loaded one's radiated; between two materials the same, and a slowly loaded interface's static energy
half of load . U). In-plane books are kept from rest only (not from an initial state).
"""

from __future__ import annotations

from dataclasses import dataclass

import numpy as np

from ..errors import ParameterError
from ..results import Result
from .antiplane import AntiplaneRun, Coulomb, SlipWeakening
from .inplane import InplaneRun
from .inplane_kernels import static_stiffness

__all__ = ["EnergyBook", "energy_book"]

#: The books' entries, in the order of `EnergyBook`'s fields after ``t``.
ENTRIES = ("load_work", "static_energy", "released_energy", "dissipation", "friction_energy", "fracture_energy",
           "wave_energy", "contact_energy")


@dataclass(frozen=True, eq=False, repr=False)
class EnergyBook(Result):
    """The entries at each sample ``t`` [s] (module docstring), each in J/m."""

    t: np.ndarray
    load_work: np.ndarray
    static_energy: np.ndarray
    released_energy: np.ndarray
    dissipation: np.ndarray
    friction_energy: np.ndarray
    fracture_energy: np.ndarray
    wave_energy: np.ndarray
    contact_energy: np.ndarray | None = None

    def __post_init__(self):
        if self.contact_energy is None:  # antiplane: no normal traction
            object.__setattr__(self, "contact_energy", np.zeros_like(self.dissipation))

    def to_dict(self) -> dict:
        """The entries at the last sample."""
        return {"t": float(self.t[-1]), **{name: float(getattr(self, name)[-1]) for name in ENTRIES}}

    def to_xarray(self):
        import xarray as xr

        from ..cf import finish

        ds = xr.Dataset({name: ("t", getattr(self, name)) for name in ENTRIES}, coords={"t": self.t})
        return finish(ds, "energy books of a run of the spectral boundary integral method (per metre along z)",
                      "sbim")


def energy_book(run) -> EnergyBook:
    """The energy books of ``run`` (an `AntiplaneRun`, or an `InplaneRun` from rest) at its samples (module
    docstring)."""
    if isinstance(run, InplaneRun):
        return _inplane_book(run)
    if not isinstance(run, AntiplaneRun) or run.load_work is None or len(run.t) == 0:
        raise ParameterError("run", type(run).__name__, "an AntiplaneRun from run_antiplane or an InplaneRun from "
                             "run_inplane, with its samples")
    p = run.problem
    k = p.wavenumbers
    n = p.elements
    stiff = np.fft.irfft(p.shear_modulus * k * np.fft.rfft(run.slip, axis=1), n, axis=1)
    static = 0.5 * p.dx * np.sum(run.slip * stiff, axis=1)
    released = run.load_work - static
    law = p.law
    kinetic = law.kinetic_strength if isinstance(law, (Coulomb, SlipWeakening)) else None
    friction = run.dissipation if kinetic is None else kinetic * run.travel
    fracture = np.zeros_like(run.dissipation) if kinetic is None else run.dissipation - friction
    return EnergyBook(run.t, run.load_work, static, released, run.dissipation, friction, fracture,
                      released - run.dissipation)


def _inplane_book(run: InplaneRun) -> EnergyBook:
    p = run.problem
    two = p.lower is not None
    if p.initial is not None or run.load_work is None or len(run.t) == 0 or (two and run.lower_displacement_x
                                                                            is None):
        raise ParameterError("run", "an InplaneRun" + (" from an initial state" if p.initial is not None else ""),
                             "an InplaneRun from rest, with its samples (a run from an initial state starts with "
                             "energy in the body that the books do not count)")
    if two:  # each surface's own: the upper's displacement is the lower's plus the slip and opening
        lx, ly = run.lower_displacement_x, run.lower_displacement_y
        static = _static(p, p.upper, run.slip + lx, run.opening + ly, 1) + _static(p, p.lower, lx, ly, -1)
    else:
        static = _static(p, p.upper, run.slip, run.opening, 1)
    released = run.load_work - static
    friction = run.friction_work  # rate-and-state's shear dissipation all friction, as antiplane
    return EnergyBook(run.t, run.load_work, static, released, run.dissipation, friction,
                      run.dissipation - friction - run.contact_work, released - run.dissipation, run.contact_work)


def _static(p, solid, ux, uy, side: int) -> np.ndarray:
    """``(1/2) int u . K[u] dx`` of a surface of ``solid`` displaced by ``(ux, uy)`` (samples x nodes), above
    the interface (``side = 1``) or below it (``-1``: reflected, the coupling's sign turned)."""
    n, muk = p.elements, solid.shear_modulus * p.wavenumbers
    s11, s22, s12 = static_stiffness(solid.poisson)
    s12 = side * s12
    fx, fy = np.fft.rfft(ux, axis=1), np.fft.rfft(uy, axis=1)
    kx = np.fft.irfft(muk * (s11 * fx - 1j * s12 * fy), n, axis=1)  # K[u], minus the static tractions
    ky = np.fft.irfft(muk * (s22 * fy + 1j * s12 * fx), n, axis=1)
    return 0.5 * p.dx * np.sum(ux * kx + uy * ky, axis=1)
