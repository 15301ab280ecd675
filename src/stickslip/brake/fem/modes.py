"""Mode-by-mode analysis of the FE ring: free frequencies, CFL limit, flutter of steady sliding.

In polar nodal frames the stiffness of the structured annulus is block circulant in the
node index ``j`` around the ring, and the lumped mass is diagonal and the same on every
ring of nodes. A field ``u_c(r_i) e^{i n theta_j}`` (``c`` = radial, hoop) is therefore
mapped to ``(K_n u)(r_i) e^{i n theta_j}`` with the Hermitian ``2 n_r x 2 n_r`` block

    K_n[(i, c), (i', c')] = sum_j K[(i, 0, c), (i', j, c')] e^{i n theta_j},

and the ``2 n_r n_theta`` eigenvalues of ``(K, gamma M)`` are those of the blocks for
``n = 0 .. n_theta - 1`` (``K_{-n}`` is the complex conjugate of ``K_n``). This gives

* the free frequencies of mode ``n`` (contact off, inner surface free), to be compared with
  the exact Bessel roots of `exact.annulus_frequencies`;
* the largest frequency of the mesh, hence the CFL step of the explicit scheme;
* the linear stability of steady sliding (all contact nodes in forward slip): the radial
  dof of the contact node is held (``u_r = delta``), its reaction is ``lambda_n = (K u)_r``,
  and the friction ``f lambda_n`` acts on the hoop dof, so that row becomes
  ``K_n[hoop, :] - f K_n[radial, :]``: a non-symmetric (circulatory) stiffness. Modes
  ``e^{i n theta + s t}`` have ``s^2 = -eig(M^{-1} K_eff,n) / gamma`` (the FE analogue of
  `stickslip.brake.growth_rates`, which is a one-term Galerkin model of the same problem).
"""

from __future__ import annotations

from typing import ClassVar

from dataclasses import dataclass

import numpy as np
import lazy_loader as lazy
from scipy.linalg import eigh, eigvals

from ...results import Result
from ...cf import finish
from ...contact import discrete_rates
from ...errors import ParameterError
from ..reduced.params import BrakeParams
from .mesh import FemSystem

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["fourier_block", "fem_frequencies", "max_frequency", "FemGrowth", "fem_growth_rates"]


def _modes(system: FemSystem, modes) -> np.ndarray:
    if not isinstance(system, FemSystem):
        raise ParameterError("system", system, "a FemSystem (see assemble)")
    n = np.atleast_1d(np.asarray(modes))
    if n.size == 0 or n.dtype.kind not in "iu" or n.min() < 0 or n.max() > system.mesh.n_theta // 2:
        raise ParameterError("modes", modes, f"integers in [0, {system.mesh.n_theta // 2}]")
    return n.astype(int)


def fourier_block(system: FemSystem, n: int) -> np.ndarray:
    """``K_n`` (complex Hermitian, ``2 n_r x 2 n_r``, local dof ``2 i + c``), ``0 <= n <= n_theta/2``."""
    n = int(_modes(system, n)[0])
    C, n_r = system.stencil, system.mesh.n_r
    phase = np.exp(1j * n * system.mesh.h_theta * np.arange(-1, 2))
    Kn = np.zeros((n_r, 2, n_r, 2), dtype=complex)
    for di in (-1, 0, 1):
        lo, hi = max(0, -di), min(n_r, n_r - di)
        blocks = np.einsum("idab,d->iab", C[lo:hi, di + 1], phase)
        Kn[np.arange(lo, hi), :, np.arange(lo, hi) + di, :] = blocks
    return Kn.reshape(2 * n_r, 2 * n_r)


def _ring_mass(system: FemSystem) -> np.ndarray:
    """Lumped mass of the local dofs ``2 i + c`` of one column of nodes."""
    return system.mass[::2 * system.mesh.n_theta].repeat(2)


def fem_frequencies(system: FemSystem, modes, count: int | None = None) -> np.ndarray:
    """Free frequencies ``omega sqrt(gamma)`` of modes ``e^{i n theta}`` (no contact).

    Returns an array ``(len(modes), count)`` (ascending per mode; all ``2 n_r`` by default).
    """
    n = _modes(system, modes)
    m = _ring_mass(system)
    out = []
    for k in n:
        w2 = eigh(fourier_block(system, k), np.diag(m).astype(complex), eigvals_only=True)
        out.append(np.sqrt(np.maximum(w2, 0.0))[:count])
    return np.array(out)


