"""The edge classes of issue 44 as fuzz trials, and their counts by outcome.

``python -m tests.fuzz_report --cli 5000 --api 3000 [--seed N] [-v]`` draws that many trials
(seeded; the seed is printed) from the classes below and prints, per class and in total, how
many gave a clean error, an internal error (exit 3, a traceback, a signal, more than one line),
a hang, a message naming the wrong thing, a refusal only after computing (a file or store
left behind), an input accepted and ignored, a foreign exception (API: not a
`stickslip.errors` one), a NaN in a result, or a result. The CLI trials run forked from this
process (`fuzz_harness.trial`; the commands that start Dask or Zarr threads in a fresh
interpreter), the API calls forked with a time limit.

CLI classes: special files (FIFOs, devices, dangling links, folders) as inputs and as outputs,
a scheduler address that answers but is not Dask, repeated values in lists, deep nesting and
subnormal numbers in config files, options that only mean something together given apart, two
spellings of one key in one file, a sweep's combination rule (fs >= fd; a fem config's static_friction >=
friction) broken at some point,
and the special values of every declared range (`fuzz_harness.declared_cases`). API classes:
every callable of the public modules' ``__all__`` with every required argument bad, and every
parameter of `tests.test_fuzz_api.CALLS` with its bad and declared special values.
"""

from __future__ import annotations

import collections
import contextlib
import dataclasses
import importlib
import inspect
import json
import math
import os
import pathlib
import random
import signal
import socket
import sys
import tempfile
import threading
import time

from .fuzz_harness import (BASE, FRESH, OSC, PATH_OPTIONS, PROGRESS, SUFFIX, SYSTEM_FILE, FOLDERS, args_for,
                           declared_cases, example_config, example_sweep, files_finite, json_finite, trial)

ROOT = pathlib.Path(__file__).resolve().parents[1]
#: The outcome classes, in the order printed.
OUTCOMES = ["clean error", "result", "internal error", "hang", "wrong name", "late refusal", "ignored input",
            "foreign exception", "NaN"]
#: The contract's failures (the others are kept promises).
FAILURES = OUTCOMES[2:]
#: A refusal of a scheduler that answers but is not Dask comes within this (2 x CONNECT_SECONDS
#: for the identity request, and the start of a fresh interpreter).
SCHEDULER_SECONDS = 45.0


@dataclasses.dataclass
class Case:
    """One CLI trial: ``args`` (``{tmp}`` a fresh folder), the option or file the refusal must
    name (or a tuple of the names it may give), and whether the input must be refused (``"refused"``) or may also give a result
    (``"either"``). ``make(tmp)`` prepares the folder (special files, configs)."""

    klass: str
    args: list
    name: str
    expect: str = "refused"
    make: object = None
    timeout: float = 120.0


# --- special files -------------------------------------------------------------------------

SPECIAL = ("a FIFO", "a dangling link", "a folder", "a link to a folder", "/dev/null", "/dev/zero", "a link to a FIFO")


def special(kind: str, folder: pathlib.Path, name: str) -> str:
    """Make a special file of ``kind`` named ``name`` in ``folder`` (or name a device): its path."""
    path = folder / name
    if kind == "a FIFO":
        os.mkfifo(path)
    elif kind == "a dangling link":
        os.symlink(folder / ("gone-" + name), path)
    elif kind == "a folder":
        path.mkdir()
    elif kind == "a link to a folder":
        (folder / ("d-" + name)).mkdir()
        os.symlink(folder / ("d-" + name), path)
    elif kind == "a link to a FIFO":
        os.mkfifo(folder / ("f-" + name))
        os.symlink(folder / ("f-" + name), path)
    elif kind.startswith("/dev/"):
        os.symlink(kind, path)  # with the option's suffix: a device behind a name that looks right
    return str(path)


