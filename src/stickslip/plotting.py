"""Plots of result datasets, for the figures of the paper and for the command line.

Every plot function reads an `xarray.Dataset` (a result's ``to_xarray()`` or a figure's
data), draws on a `matplotlib.figure.Figure` it is given or creates, and returns it.
Nothing here imports `matplotlib.pyplot` or switches the backend, so a Jupyter user keeps
theirs; `save` writes a figure to a file. Every public function checks its arguments at entry
(a `ParameterError` naming the argument, its value and what it may be).
"""

from __future__ import annotations

import os
import sys

import numpy as np
from matplotlib.axes import Axes
from matplotlib.figure import Figure, FigureBase
from matplotlib.lines import Line2D

from .errors import ParameterError
from .legibility import CLIPPED, legibility_problems  # legibility_problems: public here too (its home until 2026-11-28)
from .validation import count, finite_array, in_range, instance, positive, real_array

__all__ = ["new_figure", "save", "modal_line", "oscillator_phase", "state_image", "state_legend", "zone_legend",
           "mode_handles", "legend_beside", "legend_above", "wrap", "label_curves", "plot_cycle", "plot_trajectory",
           "plot_branch", "plot_oscillator_map", "plot_interface_fields",
           "legibility_problems", "MODE_COLOURS", "STATE_COLOURS", "ZONE_COLOURS"]

MODE_COLOURS = {-1: "tab:red", 0: "tab:green", 1: "tab:blue"}
MODE_LABELS = {-1: "reverse slip", 0: "stick", 1: "slip"}
#: Colours of the contact-node states, in the order of `stickslip.contact.STATE_NAMES`.
STATE_COLOURS = ("#1b9e77", "#d95f02", "#7570b3", "#e7e7e7")
#: Colours of the zones of a travelling wave.
ZONE_COLOURS = {"stick": "tab:green", "slip": "tab:blue", "reverse-slip": "tab:red", "separation": "tab:orange"}
#: Units of the oscillator's parameters (axes of maps and branches), where the data give none.
PARAMETER_UNITS = {"mass": "kg", "stiffness": "N/m", "normal_force": "N", "belt_speed": "m/s", "damping": "N s/m",
                   "fs": "1", "fd": "1", "vs": "m/s", "tau": "s/m"}


# --- argument checks -------------------------------------------------------------------------
def _given(value):
    """``value`` for a message: itself when short, else its type."""
    return value if len(repr(value)) <= 60 else f"<{type(value).__name__}>"


def _axes(name: str, ax):
    return instance(name, ax, Axes, "a matplotlib Axes (one of the axes of a Figure)")


def _figure(name: str, fig, optional: bool = True, sub: bool = True):
    if fig is None and optional:
        return None
    kinds = "a matplotlib Figure or SubFigure" if sub else "a matplotlib Figure (not a SubFigure)"
    return instance(name, fig, FigureBase if sub else Figure, kinds + (" or None (a new one)" if optional else ""))


def _text(name: str, value, optional: bool = False):
    if value is None and optional:
        return None
    return instance(name, value, str, "a text (str)" + (" or None" if optional else ""))


def _line(name: str, value):
    """A curve's coordinates: a 1-D array of real numbers (NaN breaks the curve)."""
    array = real_array(name, value)
    if array.ndim != 1:
        raise ParameterError(name, _given(value), f"a 1-D array of real numbers (this one has {array.ndim} "
                             "dimensions)")
    return array


def _dataset(name: str, ds, what: str, needed: tuple[str, ...]):
    """``ds`` if it is an `xarray.Dataset` holding the numeric variables ``needed``."""
    xr = sys.modules.get("xarray")  # a dataset has loaded xarray: anything else is refused without it
    if xr is None or not isinstance(ds, xr.Dataset):
        raise ParameterError(name, _given(ds), f"an xarray.Dataset of {what}")
    missing = [v for v in needed if v not in ds.variables or ds[v].dtype.kind not in "iufb"]
    if missing:
        has = ", ".join(sorted(map(str, ds.variables))) or "no variables"
        raise ParameterError(name, f"<Dataset of {has}>", f"an xarray.Dataset of {what}, with the numeric "
                             f"variables {', '.join(needed)} ({', '.join(missing)} missing or not numbers)")
    return ds


