"""Plots of the ring figures (`ring_figures`): drawn from the datasets alone."""

from __future__ import annotations

import numpy as np

__all__ = ["plot_regimes", "plot_initial_condition"]

_COLORS = ["#1b9e77", "#d95f02", "#7570b3", "#e7e7e7"]  # stick, slip, reverse slip, separation


def _pyplot():
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from matplotlib.colors import ListedColormap
    return plt, ListedColormap(_COLORS)


def _states(ax, state, cmap, title):
    ax.imshow(state, aspect="auto", origin="lower", cmap=cmap, vmin=-0.5, vmax=3.5, interpolation="nearest",
              extent=(0, 2 * np.pi, 0, 2))
    ax.set_title(title, fontsize=8)
    ax.set_xticks([0, np.pi, 2 * np.pi], ["0", "π", "2π"])


def plot_regimes(ds, path) -> None:
    """Node states (space-time) per case and scheme, energies, growth selection, and the sweep."""
    plt, cmap = _pyplot()
    ncase, nset = ds.sizes["case"], ds.sizes["setting"]
    fig = plt.figure(figsize=(13, 9))
    grid = fig.add_gridspec(3, ncase + 1)
    for i in range(ncase):
        for j in range(nset):
            ax = fig.add_subplot(grid[j, i])
            c = ds.isel(case=i, setting=j)
            _states(ax, c["state"].values, cmap,
                    f"f={float(c.friction):g}, δ={float(c.delta):g}, Ω={float(c.omega_case):g}: "
                    f"β2={float(c.beta2_setting):g}, N={int(c.nodes)}\n{str(c['regime'].values)}, "
                    f"n={int(c['n_fft'])}, c/√a={float(c['c_over_sqrt_a']):.2f}"
                    f" (FE: {str(c.paper_regime.values)}, {int(c.paper_modes)})")
            ax.set(xlabel="θ" if j == nset - 1 else "", ylabel="t [transits]" if i == 0 else "")
    ax = fig.add_subplot(grid[0, ncase])
    for i in range(ncase):
        for j in range(nset):
            ax.semilogy(ds["transit"], ds["energy"].isel(case=i, setting=j), lw=0.8, ls="-" if j == 0 else "--",
                        color=f"C{i}", label=f"case {i + 1}, β2={float(ds.beta2_setting[j]):g}")
    ax.set(xlabel="transits", ylabel="energy of the deviation", title="growth and saturation")
    ax.legend(fontsize=6)
    ax = fig.add_subplot(grid[1, ncase])
    for k, b2 in enumerate(ds["beta2"].values):
        for g, N in enumerate(ds["grid"].values):
            ax.plot(ds["mode"], ds["growth"].isel(case=1).sel(beta2=b2, grid=N), ls="-" if k == 0 else ":",
                    color=f"C{g}", label=f"N={N}, β2={b2:g}")
            if k == 0:
                ax.plot(ds["mode"], ds["growth"].isel(case=0).sel(beta2=b2, grid=N), ls="-.", color=f"C{g}", lw=0.7)
    ax.plot(ds["mode"], ds["growth_continuous"].isel(case=1), "k-", lw=2, label="continuous (case 2)")
    ax.plot(ds["mode"], ds["growth_continuous"].isel(case=0), "k-.", lw=1, label="continuous (case 1, -. β2=0.9)")
    ax.axhline(0, color="k", lw=0.5)
    ax.set(xlabel="n", ylabel="Re s per transit", title="steady sliding: fully discrete growth", ylim=(-1.5, None))
    ax.legend(fontsize=6)
    ax = fig.add_subplot(grid[2, :])
    sep, stick = ds["sweep_fraction"].sel(kind="separation"), ds["sweep_fraction"].sel(kind="stick")
    for x, xi in enumerate(ds["xi"].values):
        S = ds["sweep_S"].sel(xi=xi)
        ax.semilogx(S, sep.sel(xi=xi), "o-", color=f"C{x}", label=f"separation, ξ={xi:g}")
        ax.semilogx(S, stick.sel(xi=xi), "s--", color=f"C{x}", label=f"stick, ξ={xi:g}")
        for s_, om, r in zip(S.values, ds["omega"].values, ds["sweep_regime"].sel(xi=xi).values):
            ax.annotate(f"Ω={om:g}\n{r}", (s_, float(sep.sel(xi=xi).sel(omega=om))), fontsize=5)
    ax.set(xlabel="separation number S = g δ √a / |D|", ylabel="node fraction",
           title=f"sweep f = 0.7, d = 0.1 mm, β2 = 0.9, N = {ds.attrs['sweep_nodes']}")
    ax.legend(fontsize=6, ncol=2)
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)


def plot_initial_condition(ds, path) -> None:
    """Energy histories and final node states for the two seeds on the finest grid."""
    plt, cmap = _pyplot()
    fig, axes = plt.subplots(1, 1 + ds.sizes["seed"], figsize=(12, 3.8))
    for g, N in enumerate(ds["grid"].values):
        for k, seed in enumerate(ds["seed"].values):
            axes[0].plot(ds["transit"], ds["energy"].sel(grid=N, seed=seed), color=f"C{k}", lw=0.8,
                         ls=["-", "--", ":"][g % 3], label=f"{seed}, N={N}")
    late = ds["energy_late"].values
    axes[0].set(xlabel="transits", ylabel="energy of the deviation", ylim=(0.9 * late.min(), 1.1 * late.max()),
                title=f"f={ds.attrs['friction']:g}, δ={ds.attrs['delta']:g}, Ω={ds.attrs['omega']:g}, β2=0.9")
    axes[0].legend(fontsize=6)
    last = ds.isel(grid=-1)
    for k, seed in enumerate(ds["seed"].values):
        c = last.sel(seed=seed)
        _states(axes[k + 1], c["state"].values, cmap,
                f"seeded {seed}, N={int(last.grid)}: {str(c['regime'].values)}, dominant n={int(c['n_fft'])}, "
                f"c/√a={float(c['c_over_sqrt_a']):.2f}")
        axes[k + 1].set(xlabel="θ", ylabel="t [transits]")
    fig.tight_layout()
    fig.savefig(path, dpi=110)
    plt.close(fig)
