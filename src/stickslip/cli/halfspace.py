"""`stickslip halfspace ...`: stick-slip waves between a rigid body and an elastic half-space (paper §4-5)."""

from __future__ import annotations

import functools

from enum import Enum
from pathlib import Path
from typing import Annotated, Optional

import typer

from ..errors import MISSING, ParameterError
from ..quantities import HALFSPACE as Q
from ..quantities import RSF, SBIM
from .fault import fault
from .helptext import Typer
from .common import (FIGURE_HELP, FIGURE_SUFFIXES, Overwrite, Replace, command_line, declared, emit, output_path,
                     overwrite_needs, progress_bar, write_netcdf)

_emit = functools.partial(emit, model="halfspace")  # results are printed with the units of this model

app = Typer(no_args_is_help=True, rich_markup_mode=None, help="Rigid body sliding on an elastic half-space: periodic "
            "stick-slip waves, and the interface in time (run).")


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


class Plane(str, Enum):
    inplane = "in-plane"
    antiplane = "antiplane"


class Law(str, Enum):
    coulomb = "coulomb"
    slip_weakening = "slip-weakening"
    free = "free"
    rate_state = "rate-state"


def _sb(name: str, flag: str, note: str = ""):
    return declared(SBIM[name], flag, note)


def _rs(name: str, flag: str, default: str):
    return declared(RSF[name], flag, f"--law rate-state only; default {default}.")


#: The options of one law or another, their defaults and the laws that use them (given with another: refused).
LAW_OPTIONS = {"--static-friction": (0.6, ("coulomb", "slip-weakening")),
               "--kinetic-friction": (0.5, ("coulomb", "slip-weakening")),
               "--weakening-slip": (0.4, ("slip-weakening",)),
               "--a": (0.010, ("rate-state",)), "--b": (0.015, ("rate-state",)), "--dc": (0.008, ("rate-state",)),
               "--f0": (0.6, ("rate-state",)), "--v-ref": (1e-6, ("rate-state",)),
               "--slip-rate": (1e-6, ("rate-state",)), "--slip-law": (False, ("rate-state",))}
#: The background shear traction of the laws other than rate-and-state's [Pa].
TRACTION = 28e6


def _law_options(law, given: dict) -> dict:
    """Each law option's value (its default where not given), refusing one given with a law that does not use
    it."""
    for flag, value in given.items():
        if value not in (None, False) and law.value not in LAW_OPTIONS[flag][1]:
            raise ParameterError(flag, value, f"left out with --law {law.value} (an option of --law "
                                 f"{' or '.join(LAW_OPTIONS[flag][1])} only)")
    return {flag: LAW_OPTIONS[flag][0] if value is None else value for flag, value in given.items()}


def _rate_state(value: dict, normal_traction: float, relaxation: bool, lower):
    """The rate-and-state friction of ``--law rate-state`` (its options in ``value``)."""
    from ..rsf import RateState
    from ..sbim import RateStateFriction

    pressure = SBIM["normal_stress"].range
    if not pressure.lo <= -normal_traction <= pressure.hi:
        raise ParameterError("--normal-traction", normal_traction, f"in [{-pressure.hi:g}, {-pressure.lo:g}] Pa with "
                             "--law rate-state (a compression: the contact is held closed)")
    if lower is not None and not relaxation:
        raise ParameterError("--relaxation-slip", MISSING, "given with --law rate-state and a lower half-space (the "
                             "pressure's regularisation, with --relaxation-speed: unregularised it is ill-posed "
                             "between two materials)")
    law = RateState(value["--a"], value["--b"], value["--dc"], f0=value["--f0"], v_ref=value["--v-ref"],
                    evolution="slip" if value["--slip-law"] else "aging")
    return RateStateFriction(law, -normal_traction, value["--slip-rate"])


