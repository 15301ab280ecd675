"""The command-line fuzzing harness of issue 9.

Every numeric option of every command, one value at a time, on an otherwise valid and
cheap invocation (`BASE`). A trial runs in a forked child with a time limit: a hang inside
compiled code (numba, LAPACK) cannot be interrupted by a signal handler in the same
process, a child can be killed. Forking after the package is imported and its kernels
compiled keeps a trial at a few milliseconds of overhead.

`problems(trial, option, folder)` states the contract: exit 0 only with finite numbers on
stdout (JSON) and in every file written, and nothing on stderr; otherwise exit 1 (no
solution) or 2 (bad input) with nothing on stdout and exactly one line on stderr, which
for exit 2 names the option as typed; never exit 3, a traceback, a signal or a hang.

``python -m tests.fuzz_harness`` runs the whole battery and prints the counts of the
closing note (trials, exit-3 cases, silent non-finite successes, hangs, messages that do
not name the option).
"""

from __future__ import annotations

import collections
import contextlib
import dataclasses
import itertools
import json
import math
import os
import pathlib
import signal
import re
import sys
import tempfile
import time
import typing

import numpy as np

OSC = ["--mass", "1", "--stiffness", "1", "--normal-force", "1", "--belt-speed", "0.2", "--fs", "0.6", "--fd", "0.4"]
#: The example system of two blocks on two belts (`stickslip system ...`).
SYSTEM_FILE = str(pathlib.Path(__file__).resolve().parents[1] / "examples" / "two_blocks" / "two_blocks.toml")
#: A system with a harmonic force (a friction damper).
DAMPER_FILE = str(pathlib.Path(__file__).resolve().parents[1] / "examples" / "friction_damper" / "friction_damper.toml")
RSF = ["--a", "0.01", "--b", "0.015", "--dc", "1e-5", "--normal-stress", "1e7"]
#: A laboratory record (synthetic, examples/rsf/make_record.py) for `rsf fit`.
RECORD_FILE = str(pathlib.Path(__file__).resolve().parents[1] / "examples" / "rsf" / "velocity_step.csv")
BRAKE = ["--omega", "50", "--mismatch", "1e-4", "--friction", "0.7"]
#: A valid, fast invocation of every command ({tmp} is a fresh folder).
BASE = {
    "oscillator cycle": OSC,
    "oscillator simulate": OSC + ["--t-end", "5"],
    "oscillator stability": OSC,
    "oscillator continue": OSC + ["--stop", "0.3"],
    "oscillator map": OSC[:6] + OSC[8:] + ["--x", "belt_speed=0.2:0.3:2", "--y", "damping=0.01:0.02:2", "--out", "{tmp}/m.zarr",
                             "--workers", "1"],
    "brake coefficients": ["--xi", "1.5", "--nu", "0.3", "--gamma", "1e-6"],
    "brake steady": ["--xi", "1.5", "--nu", "0.3", "--delta", "0.004", "--friction", "0.2"],
    "brake stability": ["--xi", "1.5", "--nu", "0.3", "--gamma", "1e-6", "--delta", "0.004", "--friction", "0.2",
                        "--wave-numbers", "1-3"],
    "brake integrate": BRAKE + ["--nodes", "32", "--transits", "1", "--out", "{tmp}/i.nc"],
    "brake wave": BRAKE + ["--wave-number", "8", "--out", "{tmp}/w.nc"],
    "brake spectrum": ["--omega", "100", "--mismatch", "1e-4", "--friction", "0.2", "--nodes", "16"],
    "brake continue": ["--omega", "50", "--mismatch", "1e-5", "--friction", "0.7", "--wave-number", "4", "--stop", "9e-6",
                       "--points", "3", "--out", "{tmp}/b.nc"],
    "brake map": ["--out", "{tmp}/w.zarr", "--x", "friction=0.2:0.7:2", "--y", "mismatch=1e-5:1e-4:2:log",
                  "--workers", "1"],
    "brake fem": BRAKE + ["--n-theta", "16", "--n-r", "1", "--transits", "1", "--out", "{tmp}/f.nc", "--xdmf",
                          "{tmp}/f.xdmf"],
    "brake campaign": ["--out", "{tmp}/c", "--seeds", "1"],
    "halfspace inverse": ["--b", "2", "--c", "-0.7", "--v-star", "0.001"],
    "halfspace direct": ["--T", "9.52e-4", "--v", "3.514e-3", "--v-star", "0.001"],
    "halfspace fields": ["--b", "11.358", "--c", "-0.7", "--v-star", "0.001", "--points", "101", "--out", "{tmp}/h.nc"],
    "halfspace run": ["--elements", "16", "--duration", "0.5", "--out", "{tmp}/hr.nc"],
    "halfspace fault": ["--elements", "16", "--years", "1", "--out", "{tmp}/hf.nc"],
    "reproduce": ["--only", "fig2", "--out", "{tmp}/r"],
    "fem run": ["{config}", "--transits", "2", "--out", "{tmp}/g.nc"],
    "fem cea": ["{config}"],
    "fem steady": ["{config}"],
    "fem mesh": ["{step}", "{tmp}/m.msh", "--size", "0.03"],
    "fem map": ["{config}", "--over", "young=1e10:2e10:2", "--friction", "0:0.01:2", "--store", "{tmp}/fm.zarr",
                "--workers", "1"],
    "sweep": ["{sweep}", "--out", "{tmp}/s.zarr", "--workers", "1"],
    "system simulate": [SYSTEM_FILE, "--t-end", "5", "--out", "{tmp}/y.nc"],
    "system cycle": [SYSTEM_FILE, "--transient", "30", "--out", "{tmp}/yc.nc"],
    "system stability": [SYSTEM_FILE, "--out", "{tmp}/ys.nc"],
    "system continue": [SYSTEM_FILE, "--parameter", "contact[0].surface_speed", "--stop", "0.25", "--points", "3",
                        "--transient", "30", "--out", "{tmp}/yb.nc"],
    "rsf slide": RSF + ["--stiffness", "1e10", "--t-end", "30", "--history", "0:1e-6,10:1e-5", "--out", "{tmp}/r.nc"],
    "rsf stability": RSF + ["--stiffness", "1e10", "--load-velocity", "1e-6"],
    # a stiffness just below the critical 5e9 Pa/m: a small cycle that settles in 3 s (8 s at 3e9)
    "rsf cycle": RSF + ["--stiffness", "4.9e9", "--mass", "1e9", "--load-velocity", "1e-6", "--tol", "1e-3",
                        "--cycles", "2"],
    "rsf fit": [RECORD_FILE],
}
_CONFIG: list[str] = []


