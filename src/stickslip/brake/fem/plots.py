"""Plots of the FE figures (`fem.figures`): drawn from the datasets alone."""

from __future__ import annotations

import numpy as np

from ..ring_plots import _pyplot, _states

__all__ = ["plot_fig7", "plot_fig8", "plot_fig9", "plot_fig10", "plot_regime_map"]


def _title(ds, i):
    r = ds.isel(run=i)
    return (f"{str(r['run'].values)}: {str(r['regime'].values)}, {int(r['n_zones'])} zones, "
            f"c = {float(r['c_over_cp']):.2f} c_p/R")


def _case(ds, path, profile, label):
    """States of every run (last 2 transits), a profile per run, energies and growth rates."""
    plt, cmap = _pyplot()
    nrun = ds.sizes["run"]
    fig, axes = plt.subplots(2, nrun + 1, figsize=(4.2 * (nrun + 1), 7.5), squeeze=False)
    th = ds["theta"].values
    for i in range(nrun):
        _states(axes[0, i], ds["state"].isel(run=i).values, cmap, _title(ds, i))
        axes[0, i].set(xlabel="θ", ylabel="t [transits, last 2]" if i == 0 else "")
        ax = axes[1, i]
        ax.plot(th, ds[profile].isel(run=i, snapshot=-1), lw=0.9, label=label)
        ax.plot(th, ds["P"].isel(run=i, snapshot=-1), lw=0.9, label="p / p_e")
        ax.axhline(1.0, color="k", lw=0.4)
        ax.set(xlabel="θ", xticks=[0, np.pi, 2 * np.pi], xticklabels=["0", "π", "2π"])
        ax.legend(fontsize=7)
    ax = axes[0, nrun]
    for i in range(nrun):
        ax.semilogy(ds["transit"], ds["energy"].isel(run=i), lw=0.8, label=str(ds["run"].values[i]))
    ax.set(xlabel="transits", ylabel="energy of the deviation [E R²]", title="growth and saturation")
    ax.legend(fontsize=7)
    ax = axes[1, nrun]
    ax.plot(ds["mode"], ds["growth"], label="FE, semi-discrete (max over branches)")
    ax.plot(ds["mode"], ds["growth_discrete"], label="FE, β2 = 0.9 (fully discrete)")
    hs = ds.attrs["halfspace_rate_per_transit_per_mode"]
    if hs > 0:
        ax.plot(ds["mode"], hs * ds["mode"], "k:", label="half-space slip wave (f > 1)")
    ax.axhline(0, color="k", lw=0.5)
    ax.set(xlabel="mode n", ylabel="Re s per transit", title="flutter of steady sliding",
           ylim=(min(-1.0, float(ds["growth_discrete"].min())), 1.2 * float(ds["growth"].max())))
    ax.legend(fontsize=7)
    a = ds.attrs
    fig.suptitle(f"case {a['case']}: f = {a['friction']:g}, δ = {a['delta']:g}, Ω = {a['omega']:g} rad/s "
                 f"(κ = {a['kappa']:.3g}); paper: {a['paper_regime']}, {a['paper_modes']} modes\n{a['mesh']}, "
                 f"β2 = 0.9, {a['transits']} transits per run", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_fig7(ds, path) -> None:
    """Figure 7: stick-slip waves of case 1 (node states, hoop velocity and pressure)."""
    _case(ds, path, "Vd", "hoop velocity / RΩ")


def plot_fig8(ds, path) -> None:
    """Figure 8: stick-separation of case 3 (node states, radial displacement and pressure)."""
    _case(ds, path, "U", "u_r / d - 1")


def _spacetime(ax, ds, i, key, label, cmap):
    r = ds.isel(run=i)
    im = ax.imshow(r[key].values, aspect="auto", origin="lower", cmap=cmap, interpolation="nearest",
                   extent=(0, 2 * np.pi, float(r["snap_t"][0]), float(r["snap_t"][-1])))
    ax.set(xlabel="θ", ylabel="t [transits]", xticks=[0, np.pi, 2 * np.pi], xticklabels=["0", "π", "2π"])
    ax.set_title(f"{label}\n{_title(ds, i)}", fontsize=8)
    return im


def _waterfall(ax, ds, i, key, step, scale):
    r = ds.isel(run=i)
    for k, snap in enumerate(range(0, r.sizes["snapshot"], step)):
        ax.plot(r["theta"], r[key].isel(snapshot=snap) / scale + k, lw=0.7, color="C0")
    ax.set(xlabel="θ", ylabel="successive times (offset)", xticks=[0, np.pi, 2 * np.pi], xticklabels=["0", "π", "2π"])


def plot_fig9(ds, path) -> None:
    """Figure 9: radial displacement ``u_r(R)/d - 1`` vs ``theta`` and ``t`` (propagation)."""
    plt, _ = _pyplot()
    nrun = ds.sizes["run"]
    fig, axes = plt.subplots(2, nrun, figsize=(4.5 * nrun, 8), squeeze=False)
    for i in range(nrun):
        im = _spacetime(axes[0, i], ds, i, "U", "u_r(R)/d - 1 (> 0: separated)", "magma")
        fig.colorbar(im, ax=axes[0, i])
        scale = max(float(ds["U"].isel(run=i).max()), 1e-12)
        _waterfall(axes[1, i], ds, i, "U", 4, scale)
    a = ds.attrs
    fig.suptitle(f"Figure 9: f = {a['friction']:g}, δ = {a['delta']:g}, Ω = {a['omega']:g} rad/s; {a['mesh']}; "
                 f"paper: {a['paper_regime']}, {a['paper_modes']} modes", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_fig10(ds, path) -> None:
    """Figure 10: contact pressure ``p / p_e`` vs ``theta`` (space-time and successive profiles)."""
    plt, _ = _pyplot()
    nrun = ds.sizes["run"]
    fig, axes = plt.subplots(2, nrun, figsize=(4.5 * nrun, 8), squeeze=False)
    for i in range(nrun):
        im = _spacetime(axes[0, i], ds, i, "P", "contact pressure p / p_e", "viridis")
        fig.colorbar(im, ax=axes[0, i])
        r = ds.isel(run=i)
        for k in (0, r.sizes["snapshot"] // 4, r.sizes["snapshot"] - 1):
            axes[1, i].plot(r["theta"], r["P"].isel(snapshot=k), lw=0.8,
                            label=f"t = {float(r['snap_t'][k]):.2f} transits")
        axes[1, i].axhline(1.0, color="k", lw=0.4)
        axes[1, i].set(xlabel="θ", ylabel="p / p_e", xticks=[0, np.pi, 2 * np.pi], xticklabels=["0", "π", "2π"])
        axes[1, i].legend(fontsize=7)
    a = ds.attrs
    fig.suptitle(f"Figure 10: contact pressure, f = {a['friction']:g}, δ = {a['delta']:g}, Ω = {a['omega']:g} rad/s "
                 f"(p_e = {a['p_e']:.3g} E); {a['mesh']}", fontsize=9)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_regime_map(ds, path) -> None:
    """Regime names and zone fractions over ``xi`` and ``Omega``."""
    plt, _ = _pyplot()
    fig, ax = plt.subplots(figsize=(9, 3 + 0.8 * ds.sizes["xi"]))
    sep = ds["fraction"].sel(kind="separation").values
    im = ax.imshow(sep, origin="lower", cmap="Greys", vmin=0, vmax=max(0.3, float(sep.max())), aspect="auto")
    for i, xi in enumerate(ds["xi"].values):
        for j, om in enumerate(ds["omega"].values):
            c = ds.sel(xi=xi, omega=om)
            ax.text(j, i, f"{str(c['regime'].values)}\n{int(c['n_zones'])} zones, κ = {float(c['kappa']):.2g}",
                    ha="center", va="center", fontsize=7, color="C3")
    ax.set(xticks=range(ds.sizes["omega"]), xticklabels=[f"{o:g}" for o in ds["omega"].values],
           yticks=range(ds.sizes["xi"]), yticklabels=[f"{x:g}" for x in ds["xi"].values], xlabel="Ω [rad/s]",
           ylabel="ξ = R*/R", title=f"FE regimes, f = 0.7, d = 0.1 mm, R = 0.1 m ({ds.attrs['transits']} transits, "
                                    "grey: separation fraction)")
    fig.colorbar(im, ax=ax)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