def _keys(name: str, values, known, optional: bool = False):
    """``values``: an iterable of keys of ``known`` (a `ParameterError` naming the first other)."""
    if values is None and optional:
        return None
    if isinstance(values, (str, bytes)) or not hasattr(values, "__iter__"):
        raise ParameterError(name, _given(values), f"a list of some of {list(known)}")
    values = list(values)
    for v in values:
        if not isinstance(v, (str, int, np.integer)) or isinstance(v, bool) or v not in known:
            raise ParameterError(name, _given(values), f"a list of some of {list(known)} ({v!r} is none of them)")
    return values


OSCILLATOR = ("t", "x", "v", "mode")


def new_figure(fig: Figure | None = None, ncols: int = 1, nrows: int = 1, size=(6.4, 4.8)):
    """``(fig, axes)``: ``ncols x nrows`` axes (a flat list) on ``fig``, or on a new `Figure`
    of ``size`` per panel (inches)."""
    _figure("fig", fig)
    ncols, nrows = count("ncols", ncols, 100, "panels across"), count("nrows", nrows, 100, "panels down")
    size = finite_array("size", size, 1)
    if size.size != 2 or (size <= 0).any():
        raise ParameterError("size", _given(size.tolist()), "(width, height) of a panel in inches, both > 0")
    if fig is None:
        fig = Figure(figsize=(size[0] * ncols, size[1] * nrows))
    axes = fig.subplots(nrows, ncols, squeeze=False)
    return fig, list(axes.ravel())


def save(fig: Figure, path, dpi: int = 120) -> list[str]:
    """Lay out and write ``fig`` (the format from the suffix of ``path``); return its
    `legibility_problems` (empty: legible)."""
    _figure("fig", fig, optional=False, sub=False)
    if not isinstance(path, (str, os.PathLike)) and not hasattr(path, "write"):
        raise ParameterError("path", _given(path), "a file name (str or os.PathLike) or a file opened for writing")
    if isinstance(path, (str, os.PathLike)):
        suffix = os.path.splitext(os.fspath(path))[1].lstrip(".").lower()
        formats = fig.canvas.get_supported_filetypes()
        if suffix not in formats:
            raise ParameterError("path", _given(path), f"a file name ending in one of .{', .'.join(sorted(formats))} "
                                 "(the format)")
    positive("dpi", dpi)
    fig.tight_layout()
    problems = legibility_problems(fig)
    fig.savefig(path, dpi=dpi)
    return problems


def lay_out(fig) -> None:
    """Lay out ``fig`` as it will be shown (in a notebook, its legends off the other panels); a
    subfigure is laid out with the figure that holds it."""
    if isinstance(fig, Figure):
        fig.tight_layout()


def legend_beside(ax, *args, **kwargs):
    """A legend to the right of ``ax``, off its data (the layout makes room for it)."""
    _axes("ax", ax)
    return ax.legend(*args, **{"fontsize": 8, "loc": "upper left", "bbox_to_anchor": (1.02, 1.0),
                               "borderaxespad": 0.0, **kwargs})


def legend_above(ax, *args, **kwargs):
    """A legend over ``ax`` in one row (by default), off its data: ``ax`` has no title then."""
    _axes("ax", ax)
    handles = args[0] if args else kwargs.get("handles")
    if handles is not None and not isinstance(handles, (list, tuple)):
        raise ParameterError("handles", _given(handles), "a list of legend handles (artists)")
    ncol = len(handles) if handles is not None else len(ax.get_legend_handles_labels()[0])
    return ax.legend(*args, **{"fontsize": 8, "loc": "lower center", "bbox_to_anchor": (0.5, 1.02),
                               "borderaxespad": 0.0, "ncol": max(ncol, 1), **kwargs})