#: A status line of a long job without a terminal (`stickslip.cli.status`): a loop's progress, or the phase.
_PROGRESS = re.compile(r"^[\w .-]+: (\S+ of \S+ done(, [\d.]+ (s|min|h) so far)?(, about .+ left)?|.+, [\d.]+ (s|min|h) so far"
                       r"|started \(figure \d+ of \d+, .+ elapsed\): .+"  # reproduce's figures
                       r"|done in [\d.]+ s( \(from its checkpoint\))?: (?P<n>\d+) of (?P=n) checks pass)$")


#: The same, for the modules that judge trials.
PROGRESS = _PROGRESS


def example_sweep() -> str:
    """A sweep config of two cheap points (oscillator cycles), written once per process."""
    if not _SWEEP:
        import atexit
        import shutil

        folder = pathlib.Path(tempfile.mkdtemp(prefix="stickslip-fuzz-sweep-"))
        atexit.register(shutil.rmtree, folder, ignore_errors=True)
        (folder / "sweep.toml").write_text(
            'command = "oscillator cycle"\noutputs = ["period"]\n[fixed]\nmass = 1.0\nstiffness = 1.0\n'
            'normal_force = 1.0\nfd = 0.3\nfs = 0.5\n[axes]\nbelt_speed = [0.1, 0.2]\n')
        _SWEEP.append(str(folder / "sweep.toml"))
    return _SWEEP[0]


_SWEEP: list[str] = []


def example_step() -> str:
    """The brake example's STEP (three solids, in millimetres), written once per process."""
    if not _STEP:
        import atexit
        import shutil
        import subprocess

        folder = pathlib.Path(tempfile.mkdtemp(prefix="stickslip-fuzz-step-"))
        atexit.register(shutil.rmtree, folder, ignore_errors=True)
        example = pathlib.Path(__file__).resolve().parents[1] / "examples" / "brake3d"
        subprocess.run([sys.executable, "-c", f"import sys; sys.path.insert(0, {str(example)!r}); import brake; "
                        "brake.write_step('brake.step')"], cwd=folder, check=True, capture_output=True)
        _STEP.append(str(folder / "brake.step"))
    return _STEP[0]


_STEP: list = []