def max_frequency(system: FemSystem) -> float:
    """``max omega sqrt(gamma)`` over all modes of the mesh (contact off)."""
    if not isinstance(system, FemSystem):
        raise ParameterError("system", system, "a FemSystem (see assemble)")
    return float(fem_frequencies(system, np.arange(system.mesh.n_theta // 2 + 1))[:, -1].max())


@dataclass(frozen=True, repr=False)
class FemGrowth(Result):
    """Complex ``s`` (paper time) of steady sliding per mode ``n`` and branch (ascending ``|Im s|``)."""

    MODEL: ClassVar[str] = "brake"

    params: BrakeParams
    n: np.ndarray
    s: np.ndarray

    @property
    def growth_rate(self) -> np.ndarray:
        """``max Re s`` over the branches of each mode."""
        return self.s.real.max(axis=1)

    @property
    def lowest(self) -> np.ndarray:
        """``s`` of the lowest-frequency branch (the one the reduced model approximates)."""
        return self.s[:, 0]

    def discrete(self, dt: float, beta2: float) -> np.ndarray:
        """Fully discrete ``log z / dt`` of the explicit beta2 scheme, per mode and branch."""
        return discrete_rates(-self.s**2, dt, beta2)

    def to_dict(self) -> dict:
        top = int(np.argmax(self.growth_rate))
        return {"most_unstable": int(self.n[top]), "max_growth_rate": float(self.growth_rate[top]),
                "unstable": bool(self.growth_rate[top] > 0), "n": self.n.tolist(), "growth_rate": self.growth_rate.tolist(),
                "lowest": [[float(z.real), float(z.imag)] for z in self.lowest]}

    def to_xarray(self) -> xr.Dataset:
        ds = xr.Dataset({"growth_rate": (("n", "branch"), self.s.real,
                                         {"units": "1", "long_name": "growth rate Re s (per unit Omega t)"}),
                         "frequency": (("n", "branch"), self.s.imag,
                                       {"units": "1", "long_name": "angular frequency Im s (per unit Omega t)"})},
                        coords={"n": ("n", self.n, {"long_name": "circumferential wave number"}),
                                "branch": ("branch", np.arange(self.s.shape[1]), {"units": "1",
                                           "long_name": "eigenvalue branch, by growth rate"})},
                        attrs={"source": "FE steady sliding, forward slip, eq. [10]"})
        return finish(ds, "FE growth rates of steady sliding", "brake", params=self.params.to_attrs())


def fem_growth_rates(params: BrakeParams, system: FemSystem, modes=range(1, 9)) -> FemGrowth:
    """Flutter of steady sliding on the FE mesh: ``s`` with ``Re s >= 0`` per mode and branch.

    Parameters
    ----------
    params : BrakeParams
        ``gamma`` and ``friction`` are used (``delta`` only sets the steady state).
    system : FemSystem
        From `assemble` (its ``nu`` is the one used; ``params.nu`` must agree).
    modes : iterable of int
        Mode numbers in ``[0, n_theta/2]``.
    """
    if not isinstance(params, BrakeParams):
        raise ParameterError("params", params, "a stickslip.brake.BrakeParams")
    if not isinstance(system, FemSystem) or abs(system.nu - params.nu) > 1e-15 or \
            abs(system.mesh.xi - params.xi) > 1e-12 * params.xi:
        raise ParameterError("system", system, "a FemSystem assembled with params.xi and params.nu")
    n = _modes(system, modes)
    m = _ring_mass(system)
    keep = np.arange(1, 2 * system.mesh.n_r)
    out = []
    for k in n:
        Kn = fourier_block(system, k)
        Keff = Kn.copy()
        Keff[1, :] -= params.friction * Kn[0, :]
        lam = eigvals(Keff[np.ix_(keep, keep)] / m[keep, None]) / params.gamma
        s = np.sqrt(-lam.astype(complex))
        s = np.where(s.real < 0, -s, s)
        out.append(s[np.argsort(np.abs(s.imag))])
    return FemGrowth(params, n, np.array(out))
