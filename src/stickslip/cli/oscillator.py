"""`stickslip oscillator ...`: the one-degree-of-freedom friction oscillator (paper section 2)."""

from __future__ import annotations

import functools


from enum import Enum
from pathlib import Path
from typing import Annotated, Optional

import typer

from ..quantities import COMMON, OSCILLATOR as Q, lookup
from .helptext import Typer
from .common import (FIGURE_HELP, FIGURE_SUFFIXES, AXIS_HELP, Overwrite, Replace, Scheduler, axis, declared, map_size, emit, output_folder, output_path, overwrite_needs,
                     progress_bar, write_netcdf)

_emit = functools.partial(emit, model="oscillator")  # results are printed with the units of this model

app = Typer(no_args_is_help=True, rich_markup_mode=None, help="The 1-DOF friction oscillator m x'' + c x' + k x = F (paper section 2).")


class Law(str, Enum):
    coulomb = "coulomb"
    linear_weakening = "linear-weakening"
    stribeck = "stribeck"


Mass = Annotated[float, declared(Q["mass"], "--mass")]
Stiffness = Annotated[float, declared(Q["stiffness"], "--stiffness")]
Normal = Annotated[float, declared(Q["normal_force"], "--normal-force")]
Belt = Annotated[float, declared(Q["belt_speed"], "--belt-speed")]
Fs = Annotated[float, declared(Q["fs"], "--fs", "At least --fd.")]
Fd = Annotated[float, declared(Q["fd"], "--fd")]
LawOpt = Annotated[Law, typer.Option("--law", help="Friction law.")]
Tau = Annotated[Optional[float], declared(Q["tau"], "--tau", "With --law linear-weakening.")]
Vs = Annotated[Optional[float], declared(Q["vs"], "--vs", "With --law stribeck.")]
Damping = Annotated[float, declared(Q["damping"], "--damping", "With a damping ratio c/(2 sqrt(k m)) <= 1e11.")]
Json = Annotated[bool, typer.Option("--json", help="Print one JSON object on stdout.")]
Out = Annotated[Optional[Path], typer.Option("--out", help="Write the data to this netCDF file (.nc).")]
Plot = Annotated[Optional[Path], typer.Option("--plot", help=FIGURE_HELP)]


def Given(option):
    """The option of ``Annotated[float, option]`` made optional (None when left out)."""
    info = option.__metadata__[0]
    given = typer.Option(None, *info.param_decls, help=info.help, callback=info.callback)
    given.quantity = info.quantity
    return given


def _osc(mass, stiffness, normal_force, belt_speed, fs, fd, law, tau, vs, damping):
    from ..friction import make_law  # the models are imported by the commands that use them (`--help` stays quick)
    from ..oscillator import Oscillator

    # a value given for nothing is a mistake, not something to ignore: make_law refuses it
    friction = make_law(law.value, fs=fs, fd=fd, tau=tau, vs=vs)
    return Oscillator(mass, stiffness, normal_force, belt_speed, friction, damping)


def _outputs(out, plot, overwrite):
    """``--out`` and ``--plot`` checked before any work (an existing one only with ``--overwrite``)."""
    overwrite_needs(overwrite, "--out or --plot", out, plot)
    return output_path("--out", out, ".nc", overwrite), output_path("--plot", plot, FIGURE_SUFFIXES, overwrite)


def _write(ds, out, plot, draw: str) -> None:
    """Write ``ds`` to ``out`` and its plot ``stickslip.plotting.<draw>`` to ``plot`` (either may be None)."""
    if out is not None:
        write_netcdf(ds, out)
    if plot is not None:
        from .. import plotting

        plotting.save(getattr(plotting, draw)(ds), plot)


@app.command()
def cycle(mass: Mass, stiffness: Stiffness, normal_force: Normal, belt_speed: Belt, fs: Fs, fd: Fd,
          law: LawOpt = Law.coulomb, tau: Tau = None, vs: Vs = None, damping: Damping = 0.0,
          x0: Annotated[Optional[float], declared(Q["x0"], "--x0", "Default: the end of the stick segment.")] = None,
          v0: Annotated[Optional[float], declared(Q["v0"], "--v0", "Default: the belt speed.")] = None,
          json: Json = False, out: Out = None, plot: Plot = None, overwrite: Replace = False):
    """Limit cycle: period, stick and slip times, amplitude, Floquet multipliers."""
    out, plot = _outputs(out, plot, overwrite)
    from ..oscillator import limit_cycle

    result = limit_cycle(_osc(mass, stiffness, normal_force, belt_speed, fs, fd, law, tau, vs, damping), x0, v0)
    _emit(result.to_dict(), json, "limit cycle")

    _write(result.to_xarray() if (out or plot) else None, out, plot, "plot_cycle")


