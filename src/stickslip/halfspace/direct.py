"""Direct problem: the wave ``(cbar, b)`` produced by a loading ``(T, v, v*)`` ([52]-[55]).

The paper reports that Newton's method fails on [52]-[53]. Here the second equation
([55], or [53] for ``system="text"``) is linear in ``b`` and is solved for it,

    b(cbar) = 1 - k Gm (v - v*) / ((1 - beta1 beta2) cbar T),

which leaves one equation in one unknown, ``F(cbar) = 0`` with ``F`` the left side of
[52] at ``b = b(cbar)``. ``F`` is continuous on (-1, 0); every root where ``b(cbar) > 1``
is bracketed by a sign change on a fine grid (clustered at both ends of (-1, 0)) and
polished with Brent's method. No root: `NoSolutionError`; several: all are returned and
``unique`` is False. A root where ``F`` touches zero without changing sign would be
missed; the grid is fine enough that for the printed system, where
``F = (b/cbar)(K (v - v*) - v)`` and ``K(cbar)`` is monotone, this cannot happen.

The solution depends on the loading through ``v/v*`` and ``T/v*`` only (the inverse
problem is linear in ``v*``), so `direct_map` maps it over that plane.
"""

from __future__ import annotations

from typing import ClassVar

from dataclasses import dataclass

import numpy as np
import lazy_loader as lazy
from scipy.optimize import brentq

from ..results import Result
from ..cf import finish
from ..quantities import HALFSPACE as Q
from ..errors import NoSolutionError, ParameterError
from .inverse import system_factor
from .waves import radok

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["DirectSolution", "direct_problem", "direct_map", "cbar_grid"]


def cbar_grid(n: int = 4001) -> np.ndarray:
    """``n`` wave speeds in (-1, 0), clustered at both ends: ``-(1 - cos(pi s))/2``."""
    s = (np.arange(n) + 0.5) / n
    return -(1.0 - np.cos(np.pi * s)) / 2.0


def _b_of_c(rd, T, v, vs, k):
    return 1.0 - k * rd.gamma_mod * (v - vs) / (rd.one_minus_b1b2 * rd.cbar * T)


def _residual(rd, T, v, vs, k):
    """``(b(cbar), F(cbar))``; ``F`` is [52] scaled by ``|cbar|/(b v)`` (dimensionless)."""
    b = _b_of_c(rd, T, v, vs, k)
    c = rd.cbar
    F = -(v / c) * b + ((v - vs) / c - rd.one_minus_b1b2 * np.sin(np.pi * rd.lam) * T / (2.0 * rd.gamma1)) * rd.K * (b - 1.0)
    return b, F * (-c) / (b * v)


def _brackets(b, F):
    """Indices ``i`` with a sign change of ``F`` between grid points ``i`` and ``i+1``,
    both with ``b > 1``."""
    ok = (b > 1.0) & np.isfinite(F) & np.isfinite(b)
    change = (np.sign(F[..., :-1]) * np.sign(F[..., 1:]) <= 0) & ok[..., :-1] & ok[..., 1:]
    return change


