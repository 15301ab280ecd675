"""Inverse problem: the loading ``(v, T)`` of a stick-slip wave ``(cbar, b)`` (eqs [52]-[58]).

With ``a = 1`` (stick length), ``b`` the period, ``v = V/c2``, ``v* = V*/c2``,
``T = T*/G`` and ``K = pi (1/2 - alpha)/cos(pi alpha)``, ``Gm = gamma1 cos(pi alpha) +
mu gamma2 sin(pi alpha) = |gamma1 + i mu gamma2|``, the two relations of section 4 are
linear in ``(v, T)``:

    [54]  (K (b-1) - b) v/cbar - pi lam (b-1) (1 - beta1 beta2)/(2 gamma1) T = K (b-1) v*/cbar
    [55]  k Gm/(1 - beta1 beta2) v/cbar + (b - 1) T = k Gm v*/((1 - beta1 beta2) cbar)

with ``lam = 1/2 - alpha``. [54] is [52] rearranged. The printed [55] has ``k = 2``; the
equation [53] it is supposed to come from has ``k = 1``. ``system="printed"`` (default,
the paper's [54]-[58] and its claims ``D < 0``, ``H > 0``) uses ``k = 2``;
``system="text"`` uses [52]-[53] as printed (``k = 1``). See ``docs/theory/halfspace.md``
and the errata draft for why the two differ and what the exact periodic solution says.

Closed forms (``tan(pi alpha) = mu gamma2/gamma1`` makes ``Gm = gamma1/sin(pi lam)``):

    D = (b - 1) H / (gamma1 cbar)                                  [56]
    H = gamma1 (K (b - 1) - b) + k pi lam Gm / 2                    [57]
      = gamma1 b (K - 1)                 (printed, k = 2)  > 0 for every b > 1, cbar
      = gamma1 ((K - 1) b - K/2)         (text, k = 1)     vanishes at b = K/(2(K-1)).

For the printed system ``v = v* K/(K - 1)`` does not depend on ``b`` (the paper's
``A(b, cbar)`` of [58] simplifies to ``-1/K``) and
``T = 2 gamma1 v* / (sin(pi lam)(K - 1)(1 - beta1 beta2)(-cbar)(b - 1))``.
"""

from __future__ import annotations

from typing import ClassVar

from dataclasses import dataclass

import math

import numpy as np
import lazy_loader as lazy
from scipy.optimize import brentq

from ..results import Result
from ..cf import finish
from ..quantities import HALFSPACE as Q
from ..errors import NoSolutionError, ParameterError
from .arrays import MAX_B_ALGEBRA, b_array
from .waves import Radok, radok

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

__all__ = ["SYSTEMS", "InverseSolution", "inverse_problem", "system_matrix", "determinant",
           "closed_form", "printed_closed_form", "inverse_map", "b_for_loading", "system_factor"]

SYSTEMS = {"printed": 2.0, "text": 1.0}
"""Factor ``k`` of the second equation: [55] as printed (2) or [53] as printed (1)."""


def system_factor(system: str) -> float:
    """The factor of the v-terms of the chosen system: 2 for the printed [54]-[55], 1 for [52]-[53]."""
    if not isinstance(system, str) or system not in SYSTEMS:
        raise ParameterError("system", system, "one of " + ", ".join(repr(s) for s in SYSTEMS))
    return SYSTEMS[system]


def _v_star(v_star) -> float:
    """``v* = V*/c2``: > 0 by [26] (``c < 0``, ``tau*_yy < 0``); 0 has no wave."""
    vs = Q.check("v_star", v_star)
    if vs == 0.0:
        raise NoSolutionError(
            "v_star = 0: equations [54]-[55] are homogeneous with a non-zero determinant, so "
            "the only solution is the trivial one v = 0, T = 0 (no stick-slip wave)")
    return vs


def _entries(b, rd: Radok, v_star: float, k: float):
    """Entries ``a11, a12, a21, a22, r1, r2`` of [54]-[55] in the unknowns ``(v, T)``."""
    c = rd.cbar
    bm1 = b - 1.0
    a11 = (rd.K * bm1 - b) / c
    a12 = -np.pi * rd.lam * bm1 * rd.one_minus_b1b2 / (2.0 * rd.gamma1)
    a21 = k * rd.gamma_mod / (rd.one_minus_b1b2 * c)
    r1 = rd.K * bm1 * v_star / c
    return a11, a12, a21, bm1, r1, a21 * v_star


