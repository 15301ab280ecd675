"""Figure data, plots and checks for model 3 (paper Figure 14, maps of the inverse and
direct problems). Each figure: ``*_data(quick) -> xr.Dataset``, ``plot_*(ds, path)``,
``check_*(ds) -> list of (name, passed, measured, expected, detail)``.
"""

from __future__ import annotations

import numpy as np
import xarray as xr
from scipy.optimize import brentq

from .direct import cbar_grid, direct_map, direct_problem
from .fields import StickSlipWave, decaying_velocity
from .inverse import closed_form, inverse_map, inverse_problem, printed_closed_form
from .loading import loading_from_wave
from .waves import Material, radok, rayleigh_speed_ratio

__all__ = ["FIGURE14", "plot_fields", "figure14_data", "plot_figure14", "check_figure14",
           "inverse_map_data", "plot_inverse_map", "check_inverse_map",
           "direct_map_data", "plot_direct_map", "check_direct_map", "b_for_loading"]

FIGURE14 = dict(young=2.1e11, density=7850.0, nu=0.3, mu=0.5, mu_star=0.4, v_star=0.001, cbar=-0.7)
"""Parameters of the paper's Figure 14."""


def _rows(rows: list[tuple]) -> list[tuple]:
    """Plain Python types: ``(name, bool, measured, expected, detail)``."""
    def plain(x):
        if isinstance(x, (np.integer,)):
            return int(x)
        if isinstance(x, (np.floating, np.bool_)):
            return x.item()
        return x
    return [(str(n), bool(p), plain(m), plain(e), str(d)) for n, p, m, e, d in rows]


def b_for_loading(cbar, T, v_star, *, nu, mu, system: str = "printed") -> float:
    """The period ``b`` at which the inverse problem gives the traction ``T`` at speed ``cbar``.

    For the printed system ``T`` decreases from infinity (``b -> 1``) to 0 (``b -> inf``)
    like ``1/(b - 1)``, so the root is unique; it is bracketed in ``log(b - 1)``.
    """
    def g(u):
        sol = inverse_problem(1.0 + np.exp(u), cbar, v_star, nu=nu, mu=mu, system=system)
        return float(np.log(sol.T / T))

    u = brentq(g, -30.0, 30.0, xtol=1e-14)
    return 1.0 + float(np.exp(u))


def _wave_vars(waves: list[StickSlipWave], x: np.ndarray) -> dict:
    fields = [w.fields(x) for w in waves]
    out = {}
    for name in ("Sigma_yy", "Sigma_xy", "sigma_yy", "sigma_xy", "u_xx", "slip_velocity", "material_velocity"):
        out[name] = (("variant", "x"), np.stack([getattr(f, name) for f in fields]), {"units": "1"})
    out["Sigma_yy"][2]["long_name"] = "total normal stress Sigma_yy/G"
    out["slip_velocity"][2]["long_name"] = "slip velocity (V - U_dot)/c2"
    scal = {}
    for key in waves[0].summary():
        vals = [w.summary()[key] for w in waves]
        if all(isinstance(v, (int, float)) for v in vals):
            scal[key] = ("variant", np.array(vals, dtype=float), {"units": "1"})
    scal["slip_residual"] = ("variant", np.array([f.slip_residual for f in fields]), {"units": "1"})
    scal["stick_residual"] = ("variant", np.array([f.stick_residual for f in fields]), {"units": "1"})
    return out | scal


