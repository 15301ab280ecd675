"""`stickslip halfspace ...`: stick-slip waves between a rigid body and an elastic half-space (paper §4-5)."""

from __future__ import annotations

import functools

from enum import Enum
from pathlib import Path
from typing import Annotated, Optional

import typer

from ..quantities import HALFSPACE as Q
from .helptext import Typer
from .common import FIGURE_HELP, FIGURE_SUFFIXES, Replace, declared, emit, output_path, overwrite_needs, write_netcdf

_emit = functools.partial(emit, model="halfspace")  # results are printed with the units of this model

app = Typer(no_args_is_help=True, rich_markup_mode=None, help="Rigid body sliding on an elastic half-space: periodic stick-slip waves.")


class System(str, Enum):
    printed = "printed"
    text = "text"


B = Annotated[float, declared(Q["b"], "--b")]
C = Annotated[float, declared(Q["c"], "--c")]
VStar = Annotated[float, declared(Q["v_star"], "--v-star")]
Nu = Annotated[float, declared(Q["nu"], "--nu")]
Mu = Annotated[float, declared(Q["mu"], "--mu")]
SystemOpt = Annotated[System, typer.Option("--system", help="[54]-[55] as printed, or [52]-[53] of the text (errata H4).")]
Json = Annotated[bool, typer.Option("--json", help="Print one JSON object on stdout.")]


@app.command()
def inverse(b: B, c: C, v_star: VStar, nu: Nu = 0.3, mu: Mu = 0.5, system: SystemOpt = System.printed,
            json: Json = False):
    """(v, T) from (b, c, v*): the linear system [54]-[55]."""
    from ..halfspace import inverse_problem

    _emit(inverse_problem(b, c, v_star, nu=nu, mu=mu, system=system.value).to_dict(), json, "inverse problem")


@app.command()
def direct(T: Annotated[float, declared(Q["T"], "--T")],
           v: Annotated[float, declared(Q["v"], "--v")],
           v_star: VStar, nu: Nu = 0.3, mu: Mu = 0.5, system: SystemOpt = System.printed, json: Json = False):
    """(c, b) from the loading (T, v, v*): all solutions, or exit code 1 if there is none."""
    from ..halfspace import direct_problem

    _emit(direct_problem(T, v, v_star, nu=nu, mu=mu, system=system.value).to_dict(), json, "direct problem")


@app.command()
def fields(b: B, c: C, v_star: VStar, nu: Nu = 0.3, mu: Mu = 0.5, system: SystemOpt = System.printed,
           decaying: Annotated[bool, typer.Option(help="Use the v that makes the perturbation decay at depth (H6).")] = False,
           points: Annotated[int, declared(Q["points"], "--points")] = 2001,
           json: Json = False,
           out: Annotated[Optional[Path], typer.Option(help="Write the fields to this netCDF file (.nc).")] = None,
           plot: Annotated[Optional[Path], typer.Option(help=FIGURE_HELP)] = None,
           overwrite: Replace = False):
    """Interface fields of the wave: stresses, u_x,x, slip velocity, residuals, singularities."""
    from ..halfspace import decaying_wave, inverse_problem, wave_from_inverse

    overwrite_needs(overwrite, "--out or --plot", out, plot)
    out, plot = output_path("--out", out, ".nc", overwrite), output_path("--plot", plot, FIGURE_SUFFIXES, overwrite)
    if decaying:
        T = float(inverse_problem(b, c, v_star, nu=nu, mu=mu, system=system.value).T)
        wave = decaying_wave(b, c, T, v_star, nu=nu, mu=mu)
    else:
        wave = wave_from_inverse(b, c, v_star, nu=nu, mu=mu, system=system.value)
    _emit(wave.summary(), json, "interface fields")
    if out or plot:
        ds = wave.fields(n=points).to_xarray()
        if out:
            write_netcdf(ds, out)
        if plot:
            from .. import plotting

            plotting.save(plotting.plot_interface_fields(ds), plot)