def _H(b, rd: Radok, k: float):
    if k == 2.0:
        return rd.gamma1 * b * rd.K_minus_one
    return rd.gamma1 * (rd.K_minus_one * b - 0.5 * rd.K)


def system_matrix(b, cbar, v_star, nu, mu, system: str = "printed"):
    """Matrix ``M`` (shape ``(..., 2, 2)``) and right-hand side ``r`` (``(..., 2)``) of
    [54]-[55] in the unknowns ``(v, T)``."""
    k = system_factor(system)
    b = b_array(b)
    rd = radok(cbar, nu, mu)
    b, _ = np.broadcast_arrays(b, rd.cbar)
    a11, a12, a21, a22, r1, r2 = np.broadcast_arrays(*_entries(b, rd, Q.check("v_star", v_star), k))
    M = np.stack([np.stack([a11, a12], -1), np.stack([a21, a22], -1)], -2)
    return M, np.stack([r1, r2], -1)


def determinant(b, cbar, nu, mu, system: str = "printed"):
    """``(D, H)`` of [56]-[57]: ``D = (b - 1) H / (gamma1 cbar)`` is det of [54]-[55].

    Uses the simplified ``H`` (module docstring); the tests compare it with the printed
    [57] and with the determinant of `system_matrix`.
    """
    k = system_factor(system)
    b = b_array(b)
    rd = radok(cbar, nu, mu)
    H = _H(b, rd, k)
    return (b - 1.0) * H / (rd.gamma1 * rd.cbar), H


@dataclass(frozen=True, eq=False, repr=False)
class InverseSolution(Result):
    """Solution ``(v, T)`` of [54]-[55] for given ``(b, cbar, v*)`` (arrays, broadcast).

    ``v = V/c2`` (rigid body speed), ``T = T*/G`` (driving traction). ``D``, ``H`` are the
    determinant [56] and [57]; ``radok`` holds ``beta1, beta2, gamma1, gamma2, alpha``.
    """

    MODEL: ClassVar[str] = "halfspace"

    b: np.ndarray
    cbar: np.ndarray
    v_star: float
    system: str
    v: np.ndarray
    T: np.ndarray
    D: np.ndarray
    H: np.ndarray
    radok: Radok

    @property
    def admissible(self) -> np.ndarray:
        """Physically admissible loading — ``T > 0`` (``mu* < mu``) and ``v > v*`` (forward slip)."""
        return (self.T > 0) & (self.v > self.v_star)

    def to_dict(self) -> dict:
        """JSON-ready: floats for scalar input, nested lists otherwise."""
        rd = self.radok

        def out(x):
            x = np.asarray(x)
            return float(x) if x.ndim == 0 else x.tolist()

        return {"v": out(self.v), "T": out(self.T), "alpha": out(rd.alpha), "D": out(self.D),
                "beta1": out(rd.beta1), "beta2": out(rd.beta2), "gamma1": out(rd.gamma1),
                "gamma2": out(rd.gamma2), "H": out(self.H), "K": out(rd.K), "b": out(self.b),
                "c": out(self.cbar), "v_star": self.v_star, "nu": rd.nu, "mu": rd.mu,
                "c1_over_c2": rd.c1bar, "system": self.system}

    def to_xarray(self) -> xr.Dataset:
        shape = np.shape(self.v)
        dims = ("point",) if len(shape) == 1 else tuple(f"dim_{i}" for i in range(len(shape)))
        rd = self.radok
        one = {"units": "1"}

        def var(x, long_name):
            return (dims, np.broadcast_to(x, shape), dict(one, long_name=long_name))

        ds = xr.Dataset({
            "b": var(self.b, "period in units of the stick length a"),
            "c": var(self.cbar, "wave speed c/c2"),
            "v": var(self.v, "rigid body speed V/c2"),
            "T": var(self.T, "driving traction T*/G = (mu - mu*)(-tau*_yy)/G"),
            "D": var(self.D, "determinant of [54]-[55], eq. [56]"),
            "H": var(self.H, "H(b, c), eq. [57]"),
            "alpha": var(rd.alpha, "exponent alpha, tan(pi alpha) = mu gamma2/gamma1"),
            "beta1": var(rd.beta1, "beta1"), "beta2": var(rd.beta2, "beta2"),
            "gamma1": var(rd.gamma1, "gamma1"), "gamma2": var(rd.gamma2, "gamma2"),
        })
        ds.attrs.update({"v_star": self.v_star, "nu": rd.nu, "mu": rd.mu, "system": self.system,
                         "equations": "paper eqs [54]-[55]" if self.system == "printed" else "paper eqs [52]-[53]"})
        return finish(ds, "stick-slip wave of the half-space: inverse problem", "halfspace")