def example_config() -> str:
    """The pad-on-disc example (coarse mesh) in a folder of its own, made once per process."""
    if not _CONFIG:
        import atexit
        import shutil
        import subprocess

        root = pathlib.Path(__file__).resolve().parents[1] / "examples" / "pad_on_disc"
        folder = pathlib.Path(tempfile.mkdtemp(prefix="stickslip-fuzz-"))
        atexit.register(shutil.rmtree, folder, ignore_errors=True)
        shutil.copy(root / "pad.toml", folder)
        subprocess.run([sys.executable, str(root / "mesh.py"), "pad.msh", "0.004"], cwd=folder, check=True)
        _CONFIG.append(str(folder / "pad.toml"))
    return _CONFIG[0]
#: Options that set the same quantity another way: varying one drops the others from the
#: base invocation (and ``--omega`` comes in when the material sets gamma).
SAME_QUANTITY = [("--xi", "--inner-radius", "--outer-radius"), ("--gamma", "--omega", "--young", "--density"),
                 ("--delta", "--mismatch")]
NEVER_NUMBERS = ["nan", "inf", "-inf", "abc", ""]
EXTREMES = ["0", "-1", "1e300", "-1e300", "1e-300", "1e-320"]  # the last one subnormal


def special_numbers(q) -> list:
    """The values a declaration's range makes special: each finite end, just beyond it (or, for an
    end left out, the end itself and just inside), zero, +-1, the far ends of the doubles
    (+-1e300, 1e-300), a subnormal (1e-320) and, for a count, a huge one (10**20)."""
    out = [0.0, -1.0, 1.0, 1e300, -1e300, 1e-300, 1e-320]
    r = q.range
    if r is not None:
        for end, open_, outward in ((r.lo, r.lo_open, -math.inf), (r.hi, r.hi_open, math.inf)):
            if not math.isfinite(end):
                continue
            if q.integer:
                out += [end, end + math.copysign(1, outward)]
            else:
                out += [end, math.nextafter(end, outward), math.nextafter(end, -outward)]
    if q.integer:
        out += [10**20, 2**63]
    return list(dict.fromkeys(out))


def typed(value, integer: bool) -> str:
    """A value as a user types it on the command line."""
    if integer and isinstance(value, (int, float)) and math.isfinite(value) and float(value).is_integer():
        return str(int(value))
    return repr(float(value)) if isinstance(value, float) else str(value)


def cli_params():
    """``(command, param, hint)`` of every parameter of every command of the command line, with its
    type hint (``Annotated[...]`` where the option reads a declaration)."""
    import typer.main

    from stickslip.cli import app

    def walk(cmd, path):
        if hasattr(cmd, "commands"):
            for name, sub in cmd.commands.items():
                yield from walk(sub, path + [name])
            return
        hints = typing.get_type_hints(cmd.callback, include_extras=True)
        for param in cmd.params:
            yield " ".join(path), param, hints.get(param.name)

    yield from walk(typer.main.get_command(app), [])


def base_type(hint):
    """The type of an option's hint: the first of an ``Optional``, under ``Annotated``."""
    base = typing.get_args(hint)[0] if typing.get_origin(hint) is typing.Annotated else hint
    return ([a for a in typing.get_args(base) if a is not type(None)] or [base])[0]


def declared_options() -> list[tuple[str, str, object]]:
    """``(command, option, declaration)`` of every numeric option that reads a declaration."""
    out = []
    for command, param, hint in cli_params():
        if typing.get_origin(hint) is typing.Annotated:
            q = getattr(hint.__metadata__[0], "quantity", None)
            if q is not None and q.range is not None:
                out.append((command, param.opts[0], q))
    return out


def options_typed(*types) -> list[tuple[str, str]]:
    """``(command, option)`` for every option whose type (first of an Optional) is one of ``types``
    (an argument is an input, a config file, not an option to fuzz here)."""
    return [(command, param.opts[0]) for command, param, hint in cli_params()
            if getattr(param, "param_type_name", "option") == "option" and base_type(hint) in types]


#: Every numeric option, and every option that is a path (outputs, checkpoints, stores).
OPTIONS = options_typed(float, int)
PATH_OPTIONS = options_typed(pathlib.Path)
#: Bad places to write: ``{tmp}`` is a fresh folder holding a file ``file``; /proc is a
#: place nobody can create files in, root included (a read-only folder is writable by root).
BAD_PATHS = {"a folder": "{tmp}", "a missing folder": "{tmp}/missing/x{suffix}", "an unwritable place": "/proc/x{suffix}",
             "under a file": "{tmp}/file/x{suffix}", "another suffix": "{tmp}/x.txt",
             "a name too long": "{tmp}/" + "n" * 300 + "{suffix}"}
