"""Figure 11: continuation of a travelling wave in the mismatch ``d``; the switching points."""

from __future__ import annotations

import numpy as np
import lazy_loader as lazy
from matplotlib.figure import Figure

from ... import plotting
from ...brake import BrakeParams, continue_waves, travelling_wave
from .. import Check, FigureSpec
from .paper import FIG11
from .wave_cases import METHOD

xr = lazy.load("xarray")  # imported on first use: commands that make no dataset start without it


def compute(quick: bool = False) -> xr.Dataset:
    """Continuation in the mismatch ``d``: ``U(phi)`` at several ``d`` and the switching points."""
    d0, d1 = FIG11["mismatch"]
    R = 0.1
    p0 = BrakeParams.from_physical(FIG11["omega"], d0, FIG11["friction"])
    branch = continue_waves(p0, FIG11["modes"], "delta", d1 / R, num=25 if quick else 60, spacing="log")
    ds = branch.to_xarray()
    ds = ds.assign_coords(mismatch=("point", ds["delta"].values * R, {"units": "m"}))
    # profiles at a few points, one per zone sequence met, plus the two ends
    seqs = [str(s) for s in ds["structure"].values]
    pick = sorted({0, len(seqs) - 1} | {seqs.index(s) for s in seqs} |
                  {len(seqs) - 1 - seqs[::-1].index(s) for s in seqs})
    num = 400 if quick else 1200
    profs = [branch.waves[i].evaluate(np.linspace(0.0, branch.waves[i].period, num)) for i in pick]
    ds["profile_point"] = ("profile", pick)
    ds["profile_U"] = (("profile", "sample"), np.array([q["U"] for q in profs]), {"units": "R"})
    ds["profile_zone"] = (("profile", "sample"), np.array([q["zone"] for q in profs]))
    ds["profile_phi"] = ("sample", np.linspace(0.0, branch.waves[0].period, num), {"units": "rad"})
    ds["event_parameter"] = ("event", [e.parameter for e in branch.events])
    ds["event_kind"] = ("event", [e.kind for e in branch.events])
    ds["event_zones"] = ("event", ["+".join(e.zones) for e in branch.events])
    ds["event_after"] = ("event", [e.after for e in branch.events])
    ds["event_before"] = ("event", [e.before for e in branch.events])
    ds["event_cause"] = ("event", [e.cause for e in branch.events])
    # independent direct solves at three points of the branch
    idx = [len(seqs) // 4, len(seqs) // 2, (3 * len(seqs)) // 4]
    direct = []
    for i in idx:
        w = branch.waves[i]
        cands = [v for v in [travelling_wave(w.params, w.n, guess=w.c)] if v.structure == w.structure]
        direct.append(cands[0].c if cands else np.nan)
    ds["direct_point"] = ("check", idx)
    ds["direct_c"] = ("check", direct)
    ds["sonic_speed"] = ("point", [np.sqrt(w.params.coefficients().a) for w in branch.waves])
    ds.attrs.update({"friction": FIG11["friction"], "omega": FIG11["omega"], "modes": FIG11["modes"],
                     "stopped": branch.stopped, "min_margin": min(min(w.margins.values()) for w in branch.waves),
                     "max_residual": max(w.residual for w in branch.waves)})
    return ds


def check(ds: xr.Dataset) -> list[Check]:
    kinds = [str(k) for k in ds["event_kind"].values]
    after = [str(a) for a in ds["event_after"].values]
    before = [str(b) for b in ds["event_before"].values]
    zones = [str(z) for z in ds["event_zones"].values]
    born_sep = any(k == "birth" and "separation" in z for k, z in zip(kinds, zones))
    # death of the slip zone right of the separation zone (switching points coalesce)
    slip_dies = [i for i, (k, z, b) in enumerate(zip(kinds, zones, before))
                 if k == "death" and z == "slip" and "separation|slip" in b]
    sss = "stick|slip|separation" in [str(s) for s in ds["structure"].values]
    direct = ds["direct_c"].values
    c_branch = ds["c"].values[ds["direct_point"].values]
    ok_direct = bool(np.all(np.abs(direct - c_branch) <= 1e-8 * np.abs(c_branch)))
    lengths = ds["zone_end"] - ds["zone_start"]
    return [
        Check("Fig. 11: separation is born when the pressure touches 0 inside a slip zone",
              born_sep, "; ".join(f"{k} of {z} at delta = {p:.5g}" for k, z, p in
                                  zip(kinds, zones, ds["event_parameter"].values)), "a birth of separation"),
        Check("Fig. 11: the slip zone right of separation vanishes as d decreases (switching points coalesce)",
              bool(slip_dies), f"{[before[i] + ' -> ' + after[i] for i in slip_dies]}", "a death of that slip zone"),
        Check("Fig. 11: one ends in the stick-slip-separation state", sss,
              f"last structures {sorted(set(str(s) for s in ds['structure'].values[-3:]))}", "stick|slip|separation"),
        Check("Fig. 11: continuation agrees with direct solves", ok_direct,
              f"max |c_direct - c_branch|/|c| = {float(np.nanmax(np.abs(direct - c_branch) / np.abs(c_branch))):.1e}",
              "<= 1e-8", "return-map scan + multiple shooting at three points of the branch"),
        Check("Fig. 11: every point passes the checks", float(ds.attrs["min_margin"]) > -1e-8
              and float(ds.attrs["max_residual"]) < 1e-8 and float(lengths.min()) > 0,
              f"min margin {float(ds.attrs['min_margin']):.1e}, max residual {float(ds.attrs['max_residual']):.1e}",
              ">= -1e-8, < 1e-8"),
    ]


def plot(ds: xr.Dataset, fig: Figure | None = None) -> Figure:
    """Top: the radial displacement ``u_r(R) = U R`` over a period at a few mismatches, on a log
    scale (it equals ``d`` in contact, so each curve sits at its own level and every separation
    bump shows; ``U/delta - 1`` would put the contact parts of all curves on 0 and let the
    smallest ``d`` flatten the rest). Bottom: the switching points along the branch."""
    from matplotlib import colormaps
    from matplotlib.lines import Line2D
    from matplotlib.ticker import FuncFormatter, LogLocator, NullFormatter

    fig, (ax1, ax2) = plotting.new_figure(fig, 1, 2, size=(10.5, 4.4))
    phi = ds["profile_phi"].values
    radius = ds["mismatch"].values / ds["delta"].values  # R [m] (d = delta R)
    points = ds["profile_point"].values
    colours = colormaps["viridis"](np.linspace(0.0, 0.9, len(points)))
    for k, i in enumerate(points):
        ax1.plot(phi, ds["profile_U"].values[k] * radius[i] * 1e6, color=colours[k], lw=1.2,
                 label=f"{float(ds['mismatch'][i]) * 1e6:.3g} µm: {ds['structure'].values[i]}")
    ax1.set(yscale="log", xlabel="φ [rad]", ylabel="u_r(R) = U R [µm] (log scale)",
            title="radial displacement over a period (= d in contact, > d in separation)")
    ax1.yaxis.set_major_locator(LogLocator(subs=(1.0, 2.0, 5.0)))
    ax1.yaxis.set_major_formatter(FuncFormatter(lambda v, _: f"{v:g}"))
    ax1.yaxis.set_minor_formatter(NullFormatter())
    plotting.legend_beside(ax1, title="mismatch d: zones", title_fontsize=8)
    d = ds["mismatch"].values * 1e6
    for z in ds["zone"].values:
        kinds = ds["zone_kind"].values[:, z]
        for kind, colour in plotting.ZONE_COLOURS.items():
            sel = kinds == kind
            ax2.plot(np.where(sel, d, np.nan), np.where(sel, ds["zone_start"].values[:, z], np.nan), "o",
                     color=colour, ms=3)
    for e in ds["event_parameter"].values:
        ax2.axvline(e * float(np.median(radius)) * 1e6, color="grey", lw=0.6, ls=":")
    ax2.set(xscale="log", xlabel="mismatch d [µm]", ylabel="zone start φ [rad]",
            title="switching points (start of each zone) along the branch")
    kinds = {str(k) for k in np.ravel(ds["zone_kind"].values)}
    handles = [Line2D([], [], ls="none", marker="o", ms=4, color=c, label=k) for k, c in plotting.ZONE_COLOURS.items()
               if k in kinds]
    handles.append(Line2D([], [], color="grey", lw=0.6, ls=":", label="birth or death\nof a zone"))
    plotting.legend_beside(ax2, handles=handles, title="start of a zone", title_fontsize=8)
    return fig


FIGURE = FigureSpec(
    key="fig11", title="Figure 11 — radial displacement and switching points vs mismatch d",
    model="brake-like system, reduced model, continuation of travelling waves",
    claim="For a very small mismatch d the switching points coalesce, the slip region right of the separation zone "
          "vanishes and one obtains the stick-slip-separation state.",
    method=METHOD + " Continuation in d (f = 0.7, n = 4, Ω = 50 rad/s) with births and deaths of zones located "
                    "where two switching points coalesce; direct solves at the end points agree with the branch.",
)