def figure14_data(quick: bool = True) -> xr.Dataset:
    """Sigma_yy/G along the interface for the parameters of Figure 14.

    [26] gives ``tau*_yy/G = 2 v*/(cbar nu)`` and ``T = (mu - mu*)(-tau*_yy/G)``; ``b``
    is the period at which the inverse problem [54]-[55] returns that ``T`` at
    ``cbar = -0.7`` (`b_for_loading`), and ``v`` follows. Two variants of the field:
    ``paper`` (that ``v``, the Cauchy integral [46] with ``C0 = 0``) and ``decaying``
    (same ``b, cbar, T``, ``v`` from the exact periodic decay condition).
    """
    p = FIGURE14
    mat = Material(p["young"], p["nu"], p["density"])
    load = loading_from_wave(p["cbar"], p["v_star"], nu=p["nu"], mu=p["mu"], mu_star=p["mu_star"])
    b = b_for_loading(p["cbar"], load.T, p["v_star"], nu=p["nu"], mu=p["mu"])
    inv = inverse_problem(b, p["cbar"], p["v_star"], nu=p["nu"], mu=p["mu"])
    v_paper = float(inv.v)
    v_dec = float(decaying_velocity(b, p["cbar"], load.T, p["v_star"], nu=p["nu"], mu=p["mu"]))
    common = dict(b=b, cbar=p["cbar"], T=load.T, v_star=p["v_star"], nu=p["nu"], mu=p["mu"], tau_yy=load.tau_yy)
    waves = [StickSlipWave(v=v_paper, **common), StickSlipWave(v=v_dec, **common)]
    # two periods, points clustered at every transition point
    n = 1500 if quick else 15000
    s = 0.5 * (1.0 - np.cos(np.pi * (np.arange(n) + 0.5) / n))
    one = np.concatenate([s, 1.0 + (b - 1.0) * s])
    x = np.concatenate([one, b + one])
    ds = xr.Dataset(_wave_vars(waves, x), coords={"variant": ["paper", "decaying"],
                                                   "x": ("x", x, {"units": "1", "long_name": "x / a"})})
    ds["zone"] = ("x", (np.mod(x, b) >= 1.0).astype(np.int8), {"long_name": "0: stick, 1: slip"})
    # independent route: quadrature of the Cauchy integral, off the axis and towards x = b
    r = np.geomspace(0.1, 1e-6, 11)
    z = np.concatenate([np.linspace(0.1, b - 0.1, 12) - 0.05j, b - 1j * r])
    quad_err, slopes = [], []
    for w in waves:
        q, c = w.phi_quadrature(z), w.phi(z)
        quad_err.append(float(np.max(np.abs(q - c)) / np.max(np.abs(c))))
        tail = q[-len(r):]
        slopes.append(float(np.polyfit(np.log(r[-3:]), np.log(np.abs(tail[-3:] - w.A)), 1)[0]))
    ds["quadrature_error"] = ("variant", np.array(quad_err),
                              {"units": "1", "long_name": "max |quadrature - closed form| / max |Phi|"})
    ds["fitted_exponent"] = ("variant", np.array(slopes),
                             {"units": "1", "long_name": "slope of log|Phi - A| vs log r at z = b - i r (quadrature)"})
    direct = direct_problem(load.T, v_paper, p["v_star"], nu=p["nu"], mu=p["mu"])
    ds.attrs.update({
        "figure": "14", "young": p["young"], "density": p["density"], "nu": p["nu"], "mu": p["mu"],
        "mu_star": p["mu_star"], "v_star": p["v_star"], "cbar": p["cbar"], "b": b, "T": load.T,
        "tau_yy_over_G": load.tau_yy, "v_paper": v_paper, "v_decaying": v_dec,
        "T_inverse_at_b": float(inv.T), "direct_c": direct.c, "direct_b": direct.b,
        "direct_unique": int(direct.unique), "c2": mat.c2, "c1": mat.c1,
        "rayleigh_over_c2": rayleigh_speed_ratio(p["nu"]),
        "V_paper_m_per_s": v_paper * mat.c2, "V_star_m_per_s": p["v_star"] * mat.c2,
        "tau_yy_Pa": load.tau_yy * mat.shear_modulus, "quick": int(quick)})
    return ds


