"""`stickslip halfspace fault`: earthquake cycles on a vertical strike-slip fault (`stickslip.sbim.fault`)
from the command line, with BP1-QD's depth profile of ``a`` (velocity weakening down to
``--seismogenic-depth``, rising linearly over ``--transition-width`` to ``--deep-a``); written to a run file
as it goes and resumed after a kill."""

from __future__ import annotations

from pathlib import Path
from typing import Annotated, Optional

import typer

from ..errors import ParameterError
from ..quantities import RSF, SBIM
from .common import FIGURE_HELP, FIGURE_SUFFIXES, Overwrite, command_line, declared, emit, output_path, progress_bar

__all__ = ["fault"]


def _sb(name: str, flag: str, note: str = ""):
    return declared(SBIM[name], flag, note)


def _rsf(name: str, flag: str, note: str = ""):
    return declared(RSF[name], flag, note)


def _flag(name: str) -> str:
    """The option of a parameter of `stickslip.sbim.fault.StrikeSlipFault` (``a_profile``: ``--a``)."""
    return "--a" if name == "a_profile" else "--" + name.replace("_", "-")


def fault(out: Annotated[Path, typer.Option(help="The run (.nc): its records as a CF dataset, written as it goes "
                                                 "and at the end; a killed run resumes from it (--overwrite starts "
                                                 "afresh).")],
          years: Annotated[float, _sb("years", "--years")] = 300.0,
          shear_modulus: Annotated[float, _sb("shear_modulus", "--shear-modulus")] = 2670.0 * 3464.0**2,
          shear_wave_speed: Annotated[float, _sb("shear_wave_speed", "--shear-wave-speed")] = 3464.0,
          depth: Annotated[float, _sb("depth", "--depth")] = 40e3,
          elements: Annotated[int, _sb("elements", "--elements")] = 200,
          domain_depth: Annotated[Optional[float], _sb("domain_depth", "--domain-depth", "Default: twice "
                                                       "--depth.")] = None,
          a: Annotated[float, _rsf("a", "--a", "Above --seismogenic-depth.")] = 0.010,
          deep_a: Annotated[float, _sb("deep_a", "--deep-a")] = 0.025,
          seismogenic_depth: Annotated[float, _sb("seismogenic_depth", "--seismogenic-depth")] = 15e3,
          transition_width: Annotated[float, _sb("transition_width", "--transition-width")] = 3e3,
          b: Annotated[float, _rsf("b", "--b")] = 0.015,
          dc: Annotated[float, _rsf("dc", "--dc")] = 0.008,
          f0: Annotated[float, _rsf("f0", "--f0")] = 0.6,
          v_ref: Annotated[float, _rsf("v_ref", "--v-ref")] = 1e-6,
          slip_law: Annotated[bool, typer.Option("--slip-law", help="Ruina's slip law instead of the aging law.")]
          = False,
          normal_stress: Annotated[float, _sb("normal_stress", "--normal-stress")] = 50e6,
          plate_rate: Annotated[float, _sb("plate_rate", "--plate-rate")] = 1e-9,
          initial_rate: Annotated[Optional[float], _sb("initial_rate", "--initial-rate", "Default: "
                                                       "--plate-rate.")] = None,
          event_rate: Annotated[float, _sb("event_rate", "--event-rate")] = 1e-3,
          rtol: Annotated[float, _sb("rtol", "--rtol")] = 1e-7,
          plot: Annotated[Optional[Path], typer.Option(help=FIGURE_HELP + " The largest slip rate over time and the "
                                                       "slip profiles.")] = None,
          overwrite: Overwrite = False,
          json: Annotated[bool, typer.Option("--json", help="Print one JSON object on stdout.")] = False):
    """Earthquake cycles on a vertical strike-slip fault (quasi-dynamic, rate-and-state varying with depth,
    creeping at the plate rate below --depth): events, recurrence, peak slip rates, slip profiles. The
    defaults are the SCEC SEAS benchmark BP1-QD's, on 200-m cells (BP1 asks 25 m)."""
    import hashlib
    import json as json_module

    import numpy as np

    from .. import __version__
    from ..cf import stamp
    from ..files import exclusive
    from ..rsf import RateState
    from ..sbim.fault import RUN_FORMAT, YEAR, StrikeSlipFault, partial_fault, run_fault
    from ..sbim.runfile import Checkpoint

    out = output_path("--out", out, ".nc")
    plot = output_path("--plot", plot, FIGURE_SUFFIXES, overwrite)
    if seismogenic_depth >= depth:
        raise ParameterError("--seismogenic-depth", seismogenic_depth, f"below --depth = {depth:g} m (the "
                             "rate-and-state part of the fault)", also=("--depth",))
    law = RateState(a, b, dc, f0, v_ref, "slip" if slip_law else "aging", regularized=True)

    def a_profile(z):
        return np.clip(a + (deep_a - a) * (z - seismogenic_depth) / transition_width, min(a, deep_a),
                       max(a, deep_a))

    try:
        problem = StrikeSlipFault(shear_modulus, shear_wave_speed, depth, elements, law, a_profile, normal_stress,
                                  plate_rate, initial_rate, domain_depth)
    except ParameterError as err:  # named as the user typed it
        raise ParameterError(_flag(err.name), err.value, err.allowed, also=tuple(map(_flag, err.also))) from None
    t_end = years * YEAR
    settings = {"version": __version__, **{k: v for k, v in locals().items() if k in (
        "years", "shear_modulus", "shear_wave_speed", "depth", "elements", "domain_depth", "a", "deep_a",
        "seismogenic_depth", "transition_width", "b", "dc", "f0", "v_ref", "slip_law", "normal_stress",
        "plate_rate", "initial_rate", "event_rate", "rtol")}}
    key = hashlib.sha256(json_module.dumps(settings, sort_keys=True).encode()).hexdigest()
    with exclusive(out, "--out"):
        if overwrite and out.exists():
            out.unlink()
        command = command_line()
        checkpoint = Checkpoint(out, key, lambda state: stamp(partial_fault(problem, state, event_rate).to_xarray(),
                                                              command), run_format=RUN_FORMAT)
        with progress_bar("cycles on the fault") as tick:
            result = run_fault(problem, t_end, event_rate=event_rate, rtol=rtol, checkpoint=checkpoint,
                               progress=lambda t, total: tick(int(t / total * 1000), 1000))
    summary = {k: v for k, v in result.to_dict().items() if not (isinstance(v, float) and not np.isfinite(v))}
    rec = result.recurrence
    if rec.size:
        summary["recurrence_last"] = float(rec[-1])
    emit(summary, json, "earthquake cycles", model="sbim")
    if plot:
        from .. import plotting

        plotting.save(plotting.plot_fault_cycles(result.to_xarray()), plot)