#: ``(command words, the arguments before and after the input, the name a refusal gives)``.
READERS = [
    ("system simulate", ["--t-end", "1"], "system file"),
    ("system stability", [], "system file"),
    ("fem steady", [], "config"),
    ("fem cea", [], "config"),
    ("sweep", ["--out", "{tmp}/s.zarr", "--workers", "1"], "CONFIG"),
]


def input_cases() -> list[Case]:
    out = []
    for command, rest, name in READERS:
        for kind in SPECIAL:
            out.append(Case("special file as input", command.split() + ["{special:%s:in.toml}" % kind] + rest + ["--json"],
                            name, timeout=60))
    return out


def output_cases() -> list[Case]:
    """Every output option with every special file; with ``--overwrite`` too, but never over a
    device (unfixed, the command would replace /dev/null)."""
    out = []
    for command, option in PATH_OPTIONS:
        if (command, option) in FOLDERS or command not in BASE:
            continue
        store = option == "--store" or any(a == option and b.endswith(".zarr")
                                           for a, b in zip(BASE[command], BASE[command][1:]))
        suffix = ".zarr" if store else SUFFIX.get(option, ".nc")
        for kind in SPECIAL:
            if store and kind in ("a folder", "a link to a folder"):
                continue  # a store is a folder
            for overwrite in ([], ["--overwrite"]):
                if overwrite and (kind.startswith("/dev/") or "--overwrite" not in _options(command)):
                    continue
                value = "{special:%s:out%s}" % (kind, suffix)
                args = args_for(command, option, value, "{tmp}") + overwrite
                out.append(Case("special file as output", args, option, timeout=60))
    return out


def _options(command: str) -> set:
    from .fuzz_harness import cli_params

    if not _OPTS:
        for c, param, _ in cli_params():
            _OPTS.setdefault(c, set()).update(getattr(param, "opts", []))
    return _OPTS.get(command, set())


_OPTS: dict = {}


# --- a scheduler that is not Dask ------------------------------------------------------------

class FakeServer:
    """A TCP server on 127.0.0.1 that answers every connection with garbage (``"garbage"``) or
    accepts and says nothing (``"silent"``); it stops by itself after ``lifetime`` seconds."""

    def __init__(self, mode: str = "garbage", lifetime: float = 3600.0):
        self.mode, self.sock = mode, socket.socket()
        self.sock.bind(("127.0.0.1", 0))
        self.sock.listen(16)
        self.sock.settimeout(0.5)
        self.port, self.until = self.sock.getsockname()[1], time.time() + lifetime
        self.held: list = []
        threading.Thread(target=self._serve, daemon=True).start()

    @property
    def address(self) -> str:
        return f"tcp://127.0.0.1:{self.port}"

    def _serve(self):
        while time.time() < self.until:
            try:
                conn, _ = self.sock.accept()
            except OSError:
                continue
            if self.mode == "garbage":
                with contextlib.suppress(OSError):
                    conn.sendall(b"HTTP/1.1 200 OK\r\nContent-Length: 5\r\n\r\nhello" * 20)
                conn.close()
            else:
                while len(self.held) >= 50:  # the oldest closed, not left to the garbage collector
                    self.held.pop(0).close()
                self.held.append(conn)
        self.stop()

    def stop(self) -> None:
        """Close the held connections and the listening socket (the serving thread ends)."""
        self.until = 0.0
        for conn in self.held:
            with contextlib.suppress(OSError):
                conn.close()
        self.held = []
        with contextlib.suppress(OSError):
            self.sock.close()


def scheduler_cases(servers: dict) -> list[Case]:
    out = []
    for mode, server in servers.items():
        for command in ("sweep", "oscillator map", "brake map"):
            out.append(Case("scheduler that is not Dask", args_for(command, "--scheduler", server.address, "{tmp}"),
                            "--scheduler", timeout=SCHEDULER_SECONDS))
        out.append(Case("scheduler that is not Dask", ["fem", "cea", "{config}", "--sweep", "friction=0.1:0.3:2",
                                                         "--store", "{tmp}/c.zarr", "--scheduler", server.address,
                                                         "--json"], "--scheduler", timeout=SCHEDULER_SECONDS))
    return out