def plot_figure14(ds: xr.Dataset, path) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    b = ds.attrs["b"]
    fig, (ax, ax2) = plt.subplots(1, 2, figsize=(11, 4.2))
    x = ds.x.values
    for k in range(0, 2):
        ax.axvspan(k * b, k * b + 1.0, color="0.9", lw=0)
    for variant, style in (("paper", "-"), ("decaying", "--")):
        y = ds.Sigma_yy.sel(variant=variant).values
        ax.plot(x, y, style, lw=1.2, label=f"{variant} (v = {ds.attrs['v_' + variant]:.4g})")
    ax.axhline(0, color="k", lw=0.6)
    yr = ds.Sigma_yy.sel(variant="paper").values
    lo = np.nanmin(yr)
    ax.set_ylim(1.6 * lo, -1.2 * lo)
    ax.set_xlabel("x / a   (grey: stick, white: slip)")
    ax.set_ylabel(r"$\Sigma_{yy}/G$")
    ax.set_title(f"Figure 14: c = {ds.attrs['cbar']}, b = {b:.4g}, T = {ds.attrs['T']:.3g}")
    ax.legend(fontsize=8, loc="lower right")
    sel = (ds.zone.values == 1) & (x < b)
    stick = np.flatnonzero(ds.zone.values == 0)[0]
    for variant, style in (("paper", "-"), ("decaying", "--")):
        s = ds.sigma_yy.sel(variant=variant).values
        ax2.loglog(b - x[sel], s[sel] - s[stick], style, label=variant)
    alpha = float(ds.alpha.sel(variant="paper"))
    xs = np.geomspace((b - x[sel]).min(), 1.0, 10)
    s = ds.sigma_yy.sel(variant="paper").values
    k = (s[sel] - s[stick])[-1] / (b - x[sel])[-1] ** (alpha - 0.5)
    ax2.loglog(xs, 2 * k * xs ** (alpha - 0.5), "k:", label=fr"slope $\alpha - 1/2$ = {alpha - 0.5:.3f}")
    ax2.set_xlabel("b - x (slip side)")
    ax2.set_ylabel(r"$(\sigma_{yy} - \sigma_{yy}^{stick})/G$")
    ax2.legend(fontsize=8, loc="upper right")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def check_figure14(ds: xr.Dataset) -> list[tuple]:
    out = []
    b, T = ds.attrs["b"], ds.attrs["T"]
    out.append(("b follows from [26] and [54]-[55]", abs(ds.attrs["T_inverse_at_b"] / T - 1) < 1e-10,
                ds.attrs["T_inverse_at_b"], T, f"b = {b:.6g}; T = (mu - mu*)(-tau*_yy/G), tau*_yy/G = 2 v*/(c nu)"))
    out.append(("direct problem recovers c = -0.7", abs(ds.attrs["direct_c"] - ds.attrs["cbar"]) < 1e-9
                and abs(ds.attrs["direct_b"] / b - 1) < 1e-9 and ds.attrs["direct_unique"] == 1,
                ds.attrs["direct_c"], ds.attrs["cbar"], f"direct b = {ds.attrs['direct_b']:.6g}, unique"))
    for variant in ("paper", "decaying"):
        d = ds.sel(variant=variant)
        k = float(d.stress_intensity)
        first_slip = (ds.zone.values == 1) & (ds.x.values < b)
        near = d.Sigma_yy.values[first_slip][-5:]
        gap = b - ds.x.values[first_slip][-1]
        out.append((f"{variant}: positive singularity of Sigma_yy at SL->ST",
                    k > 0 and bool(np.all(np.diff(near) > 0)) and near[-1] > 0, k, "> 0",
                    f"sigma_yy ~ k (b - x)^(alpha - 1/2); Sigma_yy/G = {near[-1]:.3g} at b - x = {gap:.2g}"))
        out.append((f"{variant}: singularity exponent (quadrature of [46])",
                    abs(float(d.fitted_exponent) - float(d.exponent_slip_to_stick)) < 1e-4,
                    float(d.fitted_exponent), float(d.exponent_slip_to_stick), "alpha - 1/2, fitted at z = b - i r, r -> 0"))
        out.append((f"{variant}: slip condition [40] on SL", float(d.slip_residual) < 1e-10,
                    float(d.slip_residual), "< 1e-10", "max |sigma_xy + mu sigma_yy - T|/T"))
        out.append((f"{variant}: stick condition on ST", float(d.stick_residual) < 1e-10,
                    float(d.stick_residual), "< 1e-10", "max |V - U_dot| / |V - V*|"))
        out.append((f"{variant}: closed form = quadrature of the Cauchy integral [46]",
                    float(d.quadrature_error) < 1e-10, float(d.quadrature_error), "< 1e-10",
                    "composite Gauss(-Jacobi) quadrature of the periodic Cauchy integral, 20 points off the axis"))
        x_t = float(d.tensile_zone_start)
        sig = StickSlipWave(b=b, cbar=ds.attrs["cbar"], T=T, v=ds.attrs["v_" + variant], v_star=ds.attrs["v_star"],
                            nu=ds.attrs["nu"], mu=ds.attrs["mu"], tau_yy=ds.attrs["tau_yy_over_G"]).fields(
            np.array([x_t - 1e-9, x_t + 1e-9])).Sigma_yy
        out.append((f"{variant}: tensile zone before SL->ST", float(d.tensile_zone_length) > 0 and sig[0] < 0 < sig[1],
                    float(d.tensile_zone_length), "> 0", f"Sigma_yy > 0 on ({x_t:.6g}, b); length in units of a"))
    dec = ds.sel(variant="decaying")
    pap = ds.sel(variant="paper")
    out.append(("decaying variant leaves no stress at depth", float(dec.decay_residual) < 1e-12,
                float(dec.decay_residual), "< 1e-12",
                f"the paper's v leaves Phi(-i inf)/G = {float(pap.far_field_re):.3g} + {float(pap.far_field_im):.3g} i "
                f"(v = {ds.attrs['v_paper']:.4g} vs {ds.attrs['v_decaying']:.4g})"))
    return _rows(out)