@app.command("simulate")
def simulate_cmd(mass: Mass, stiffness: Stiffness, normal_force: Normal, belt_speed: Belt, fs: Fs, fd: Fd,
                 t_end: Annotated[float, declared(Q["t_end"], "--t-end")],
                 law: LawOpt = Law.coulomb, tau: Tau = None, vs: Vs = None, damping: Damping = 0.0,
                 x0: Annotated[Optional[float], declared(Q["x0"], "--x0", "Default: steady sliding.")] = None,
                 v0: Annotated[float, declared(Q["v0"], "--v0")] = 0.0,
                 samples: Annotated[int, declared(Q["samples"], "--samples")] = 2001,
                 json: Json = False, out: Out = None, plot: Plot = None, overwrite: Replace = False):
    """Event-driven simulation with exact stick/slip switching."""
    out, plot = _outputs(out, plot, overwrite)
    from ..oscillator import simulate

    traj = simulate(_osc(mass, stiffness, normal_force, belt_speed, fs, fd, law, tau, vs, damping), t_end, x0, v0)
    counts = {name: int((traj.modes == m).sum()) for name, m in (("stick_segments", 0), ("slip_segments", 1),
                                                                  ("reverse_slip_segments", -1))}
    _emit({"status": traj.status, "message": traj.message, "t_end": traj.t_end, "x_end": float(traj.x[-1]),
          "v_end": float(traj.v[-1]), "switches": len(traj.events), **counts}, json, "simulation")

    _write(traj.to_xarray(samples) if (out or plot) else None, out, plot, "plot_trajectory")


@app.command()
def stability(mass: Mass, stiffness: Stiffness, normal_force: Normal, belt_speed: Belt, fs: Fs, fd: Fd,
              law: LawOpt = Law.coulomb, tau: Tau = None, vs: Vs = None, damping: Damping = 0.0,
              parameter: Annotated[str, typer.Option(help="Parameter scanned for Hopf points.")] = "belt_speed",
              lo: Annotated[Optional[float], declared(Q["lo"], "--lo", "Default: the value / 100.")] = None,
              hi: Annotated[Optional[float], declared(Q["hi"], "--hi", "Default: the value x 100.")] = None,
              json: Json = False):
    """Stability of steady sliding and its Hopf (flutter) points."""
    osc = _osc(mass, stiffness, normal_force, belt_speed, fs, fd, law, tau, vs, damping)
    value = osc.parameter(parameter)
    span = Q[parameter].range  # the defaults stay where the parameter is declared
    lo = max(value / 100, span.lo) if lo is None else lo
    hi = min(value * 100, span.hi) if hi is None else hi
    if lo == hi:  # a parameter at zero (damping 0): scanned over its declared range
        lo, hi = span.lo, min(span.hi, 1.0)
    from ..oscillator import equilibrium_stability, hopf_points

    data = equilibrium_stability(osc).to_dict()
    data["hopf_points"] = [h.to_dict() for h in hopf_points(osc, parameter, lo, hi)]
    _emit(data, json, "steady sliding", meanings={"stable": lookup("equilibrium_stable", "oscillator"),
                                                  "kind": lookup("equilibrium_kind", "oscillator")})


@app.command("continue")
def continue_cmd(mass: Mass, stiffness: Stiffness, normal_force: Normal, belt_speed: Belt, fs: Fs, fd: Fd,
                 stop: Annotated[float, declared(Q["stop"], "--stop")],
                 law: LawOpt = Law.coulomb, tau: Tau = None, vs: Vs = None, damping: Damping = 0.0,
                 parameter: Annotated[str, typer.Option(help="Continuation parameter.")] = "belt_speed",
                 from_hopf: Annotated[bool, typer.Option(help="Start from the nearest Hopf point instead.")] = False,
                 step: Annotated[float, declared(Q["initial_step"], "--step")] = 0.02,
                 max_step: Annotated[float, declared(Q["max_step"], "--max-step")] = 0.05,
                 json: Json = False, out: Out = None, plot: Plot = None, overwrite: Replace = False):
    """Continuation of the limit cycle in a parameter (amplitude, period, grazing, Hopf)."""
    out, plot = _outputs(out, plot, overwrite)
    from ..oscillator import continue_cycle, continue_from_hopf, hopf_points

    osc = _osc(mass, stiffness, normal_force, belt_speed, fs, fd, law, tau, vs, damping)
    if from_hopf:
        start = osc.parameter(parameter)
        points = hopf_points(osc, parameter, min(start, stop), max(start, stop))
        if not points:
            from ..errors import NoSolutionError

            raise NoSolutionError(f"no Hopf point for {parameter} between {start:g} and {stop:g}")
        branch = continue_from_hopf(osc, points[0], stop, step=step, max_step=max_step)
    else:
        branch = continue_cycle(osc, stop, parameter=parameter, step=step, max_step=max_step)
    data = branch.to_dict()
    if not json:
        data = {"parameter": data["parameter"], "points": len(data["points"]), "end_reason": data["end_reason"],
                "events": data["events"]}
    _emit(data, json, "continuation")

    _write(branch.to_xarray() if (out or plot) else None, out, plot, "plot_branch")