_SUFFIX = {"--plot": ".png", "--checkpoint": ".nc", "--out": ".nc", "--export": "", "--xdmf": ".xdmf", "--store": ".zarr",
           "--uff": ".uff"}
SUFFIX = _SUFFIX  # each output option's suffix, for the modules that make its paths
#: Options that name a folder to create (any name, parents made): only unwritable places are bad.
FOLDERS = {("brake campaign", "--out"), ("brake campaign", "--export"), ("reproduce", "--out")}


def bad_places(command: str, option: str) -> list[str]:
    """The kinds of `BAD_PATHS` that are wrong for this option."""
    if (command, option) in FOLDERS:
        return ["an unwritable place", "under a file", "a name too long"]
    if option == "--store" or any(a == option and b.endswith(".zarr") for a, b in zip(BASE[command], BASE[command][1:])):
        return [k for k in BAD_PATHS if k != "a missing folder"]  # a store is made with its parents
    return list(BAD_PATHS)


def path_args(command: str, option: str, kind: str, tmp) -> list[str]:
    """The base invocation with ``option`` pointing to a bad place of ``kind``."""
    tmp = pathlib.Path(tmp)
    (tmp / "file").write_text("")
    folder_option = any(a == option and b.endswith(".zarr") for a, b in zip(BASE[command], BASE[command][1:]))
    suffix = ".zarr" if folder_option else ("" if command in ("reproduce", "brake campaign") else _SUFFIX[option])
    value = BAD_PATHS[kind].format(tmp=tmp, suffix=suffix)
    return args_for(command, option, value, tmp)


def args_for(command: str, option: str, value: str, tmp) -> list[str]:
    """The base invocation of ``command`` with ``option value`` (and ``--json``)."""
    base = [a.replace("{tmp}", str(tmp)) for a in BASE[command]]
    lead = list(itertools.takewhile(lambda a: not a.startswith("--"), base))
    positional = [example_config() if a == "{config}" else example_sweep() if a == "{sweep}" else
                  example_step() if a == "{step}" else a for a in lead]
    base = base[len(positional):]
    drop = {option}
    for group in SAME_QUANTITY:
        if option in group:
            drop |= set(group)
    pairs = [(base[i], base[i + 1]) for i in range(0, len(base), 2)]
    pairs = [(k, v) for k, v in pairs if k not in drop]
    if option in ("--young", "--density") and command.startswith("brake"):
        pairs.append(("--omega", "50"))
    return command.split() + positional + [x for kv in pairs for x in kv] + [option, value, "--json"]


@dataclasses.dataclass(frozen=True)
class Trial:
    args: tuple[str, ...]
    code: int | str  # an exit code, "hang" or "killed by signal N"
    out: str
    err: str
    seconds: float

    @property
    def hang(self) -> bool:
        return self.code == "hang"


#: Commands that write Zarr stores or start Dask: zarr keeps an event-loop thread, which a forked
#: child does not inherit (the child would wait on it forever), so these run in a fresh interpreter
#: ("sweep" was forked: CI saw 'sweep --workers 1' wait 300 s after the dashboard line, 2026-11-26).
FRESH = ("oscillator map", "brake map", "brake campaign", "reproduce", "sweep")


_WARM: set[str] = set()


def _warm(args) -> None:
    """What a trial's child inherits, made once in this process: the command tree (0.1 s to
    build) and, for a command that is not `FRESH`, its modules and compiled kernels, by running its
    base invocation here (a child would otherwise import and load them again: 0.1 to 1.5 s a trial)."""
    from stickslip.cli import app, run
    from stickslip.cli.helptext import command_tree

    command_tree(app)
    command = next((c for c in sorted(BASE, key=len, reverse=True) if list(args[:len(c.split())]) == c.split()), None)
    if command is None or command in _WARM or command.startswith(FRESH):
        return
    _WARM.add(command)
    import contextlib
    import io

    with tempfile.TemporaryDirectory(prefix="stickslip-warm-") as tmp, \
            contextlib.redirect_stdout(io.StringIO()), contextlib.redirect_stderr(io.StringIO()):
        base = [a.replace("{tmp}", tmp) for a in BASE[command]]
        base = [example_config() if a == "{config}" else example_sweep() if a == "{sweep}" else a for a in base]
        run(command.split() + base)


