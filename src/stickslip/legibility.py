"""Is a figure legible at 100 %? `legibility_problems`: the report's figures, the notebooks' and the
command line's are laid out, then checked by these rules (texts large enough in the report's column, no
overlaps, legends and labels off the curves, units on the axes, colour codes explained).

It reads a laid-out `matplotlib.figure.Figure` and draws nothing (`stickslip.plotting` draws).
"""

from __future__ import annotations

import numpy as np
from matplotlib.figure import Figure

from .validation import instance, positive

__all__ = ["legibility_problems", "REPORT_WIDTH_IN", "MIN_FONT_PT", "CLIPPED"]

#: Rules and thresholds of `legibility_problems`, fixed before any figure was measured.
MIN_FONT_PT = 7.0
#: Width of the report's column (``max-width: 70em`` at 16 px = 1120 CSS px = 11.67 in): a wider
#: figure is shrunk to it, and so are its texts.
REPORT_WIDTH_IN = 1120 / 96
#: Two text boxes overlap when they intersect by more than this (points) in both directions.
OVERLAP_PT = 1.0
#: Length of data curve (points) a legend or a text may cover: a curve grazing a corner, no more;
#: the boxes are grown by `COVER_PAD_PT` first (a text touching a curve sits on it: added after the
#: first measurements, where a label set at a curve's vertical tangent was not caught).
COVER_PT = 2.0
COVER_PAD_PT = 1.5
#: A colour map of at most this many colours codes categories (it needs a legend of them).
CATEGORICAL_COLOURS = 16
#: A unit in an axis label: in square brackets, ``[m/s]``, ``[rad]``, ``[1]`` for a pure number.
UNIT = r"\[[^\]]*\S[^\]]*\]"
#: The ``gid`` of a line clipped on purpose (a singularity); the figure must say "clipped".
CLIPPED = "clipped"


