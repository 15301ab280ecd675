"""`stickslip system ...`: linear structures with several frictional contacts, from a TOML file."""

from __future__ import annotations

import contextlib
import functools
from pathlib import Path
from typing import Annotated, Optional

import typer

from ..errors import NoSolutionError, ParameterError
from ..quantities import COMMON, SYSTEM as Q
from .helptext import Typer
from .common import Replace, declared, emit, output_path, overwrite_needs, progress_bar, write_netcdf

_emit = functools.partial(emit, model="system")

app = Typer(no_args_is_help=True, rich_markup_mode=None,
                  help="Structures M x'' + C x' + K x = f(t) + sum of contact forces, with several frictional "
                       "contacts and harmonic forces (a TOML file; its keys, with an example: python -m pydoc "
                       "stickslip.system.config).")

File = Annotated[Path, typer.Argument(help="The system: a TOML file of mass, stiffness, [damping, force], one "
                                           "[[contact]] table per contact and one [[harmonic]] per harmonic force "
                                           "(an example: python -m pydoc stickslip.system.config).",
                                      show_default=False)]
Periods = Annotated[int, declared(Q["periods"], "--periods", "With a periodic force: the forcing periods over "
                                                             "which the response repeats (more than 1: a "
                                                             "subharmonic).")]
Json = Annotated[bool, typer.Option("--json", help="Print one JSON object on stdout.")]
Out = Annotated[Optional[Path], typer.Option("--out", help="Write the data to this netCDF file (.nc).")]
X0 = Annotated[Optional[str], typer.Option("--x0", help=f"Initial displacement: one number per degree of freedom, "
                                                        f"separated by commas ({Q['x0'].units}). Default: zeros.")]
V0 = Annotated[Optional[str], typer.Option("--v0", help=f"Initial velocity: one number per degree of freedom, "
                                                        f"separated by commas ({Q['v0'].units}). Default: zeros.")]


Psi0 = Annotated[Optional[str], typer.Option(
    "--psi0", help="Rate-and-state contacts: their state variables ln(V_0 theta / D_c) at the start, separated by "
                   "commas, in the order of the contacts (two for a law with two). Default: steady at the start's "
                   "slip rates (cycle: steady sliding with the first raised by 0.01).")]


def _load(path: Path):
    from ..system import load_system

    return load_system(path)


@contextlib.contextmanager
def _file_keys():
    """A problem found after the file was read (steady sliding of a contact on a surface at rest)
    names its key as the file writes it."""
    from ..system.config import as_file_keys

    try:
        yield
    except ParameterError as err:
        raise as_file_keys(err) from None


def _numbers(option: str, text: str | None, n: int):
    """``--x0 "0.1, 0.2"``: ``n`` numbers (None if not given); each is checked by the library."""
    if text is None:
        return None
    try:
        values = [float(part) for part in text.split(",")]
    except ValueError:
        values = None
    if values is None or len(values) != n:
        raise ParameterError(option, text, f"{n} numbers separated by commas (one per degree of freedom)")
    return values


def _psi(text: str | None, system):
    """``--psi0 "0.1, 0.2"``: the rate-and-state contacts' state variables in order, grouped per contact."""
    if text is None:
        return None
    counts = [c.friction.states for c in system.contacts if hasattr(c.friction, "states")]
    try:
        values = [float(part) for part in text.split(",")]
    except ValueError:
        values = None
    if values is None or len(values) != sum(counts):
        raise ParameterError("--psi0", text, f"{sum(counts)} numbers separated by commas (the rate-and-state "
                             "contacts' state variables, in order)")
    rows, at = [], 0
    for k in counts:
        rows.append(values[at:at + k])
        at += k
    return rows


def _out(out: Path | None, overwrite: bool) -> Path | None:
    overwrite_needs(overwrite, "--out", out)
    return output_path("--out", out, ".nc", overwrite)


@app.command("simulate")
def simulate_cmd(file: File, t_end: Annotated[float, declared(Q["t_end"], "--t-end")],
                 x0: X0 = None, v0: V0 = None,
                 samples: Annotated[int, declared(Q["samples"], "--samples")] = 1001,
                 max_events: Annotated[int, declared(Q["max_events"], "--max-events")] = 1_000_000,
                 psi0: Annotated[Optional[str], typer.Option(
                     "--psi0", help="Rate-and-state contacts: their state variables ln(V_0 theta / D_c) at the start, "
                                    "separated by commas, in the order of the contacts (two for a law with two). "
                                    "Default: steady at the start's slip rates.")] = None,
                 json: Json = False, out: Out = None, overwrite: Replace = False):
    """Event-driven simulation with exact stick/slip switching at every contact (with rate-and-state
    laws: their smooth motion, Radau IIA; the start at steady sliding's position unless --x0)."""
    out = _out(out, overwrite)
    from ..system import integrated, is_rate_state, rate_state_simulate, simulate

    system = _load(file)
    n = system.dofs
    with _file_keys():
        if psi0 is not None and not is_rate_state(system):
            raise ParameterError("--psi0", psi0, "left out: it is the state of rate-and-state contacts, and this "
                                 "system has none")
        if integrated(system):
            run = rate_state_simulate(system, _numbers("--x0", x0, n), _numbers("--v0", v0, n), t_end,
                                      psi0=_psi(psi0, system), samples=samples)
        else:
            run = simulate(system, _numbers("--x0", x0, n), _numbers("--v0", v0, n), t_end, samples=samples,
                           max_events=max_events)
    _emit(run.to_dict(), json, "simulation")
    if out is not None:
        write_netcdf(run.to_xarray(), out)


