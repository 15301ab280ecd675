"""`stickslip fem ...`: any 2-D body from a mesh file and a TOML config (see `stickslip.fem.config`)."""

from __future__ import annotations

import functools
import math
import sys
from enum import Enum
from pathlib import Path
from typing import Annotated, Optional

import typer

from ..quantities import COMMON, FEM as Q
from ..errors import NoSolutionError, ParameterError
from . import status
from .helptext import Typer
from .common import (FIGURE_HELP, FIGURE_SUFFIXES, Overwrite, Replace, RunOut, Scheduler, XdmfEvery, declared, emit, output_path, overwrite_needs, progress_bar, write_netcdf,
                     xdmf_path, xdmf_snapshots)

_emit = functools.partial(emit, model="fem")  # SI units: growth rates in 1/s, frequencies in Hz

app = Typer(no_args_is_help=True, rich_markup_mode=None,
                  help="A 2-D body of your own (a mesh file and a TOML config) on a rigid counter-surface.")

#: The library's names of what a `fem` command reads from its config, as the config writes them.
CONFIG_NAMES = {"alpha": "material.alpha", "beta": "material.beta", "band": "cea.band", "count": "cea.count",
                "complete_below": "cea.complete_below"}

Config = Annotated[Path, typer.Argument(help="The TOML config (mesh, material, contact, surface; its keys, with an "
                                                 "example: python -m pydoc stickslip.fem.config).")]
Json = Annotated[bool, typer.Option("--json", help="Print one JSON object on stdout.")]


class Start(str, Enum):
    steady = "steady"
    rest = "rest"
    stick = "stick"


StartOpt = Annotated[Start, typer.Option("--start", help=(
    "steady: steady sliding plus --amplitude noise; rest: the preload at rest (the surface drags the body); "
    "stick: the preload moving with a flat surface (the 1-DOF oscillator's stick segment)."))]


#: Samples per transit of `fem run` (`stickslip.fem.integrate_body`, `integrate_pair`): its tail's
#: snapshots are at most this dense, so a shorter --window than 2 samples never holds 3 of them.
DENSEST = 32
Set = Annotated[Optional[list[str]], typer.Option("--set", help=(
    "Replace a number of the config for this run: KEY=VALUE, the key as the config writes it (contact.friction, "
    "material[1].young) or its last part when that is one key (friction); repeatable."))]


def overrides(config: Path, sets: list[str] | None) -> dict:
    """``{config key: number}`` of the ``--set KEY=VALUE`` options (each key resolved in the config)."""
    from ..fem.config import read_toml, resolve_key

    out = {}
    for text in sets or ():
        name, sep, value = text.partition("=")
        try:
            number = float(value)
        except ValueError:
            number = None
        if not sep or number is None:
            raise ParameterError("--set", text, "KEY=VALUE with a number VALUE (e.g. contact.friction=0.5)")
        key = resolve_key(read_toml(config), name.strip(), "--set")
        if key in out:
            raise ParameterError("--set", text, f"one value per key ({key} is set twice)")
        out[key] = number
    return out


def _problem(config: Path, sets: list[str] | None = None):
    from ..fem.config import load_config

    return load_config(config, overrides(config, sets))


@app.command()
def steady(config: Config, json: Json = False,
           out: Annotated[Optional[Path], typer.Option(help=(
               "Write the contact line node by node to this netCDF file (.nc): forces [N/m], displacements [m] "
               "and contact state along the arclength [m]."))] = None,
           overwrite: Replace = False, set_: Set = None):
    """Steady sliding (or the preload, with friction 0): contact nodes, forces and nodes in contact."""
    overwrite_needs(overwrite, "--out", out)
    out = output_path("--out", out, ".nc", overwrite)
    cfg = _problem(config, set_)
    problem = cfg.problem()
    st = problem.steady
    if not st.loaded:
        d = st.to_dict()  # solids' forces are normal_load [N], plane bodies' normal_force [N/m]
        force, unit = (d["normal_load"], "N") if "normal_load" in d else (d["normal_force"], "N/m")
        print(f"warning: the contact carries no load (normal force {force:.3g} {unit}, at most "
              f"{st.load_floor:.3g}): the body only touches, and which nodes count as active is round-off",
              file=sys.stderr)
    if out is not None:  # the file first: what is printed is what was kept
        write_netcdf(st.to_xarray(), out)
    _emit(st.to_dict(), json, "steady sliding")