# --- config files -----------------------------------------------------------------------------

SWEEP_HEAD = 'command = "oscillator cycle"\noutputs = ["period"]\n'
SWEEP_FIXED = "[fixed]\nmass = 1.0\nstiffness = 1.0\nnormal_force = 1.0\n"


def sweep_case(klass: str, text: str, expect: str = "refused") -> Case:
    return Case(klass, ["sweep", "{file:sweep.toml}", "--out", "{tmp}/s.zarr", "--workers", "1", "--json"], "CONFIG",
                expect, make={"sweep.toml": text})


def _nest(kind: str, depth: int) -> str:
    return "[" * depth + "1" + "]" * depth if kind == "array" else "{a=" * depth + "1" + "}" * depth


def config_cases() -> list[Case]:
    out = []
    system = pathlib.Path(SYSTEM_FILE).read_text()
    pad = pathlib.Path(example_config()).read_text().replace('mesh = "pad.msh"',
                                                             f'mesh = "{example_config().replace("pad.toml", "pad.msh")}"')
    for depth in (100, 1000, 3000, 20000):
        for kind in ("array", "table"):
            deep = f"deep = {_nest(kind, depth)}\n"
            out.append(Case("deep nesting in a config", ["system", "stability", "{file:s.toml}", "--json"],
                            ("system file", "invalid deep ="), make={"s.toml": deep + system}))  # or the key
            out.append(Case("deep nesting in a config", ["fem", "steady", "{file:p.toml}", "--json"], "config",
                            make={"p.toml": deep + pad}))
            out.append(sweep_case("deep nesting in a config", deep + SWEEP_HEAD + SWEEP_FIXED
                                  + "fd = 0.3\nfs = 0.5\n[axes]\nbelt_speed = [0.1, 0.2]\n"))
    for value in ("1e-320", "-4.9e-324", "2.2e-308", "1e-310"):
        out.append(sweep_case("subnormal in a config", SWEEP_HEAD + SWEEP_FIXED.replace("mass = 1.0", f"mass = {value}")
                              + "fd = 0.3\nfs = 0.5\n[axes]\nbelt_speed = [0.1, 0.2]\n"))
        out.append(sweep_case("subnormal in a config", SWEEP_HEAD + SWEEP_FIXED
                              + f"fd = 0.3\nfs = 0.5\n[axes]\nbelt_speed = [0.1, {value}]\n"))
        out.append(Case("subnormal in a config", ["fem", "steady", "{file:p.toml}", "--json"], "config",
                        make={"p.toml": pad.replace("friction = 0.5", f"friction = {value}")}))
        for key in ("normal_force", "surface_speed"):
            out.append(Case("subnormal in a config", ["system", "stability", "{file:s.toml}", "--json"],
                            f"contact[0].{key}", make={"s.toml": _system_with(system, key, value)}))  # the file's key
    return out


def _system_with(text: str, key: str, value: str) -> str:
    """The system file with the first ``key = ...`` line set to ``value``."""
    lines = text.splitlines()
    i = next(k for k, line in enumerate(lines) if line.replace(" ", "").startswith(f"{key}="))
    lines[i] = f"{key} = {value}"
    return "\n".join(lines) + "\n"


