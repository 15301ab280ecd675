"""`stickslip brake ...`: the brake-like system, reduced model (paper section 3)."""

from __future__ import annotations

import functools

from pathlib import Path
from typing import Annotated, Optional

import typer

from ..quantities import BRAKE as Q, COMMON
from ..errors import MISSING, ParameterError
from .helptext import Typer
from .common import (AXIS_HELP, Overwrite, Replace, RunOut, Scheduler, XdmfEvery, axis, checked_axis, declared, emit, map_size, output_folder, output_path, overwrite_needs,
                     progress_bar, write_netcdf, xdmf_snapshots)

_emit = functools.partial(emit, model="brake")  # results are printed with the units of this model

app = Typer(no_args_is_help=True, rich_markup_mode=None, help="Elastic annulus on a rotating shaft: reduced model (paper section 3).")

Opt = Optional[float]
Xi = Annotated[Opt, declared(Q["xi"], "--xi")]
Nu = Annotated[float, declared(Q["nu"], "--nu")]
Gamma = Annotated[Opt, declared(Q["gamma"], "--gamma", "Or --omega with the material.")]
Delta = Annotated[Opt, declared(Q["delta"], "--delta", "Or --mismatch (scaled: the model is linear in it).")]
Friction = Annotated[float, declared(Q["friction"], "--friction")]
Inner = Annotated[Opt, declared(Q["inner_radius"], "--inner-radius", "Default 0.1 with SI input.")]
Outer = Annotated[Opt, declared(Q["outer_radius"], "--outer-radius", "Default 0.15 with SI input.")]
Young = Annotated[Opt, declared(Q["young"], "--young", "Default 2.1e11, with --omega.")]
Density = Annotated[Opt, declared(Q["density"], "--density", "Default 7850, with --omega.")]
Omega = Annotated[Opt, declared(Q["omega"], "--omega", "Sets gamma = rho R^2 Omega^2 / E, in its range.")]
Mismatch = Annotated[Opt, declared(Q["mismatch"], "--mismatch", "At most 0.01 R (small strain at the bore).")]
Json = Annotated[bool, typer.Option("--json", help="Print one JSON object on stdout.")]
SeedWave = Annotated[Optional[int], declared(Q["mode"], "--seed-wave-number", (
    "Start from steady sliding plus this Fourier mode (default: white noise)."))]

_DEFAULTS = {"inner_radius": 0.1, "outer_radius": 0.15, "young": 2.1e11, "density": 7850.0}


def _pick(name: str, given, physical_names: list[str]):
    """The dimensionless ``given`` value, refused when physical options that set it are given too."""
    if given is not None and physical_names:
        raise ParameterError(f"--{name}", given, "given alone, not together with "
                             + " and ".join(f"--{n.replace('_', '-')}" for n in physical_names))
    return given


def _check_options(options: dict) -> None:
    """Every option given is in its declared range, named as typed (the options check themselves
    as they are parsed; a call from Python is checked here), and no option contradicts another."""
    for name, value in options.items():
        if value is not None and name != "need":
            Q.check(name, value, "--" + name.replace("_", "-"))
    material = [n for n in ("young", "density") if options.get(n) is not None]
    if material and options.get("gamma") is not None:
        raise ParameterError("--" + material[0], options[material[0]], "left out with --gamma (the material only "
                             "serves to compute gamma from --omega)")