@app.command()
def cea(config: Config, json: Json = False,
        out: Annotated[Optional[Path], typer.Option(help=(
            "Write the modes to this netCDF file (.nc): growth rate [1/s], frequency [Hz], unstable and neutral "
            "flags, and the shifts [Hz]."))] = None,
        xdmf: Annotated[Optional[Path], typer.Option(help=(
            "Write the mode shapes for ParaView to this XDMF file (.xdmf, data in the .h5 beside it): one step per "
            "mode, most unstable first; lengths in m, growth rate [1/s], frequency [Hz]."))] = None,
        overwrite: Replace = False,
        sweep: Annotated[Optional[str], typer.Option(help=(
            "Sweep a number of the config, KEY=LO:HI:N (e.g. friction=0:0.8:41, material[1].young=1e9:1e10:10): the "
            "CEA at every value, each mode tracked along the sweep by its shape (MAC), the critical value where "
            "it turns unstable or stable located by multisection (its CEAs kept in --store too), its coupling "
            "partner. --out gets the tracked branches (.nc); needs --store."))] = None,
        store: Annotated[Optional[Path], typer.Option(help=(
            "With --sweep: the sweep's checkpoint, a Zarr store (.zarr); resumed if it holds this sweep."))] = None,
        workers: Annotated[Optional[int], declared(COMMON["workers"], "--workers", "With --sweep; default: all "
                                                                                   "cores.")] = None,
        plot: Annotated[Optional[Path], typer.Option(help=(
            "With --sweep: write the stability map (growth rate and frequency of every branch against the swept "
            "value, unstable stretches marked) to this file: PNG, SVG or PDF by its suffix."))] = None,
        scheduler: Scheduler = None, set_: Set = None,
        uff: Annotated[Optional[Path], typer.Option(help=(
            "Write the complex mode shapes of a pair to this Universal File (.uff or .unv: the nodes as dataset "
            "2411, each mode as dataset 55, for NVH tools); lengths in m."))] = None):
    """Complex eigenvalue analysis of steady sliding over [cea] band: growth rate [1/s] and
    frequency [Hz] of every mode found, most unstable first (with [cea] reduced_modes, of the
    modally reduced pair)."""
    from ..fem import complex_eigenvalues
    from ..fem.paraview import write_modes_xdmf

    if sweep is not None or store is not None or plot is not None or workers is not None or scheduler is not None:
        if set_:
            raise ParameterError("--set", set_[0], "left out with --sweep (write the fixed numbers into the config)")
        if uff is not None:
            raise ParameterError("--uff", str(uff), "left out with --sweep (the mode shapes of one CEA)")
        return _cea_sweep(config, json, out, xdmf, overwrite, sweep, store, workers, plot, scheduler)
    overwrite_needs(overwrite, "--out, --xdmf or --uff", out, xdmf, uff)
    out = output_path("--out", out, ".nc", overwrite)
    xdmf = xdmf_path(xdmf, overwrite)
    uff = output_path("--uff", uff, (".uff", ".unv"), overwrite)
    cfg = _problem(config, set_)
    if uff is not None and cfg.partner is None:
        raise ParameterError("--uff", str(uff), "given with a [partner] (the UFF writer takes a pair's modes)")
    problem = cfg.problem()
    shapes = xdmf is not None or uff is not None
    if cfg.reduced is not None:
        from ..fem.reduced import config_basis, reduced_modes

        status.phase("the reduction basis")
        result = reduced_modes(config_basis(cfg, problem), band=cfg.band, mode_shapes=shapes)
    else:
        result = complex_eigenvalues(problem, cfg.band, cfg.count, mode_shapes=shapes,
                                     complete_below=cfg.complete_below, **cfg.cea_options)
    if not result.s.size:  # nothing to report or write: said, not an empty success
        raise NoSolutionError(f"no mode of steady sliding has its frequency in cea.band = {list(cfg.band)} Hz (every "
                              f"mode there with |growth rate| below {result.complete_below:.4g} 1/s would have been "
                              "found): widen the band")
    if xdmf is not None:
        write_modes_xdmf(problem, result, xdmf)
    if uff is not None:
        from ..fem.uff import write_modes_uff

        write_modes_uff(problem, result, uff)
    if out is not None:  # the files first: what is printed is what was kept
        write_netcdf(result.to_xarray(), out)
    data = result.to_dict()
    if not result.complete:
        print(f"warning: modes growing or decaying faster than {result.complete_below:.4g} 1/s may be missing "
              f"(asked: {result.asked_below:.4g} 1/s); raise [cea] count", file=sys.stderr)
    if cfg.reduced is not None:  # every mode of the reduced problem in the band: no shifts, nothing left out
        _emit({"modes": data["modes"], "unstable": data["unstable"], "neutral": data["neutral"],
               "params": data["params"]}, json, "reduced complex eigenvalue analysis")
        return
    _emit({"modes": data["modes"], "unstable": data["unstable"], "neutral": data["neutral"],
           "complete_below": data["complete_below"], "asked_below": data["asked_below"],
           "shift_count": len(data["shifts"]), "params": data["params"]}, json, "complex eigenvalue analysis")