@app.command("map")
def map_cmd(out: Annotated[Path, typer.Option(help="Zarr store (a directory ending in .zarr); resumed if it exists.")],
            mass: Optional[float] = Given(Mass), stiffness: Optional[float] = Given(Stiffness),
            normal_force: Optional[float] = Given(Normal), belt_speed: Optional[float] = Given(Belt),
            fs: Optional[float] = Given(Fs), fd: Optional[float] = Given(Fd),
            x: Annotated[str, typer.Option("--x", help=f"First axis, a parameter's {AXIS_HELP}.")] =
            "belt_speed=0.05:1.5:30",
            y: Annotated[str, typer.Option("--y", help=f"Second axis, {AXIS_HELP}.")] = "damping=0.01:0.3:20",
            law: LawOpt = Law.coulomb, tau: Tau = None, vs: Vs = None, damping: Optional[float] = Given(Damping),
            workers: Annotated[Optional[int], declared(COMMON["workers"], "--workers", "Default: all cores.")] = None,
            scheduler: Scheduler = None, overwrite: Overwrite = False, json: Json = False, plot: Plot = None):
    """Regime map over two parameters (steady sliding, stick-slip, bistable, pure slip): resumable, parallel."""
    from ..errors import MISSING, ParameterError
    from ..oscillator.regimes import REGIMES, regime_map

    out = output_folder("--out", out, ".zarr")
    plot = output_path("--plot", plot, FIGURE_SUFFIXES, overwrite)
    pair = [axis(option, text) for option, text in (("--x", x), ("--y", y))]
    if pair[0][0] == pair[1][0]:
        raise ParameterError("--y", y, f"an axis of another parameter than --x (both are {pair[0][0]}: a map needs two)")
    map_size("--y", y, *(len(values) for _, values in pair))
    named = dict(pair)
    base = {"mass": mass, "stiffness": stiffness, "normal_force": normal_force, "belt_speed": belt_speed, "fs": fs,
            "fd": fd, "damping": damping, "tau": tau, "vs": vs}
    for name, value in base.items():  # a swept parameter takes its values from the axis, not from its option
        option = "--" + name.replace("_", "-")
        if name in named and value is not None:
            raise ParameterError(option, value, f"left out: {name} is an axis of the map")
        if name in named:
            base[name] = named[name][0]
        elif value is None and name not in ("tau", "vs", "damping"):
            raise ParameterError(option, MISSING, f"given (or made an axis with --x/--y {name}=lo:hi:n)")
    base["damping"] = 0.0 if base["damping"] is None else base["damping"]
    try:
        osc = _osc(*(base[k] for k in ("mass", "stiffness", "normal_force", "belt_speed", "fs", "fd")), law,
                   base["tau"], base["vs"], base["damping"])
    except ParameterError as exc:  # an axis' first value out of range: the axis is named
        option, text = next(((o, t) for o, t in (("--x", x), ("--y", y)) if t.split("=")[0].strip() == exc.name),
                            (None, None))
        if option is None:
            raise
        raise ParameterError(option, text, f"an axis of {exc.name} with every value {exc.allowed}",
                             also=exc.also) from None
    axes = {}
    for option, text in (("--x", x), ("--y", y)):
        name, values = axis(option, text)
        try:  # every point of the map is a valid oscillator, checked here rather than in a worker
            for value in values:
                osc.with_parameter(name, value)
        except ParameterError as exc:
            raise ParameterError(option, text, f"an axis of {exc.name} with every value {exc.allowed}"
                                 if exc.name != "parameter" else exc.allowed, also=exc.also) from None
        axes[name] = values
    with progress_bar("regime map") as tick:
        ds = regime_map(osc, axes, out, workers=workers, progress=tick, overwrite=overwrite,
                        scheduler=scheduler or "processes")
    counts = {REGIMES[k]: int((ds["regime"] == k).sum()) for k in REGIMES}
    _emit({"store": str(out), "axes": {k: [min(v), max(v), len(v)] for k, v in axes.items()}, "counts": counts},
         json, "regime map")
    if plot:
        from .. import plotting

        plotting.save(plotting.plot_oscillator_map(ds, REGIMES), plot)