def resolve(*, xi=None, nu=0.3, gamma=None, delta=None, friction=0.0, inner_radius=None, outer_radius=None,
            young=None, density=None, omega=None, mismatch=None, need=("xi", "gamma", "delta")) -> dict:
    """Dimensionless ``xi, gamma, delta`` from either the dimensionless or the SI options."""
    from ..brake.reduced.params import in_ratio, small_strain  # the models load with the commands that use them

    _check_options(dict(xi=xi, nu=nu, gamma=gamma, delta=delta, friction=friction, inner_radius=inner_radius,
                        outer_radius=outer_radius, young=young, density=density, omega=omega, mismatch=mismatch))
    phys = {k: v for k, v in dict(inner_radius=inner_radius, outer_radius=outer_radius, young=young,
                                  density=density, omega=omega, mismatch=mismatch).items() if v is not None}
    m = {**_DEFAULTS, **phys}
    out = {"nu": nu, "friction": friction}
    if "xi" in need:
        out["xi"] = _pick("xi", xi, [n for n in ("inner_radius", "outer_radius") if n in phys])
        if out["xi"] is None:
            if m["inner_radius"] <= 0:
                raise ParameterError("--inner-radius", m["inner_radius"], "> 0")
            in_ratio("--outer-radius", m["outer_radius"], m["inner_radius"], "--inner-radius")
            out["xi"] = m["outer_radius"] / m["inner_radius"]
    if "gamma" in need:
        out["gamma"] = _pick("gamma", gamma, [n for n in ("omega",) if n in phys])
        if out["gamma"] is None:
            if "omega" not in phys:
                given = [f"--{n}" for n in ("young", "density") if n in phys]
                if given:  # the material alone sets no gamma: the shaft speed is missing
                    raise ParameterError("--omega", MISSING, f"given with {' and '.join(given)} (gamma = rho R^2 "
                                         "Omega^2 / E needs the shaft speed), or --gamma alone")
                raise ParameterError("--gamma", MISSING, "given, or --omega [rad/s] (with the material)")
            from ..brake import PhysicalParams

            out["gamma"] = PhysicalParams(m["omega"], 0.0, 0.0, m["inner_radius"], m["outer_radius"], m["young"],
                                          m["density"], nu).gamma
    if "delta" in need:
        out["delta"] = _pick("delta", delta, [n for n in ("mismatch",) if n in phys])
        if out["delta"] is None:
            if "mismatch" not in phys:
                raise ParameterError("--delta", MISSING, "given, or --mismatch [m]")
            small_strain("--mismatch", m["mismatch"], m["inner_radius"], "--inner-radius")
            out["delta"] = m["mismatch"] / m["inner_radius"]
    return out


def params(**options):
    """`BrakeParams` from the options; built from the SI set (kept, e.g. for rates in 1/s and
    continuation in Omega) when ``--omega`` and ``--mismatch`` are given without dimensionless ones."""
    from ..brake import BrakeParams, PhysicalParams

    si = {k: options[k] for k in ("inner_radius", "outer_radius", "young", "density") if options.get(k) is not None}
    if options.get("omega") is not None and options.get("mismatch") is not None and all(
            options.get(k) is None for k in ("xi", "gamma", "delta")):
        _check_options({k: v for k, v in options.items() if k != "need"})  # resolve() checks the other path
        return PhysicalParams(options["omega"], options["mismatch"], options.get("friction", 0.0),
                              poisson=options.get("nu", 0.3), **si).dimensionless()
    return BrakeParams(**resolve(**options))


def parse_modes(text: str) -> list[int]:
    """``"1-20"``, ``"8"`` or ``"2,4,8"`` -> list of wave numbers (``--wave-numbers``)."""
    try:
        modes = []
        for part in text.split(","):
            lo, _, hi = part.strip().partition("-")
            if hi and int(hi) - int(lo) > 10_000:
                raise ParameterError("--wave-numbers", text, "mode numbers from 1 to 100000, at most 10000 per range")
            modes += list(range(int(lo), int(hi) + 1)) if hi else [int(lo)]
    except ParameterError:
        raise
    except ValueError:
        raise ParameterError("--wave-numbers", text, "a list like 1-20, 8 or 2,4,8") from None
    if not modes or min(modes) < 1 or max(modes) > 100_000:
        raise ParameterError("--wave-numbers", text, "mode numbers from 1 to 100000")
    if len(set(modes)) < len(modes):  # a mode twice was computed and printed twice
        twice = sorted({m for m in modes if modes.count(m) > 1})
        raise ParameterError("--wave-numbers", text, f"each mode number once ({twice[0]} is given twice)")
    return modes