def trial(args: list[str], timeout: float = 60.0) -> Trial:
    """Run ``stickslip ARGS`` in a forked child (a fresh interpreter for `FRESH` commands);
    kill it after ``timeout`` seconds."""
    from stickslip.cli import run

    _warm(args)

    if " ".join(args).startswith(FRESH):
        import subprocess

        start = time.perf_counter()
        try:
            proc = subprocess.run([sys.executable, "-m", "stickslip", *args], capture_output=True, text=True,
                                  timeout=timeout)
        except subprocess.TimeoutExpired as err:
            return Trial(tuple(args), "hang", err.stdout or "", err.stderr or "", time.perf_counter() - start)
        code = proc.returncode if proc.returncode >= 0 else f"killed by signal {-proc.returncode}"
        return Trial(tuple(args), code, proc.stdout, proc.stderr, time.perf_counter() - start)

    with tempfile.TemporaryFile("w+") as out, tempfile.TemporaryFile("w+") as err:
        start = time.perf_counter()
        pid = os.fork()
        if pid == 0:  # the child: never returns into pytest
            code = 3
            try:
                os.dup2(out.fileno(), 1)
                os.dup2(err.fileno(), 2)
                # under pytest sys.stdout/err are capture objects, not the descriptors
                sys.stdout = open(1, "w", closefd=False)
                sys.stderr = open(2, "w", closefd=False)
                code = run(list(args))
            finally:
                sys.stdout.flush()
                sys.stderr.flush()
                os._exit(code if isinstance(code, int) else 3)
        code: int | str = "hang"
        while time.perf_counter() - start < timeout:
            done, status = os.waitpid(pid, os.WNOHANG)
            if done:
                code = os.waitstatus_to_exitcode(status)
                if code < 0:
                    code = f"killed by signal {-code}"
                break
            time.sleep(0.002)
        else:
            os.kill(pid, signal.SIGKILL)
            os.waitpid(pid, 0)
        seconds = time.perf_counter() - start
        out.seek(0)
        err.seek(0)
        return Trial(tuple(args), code, out.read(), err.read(), seconds)


def json_finite(text: str) -> bool:
    """Every number in a JSON document is finite (``NaN``/``Infinity`` parse as floats)."""
    def walk(v):
        if isinstance(v, dict):
            return all(walk(x) for x in v.values())
        if isinstance(v, list):
            return all(walk(x) for x in v)
        return not isinstance(v, float) or math.isfinite(v)
    return walk(json.loads(text))


def files_finite(folder) -> list[str]:
    """Files under ``folder`` (netCDF, Zarr, XDMF, CSV, JSON) holding a non-finite number that
    their metadata does not explain (a variable may hold NaN if its ``comment`` says where)."""

    import xarray as xr

    bad = []
    for path in sorted(pathlib.Path(folder).rglob("*")):
        if path.suffix in (".nc", ".zarr") and (path.is_file() or (path / ".zattrs").exists()
                                                 or (path / "zarr.json").exists()):
            opened = xr.open_zarr(path, consolidated=False) if path.suffix == ".zarr" else xr.open_dataset(path)
            with opened as ds:
                for name, var in {**ds.data_vars, **ds.coords}.items():
                    values = np.asarray(var.values)
                    if values.dtype.kind == "f" and not np.isfinite(values).all():
                        if "NaN" not in var.attrs.get("comment", ""):
                            bad.append(f"{path.name}:{name}")
        elif path.suffix == ".xdmf" and path.is_file():  # ParaView output: every array of every time step
            import meshio

            with meshio.xdmf.TimeSeriesReader(path) as reader:
                arrays = list(reader.read_points_cells()[:1])
                for k in range(reader.num_steps):
                    t, point_data, cell_data = reader.read_data(k)
                    arrays += [np.asarray(t), *point_data.values(), *(a for v in cell_data.values() for a in v)]
            if not all(np.isfinite(a).all() for a in arrays):
                bad.append(path.name)
        elif path.suffix == ".json" and path.is_file():
            if not json_finite(path.read_text()):
                bad.append(path.name)
        elif path.suffix == ".csv" and path.is_file():
            text = path.read_text().lower()
            if "nan" in text or "inf" in text:
                bad.append(path.name)
    return bad