def wrap(text: str, width: int = 90) -> str:
    """``text`` broken into lines of at most ``width`` characters (titles that must fit the figure)."""
    import textwrap

    _text("text", text)
    width = count("width", width, 10**6, "characters a line")
    return "\n".join(textwrap.fill(line, width) for line in text.split("\n"))


def label_curves(ax, curves, labels, fontsize: float = 8.0, shrink: float = 0.8) -> None:
    """Write ``labels[k]`` next to ``curves[k]`` (``(x, y)`` arrays in data units) off every curve.

    The candidate spots are just above the top, right of the rightmost point, below the bottom
    and left of the leftmost point of the curve; the first (in that order) whose text box holds
    no point of any curve, no other label and stays inside the axes is taken, else the least
    covered. Call it after the limits are final. Text sizes are estimated before the layout,
    on axes ``shrink`` times their current size (a margin for the layout to come)."""
    _axes("ax", ax)
    if not isinstance(curves, (list, tuple)):
        raise ParameterError("curves", _given(curves), "a list of (x, y) pairs of 1-D arrays")
    for k, curve in enumerate(curves):
        if not isinstance(curve, (list, tuple)) or len(curve) != 2:
            raise ParameterError(f"curves[{k}]", _given(curve), "an (x, y) pair of 1-D arrays")
        x, y = _line(f"curves[{k}][0]", curve[0]), _line(f"curves[{k}][1]", curve[1])
        if x.size != y.size or not (np.isfinite(x) & np.isfinite(y)).any():
            raise ParameterError(f"curves[{k}]", f"<x of {x.size}, y of {y.size} points>", "x and y of the same "
                                 "length with at least one point of finite x and y")
    if not isinstance(labels, (list, tuple)) or len(labels) != len(curves):
        raise ParameterError("labels", _given(labels), f"a list of {len(curves)} texts, one a curve")
    for k, label in enumerate(labels):
        _text(f"labels[{k}]", label)
    fontsize, shrink = positive("fontsize", fontsize), in_range("shrink", shrink, 0.0, 1.0, lo_open=True)
    fig = ax.figure
    pos = ax.get_position()
    width, height = pos.width * fig.get_figwidth() * shrink, pos.height * fig.get_figheight() * shrink
    (x0, x1), (y0, y1) = ax.get_xlim(), ax.get_ylim()

    def inches(x, y):
        return (np.asarray(x, float) - x0) / (x1 - x0) * width, (np.asarray(y, float) - y0) / (y1 - y0) * height

    pts = []
    for x, y in curves:
        x, y = np.append(x, x[0]), np.append(y, y[0])  # closed orbits: the closing chord too
        px, py = inches(x, y)
        t = np.linspace(0.0, 1.0, 8)[:, None]
        pts.append(np.column_stack([(px[:-1] + t * np.diff(px)).ravel(), (py[:-1] + t * np.diff(py)).ravel()]))
    pts = np.concatenate(pts) if pts else np.zeros((0, 2))
    pts = pts[np.isfinite(pts).all(axis=1)]
    taken = []
    gap = 3.0 / 72  # clear of the curve (and of the margin of `legibility_problems`)
    for (x, y), text in zip(curves, labels):
        ok = np.isfinite(x) & np.isfinite(y)
        x, y = np.asarray(x, float)[ok], np.asarray(y, float)[ok]
        w = 0.62 * fontsize * max(len(line) for line in text.split("\n")) / 72
        h = 1.3 * fontsize * (text.count("\n") + 1) / 72
        spots = []
        top, right = y >= y.max() - 1e-3 * np.ptp(y), x >= x.max() - 1e-3 * np.ptp(x)
        bottom, left = y <= y.min() + 1e-3 * np.ptp(y), x <= x.min() + 1e-3 * np.ptp(x)
        for sel, along, (dx, dy), ha, va in ((top, "x", (0, gap), "center", "bottom"),
                                             (right, "y", (gap, 0), "left", "center"),
                                             (bottom, "x", (0, -gap), "center", "top"),
                                             (left, "y", (-gap, 0), "right", "center")):
            ax_ = float(np.mean(x[sel])) if along == "x" else float(x[sel][0])
            ay_ = float(np.mean(y[sel])) if along == "y" else float(y[sel][0])
            cx, cy = inches(ax_, ay_)
            cx, cy = float(cx) + dx, float(cy) + dy
            bx0 = cx - w / 2 if ha == "center" else (cx if ha == "left" else cx - w)
            by0 = cy - h / 2 if va == "center" else (cy if va == "bottom" else cy - h)
            box = (bx0, by0, bx0 + w, by0 + h)
            inside = np.count_nonzero((pts[:, 0] >= box[0]) & (pts[:, 0] <= box[2]) & (pts[:, 1] >= box[1])
                                      & (pts[:, 1] <= box[3]))
            clash = sum(min(box[2], b[2]) > max(box[0], b[0]) and min(box[3], b[3]) > max(box[1], b[1])
                        for b in taken)
            out = box[0] < 0 or box[1] < 0 or box[2] > width or box[3] > height
            spots.append((inside + 1000 * (clash + out), len(spots), (ax_, ay_), (dx * 72, dy * 72), ha, va, box))
        score, _, xy, offset, ha, va, box = min(spots)
        taken.append(box)
        ax.annotate(text, xy, xytext=offset, textcoords="offset points", ha=ha, va=va, fontsize=fontsize)


