"""The legibility check of the figures (`stickslip.plotting.legibility_problems`): it finds
each kind of defect on deliberately bad figures and none on a clean one; the figures of issue
10 (Figures 5-8, 10, 11, the ring's regimes and initial conditions, the oscillator's regime
map of the command line) drawn from small synthetic datasets shaped like the real ones pass
it, and fail it again when an original defect is planted back. The figures drawn from the
real (quick) data are checked by a slow test that runs the report."""

from __future__ import annotations

import numpy as np
import pytest
import xarray as xr
from matplotlib.figure import Figure
from matplotlib.patches import Patch

from stickslip import plotting
from stickslip.plotting import legibility_problems


def _laid_out(fig):
    fig.tight_layout()
    return fig


def _clean():
    fig = Figure(figsize=(6, 4))
    ax = fig.subplots()
    x = np.linspace(0, 10, 200)
    ax.plot(x, np.sin(x), label="sin")
    ax.plot(x, np.cos(x), label="cos")
    ax.set(xlabel="t [s]", ylabel="x [m]", title="two curves")
    plotting.legend_beside(ax)
    return fig, ax


def _has(problems, *words):
    return any(all(w in p for w in words) for p in problems)


# --- the checker on deliberately bad figures ----------------------------------------------------
def test_a_clean_figure_has_no_problem():
    fig, _ = _clean()
    assert legibility_problems(_laid_out(fig)) == []


def test_small_text_is_reported():
    fig, ax = _clean()
    ax.text(1, 0.5, "tiny", fontsize=4)
    ax.get_legend().get_texts()[0].set_fontsize(5)
    problems = legibility_problems(_laid_out(fig))
    assert _has(problems, "'tiny'", "4 pt") and _has(problems, "legend text 'sin'", "5 pt")


def test_text_shrunk_with_a_wide_figure_is_reported():
    """The report shows a figure at most 11.7 in wide: the texts of a wider one shrink with it."""
    fig, ax = _clean()
    fig.set_size_inches(24, 4)
    assert _has(legibility_problems(_laid_out(fig)), "in the report")
    assert legibility_problems(fig, width_in=None) == []


def test_a_legend_over_a_line_is_reported():
    fig, ax = _clean()
    ax.legend(loc="center")  # on the curves
    assert _has(legibility_problems(_laid_out(fig)), "legend covers", "pt of the curves")


def test_a_label_on_a_curve_is_reported():
    fig, ax = _clean()
    ax.annotate("here", (np.pi / 2, 1.0), ha="center", va="center")
    assert _has(legibility_problems(_laid_out(fig)), "'here' covers")


def test_overlapping_titles_are_reported():
    fig = Figure(figsize=(6, 3))
    axes = fig.subplots(1, 2)
    for ax in axes:
        ax.plot([0, 1], [0, 1])
        ax.set(xlabel="x [m]", ylabel="y [m]", title="a title long enough to run into the neighbouring one")
    assert _has(legibility_problems(_laid_out(fig)), "title", "overlaps")


def test_a_text_off_the_figure_is_reported():
    fig, ax = _clean()
    fig.suptitle("a suptitle far too long for its figure " * 4)
    assert _has(legibility_problems(_laid_out(fig)), "runs off the figure")


def test_missing_labels_and_units_are_reported():
    fig, ax = _clean()
    ax.set_xlabel("")
    ax.set_ylabel("displacement")
    problems = legibility_problems(_laid_out(fig))
    assert _has(problems, "no x label") and _has(problems, "'displacement' has no unit")


def test_a_categorical_axis_needs_a_label_but_no_unit():
    fig = Figure(figsize=(6, 4))
    ax = fig.subplots()
    ax.barh([0, 1], [3, 4])
    ax.set_yticks([0, 1], ["stick-slip, 2 modes", "slip"])
    ax.set(xlabel="number of runs [1]", ylabel="limit regime")
    assert legibility_problems(_laid_out(fig)) == []
    ax.set_ylabel("")
    assert _has(legibility_problems(_laid_out(fig)), "no y label")


def test_a_shared_axis_without_tick_labels_needs_no_label():
    fig = Figure(figsize=(6, 6))
    top, bottom = fig.subplots(2, 1, sharex=True)
    for ax in (top, bottom):
        ax.plot([0, 1], [0, 1])
        ax.set_ylabel("y [m]")
    bottom.set_xlabel("x [m]")
    assert legibility_problems(_laid_out(fig)) == []