def problems(t: Trial, option: str, folder) -> list[str]:
    """How a trial breaks the contract (empty: it keeps it)."""
    if t.hang:
        return ["hang"]
    if t.code not in (0, 1, 2):
        return [f"exit {t.code}"]
    found = []
    if "Traceback" in t.err:
        found.append("traceback")
    if t.code == 0:
        # on success stderr stays empty, but for what a long job owes its user: where its cluster's
        # dashboard is, and (without a terminal, every minute) how far it is (issue 25); and that its law
        # is ill-posed, or its grid too coarse or its period too short for its law, which an interface run
        # must say (issue 46)
        owed = ("warning: ill-posed: ", "warning: unresolved: ", "warning: too short: ")
        if [line for line in t.err.splitlines() if not line.startswith("Dask dashboard: http")
                and not line.startswith(owed) and not _PROGRESS.match(line)]:
            found.append("stderr on success")
        try:
            finite = json_finite(t.out)
        except ValueError:
            finite = False
        bad = files_finite(folder)
        if not finite or bad:
            found.append("non-finite success")
    else:  # one line saying why, after the status lines a job that ran for minutes wrote on its way
        said = [line for line in t.err.splitlines() if not _PROGRESS.match(line)]
        if t.out or len(said) != 1 or not t.err.endswith(said[-1] + "\n"):
            found.append("not one line")
        if t.code == 2 and option not in t.err:
            found.append("option not named")
    return found


def battery(values=EXTREMES, options=None, timeout: float = 120.0, log=None):
    """Every ``(command, option)`` with every value: a list of ``(args, trial, problems)``."""
    out = []
    for command, option in (OPTIONS if options is None else options):
        for value in values:
            with tempfile.TemporaryDirectory() as tmp:
                args = args_for(command, option, value, tmp)
                t = trial(args, timeout)
                found = problems(t, option, tmp)
            out.append((args, t, found))
            if log:
                print(f"{t.code!s:>4} {t.seconds:6.1f}s {' '.join(args)}  {found or ''}  {t.err.strip()[:200]}",
                      file=log, flush=True)
    return out


def path_battery(log=None, timeout: float = 120.0):
    """Every path option with every kind of bad place: a list of ``(args, trial, problems)``."""
    out = []
    for command, option in PATH_OPTIONS:
        for kind in bad_places(command, option):
            with tempfile.TemporaryDirectory() as tmp:
                args = path_args(command, option, kind, tmp)
                t = trial(args, timeout)
                found = problems(t, option, tmp)
                if t.code == 0 and kind != "another suffix":
                    found.append("wrote to a bad place")
            out.append((args, t, found))
            if log:
                print(f"{t.code!s:>4} {t.seconds:6.1f}s {' '.join(args)}  {found or ''}  {t.err.strip()[:200]}",
                      file=log, flush=True)
    return out


#: Computations of hours by design (the FE campaign runs for an hour or more, resumable and with
#: its progress shown; a map's workers only change how fast it goes): their options are tried
#: with the values their declarations refuse only, which must be refused at once.
LONG_BY_DESIGN = {"brake campaign", ("oscillator map", "--workers"), ("brake map", "--workers"),
                  ("fem map", "--workers"), "halfspace fault"}  # earthquake cycles: minutes to hours at the ends of their ranges (1e6 years,
#                                     a = 1e-8, D_c = 1e-12 m, ...), resumable and with their progress shown
#: Sizes whose upper end is a run the work budget allows (1e13 dof-steps, about 4 hours: 16 x 4096
#: elements make a step a thousand times shorter; a branch of 1e5 waves, 190 s idle and past the
#: 300-s limit on a loaded machine): tried up to half their upper end.
LONG_AT_THE_TOP = {("brake fem", "--n-r"), ("brake fem", "--n-theta"), ("brake integrate", "--nodes"),
                   ("brake continue", "--points")}


def declared_cases() -> list[tuple[str, str, str]]:
    """``(command, option, value as typed)``: every special value of every declared option."""
    out = []
    for command, option, q in declared_options():
        if command not in BASE:
            continue
        for value in special_numbers(q):
            long = command in LONG_BY_DESIGN or (command, option) in LONG_BY_DESIGN
            inside = value in q.range and (not q.integer or float(value).is_integer())
            if long and inside or (command, option) in LONG_AT_THE_TOP and inside and value > q.range.hi / 2:
                continue
            out.append((command, option, typed(value, q.integer)))
    return out


def declared_battery(cases=None, timeout: float = 300.0, log=None):
    """The trials of `declared_cases`: a list of ``(args, trial, problems)``."""
    out = []
    for command, option, value in (declared_cases() if cases is None else cases):
        with tempfile.TemporaryDirectory() as tmp:
            args = args_for(command, option, value, tmp)
            t = trial(args, timeout)
            found = problems(t, option, tmp)
        out.append((args, t, found))
        if log:
            print(f"{t.code!s:>4} {t.seconds:6.1f}s {' '.join(args)}  {found or ''}  {t.err.strip()[:200]}",
                  file=log, flush=True)
    return out


@dataclasses.dataclass(frozen=True)
class Call:
    """What one call of the Python API did: ``outcome`` is ``ok``, an exception's type name, or
    ``hang``."""
    outcome: str
    message: str
    seconds: float