def legibility_problems(fig: Figure, width_in: float | None = REPORT_WIDTH_IN) -> list[str]:
    """What makes ``fig`` hard to read at 100 %, as it is laid out now (call after the layout).

    The rules (thresholds in the module constants, chosen before measuring the figures, but
    for `COVER_PAD_PT`):

    * every visible, non-empty text is at least `MIN_FONT_PT` points as shown in a column
      ``width_in`` inches wide (the report's, `REPORT_WIDTH_IN`): a wider figure is shrunk to
      the column, and its texts with it (``width_in=None``: the figure's own size);
    * every axes with data has an x and a y label with a unit in square brackets (`UNIT`);
      a categorical axis (text tick labels) needs a label but no unit, an axis shared with a
      labelled one and showing no tick labels needs neither; a colour bar's long axis is
      labelled likewise;
    * titles, axis labels, tick labels, texts and legends do not overlap each other (by more
      than `OVERLAP_PT` both ways) and lie inside the figure; texts in an axes lie inside it;
    * legends and texts do not cover data: at most `COVER_PT` points of data curve and no
      marker inside their boxes grown by `COVER_PAD_PT`; a legend does not lie on an image or
      a bar (a text on a cell of an image is a cell label);
    * data curves do not run off the axes: no finite vertex outside the view limits (or
      ``<= 0`` on a log axis), unless the line's gid is `CLIPPED` and a text of the figure says so;
    * colour codes are explained: every colour of a categorical image or mesh (colour map of
      at most `CATEGORICAL_COLOURS` colours) is in a legend, or its colour bar has a text tick
      per category; a continuous one has a colour bar; where data lines or bars of an axes
      have two or more colours (not black or grey), each is in a legend of the figure.
    """
    import re

    instance("fig", fig, Figure, "a matplotlib Figure (not a SubFigure)")
    if width_in is not None:
        width_in = positive("width_in", width_in)
    fig.draw_without_rendering()
    scale = 72.0 / fig.dpi  # display pixels -> points
    shrink = min(1.0, width_in / fig.get_figwidth()) if width_in else 1.0
    problems: list[str] = []

    def small(text):
        return text.get_fontsize() * shrink < MIN_FONT_PT - 1e-9

    def size(text):
        shown = f", {text.get_fontsize() * shrink:.1f} pt in the report" if shrink < 1 else ""
        return f"{text.get_fontsize():g} pt{shown} (< {MIN_FONT_PT:g} pt)"

    axes = _all_axes(fig)
    names = {ax: _axes_name(ax, i) for i, ax in enumerate(axes)}

    # texts: font sizes, boxes
    boxes = []  # (description, bbox, inside-axes or None)
    for text, where, inside in _texts(fig, axes, names):
        if small(text):
            problems.append(f"{where}: text {_quote(text)} is {size(text)}")
        boxes.append((f"{where} {_quote(text)}", text.get_window_extent(), inside))
    for legend, where in _legends(fig, axes, names):
        for text in [*legend.get_texts(), legend.get_title()]:
            if _shown(text) and small(text):
                problems.append(f"{where}: legend text {_quote(text)} is {size(text)}")
        boxes.append((where, legend.get_window_extent(), None))
    tol = OVERLAP_PT / scale
    page = fig.bbox
    for k, (what, box, inside) in enumerate(boxes):
        if box.x0 < page.x0 - tol or box.y0 < page.y0 - tol or box.x1 > page.x1 + tol or box.y1 > page.y1 + tol:
            problems.append(f"{what} runs off the figure")
        if inside is not None:
            a = inside.bbox
            if box.x0 < a.x0 - tol or box.y0 < a.y0 - tol or box.x1 > a.x1 + tol or box.y1 > a.y1 + tol:
                problems.append(f"{what} runs over the frame of its axes")
        for other, obox, _ in boxes[k + 1:]:
            w = min(box.x1, obox.x1) - max(box.x0, obox.x0)
            h = min(box.y1, obox.y1) - max(box.y0, obox.y0)
            if w > tol and h > tol:
                problems.append(f"{what} overlaps {other}")

    # labels and units
    unit = re.compile(UNIT)
    for ax in axes:
        cb = getattr(ax, "_colorbar", None)
        if cb is not None:
            axis = ax.yaxis if cb.orientation == "vertical" else ax.xaxis
            problems += _label_problems(axis, f"{names[ax]} colour bar", unit, ax)
            continue
        if not ax.axison or not _has_data(ax):
            continue
        for axis in (ax.xaxis, ax.yaxis):
            problems += _label_problems(axis, names[ax], unit, ax)

    # legends and texts over data; curves off the axes
    pad = COVER_PAD_PT / scale
    covers = [(where, legend.get_window_extent().padded(pad), True) for legend, where in _legends(fig, axes, names)]
    covers += [(f"{names[ax]} text {_quote(t)}", t.get_window_extent().padded(pad), False)
               for ax in axes for t in ax.texts if _shown(t) and not _on_image(ax, t)]
    said = " ".join(t.get_text() for t, _, _ in _texts(fig, axes, names)).lower()
    said += " ".join(t.get_text() for legend, _ in _legends(fig, axes, names)
                     for t in [*legend.get_texts(), legend.get_title()]).lower()
    for ax in axes:
        if getattr(ax, "_colorbar", None) is not None:
            continue
        curves, points, areas = _data_geometry(ax)
        for what, box, is_legend in covers:
            covered = sum(float(np.count_nonzero(_inside(box, c))) for c in curves) * scale
            if covered > COVER_PT:
                problems.append(f"{what} covers {covered:.0f} pt of the curves of {names[ax]}")
            hits = sum(int(np.count_nonzero(_inside(box, p))) for p in points)
            if hits:
                problems.append(f"{what} covers {hits} marker(s) of {names[ax]}")
            if is_legend:
                for kind, area in areas:
                    w = min(box.x1, area.x1) - max(box.x0, area.x0)
                    h = min(box.y1, area.y1) - max(box.y0, area.y0)
                    if w > tol and h > tol:
                        problems.append(f"{what} lies on the {kind} of {names[ax]}")
                        break
        for line in _data_lines(ax):
            off = _off_axes(ax, line)
            if off and not (line.get_gid() == CLIPPED and CLIPPED in said):
                problems.append(f"{names[ax]}: {off} vertices of the curve {_line_name(line)} lie outside the axes")

    # colour codes
    legend_colours = _legend_colours(fig, axes)
    for ax in axes:
        if getattr(ax, "_colorbar", None) is not None:
            continue
        for mappable in [*ax.images, *[c for c in ax.collections if c.get_array() is not None]]:
            problems += _colour_code_problems(mappable, names[ax], legend_colours)
        colours = {}
        for artist in [*_data_lines(ax), *[p for c in ax.containers for p in getattr(c, "patches", [])]]:
            rgb = _rgb(artist.get_color() if hasattr(artist, "get_color") and not hasattr(artist, "get_facecolor")
                       else artist.get_facecolor())
            if rgb is not None and not _neutral(rgb):
                colours.setdefault(rgb, artist)
        if len(colours) >= 2:
            for rgb, artist in colours.items():
                if not any(_close(rgb, c) for c in legend_colours):
                    problems.append(f"{names[ax]}: the colour {_hex(rgb)} (of {_line_name(artist)}) is in no legend")
    return problems