def _cea_sweep(config, json, out, xdmf, overwrite, sweep, store, workers, plot, scheduler):
    """`fem cea --sweep`: the tracked sweep (`stickslip.fem.tracking.cea_sweep`)."""
    from ..errors import MISSING
    from ..fem.config import load_config, read_toml, resolve_key
    from ..fem.tracking import cea_sweep
    from .common import axis, output_folder

    if sweep is None:  # the first option that belongs to a sweep is named
        option, value = next((o, v) for o, v in (("--store", store), ("--workers", workers), ("--plot", plot))
                             if v is not None)
        raise ParameterError(option, str(value), "left out without --sweep KEY=LO:HI:N (it belongs to a sweep)")
    if xdmf is not None:
        raise ParameterError("--xdmf", str(xdmf), "left out with --sweep (the mode shapes of one CEA)")
    if load_config(config).reduced is not None:
        return _reduced_sweep(config, json, out, overwrite, sweep, store, workers, plot, scheduler)
    if store is None:
        raise ParameterError("--store", MISSING, "given with --sweep: the sweep's checkpoint (a .zarr folder)")
    overwrite_needs(overwrite, "--out, --store or --plot", out, store, plot)
    out = output_path("--out", out, ".nc", overwrite)
    plot = output_path("--plot", plot, FIGURE_SUFFIXES, overwrite)
    store = output_folder("--store", store, ".zarr")
    name, values = axis("--sweep", sweep, increasing=True)
    key = resolve_key(read_toml(config), name, "--sweep")
    try:  # every value a valid config, checked before any work
        for value in values:
            load_config(config, {key: value})
    except ParameterError as err:
        raise ParameterError("--sweep", sweep, f"values of {key} each valid in the config: at {value:g}, "
                             f"{err.allowed}") from None
    with progress_bar("CEA sweep") as tick:
        tracked = cea_sweep(config, key, values, store, workers=workers, progress=tick, overwrite=overwrite,
                            scheduler=scheduler or "processes")
    _keep(tracked.to_xarray(), out, plot, "plot_stability_map")
    _emit({"swept_key": key, "sweep_points": len(values), "branches": len(tracked.s), "critical": _critical(tracked),
           "store": str(store)}, json, "CEA sweep")


