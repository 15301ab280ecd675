"""`stickslip halfspace ...`: stick-slip waves between a rigid body and an elastic half-space (paper §4-5)."""

from __future__ import annotations

import functools

from enum import Enum
from pathlib import Path
from typing import Annotated, Optional

import typer

from .. import validation as check
from .common import emit, output_path, write_netcdf

_emit = functools.partial(emit, model="halfspace")  # results are printed with the units of this model

app = typer.Typer(no_args_is_help=True, rich_markup_mode=None, help="Rigid body sliding on an elastic half-space: periodic stick-slip waves.")


class System(str, Enum):
    printed = "printed"
    text = "text"


B = Annotated[float, typer.Option("--b", help="Period / stick length b in (1, 1e100] (fields: 1e6).")]
C = Annotated[float, typer.Option("--c", help="Wave speed c/c2 in (-1, 0).")]
VStar = Annotated[float, typer.Option("--v-star", help="v* = V*/c2 in (0, 1] (longitudinal elongation, [26]).")]
Nu = Annotated[float, typer.Option("--nu", help="Poisson's ratio in [0, 0.5).")]
Mu = Annotated[float, typer.Option("--mu", help="Interface friction coefficient mu in (0, 100].")]
SystemOpt = Annotated[System, typer.Option("--system", help="[54]-[55] as printed, or [52]-[53] of the text (errata H4).")]
Json = Annotated[bool, typer.Option("--json", help="Print one JSON object on stdout.")]


@app.command()
def inverse(b: B, c: C, v_star: VStar, nu: Nu = 0.3, mu: Mu = 0.5, system: SystemOpt = System.printed,
            json: Json = False):
    """(v, T) from (b, c, v*): the linear system [54]-[55]."""
    from ..halfspace import inverse_problem

    _emit(inverse_problem(b, c, v_star, nu=nu, mu=mu, system=system.value).to_dict(), json, "inverse problem")


@app.command()
def direct(T: Annotated[float, typer.Option("--T", help="Driving traction T = T*/G > 0.")],
           v: Annotated[float, typer.Option("--v", help="Sliding speed v = V/c2 > 0.")],
           v_star: VStar, nu: Nu = 0.3, mu: Mu = 0.5, system: SystemOpt = System.printed, json: Json = False):
    """(c, b) from the loading (T, v, v*): all solutions, or exit code 1 if there is none."""
    from ..halfspace import direct_problem

    _emit(direct_problem(T, v, v_star, nu=nu, mu=mu, system=system.value).to_dict(), json, "direct problem")


@app.command()
def fields(b: B, c: C, v_star: VStar, nu: Nu = 0.3, mu: Mu = 0.5, system: SystemOpt = System.printed,
           decaying: Annotated[bool, typer.Option(help="Use the v that makes the perturbation decay at depth (H6).")] = False,
           points: Annotated[int, typer.Option(help="Interface points per period.")] = 2001,
           json: Json = False,
           out: Annotated[Optional[Path], typer.Option(help="Write the fields to this netCDF file (.nc).")] = None,
           plot: Annotated[Optional[Path], typer.Option(help="Write a figure to this PNG file.")] = None):
    """Interface fields of the wave: stresses, u_x,x, slip velocity, residuals, singularities."""
    from ..halfspace import decaying_wave, inverse_problem, wave_from_inverse

    out, plot = output_path("--out", out, ".nc"), output_path("--plot", plot, ".png")
    check.count("--points", points, 10_000_000, "interface points per period")
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
