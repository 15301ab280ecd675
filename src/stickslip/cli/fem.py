"""`stickslip fem ...`: any 2-D body from a mesh file and a TOML config (see `stickslip.fem.config`)."""

from __future__ import annotations

import functools
from pathlib import Path
from typing import Annotated

import typer

from .common import emit

_emit = functools.partial(emit, model="fem")  # SI units: growth rates in 1/s, frequencies in Hz

app = typer.Typer(no_args_is_help=True, rich_markup_mode=None,
                  help="A 2-D body of your own (a mesh file and a TOML config) on a rigid counter-surface.")

Config = Annotated[Path, typer.Argument(help="The TOML config (mesh, material, contact, surface; see the docs).")]
Json = Annotated[bool, typer.Option("--json", help="Print one JSON object on stdout.")]


def _problem(config: Path):
    from ..fem.config import load_config

    return load_config(config)


@app.command()
def steady(config: Config, json: Json = False):
    """Steady sliding (or the preload, with friction 0): contact nodes, forces and active set."""
    from ..fem import steady_contact

    cfg = _problem(config)
    problem = cfg.problem()
    st = steady_contact(problem.system, problem.frames, problem.friction, problem.clamped)
    _emit({"contact_nodes": int(len(st.pressure)), "active_nodes": int(st.active.sum()),
           "normal_force": float(st.pressure.sum()), "friction_force": float(st.shear.sum()),
           "max_node_force": float(st.pressure.max()), "iterations": int(st.iterations)}, json, "steady sliding")


@app.command()
def cea(config: Config, json: Json = False):
    """Complex eigenvalue analysis of steady sliding over [cea] band: growth rate [1/s] and
    frequency [Hz] of every mode found, most unstable first."""
    from ..fem import complex_eigenvalues

    cfg = _problem(config)
    result = complex_eigenvalues(cfg.problem(), cfg.band, cfg.count)
    data = result.to_dict()
    _emit({"modes": data["modes"], "unstable": data["unstable"], "complete_below": data["complete_below"],
           "shifts": len(data["shifts"])}, json, "complex eigenvalue analysis")