def mode_handles(modes=(0, 1, -1)) -> list:
    """Legend handles of the contact-mode colours of `modal_line`."""
    modes = _keys("modes", modes, MODE_COLOURS)
    return [Line2D([], [], color=MODE_COLOURS[m], label=MODE_LABELS[m]) for m in modes]


def modal_line(ax, x, y, mode, lw=1.2, alpha=1.0):
    """A curve coloured by contact mode (stick, slip, reverse slip)."""
    _axes("ax", ax)
    x, y, mode = _line("x", x), _line("y", y), _line("mode", mode)
    if not x.size == y.size == mode.size:
        raise ParameterError("y", f"<{y.size} points>", f"as many points as x ({x.size}), and mode as many "
                             f"({mode.size})")
    lw, alpha = positive("lw", lw), in_range("alpha", alpha, 0.0, 1.0)
    ok = np.isfinite(x) & np.isfinite(y)
    if not np.isfinite(mode[ok]).all():
        raise ParameterError("mode", "<NaN where x and y are numbers>", "a contact mode (-1, 0, 1) at every point")
    x, y, mode = x[ok], y[ok], mode[ok]
    if x.size == 0:
        return
    cuts = np.nonzero(np.diff(mode))[0] + 1
    for seg in np.split(np.arange(x.size), cuts):
        if seg.size == 0:
            continue
        idx = np.arange(max(seg[0] - 1, 0), seg[-1] + 1)
        ax.plot(x[idx], y[idx], color=MODE_COLOURS.get(int(mode[seg[0]]), "k"), lw=lw, alpha=alpha)


def oscillator_phase(ax, ds, title: str | None = None) -> None:
    """Phase portrait ``(x, v)`` of a simulated or periodic trajectory dataset."""
    _axes("ax", ax)
    _dataset("ds", ds, "a trajectory (Trajectory or LimitCycle .to_xarray())", OSCILLATOR[1:])
    _text("title", title, optional=True)
    modal_line(ax, ds["x"].values, ds["v"].values, ds["mode"].values)
    ax.axhline(ds.attrs.get("belt_speed_m_per_s", np.nan), color="0.6", lw=0.6, ls=":")
    ax.set_xlabel("x [m]")
    ax.set_ylabel("dx/dt [m/s]")
    handles = mode_handles() + [Line2D([], [], color="0.6", lw=0.6, ls=":", label="belt speed")]
    legend_beside(ax, handles=handles)
    if title:
        ax.set_title(title)