@app.command()
def cycle(file: File, x0: X0 = None, v0: V0 = None,
          transient: Annotated[Optional[float], declared(Q["transient"], "--transient", "Default: 100 s (with "
                                                          "rate-and-state contacts: see below).")] = None,
          tol: Annotated[Optional[float], declared(COMMON["tol"], "--tol", "Default: 1e-10 (with rate-and-state "
                                                                         "contacts 1e-7).")] = None,
          max_iter: Annotated[int, declared(Q["max_iter"], "--max-iter")] = 200,
          periods: Periods = 1,
          psi0: Psi0 = None,
          json: Json = False, out: Out = None, overwrite: Replace = False):
    """Limit cycle the motion settles on: period, events, Floquet multipliers (with saltation matrices).
    With harmonic forces: the periodic response (at phase zero of the force), its amplitude and multipliers.
    With rate-and-state contacts: the cycle by Newton's method on the smooth equations (multipliers by
    central differences); --transient then defaults to the growth of a small perturbation."""
    out = _out(out, overwrite)
    from ..system import forced_response, integrated, is_rate_state, limit_cycle, rate_state_cycle

    system = _load(file)
    n = system.dofs
    with _file_keys():
        x0, v0 = _numbers("--x0", x0, n), _numbers("--v0", v0, n)
        rate_state = integrated(system)
        if psi0 is not None and not is_rate_state(system):
            raise ParameterError("--psi0", psi0, "left out: it is the state of rate-and-state contacts, and this "
                                 "system has none")
        if periods != 1 and not system.harmonics:
            raise ParameterError("--periods", periods, "1 (left out): it counts forcing periods, and this system "
                                 "has no [[harmonic]] force")
        if rate_state:
            result = rate_state_cycle(system, x0, v0, psi0=_psi(psi0, system), transient=transient,
                                      tol=1e-7 if tol is None else tol, max_iter=max_iter)
        else:
            common = {"transient": 100.0 if transient is None else transient, "tol": 1e-10 if tol is None else tol,
                      "max_iter": max_iter}
            try:
                result = (forced_response(system, x0, v0, periods=periods, **common) if system.harmonics
                          else limit_cycle(system, x0, v0, **common))
            except NoSolutionError as err:  # the library's advice, in the option's name
                raise NoSolutionError(str(err).replace("a longer transient", "a longer --transient")) from None
    _emit(result.to_dict(), json, "periodic response" if system.harmonics else "limit cycle")
    if out is not None:
        write_netcdf(result.to_xarray(), out)


@app.command()
def stability(file: File, json: Json = False, out: Out = None, overwrite: Replace = False):
    """Steady sliding (every contact slipping, the structure at rest) and its linear stability (with
    rate-and-state laws, in the displacements, velocities and the contacts' state variables)."""
    out = _out(out, overwrite)
    from ..system import is_rate_state, rate_state_steady, steady_sliding

    system = _load(file)
    with _file_keys():
        result = rate_state_steady(system) if is_rate_state(system) else steady_sliding(system)
    _emit(result.to_dict(), json, "steady sliding")
    if out is not None:
        write_netcdf(result.to_xarray(), out)


@app.command("continue")
def continue_cmd(file: File,
                 parameter: Annotated[str, typer.Option(help="The number of the file to vary, as the file names it: "
                                                             "contact[0].surface_speed (normal_force, fs, fd, tau, "
                                                             "normal_stiffness), stiffness[0][1] (mass, damping), "
                                                             "force[1], harmonic[0].frequency, harmonic[0].cos[1] "
                                                             "(sin), harmonic.frequency (every harmonic's frequency "
                                                             "scaled together).", show_default=False)],
                 stop: Annotated[float, declared(Q["parameter_value"], "--stop", "The value the branch heads for.")],
                 points: Annotated[int, declared(Q["points"], "--points")] = 41,
                 x0: X0 = None, v0: V0 = None,
                 transient: Annotated[Optional[float], declared(
                     Q["transient"], "--transient", "Default: 100 s (with rate-and-state contacts: as for cycle).")
                 ] = None,
                 tol: Annotated[Optional[float], declared(COMMON["tol"], "--tol", "Default: 1e-10 (with "
                                                                      "rate-and-state contacts 1e-7).")] = None,
                 periods: Periods = 1,
                 psi0: Psi0 = None,
                 json: Json = False, out: Out = None, overwrite: Replace = False):
    """The limit cycle followed along one number of the file, with the values where its events change
    (a stick phase born or gone: grazing), where it is lost, and where its stability changes. With
    harmonic forces: the periodic response (harmonic[0].frequency: a frequency response curve;
    harmonic.frequency: engine orders, every harmonic scaled with the lowest). With rate-and-state
    contacts: the smooth cycles, from the one the motion settles on, to a Hopf point or a fold."""
    out = _out(out, overwrite)
    from ..system import continue_system, file_parameter, is_rate_state
    from ..system.config import read_table

    build, start = file_parameter(read_table(file), parameter)
    first = build(start)
    n = first.dofs
    with _file_keys():
        if psi0 is not None and not is_rate_state(first):
            raise ParameterError("--psi0", psi0, "left out: it is the state of rate-and-state contacts, and this "
                                 "system has none")
        with progress_bar("branch points") as tick:  # without a terminal: the heartbeat's time left
            branch = continue_system(build, start, stop, points=points, x0=_numbers("--x0", x0, n),
                                     v0=_numbers("--v0", v0, n), transient=transient, tol=tol, parameter=parameter,
                                     periods=periods, psi0=_psi(psi0, first), progress=tick)
    _emit(branch.to_dict(), json, "continuation")
    if out is not None:
        write_netcdf(branch.to_xarray(), out)