def repeated_cases() -> list[Case]:
    out = []
    for values in ("[0.1, 0.1]", "[0.1, 0.2, 0.1]", "{ start = 0.2, stop = 0.2, num = 3 }"):
        out.append(sweep_case("repeated values in a list", SWEEP_HEAD + SWEEP_FIXED
                              + f"fd = 0.3\nfs = 0.5\n[axes]\nbelt_speed = {values}\n"))
    for modes in ("2,2", "1-3,2", "4,1-4"):
        out.append(Case("repeated values in a list", ["brake", "stability", *BASE["brake stability"][:-2],
                                                       "--wave-numbers", modes, "--json"], "--wave-numbers"))
    for history in ("0:1e-6,0:1e-5", "0:1e-6,5:1e-5,5:1e-6"):
        out.append(Case("repeated values in a list", ["rsf", "slide", *BASE["rsf slide"][:-4], "--history", history,
                                                       "--json"], "--history"))
    for command in ("oscillator map", "brake map"):
        axis = "belt_speed=0.2:0.2:3" if command == "oscillator map" else "friction=0.3:0.3:2"
        out.append(Case("repeated values in a list", args_for(command, "--x", axis, "{tmp}"), "--x"))
    out.append(Case("repeated values in a list", ["fem", "cea", "{config}", "--sweep", "friction=0.3:0.3:3", "--store",
                                                   "{tmp}/c.zarr", "--json"], "--sweep"))
    return out


#: ``(args, the option that needs another)``: options that mean something with another only.
APART = [
    (["oscillator", "cycle", *OSC, "--overwrite"], "--overwrite"),
    (["fem", "steady", "{config}", "--overwrite"], "--overwrite"),
    (["fem", "run", "{config}", "--transits", "1", "--xdmf-every", "0.5"], "--xdmf-every"),
    (["brake", "fem", *BASE["brake fem"][:-4], "--xdmf-every", "0.5"], "--xdmf-every"),
    (["fem", "cea", "{config}", "--store", "{tmp}/c.zarr"], "--store"),
    (["fem", "cea", "{config}", "--plot", "{tmp}/c.png"], "--plot"),
    (["fem", "cea", "{config}", "--workers", "2"], "--workers"),
    (["fem", "cea", "{config}", "--sweep", "friction=0.1:0.3:2", "--set", "friction=0.2", "--store", "{tmp}/c.zarr"],
     "--set"),
    (["brake", "coefficients", "--xi", "1.5", "--nu", "0.3", "--young", "2e11"], "--omega"),
    (["brake", "coefficients", "--xi", "1.5", "--nu", "0.3", "--density", "7850"], "--omega"),
    (["brake", "wave", "--xi", "1.5", "--gamma", "1e-6", "--friction", "0.7"], "--delta"),
    (["rsf", "slide", *BASE["rsf slide"][:-4], "--history", "0:1e-6,10:1e-5", "--load-velocity", "1e-6"], "--history"),
    (["system", "continue", SYSTEM_FILE, "--parameter", "contact[0].surface_speed"], "--stop"),
    (["system", "continue", SYSTEM_FILE, "--stop", "0.3"], "--parameter"),
]


def apart_cases() -> list[Case]:
    return [Case("options given apart", args + ["--json"], name) for args, name in APART]


def spelling_cases() -> list[Case]:
    out = []
    for fixed in ("normal_force = 1.0\nnormal-force = 2.0\n", "normal-force = 1.0\nnormal_force = 1.0\n"):
        out.append(sweep_case("two spellings of one key", SWEEP_HEAD + "[fixed]\nmass = 1.0\nstiffness = 1.0\n" + fixed
                              + "fd = 0.3\nfs = 0.5\n[axes]\nbelt_speed = [0.1, 0.2]\n"))
    out.append(sweep_case("two spellings of one key", SWEEP_HEAD + SWEEP_FIXED + "fd = 0.3\nfs = 0.5\n[axes]\n"
                          "belt_speed = [0.1, 0.2]\nbelt-speed = [0.3, 0.4]\n"))
    fem = ('command = "fem steady"\nconfig = "pad.toml"\noutputs = ["normal_force"]\n[fixed]\nfriction = 0.4\n'
           'contact.friction = 0.3\n[axes]\nsurface.speed = [1.0, 2.0]\n')
    out.append(Case("two spellings of one key", ["sweep", "{file:fem.toml}", "--out", "{tmp}/s.zarr", "--workers", "1",
                                                   "--json"], "CONFIG", make={"fem.toml": fem, "pad.toml": "{pad}"}))
    out.append(Case("two spellings of one key", ["fem", "steady", "{config}", "--set", "friction=0.3", "--set",
                                                  "contact.friction=0.4", "--json"], "--set"))
    return out