def _keep(ds, out, plot, draw: str) -> None:
    """Write a sweep's or a map's dataset to ``out`` (.nc) and its picture by `stickslip.plotting`'s
    ``draw`` to ``plot``, each if asked (before anything is printed: what is printed was kept)."""
    if out is not None:
        write_netcdf(ds, out)
    if plot is not None:
        from .. import plotting

        plotting.save(getattr(plotting, draw)(ds), plot)


def _critical(tracked) -> list:
    """Each branch's critical value, turn and coupling partner, lowest first."""
    import numpy as np

    critical = [{"branch": int(b), "critical": float(tracked.critical[b]),
                 "critical_frequency": float(tracked.critical_frequency[b]), "turn": int(tracked.turn[b]),
                 "partner": int(tracked.partner[b])} for b in np.flatnonzero(np.isfinite(tracked.critical))]
    return sorted(critical, key=lambda c: c["critical"])


def _reduced_sweep(config, json, out, overwrite, sweep, store, workers, plot, scheduler):
    """`fem cea --sweep friction=...` with [cea] reduced_modes: one basis, the reduced CEA at every value
    (`stickslip.fem.reduced.reduced_sweep`)."""
    from ..fem.config import load_config, read_toml, resolve_key
    from ..fem.reduced import config_basis, reduced_sweep
    from .common import axis

    for option, value in (("--store", store), ("--workers", workers), ("--scheduler", scheduler)):
        if value is not None:
            raise ParameterError(option, str(value), "left out with cea.reduced_modes (a reduced friction sweep is one "
                                 "basis, then seconds in one process: nothing to resume or share out)")
    name, values = axis("--sweep", sweep, increasing=True)
    key = resolve_key(read_toml(config), name, "--sweep")
    if key != "contact.friction":
        raise ParameterError("--sweep", sweep, "a sweep of contact.friction with cea.reduced_modes (the basis is of one "
                             "structure: sweep another key with the full CEA, reduced_modes left out)")
    overwrite_needs(overwrite, "--out or --plot", out, plot)
    out = output_path("--out", out, ".nc", overwrite)
    plot = output_path("--plot", plot, FIGURE_SUFFIXES, overwrite)
    cfg = load_config(config)
    status.phase("the reduction basis")
    basis = config_basis(cfg, cfg.problem())
    status.phase("the reduced sweep")
    tracked = reduced_sweep(basis, values, band=cfg.band)
    _keep(tracked.to_xarray(), out, plot, "plot_stability_map")
    _emit({"swept_key": key, "sweep_points": len(values), "branches": len(tracked.s), "critical": _critical(tracked),
           "reduced_modes": basis.modes, "static_vectors": basis.augmented, "basis_top_hz": basis.top}, json,
          "reduced CEA sweep")