def state_image(ax, state, title: str = "", extent=(0, 2 * np.pi, 0, 2)):
    """Contact-node states (rows: times, columns: nodes along the contact line) as an image
    (explain its colours with `state_legend`)."""
    from matplotlib.colors import ListedColormap

    _axes("ax", ax)
    array = real_array("state", state)
    if array.ndim != 2 or array.size == 0:
        raise ParameterError("state", _given(state), "a 2-D array of node states 0 to 3 (rows: times, columns: "
                             "nodes)")
    _text("title", title)
    extent = finite_array("extent", extent, 1)
    if extent.size != 4:
        raise ParameterError("extent", _given(extent.tolist()), "(left, right, bottom, top): 4 finite numbers")
    im = ax.imshow(state, aspect="auto", origin="lower", cmap=ListedColormap(STATE_COLOURS), vmin=-0.5, vmax=3.5,
                   interpolation="nearest", extent=extent)
    if title:
        ax.set_title(title, fontsize=8)
    ax.set_xticks([0, np.pi, 2 * np.pi], ["0", "π", "2π"])
    return im


def state_legend(ax, **kwargs) -> None:
    """A legend of the four contact-node states (by default beside ``ax``, off its image)."""
    from matplotlib.patches import Patch

    _axes("ax", ax)
    names = ("stick", "slip", "reverse slip", "separation")
    handles = [Patch(facecolor=c, edgecolor="0.5", lw=0.5, label=n) for c, n in zip(STATE_COLOURS, names)]
    legend_beside(ax, handles=handles, **{"title": "node state", "title_fontsize": 8, **kwargs})


def zone_legend(ax, kinds=None, marker=None, **kwargs) -> None:
    """A legend of the zone kinds of a travelling wave (``kinds``: those shown, default all;
    ``marker``: zones drawn as markers rather than lines)."""
    _axes("ax", ax)
    kinds = _keys("kinds", kinds, ZONE_COLOURS, optional=True)
    _text("marker", marker, optional=True)
    kinds = [k for k in ZONE_COLOURS if kinds is None or k in kinds]
    style = {"ls": "none", "marker": marker, "ms": 5} if marker else {}
    ax.legend([Line2D([], [], color=ZONE_COLOURS[k], **style) for k in kinds], kinds,
              **{"fontsize": 8, "loc": "best", **kwargs})


def plot_cycle(ds, fig: Figure | None = None) -> Figure:
    """A limit cycle (`LimitCycle.to_xarray`): phase portrait and ``x(t)``."""
    _dataset("ds", ds, "a limit cycle (LimitCycle.to_xarray())", OSCILLATOR)
    fig, (ax1, ax2) = new_figure(fig, 2, size=(5.5, 4.2))
    oscillator_phase(ax1, ds, "limit cycle")
    ax2.plot(ds["t"], ds["x"], lw=1)
    ax2.set(xlabel="t [s]", ylabel="x [m]")
    lay_out(fig)
    return fig


def plot_trajectory(ds, fig: Figure | None = None) -> Figure:
    """A simulated trajectory (`Trajectory.to_xarray`): phase portrait and ``x(t)`` by contact mode."""
    _dataset("ds", ds, "a trajectory (Trajectory.to_xarray())", OSCILLATOR)
    fig, (ax1, ax2) = new_figure(fig, 2, size=(5.5, 4.2))
    oscillator_phase(ax1, ds, "phase portrait")
    modal_line(ax2, ds["t"].values, ds["x"].values, ds["mode"].values)
    ax2.set(xlabel="t [s]", ylabel="x [m]", title="displacement (colours as in the phase portrait)")
    lay_out(fig)
    return fig


def plot_branch(ds, fig: Figure | None = None) -> Figure:
    """A branch of limit cycles (`Branch.to_xarray`): amplitude and period, stable or not."""
    _dataset("ds", ds, "a branch (Branch.to_xarray())", ("parameter_value", "stable", "amplitude", "period"))
    _figure("fig", fig)
    fig, axes = new_figure(fig, 2, size=(5.5, 4.2))
    p = ds["parameter_value"].values
    stable = ds["stable"].values.astype(bool)
    name = str(ds.attrs.get("continuation_parameter", "parameter"))
    units = ds["parameter_value"].attrs.get("units") or PARAMETER_UNITS.get(name, "1")
    for ax, key in zip(axes, ("amplitude", "period")):
        ax.plot(p, ds[key], color="0.7", lw=0.8)
        ax.plot(p[stable], ds[key].values[stable], "o", color="tab:blue", ms=3, label="stable")
        ax.plot(p[~stable], ds[key].values[~stable], "x", color="tab:red", ms=3, label="unstable")
        ax.set(xlabel=f"{name.replace('_', ' ')} [{units}]", ylabel=f"{key} [{ds[key].attrs.get('units', '1')}]")
    legend_beside(axes[-1])
    lay_out(fig)
    return fig


