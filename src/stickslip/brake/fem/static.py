"""Steady sliding on the FE mesh: the static contact problem in full forward slip ([10], [11]).

Every contact node slips forward (the shaft surface moves at speed 1, the ring is at
rest), so its radial displacement is held, ``u_r = delta``, and its hoop dof carries the
friction ``f lambda_n``, where ``lambda_n = (K u)_r`` is the radial reaction. This is the
general body's steady sliding (`stickslip.fem.static.steady_contact`) on the annulus's problem
(`problem.annulus_problem`: the shaft a rigid cylinder ``delta`` into the bore, every bore
node active from the first iteration), written in the annulus's polar frames. The solution
is an exact fixed point of the explicit scheme (the reactions the scheme computes at rest are
``lambda_n`` and ``f lambda_n``). It must agree with the Lame solution `brake.reduced.steady`:
``u = delta X(r)``, ``v = V_e X(r)`` and ``p = lambda_n / (2 pi / n_theta) = p_e``, up to the
discretisation error ``O(h^2)``.
"""

from __future__ import annotations

from typing import ClassVar

from dataclasses import dataclass

import numpy as np
import lazy_loader as lazy

from ...results import Result
from ...cf import finish
from ...errors import ParameterError
from ..reduced.params import BrakeParams
from ..reduced.steady import steady_sliding
from .mesh import FemSystem, annulus_mesh, assemble
from .problem import annulus_problem

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["FemSteady", "steady_state"]


@dataclass(frozen=True, eq=False, repr=False)
class FemSteady(Result):
    """FE steady sliding: free-dof displacement ``u`` and contact reactions (per node).

    ``reaction_n, reaction_t`` are nodal forces (units ``E R`` per unit length in z);
    ``pressure = reaction_n / h_theta`` is in units of ``E``.
    """

    MODEL: ClassVar[str] = "brake"

    params: BrakeParams
    system: FemSystem
    u: np.ndarray
    reaction_n: np.ndarray
    reaction_t: np.ndarray

    @property
    def pressure(self) -> np.ndarray:
        return self.reaction_n / self.system.mesh.h_theta

    @property
    def forces(self) -> np.ndarray:
        """``K u`` on the free dofs: the reactions on the contact dofs, 0 elsewhere (to round-off)."""
        return self.system.K @ self.u

    def errors(self) -> dict:
        """Max-norm errors against the Lamé solution, relative to its scale.

        ``u``: max over nodes of ``|u_r - delta X(r)|/delta``; ``v``: the same for ``u_theta``
        and ``V_e``; ``p``: ``max |p_j - p_e| / p_e`` over the contact nodes.
        """
        p, s = self.params, self.system
        lame = steady_sliding(p.xi, p.nu, p.delta, p.friction)
        r = s.mesh.radii[:-1, None]
        err_u = np.abs(s.radial(self.u) - lame.u(r)).max() / lame.delta
        err_v = np.abs(s.hoop(self.u) - lame.v(r)).max() / abs(lame.V_e) if lame.V_e else np.nan
        err_p = np.abs(self.pressure - lame.p_e).max() / lame.p_e
        return {"u": float(err_u), "v": float(err_v), "p": float(err_p), "p_e": lame.p_e,
                "p_fem": float(self.pressure.mean()), "V_e": lame.V_e, "V_fem": float(self.u[1])}

    def to_dict(self) -> dict:
        return {"n_theta": self.system.mesh.n_theta, "n_r": self.system.mesh.n_r, **self.errors()}

    def to_xarray(self) -> xr.Dataset:
        s = self.system
        ds = xr.Dataset({"u_r": (("r", "theta"), s.radial(self.u), {"units": "R", "long_name": "radial displacement"}),
                         "u_theta": (("r", "theta"), s.hoop(self.u), {"units": "R", "long_name": "hoop displacement"}),
                         "pressure": ("theta", self.pressure, {"units": "E", "long_name": "contact pressure"})},
                        coords={"r": ("r", s.mesh.radii[:-1], {"units": "R", "long_name": "radius of the node ring"}),
                                "theta": ("theta", s.mesh.theta, {"units": "rad"})})
        ds.attrs["source"] = "FE static contact problem in forward slip; compare eq. [11] (corrected)"
        return finish(ds, "FE steady sliding", "brake", params=self.to_dict())


def steady_state(params: BrakeParams, system: FemSystem | None = None, *, n_theta: int = 256,
                 n_r: int = 16) -> FemSteady:
    """Solve the FE steady-sliding problem (see the module docstring).

    Parameters
    ----------
    params : BrakeParams
        ``delta`` and ``friction`` are used; ``xi``, ``nu`` must be those of ``system``.
    system : FemSystem, optional
        From `assemble`; default: `annulus_mesh` ``(n_theta, n_r, params.xi)`` assembled
        with ``params.nu``.
    n_theta, n_r : int
        The mesh when ``system`` is not given.
    """
    if not isinstance(params, BrakeParams):
        raise ParameterError("params", params, "a stickslip.brake.BrakeParams")
    if system is None:
        system = assemble(annulus_mesh(n_theta, n_r, params.xi), params.nu)
    if not isinstance(system, FemSystem) or abs(system.nu - params.nu) > 1e-15 or \
            abs(system.mesh.xi - params.xi) > 1e-12 * params.xi:
        raise ParameterError("system", system, "a FemSystem assembled with params.xi and params.nu")
    general = annulus_problem(params, system.mesh.n_theta, system.mesh.n_r).steady
    u = (system.mesh.polar_rotation.T @ general.u)[:system.n_free]  # the clamped ring comes last
    return FemSteady(params, system, u, general.pressure.copy(), general.shear.copy())
