"""`stickslip rsf ...`: the spring-slider with rate-and-state friction."""

from __future__ import annotations

import functools
from enum import Enum
from pathlib import Path
from typing import Annotated, Optional

import typer

from ..errors import ParameterError
from ..quantities import COMMON, RSF as Q
from .helptext import Typer
from .common import Replace, declared, emit, output_path, overwrite_needs, write_netcdf

_emit = functools.partial(emit, model="rsf")

app = Typer(no_args_is_help=True, rich_markup_mode=None,
                  help="The spring-slider with rate-and-state friction (per unit area: Pa, Pa/m, kg/m2).")


class Evolution(str, Enum):
    aging = "aging"
    slip = "slip"
    prz = "prz"


def _opt(name: str, note: str = ""):
    return declared(Q[name], "--" + name.replace("_", "-"), note)


A = Annotated[float, _opt("a")]
B = Annotated[float, _opt("b")]
Dc = Annotated[float, _opt("dc")]
F0 = Annotated[float, _opt("f0")]
Vref = Annotated[float, _opt("v_ref")]
Ev = Annotated[Evolution, typer.Option("--evolution", help="Evolution law of the state: aging (Dieterich), slip "
                                                          "(Ruina) or prz (Perrin-Rice-Zheng).")]
B2 = Annotated[float, _opt("b2")]
Dc2 = Annotated[Optional[float], _opt("dc2", "With --b2.")]
Reg = Annotated[bool, typer.Option("--regularized", help="The law regularised near zero slip rate (asinh form).")]
Sigma = Annotated[float, _opt("normal_stress")]
K = Annotated[float, _opt("stiffness")]
Mass = Annotated[float, _opt("mass")]
Vlp = Annotated[float, _opt("load_velocity")]
Json = Annotated[bool, typer.Option("--json", help="Print one JSON object on stdout.")]
Out = Annotated[Optional[Path], typer.Option("--out", help="Write the data to this netCDF file (.nc).")]


def _slider(a, b, dc, f0, v_ref, evolution, b2, dc2, regularized, normal_stress, stiffness, mass):
    from ..rsf import RateState, SpringSlider

    law = RateState(a, b, dc, f0=f0, v_ref=v_ref, evolution=evolution.value, b2=b2, dc2=dc2, regularized=regularized)
    return SpringSlider(law, normal_stress, stiffness, mass)


def _history(text: str | None, load_velocity: float | None):
    """``--history "0:1e-6, 20:1e-5, 60:0"`` (time: load velocity, from time 0) or ``--load-velocity``."""
    if (text is None) == (load_velocity is None):
        raise ParameterError("--history", text, "given, or --load-velocity, but not both")
    if text is None:
        return load_velocity, None
    try:
        pairs = [tuple(float(x) for x in part.split(":")) for part in text.split(",")]
    except ValueError:
        pairs = [()]
    if not pairs or any(len(p) != 2 for p in pairs):
        raise ParameterError("--history", text, "time:velocity pairs separated by commas, from time 0 "
                                                "(s:m/s, e.g. 0:1e-6,20:1e-5,60:0,100:1e-6)")
    velocities, times = [p[1] for p in pairs], [p[0] for p in pairs]
    from ..rsf import load_history

    try:  # a bad time or velocity named as typed: --history (the library names its times and load_velocity)
        load_history(velocities, times)
    except ParameterError as err:
        part = "its times" if err.name == "times" else "its velocities"
        raise ParameterError("--history", text, f"{err.allowed} ({part})") from None
    return velocities, times


@app.command()
def slide(a: A, b: B, dc: Dc, normal_stress: Sigma, stiffness: K,
          t_end: Annotated[float, _opt("t_end")],
          history: Annotated[Optional[str], typer.Option(
              "--history", help="Load-point velocities from given times: time:velocity pairs (s:m/s) separated by "
                                "commas, from time 0 (a velocity step: 0:1e-6,20:1e-5; a hold: a velocity 0).")] = None,
          load_velocity: Annotated[Optional[float], _opt("load_velocity", "Instead of --history.")] = None,
          v_init: Annotated[Optional[float], _opt("v_init", "Default: the first load velocity.")] = None,
          f0: F0 = 0.6, v_ref: Vref = 1e-6, evolution: Ev = Evolution.aging, b2: B2 = 0.0, dc2: Dc2 = None,
          regularized: Reg = False, mass: Mass = 0.0,
          samples: Annotated[int, _opt("samples")] = 1001,
          rtol: Annotated[float, _opt("rtol")] = 1e-10,
          json: Json = False, out: Out = None, overwrite: Replace = False):
    """Response to a load-point velocity history (velocity steps, slide-hold-slide)."""
    overwrite_needs(overwrite, "--out", out)
    out = output_path("--out", out, ".nc", overwrite)
    velocities, times = _history(history, load_velocity)
    from ..rsf import slide as run_slide

    slider = _slider(a, b, dc, f0, v_ref, evolution, b2, dc2, regularized, normal_stress, stiffness, mass)
    run = run_slide(slider, velocities, t_end, times=times, v_init=v_init, samples=samples, rtol=rtol)
    _emit(run.to_dict(), json, "slider run")
    if out is not None:
        write_netcdf(run.to_xarray(), out)


@app.command()
def stability(a: A, b: B, dc: Dc, normal_stress: Sigma, stiffness: K, load_velocity: Vlp,
              f0: F0 = 0.6, v_ref: Vref = 1e-6, evolution: Ev = Evolution.aging, b2: B2 = 0.0, dc2: Dc2 = None,
              regularized: Reg = False, mass: Mass = 0.0, json: Json = False):
    """Stability of steady sliding, the critical stiffness and the Hopf frequency."""
    from ..rsf import linear_stability

    slider = _slider(a, b, dc, f0, v_ref, evolution, b2, dc2, regularized, normal_stress, stiffness, mass)
    _emit(linear_stability(slider, load_velocity).to_dict(), json, "steady sliding")


@app.command()
def cycle(a: A, b: B, dc: Dc, normal_stress: Sigma, stiffness: K, load_velocity: Vlp,
          f0: F0 = 0.6, v_ref: Vref = 1e-6, evolution: Ev = Evolution.aging, b2: B2 = 0.0, dc2: Dc2 = None,
          regularized: Reg = False, mass: Mass = 0.0,
          cycles: Annotated[int, _opt("cycles")] = 5,
          tol: Annotated[float, declared(COMMON["tol"], "--tol")] = 1e-6,
          json: Json = False):
    """The stick-slip cycle beyond the Hopf point (below the critical stiffness): period and extremes."""
    from ..rsf import slider_cycle

    slider = _slider(a, b, dc, f0, v_ref, evolution, b2, dc2, regularized, normal_stress, stiffness, mass)
    _emit(slider_cycle(slider, load_velocity, cycles=cycles, tol=tol).to_dict(), json, "limit cycle")


@app.command()
def fit(record: Annotated[Path, typer.Argument(help="A CSV record with the header columns time [s], friction and "
                                                    "load_velocity [m/s] (a velocity step or slide-hold-slide).")],
        states: Annotated[int, _opt("states")] = 1,
        evolution: Ev = Evolution.aging, json: Json = False):
    """a, b, D_c, the stiffness k / sigma and f0 of a laboratory record, with their standard errors."""
    from ..rsf.fit import fit_record, read_record

    result = fit_record(read_record(record), states=states, evolution=evolution.value)
    _emit(result.to_dict(), json, "rate-and-state fit")