def inverse_problem(b, cbar, v_star, *, nu, mu, system: str = "printed") -> InverseSolution:
    """Solve [54]-[55] for ``(v, T)`` by Cramer's rule, vectorised over ``(b, cbar)``.

    Parameters
    ----------
    b : array_like
        Period in units of the stick length, every entry > 1.
    cbar : array_like
        Wave speed ``c/c2``, every entry in (-1, 0). Broadcast against ``b``.
    v_star : float
        ``V*/c2`` > 0 (eq. [26]). ``0`` raises `NoSolutionError`: the system is then
        homogeneous with ``D != 0`` and only ``v = T = 0`` solves it.
    nu, mu : float
        Poisson's ratio in [0, 0.5), local friction coefficient > 0.
    system : {"printed", "text"}
        Second equation as [55] (default) or as [53] (see module docstring).

    Raises
    ------
    NoSolutionError
        ``v_star == 0``, or (``system="text"``) ``D = 0`` at some point.
    """
    vs = _v_star(v_star)
    k = system_factor(system)
    b = b_array(b)
    rd = radok(cbar, nu, mu)
    a11, a12, a21, a22, r1, r2 = _entries(b, rd, vs, k)
    det = a11 * a22 - a12 * a21
    if np.any(det == 0.0):
        raise NoSolutionError("[54]-[55] are singular (D = 0) at some (b, c): no unique (v, T) there")
    v = (r1 * a22 - a12 * r2) / det
    T = (a11 * r2 - a21 * r1) / det
    H = _H(b, rd, k)
    D = (b - 1.0) * H / (rd.gamma1 * rd.cbar)
    b_arr, c_arr = np.broadcast_arrays(b, rd.cbar)
    return InverseSolution(b=b_arr, cbar=c_arr, v_star=vs, system=system, v=v, T=T, D=D, H=H, radok=rd)


def closed_form(b, cbar, v_star, *, nu, mu):
    """``(v, T)`` of the printed system in simplified closed form (derived, see module doc).

    ``v = v* K/(K - 1)`` and
    ``T = 2 gamma1 v* / (sin(pi lam) (K - 1) (1 - beta1 beta2) (-cbar) (b - 1))``.
    """
    vs = _v_star(v_star)
    b = b_array(b)
    rd = radok(cbar, nu, mu)
    v = vs * rd.K / rd.K_minus_one + 0 * b
    T = 2.0 * rd.gamma1 * vs / (np.sin(np.pi * rd.lam) * rd.K_minus_one * rd.one_minus_b1b2 * (-rd.cbar) * (b - 1.0))
    return v, T


def printed_closed_form(b, cbar, v_star, *, nu, mu, as_printed: bool = False):
    """``(v, T)`` from the paper's formulas after [58], term by term.

    ``v = v*/(1 + A(b, cbar))`` with the printed ``A``. The printed ``T`` has ``sin(pi
    alpha)`` and ``cos(pi alpha)`` in the last factor of its denominator where the
    solution of [54]-[55] has ``sin(2 pi alpha)`` and ``cos(2 pi alpha)`` (as in ``A``);
    ``as_printed=True`` evaluates the misprinted version (errata), the default the
    corrected one.
    """
    vs = _v_star(v_star)
    b = b_array(b)
    rd = radok(cbar, nu, mu)
    al, g1, g2, mu_, c = rd.alpha, rd.gamma1, rd.gamma2, rd.mu, rd.cbar
    pa = np.pi * al
    A = 4 * b * g1 * np.cos(pa) / (np.pi * (-1 + 2 * al) * (mu_ * g2 * np.sin(2 * pa) + g1 * (-1 + 2 * b + np.cos(2 * pa))))
    v = vs / (1.0 + A)
    m = 1.0 if as_printed else 2.0
    num = -4 * b * g1 * (g1 + g1 * np.cos(2 * pa) + mu_ * g2 * np.sin(2 * pa)) / ((b - 1) * (-1 + rd.beta1 * rd.beta2))
    den = c * (4 * b * g1 * np.cos(pa) + np.pi * (-1 + 2 * al) * (mu_ * g2 * np.sin(m * pa) + g1 * (-1 + 2 * b + np.cos(m * pa))))
    return v, num * vs / den