def combination_cases() -> list[Case]:
    out = []
    for fixed, axes in (("fd = 0.4\n", "fs = [0.5, 0.3]\n"), ("fs = 0.5\n", "fd = [0.3, 0.6]\n"),
                        ("", "fs = [0.5, 0.6]\nfd = [0.3, 0.55]\n"), ("fd = 0.5\n", "fs = { start = 0.6, stop = 0.4, num = 3 }\n")):
        out.append(sweep_case("sweep combination rule", SWEEP_HEAD + SWEEP_FIXED + fixed + "[axes]\n" + axes
                              + "belt_speed = [0.1, 0.2]\n"))
    for axes in ("friction = [0.2, 0.5]\nstatic_friction = [0.6, 0.3]\n",  # a fem config's two numbers together
                 "contact.static_friction = [0.4, 0.45]\ncontact.friction = [0.3, 0.5]\n"):
        fem = 'command = "fem steady"\nconfig = "pad.toml"\noutputs = ["normal_force"]\n[axes]\n' + axes
        out.append(Case("sweep combination rule", ["sweep", "{file:fem.toml}", "--out", "{tmp}/s.zarr", "--workers", "1",
                                                    "--json"], "CONFIG", make={"fem.toml": fem, "pad.toml": "{pad}"}))
    return out


def declared_sample(n: int, rng: random.Random) -> list[Case]:
    """``n`` of the special values of the declared ranges (`fuzz_harness.declared_cases`), and of
    values drawn inside and around them (`fuzz_harness.drawn_cases`): a result or a clean
    refusal, never more. The commands that need a fresh interpreter (maps, sweeps, ~10 s a trial
    on a loaded machine) are left to `fuzz_harness`'s own battery."""
    from .fuzz_harness import drawn_cases

    cases = [c for c in declared_cases() if not c[0].startswith(FRESH)]
    if n > len(cases):  # and values drawn inside and around each range, as many as it takes
        per_option = 1 + (n - len(cases)) // max(1, len(drawn_cases(1, rng.randrange(2**31))))
        cases += [c for c in drawn_cases(per_option, rng.randrange(2**31)) if not c[0].startswith(FRESH)]
    return [Case("edges of declared ranges", args_for(c, o, v, "{tmp}"), o, "either", timeout=120)
            for c, o, v in rng.sample(cases, min(n, len(cases)))]


# --- running and judging a CLI case -------------------------------------------------------------

def materialise(case: Case, tmp: pathlib.Path) -> list[str]:
    """The case's arguments in folder ``tmp``: its files written, its special files made."""
    pad = pathlib.Path(example_config())
    for name, text in (case.make or {}).items():
        if text == "{pad}":
            text = pad.read_text().replace('mesh = "pad.msh"', f'mesh = "{pad.with_suffix(".msh")}"')
        (tmp / name).write_text(text)
    out = []
    for a in case.args:
        if a.startswith("{special:"):
            kind, name = a[len("{special:"):-1].rsplit(":", 1)
            a = special(kind, tmp, name.replace("{tmp}/", ""))
        elif a.startswith("{file:"):
            a = str(tmp / a[len("{file:"):-1])
        elif "{special:" in a:  # an option's value: {tmp}/... made inside
            kind, name = a.split("{special:", 1)[1][:-1].rsplit(":", 1)
            a = special(kind, tmp, name)
        a = a.replace("{tmp}", str(tmp))
        out.append(example_config() if a == "{config}" else example_sweep() if a == "{sweep}" else a)
    return out