def _all_axes(fig):
    out = []

    def walk(ax):
        if not ax.get_visible():
            return
        out.append(ax)
        for child in getattr(ax, "child_axes", []):
            walk(child)

    for ax in fig.axes:
        walk(ax)
    return out


def _axes_name(ax, i):
    title = ax.get_title() or ax.get_title("left") or ax.get_ylabel() or ax.get_xlabel()
    title = title.replace("\n", " ")
    return f"axes {i + 1}" + (f" ({title[:40]})" if title else "")


def _quote(text):
    s = text.get_text().replace("\n", " ")
    return repr(s if len(s) <= 40 else s[:37] + "...")


def _shown(text):
    return text.get_visible() and bool(text.get_text().strip())


def _drawn_ticks(axis):
    try:
        ticks = axis._update_ticks()  # the ticks inside the view (the drawn ones)
    except Exception:  # pragma: no cover - a future matplotlib
        ticks = axis.get_major_ticks()
    return ticks


def _texts(fig, axes, names):
    """``(text, where, axes it must lie in or None)`` for every visible non-empty text but legends'."""
    for t in fig.texts:
        if _shown(t):
            yield t, "figure", None
    for ax in axes:
        where = names[ax]
        for t in (ax.title, ax._left_title, ax._right_title):
            if _shown(t):
                yield t, f"{where} title", None
        for t in ax.texts:
            if _shown(t):
                yield t, f"{where} text", ax
        if not ax.axison:
            continue
        for name, axis in (("x", ax.xaxis), ("y", ax.yaxis)):
            if not axis.get_visible():
                continue
            if _shown(axis.label):
                yield axis.label, f"{where} {name} label", None
            if _shown(axis.offsetText):
                yield axis.offsetText, f"{where} {name} offset", None
            for tick in _drawn_ticks(axis):
                for t in (tick.label1, tick.label2):
                    if _shown(t) and t.get_visible():
                        yield t, f"{where} {name} tick label", None


def _legends(fig, axes, names):
    for legend in fig.legends:
        if legend.get_visible():
            yield legend, "figure legend"
    for ax in axes:
        legend = ax.get_legend()
        if legend is not None and legend.get_visible():
            yield legend, f"{names[ax]} legend"


def _numeric(label: str) -> bool:
    import re

    s = re.sub(r"\\mathdefault|\\times|\\cdot|[${}^\\]", "", label)
    return bool(re.fullmatch(r"[\s\d.,+\-−×·πe]*", s)) and bool(re.search(r"[\dπ]", s))