def plot_fields(ds: xr.Dataset, path) -> None:
    """Plot the interface fields of one wave (``StickSlipWave.fields(...).to_xarray()``)."""
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    x = ds.x.values
    order = np.argsort(x)
    fig, axes = plt.subplots(3, 1, figsize=(8, 8), sharex=True)
    for ax, names, label in ((axes[0], ("Sigma_yy", "Sigma_xy"), "stress / G"),
                             (axes[1], ("u_xx",), "u_x,x"),
                             (axes[2], ("slip_velocity", "material_velocity"), "velocity / c2")):
        for name in names:
            y = ds[name].values[order]
            ax.plot(x[order], y, lw=1, label=name)
        finite = np.concatenate([ds[n].values[np.isfinite(ds[n].values)] for n in names])
        lo, hi = np.percentile(finite, [1, 99])
        pad = 0.3 * (hi - lo + 1e-30)
        ax.set_ylim(lo - pad, hi + pad)
        ax.set_ylabel(label)
        ax.legend(fontsize=8, loc="lower right")
        for ax_ in (ax,):
            stick = ds.zone.values[order] == 0
            ax_.fill_between(x[order], 0, 1, where=stick, transform=ax_.get_xaxis_transform(), color="0.9", lw=0)
    axes[-1].set_xlabel("x / a  (grey: stick)")
    a = ds.attrs
    axes[0].set_title(f"c = {a.get('c', float('nan')):.3g}, b = {a.get('b', float('nan')):.4g}, "
                      f"v = {a.get('v', float('nan')):.3g}, T = {a.get('T', float('nan')):.3g}")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def inverse_map_data(quick: bool = True) -> xr.Dataset:
    """``v``, ``T``, ``D``, ``H`` over ``(b, c)`` for both systems, Figure 14 material
    (``nu = 0.3, mu = 0.5, v* = 0.001``), plus the closed forms and the exact decay ratio."""
    p = FIGURE14
    nb, nc = (60, 50) if quick else (400, 400)
    b = 1.0 + np.geomspace(1e-3, 1e3, nb)
    c = -(1.0 - np.cos(np.pi * (np.arange(nc) + 0.5) / nc)) / 2.0
    ds = inverse_map(b, c, p["v_star"], nu=p["nu"], mu=p["mu"])
    B, C = np.meshgrid(b, c, indexing="ij")
    v_cf, T_cf = closed_form(B, C, p["v_star"], nu=p["nu"], mu=p["mu"])
    v_pr, T_pr = printed_closed_form(B, C, p["v_star"], nu=p["nu"], mu=p["mu"])
    _, T_mis = printed_closed_form(B, C, p["v_star"], nu=p["nu"], mu=p["mu"], as_printed=True)
    ds["v_closed"], ds["T_closed"] = (("b", "c"), v_cf, {"units": "1"}), (("b", "c"), T_cf, {"units": "1"})
    ds["v_58"], ds["T_58"] = (("b", "c"), v_pr, {"units": "1"}), (("b", "c"), T_pr, {"units": "1"})
    ds["T_as_printed"] = (("b", "c"), T_mis, {"units": "1", "long_name": "T formula after [58] as printed"})
    v_dec = np.stack([decaying_velocity(B, C, ds["T"].sel(system=s).values, p["v_star"], nu=p["nu"], mu=p["mu"])
                      for s in ds.system.values])
    ds["slip_rate_ratio"] = (("system", "b", "c"), (ds["v"].values - p["v_star"]) / (v_dec - p["v_star"]),
                             {"units": "1", "long_name": "(v - v*) of the system / (v - v*) of the decaying field"})
    rd = radok(c, p["nu"], p["mu"])
    ds["b_singular_text"] = ("c", rd.K / (2 * rd.K_minus_one), {"units": "1", "long_name": "b where D = 0 for [53]"})
    ds.attrs["quick"] = int(quick)
    return ds


