"""Interface fields of a periodic stick-slip wave (eqs [34]-[48]).

Scaling: lengths in units of the stick length ``a = 1``, period ``b``; stick ``ST =
[0, 1)``, slip ``SL = [1, b)`` (mod ``b``); stresses over ``G``; velocities over ``c2``.
The elastic body is the lower half-plane; ``Phi = phi1'`` is continued to the upper one
by ``Phi(z) = -conj(Phi(conj z))`` (eq. [39]), so on the interface ``Phi+ = -conj(Phi-)``
and ``Phi-`` carries the physical values: ``sigma_yy = gamma2 Re Phi-``,
``sigma_xy = gamma1 Im Phi-``, ``u_x,x = -(1 - beta1 beta2) Re Phi- / G`` ([34]-[37]).

Riemann-Hilbert problem ([41], [44]): ``Phi+ - Phi- = f1`` on ST,
``Phi+ - g Phi- = f2`` on SL, ``g = -exp(2 i pi alpha)``. Its periodic canonical
function (not printed in the paper) is

    X(z) = s(z)^(-lam),   s(z) = sin(pi (z - b)/b) / sin(pi (z - a)/b),   lam = 1/2 - alpha,

with the principal power: ``s`` maps each half-plane into itself, is > 0 on ST and
< 0 on SL, so ``X+ = g X-`` on SL, ``X+ = X-`` on ST; ``X ~ (z - b)^(-lam)`` at the
slip->stick point ``b`` and ``X ~ (z - a)^lam`` at the stick->slip point ``a``. The
periodic Cauchy integral [46] (kernel ``cot(pi (t - z)/b)/(2 i b)``, ``C0 = 0``) has
the closed form, in the lower half-plane,

    Phi(z) = A' + i beta0 X(z),   A' = R + i (T/gamma1 - R cot(pi lam)),
    R = (v - v*)/(cbar (1 - beta1 beta2)),   beta0 = -Im(A'/X_inf),

``X_inf = X(-i inf) = exp(i pi lam (b - 1)/b)``. At depth ``Phi -> X_inf Re(A'/X_inf)``:
the perturbation decays (the remote stresses are really ``tau*``) only if

    R sin(pi lam/b) + (T/Gm) sin(pi lam (b - 1)/b) = 0,   Gm = |gamma1 + i mu gamma2|,

the exact periodic form of [50] (see the theory note). `StickSlipWave.far_field`
reports the departure; `decaying_wave` builds the wave that satisfies it.
"""

from __future__ import annotations

from typing import ClassVar

from dataclasses import dataclass, field

import math

import numpy as np
import lazy_loader as lazy
from scipy.special import roots_jacobi

from ..results import Result
from ..cf import finish
from ..quantities import HALFSPACE as Q
from ..errors import NoSolutionError, ParameterError
from .arrays import MAX_B, b_array
from .inverse import inverse_problem
from .waves import Radok, radok
from .. import validation as check

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it

#: The totals ``Sigma_*`` are ``stress_*`` in datasets and files: a netCDF name may not differ from
#: another (``sigma_*``, the perturbation) by case alone (CF 2.3).
FILE_NAMES = {"Sigma_yy": "stress_yy", "Sigma_xy": "stress_xy"}

__all__ = ["StickSlipWave", "InterfaceFields", "wave_from_inverse", "decaying_wave", "decaying_velocity",
           "periodic_X"]


def periodic_X(z, b, lam):
    """Canonical function ``X(z) = s(z)^(-lam)`` (principal branch), ``Im z != 0``, ``a = 1``."""
    try:
        z = np.asarray(z, dtype=complex)
    except (TypeError, ValueError):
        raise ParameterError("z", z, "a complex number or an array of them") from None
    if z.size == 0 or not np.isfinite(z).all():
        raise ParameterError("z", z.tolist() if z.size <= 8 else f"{z.size} values", "finite complex numbers")
    b, lam = check.finite_array("b", b), check.finite_array("lam", lam)
    if (b <= 1.0).any():
        raise ParameterError("b", b.tolist() if b.size <= 8 else f"{b.size} values", "> 1 (the period over the slip zone)")
    s = np.sin(np.pi * (z - b) / b) / np.sin(np.pi * (z - 1.0) / b)
    return np.exp(-lam * np.log(s))