def judge_cli(case: Case, t, tmp: pathlib.Path, before: set) -> str:
    """The outcome class of a CLI trial (`OUTCOMES`)."""
    if t.hang:
        return "hang"
    if t.code not in (0, 1, 2) or "Traceback" in t.err:
        return "internal error"
    said = [line for line in t.err.splitlines() if not PROGRESS.match(line) and not line.startswith("Dask dashboard")]
    if t.code == 0:
        try:
            finite = json_finite(t.out)
        except ValueError:
            return "internal error"
        if not finite or _bad_files(tmp):
            return "NaN"
        return "ignored input" if case.expect == "refused" else "result"
    if t.out or len(said) != 1:
        return "internal error"
    if t.code == 2 and not any(n in t.err for n in (case.name if isinstance(case.name, tuple) else (case.name,))):
        return "wrong name"
    if t.code == 2 and sorted(set(_listing(tmp)) - before):
        return "late refusal"  # refused, but after writing a store, a checkpoint or a partial file
    return "clean error"


def _listing(tmp: pathlib.Path) -> list[str]:
    return [str(p.relative_to(tmp)) for p in tmp.rglob("*") if not p.is_symlink() and not p.is_fifo()]


def _bad_files(tmp: pathlib.Path) -> list[str]:
    try:
        return files_finite(tmp)
    except Exception:  # noqa: BLE001 - a file that is not what its suffix says
        return []


def run_cli(case: Case) -> tuple[str, object]:
    with tempfile.TemporaryDirectory(prefix="stickslip-edge-") as tmp:
        tmp = pathlib.Path(tmp)
        args = materialise(case, tmp)
        before = set(_listing(tmp))
        t = trial(args, case.timeout)
        return judge_cli(case, t, tmp, before), t


# --- the API ------------------------------------------------------------------------------------

#: The modules of the API reference (docs/api): their ``__all__`` is the public API.
PUBLIC = sorted(f"stickslip.{p.stem}" for p in (ROOT / "docs" / "api").glob("*.rst") if p.stem != "index")
BAD = [float("nan"), float("inf"), -float("inf"), -1.0, 0.0, 1e300, 1e-320, "x", None, True, [], [[1.0], [1.0, 2.0]],
       10**20, 1j]


def public_callables() -> dict:
    """``{module.name: callable}`` of every function and class in the public modules' ``__all__``
    (exceptions left out)."""
    out = {}
    for module_name in PUBLIC:
        module = importlib.import_module(module_name)
        for name in getattr(module, "__all__", ()):
            obj = getattr(module, name, None)
            if (inspect.isfunction(obj) or inspect.isclass(obj) and not issubclass(obj, BaseException)) \
                    and obj.__module__.startswith("stickslip"):
                out.setdefault(f"{module_name}.{name}", obj)
    return out


def _record(func) -> bool:
    from stickslip.results import Result

    return inspect.isclass(func) and issubclass(func, Result)


def _unset(func) -> set:
    try:
        return {p.name for p in inspect.signature(func).parameters.values() if p.default is None}
    except (TypeError, ValueError):
        return set()


def required(func) -> list[str]:
    try:
        params = inspect.signature(func).parameters.values()
    except (TypeError, ValueError):
        return []
    return [p.name for p in params if p.default is p.empty and p.kind in (p.POSITIONAL_ONLY, p.POSITIONAL_OR_KEYWORD,
                                                                          p.KEYWORD_ONLY)]