def plot_stability_map(ds, fig: Figure | None = None) -> Figure:
    """A CEA sweep with tracked modes (`stickslip.fem.tracking.Tracked.to_xarray`): growth rate
    and frequency of every branch against the swept value, its unstable stretches in red and
    thick, each critical value a circle."""
    _dataset("ds", ds, "tracked modes (Tracked.to_xarray())", ("value", "growth_rate", "frequency", "growing",
                                                                "critical", "critical_frequency"))
    if "branch" not in ds.dims:
        raise ParameterError("ds", f"<Dataset of dimensions {', '.join(map(str, ds.dims))}>", "tracked modes along "
                             "a dimension 'branch' (Tracked.to_xarray())")
    _figure("fig", fig)
    fig, (ax1, ax2) = new_figure(fig, 2, size=(5.5, 5.6))
    x = ds["value"].values
    key = str(ds.attrs.get("swept_key", "value"))
    units = ds["value"].attrs.get("units", "1")
    for b in range(ds.sizes["branch"]):
        g, f = ds["growth_rate"].values[b], ds["frequency"].values[b] / 1e3
        up = ds["growing"].values[b].astype(bool)
        for ax, y in ((ax1, g), (ax2, f)):
            ax.plot(x, y, color="0.6", lw=0.8)
            ax.plot(x, np.where(up, y, np.nan), color="tab:red", lw=2.2)
        c = float(ds["critical"].values[b])
        if np.isfinite(c):
            ax1.plot([c], [0.0], "o", color="k", mfc="none", ms=5)
            ax2.plot([c], [float(ds["critical_frequency"].values[b]) / 1e3], "o", color="k", mfc="none", ms=5)
    ax1.axhline(0.0, color="k", lw=0.5)
    label = f"{key} [{units or '1'}]"
    ax1.set(xlabel=label, ylabel="growth rate [1/s]", title="tracked modes")
    ax2.set(xlabel=label, ylabel="frequency [kHz]")
    handles = [Line2D([], [], color="0.6", lw=0.8, label="stable or neutral"),
               Line2D([], [], color="tab:red", lw=2.2, label="unstable"),
               Line2D([], [], ls="none", marker="o", color="k", mfc="none", label="critical value")]
    legend_beside(ax2, handles=handles)
    return fig


def plot_friction_map(ds, fig: Figure | None = None) -> Figure:
    """A stability map over the friction and one more number (`stickslip.fem.maps.stability_map`): the
    largest growth rate of the band's modes over both axes (diverging about 0: stable blue, growing red),
    the onset friction of each value a black line."""
    from matplotlib.colors import TwoSlopeNorm

    _dataset("ds", ds, "a stability map (stability_map)", ("max_growth_rate", "onset", "value", "friction"))
    _figure("fig", fig)
    fig, (ax,) = new_figure(fig, size=(6.4, 4.6))
    g = ds["max_growth_rate"].values
    top = float(np.nanmax(np.abs(g))) if np.any(np.isfinite(g)) else 1.0
    top = top if top > 0 else 1.0
    mesh = ax.pcolormesh(ds["friction"].values, ds["value"].values, g, shading="nearest", cmap="RdBu_r",
                         norm=TwoSlopeNorm(0.0, -top, top))
    fig.colorbar(mesh, ax=ax, label="largest growth rate [1/s]")
    onset = ds["onset"].values
    ax.plot(onset, ds["value"].values, "k-o", ms=3, lw=1.2, label="onset friction")
    key = str(ds.attrs.get("swept_key", "value"))
    units = ds["value"].attrs.get("units", "1") or "1"
    ax.set(xlabel="friction coefficient", ylabel=f"{key} [{units}]", title="stability map")
    ax.legend(loc="lower left", fontsize=8)
    return fig