def _balanced(rate_state, damping: float, shears: dict) -> None:
    """Refuse a rate-and-state start whose shear no slip rate balances (``shears``: option -> (its value, the
    traction it makes))."""
    import math

    import numpy as np

    from ..errors import NoSolutionError
    from ..sbim.ratestate import slip_rates

    psi = rate_state.initial_psi(1)
    for flag, (value, shear) in shears.items():
        if shear <= 0.0:
            raise ParameterError(flag, value, f"a shear traction > 0 with --law rate-state (the interface slides "
                                 f"forwards only; here {shear:g} Pa)")
        try:
            slip_rates(rate_state.law, rate_state.normal_stress, damping, np.array([shear]), psi,
                       np.array([math.log(rate_state.slip_rate)]))
        except NoSolutionError:
            raise ParameterError(flag, value, f"a shear traction the rate-and-state strength can balance at the start "
                                 f"(at {shear:g} Pa no slip rate above 1e-300 m/s does; the steady drive at --slip-rate "
                                 f"is {rate_state.steady_drive(damping):.6g} Pa)") from None


def _given(ds, loading: dict):
    """``ds`` with the run's ``loading`` among its attributes."""
    ds.attrs.update(loading)
    return ds


def _antiplane(friction, pressure: float):
    """The antiplane law of an in-plane one under a normal traction held at ``pressure`` [Pa] (the strengths
    the coefficients times it)."""
    from ..sbim import Coulomb, CoulombFriction, SlipWeakening, SlipWeakeningFriction

    if isinstance(friction, CoulombFriction):
        return Coulomb(friction.static_friction * pressure, friction.kinetic_friction * pressure)
    if isinstance(friction, SlipWeakeningFriction):
        return SlipWeakening(friction.static_friction * pressure, friction.kinetic_friction * pressure,
                             friction.weakening_slip)
    return friction  # a free surface, rate-and-state friction: the same in both planes