@dataclass(frozen=True, repr=False)
class DirectSolution(Result):
    """Waves ``(cbar, b)`` solving [52]-[55] for the loading ``(T, v, v*)``.

    ``solutions`` lists every ``(cbar, b)`` found, ordered by ``cbar``; ``c`` and ``b``
    are those of the first. ``tau_yy_over_G`` and ``mu_star`` are what [26] and
    ``T = (mu - mu*)(-tau*_yy)/G`` imply for each solution (NaN for ``nu = 0``, where
    [26] gives ``V* = 0``).
    """

    MODEL: ClassVar[str] = "halfspace"

    T: float
    v: float
    v_star: float
    nu: float
    mu: float
    system: str
    solutions: tuple[tuple[float, float], ...]
    residuals: tuple[float, ...]

    @property
    def c(self) -> float:
        return self.solutions[0][0]

    @property
    def b(self) -> float:
        return self.solutions[0][1]

    @property
    def unique(self) -> bool:
        return len(self.solutions) == 1

    @property
    def tau_yy_over_G(self) -> list[float]:
        if self.nu == 0.0:
            return [float("nan")] * len(self.solutions)
        return [2.0 * self.v_star / (c * self.nu) for c, _ in self.solutions]

    @property
    def mu_star(self) -> list[float]:
        return [self.mu - self.T / (-t) for t in self.tau_yy_over_G]

    def to_dict(self) -> dict:
        return {"c": self.c, "b": self.b, "unique": self.unique, "n_solutions": len(self.solutions),
                "solutions": [{"c": c, "b": b, "tau_yy_over_G": t, "mu_star": m}
                              for (c, b), t, m in zip(self.solutions, self.tau_yy_over_G, self.mu_star)],
                "T": self.T, "v": self.v, "v_star": self.v_star, "nu": self.nu, "mu": self.mu,
                "system": self.system}

    def to_xarray(self) -> xr.Dataset:
        cs, bs = (np.array([s[i] for s in self.solutions]) for i in (0, 1))
        ds = xr.Dataset(
            {"c": ("solution", cs, {"units": "1", "long_name": "wave speed c/c2"}),
             "b": ("solution", bs, {"units": "1", "long_name": "period / stick length"}),
             "mu_star": ("solution", np.array(self.mu_star), {"units": "1", "long_name": "apparent friction implied by [26]"})},
            attrs={k: v for k, v in self.to_dict().items() if k in ("T", "v", "v_star", "nu", "mu", "system", "n_solutions")}
            | {"unique": int(self.unique)})
        ds.coords["solution"] = ("solution", np.arange(len(cs)), {"units": "1", "long_name": "solution number"})
        return finish(ds, "stick-slip wave of the half-space: direct problem", "halfspace")


def _loading(T, v, v_star):
    T, v, vs = Q.check("T", T), Q.check("v", v), Q.check("v_star", v_star)
    if vs == 0.0:
        raise NoSolutionError("v_star = 0: [54]-[55] only have the trivial solution v = 0, T = 0, "
                              "so no stick-slip wave carries a loading with T > 0")
    return T, v, vs


def direct_problem(T, v, v_star, *, nu, mu, system: str = "printed", n_grid: int = 4001) -> DirectSolution:
    """Find every wave ``(cbar, b)``, ``-1 < cbar < 0``, ``b > 1``, carrying the loading.

    Parameters
    ----------
    T : float
        ``T*/G`` > 0.
    v, v_star : float
        ``V/c2`` > 0 and ``V*/c2`` > 0.
    nu, mu : float
        Poisson's ratio in [0, 0.5), local friction coefficient > 0.
    system : {"printed", "text"}
        As in `stickslip.halfspace.inverse_problem`.
    n_grid : int
        Number of grid points used to bracket roots in ``cbar``.

    Raises
    ------
    NoSolutionError
        No wave carries this loading (the message says what was searched).
    """
    T, v, vs = _loading(T, v, v_star)
    k = system_factor(system)
    n_grid = Q.check("n_grid", n_grid)
    grid = cbar_grid(n_grid)
    rd = radok(grid, nu, mu)
    b, F = _residual(rd, T, v, vs, k)
    idx = np.flatnonzero(_brackets(b, F))

    def f(c):
        return float(_residual(radok(c, nu, mu), T, v, vs, k)[1])

    sols, res = [], []
    for i in idx:
        lo, hi = grid[i], grid[i + 1]
        c = lo if F[i] == 0 else (hi if F[i + 1] == 0 else brentq(f, lo, hi, xtol=1e-15, rtol=1e-15))
        if sols and abs(c - sols[-1][0]) < 1e-12:
            continue
        bc = float(_b_of_c(radok(c, nu, mu), T, v, vs, k))
        if bc > 1.0:
            sols.append((float(c), bc))
            res.append(f(c))
    sols.sort()
    if not sols:
        valid = b > 1.0
        where = ("b(c) <= 1 for every c in (-1, 0) (this needs v > v_star)" if not valid.any()
                 else f"F(c) keeps one sign where b(c) > 1 (min |F| = {np.min(np.abs(F[valid])):.3g})")
        raise NoSolutionError(
            f"no stick-slip wave for T = {T:g}, v = {v:g}, v_star = {vs:g} (nu = {nu:g}, mu = {mu:g}, "
            f"system {system!r}): searched -1 < c < 0 on {n_grid} points with b eliminated by the second "
            f"equation; {where}")
    return DirectSolution(T=T, v=v, v_star=vs, nu=float(nu), mu=float(mu), system=system,
                          solutions=tuple(sols), residuals=tuple(res))