@app.command()
def coefficients(xi: Xi = None, nu: Nu = 0.3, gamma: Gamma = None, inner_radius: Inner = None,
                 outer_radius: Outer = None, young: Young = None, density: Density = None, omega: Omega = None,
                 json: Json = False):
    """Coefficients a, b, g, h, D, A, B, C1, C2 of the reduced model (eq. [13])."""
    from ..brake import coefficients as compute

    p = resolve(xi=xi, nu=nu, gamma=gamma, inner_radius=inner_radius, outer_radius=outer_radius, young=young,
                density=density, omega=omega, need=("xi", "gamma"))
    _emit(compute(p["xi"], p["nu"], p["gamma"]).to_dict(), json, "reduced-model coefficients [13]")


@app.command()
def steady(xi: Xi = None, nu: Nu = 0.3, delta: Delta = None, friction: Friction = 0.0,
           inner_radius: Inner = None, outer_radius: Outer = None, mismatch: Mismatch = None, json: Json = False):
    """Steady sliding: p_e, q_e (units of E), U_e, V_e (units of R), eqs. [11] and [16]."""
    from ..brake import steady_sliding

    p = resolve(xi=xi, nu=nu, delta=delta, friction=friction, inner_radius=inner_radius, outer_radius=outer_radius,
                mismatch=mismatch, need=("xi", "delta"))
    _emit(steady_sliding(p["xi"], p["nu"], p["delta"], p["friction"]).to_dict(), json, "steady sliding")


@app.command()
def stability(xi: Xi = None, nu: Nu = 0.3, gamma: Gamma = None, delta: Delta = None, friction: Friction = 0.0,
              modes: Annotated[str, typer.Option("--wave-numbers", help="Wave numbers n (waves around the ring), "
                                                 "e.g. 1-20 or 2,4,8.")] = "1-20",
              inner_radius: Inner = None, outer_radius: Outer = None, young: Young = None, density: Density = None,
              omega: Omega = None, mismatch: Mismatch = None, json: Json = False):
    """Growth rate Re s and frequency Im s of each Fourier mode n of steady sliding."""
    from ..brake import growth_rates

    p = params(xi=xi, nu=nu, gamma=gamma, delta=delta, friction=friction, inner_radius=inner_radius,
               outer_radius=outer_radius, young=young, density=density, omega=omega, mismatch=mismatch)
    _emit(growth_rates(p, parse_modes(modes)).to_dict(), json, "linear stability of steady sliding")


@app.command("integrate")
def integrate_cmd(xi: Xi = None, nu: Nu = 0.3, gamma: Gamma = None, delta: Delta = None, friction: Friction = 0.0,
                  inner_radius: Inner = None, outer_radius: Outer = None, young: Young = None,
                  density: Density = None, omega: Omega = None, mismatch: Mismatch = None,
                  nodes: Annotated[int, declared(Q["nodes"], "--nodes")] = 512,
                  transits: Annotated[float, declared(Q["transits"], "--transits", "A transit: 2 pi / sqrt(a).")] = 100.0,
                  beta2: Annotated[float, declared(COMMON["beta2"], "--beta2")] = 0.5,
                  mode: SeedWave = None,
                  amplitude: Annotated[float, declared(COMMON["amplitude"], "--amplitude", "Relative to delta.")] = 1e-3,
                  out: RunOut = None,
                  overwrite: Overwrite = False, json: Json = False):
    """Time integration of [12] on the ring from perturbed steady sliding; classifies the limit regime."""
    from ..brake import classify, integrate, perturbed_steady

    overwrite_needs(overwrite, "--out", out)
    out = output_path("--out", out, ".nc")
    p = params(xi=xi, nu=nu, gamma=gamma, delta=delta, friction=friction, inner_radius=inner_radius,
               outer_radius=outer_radius, young=young, density=density, omega=omega, mismatch=mismatch)
    initial = perturbed_steady(p, nodes, amplitude=amplitude, mode=mode)
    with progress_bar("integrating") as tick:
        run = integrate(p, nodes, transits=transits, beta2=beta2, initial=initial, checkpoint=out,
                        progress=tick, overwrite=overwrite)
    _emit(classify(run).to_dict(), json, "limit regime")