def plot_oscillator_map(ds, regimes: dict, fig: Figure | None = None) -> Figure:
    """A regime map of the oscillator over its two sweep axes (``regime`` codes named by ``regimes``)."""
    from matplotlib.colors import BoundaryNorm, ListedColormap

    _dataset("ds", ds, "a regime map (codes in a 2-D variable 'regime')", ("regime",))
    if ds["regime"].ndim != 2:
        raise ParameterError("ds", f"<Dataset with a {ds['regime'].ndim}-D regime>", "a regime map over two axes "
                             "(a 2-D variable 'regime')")
    if not isinstance(regimes, dict) or not regimes:
        raise ParameterError("regimes", _given(regimes), "a dict of regime codes (integers) to names")
    for k in regimes:
        if isinstance(k, bool) or not isinstance(k, (int, np.integer, str)) or not str(k).lstrip("-").isdigit():
            raise ParameterError("regimes", _given(regimes), f"a dict of regime codes (integers) to names ({k!r} is "
                                 "no integer)")
    codes = ds["regime"].values[np.isfinite(ds["regime"].values)]
    unnamed = sorted(set(int(c) for c in codes) - {int(k) for k in regimes})
    if unnamed:
        raise ParameterError("regimes", _given(regimes), f"a name for every code of ds.regime ({unnamed} have none)")
    _figure("fig", fig)
    fig, (ax,) = new_figure(fig, size=(8.4, 5.2))
    names = [d for d in ds["regime"].dims]
    codes = sorted(int(k) for k in regimes)
    # one colour per category (code k is the interval k +- 1/2), a labelled colour-bar tick each
    palette = ["#9ecae1", "#fdae6b", "#e6550d", "#74c476", "#bbbbbb", "#9e9ac8", "#fdd0a2", "#31a354"]
    cmap = ListedColormap([palette[i % len(palette)] for i in range(len(codes))])
    bounds = np.concatenate([[codes[0] - 0.5], np.asarray(codes[1:], float) - 0.5, [codes[-1] + 0.5]])
    mesh = ax.pcolormesh(ds[names[0]], ds[names[1]], ds["regime"].values.T, shading="nearest", cmap=cmap,
                         norm=BoundaryNorm(bounds, cmap.N))
    bar = fig.colorbar(mesh, ax=ax, label="regime (white: not computed)")
    bar.set_ticks([float(k) for k in codes], labels=[wrap(str(regimes[k]), 22) for k in codes])
    bar.ax.tick_params(labelsize=8, length=0)
    bar.minorticks_off()

    def label(name):
        units = ds[name].attrs.get("units") or PARAMETER_UNITS.get(name, "1")
        return f"{name.replace('_', ' ')} [{units}]"

    ax.set(xlabel=label(names[0]), ylabel=label(names[1]))
    return fig


def plot_interface_fields(ds, fig: Figure | None = None) -> Figure:
    """The interface fields of a half-space wave (``StickSlipWave.fields(...).to_xarray()``)."""
    _dataset("ds", ds, "a half-space wave's fields (StickSlipWave.fields(...).to_xarray())",
             ("x", "zone", "stress_yy", "stress_xy", "u_xx", "slip_velocity", "material_velocity"))
    _figure("fig", fig)
    fig = Figure(figsize=(8, 8)) if fig is None else fig
    axes = fig.subplots(3, 1, sharex=True)
    x = ds.x.values
    order = np.argsort(x)
    stick = ds.zone.values[order] == 0
    for ax, names, label in ((axes[0], ("stress_yy", "stress_xy"), "stress / G [1]"), (axes[1], ("u_xx",), "u_x,x [1]"),
                             (axes[2], ("slip_velocity", "material_velocity"), "velocity / c2 [1]")):
        finite = np.concatenate([ds[n].values[np.isfinite(ds[n].values)] for n in names])
        lo, hi = np.percentile(finite, [1, 99])
        pad = 0.3 * (hi - lo + 1e-30)
        lo, hi = lo - pad, hi + pad
        clipped = bool(np.any((finite < lo) | (finite > hi)))
        for name in names:
            ax.plot(x[order], ds[name].values[order], lw=1, label=name, gid=CLIPPED if clipped else None)
        ax.set_ylim(lo, hi)
        ax.set_ylabel(label)
        legend_beside(ax, title="clipped at the singularities" if clipped else None, title_fontsize=7)
        ax.fill_between(x[order], 0, 1, where=stick, transform=ax.get_xaxis_transform(), color="0.9", lw=0)
    axes[-1].set_xlabel("x / a [1]  (grey: stick)")
    a = ds.attrs
    axes[0].set_title(f"c = {a.get('c', float('nan')):.3g}, b = {a.get('b', float('nan')):.4g}, "
                      f"v = {a.get('v', float('nan')):.3g}, T = {a.get('T', float('nan')):.3g}")
    lay_out(fig)
    return fig