def plot_inverse_map(ds: xr.Dataset, path) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import LogNorm

    fig, axes = plt.subplots(1, 3, figsize=(14, 4.2))
    pr = ds.sel(system="printed")
    bm1 = ds.b.values - 1.0
    m = axes[0].pcolormesh(ds.c.values, bm1, pr.v.values / ds.attrs["v_star"], shading="auto")
    fig.colorbar(m, ax=axes[0], label="v / v*")
    axes[0].set_title("printed [54]-[55]: v / v* (independent of b)")
    m = axes[1].pcolormesh(ds.c.values, bm1, pr["T"].values, norm=LogNorm(), shading="auto")
    fig.colorbar(m, ax=axes[1], label="T = T*/G")
    axes[1].set_title("printed [54]-[55]: T")
    tx = ds.sel(system="text")
    m = axes[2].pcolormesh(ds.c.values, bm1, np.sign(tx.D.values), cmap="coolwarm", shading="auto")
    axes[2].plot(ds.c.values, ds.b_singular_text.values - 1.0, "k", lw=1, label="b = K/(2(K-1))")
    axes[2].set_title("[52]-[53] as printed: sign of D")
    axes[2].legend(fontsize=8, loc="upper right")
    for ax in axes:
        ax.set_yscale("log")
        ax.set_xlabel("c / c2")
        ax.set_ylabel("b - 1")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def check_inverse_map(ds: xr.Dataset) -> list[tuple]:
    pr, tx = ds.sel(system="printed"), ds.sel(system="text")
    vs = ds.attrs["v_star"]
    rel = lambda a, b: float(np.max(np.abs(a - b) / np.abs(b)))  # noqa: E731
    ok = np.abs(ds.c.values) >= 1e-3
    out = [
        ("D < 0 on the grid (printed [54]-[55])", bool(np.all(pr.D < 0)), float(pr.D.max()), "< 0", "[56]"),
        ("H > 0 on the grid (printed)", bool(np.all(pr.H > 0)), float(pr.H.min()), "> 0", "[57] = gamma1 b (K - 1)"),
        ("T > 0 and v > v* (printed)", bool(np.all(pr["T"] > 0) and np.all(pr.v > vs)),
         float(min(pr["T"].min(), pr.v.min() - vs)), "> 0", "admissible loading everywhere"),
        ("v independent of b (printed)", float((pr.v.max("b") - pr.v.min("b")).max() / pr.v.max()) < 1e-12,
         float((pr.v.max("b") - pr.v.min("b")).max() / pr.v.max()), "0", "v = v* K/(K - 1)"),
        ("closed forms after [58] (T corrected) = linear solve (|c| >= 1e-3)",
         max(rel(ds.v_58[:, ok], pr.v[:, ok]), rel(ds.T_58[:, ok], pr["T"][:, ok])) < 1e-7,
         max(rel(ds.v_58[:, ok], pr.v[:, ok]), rel(ds.T_58[:, ok], pr["T"][:, ok])), "< 1e-7",
         "A(b, c) as printed; T with sin(2 pi alpha), cos(2 pi alpha). The printed forms lose digits to the "
         "cancellation mu gamma2 sin(2 pi alpha) + gamma1 (cos(2 pi alpha) - 1) = 0 as c -> 0 "
         f"(max rel. difference {max(rel(ds.v_58, pr.v), rel(ds.T_58, pr['T'])):.1e} over the whole grid; "
         "the linear solve agrees with 50-digit arithmetic there)"),
        ("T formula as printed differs from the linear solve", rel(ds.T_as_printed, pr["T"]) > 1e-3,
         rel(ds.T_as_printed, pr["T"]), "> 1e-3", "misprint: sin(pi alpha), cos(pi alpha) in its denominator"),
    ]
    sign = np.sign(tx.D.values)
    flips = np.abs(np.diff(sign, axis=0)).sum(axis=0) / 2  # sign changes along b for each c
    B = ds.b.values
    i = np.argmax(np.diff(sign, axis=0) != 0, axis=0)
    located = float(np.max(np.abs(np.log((B[i] * B[i + 1]) ** 0.5 - 1) - np.log(ds.b_singular_text.values - 1))))
    out.append(("[52]-[53] as printed: D changes sign once, on b = K/(2(K-1))",
                bool(np.all(flips == 1)) and located < np.log(B[1] - 1) - np.log(B[0] - 1),
                located, "within one grid cell", "the paper's claim D < 0 does not hold for [53] as printed"))
    ratio = ds.slip_rate_ratio.sel(system="printed")
    out.append(("printed (v - v*) vs exact periodic decay", bool(np.all(ratio < 1)), float(ratio.max()), "< 1",
                f"min {float(ratio.min()):.3g}: [55] underestimates the slip rate that makes the field decay"))
    return _rows(out)


