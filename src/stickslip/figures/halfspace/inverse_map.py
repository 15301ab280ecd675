"""Section 5: the inverse problem over ``(b, c)`` — existence, uniqueness, closed forms [56]-[58]."""

from __future__ import annotations

import numpy as np
import lazy_loader as lazy
from matplotlib.colors import LogNorm
from matplotlib.figure import Figure

from ... import plotting
from ...halfspace import closed_form, decaying_velocity, inverse_map, printed_closed_form, radok
from .. import Check, FigureSpec
from .common import FIGURE14, checks

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it


def compute(quick: bool = True) -> xr.Dataset:
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


def check(ds: xr.Dataset) -> list[Check]:
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
    return checks(out)


def plot(ds: xr.Dataset, fig: Figure | None = None) -> Figure:
    from matplotlib.colors import ListedColormap
    from matplotlib.lines import Line2D
    from matplotlib.patches import Patch

    fig, axes = plotting.new_figure(fig, 3, size=(3.8, 4.2))
    pr = ds.sel(system="printed")
    bm1 = ds.b.values - 1.0
    m = axes[0].pcolormesh(ds.c.values, bm1, pr.v.values / ds.attrs["v_star"], shading="auto")
    fig.colorbar(m, ax=axes[0], label="v / v* [1]")
    axes[0].set_title("printed [54]-[55]: v / v*\n(independent of b)")
    m = axes[1].pcolormesh(ds.c.values, bm1, pr["T"].values, norm=LogNorm(), shading="auto")
    fig.colorbar(m, ax=axes[1], label="T = T*/G [1]")
    axes[1].set_title("printed [54]-[55]: T")
    tx = ds.sel(system="text")
    sign = np.sign(tx.D.values)
    colours = {-1: "#3b4cc0", 0: "#dddddd", 1: "#b40426"}  # categories: D < 0, D = 0, D > 0
    axes[2].pcolormesh(ds.c.values, bm1, sign, cmap=ListedColormap(list(colours.values())), vmin=-1.5, vmax=1.5,
                       shading="auto")
    axes[2].plot(ds.c.values, ds.b_singular_text.values - 1.0, "k", lw=1)
    axes[2].set_title("[52]-[53] as printed:\nsign of D")
    present = set(np.unique(sign[np.isfinite(sign)]).astype(int))
    handles = [Patch(facecolor=c, label=f"D {'<' if k < 0 else '=' if k == 0 else '>'} 0")
               for k, c in colours.items() if k in present]
    plotting.legend_beside(axes[2], handles=handles + [Line2D([], [], color="k", lw=1, label="b = K/(2(K−1))")])
    for ax in axes:
        ax.title.set_fontsize(10)
        ax.set_yscale("log")
        ax.set_xlabel("c / c2 [1]")
        ax.set_ylabel("b − 1 [1]")
    return fig


FIGURE = FigureSpec(
    key="halfspace-inverse-map", title="Section 5 — the inverse problem over (b, c̄)",
    model="rigid body on an elastic half-space",
    claim="For any b > 1 and -1 < c̄ < 0 the determinant D(b, c̄) of [54]-[55] is negative (H > 0), so (v, T) exists "
          "and is unique; with v* = 0 only the trivial solution exists; closed forms [56]-[58].",
    method="The 2×2 system [54]-[55] solved vectorised on a dense (b, c̄) grid; D and H evaluated; the printed closed "
           "forms for v and T compared with the linear solve; H = γ1 b (K − 1) with K = πλ/sin πλ.",
   
    errata=("H4", "H5"),
)