def test_a_curve_off_the_axes_is_reported_unless_clipped_and_said():
    fig, ax = _clean()
    ax.set_ylim(-0.5, 0.5)
    assert _has(legibility_problems(_laid_out(fig)), "lie outside the axes")
    for line in ax.lines:
        line.set_gid(plotting.CLIPPED)
    assert _has(legibility_problems(_laid_out(fig)), "lie outside the axes")  # clipped, but not said
    ax.set_title("curves clipped at ±0.5")
    assert legibility_problems(_laid_out(fig)) == []


def test_colour_codes_without_a_legend_are_reported():
    from matplotlib.colors import ListedColormap

    fig = Figure(figsize=(7, 4))
    ax = fig.subplots()
    ax.imshow(np.arange(12).reshape(3, 4) % 3, cmap=ListedColormap(["r", "g", "b"]), aspect="auto",
              extent=(0, 1, 0, 1))
    ax.set(xlabel="x [m]", ylabel="y [m]")
    assert _has(legibility_problems(_laid_out(fig)), "categories", "in no legend")
    plotting.legend_beside(ax, handles=[Patch(color=c, label=c) for c in "rgb"])
    assert legibility_problems(_laid_out(fig)) == []
    ax.legend(handles=[Patch(color=c, label=c) for c in "rgb"], loc="center")  # now over the image
    assert _has(legibility_problems(_laid_out(fig)), "legend lies on the image")


def test_a_continuous_colour_map_needs_a_labelled_colour_bar():
    fig = Figure(figsize=(7, 4))
    ax = fig.subplots()
    im = ax.imshow(np.random.default_rng(0).random((5, 5)), extent=(0, 1, 0, 1))
    ax.set(xlabel="x [m]", ylabel="y [m]")
    assert _has(legibility_problems(_laid_out(fig)), "without a colour bar")
    bar = fig.colorbar(im, ax=ax)
    assert _has(legibility_problems(_laid_out(fig)), "colour bar: no y label")
    bar.set_label("pressure [Pa]")
    assert legibility_problems(_laid_out(fig)) == []


def test_line_colours_without_a_legend_are_reported():
    fig, ax = _clean()
    ax.get_legend().remove()
    assert _has(legibility_problems(_laid_out(fig)), "is in no legend")
    fig, ax = _clean()
    for line in ax.lines:  # black and grey lines code nothing
        line.set_color("0.3")
    ax.get_legend().remove()
    assert legibility_problems(_laid_out(fig)) == []


def test_save_returns_the_problems(tmp_path):
    fig, ax = _clean()
    assert plotting.save(fig, tmp_path / "ok.png") == [] and (tmp_path / "ok.png").exists()
    ax.set_ylabel("")
    assert _has(plotting.save(fig, tmp_path / "bad.png"), "no y label")


# --- synthetic datasets shaped like the figures' data --------------------------------------------
def _waves(pairs=("V", "dV"), kinds=("stick", "slip"), omegas=(50.0, 100.0, 150.0, 200.0), separation=False):
    """Nested orbits, one per shaft speed, with a stick segment on top (as Figures 5, 6)."""
    t = np.linspace(0.0, 2 * np.pi, 400, endpoint=False)
    data = {}
    for name, phase in (("U", 0.3), ("V", 0.0)):
        x = np.array([1e-5 * om / 50 * (1.5 + np.cos(t + phase)) for om in omegas])
        dx = np.array([1e-4 * om / 50 * np.sin(t + phase) for om in omegas])
        data[name], data["d" + name] = (("case", "sample"), x), (("case", "sample"), dx)
    zone = np.where(np.sin(t) > 0.9, 0, 1)
    if separation:
        zone = np.where(np.cos(t) < -0.3, 2, zone)
    data["zone"] = (("case", "sample"), np.tile(zone, (len(omegas), 1)))
    data["zone_kind"] = (("case", "zone"), np.array([list(kinds)] * len(omegas)))
    data["phi"] = (("case", "sample"), np.tile(t / 4, (len(omegas), 1)))
    data["slip_velocity"] = (("case", "sample"), np.tile(1 - np.cos(t), (len(omegas), 1)))
    return xr.Dataset(data, coords={"case": np.arange(len(omegas)), "omega": ("case", list(omegas))},
                      attrs={"friction": 0.2, "modes": 4, "mismatch": 1e-4})