@app.command()
def run(out: Annotated[Path, typer.Option(help="The run (.nc): its fields as a CF dataset, written as it goes and at "
                                                "the end; a killed run resumes from it (--overwrite starts afresh).")],
        shear_modulus: Annotated[float, _sb("shear_modulus", "--shear-modulus")] = 3e10,
        shear_wave_speed: Annotated[float, _sb("shear_wave_speed", "--shear-wave-speed")] = 3464.0,
        plane: Annotated[Plane, typer.Option("--plane", help="The motion: in the plane (slip and opening, the "
                                             "normal traction varying) or antiplane (slip along z under a normal "
                                             "traction held: no --poisson, --relaxation- or --lower- "
                                             "options).")] = Plane.inplane,
        poisson: Annotated[Optional[float], _sb("poisson", "--poisson", "At most 0.49; in-plane only; default "
                                                "0.25.")] = None,
        length: Annotated[float, _sb("length", "--length")] = 40e3,
        elements: Annotated[int, _sb("elements", "--elements")] = 512,
        law: Annotated[Law, typer.Option("--law", help="Interface law: unilateral contact with Coulomb or "
                                         "slip-weakening friction, a free surface, or rate-and-state friction "
                                         "(every node sliding from steady sliding at --slip-rate, the contact "
                                         "held closed).")] = Law.slip_weakening,
        static_friction: Annotated[Optional[float], _sb("static_friction", "--static-friction", "Coulomb and "
                                                        "slip-weakening; default 0.6.")] = None,
        kinetic_friction: Annotated[Optional[float], _sb("kinetic_friction", "--kinetic-friction", "Coulomb and "
                                                         "slip-weakening; default 0.5.")] = None,
        weakening_slip: Annotated[Optional[float], _sb("weakening_slip", "--weakening-slip", "Slip-weakening only; "
                                                       "default 0.4.")] = None,
        relaxation_slip: Annotated[Optional[float], _sb("relaxation_slip", "--relaxation-slip",
                                                        "With --relaxation-speed: Prakash-Clifton.")] = None,
        relaxation_speed: Annotated[Optional[float], _sb("relaxation_speed", "--relaxation-speed")] = None,
        a: Annotated[Optional[float], _rs("a", "--a", "0.010")] = None,
        b: Annotated[Optional[float], _rs("b", "--b", "0.015")] = None,
        dc: Annotated[Optional[float], _rs("dc", "--dc", "0.008")] = None,
        f0: Annotated[Optional[float], _rs("f0", "--f0", "0.6")] = None,
        v_ref: Annotated[Optional[float], _rs("v_ref", "--v-ref", "1e-6")] = None,
        slip_rate: Annotated[Optional[float], _sb("slip_rate", "--slip-rate", "--law rate-state only: every "
                                                  "node's state that of steady sliding at this rate, and so its "
                                                  "rate where the shear is the steady drive (--traction's "
                                                  "default); default 1e-6.")] = None,
        slip_law: Annotated[bool, typer.Option("--slip-law", help="Ruina's slip law instead of the aging law "
                                               "(--law rate-state).")] = False,
        traction: Annotated[Optional[float], _sb("traction", "--traction", "Uniform. Default: 28e6; with --law "
                                                 "rate-state the steady drive at --slip-rate.")] = None,
        normal_traction: Annotated[Optional[float], _sb("normal_traction", "--normal-traction", "Uniform; default "
                                                        "-50e6 (not with --plane antiplane --law free).")] = None,
        patch_traction: Annotated[float, _sb("patch_traction", "--patch-traction")] = 3e6,
        patch_width: Annotated[float, _sb("patch_width", "--patch-width")] = 8e3,
        patch_centre: Annotated[Optional[float], _sb("patch_centre", "--patch-centre", "Default: the middle.")] = None,
        patch_speed: Annotated[float, _sb("load_speed", "--patch-speed", "Of the patch, at most c_s / --beta "
                                          "(a cell per step).")] = 0.0,
        beta: Annotated[float, _sb("beta", "--beta")] = 0.3,
        history_periods: Annotated[float, _sb("history_periods", "--history-periods")] = 16.0,
        duration: Annotated[Optional[float], _sb("t_end", "--duration", "Default: 1.5 length / c_s.")] = None,
        every: Annotated[int, _sb("every", "--every")] = 10,
        lower_shear_modulus: Annotated[Optional[float], _sb("lower_shear_modulus", "--lower-shear-modulus",
                                                            "Of a second half-space below (with its two other "
                                                            "--lower- options); default: a rigid body.")] = None,
        lower_shear_wave_speed: Annotated[Optional[float], _sb("lower_shear_wave_speed", "--lower-shear-wave-speed")] = None,
        lower_poisson: Annotated[Optional[float], _sb("lower_poisson", "--lower-poisson", "At most 0.49.")] = None,
        plot: Annotated[Optional[Path], typer.Option(help=FIGURE_HELP + " Slip rate and normal traction (in-plane) "
                                                     "or shear stress (antiplane) over x and t.")] = None,
        overwrite: Overwrite = False, json: Json = False):
    """A half-space sliding in its plane on a rigid body (or on a second half-space: the --lower- options), or
    antiplane on a rigid body (--plane antiplane), in time (spectral boundary integral method): uniform
    tractions with more shear on a patch; slip, opening, rates and tractions over x and t."""
    import hashlib
    import json as json_module

    import numpy as np

    from ..sbim import (CoulombFriction, FreeSurface, InplaneProblem, PrakashClifton, SlipWeakeningFriction,
                        run_inplane)
    from ..sbim import AntiplaneProblem, run_antiplane
    from ..sbim.antiplane import RUN_FORMAT as ANTIPLANE, partial_antiplane
    from ..sbim.inplane import partial_run, patch_load
    from ..sbim.runfile import Checkpoint
    from ..sbim.surface import MAX_POISSON, Solid, interface_damping
    from ..cf import stamp
    from ..files import exclusive
    from .. import __version__

    out = output_path("--out", out, ".nc")
    plot = output_path("--plot", plot, FIGURE_SUFFIXES, overwrite)
    if plane is Plane.antiplane:
        for flag, given_value in (("--poisson", poisson), ("--relaxation-slip", relaxation_slip),
                                  ("--relaxation-speed", relaxation_speed),
                                  ("--lower-shear-modulus", lower_shear_modulus),
                                  ("--lower-shear-wave-speed", lower_shear_wave_speed),
                                  ("--lower-poisson", lower_poisson)):
            if given_value is not None:
                raise ParameterError(flag, given_value, "left out with --plane antiplane (in-plane only: antiplane "
                                     "runs are on a rigid body, their normal traction held)")
        if law is Law.free and normal_traction is not None:
            raise ParameterError("--normal-traction", normal_traction, "left out with --plane antiplane --law free "
                                 "(a free surface along z feels no normal traction)")
        if law in (Law.coulomb, Law.slip_weakening) and normal_traction is not None and normal_traction >= 0.0:
            raise ParameterError("--normal-traction", normal_traction, f"a compression (< 0) with --plane antiplane "
                                 f"--law {law.value} (the strengths are the coefficients times it)")
    if (relaxation_slip is None) != (relaxation_speed is None):
        given = "--relaxation-slip" if relaxation_slip is not None else "--relaxation-speed"
        other = "--relaxation-speed" if relaxation_slip is not None else "--relaxation-slip"
        raise ParameterError(other, MISSING, f"given with {given} (Prakash-Clifton needs both)")
    normal_traction = -50e6 if normal_traction is None else normal_traction
    poisson = 0.25 if poisson is None else poisson
    if law is Law.free and relaxation_slip is not None:
        raise ParameterError("--relaxation-slip", relaxation_slip, "left out with --law free (no friction to regularise)")
    lowers = {"--lower-shear-modulus": lower_shear_modulus, "--lower-shear-wave-speed": lower_shear_wave_speed,
              "--lower-poisson": lower_poisson}
    given = [flag for flag, value in lowers.items() if value is not None]
    if given and len(given) < 3:
        missing = next(flag for flag, value in lowers.items() if value is None)
        raise ParameterError(missing, MISSING, f"given with {given[0]} (a lower half-space needs all three)")
    for flag, value in (("--poisson", poisson), ("--lower-poisson", lower_poisson)):
        if value is not None and value > MAX_POISSON:
            raise ParameterError(flag, value, f"at most {MAX_POISSON} in-plane (the kernels' quadrature grows with "
                                 "c_p / c_s)")
    lower = Solid(lower_shear_modulus, lower_shear_wave_speed, lower_poisson) if given else None
    centre = length / 2 if patch_centre is None else patch_centre
    if centre > length or patch_width > length:
        bad = ("--patch-centre", centre) if centre > length else ("--patch-width", patch_width)
        raise ParameterError(*bad, f"at most --length = {length:g} m", also=("--length",))
    value = _law_options(law, {"--static-friction": static_friction, "--kinetic-friction": kinetic_friction,
                               "--weakening-slip": weakening_slip, "--a": a, "--b": b, "--dc": dc, "--f0": f0,
                               "--v-ref": v_ref, "--slip-rate": slip_rate, "--slip-law": slip_law})
    static_friction, kinetic_friction = value["--static-friction"], value["--kinetic-friction"]
    if kinetic_friction > static_friction and law in (Law.coulomb, Law.slip_weakening):
        raise ParameterError("--kinetic-friction", kinetic_friction, f"at most --static-friction = {static_friction:g}")
    if patch_speed != 0.0 and patch_width == 0.0:
        raise ParameterError("--patch-speed", patch_speed, "left out with --patch-width 0 (no patch to move)")
    friction = {Law.coulomb: lambda: CoulombFriction(static_friction, kinetic_friction),
                Law.slip_weakening: lambda: SlipWeakeningFriction(static_friction, kinetic_friction,
                                                                  value["--weakening-slip"]),
                Law.free: FreeSurface,
                Law.rate_state: lambda: _rate_state(value, normal_traction, relaxation_slip is not None, lower)}[law]()
    damping = interface_damping(Solid(shear_modulus, shear_wave_speed, poisson), lower)[0]
    if traction is None:
        traction = friction.steady_drive(damping) if law is Law.rate_state else TRACTION
    if law is Law.rate_state:
        shears = {"--traction": (traction, traction)}
        if patch_width > 0.0:
            shears["--patch-traction"] = (patch_traction, traction + patch_traction)
        _balanced(friction, damping, shears)
    if relaxation_slip is not None:
        friction = PrakashClifton(friction, relaxation_slip, relaxation_speed)
    load = patch_load(traction, normal_traction, patch_traction, patch_width, centre, patch_speed)
    if plane is Plane.antiplane:
        problem = AntiplaneProblem(shear_modulus, shear_wave_speed, length, elements, lambda x, t: load(x, t)[0],
                                   _antiplane(friction, -normal_traction), beta=beta, history_periods=history_periods)
        runner, partial, kind = run_antiplane, partial_antiplane, {"run_format": ANTIPLANE}
    else:
        problem = InplaneProblem(shear_modulus, shear_wave_speed, poisson, length, elements, load, friction, beta=beta,
                                 history_periods=history_periods, lower=lower)
        runner, partial, kind = run_inplane, partial_run, {}
    if abs(patch_speed) * problem.dt > problem.dx:
        raise ParameterError("--patch-speed", patch_speed, f"at most {problem.dx / problem.dt:.6g} m/s in size here (a "
                             "cell per step)", also=("--shear-wave-speed", "--beta"))
    t_end = 1.5 * length / shear_wave_speed if duration is None else duration
    if t_end < problem.dt:
        raise ParameterError("--duration", t_end, f"at least one step, {problem.dt:.4g} s here",
                             also=("--length", "--elements", "--beta", "--shear-wave-speed"))
    if t_end / problem.dt > 1e9:
        raise ParameterError("--duration", t_end, f"at most {1e9 * problem.dt:.4g} s here (1e9 steps of {problem.dt:.3g} s)",
                             also=("--elements", "--beta"))
    steps = max(1, int(round(t_end / problem.dt)))
    settings = {"version": __version__, "law": law.value, "plane": plane.value, **{k: v for k, v in locals().items() if k in (
        "shear_modulus", "shear_wave_speed", "poisson", "length", "elements", "relaxation_slip", "relaxation_speed",
        "traction", "normal_traction", "patch_traction",
        "patch_width", "centre", "patch_speed", "beta", "history_periods", "steps", "every", "lower_shear_modulus",
        "lower_shear_wave_speed", "lower_poisson")}, **{flag: v for flag, v in value.items()
                                                        if law.value in LAW_OPTIONS[flag][1]}}
    key = hashlib.sha256(json_module.dumps(settings, sort_keys=True).encode()).hexdigest()
    # what the run was given beyond its problem's numbers: its loading (and, antiplane, the coefficients its
    # strengths are of), said in its JSON and its file
    loading = {"traction": traction, "patch_traction": patch_traction, "patch_width": patch_width,
               "patch_centre": centre, "load_speed": patch_speed,
               **({} if plane is Plane.antiplane and law is Law.free else {"normal_traction": normal_traction}),
               **({"static_friction": static_friction, "kinetic_friction": kinetic_friction}
                  if plane is Plane.antiplane and law in (Law.coulomb, Law.slip_weakening) else {})}
    with exclusive(out, "--out"):
        if overwrite and out.exists():
            out.unlink()
        command = command_line()
        checkpoint = Checkpoint(out, key, lambda state: stamp(_given(partial(problem, state).to_xarray(), loading),
                                                              command), **kind)
        with progress_bar("running the interface") as tick:
            try:
                result = runner(problem, steps, every=every, checkpoint=checkpoint, progress=tick)
            except ParameterError as err:  # the run's steps are this command's --duration over its step
                if err.name != "steps":
                    raise
                raise ParameterError("--duration", t_end, f"{err.allowed} ({steps} steps of {problem.dt:.3g} s)",
                                     also=("--elements", "--beta", "--history-periods")) from None
    slipped = np.any(result.slip != result.slip[0], axis=0)  # moved at all (a stuck node's slip stays exact)
    summary = {**result.to_dict(), "plane": plane.value, "t_end": float(result.t[-1]), "steps": steps,
               "peak_slip_rate": float(np.abs(result.slip_rate).max()), "final_max_slip": float(np.abs(result.slip[-1]).max()),
               "slipped_fraction": float(slipped.mean())}
    if plane is Plane.inplane:
        summary.update({"peak_opening": float(result.opening.max()),
                        "open_fraction_at_end": float((result.opening[-1] > 0).mean())})
    from ..sbim.energy import energy_book  # the energy books at the end

    summary.update({k: v for k, v in energy_book(result).to_dict().items() if k != "t"})
    # the loading the run was given (the law's options are the run's own numbers, in its summary)
    summary.update(loading)
    meanings = {k: (RSF[k].units, RSF[k].meaning) for k in ("a", "b", "dc", "f0", "v_ref") if k in summary}
    if "slip_law" in summary:
        meanings["slip_law"] = ("1", "Ruina's slip law (false: the aging law)")
    emit(summary, json, "interface run", model="sbim", meanings=meanings)  # an ill-posed law is said
    # on stderr by the run (its log)
    if plot:
        from .. import plotting

        names = ("slip_rate", "normal_traction" if plane is Plane.inplane else "shear_stress")
        plotting.save(plotting.plot_space_time(result.to_xarray(), names), plot)


app.command(name="fault")(fault)