#: The exceptions a public function may raise on bad input or a problem without answer.
ALLOWED = {"ok", "ParameterError", "NoSolutionError"}


def api_call(func, kwargs: dict, timeout: float = 120.0) -> Call:
    """``func(**kwargs)`` in a forked child with a time limit: what it returned or raised."""
    import warnings

    read, write = os.pipe()
    start = time.perf_counter()
    pid = os.fork()
    if pid == 0:
        os.close(read)
        outcome, message = "ok", ""
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                func(**kwargs)
        except BaseException as err:  # noqa: BLE001 - what the parent judges
            outcome, message = type(err).__name__, str(err)[:300]
        os.write(write, json.dumps([outcome, message]).encode())
        os._exit(0)
    os.close(write)
    outcome, message = "hang", ""
    while time.perf_counter() - start < timeout:
        done, _ = os.waitpid(pid, os.WNOHANG)
        if done:
            data = b""
            while chunk := os.read(read, 65536):
                data += chunk
            outcome, message = json.loads(data) if data else ("killed", "")
            break
        time.sleep(0.002)
    else:
        os.kill(pid, signal.SIGKILL)
        os.waitpid(pid, 0)
    os.close(read)
    return Call(outcome, message, time.perf_counter() - start)


def api_values(name: str, param: str) -> list:
    """The bad values of the API battery (`tests.test_fuzz_api.BAD`) and the special values of the
    parameter's declaration (in its model's domain), if it has one."""
    from stickslip.quantities import declared

    from .test_fuzz_api import BAD, DOMAIN

    q = declared(param, DOMAIN.get(name, "common"))
    specials = special_numbers(q) if q is not None and q.range is not None else []
    if (name, param) in API_LONG_AT_THE_TOP:  # legal computations of an hour or more at the top of the range
        specials = [v for v in specials if not (v in q.range and v > q.range.hi / 2)]
    return BAD + [v for v in specials if v not in BAD]


#: Parameters whose upper end is a computation the budgets allow but that takes an hour or more
#: (a branch of 1e5 waves, an annulus of 16 x 4096 elements): tried up to half their upper end.
API_LONG_AT_THE_TOP = {("continue_waves", "num"), ("travelling_wave", "num"), ("integrate_fem", "n_r"), ("integrate_fem", "n_theta"),
                       ("integrate", "nodes"), ("FemScheme", "n_r"), ("FemScheme", "n_theta"), ("RingScheme", "nodes"),
                       ("perturbed_steady", "nodes"), ("continue_system", "points")}


def api_battery(timeout: float = 120.0, log=None, only=None):
    """Every parameter of every call of `tests.test_fuzz_api.CALLS` with `api_values` (``only``:
    one ``(name, param)``)."""
    from .test_fuzz_api import CALLS

    out = []
    for name, (func, params) in CALLS.items():
        for param in params:
            if only is not None and (name, param) != tuple(only):
                continue
            for value in api_values(name, param):
                with tempfile.TemporaryDirectory() as tmp:
                    cwd = os.getcwd()
                    os.chdir(tmp)  # a value such as "x" is a valid relative store path: kept out of the tree
                    try:
                        c = api_call(func, {param: value}, timeout)
                    finally:
                        os.chdir(cwd)
                out.append(((name, param, repr(value)[:40]), c))
                if log:
                    print(f"{c.outcome:>16} {c.seconds:6.1f}s {name}({param}={value!r:.40})  {c.message[:160]}",
                          file=log, flush=True)
    return out


def drawn_cases(per_option: int = 8, seed: int = 20261125) -> list[tuple[str, str, str]]:
    """``per_option`` values drawn (seeded, for the record) inside and around each declared range
    of the options whose large values are not sizes: uniform in the value and in its logarithm,
    and beyond the range."""
    import random

    rng = random.Random(seed)
    out = []
    for command, option, q in declared_options():
        if command not in BASE or q.integer or command in LONG_BY_DESIGN or option in DRAWN_LEFT_OUT:
            continue
        lo = q.range.lo if math.isfinite(q.range.lo) else -1e300
        hi = q.range.hi if math.isfinite(q.range.hi) else 1e300
        for k in range(per_option):
            if k % 3 == 0:
                value = rng.uniform(lo, hi)
            elif k % 3 == 1 and lo > 0:
                value = 10 ** rng.uniform(math.log10(lo), math.log10(hi))
            else:
                value = rng.choice([lo - abs(lo) * rng.random() - rng.random(), hi + abs(hi) * rng.random() + rng.random()])
            out.append((command, option, repr(value)))
    return out