def _fem_case(nrun=2, n=128, snaps=64, transits=300, f=0.2, halfspace=0.0):
    """Runs of a section 3.1 case (Figures 7-10): node states, profiles, energies, growth rates."""
    rng = np.random.default_rng(1)
    theta = np.linspace(0, 2 * np.pi, n, endpoint=False)
    snap = np.arange(snaps)[:, None]
    wave = np.sin(4 * theta[None, :] - 0.3 * snap)
    state = np.where(wave > 0.5, 0, np.where(wave < -0.8, 3, 1))
    modes = np.arange(1, n // 2 + 1)
    data = {
        "state": (("run", "snapshot", "theta"), np.stack([state] * nrun)),
        "U": (("run", "snapshot", "theta"), np.stack([np.clip(-wave - 0.8, 0, None)] * nrun)),
        "Vd": (("run", "snapshot", "theta"), np.stack([np.clip(wave, -1.3, 1.0)] * nrun)),
        "P": (("run", "snapshot", "theta"), np.stack([np.clip(1 + 1.5 * wave, 0, None)] * nrun)),
        "snap_t": (("run", "snapshot"), np.stack([transits - 2 + 2 * np.arange(snaps) / snaps] * nrun)),
        "energy": (("run", "transit"), 1e-9 * (1 + rng.random((nrun, transits)))),
        "growth": ("mode", 10 * np.sin(np.pi * modes / modes[-1]) + 0.5),
        "growth_discrete": ("mode", 10 * np.sin(np.pi * modes / modes[-1]) - 0.2 * modes),
        "regime": ("run", ["stick-slip"] * nrun), "n_zones": ("run", [4] * nrun),
        "c_over_cp": ("run", [-1.3] * nrun),
    }
    return xr.Dataset(data, coords={"run": ["noise"] + [f"mode {4 + k}" for k in range(nrun - 1)], "theta": theta,
                                    "transit": np.arange(transits), "mode": modes},
                      attrs={"case": 1, "friction": f, "delta": 0.004, "omega": 1.0, "kappa": 207.0,
                             "paper_regime": "stick-slip", "paper_modes": 4, "transits": transits, "p_e": 0.003,
                             "mesh": f"{n} x 16 bilinear quadrilaterals (xi = 1.5; h_theta = 0.0245 R at r = R)",
                             "halfspace_rate_per_transit_per_mode": halfspace})


def _fig11(npoint=25):
    d = np.geomspace(1e-5, 2.5e-7, npoint)
    delta = d / 0.1
    structures = ["stick|slip"] * 3 + ["stick|slip|separation|slip|reverse-slip"] * 4 + ["stick|slip|separation"] * 18
    kinds = [s.split("|") + [""] * (5 - len(s.split("|"))) for s in structures]
    starts = np.array([[0.0, 0.1, 0.5, 0.9, 1.3][:len(s.split("|"))] + [np.nan] * (5 - len(s.split("|")))
                       for s in structures])
    pick = [0, 2, 3, 6, 7, 12, 18, 24]
    phi = np.linspace(0, np.pi / 2, 400)
    bump = np.clip(np.sin((phi - 0.5) * 3), 0, None)
    amplitude = [0.0 if i < 3 else 22.0 if i == pick[-1] else 3 * i / npoint for i in pick]  # one dominates
    profile = np.array([delta[i] * (1 + a * bump) for i, a in zip(pick, amplitude)])
    return xr.Dataset({"profile_point": ("profile", pick), "profile_U": (("profile", "sample"), profile),
                       "profile_phi": ("sample", phi), "structure": ("point", structures),
                       "zone_kind": (("point", "zone"), np.array(kinds)), "zone_start": (("point", "zone"), starts),
                       "event_parameter": ("event", [delta[3], delta[7]])},
                      coords={"point": np.arange(npoint), "delta": ("point", delta), "mismatch": ("point", d),
                              "zone": np.arange(5)})


def _ring_regimes(ncase=3, nset=2, snaps=60, nphi=256, transits=300):
    rng = np.random.default_rng(2)
    phi = np.linspace(0, 2 * np.pi, nphi, endpoint=False)
    state = np.where(np.sin(2 * phi[None, :] - 0.2 * np.arange(snaps)[:, None]) > 0.7, 0, 1)
    xis, omegas = [1.5, 2.0, 3.0], [12.5, 50.0, 200.0, 800.0, 3200.0]
    S = np.array([[30.0 / xi / om ** 0.7 * 10 for om in omegas] for xi in xis])
    sep = np.clip(0.7 - 0.3 * np.log10(S + 1e-3), 0, 0.7) * (S < 2)
    frac = np.stack([1 - sep - 0.2, sep, np.zeros_like(S), 0.2 + 0 * S], axis=-1)
    regime = np.where(sep > 0, "stick-slip-separation", "stick-slip")
    grids, modes = np.array([128, 256, 512, 1024]), np.arange(1, 17)
    growth = np.array([[[1.6 * (1 - np.exp(-m / 3)) - (b2 - 0.4) * (m / (N / 64)) ** 2 for m in [modes]][0]
                        for N in grids] for b2 in (0.9, 0.5)])
    return xr.Dataset({
        "state": (("case", "setting", "snapshot", "phi"), np.broadcast_to(state, (ncase, nset, snaps, nphi)).copy()),
        "regime": (("case", "setting"), np.array([["stick-slip"] * nset] * ncase)),
        "n_fft": (("case", "setting"), np.full((ncase, nset), 2)),
        "c_over_sqrt_a": (("case", "setting"), np.full((ncase, nset), -1.5)),
        "energy": (("case", "setting", "transit"), 10 ** rng.normal(0, 0.3, (ncase, nset, transits))),
        "growth": (("case", "beta2", "grid", "mode"), np.stack([growth] * ncase)),
        "growth_continuous": (("case", "mode"), np.stack([1.6 * (1 - np.exp(-modes / 3))] * ncase)),
        "sweep_fraction": (("xi", "omega", "kind"), frac), "sweep_S": (("xi", "omega"), S),
        "sweep_regime": (("xi", "omega"), regime),
    }, coords={"case": np.arange(ncase), "setting": np.arange(nset), "beta2_setting": ("setting", [0.9, 0.5][:nset]),
               "nodes": ("setting", [256] * nset), "friction": ("case", [0.2, 0.7, 2.0][:ncase]),
               "delta": ("case", [0.004, 0.001, 0.004][:ncase]), "omega_case": ("case", [1.0, 50.0, 80.0][:ncase]),
               "paper_regime": ("case", ["stick-slip", "stick-slip-separation", "stick-separation"][:ncase]),
               "paper_modes": ("case", [4, 8, 2][:ncase]), "kind": ["stick", "slip", "reverse_slip", "separation"],
               "beta2": [0.9, 0.5], "grid": grids, "mode": modes, "xi": xis, "omega": omegas,
               "transit": np.arange(transits)},
        attrs={"sweep_nodes": 128})


def _initial_condition(grids=(128, 192), transits=400, snaps=60, nphi=256):
    t = np.arange(transits)
    phi = np.linspace(0, 2 * np.pi, nphi, endpoint=False)
    energy = np.array([[np.minimum(1e-6 * np.exp(t), 3.5 + 0.1 * k) * (1 + 0.05 * np.sin(t * (k + 1)))
                        + 0.6 * np.exp(-((t - 20) / 5.0) ** 2) for k in range(2)] for _ in grids])
    state = np.array([[np.where(np.sin(m * phi[None, :] - 0.2 * np.arange(snaps)[:, None]) > 0.8, 0, 1)
                       for m in (2, 3)] for _ in grids])
    return xr.Dataset({"energy": (("grid", "seed", "transit"), energy),
                       "state": (("grid", "seed", "snapshot", "phi"), state),
                       "regime": (("grid", "seed"), np.array([["stick-slip"] * 2] * len(grids))),
                       "n_fft": (("grid", "seed"), np.array([[2, 3]] * len(grids))),
                       "c_over_sqrt_a": (("grid", "seed"), np.full((len(grids), 2), -1.5))},
                      coords={"grid": list(grids), "seed": ["mode 2", "mode 3"], "transit": t},
                      attrs={"friction": 0.7, "delta": 0.001, "omega": 50.0})


def _oscillator_map():
    v, c = np.linspace(0.05, 1.5, 30), np.linspace(0.01, 0.3, 20)
    regime = np.where(v[:, None] < 0.3, 1, np.where(v[:, None] * c[None, :] < 0.05, 2, 0)).astype(float)
    regime[-3:, :2] = 3
    regime[0, -1] = np.nan  # not computed yet
    return xr.Dataset({"regime": (("belt_speed", "damping"), regime)}, coords={"belt_speed": v, "damping": c})


def _draw(key):
    from stickslip.figures.brake import fig5, fig6, fig7, fig8, fig10, fig11, initial_condition, ring_regimes
    from stickslip.oscillator.regimes import REGIMES

    draw = {"fig5": lambda: fig5.plot(_waves()),
            "fig6": lambda: fig6.plot(_waves(kinds=("stick", "slip", "separation"), omegas=(40.0, 60.0, 80.0, 100.0),
                                              separation=True)),
            "fig7": lambda: fig7.plot(_fem_case()),
            "fig8": lambda: fig8.plot(_fem_case(f=2.0, halfspace=0.8)),
            "fig10": lambda: fig10.plot(_fem_case()),
            "fig11": lambda: fig11.plot(_fig11()),
            "brake-ring-regimes": lambda: ring_regimes.plot(_ring_regimes()),
            "brake-initial-condition": lambda: initial_condition.plot(_initial_condition()),
            "oscillator map --plot": lambda: plotting.plot_oscillator_map(_oscillator_map(), REGIMES)}
    return _laid_out(draw[key]())


LISTED = ["fig5", "fig6", "fig7", "fig8", "fig10", "fig11", "brake-ring-regimes", "brake-initial-condition",
          "oscillator map --plot"]


@pytest.mark.parametrize("key", LISTED)
def test_the_figures_of_issue_10_are_legible(key):
    assert legibility_problems(_draw(key)) == []


# --- each listed defect, planted back, is caught --------------------------------------------------
def _axes_with(fig, predicate):
    return next(ax for ax in fig.axes if predicate(ax))


def test_fig5_and_fig6_omega_labels_are_off_the_curves():
    for key in ("fig5", "fig6"):
        fig = _draw(key)
        labels = [t for ax in fig.axes for t in ax.texts]
        assert labels and all(t.get_text().startswith("Ω = ") for t in labels)
        ax = labels[0].axes
        x, y = ax.lines[0].get_xdata(), ax.lines[0].get_ydata()
        k = int(np.argmax(x))  # the original placement: at the rightmost point of the orbit
        ax.annotate("planted Ω", (x[k], y[k]), fontsize=7)
        assert _has(legibility_problems(fig), "'planted Ω' covers")


@pytest.mark.parametrize("key", ["fig7", "fig8", "brake-ring-regimes", "brake-initial-condition"])
def test_the_node_state_colours_have_a_legend(key):
    fig = _draw(key)
    legends = [ax.get_legend() for ax in fig.axes if ax.get_legend() is not None]
    states = [lg for lg in legends if lg.get_title().get_text() == "node state"]
    assert len(states) == 1
    states[0].remove()
    assert _has(legibility_problems(fig), "categories", "in no legend")


def test_fig10_legends_are_off_the_curves():
    fig = _draw("fig10")
    ax = _axes_with(fig, lambda a: a.get_legend() is not None and "profiles" in a.get_legend().get_title().get_text())
    ax.legend(fontsize=7)  # the original: inside the axes, on the profiles
    assert _has(legibility_problems(fig), "legend covers")


def test_fig11_legend_size_and_curve_scales():
    fig = _draw("fig11")
    ax = fig.axes[0]
    assert ax.get_yscale() == "log"
    lines = [ln.get_ydata() for ln in ax.lines]
    # every profile spans at least a twentieth of the axis (log decades): none is flattened
    lo, hi = np.log10(ax.get_ylim())
    assert all((np.log10(np.nanmax(y)) - np.log10(np.nanmin(y)) > 0.05 * (hi - lo)) or np.ptp(y) == 0 for y in lines)
    levels = sorted(np.log10(np.nanmin(y)) for y in lines)
    assert min(np.diff(levels)) > 0.02 * (hi - lo)  # distinct levels: no two curves drawn on each other
    for text in ax.get_legend().get_texts():
        text.set_fontsize(5)
    assert _has(legibility_problems(fig), "legend text", "5 pt")


def test_fig11_original_scale_flattens_all_curves_but_one():
    """The original plot (U/delta - 1, linear): the largest curve dominates; in the new one, no."""
    ds = _fig11()
    peaks = [float(np.max(ds["profile_U"].values[k] / float(ds["delta"][i]) - 1))
             for k, i in enumerate(ds["profile_point"].values)]
    assert sorted(peaks)[-2] < 0.6 * max(peaks)  # the data do have one dominating curve


def test_ring_regimes_titles_and_annotations():
    fig = _draw("brake-ring-regimes")
    images = [ax for ax in fig.axes if ax.images]
    images[0].set_title(images[0].get_title() + " and a much longer tail of words " * 2, fontsize=8)
    assert _has(legibility_problems(fig), "title", "overlaps")
    fig = _draw("brake-ring-regimes")
    sweep = _axes_with(fig, lambda a: a.get_xscale() == "log" and not a.images)
    sweep.annotate("Ω=50\nstick-slip", (sweep.lines[0].get_xdata()[0], sweep.lines[0].get_ydata()[0]), fontsize=4)
    assert _has(legibility_problems(fig), "4 pt")


def test_initial_condition_curves_stay_on_the_axes():
    fig = _draw("brake-initial-condition")
    ax = fig.axes[0]
    late = np.concatenate([ln.get_ydata()[-100:] for ln in ax.lines])
    ax.set_ylim(0.9 * late.min(), 1.1 * late.max())  # the original limits
    assert _has(legibility_problems(fig), "lie outside the axes")


def test_oscillator_map_is_categorical_with_a_tick_per_regime():
    from stickslip.oscillator.regimes import REGIMES

    fig = _draw("oscillator map --plot")
    bar = next(ax for ax in fig.axes if hasattr(ax, "_colorbar"))
    labels = [t.get_text().replace("\n", " ") for t in bar.get_yticklabels()]
    assert labels == list(REGIMES.values())
    mesh = fig.axes[0].collections[0]
    assert mesh.get_cmap().N == len(REGIMES)
    # the original: a continuous colour map, numbers on the colour bar
    bad = plotting.new_figure()[0]
    ax = bad.axes[0]
    ds = _oscillator_map()
    m = ax.pcolormesh(ds["belt_speed"], ds["damping"], ds["regime"].values.T, shading="nearest", vmin=0, vmax=4)
    bad.colorbar(m, ax=ax, label="; ".join(f"{k} {v}" for k, v in REGIMES.items()))
    ax.set(xlabel="belt_speed", ylabel="damping")
    problems = legibility_problems(_laid_out(bad))
    assert _has(problems, "no unit") and _has(problems, "colour bar")


def test_the_other_command_line_plots_are_legible():
    """``--plot`` of oscillator simulate, cycle and continue, and of halfspace fields (small real runs)."""
    from stickslip.figures.oscillator.bifurcation import STRIBECK
    from stickslip.figures.oscillator.fig2 import OSC
    from stickslip.halfspace import wave_from_inverse
    from stickslip.oscillator import continue_cycle, limit_cycle, simulate

    figures = {"trajectory": plotting.plot_trajectory(simulate(OSC, 30.0, -1.5, 0.0).to_xarray()),
               "cycle": plotting.plot_cycle(limit_cycle(OSC).to_xarray()),
               "branch": plotting.plot_branch(continue_cycle(STRIBECK, 0.6, step=0.05, max_step=0.2).to_xarray()),
               "fields": plotting.plot_interface_fields(
                   wave_from_inverse(4.0, -0.6, 1e-3, nu=0.3, mu=0.5).fields(n=400).to_xarray())}
    assert {k: legibility_problems(_laid_out(f)) for k, f in figures.items()} == {k: [] for k in figures}


# --- every figure of the report, from its real quick data -----------------------------------------
@pytest.mark.slow
def test_every_report_figure_is_legible_on_quick_data(quick_report):
    _, summary = quick_report
    failed = {o.spec.key: c.detail for o in summary.outcomes for c in o.checks
              if c.name.startswith("the figure is legible") and not c.passed}
    assert not failed, failed
