"""Where a mode's energy is: the share of each body and each cell group of a pair (which part drives
a squeal).

For a complex mode shape ``w`` (the CEA's, full or reduced: `stickslip.fem.cea.CeaModes` with
shapes) of a `stickslip.fem.PairProblem`, the time-averaged kinetic and strain energies of a part
``g`` are proportional to ``w^H M_g w`` and ``Re(w^H K_g w)`` (``M_g`` its lumped mass, ``K_g`` its
stiffness: the cells of the group, or the whole body for 2-D bodies), and its shares are these over
their sums: each mode's shares add up to 1 (the contact's springs and the turning disc's transport
terms are not any part's and are left out of both).
"""

from __future__ import annotations

import numpy as np
import lazy_loader as lazy

from ..cf import finish
from ..errors import ParameterError
from .cea import CeaModes
from .pair import PairProblem
from .solid import SolidSystem

xr = lazy.load("xarray")

__all__ = ["energy_shares", "parts"]


def parts(problem: PairProblem) -> dict:
    """``{part: (lumped mass, stiffness)}`` on all of the pair's dofs: ``slave:GROUP`` and
    ``master:GROUP`` for solids (each cell group with a material; ``slave``, ``master`` for one
    material on a body), ``slave`` and ``master`` for 2-D bodies."""
    import scipy.sparse as sp

    out, offset, total = {}, 0, problem.slave.n_dofs + problem.master.n_dofs
    for who, system in (("slave", problem.slave), ("master", problem.master)):
        n = system.n_dofs
        if isinstance(system, SolidSystem):
            pieces = {name: (system.group_mass[name], system.group_stiffness[name]) for name in system.group_mass}
        else:
            pieces = {"": (system.mass, system.K)}
        for name, (m, K) in pieces.items():
            mass = np.zeros(total)
            mass[offset:offset + n] = m
            stiffness = sp.block_diag([sp.csr_matrix((offset, offset)), K, sp.csr_matrix((total - offset - n,) * 2)],
                                      format="csr")
            out[f"{who}:{name}" if name else who] = (mass, stiffness)
        offset += n
    return out


def energy_shares(problem: PairProblem, modes: CeaModes) -> xr.Dataset:
    """The kinetic and strain energy shares ``(mode, part)`` of each of ``modes`` (with shapes) of
    ``problem`` (see the module docstring), with the modes' growth rates and frequencies."""
    if not isinstance(problem, PairProblem):
        raise ParameterError("problem", problem, "a stickslip.fem.PairProblem")
    if not isinstance(modes, CeaModes) or modes.shapes is None:
        raise ParameterError("modes", type(modes).__name__, "CeaModes with shapes (mode_shapes=True)")
    w = problem.displacements(modes.shapes)
    names, kinetic, strain = [], [], []
    for name, (m, K) in parts(problem).items():
        names.append(name)
        kinetic.append(np.einsum("i,ij->j", m, np.abs(w) ** 2))
        strain.append(np.einsum("ij,ij->j", w.conj(), K @ w).real)
    kinetic, strain = np.array(kinetic).T, np.array(strain).T
    kinetic /= kinetic.sum(axis=1, keepdims=True)
    strain /= strain.sum(axis=1, keepdims=True)
    one = {"units": "1"}
    ds = xr.Dataset({"kinetic_share": (("mode", "part"), kinetic, {**one, "long_name": "share of the mode's kinetic "
                                                                             "energy in the part"}),
                     "strain_share": (("mode", "part"), strain, {**one, "long_name": "share of the mode's strain "
                                                                           "energy in the part"}),
                     "growth_rate": ("mode", modes.growth_rate, {"units": "1/s", "long_name": "growth rate"}),
                     "frequency": ("mode", modes.frequency, {"units": "Hz", "long_name": "frequency"})},
                    coords={"mode": ("mode", np.arange(len(modes.s)), {"units": "1", "long_name": "index of the "
                                                                        "mode, most unstable first"}),
                            "part": ("part", np.array(names, dtype=object), {"long_name": "body and cell group"})})
    return finish(ds, "energy shares of the modes of steady sliding by part", "fem", params=modes.params or {})