REGIME_NAMES = ["stick-slip", "stick-slip-separation", "stick-separation", "stick-slip-reverse-slip",
                "stick-slip-separation-reverse-slip"]


def _regime(value: Optional[str]) -> Optional[str]:
    if value is not None and value not in REGIME_NAMES:
        raise ParameterError("--regime", value, "one of " + ", ".join(REGIME_NAMES))
    return value


@app.command()
def wave(xi: Xi = None, nu: Nu = 0.3, gamma: Gamma = None, delta: Delta = None, friction: Friction = 0.0,
         modes: Annotated[int, declared(Q["modes"], "--wave-number", "The period is 2 pi / n.")] = 4,
         regime: Annotated[Optional[str], typer.Option(help="Wanted regime, e.g. stick-slip (default: any).")] = None,
         inner_radius: Inner = None, outer_radius: Outer = None, young: Young = None, density: Density = None,
         omega: Omega = None, mismatch: Mismatch = None, json: Json = False,
         out: Annotated[Optional[Path], typer.Option(help="Write the wave profiles to this netCDF file (.nc).")] = None,
         overwrite: Replace = False):
    """Travelling wave of [14]-[20] by multiple shooting: speed c, regime and zones."""
    from ..brake import travelling_wave

    overwrite_needs(overwrite, "--out", out)
    out = output_path("--out", out, ".nc", overwrite)
    p = params(xi=xi, nu=nu, gamma=gamma, delta=delta, friction=friction, inner_radius=inner_radius,
               outer_radius=outer_radius, young=young, density=density, omega=omega, mismatch=mismatch)
    result = travelling_wave(p, modes, regime=_regime(regime))
    _emit(result.to_dict(), json, "travelling wave")
    if out:
        write_netcdf(result.to_xarray(), out)


def parse_nodes(text: str, modes: int) -> list[int]:
    """``"64,128,256"`` -> the ring sizes of ``--nodes`` (each in its range, a multiple of ``modes``)."""
    try:
        nodes = [int(part) for part in text.split(",")]
    except ValueError:
        raise ParameterError("--nodes", text, "a list of node counts like 64,128,256") from None
    if not 1 <= len(nodes) <= 16:
        raise ParameterError("--nodes", text, "1 to 16 node counts")
    for k in nodes:
        Q.check("spectrum_nodes", k, "--nodes")
        if k % modes:
            raise ParameterError("--nodes", k, f"a multiple of the wave number {modes} (--wave-number)")
    return nodes