def _bisect(nu, mu, T, v, vs, k, lo, hi, F_lo, iters=60):
    """Vectorised bisection of ``F`` on brackets ``[lo, hi]`` (arrays)."""
    lo, hi, F_lo = lo.copy(), hi.copy(), F_lo.copy()
    for _ in range(iters):
        mid = 0.5 * (lo + hi)
        _, F_mid = _residual(radok(mid, nu, mu), T, v, vs, k)
        left = np.sign(F_mid) == np.sign(F_lo)
        lo = np.where(left, mid, lo)
        F_lo = np.where(left, F_mid, F_lo)
        hi = np.where(left, hi, mid)
    return 0.5 * (lo + hi)


#: Why a direct map holds NaN (a variable's ``comment``).
NO_SOLUTION = "NaN past a point's last solution (n_solutions of them; points have different numbers)"


def direct_map(v_ratio, T_ratio, *, nu, mu, system: str = "printed", n_grid: int = 2001,
               max_solutions: int = 3) -> xr.Dataset:
    """The solution ``(cbar, b)`` over the loading plane ``(v/v*, T/v*)``.

    Returns a Dataset with dims ``(v_ratio, T_ratio, solution)``: ``c`` and ``b`` (NaN
    where there is no ``solution``-th wave) and ``n_solutions`` (0: no wave, > 1: not
    unique). Roots are bracketed on the ``cbar`` grid as in `direct_problem` and refined
    by vectorised bisection.
    """
    k = system_factor(system)
    v_ratio = np.atleast_1d(Q["v_ratio"].check_array(v_ratio))
    T_ratio = np.atleast_1d(Q["T_ratio"].check_array(T_ratio))
    for name, arr in (("v_ratio", v_ratio), ("T_ratio", T_ratio)):
        if arr.size == 0 or arr.ndim != 1:
            raise ParameterError(name, arr.tolist(), "a number or a non-empty list of numbers")
    n_grid, max_solutions = Q.check("n_grid", n_grid), Q.check("max_solutions", max_solutions)
    grid = cbar_grid(n_grid)
    rd = radok(grid, nu, mu)
    V, TT = np.meshgrid(v_ratio, T_ratio, indexing="ij")
    Vf, Tf = V.reshape(-1, 1), TT.reshape(-1, 1)
    npts = Vf.shape[0]
    chunk = max(1, 2_000_000 // n_grid)  # bounds the (loading x grid) work arrays
    rows, cols, F_lo = [], [], []
    for start in range(0, npts, chunk):
        b, F = _residual(rd, Tf[start:start + chunk], Vf[start:start + chunk], 1.0, k)
        r, c = np.nonzero(_brackets(b, F))
        rows.append(r + start)
        cols.append(c)
        F_lo.append(F[r, c])
    rows, cols, F_lo = np.concatenate(rows), np.concatenate(cols), np.concatenate(F_lo)
    c_root = _bisect(nu, mu, Tf[rows, 0], Vf[rows, 0], 1.0, k, grid[cols], grid[cols + 1], F_lo)
    b_root = _b_of_c(radok(c_root, nu, mu), Tf[rows, 0], Vf[rows, 0], 1.0, k)
    C = np.full((npts, max_solutions), np.nan)
    B = np.full((npts, max_solutions), np.nan)
    count = np.zeros(npts, dtype=int)
    for r, c, bb in zip(rows, c_root, b_root):
        if bb > 1.0:
            if count[r] < max_solutions:
                C[r, count[r]], B[r, count[r]] = c, bb
            count[r] += 1
    shape = (v_ratio.size, T_ratio.size, max_solutions)
    return xr.Dataset(
        {"c": (("v_ratio", "T_ratio", "solution"), C.reshape(shape), {"units": "1", "long_name": "wave speed c/c2",
                                                                      "comment": NO_SOLUTION}),
         "b": (("v_ratio", "T_ratio", "solution"), B.reshape(shape), {"units": "1", "long_name": "period / stick length",
                                                                      "comment": NO_SOLUTION}),
         "n_solutions": (("v_ratio", "T_ratio"), count.reshape(shape[:2]), {"units": "1"})},
        coords={"v_ratio": ("v_ratio", v_ratio, {"units": "1", "long_name": "v / v*"}),
                "T_ratio": ("T_ratio", T_ratio, {"units": "1", "long_name": "T / v*"}),
                "solution": np.arange(max_solutions)},
        attrs={"nu": float(nu), "mu": float(mu), "system": system, "n_grid": n_grid})