def _label_problems(axis, where, unit, ax):
    name = "x" if axis is ax.xaxis else "y"
    label = axis.get_label_text().strip() if axis.label.get_visible() else ""
    ticks = [t.label1.get_text() for t in _drawn_ticks(axis) if t.label1.get_visible() and t.label1.get_text().strip()]
    ticks += [t.label2.get_text() for t in _drawn_ticks(axis) if t.label2.get_visible() and t.label2.get_text().strip()]
    if not ticks:
        shared = axis._get_shared_axis() if hasattr(axis, "_get_shared_axis") else [axis]
        if any(other is not axis and other.get_label_text().strip() for other in shared):
            return []
    if not label:
        return [f"{where}: no {name} label"]
    categorical = bool(ticks) and not any(_numeric(t) for t in ticks)
    if not categorical and not unit.search(label):
        return [f"{where}: the {name} label {label!r} has no unit in square brackets"]
    return []


def _has_data(ax) -> bool:
    return bool(_data_lines(ax) or ax.images or ax.collections or ax.containers)


def _data_lines(ax):
    out = []
    for line in ax.lines:
        if not line.get_visible() or not line.get_transform().contains_branch(ax.transData):
            continue
        xy = np.asarray(line.get_xydata(), float)
        if xy.size and np.isfinite(xy).all(axis=1).any():
            out.append(line)
    return out


def _line_name(artist) -> str:
    label = artist.get_label() if hasattr(artist, "get_label") else ""
    return repr(label) if label and not label.startswith("_") else type(artist).__name__


def _data_geometry(ax):
    """Display geometry of the data of ``ax`` inside its frame: curves sampled every pixel,
    marker positions, and the boxes of images, meshes and bars."""
    from matplotlib.collections import LineCollection, PathCollection, QuadMesh

    from matplotlib.transforms import Bbox

    frame = ax.bbox
    curves, points, areas = [], [], []

    def shown(box):  # the part of an image or a mesh inside the frame (the rest is clipped)
        return Bbox.intersection(box, frame) or Bbox.from_extents(0, 0, 0, 0)

    for line in _data_lines(ax):
        xy = line.get_transform().transform(np.asarray(line.get_xydata(), float))
        if line.get_linestyle() not in ("None", "", " ", "none") and line.get_linewidth() > 0:
            curves.append(_clip(frame, _sample(xy)))
        if line.get_marker() not in (None, "None", "", " ", "none"):
            points.append(_clip(frame, xy[np.isfinite(xy).all(axis=1)]))
    for coll in ax.collections:
        if not coll.get_visible():
            continue
        if isinstance(coll, PathCollection) and len(coll.get_offsets()):
            xy = coll.get_offset_transform().transform(np.asarray(coll.get_offsets(), float))
            points.append(_clip(frame, xy[np.isfinite(xy).all(axis=1)]))
        elif isinstance(coll, LineCollection):
            for seg in coll.get_segments():
                curves.append(_clip(frame, _sample(coll.get_transform().transform(np.asarray(seg, float)))))
        elif isinstance(coll, QuadMesh):
            areas.append(("mesh", shown(coll.get_window_extent())))
    for image in ax.images:
        if image.get_visible():
            areas.append(("image", shown(image.get_window_extent())))
    for container in ax.containers:
        for patch in getattr(container, "patches", []):
            if patch.get_visible():
                areas.append(("bars", patch.get_window_extent()))
    return curves, points, areas


def _sample(xy):
    """Points every display pixel along a polyline (NaN breaks it)."""
    out = []
    ok = np.isfinite(xy).all(axis=1)
    a, b = xy[:-1], xy[1:]
    seg = ok[:-1] & ok[1:]
    a, b = a[seg], b[seg]
    if not len(a):
        return xy[ok]
    n = np.maximum(np.ceil(np.hypot(*(b - a).T)).astype(int), 1)
    idx = np.repeat(np.arange(len(a)), n)
    frac = (np.arange(n.sum()) - np.repeat(np.cumsum(n) - n, n)) / np.repeat(n, n)
    out = a[idx] + (b - a)[idx] * frac[:, None]
    return out


def _clip(frame, xy):
    return xy[_inside(frame, xy)] if len(xy) else xy