@app.command()
def spectrum(xi: Xi = None, nu: Nu = 0.3, gamma: Gamma = None, delta: Delta = None, friction: Friction = 0.0,
             modes: Annotated[int, declared(Q["modes"], "--wave-number", "The period is 2 pi / n.")] = 4,
             nodes: Annotated[str, typer.Option(help="Ring sizes, e.g. 64,128,256 (each 8 to 1024, a multiple of "
                                                     "the wave number; 512 nodes take about a minute).")] = "64,128",
             regime: Annotated[Optional[str], typer.Option(help="Wanted regime, e.g. stick-slip (default: any).")] = None,
             inner_radius: Inner = None, outer_radius: Outer = None, young: Young = None, density: Density = None,
             omega: Omega = None, mismatch: Mismatch = None, json: Json = False,
             out: Annotated[Optional[Path], typer.Option(help="Write the convergence table to this netCDF file "
                                                              "(.nc).")] = None,
             overwrite: Replace = False):
    """Stability of a travelling wave: the multipliers of its node-shift map on rings of --nodes nodes
    (a perturbation grows by exp(growth_per_period) per wave period); a wave that separates from the
    shaft on the ring whose nodes may leave it too."""
    from ..brake import travelling_wave
    from ..brake.waves import wave_spectra

    overwrite_needs(overwrite, "--out", out)
    out = output_path("--out", out, ".nc", overwrite)
    sizes = parse_nodes(nodes, Q.check("modes", modes, "--wave-number"))
    p = params(xi=xi, nu=nu, gamma=gamma, delta=delta, friction=friction, inner_radius=inner_radius,
               outer_radius=outer_radius, young=young, density=density, omega=omega, mismatch=mismatch)
    if not p.delta > 0:  # the ring's contact reaction g delta: no ring without a press
        raise ParameterError("--mismatch" if mismatch is not None else "--delta",
                             mismatch if mismatch is not None else delta, "> 0 (a ring pressed on the shaft)")
    wave = travelling_wave(p, modes, regime=_regime(regime))
    ds = wave_spectra(wave, sizes)
    last = ds.isel(nodes=-1)
    data = {"c": float(wave.c), "structure": wave.structure, "separates": "separation" in wave.structure,
            "stable": bool(int(last["stable"])),
            "growth_per_period": float(last["growth_per_period"]), "nodes": [int(k) for k in ds.nodes.values],
            "growth_per_period_by_nodes": [float(v) for v in ds["growth_per_period"].values],
            "leading_abs_by_nodes": [float(v) for v in ds["leading_abs"].values],
            "speed_error_by_nodes": [float(v) for v in ds["speed_error"].values]}
    _emit(data, json, "wave spectrum")
    if out:
        write_netcdf(ds, out)


@app.command("continue")
def continue_cmd(xi: Xi = None, nu: Nu = 0.3, gamma: Gamma = None, delta: Delta = None, friction: Friction = 0.0,
                 modes: Annotated[int, declared(Q["modes"], "--wave-number")] = 4,
                 parameter: Annotated[str, typer.Option(help="delta, gamma, omega (needs SI input) or friction.")] = "delta",
                 stop: Annotated[float, declared(Q["stop"], "--stop")] = 0.0,
                 points: Annotated[int, declared(COMMON["points"], "--points")] = 50,
                 regime: Annotated[Optional[str], typer.Option(help="Regime of the starting wave.")] = None,
                 inner_radius: Inner = None, outer_radius: Outer = None, young: Young = None, density: Density = None,
                 omega: Omega = None, mismatch: Mismatch = None, json: Json = False,
                 out: Annotated[Optional[Path], typer.Option(help="Write the branch to this netCDF file (.nc).")] = None,
                 overwrite: Replace = False):
    """Continuation of a wave family in delta, gamma, Omega or f, with births and deaths of zones."""
    from ..brake import continue_waves

    overwrite_needs(overwrite, "--out", out)
    out = output_path("--out", out, ".nc", overwrite)
    p = params(xi=xi, nu=nu, gamma=gamma, delta=delta, friction=friction, inner_radius=inner_radius,
               outer_radius=outer_radius, young=young, density=density, omega=omega, mismatch=mismatch)
    branch = continue_waves(p, modes, parameter=parameter, stop=stop, num=points, regime=_regime(regime))
    data = branch.to_dict()
    if not json:
        data = {"parameter": data["parameter"], "n": data["n"], "points": len(data["values"]),
                "c": [min(data["c"]), max(data["c"])], "events": data["events"], "stopped": data["stopped"]}
    _emit(data, json, "wave branch")
    if out:
        write_netcdf(branch.to_xarray(), out)


