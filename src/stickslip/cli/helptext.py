"""How the command line presents itself: options grouped by topic in every command's help, and
one example per command (`EXAMPLES`, shown under the help and in the docs' CLI reference).

Every module of the command line makes its group with `Typer`, whose commands print their
options under the headings of `PANELS` (an option not named there is a model parameter).
`command_tree` builds the click command of the whole app with the examples attached.
"""

from __future__ import annotations

import functools

import typer
import typer.core

#: Heading -> the parameter names (as in the Python signature) listed under it, in this order
#: after "Model"; an option in no set is a model parameter.
PANELS = {
    "Run and numerics": {"t_end", "transient", "periods", "cycles", "transits", "window", "samples", "rtol", "tol",
                         "max_iter", "max_step", "max_events", "time_step", "n_r", "n_theta", "nodes", "modes", "mode",
                         "kind", "parameter", "start", "stop", "points", "step", "lo", "hi", "x", "y", "from_hopf",
                         "x0", "v0", "v_init", "psi0", "method", "set_", "part", "regime", "quick", "only", "force"},
    "Output": {"json", "out", "plot", "overwrite", "xdmf", "xdmf_every", "export", "list_"},
    "Parallel runs and sweeps": {"workers", "scheduler", "store", "sweep", "seeds", "geometry_seeds"},
    "Other": {"help", "version", "install_completion", "show_completion"},
}
MODEL = "Model"
ARGUMENTS = "Arguments"

#: Command path -> one command line that runs as written (from a clone of the repository where
#: it names a file of ``examples/``); the tests parse every one against its command.
EXAMPLES = {
    "reproduce": "stickslip reproduce --quick --only fig2 --out results",
    "sweep": "stickslip sweep examples/sweep/oscillator_cycles.toml --out cycles.zarr --workers 2",
    "oscillator cycle": "stickslip oscillator cycle --mass 1 --stiffness 1 --normal-force 1 --belt-speed 0.2 "
                        "--fs 0.6 --fd 0.4 --json",
    "oscillator simulate": "stickslip oscillator simulate --mass 1 --stiffness 1 --normal-force 1 --belt-speed 0.2 "
                           "--fs 0.6 --fd 0.4 --t-end 50 --x0 -1.5 --out run.nc --plot run.svg",
    "oscillator stability": "stickslip oscillator stability --mass 1 --stiffness 1 --normal-force 1 --belt-speed 0.2 "
                            "--fs 0.6 --fd 0.4 --law stribeck --vs 0.1 --damping 0.05",
    "oscillator continue": "stickslip oscillator continue --mass 1 --stiffness 1 --normal-force 1 --belt-speed 0.2 "
                           "--fs 0.6 --fd 0.4 --stop 2 --plot branch.pdf",
    "oscillator map": "stickslip oscillator map --mass 1 --stiffness 1 --normal-force 1 --fs 0.6 --fd 0.4 "
                      "--law stribeck --vs 0.1 --x belt_speed=0.05:1.5:8 --y damping=0.01:0.3:5 --out map.zarr",
    "brake coefficients": "stickslip brake coefficients --xi 1.5 --nu 0.3 --gamma 1e-6 --json",
    "brake steady": "stickslip brake steady --mismatch 1e-4 --friction 0.7 --json",
    "brake stability": "stickslip brake stability --xi 1.5 --nu 0.3 --gamma 1e-6 --delta 0.004 --friction 0.2 "
                       "--wave-numbers 1-20 --json",
    "brake integrate": "stickslip brake integrate --omega 50 --mismatch 1e-4 --friction 0.7 --transits 200 "
                       "--out run.nc",
    "brake wave": "stickslip brake wave --omega 50 --mismatch 1e-4 --friction 0.7 --wave-number 8 --json",
    "brake spectrum": "stickslip brake spectrum --omega 100 --mismatch 1e-4 --friction 0.2 --wave-number 4 "
                      "--nodes 64,128 --json",
    "brake continue": "stickslip brake continue --omega 50 --mismatch 1e-5 --friction 0.7 --wave-number 4 "
                      "--stop 2.5e-6 --out branch.nc",
    "brake map": "stickslip brake map --out waves.zarr --kind waves --x friction=0.1:2:6 --y mismatch=1e-7:1e-4:5:log",
    "brake fem": "stickslip brake fem --omega 50 --mismatch 1e-4 --friction 0.7 --n-theta 128 --n-r 8 "
                 "--transits 100 --out fem.nc --xdmf fem.xdmf",
    "brake campaign": "stickslip brake campaign --workers 2",
    "halfspace inverse": "stickslip halfspace inverse --b 2 --c -0.7 --v-star 0.001 --nu 0.3 --mu 0.5 --json",
    "halfspace direct": "stickslip halfspace direct --T 9.52e-4 --v 3.514e-3 --v-star 0.001 --nu 0.3 --mu 0.5 --json",
    "halfspace fields": "stickslip halfspace fields --b 11.358 --c -0.7 --v-star 0.001 --plot fig14.png "
                        "--out fields.nc",
    "halfspace run": "stickslip halfspace run --out run.nc --elements 256 --plot run.png --json",
    "halfspace fault": "stickslip halfspace fault --out fault.nc --years 300 --plot fault.png --json",
    "fem steady": "stickslip fem steady examples/block_on_belt/block.toml --out steady.nc",
    "fem cea": "stickslip fem cea examples/pad_on_disc/pad.toml --sweep friction=0:0.8:41 --store sweep.zarr "
               "--plot map.png --json",
    "fem mesh": "stickslip fem mesh brake.step pad.msh --size 0.004 --order 2 --solid lining --solid backplate "
                "--face friction=z:0.012 --face piston=z:0.027 --json",
    "fem map": "stickslip fem map examples/pad_on_disc/pad.toml --over surface.omega=10:50:5 --friction 0:0.8:17 "
               "--store map.zarr --plot map.png --json",
    "fem run": "stickslip fem run examples/block_on_belt/block.toml --start stick --transits 2000 --window 1000 "
               "--out run.nc --xdmf run.xdmf",
    "system simulate": "stickslip system simulate examples/two_blocks/two_blocks.toml --t-end 20 --x0 0.1,0 "
                       "--out run.nc",
    "system cycle": "stickslip system cycle examples/two_blocks/two_blocks.toml --transient 60 --json",
    "system stability": "stickslip system stability examples/hoffmann/hoffmann.toml --json",
    "system continue": "stickslip system continue examples/two_blocks/two_blocks.toml "
                       "--parameter contact[0].surface_speed --stop 0.12 --points 8 --x0 0.1,0",
    "rsf slide": "stickslip rsf slide --a 0.01 --b 0.015 --dc 1e-5 --normal-stress 1e7 --stiffness 1.5e10 "
                 "--t-end 160 --history 0:1e-6,20:1e-5,60:0,100:1e-6 --out shs.nc",
    "rsf stability": "stickslip rsf stability --a 0.01 --b 0.015 --dc 1e-5 --normal-stress 1e7 --stiffness 1.5e10 "
                     "--load-velocity 1e-6",
    "rsf cycle": "stickslip rsf cycle --a 0.01 --b 0.015 --dc 1e-5 --normal-stress 1e7 --stiffness 4.5e9 "
                 "--mass 1e9 --load-velocity 1e-6 --tol 1e-4 --json",
    "rsf fit": "stickslip rsf fit examples/rsf/velocity_step.csv --json",
}