def inverse_map(b_values, c_values, v_star, *, nu, mu, systems=("printed", "text")) -> xr.Dataset:
    """``v``, ``T``, ``D``, ``H`` over the ``(b, c)`` grid for each system (an xarray Dataset)."""
    b_values = b_array(b_values, "b_values").ravel()
    c_values = Q["cbar"].check_array(c_values, "c_values").ravel()
    if not (b_values.size and c_values.size):
        raise ParameterError("b_values" if not b_values.size else "c_values", [], "a non-empty list of numbers")
    if isinstance(systems, str) or not (isinstance(systems, (list, tuple)) and systems):
        raise ParameterError("systems", systems, "a non-empty list of " + ", ".join(Q["system"].choices))
    systems = [Q.check("system", s, "systems") for s in systems]
    B, C = np.meshgrid(b_values, c_values, indexing="ij")
    rd = radok(c_values, nu, mu)
    out = {name: [] for name in ("v", "T", "D", "H")}
    for system in systems:
        sol = inverse_problem(B, C, v_star, nu=nu, mu=mu, system=system) if system == "printed" else \
            _inverse_allow_singular(B, C, v_star, nu, mu, system)
        for name in out:
            out[name].append(getattr(sol, name))
    attrs = {"v": "rigid body speed V/c2", "T": "driving traction T*/G", "D": "determinant [56]", "H": "H, eq. [57]"}
    ds = xr.Dataset(
        {name: (("system", "b", "c"), np.stack(vals), {"units": "1", "long_name": attrs[name]}) for name, vals in out.items()},
        coords={"system": list(systems), "b": ("b", b_values, {"units": "1", "long_name": "period / stick length"}),
                "c": ("c", c_values, {"units": "1", "long_name": "wave speed c/c2"})})
    for name in ("alpha", "beta1", "beta2", "gamma1", "gamma2", "K"):
        ds[name] = ("c", getattr(rd, name), {"units": "1"})
    ds.attrs.update({"v_star": float(v_star), "nu": float(nu), "mu": float(mu)})
    return ds


def _inverse_allow_singular(B, C, v_star, nu, mu, system):
    """Like `inverse_problem` but returns NaN where ``D = 0`` exactly (for maps)."""
    vs = _v_star(v_star)
    M, r = system_matrix(B, C, vs, nu, mu, system)
    D, H = determinant(B, C, nu, mu, system)
    det = M[..., 0, 0] * M[..., 1, 1] - M[..., 0, 1] * M[..., 1, 0]
    with np.errstate(divide="ignore", invalid="ignore"):
        v = np.where(det != 0, (r[..., 0] * M[..., 1, 1] - M[..., 0, 1] * r[..., 1]) / det, np.nan)
        T = np.where(det != 0, (M[..., 0, 0] * r[..., 1] - M[..., 1, 0] * r[..., 0]) / det, np.nan)
    rd = radok(C, nu, mu)
    return InverseSolution(b=B, cbar=C, v_star=vs, system=system, v=v, T=T, D=D, H=H, radok=rd)


def b_for_loading(cbar, T, v_star, *, nu, mu, system: str = "printed") -> float:
    """The period ``b`` at which the inverse problem gives the traction ``T`` at speed ``cbar``.

    For the printed system ``T`` decreases from infinity (``b -> 1``) to 0 (``b -> inf``)
    like ``1/(b - 1)``, so the root is unique; it is bracketed in ``log(b - 1)``.
    """
    def g(u):
        sol = inverse_problem(1.0 + np.exp(u), cbar, v_star, nu=nu, mu=mu, system=system)
        return float(np.log(sol.T / T))

    lo, hi = -30.0, math.log(MAX_B_ALGEBRA - 1.0) - 1e-9  # b from 1 + 1e-13 to (just under) the largest declared
    if g(lo) * g(hi) > 0:
        raise NoSolutionError(f"no period b in (1, {MAX_B_ALGEBRA:g}] gives the traction T = {T:g} at c = {cbar:g}")
    u = brentq(g, lo, hi, xtol=1e-14)
    return 1.0 + float(np.exp(u))