def _abs_s(xi, b):
    """``|s(x)|`` on the axis for ``xi = x mod b`` in [0, b), accurate near 0, 1 and b."""
    num = np.sin(np.pi * np.minimum(xi, b - xi) / b)
    den = np.abs(np.sin(np.pi * (xi - 1.0) / b))
    with np.errstate(divide="ignore"):
        return num / den


def _x_of_s(S, b):
    """Position ``x`` in [0, b) where ``s(x) = S`` (``S > 0``: in ST, ``S < 0``: in SL)."""
    u = np.arctan2(S * np.sin(np.pi / b), 1.0 + S * np.cos(np.pi / b))
    u = np.where(u < 0, u + np.pi, u)
    return b * u / np.pi


def decaying_velocity(b, cbar, T, v_star, *, nu, mu):
    """``v`` for which the periodic field decays at depth, for given ``(b, cbar, T, v*)``.

    ``R = -(T/Gm) sin(pi lam (b-1)/b)/sin(pi lam/b)``, ``v = v* + R cbar (1 - beta1 beta2)``.
    """
    rd = radok(cbar, nu, mu)
    b = b_array(b)
    # T of a computed solution, any real: the formula is linear in T (physical loadings have T > 0)
    T, v_star = Q["T_result"].check_array(T, "T"), Q.check("v_star", v_star)
    lam = rd.lam
    R = -(T / rd.gamma_mod) * np.sin(np.pi * lam * (b - 1.0) / b) / np.sin(np.pi * lam / b)
    return v_star + R * rd.cbar * rd.one_minus_b1b2


@dataclass(frozen=True, eq=False, repr=False)
class InterfaceFields(Result):
    """Fields along the interface at points ``x`` (one period: ST = [0, 1), SL = [1, b)).

    Stresses are perturbations over ``G`` (``sigma_*``) and totals with the remote
    stresses (``Sigma_* = tau*_* + sigma_*``); velocities over ``c2``.
    """

    MODEL: ClassVar[str] = "halfspace"

    wave: "StickSlipWave"
    x: np.ndarray
    slip: np.ndarray
    phi: np.ndarray
    sigma_yy: np.ndarray
    sigma_xy: np.ndarray
    sigma_xx: np.ndarray
    u_xx: np.ndarray
    material_velocity: np.ndarray
    slip_velocity: np.ndarray
    Sigma_yy: np.ndarray
    Sigma_xy: np.ndarray

    @property
    def slip_residual(self) -> float:
        """max over SL of ``|sigma_xy + mu sigma_yy - T| / T`` (condition [40])."""
        w = self.wave
        r = self.sigma_xy + w.mu * self.sigma_yy - w.T
        return float(np.max(np.abs(r[self.slip]), initial=0.0) / w.T)

    @property
    def stick_residual(self) -> float:
        """max over ST of ``|V - U_dot| / |V - V*|`` (stick: ``u_x,x = -(V - V*)/c``, [44])."""
        w = self.wave
        return float(np.max(np.abs(self.slip_velocity[~self.slip]), initial=0.0) / abs(w.v - w.v_star))

    def to_dict(self) -> dict:
        """The wave's scalars, the residuals of the fields and their size (JSON-ready)."""
        return {**self.wave.summary(), "points": int(self.x.size), "slip_residual": float(self.slip_residual),
                "stick_residual": float(self.stick_residual), "slip_fraction": float(np.mean(self.slip))}

    def to_xarray(self) -> xr.Dataset:
        w = self.wave
        one = {"units": "1"}
        data = {
            "zone": (self.slip.astype(np.int8), {"long_name": "0: stick (ST), 1: slip (SL)"}),
            "sigma_yy": (self.sigma_yy, {"long_name": "perturbation normal stress sigma_yy/G"}),
            "sigma_xy": (self.sigma_xy, {"long_name": "perturbation shear stress sigma_xy/G"}),
            "sigma_xx": (self.sigma_xx, {"long_name": "perturbation stress sigma_xx/G"}),
            FILE_NAMES["Sigma_yy"]: (self.Sigma_yy, {"long_name": "total normal stress Sigma_yy = (tau*_yy + sigma_yy)/G"}),
            FILE_NAMES["Sigma_xy"]: (self.Sigma_xy, {"long_name": "total shear stress Sigma_xy = (tau*_xy + sigma_xy)/G"}),
            "u_xx": (self.u_xx, {"long_name": "perturbation strain u_x,x"}),
            "material_velocity": (self.material_velocity, {"long_name": "material velocity (V* - c u_x,x)/c2"}),
            "slip_velocity": (self.slip_velocity, {"long_name": "slip velocity (V - U_dot)/c2"}),
            "phi_re": (self.phi.real, {"long_name": "Re Phi-/G"}),
            "phi_im": (self.phi.imag, {"long_name": "Im Phi-/G"}),
        }
        ds = xr.Dataset({k: ("x", v, dict(one, **a)) for k, (v, a) in data.items()},
                        coords={"x": ("x", self.x, {"units": "1", "long_name": "x / a (moving frame)"})})
        ds.attrs.update(w.summary())
        ds.attrs.update({"slip_residual": self.slip_residual, "stick_residual": self.stick_residual})
        ds["zone"] = ds["zone"].astype(np.int8)
        ds["zone"].attrs.update({"long_name": "zone of the interface", "flag_values": np.array([0, 1], np.int8),
                                 "flag_meanings": "stick slip"})
        return finish(ds, "interface fields of a stick-slip wave of the half-space", "halfspace")