@app.command("mesh")
def mesh(step: Annotated[Path, typer.Argument(help="The STEP file (its solids; any length unit its header states).")],
         out: Annotated[Path, typer.Argument(help="The gmsh mesh to write (.msh), in metres: a config's mesh with "
                                                  "units = \"m\".")],
         size: Annotated[float, declared(Q["mesh_size"], "--size")],
         order: Annotated[int, declared(Q["element_order"], "--order")] = 1,
         solid: Annotated[Optional[list[str]], typer.Option("--solid", help=(
             "Mesh only this solid of the STEP (its label, or solid1, solid2, ... by its place in the file); "
             "repeatable: the solids given are fused where they touch (a lining on its backplate)."))] = None,
         face: Annotated[Optional[list[str]], typer.Option("--face", help=(
             "A face group NAME=AXIS:VALUE: the boundary surfaces in the plane x, y or z = VALUE [m], or on the "
             "cylinder r = VALUE [m] about z (a disc's bore); repeatable."))] = None,
         overwrite: Replace = False, json: Json = False):
    """Mesh a STEP file's solids (gmsh's OpenCASCADE kernel) into a mesh for a config of solids: each
    solid a cell group, each --face a face group."""
    from ..fem.cad import CYLINDER, PLANES, mesh_step
    from ..fem.solid import read_solid

    out = output_path("OUT", out, ".msh", overwrite)
    if out is None:
        raise ParameterError("OUT", "", "a .msh file to write")
    faces = {}
    for text in face or ():
        name, _, where = text.partition("=")
        axis, _, value = where.partition(":")
        try:
            number = float(value)
        except ValueError:
            number = None
        if not name or axis not in PLANES + (CYLINDER,) or number is None or not math.isfinite(number):
            raise ParameterError("--face", text, "NAME=AXIS:VALUE with AXIS x, y, z (a plane) or r (a cylinder about "
                                 "z) and VALUE in metres, e.g. friction=z:0.012 or bore=r:0.06")
        if name in faces:
            raise ParameterError("--face", text, f"each group once ({name!r} is given twice)")
        faces[name] = (axis, number)
    status.phase("meshing")
    partial = out.with_name(out.name + ".partial.msh")  # written whole or not at all
    try:
        mesh_step(step, partial, size, faces=faces, order=order, solids=list(solid) if solid else None)
        made = read_solid(partial, "m")
        partial.replace(out)
    finally:
        partial.unlink(missing_ok=True)
    extent = made.points.max(axis=0) - made.points.min(axis=0)
    _emit({"mesh": str(out), "nodes": len(made.points), "cells": len(made.cells), "cell_kind": made.kind,
           "dofs": 3 * len(made.points), "face_groups": sorted(made.faces), "cell_groups": sorted(made.cell_groups),
           "extent": [float(x) for x in extent]}, json, "mesh of a STEP file")


@app.command("map")
def map_(config: Config,
         over: Annotated[str, typer.Option("--over", help=(
             "The map's other axis, KEY=LO:HI:N (or :log): a number of the config besides the friction, e.g. "
             "pressure=2e5:2e6:6, partner.omega=5:50:10, material[0].e3=1e9:5e9:5."))],
         friction: Annotated[str, typer.Option("--friction", help=(
             "The frictions of each row, LO:HI:N (e.g. 0:0.8:41)."))],
         store: Annotated[Path, typer.Option(help=(
             "The map's checkpoint, a Zarr store (.zarr): each row kept as it finishes, resumed if it holds this "
             "map, refused if it holds another."))],
         out: Annotated[Optional[Path], typer.Option(help=(
             "Write the map to this netCDF file (.nc): largest growth rate [1/s], its frequency [Hz] and the "
             "number of growing modes on (value, friction); the onset friction of each value."))] = None,
         plot: Annotated[Optional[Path], typer.Option(help=(
             "Write the map's picture (the largest growth rate over both axes, the onset friction drawn) to this "
             "file: PNG, SVG or PDF by its suffix."))] = None,
         workers: Annotated[Optional[int], declared(COMMON["workers"], "--workers", "Default: all cores.")] = None,
         scheduler: Scheduler = None, overwrite: Replace = False, json: Json = False):
    """A stability map over the friction and one more number of the config: the CEA (with [cea]
    reduced_modes, the reduced one and its tracked friction sweep) at every point, the onset
    friction of each value."""
    import numpy as np

    from ..fem.config import load_config, read_toml, resolve_key
    from ..fem.maps import stability_map
    from .common import axis, output_folder

    overwrite_needs(overwrite, "--out, --store or --plot", out, store, plot)
    out = output_path("--out", out, ".nc", overwrite)
    plot = output_path("--plot", plot, FIGURE_SUFFIXES, overwrite)
    store = output_folder("--store", store, ".zarr")
    name, values = axis("--over", over, increasing=True)
    _, frictions = axis("--friction", f"friction={friction}", increasing=True)
    key = resolve_key(read_toml(config), name, "--over")
    if key == "contact.friction":
        raise ParameterError("--over", over, "a number of the config other than contact.friction (--friction gives "
                             "the friction axis)")
    try:  # every corner a valid config, checked before any work
        for v in (values[0], values[-1]):
            for f in (frictions[0], frictions[-1]):
                load_config(config, {key: v, "contact.friction": f})
    except ParameterError as err:
        raise ParameterError("--over", over, f"values each valid in the config with the frictions of --friction: "
                             f"{err.allowed}") from None
    with progress_bar("stability map") as tick:
        ds = stability_map(config, key, values, frictions, store, workers=workers, progress=tick, overwrite=overwrite,
                           scheduler=scheduler or "processes")
    _keep(ds, out, plot, "plot_friction_map")
    onsets = [{"value": float(v), "onset": float(o), "onset_frequency": float(f)}
              for v, o, f in zip(ds["value"].values, ds["onset"].values, ds["onset_frequency"].values)
              if math.isfinite(o)]
    _emit({"swept_key": key, "values": len(values), "frictions": len(frictions), "onsets": onsets,
           "stable_values": int(np.sum(~np.isfinite(ds["onset"].values))), "store": str(store)}, json,
          "stability map")