def panel_of(name: str) -> str:
    """The heading a parameter's option is listed under."""
    return next((heading for heading, names in PANELS.items() if name in names), MODEL)


def help_sections(command, ctx) -> dict[str, list[tuple[str, str]]]:
    """Heading -> the ``(name, help)`` records of ``command``'s parameters listed under it: the
    arguments, then the options by `panel_of`, in the order of the headings (some may be empty)."""
    sections: dict[str, list] = {ARGUMENTS: [], MODEL: []} | {heading: [] for heading in PANELS}
    for param in command.get_params(ctx):
        record = param.get_help_record(ctx)
        if record is not None:
            sections[ARGUMENTS if param.param_type_name == "argument" else panel_of(param.name)].append(record)
    return sections


class SectionedCommand(typer.core.TyperCommand):
    """A command whose help lists its arguments, then its options under the headings of `PANELS`."""

    def format_options(self, ctx, formatter) -> None:
        for heading, rows in help_sections(self, ctx).items():
            if rows:
                with formatter.section(heading):
                    formatter.write_dl(rows)


class Typer(typer.Typer):
    """`typer.Typer` whose commands group their options (`SectionedCommand`)."""

    def command(self, *args, **kwargs):
        kwargs.setdefault("cls", SectionedCommand)
        return super().command(*args, **kwargs)


def example_epilog(line: str) -> str:
    """The epilog of a command: its example, kept as written (click's ``\\b`` stops rewrapping)."""
    return f"Example:\n\n\b\n  {line}"


@functools.lru_cache(maxsize=None)
def command_tree(app: typer.Typer):
    """The click command of ``app``, each command carrying its example as its epilog; built once
    per process (typer's conversion of the signatures costs about 0.1 s) and reused by every call
    of `stickslip.cli.run`: click's commands keep no state between calls (each call makes its
    own context)."""
    root = typer.main.get_command(app)

    def attach(command, path: tuple[str, ...]) -> None:
        for name, sub in getattr(command, "commands", {}).items():
            attach(sub, path + (name,))
        line = EXAMPLES.get(" ".join(path))
        if line is not None:
            command.epilog = example_epilog(line)

    attach(root, ())
    return root