def direct_map_data(quick: bool = True) -> xr.Dataset:
    """Direct problem over the loading plane ``(v/v*, T/v*)``, both systems (nu = 0.3, mu = 0.5)."""
    p = FIGURE14
    n = 40 if quick else 200
    vr = np.geomspace(1.05, 50.0, n)
    tr = np.geomspace(1e-2, 1e3, n)
    maps = [direct_map(vr, tr, nu=p["nu"], mu=p["mu"], system=s, n_grid=1001 if quick else 4001) for s in ("printed", "text")]
    ds = xr.concat(maps, dim=xr.DataArray(["printed", "text"], dims="system", name="system"))
    rd = radok(cbar_grid(20001), p["nu"], p["mu"])
    ratio = rd.K / rd.K_minus_one
    ds.attrs.update({"v_ratio_band_lo": float(ratio.min()), "v_ratio_band_hi": float(ratio.max()),
                     "quick": int(quick), "nu": p["nu"], "mu": p["mu"]})
    return ds


def plot_direct_map(ds: xr.Dataset, path) -> None:
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig, axes = plt.subplots(1, 2, figsize=(11, 4.2))
    for ax, system in zip(axes, ("printed", "text")):
        d = ds.sel(system=system, solution=0)
        m = ax.pcolormesh(d.T_ratio.values, d.v_ratio.values, d.c.values, shading="auto")
        fig.colorbar(m, ax=ax, label="c / c2 (blank: no wave)")
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.set_xlabel("T / v*")
        ax.set_ylabel("v / v*")
        ax.set_title(f"direct problem, {system}: max {int(ds.n_solutions.sel(system=system).max())} wave(s)")
    fig.tight_layout()
    fig.savefig(path, dpi=120)
    plt.close(fig)


def check_direct_map(ds: xr.Dataset) -> list[tuple]:
    pr = ds.sel(system="printed")
    has = pr.n_solutions.values > 0
    vr = np.broadcast_to(pr.v_ratio.values[:, None], has.shape)
    lo, hi = ds.attrs["v_ratio_band_lo"], ds.attrs["v_ratio_band_hi"]
    inside = (vr > lo) & (vr < hi)
    out = [("printed: at most one wave per loading", int(ds.n_solutions.sel(system="printed").max()) <= 1,
            int(ds.n_solutions.sel(system="printed").max()), "<= 1", "K(c) is monotone"),
           ("printed: a wave exists iff v/v* lies in the band K/(K-1)", bool(np.array_equal(has, inside)),
            float(np.mean(has == inside)), "1", f"band ({lo:.4g}, {hi:.4g})")]
    c = pr.c.sel(solution=0).values
    b = pr.b.sel(solution=0).values
    ok = np.isfinite(c)
    if ok.any():
        idx = np.argwhere(ok)[:: max(1, ok.sum() // 20)]
        err = 0.0
        for i, j in idx:
            sol = inverse_problem(b[i, j], c[i, j], 1.0, nu=ds.attrs["nu"], mu=ds.attrs["mu"])
            err = max(err, abs(float(sol.v) / pr.v_ratio.values[i] - 1), abs(float(sol.T) / pr.T_ratio.values[j] - 1))
        out.append(("printed: inverse problem reproduces the loading", err < 1e-8, err, "< 1e-8", "round trip at sampled points"))
    return _rows(out)