#: Run lengths: a large valid value is a legal run of minutes or hours (their ends are in the
#: declared cases, where the work budgets refuse what exceeds them).
DRAWN_LEFT_OUT = {"--transits", "--t-end", "--window", "--xdmf-every", "--duration"}


def api_one(name: str, param: str) -> None:
    """``python -m tests.fuzz_harness --api NAME PARAM``: one parameter's battery from a fresh
    interpreter, the calls not allowed as JSON on stdout. A fork is safe only from a process
    without threads: a test process that ran Dask or Zarr before may hold a lock in another
    thread, and a forked child waits on it for ever (seen in CI as 'hangs' of run_sweep)."""
    bad = [[list(map(str, k)), c.outcome, c.message[:300]] for k, c in api_battery(only=(name, param))
           if c.outcome not in ALLOWED]
    print(json.dumps(bad))


def api_serve() -> None:
    """``python -m tests.fuzz_harness --api-serve``: a fresh interpreter that takes ``NAME\tPARAM``
    lines on stdin and answers each with `api_one`'s JSON line, run in a child forked from this
    process, which itself never calls anything (so it holds no thread a fork could inherit
    locked). The test process keeps one such server: a parameter costs its calls, not an
    interpreter's start and imports (289 of them took 20 minutes of CI)."""
    from .test_fuzz_api import CALLS  # noqa: F401 - the modules the children call, imported once

    for line in sys.stdin:
        name, param = line.rstrip("\n").split("\t")
        read, write = os.pipe()
        pid = os.fork()
        if pid == 0:
            os.close(read)
            code = 0
            with os.fdopen(write, "w") as out:
                try:
                    sys.stdout = out
                    api_one(name, param)
                except BaseException:  # noqa: BLE001 - reported to the test as text
                    import traceback

                    out.write(json.dumps([["server", name, param], "crash", traceback.format_exc()[-2000:]]) + "\n")
                    code = 1
            os._exit(code)
        os.close(write)
        with os.fdopen(read) as answer:
            text = answer.read()
        os.waitpid(pid, 0)
        print(text.strip().splitlines()[-1] if text.strip() else json.dumps([[name, param, "no answer"]]), flush=True)


def main() -> None:
    if sys.argv[1:2] == ["--api"]:
        return api_one(*sys.argv[2:4])
    if sys.argv[1:2] == ["--api-serve"]:
        return api_serve()
    values = EXTREMES + NEVER_NUMBERS
    log = sys.stderr if "-v" in sys.argv else None
    results = battery(values, log=log) + path_battery(log=log) + declared_battery(log=log) + \
        declared_battery(drawn_cases(), log=log)
    calls = api_battery(log=log)
    counts = collections.Counter(p for _, _, found in results for p in found)
    slowest = max(results, key=lambda r: r[1].seconds)
    print(json.dumps({"trials": len(results), "values": values, "options": len(OPTIONS),
                      "path_options": len(PATH_OPTIONS), "bad_places": list(BAD_PATHS),
                      "exit_3_or_signal": sum(1 for _, t, _ in results if not t.hang and t.code not in (0, 1, 2)),
                      "non_finite_successes": counts["non-finite success"], "hangs": counts["hang"],
                      "option_not_named": counts["option not named"], "not_one_line": counts["not one line"],
                      "stderr_on_success": counts["stderr on success"], "tracebacks": counts["traceback"],
                      "exits": dict(collections.Counter(str(t.code) for _, t, _ in results)),
                      "slowest": [" ".join(slowest[0]), round(slowest[1].seconds, 1)],
                      "failures": [[" ".join(a), f] for a, _, f in results if f],
                      "api_calls": len(calls),
                      "api_outcomes": dict(collections.Counter(c.outcome for _, c in calls)),
                      "api_failures": [[list(k), c.outcome, c.message[:200]] for k, c in calls
                                       if c.outcome not in ALLOWED]}, indent=1))


if __name__ == "__main__":
    main()


class Hang(Exception):
    """A call that did not answer within `time_limit`."""


@contextlib.contextmanager
def time_limit(seconds: int):
    """A hang guard, not a timing check: `Hang` after ``seconds`` (a FIFO opened for reading
    blocks until then)."""
    def alarm(signum, frame):
        raise Hang(f"no answer after {seconds} s")
    old = signal.signal(signal.SIGALRM, alarm)
    signal.alarm(seconds)
    try:
        yield
    finally:
        signal.alarm(0)
        signal.signal(signal.SIGALRM, old)