@app.command("map")
def map_cmd(out: Annotated[Path, typer.Option(help="Zarr store (directory ending in .zarr); resumed if it exists.")],
            kind: Annotated[str, typer.Option(help="waves (shooting) or ring (time integration).")] = "waves",
            x: Annotated[str, typer.Option("--x", help=f"First axis: friction or mismatch [m], {AXIS_HELP}.")] =
            "friction=0.1:2:16",
            y: Annotated[str, typer.Option("--y", help=f"Second axis: the other one, {AXIS_HELP}.")] =
            "mismatch=1e-7:1e-4:12:log",
            omega: Annotated[float, declared(Q["omega"], "--omega")] = 50.0,
            modes: Annotated[Optional[int], declared(Q["modes"], "--wave-number", "With --kind waves only; "
                                                     "default 4.")] = None,
            workers: Annotated[Optional[int], declared(COMMON["workers"], "--workers", "Default: all cores.")] = None,
            scheduler: Scheduler = None, overwrite: Overwrite = False, json: Json = False):
    """Regime map over friction and mismatch (resumable, parallel): travelling waves or ring limit regimes."""
    from ..brake.maps import REGIME_CODES, ring_regime_map, wave_regime_map

    out = output_folder("--out", out, ".zarr")
    if kind not in ("waves", "ring"):
        raise ParameterError("--kind", kind, "waves or ring")
    if kind == "ring" and modes is not None:
        raise ParameterError("--wave-number", modes, "left out with --kind ring (the ring finds its own waves)")
    modes = 4 if modes is None else modes
    named = [axis(option, text) for option, text in (("--x", x), ("--y", y))]
    if {n for n, _ in named} != {"friction", "mismatch"}:
        raise ParameterError("--x", x, f"an axis of friction, with --y an axis of mismatch or the other way round "
                             f"(got {' and '.join(n for n, _ in named)})", also=("--y",))

    def point(name, value):  # every point is a valid SI annulus of the default geometry (R = 0.1 m)
        if name == "mismatch" and value <= 0:
            raise ParameterError(name, value, "> 0 (without interference there is no contact)")
        if name == "friction" and kind == "waves" and value <= 0:
            raise ParameterError(name, value, "> 0 with --kind waves (no stick zone without friction)")
        Q.check(name, value)
        if name == "mismatch":
            from ..brake.reduced.params import small_strain

            small_strain(name, value, 0.1, "the bore radius 0.1 m")

    axes = dict(checked_axis(option, text, point) for option, text in (("--x", x), ("--y", y)))
    map_size("--y", y, *(len(v) for v in axes.values()))
    f, d = axes["friction"], axes["mismatch"]
    with progress_bar(f"{kind} map") as tick:
        if kind == "waves":
            ds = wave_regime_map(f, d, out, omega=omega, modes=modes, workers=workers, progress=tick,
                                 overwrite=overwrite, scheduler=scheduler or "processes")
        else:
            ds = ring_regime_map(f, d, out, omega=omega, workers=workers, progress=tick, overwrite=overwrite,
                                 scheduler=scheduler or "processes")
    name = "wave_regime" if kind == "waves" else "ring_regime"
    counts = {k: int((ds[name] == v).sum()) for k, v in REGIME_CODES.items() if int((ds[name] == v).sum())}
    _emit({"store": str(out), "kind": kind, "points": int(ds[name].size), "counts": counts}, json, "regime map")