def api_cases(rng: random.Random, n: int) -> list[tuple]:
    """``(class, label, func, kwargs, names a ParameterError may give)``: every public callable
    with all its required arguments one bad value (a callable without any, called bare), then
    the parameters of `tests.test_fuzz_api.CALLS` one at a time with their bad and special values."""
    from .fuzz_harness import api_values
    from .test_fuzz_api import CALLS

    walk = []
    for label, func in public_callables().items():
        names = required(func)
        unset = _unset(func)  # a refusal may name one of these first: left at None, it is missing
        for value in (BAD if names else [None]):
            walk.append(("public function, bad arguments", f"{label}({', '.join(names)} = {value!r:.30})", func,
                         {k: value for k in names}, set(names) | unset, _record(func)))
    calls = [("declared parameters", f"{name}({param} = {value!r:.30})", func, {param: value}, {param}, False)
             for name, (func, params) in CALLS.items() for param in params for value in api_values(name, param)]
    rng.shuffle(calls)
    return walk + calls[:max(0, n - len(walk))]


def api_trial(func, kwargs: dict, timeout: float = 120.0) -> tuple[str, str, str | None, float]:
    """``(outcome, message, ParameterError's name, seconds)`` of ``func(**kwargs)`` in a forked
    child; outcome ``ok``, ``nan`` (a result holding NaN), ``hang`` or an exception's type name."""
    import warnings

    read, write = os.pipe()
    start = time.perf_counter()
    pid = os.fork()
    if pid == 0:
        os.close(read)
        outcome, message, name = "ok", "", None
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                value = func(**kwargs)
            if _holds_nan(value):
                outcome = "nan"
        except BaseException as err:  # noqa: BLE001 - what the parent judges
            outcome, message, name = type(err).__name__, str(err)[:300], getattr(err, "name", None)
        os.write(write, json.dumps([outcome, message, name if isinstance(name, str) else None]).encode())
        os._exit(0)
    os.close(write)
    answer = ["hang", "", None]
    while time.perf_counter() - start < timeout:
        done, _ = os.waitpid(pid, os.WNOHANG)
        if done:
            data = b""
            while chunk := os.read(read, 65536):
                data += chunk
            answer = json.loads(data) if data else ["killed", "", None]
            break
        time.sleep(0.002)
    else:
        os.kill(pid, signal.SIGKILL)
        os.waitpid(pid, 0)
    os.close(read)
    return answer[0], answer[1], answer[2], time.perf_counter() - start


def _holds_nan(value) -> bool:
    """A result with a NaN that its documentation does not announce: the floats of its
    ``to_dict`` (a result object) or of a plain float / tuple of floats."""
    if hasattr(value, "to_dict"):
        try:
            value = value.to_dict()
        except Exception:  # noqa: BLE001 - a result that cannot say itself is judged by its fields elsewhere
            return False
    if isinstance(value, (float, int)) and not isinstance(value, bool):
        return not math.isfinite(value)
    if isinstance(value, (tuple, list)) and all(isinstance(v, (float, int)) for v in value):
        return not all(math.isfinite(v) for v in value)
    if isinstance(value, dict):
        return not json_finite(json.dumps(value, default=str))
    return False


#: The names a refusal gives to an argument for what it is (the file it reads, the law it
#: names, the table it holds), where they differ from the argument's own name.
ROLES = {"path": {"mesh", "system file", "config", "CONFIG"}, "name": {"law"}, "data": {"system"},
         "key": {"parameter"}}


def judge_api(outcome: str, name: str | None, names: set, record: bool = False, message: str = "") -> str:
    """The outcome class of a call (`OUTCOMES`); ``record``: the callable is a result record (a
    `stickslip.results.Result`), which holds what it is given, NaN included."""
    if outcome == "TypeError" and message.startswith("Can't instantiate abstract class"):
        return "clean error"  # Python's own call mechanism, as for a wrong number of arguments
    if outcome == "hang":
        return "hang"
    if outcome == "killed":
        return "internal error"
    if outcome == "nan":
        return "result" if record else "NaN"
    if outcome == "ok":
        return "result"
    if outcome == "NoSolutionError":
        return "clean error"
    if outcome == "ParameterError":
        # the argument given, or one it is checked against (a part of it: "params" for a BrakeParams' field)
        allowed = set(names) | {r for n in names for r in ROLES.get(n, ())}
        return "clean error" if name is not None and any(n in name or name in n for n in allowed) or not names \
            else "wrong name"
    return "foreign exception"