def plot_fault_cycles(ds, fig: Figure | None = None) -> Figure:
    """A fault's run (`stickslip.sbim.fault.FaultRun.to_xarray()`): its largest slip rate over time, and
    its slip profiles against depth, those during an event in orange."""
    _dataset("ds", ds, "a fault's run (FaultRun.to_xarray())", ("max_slip_rate", "step_t", "slip", "profile_t",
                                                                 "event_start", "event_end", "z"))
    _figure("fig", fig)
    fig = Figure(figsize=(9.0, 4.4)) if fig is None else fig
    left, right = fig.subplots(1, 2)
    year = 365.0 * 86400.0
    left.semilogy(ds.step_t.values / year, ds.max_slip_rate.values, "k-", lw=0.8)
    left.set_xlabel("t [years]")
    left.set_ylabel("largest slip rate [m/s]")
    starts, ends = ds.event_start.values, ds.event_end.values
    for t, slip in zip(ds.profile_t.values, ds.slip.values):
        during = bool(np.any((starts <= t) & (t <= ends)))
        right.plot(slip, ds.z.values / 1e3, color="C1" if during else "C0", lw=0.5)
    right.invert_yaxis()
    right.set_xlabel("slip [m]")
    right.set_ylabel("depth [km]")
    right.set_title("profiles: locked (blue), during events (orange)", fontsize=9)
    lay_out(fig)
    return fig


def plot_space_time(ds, names=("slip_rate", "normal_traction"), fig: Figure | None = None) -> Figure:
    """Fields of an interface run over ``x`` and ``t`` (an `stickslip.sbim` run's ``to_xarray()``), one
    image each, side by side."""
    _dataset("ds", ds, "an interface run's fields (InplaneRun.to_xarray())", ("t", "x") + tuple(names))
    _figure("fig", fig)
    fig = Figure(figsize=(4.2 * len(names) + 1.0, 4.8)) if fig is None else fig
    axes = np.atleast_1d(fig.subplots(1, len(names), sharey=True))
    t, x = ds.t.values, ds.x.values
    extent = (x[0] / 1e3, x[-1] / 1e3, t[-1], t[0])
    for ax, name in zip(axes, names):
        values = ds[name].values
        signed = bool(np.nanmin(values) < 0 < np.nanmax(values))
        top = float(np.nanmax(np.abs(values))) or 1.0
        image = ax.imshow(values, aspect="auto", extent=extent, interpolation="nearest",
                          cmap="RdBu_r" if signed else "viridis", vmin=-top if signed else None,
                          vmax=top if signed else None)
        units = ds[name].attrs.get("units", "1")
        fig.colorbar(image, ax=ax, label=f"{name.replace('_', ' ')} [{units}]")
        ax.set_xlabel("x [km]")
    axes[0].set_ylabel("t [s]")
    status = ds.attrs.get("well_posedness", "")
    if status.startswith("ill-posed"):
        fig.suptitle("ill-posed: the result depends on the grid (see the run's well_posedness)", fontsize=9)
    lay_out(fig)
    return fig