@app.command("fem")
def fem_cmd(xi: Xi = None, nu: Nu = 0.3, gamma: Gamma = None, delta: Delta = None, friction: Friction = 0.0,
            inner_radius: Inner = None, outer_radius: Outer = None, young: Young = None, density: Density = None,
            omega: Omega = None, mismatch: Mismatch = None,
            n_theta: Annotated[int, declared(Q["n_theta"], "--n-theta")] = 256,
            n_r: Annotated[int, declared(Q["n_r"], "--n-r")] = 16,
            transits: Annotated[float, declared(Q["transits"], "--transits", "A P-wave transit: 2 pi R / c_p.")] = 100.0,
            beta2: Annotated[float, declared(COMMON["beta2"], "--beta2", "The paper's: 0.9.")] = 0.9,
            mode: SeedWave = None,
            out: RunOut = None,
            xdmf: Annotated[Optional[Path], typer.Option(help=(
                "Write volume snapshots for ParaView to this XDMF file (.xdmf, data in the .h5 of the same name): "
                "displacement, velocity, stress; contact pressure, shear, traction, state. Lengths in R, stresses "
                "in E, times in seconds; meshio.xdmf.TimeSeriesReader reads it."))] = None,
            xdmf_every: XdmfEvery = None,
            overwrite: Overwrite = False, json: Json = False):
    """Finite element model of section 3.1 (scikit-fem): run to the limit regime and classify it."""
    from ..brake.fem import FemScheme, classify_fem, integrate_fem, perturbed_steady, write_xdmf

    overwrite_needs(overwrite, "--out or --xdmf", out, xdmf)
    out = output_path("--out", out, ".nc")
    xdmf, volume_every = xdmf_snapshots(xdmf, xdmf_every, overwrite)
    p = params(xi=xi, nu=nu, gamma=gamma, delta=delta, friction=friction, inner_radius=inner_radius,
               outer_radius=outer_radius, young=young, density=density, omega=omega, mismatch=mismatch)
    if p.delta == 0:  # checked before the run, not after it
        raise ParameterError("delta", p.delta, "> 0 (the limit regime is measured against the steady contact pressure "
                             "p_e, which is zero without interference)", also=("mismatch",))
    initial = perturbed_steady(FemScheme(p, n_theta, n_r, beta2), mode=mode)
    with progress_bar("finite elements") as tick:
        try:
            run = integrate_fem(p, n_theta, n_r, transits=transits, beta2=beta2, initial=initial,
                                checkpoint=out, progress=tick, overwrite=overwrite, volume_every=volume_every)
        except ParameterError as err:  # the library names the interval volume_every
            if err.name != "volume_every":
                raise
            raise ParameterError("--xdmf-every", volume_every, err.allowed) from None
    if xdmf is not None:
        write_xdmf(run, xdmf)
    _emit(classify_fem(run).to_dict(), json, "FE limit regime")


@app.command("campaign")
def campaign_cmd(
        out: Annotated[Path, typer.Option(help="Folder of the campaign's stores (resumed if present).")] =
        Path("results/data/brake-fem-campaign"),
        part: Annotated[str, typer.Option(help="statistics, geometry or all.")] = "all",
        seeds: Annotated[int, declared(COMMON["seeds"], "--seeds", "Per case and mesh (statistics).")] = 16,
        geometry_seeds: Annotated[int, declared(COMMON["geometry_seeds"], "--geometry-seeds",
                                                "Per case, xi and beta2 (geometry).")] = 4,
        workers: Annotated[Optional[int], declared(COMMON["workers"], "--workers", "Default: all cores.")] = None,
        export: Annotated[Optional[Path], typer.Option(help="When done, also write fem_<part>.nc here.")] = None,
        scheduler: Scheduler = None, overwrite: Overwrite = False, json: Json = False):
    """Section 3.1 by finite elements: limit regimes from unseeded starts (about an hour on 2 cores; resumable)."""
    import datetime

    from ..brake.fem import campaign
    from ..figures.brake import campaign_data
    from ..figures.brake.paper import CASES

    if part not in ("statistics", "geometry", "all"):
        raise ParameterError("--part", part, "statistics, geometry or all")
    out = output_folder("--out", out)
    export = None if export is None else output_folder("--export", export)
    out.mkdir(parents=True, exist_ok=True)
    summary = {"out": str(out)}
    where = {"workers": workers, "scheduler": scheduler or "processes"}
    sweeps = {"statistics": lambda tick: campaign.statistics(out / "statistics.zarr", CASES, seeds=seeds,
                                                             progress=tick, overwrite=overwrite, **where),
              "geometry": lambda tick: campaign.geometry(out / "geometry.zarr", CASES, seeds=geometry_seeds,
                                                         progress=tick, overwrite=overwrite, **where)}
    for kind, sweep in sweeps.items():
        if part not in (kind, "all"):
            continue
        with progress_bar(f"FE {kind}") as tick:
            ds = sweep(tick)
        summary[kind] = campaign_data.summary(ds, kind)
        if export is not None:
            summary[kind]["exported"] = str(campaign_data.export(ds.drop_vars("done"), kind, export,
                                                                 datetime.date.today().isoformat()))
    _emit(summary, json, "FE campaign")