@app.command()
def run(config: Config,
        transits: Annotated[float, declared(Q["transits"], "--transits")] = 20.0,
        beta2: Annotated[float, declared(COMMON["beta2"], "--beta2")] = 0.9,
        time_step: Annotated[Optional[float], declared(Q["time_step"], "--time-step", "Default 0.9 of the stable "
                                                       "step.")] = None,
        start: StartOpt = Start.steady,
        amplitude: Annotated[Optional[float], declared(COMMON["amplitude"], "--amplitude", (
            "With --start steady: the RMS of a tangential noise, relative to the steady displacement (default "
            "1e-3)."))] = None,
        out: RunOut = None,
        xdmf: Annotated[Optional[Path], typer.Option(help=(
            "Write volume snapshots for ParaView to this XDMF file (.xdmf, data in the .h5 beside it): "
            "displacement [m], velocity [m/s], contact forces [N/m; N between solids] and states, cell stresses [Pa]; times [s]."))] = None,
        xdmf_every: XdmfEvery = None,
        window: Annotated[Optional[float], declared(Q["window_transits"], "--window", (
            "Classify the limit regime over the last this many transits, at most --transits (default the run's "
            "dense tail, 2 transits: the wave scale). A stick-slip cycle is often much longer: give a window of "
            "several cycles."))] = None,
        overwrite: Overwrite = False, json: Json = False, set_: Set = None):
    """Explicit dynamics from perturbed steady sliding (or the preload, --start), then the limit
    regime on the contact nodes."""
    from ..fem.paraview import write_run_xdmf
    from ..fem.run import integrate_body, perturbed_steady_body, preload_body
    from ..fem.scheme import BodyScheme
    from ..fem.surfaces import RigidFlat

    overwrite_needs(overwrite, "--out or --xdmf", out, xdmf)
    out = output_path("--out", out, ".nc")
    xdmf, volume_every = xdmf_snapshots(xdmf, xdmf_every, overwrite)
    if amplitude is not None and start is not Start.steady:
        raise ParameterError("--amplitude", amplitude, f"not given with --start {start.value} (it sets the noise "
                             "of --start steady)")
    amplitude = 1e-3 if amplitude is None else amplitude
    if window is not None and not (math.isfinite(window) and 0.0 < window <= transits):
        raise ParameterError("--window", window, f"in (0, {transits:g}] transits (at most --transits)",
                             also=("--transits",))
    if window is not None and window < 2.0 / DENSEST:  # no run can hold 3 snapshots in it: said before the run
        raise ParameterError("--window", window, f">= {2.0 / DENSEST:g} transits (3 snapshots at the densest "
                             f"sampling of a run, {DENSEST} a transit)")
    status.phase("reading the config and the mesh")
    cfg = _problem(config, set_)
    if cfg.partner is not None:
        return _run_pair(cfg, transits, beta2, time_step, start, amplitude, out, xdmf, volume_every, window, overwrite,
                         json)
    if start is Start.stick and not isinstance(cfg.surface, RigidFlat):
        raise ParameterError("--start", start.value, "steady or rest with a rotating cylinder (stick moves the "
                             "whole body with a flat surface)")
    status.phase("assembling")
    problem = cfg.problem()
    scheme = BodyScheme(problem, beta2, time_step=time_step)
    status.phase("steady sliding and the stable step" if start is Start.steady else "the preload and the stable step")
    if start is Start.steady:
        initial = perturbed_steady_body(scheme, amplitude)
    else:
        initial = preload_body(scheme, cfg.surface.velocity if start is Start.stick else (0.0, 0.0))
    status.phase("integrating")
    with progress_bar("transits") as tick:
        result = integrate_body(problem, transits=transits, beta2=beta2, time_step=time_step, initial=initial,
                                checkpoint=out, progress=_in_transits(tick, transits), overwrite=overwrite,
                                volume_every=volume_every)
    if xdmf is not None:
        status.phase("writing the ParaView files")
        write_run_xdmf(result, xdmf)
    _limit_regime(result, window, json)