def _inside(box, xy):
    if not len(xy):
        return np.zeros(0, bool)
    return (xy[:, 0] >= box.x0) & (xy[:, 0] <= box.x1) & (xy[:, 1] >= box.y0) & (xy[:, 1] <= box.y1)


def _on_image(ax, text) -> bool:
    """A text whose anchor lies on an image or a mesh of ``ax``: a cell label."""
    from matplotlib.collections import QuadMesh

    x, y = text.get_transform().transform(text.get_unitless_position())
    areas = [im.get_window_extent() for im in ax.images]
    areas += [c.get_window_extent() for c in ax.collections if isinstance(c, QuadMesh)]
    return any(a.x0 <= x <= a.x1 and a.y0 <= y <= a.y1 for a in areas)


def _off_axes(ax, line) -> int:
    xy = np.asarray(line.get_xydata(), float)
    xy = xy[np.isfinite(xy).all(axis=1)]
    bad = np.zeros(len(xy), bool)
    for k, (lim, log) in enumerate(((ax.get_xlim(), ax.get_xscale() == "log"),
                                    (ax.get_ylim(), ax.get_yscale() == "log"))):
        lo, hi = min(lim), max(lim)
        eps = 1e-9 * (hi - lo)
        bad |= (xy[:, k] < lo - eps) | (xy[:, k] > hi + eps)
        if log:
            bad |= xy[:, k] <= 0
    return int(bad.sum())


def _rgb(colour):
    """``(r, g, b)`` rounded, of a colour or of the first of an array of colours (None if none)."""
    from matplotlib.colors import to_rgba

    try:
        r, g, b, _ = to_rgba(colour)
    except (ValueError, TypeError):
        c = np.asarray(colour, float)
        if c.ndim != 2 or not len(c):
            return None
        r, g, b, _ = to_rgba(c[0])
    return (round(r, 3), round(g, 3), round(b, 3))


def _neutral(rgb) -> bool:
    return max(rgb) - min(rgb) < 0.02


def _close(a, b, tol=0.02) -> bool:
    return max(abs(x - y) for x, y in zip(a, b)) <= tol


def _hex(rgb) -> str:
    return "#" + "".join(f"{int(round(255 * c)):02x}" for c in rgb)


def _legend_colours(fig, axes):
    out = []
    for legend, _ in _legends(fig, axes, {ax: "" for ax in axes}):
        for handle in legend.legend_handles:
            if handle is None:
                continue
            for getter in ("get_color", "get_markerfacecolor", "get_facecolor", "get_edgecolor"):
                if hasattr(handle, getter):
                    rgb = _rgb(getattr(handle, getter)())
                    if rgb is not None:
                        out.append(rgb)
    return out


def _colour_code_problems(mappable, where, legend_colours):
    values = np.ma.masked_invalid(np.ma.asarray(mappable.get_array(), float)).compressed()
    if not values.size:
        return []
    cmap = mappable.get_cmap()
    colorbar = getattr(mappable, "colorbar", None)
    if cmap.N > CATEGORICAL_COLOURS:
        return [] if colorbar is not None else [f"{where}: a colour map without a colour bar"]
    if colorbar is not None:
        axis = colorbar.ax.yaxis if colorbar.orientation == "vertical" else colorbar.ax.xaxis
        ticks = [t.label1.get_text() for t in _drawn_ticks(axis) if _shown(t.label1)]
        ticks += [t.label2.get_text() for t in _drawn_ticks(axis) if _shown(t.label2)]
        if len(ticks) >= len(np.unique(values)) and not any(_numeric(t) for t in ticks):
            return []
    missing = []
    for value in np.unique(values):
        rgb = _rgb(cmap(mappable.norm(value)))
        if not any(_close(rgb, c) for c in legend_colours):
            missing.append(f"{value:g} ({_hex(rgb)})")
    if missing:
        return [f"{where}: the categories {', '.join(missing)} of a colour code are in no legend "
                "(nor a colour bar with a text tick per category)"]
    return []