# --- the report ---------------------------------------------------------------------------------

def main(argv=None) -> int:
    import argparse

    parser = argparse.ArgumentParser(prog="python -m tests.fuzz_report", description=__doc__.split("\n\n")[0])
    parser.add_argument("--cli", type=int, default=5000, help="CLI trials (default 5000)")
    parser.add_argument("--api", type=int, default=3000, help="API calls (default 3000)")
    parser.add_argument("--seed", type=int, default=20261128, help="the draw's seed (printed)")
    parser.add_argument("-v", action="store_true", help="a line per trial on stderr")
    parser.add_argument("--out", type=pathlib.Path, help="also write the counts and the failures as JSON here")
    args = parser.parse_args(argv)
    rng = random.Random(args.seed)
    print(f"seed {args.seed}", flush=True)
    start = time.time()
    servers = {"garbage": FakeServer("garbage", lifetime=6 * 3600), "silent": FakeServer("silent", lifetime=6 * 3600)}
    fixed = (input_cases() + output_cases() + scheduler_cases(servers) + config_cases() + repeated_cases()
             + apart_cases() + spelling_cases() + combination_cases())
    cases = fixed + declared_sample(max(0, args.cli - len(fixed)), rng) if args.cli else []
    counts: dict = collections.defaultdict(collections.Counter)
    failures = []
    for case in cases:
        outcome, t = run_cli(case)
        counts["cli: " + case.klass][outcome] += 1
        if outcome in FAILURES:
            failures.append(["cli", case.klass, outcome, " ".join(t.args), str(t.code), t.err.strip()[-300:]])
        if args.v:
            print(f"{outcome:>16} {t.seconds:6.1f}s {' '.join(t.args)[:200]}  {t.err.strip()[-160:]}", file=sys.stderr,
                  flush=True)
    cli_seconds = time.time() - start
    for klass, label, func, kwargs, names, record in api_cases(rng, args.api) if args.api else []:
        with tempfile.TemporaryDirectory(prefix="stickslip-edge-api-") as tmp:
            cwd = os.getcwd()
            os.chdir(tmp)  # a bad value such as "x" is a valid relative path: kept out of the tree
            try:
                outcome, message, name, seconds = api_trial(func, kwargs)
            finally:
                os.chdir(cwd)
        judged = judge_api(outcome, name, names, record, message)
        counts["api: " + klass][judged] += 1
        if judged in FAILURES:
            failures.append(["api", klass, judged, label, outcome, message[:300]])
        if args.v:
            print(f"{judged:>16} {seconds:6.1f}s {label}  {outcome}: {message[:160]}", file=sys.stderr, flush=True)
    total = collections.Counter()
    width = max(len(k) for k in counts) if counts else 10
    print(f"{'class':{width}}  trials  " + "  ".join(OUTCOMES))
    for klass in sorted(counts):
        total.update(counts[klass])
        print(f"{klass:{width}}  {sum(counts[klass].values()):6}  "
              + "  ".join(f"{counts[klass][o]:{len(o)}}" for o in OUTCOMES))
    for side in ("cli", "api"):
        sub = collections.Counter()
        for klass in counts:
            if klass.startswith(side):
                sub.update(counts[klass])
        print(f"{'all ' + side:{width}}  {sum(sub.values()):6}  " + "  ".join(f"{sub[o]:{len(o)}}" for o in OUTCOMES))
    print(f"failures: {len(failures)}; {time.time() - start:.0f} s ({cli_seconds:.0f} s CLI)")
    for f in failures[:200]:
        print("  " + " | ".join(f))
    if args.out:
        args.out.write_text(json.dumps({"seed": args.seed, "counts": {k: dict(v) for k, v in counts.items()},
                                        "failures": failures, "seconds": time.time() - start}, indent=1))
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