@dataclass(frozen=True, repr=False)
class StickSlipWave(Result):
    """A periodic stick-slip wave and its potential (closed form of [46], ``C0 = 0``).

    Parameters
    ----------
    b : float
        Period (> 1) in units of the stick length.
    cbar : float
        Wave speed ``c/c2`` in (-1, 0).
    T : float
        ``T*/G`` > 0.
    v, v_star : float
        ``V/c2`` and ``V*/c2`` (``v != v_star``).
    nu, mu : float
        Poisson's ratio in [0, 0.5) and local friction coefficient > 0.
    tau_yy : float, optional
        Remote normal stress over ``G`` (< 0), for the total stresses; by default the
        value [26] implies, ``2 v*/(cbar nu)`` (NaN if ``nu = 0``).
    """

    MODEL: ClassVar[str] = "halfspace"

    b: float
    cbar: float
    T: float
    v: float
    v_star: float
    nu: float
    mu: float
    tau_yy: float | None = None
    rd: Radok = field(init=False, repr=False, compare=False)

    def __post_init__(self):
        object.__setattr__(self, "b", float(b_array(Q.check("b", self.b), most=MAX_B)))
        object.__setattr__(self, "cbar", Q.check("cbar", self.cbar, "c"))
        object.__setattr__(self, "T", Q.check("T", self.T))
        object.__setattr__(self, "v", Q.check("v", self.v))
        object.__setattr__(self, "v_star", Q.check("v_star", self.v_star))
        if self.v == self.v_star:
            raise ParameterError("v", self.v, f"!= v_star = {self.v_star:g} (no slip, no wave)")
        rd = radok(self.cbar, self.nu, self.mu)
        object.__setattr__(self, "rd", rd)
        object.__setattr__(self, "cbar", float(rd.cbar))
        object.__setattr__(self, "nu", rd.nu)
        object.__setattr__(self, "mu", rd.mu)
        if self.tau_yy is None:
            physical = self.nu > 0 and self.v_star > 0
            tau = 2.0 * self.v_star / (self.cbar * self.nu) if physical else float("nan")
        else:
            tau = Q.check("tau_yy", self.tau_yy)
        object.__setattr__(self, "tau_yy", float(tau))

    # --- constants of the closed form -------------------------------------------
    @property
    def lam(self) -> float:
        return float(self.rd.lam)

    @property
    def alpha(self) -> float:
        return float(self.rd.alpha)

    @property
    def R(self) -> float:
        """``Re Phi-`` on ST: ``(v - v*)/(cbar (1 - beta1 beta2))``."""
        return (self.v - self.v_star) / (self.cbar * float(self.rd.one_minus_b1b2))

    @property
    def A(self) -> complex:
        """``A' = (f2 - f1)/(1 - g)``: ``Phi-`` at the stick->slip point ``a``."""
        return complex(self.R, self.T / float(self.rd.gamma1) - self.R / np.tan(np.pi * self.lam))

    @property
    def X_inf(self) -> complex:
        return complex(np.exp(1j * np.pi * self.lam * (self.b - 1.0) / self.b))

    @property
    def beta0(self) -> float:
        """Coefficient of ``i X`` (real: the symmetry [39] holds because of alpha)."""
        return -float((self.A / self.X_inf).imag)

    @property
    def far_field(self) -> complex:
        """``Phi(-i inf)``: the uniform stress left at depth (0 for a consistent wave)."""
        return self.X_inf * (self.A / self.X_inf).real

    @property
    def decay_residual(self) -> float:
        """``|Phi(-i inf)| / |A'|``: 0 iff the exact periodic condition holds."""
        return abs(self.far_field) / abs(self.A)

    @property
    def tau_xy(self) -> float:
        """Remote shear stress over G — ``tau*_xy = -T - mu tau*_yy`` (from the definition of T*)."""
        return -self.T - self.mu * self.tau_yy

    @property
    def mu_star(self) -> float:
        """Apparent friction ``-tau*_xy/tau*_yy`` implied by ``T`` and ``tau*_yy``."""
        return -self.tau_xy / self.tau_yy

    @property
    def singularity_exponents(self) -> dict:
        """``Phi ~ |x - b|^(alpha - 1/2)`` at SL->ST; ``Phi - Phi(a) ~ |x - a|^(1/2 - alpha)`` at ST->SL."""
        return {"slip_to_stick": self.alpha - 0.5, "stick_to_slip": 0.5 - self.alpha}

    @property
    def stress_intensity(self) -> float:
        """``k`` in ``sigma_yy ~ k (b - x)^(alpha - 1/2)`` as ``x -> b-`` (on SL; > 0: tensile)."""
        lam, b = self.lam, self.b
        scale = (np.pi / (b * np.sin(np.pi * (b - 1.0) / b))) ** (-lam)
        return float(-self.rd.gamma2 * self.beta0 * np.sin(np.pi * lam) * scale)

    # --- potentials -------------------------------------------------------------
    def phi(self, z):
        """``Phi(z)/G`` in the lower half-plane (closed form)."""
        z = np.asarray(z, dtype=complex)
        if np.any(z.imag >= 0):
            raise ParameterError("z", z[z.imag >= 0].flat[0], "in the lower half-plane (Im z < 0)")
        return self.A + 1j * self.beta0 * periodic_X(z, self.b, self.lam)

    def X_boundary(self, x):
        """``X-(x)``: ``|s|^(-lam)`` on ST, ``|s|^(-lam) exp(i pi lam)`` on SL."""
        mod, on_slip = self._X_mod(x)
        return np.where(on_slip, mod * np.exp(1j * np.pi * self.lam), mod + 0j)

    def _X_mod(self, x):
        xi = np.mod(np.asarray(x, dtype=float), self.b)
        with np.errstate(divide="ignore"):
            return _abs_s(xi, self.b) ** (-self.lam), xi >= 1.0

    def phi_boundary(self, x):
        """``Phi-(x)/G`` on the interface (the limit from the body); infinite at ``x = b``."""
        mod, on_slip = self._X_mod(x)
        c, s = np.cos(np.pi * self.lam), np.sin(np.pi * self.lam)
        re = np.where(on_slip, self.A.real - self.beta0 * s * np.where(on_slip, mod, 0.0), self.A.real)
        im = self.A.imag + self.beta0 * np.where(on_slip, c, 1.0) * mod
        out = np.empty(np.shape(re), dtype=complex)
        out.real, out.imag = re, im
        return out

    def phi_quadrature(self, z, n: int = 16):
        """``Phi(z)/G`` by composite Gauss quadrature of the periodic Cauchy integral [46].

        ``Phi = X(z)/(2 i b) * integral over a period of f(t)/X+(t) cot(pi (t - z)/b) dt``,
        ``f = f1 = -2R`` on ST and ``f2`` on SL (``f2/X+ = -(2T/Gm) |s|^lam``, real). An
        independent route to `phi` for ``Im z < 0``. Each of ST, SL is cut into panels of
        length at most ``2 min|Im z|`` (at most 4000), halved geometrically towards the
        ends down to ``min|Im z|/4``; the two end panels use Gauss-Jacobi rules for the
        end behaviour ``|s|^lam ~ |t - b|^lam, |t - a|^-lam``, the others Gauss-Legendre,
        ``n`` nodes each.
        """
        z = np.asarray(z, dtype=complex)
        if np.any(z.imag >= 0):
            raise ParameterError("z", z[z.imag >= 0].flat[0], "in the lower half-plane (Im z < 0)")
        n = Q.check("n", n)
        b, lam = self.b, self.lam
        d = float(np.min(-z.imag))
        xl, wl = np.polynomial.legendre.leggauss(n)

        def nodes(lo, hi, e_lo, e_hi):
            """Nodes and weights for integral of (t-lo)^e_lo (hi-t)^e_hi h(t) dt; returns the
            weights already divided by nothing: the caller multiplies by h(t) only."""
            L = hi - lo
            m = int(min(max(np.ceil(L / (2.0 * d)), 2), 4000))
            inner = np.linspace(0.0, L, m + 1)
            head, size = [], inner[1]
            while size > d / 4 and len(head) < 60:
                size /= 2
                head.append(size)
            cuts = np.unique(np.concatenate([inner, head, L - np.array(head + [0.0])]))
            t_all, w_all = [], []
            for i, (u0, u1) in enumerate(zip(cuts[:-1], cuts[1:])):
                h = 0.5 * (u1 - u0)
                if i == 0 or i == len(cuts) - 2:
                    ea, eb = (e_lo, 0.0) if i == 0 else (0.0, e_hi)
                    xj, wj = roots_jacobi(n, eb, ea)  # weight (1-x)^eb (1+x)^ea
                    t = lo + u0 + h * (xj + 1.0)
                    # the Jacobi rule carries the singular end factor; restore the other one
                    other = (hi - t) ** e_hi if i == 0 else (t - lo) ** e_lo
                    w = wj * h ** (1.0 + ea + eb) * other
                else:
                    t = lo + u0 + h * (xl + 1.0)
                    w = wl * h * (t - lo) ** e_lo * (hi - t) ** e_hi
                t_all.append(t)
                w_all.append(w)
            t = np.concatenate(t_all)
            return t, np.concatenate(w_all), (t - lo) ** e_lo * (hi - t) ** e_hi

        t1, w1, wt1 = nodes(b, b + 1.0, lam, -lam)            # ST, s^lam ~ (t-b)^lam (b+1-t)^-lam
        t2, w2, wt2 = nodes(1.0, b, -lam, lam)                # SL, |s|^lam ~ (t-1)^-lam (b-t)^lam
        d1 = -2.0 * self.R * _abs_s(np.mod(t1, b), b) ** lam / wt1
        d2 = -(2.0 * self.T / float(self.rd.gamma_mod)) * _abs_s(t2, b) ** lam / wt2
        zz = z[..., None]
        integral = (np.sum(w1 * d1 / np.tan(np.pi * (t1 - zz) / b), axis=-1)
                    + np.sum(w2 * d2 / np.tan(np.pi * (t2 - zz) / b), axis=-1))
        return periodic_X(z, b, lam) * integral / (2j * b)

    # --- fields and diagnostics ---------------------------------------------------
    def fields(self, x=None, n: int = 2001) -> InterfaceFields:
        """Interface fields at ``x`` (default: ``n`` points over one period, clustered at
        the transitions ``0 (= b), 1``)."""
        if x is None:
            n = Q.check("points", n)
            n_st = max(n // 4, 2)
            s_st = (np.arange(n_st) + 0.5) / n_st
            s_sl = (np.arange(max(n - n_st, 2)) + 0.5) / max(n - n_st, 2)
            st = 0.5 * (1.0 - np.cos(np.pi * s_st))
            sl = 1.0 + (self.b - 1.0) * 0.5 * (1.0 - np.cos(np.pi * s_sl))
            x = np.concatenate([st, sl])
        x = Q["x"].check_array(x)
        rd = self.rd
        ph = self.phi_boundary(x)
        re, im = ph.real, ph.imag
        u_xx = -float(rd.one_minus_b1b2) * re
        sxx_coef = -self.cbar**2 - 2.0 * float(rd.beta1) * (float(rd.beta1) - float(rd.beta2))
        mat = self.v_star - self.cbar * u_xx
        slip = np.mod(x, self.b) >= 1.0
        syy, sxy = float(rd.gamma2) * re, float(rd.gamma1) * im
        return InterfaceFields(wave=self, x=x, slip=slip, phi=ph, sigma_yy=syy, sigma_xy=sxy,
                               sigma_xx=sxx_coef * re, u_xx=u_xx, material_velocity=mat,
                               slip_velocity=self.v - mat, Sigma_yy=self.tau_yy + syy, Sigma_xy=self.tau_xy + sxy)

    def tensile_zone(self) -> tuple[float, float] | None:
        """``(x_t, b)``: where the total ``Sigma_yy > 0`` near the slip->stick point, or None.

        On SL ``Sigma_yy = tau*_yy + gamma2 (R - beta0 sin(pi lam) |X|)`` and ``|X|``
        grows monotonically from 0 at ``a`` to infinity at ``b``, so the zone is an
        interval ending at ``b``; ``x_t`` solves ``s(x_t) = -|X_t|^(-1/lam)`` in closed form.
        """
        g2, lam = float(self.rd.gamma2), self.lam
        if not np.isfinite(self.tau_yy):
            return None
        if self.beta0 >= 0:
            return None
        X_t = (self.tau_yy / g2 + self.R) / (self.beta0 * np.sin(np.pi * lam))
        if X_t <= 0:
            return (1.0, self.b)  # tensile on the whole slip zone
        return float(_x_of_s(-X_t ** (-1.0 / lam), self.b)), self.b

    def stick_violation(self) -> list[tuple[float, float]]:
        """Intervals of ST where ``|Sigma_xy| > -mu Sigma_yy`` (Coulomb's inequality fails).

        On ST ``Sigma_xy = p + q X`` with ``X`` real, decreasing from infinity at ``b``
        (x = 0) to 0 at ``a`` (x = 1), and ``Sigma_yy`` constant, so the failing set is at
        most an interval at each end of ST. Beyond the paper, which does not check it.
        """
        g1 = float(self.rd.gamma1)
        m = -self.mu * (self.tau_yy + float(self.rd.gamma2) * self.R)
        if not np.isfinite(m):
            return []
        if m <= 0:
            return [(0.0, 1.0)]
        p, q = self.tau_xy + g1 * self.A.imag, g1 * self.beta0
        if q == 0:
            return [] if abs(p) <= m else [(0.0, 1.0)]
        lo, hi = sorted(((p - m) / -q, (p + m) / -q))  # admissible X in [lo, hi]
        out = []
        if hi <= 0:
            return [(0.0, 1.0)]
        out.append((0.0, float(_x_of_s(hi ** (-1.0 / self.lam), self.b))))
        if lo > 0:
            out.append((float(_x_of_s(lo ** (-1.0 / self.lam), self.b)), 1.0))
        return out

    def to_dict(self) -> dict:
        """The scalars describing the wave (`summary`)."""
        return self.summary()

    def to_xarray(self, n: int = 2001) -> xr.Dataset:
        """The interface fields over one period (``fields(n=n).to_xarray()``)."""
        return self.fields(n=n).to_xarray()

    def summary(self) -> dict:
        """Scalars describing the wave (JSON-ready)."""
        rd = self.rd
        tz = self.tensile_zone()
        sv = self.stick_violation()
        ff = self.far_field
        return {"b": self.b, "c": self.cbar, "T": self.T, "v": self.v, "v_star": self.v_star,
                "nu": self.nu, "mu": self.mu, "tau_yy": self.tau_yy, "tau_xy": self.tau_xy,
                "mu_star": self.mu_star, "alpha": self.alpha, "beta1": float(rd.beta1),
                "beta2": float(rd.beta2), "gamma1": float(rd.gamma1), "gamma2": float(rd.gamma2),
                "exponent_slip_to_stick": self.alpha - 0.5, "exponent_stick_to_slip": 0.5 - self.alpha,
                "stress_intensity": self.stress_intensity, "beta0": self.beta0,
                "far_field_re": float(ff.real), "far_field_im": float(ff.imag),
                "far_field_sigma_yy": float(rd.gamma2) * float(ff.real),
                "far_field_sigma_xy": float(rd.gamma1) * float(ff.imag),
                "decay_residual": self.decay_residual,
                **({} if tz is None else {"tensile_zone_start": tz[0]}),  # left out when there is none
                "tensile_zone_length": 0.0 if tz is None else tz[1] - tz[0],
                "stick_violation_length": float(sum(h - l for l, h in sv))}


def wave_from_inverse(b, cbar, v_star, *, nu, mu, system: str = "printed", tau_yy=None) -> StickSlipWave:
    """The wave with ``(v, T)`` from the paper's inverse problem [54]-[55]."""
    sol = inverse_problem(b, cbar, v_star, nu=nu, mu=mu, system=system)
    _physical(sol.T, sol.v, "T and v from the inverse problem", dict(b=b, cbar=cbar, v_star=v_star))
    return StickSlipWave(b=float(b), cbar=float(cbar), T=float(sol.T), v=float(sol.v), v_star=float(v_star),
                         nu=nu, mu=mu, tau_yy=tau_yy)


def _physical(T, v, what: str, given: dict) -> None:
    """A wave whose computed ``T`` or ``v`` leaves its declared range is no answer (a traction
    beyond the shear modulus, a supersonic slider): a `NoSolutionError` saying which and why."""
    for name, value in (("T", float(T)), ("v", float(v))):
        q = Q[name]
        if not (math.isfinite(value) and value in q.range):
            args = ", ".join(f"{k} = {float(x):.6g}" for k, x in given.items())
            raise NoSolutionError(f"no wave for {args}: {what} give {name} = {value:.4g}, outside {q.range.interval} "
                                  f"({q.why})")


def decaying_wave(b, cbar, T, v_star, *, nu, mu, tau_yy=None) -> StickSlipWave:
    """The wave with ``v`` from the exact decay condition (`decaying_velocity`)."""
    v = float(decaying_velocity(b, cbar, T, v_star, nu=nu, mu=mu))
    _physical(T, v, "the decay condition's v", dict(b=b, cbar=cbar, T=T, v_star=v_star))
    return StickSlipWave(b=float(b), cbar=float(cbar), T=float(T), v=v, v_star=float(v_star), nu=nu, mu=mu,
                         tau_yy=tau_yy)