def _run_pair(cfg, transits, beta2, time_step, start, amplitude, out, xdmf, volume_every, window, overwrite, json):
    """`run` of a pad on a [partner]: from perturbed steady sliding only."""
    from ..fem.paraview import write_run_xdmf
    from ..fem.pair_run import SOLVERS, integrate_pair

    if start is not Start.steady:
        raise ParameterError("--start", start.value, "steady with a [partner] (a run of two bodies starts from their "
                             "steady sliding)")
    status.phase("assembling")
    problem = cfg.problem()
    try:  # the step, the damping and the supports refused before the run, by the config's names
        SOLVERS[problem.dimension][0](problem, beta2, time_step=time_step)
    except ParameterError as err:
        keys = {"rollers_slave": "rollers", "rollers_master": "partner.rollers"}
        if err.name not in keys:
            raise
        raise ParameterError(keys[err.name], err.value, err.allowed) from None
    status.phase("integrating (steady sliding of both bodies first)")
    with progress_bar("transits") as tick:
        result = integrate_pair(problem, transits=transits, amplitude=amplitude, beta2=beta2, time_step=time_step,
                                checkpoint=out, progress=_in_transits(tick, transits), overwrite=overwrite,
                                volume_every=volume_every)
    if xdmf is not None:
        status.phase("writing the ParaView files")
        write_run_xdmf(result, xdmf)
    _limit_regime(result, window, json)


def _in_transits(tick, transits: float):
    """A run's ``progress(t, t_end)`` (seconds of its time) as transits done of ``transits``."""
    return lambda t, t_end: tick(transits * t / t_end if t_end > 0 else transits, transits)


def _limit_regime(result, window, json) -> None:
    """Classify a run's limit regime over ``--window`` and print it."""
    from ..fem.run import classify_body

    status.phase("classifying the limit regime")
    try:
        regime = classify_body(result, window)
    except ParameterError as err:
        if window is None or err.name != "transits":
            raise
        raise ParameterError("--window", window, err.allowed) from None
    warn_short_window(result, regime)
    _emit(regime.to_dict(), json, "limit regime")


#: The largest difference of a state's node-time fraction between the classification window and
#: the last half of the run before the window is said to miss a longer cycle.
WINDOW_MISMATCH = 0.1


def warn_short_window(run, regime) -> None:
    """Warn on stderr when the window's state fractions differ from those of the run's last half
    (the window sees one phase of a longer cycle, such as the stick of a stick-slip cycle)."""
    half = run.t >= 0.5 * run.t_end
    if regime.window[0] <= run.t_end * 0.5 or not half.any():
        return
    whole = dict(zip(regime.fractions, run.series["fractions"][half].mean(axis=0)))
    worst = max(regime.fractions, key=lambda k: abs(regime.fractions[k] - whole[k]))
    if abs(regime.fractions[worst] - whole[worst]) > WINDOW_MISMATCH:
        print(f"warning: the classification window ({(regime.window[1] - regime.window[0]):.3g} s) differs from the "
              f"run's last half ({worst} {regime.fractions[worst]:.3g} vs {whole[worst]:.3g}): it sees part of a "
              "longer cycle; widen --window", file=sys.stderr)
