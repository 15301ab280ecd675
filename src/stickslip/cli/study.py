"""`stickslip sweep CONFIG.toml`: any command that prints ``--json``, over a grid of its
options, on dask.distributed, into one resumable Zarr store.

The sweep's config names the command, its fixed options, the swept axes and the outputs
kept (numbers of the command's ``--json``)::

    command = "oscillator cycle"
    outputs = ["period", "amplitude", "stick_time"]

    [fixed]
    mass = 1.0
    stiffness = 1.0
    normal_force = 1.0
    fd = 0.3

    [axes]
    belt_speed = { start = 0.05, stop = 0.5, num = 10 }             # a grid
    fs = [0.4, 0.5, 0.6]                                              # a list
    damping = { start = 1e-3, stop = 1e-1, num = 5, scale = "log" }  # a log range
    replicate = { count = 8 }                                         # unseeded repetitions

A `fem` command also names its ``config`` (relative to the sweep's file), and its keys may be
fixed or swept like options (``contact.friction``, or ``friction`` when that is one key).
Every point is the command itself, run in a worker with its options (``--set`` for the
config's numbers), so a point computes what the command computes; a command that writes a
run as it goes gets one checkpoint per point beside the store (``<store>.runs/``), so a
killed sweep loses no run. Everything is checked before anything runs: every problem of the
config in one error.
"""

from __future__ import annotations

import contextlib
import hashlib
import io
import json
import math
import tomllib
from pathlib import Path

import shutil
from typing import Annotated, Optional

import numpy as np
import typer

from ..errors import MISSING, NoSolutionError, ParameterError
from ..validation import regular_input
from ..quantities import COMMON, MAX_POINTS
from .common import Overwrite, declared, scheduler_option, emit, output_folder, progress_bar, units_of
from .helptext import command_tree

_CLICK_ERROR = next(c for c in typer.BadParameter.__mro__ if c.__name__ == "ClickException")  # typer's own click
Json = Annotated[bool, typer.Option("--json", help="Print one JSON object on stdout.")]

__all__ = ["Study", "read_study", "run_point", "command"]

#: The model (vocabulary of units) of each command group.
MODELS = {"oscillator": "oscillator", "brake": "brake", "halfspace": "halfspace", "fem": "fem"}
#: Commands whose vocabulary is not their group's.
COMMAND_MODELS = {("halfspace", "run"): "sbim", ("halfspace", "fault"): "sbim"}


def model_of(words: tuple) -> str:
    """The vocabulary of units of the command ``words``."""
    return COMMAND_MODELS.get(tuple(words), MODELS.get(words[0], "common"))
#: Commands that are sweeps themselves, or write no result: not swept.
NOT_SWEPT = {("reproduce",), ("sweep",), ("oscillator", "map"), ("brake", "map"), ("brake", "campaign"),
             ("oscillator", "continue"), ("brake", "continue")}
#: Options the sweep sets itself, per point.
OWN = {"json", "out", "overwrite", "plot", "xdmf", "xdmf_every", "store", "sweep", "workers", "scheduler", "set_"}
REPLICATE = "replicate"
_CONFIG = "config:"  # the swept key is a number of the command's config
_KEYS = {"command", "config", "outputs", "fixed", "axes", "title"}
#: Commands that write their run as it goes (``--out``) and resume it: one checkpoint per point.
RESUMABLE = {("brake", "integrate"), ("brake", "fem"), ("fem", "run"), ("halfspace", "run"), ("halfspace", "fault")}


class Study:
    """A checked sweep config: the command, its fixed options and config numbers, the axes,
    the outputs and their units."""

    def __init__(self, path: Path, words: tuple, config: Path | None, fixed: dict, sets: dict, axes: dict,
                 keys: dict, outputs: dict, title: str, flags: dict, ints: frozenset):
        self.path, self.words, self.config, self.fixed, self.sets = path, words, config, fixed, sets
        self.axes, self.keys, self.outputs, self.title = axes, keys, outputs, title
        self.flags, self.ints = flags, ints  # each option's flag as the command takes it; the integer ones

    @property
    def points(self) -> int:
        return math.prod(len(v) for v in self.axes.values())

    @property
    def model(self) -> str:
        return model_of(self.words)

    def attrs(self) -> dict:
        """Every parameter of the sweep (a resume with others is refused)."""
        out = {"command": " ".join(self.words), "swept_keys": json.dumps(self.keys),
               "outputs_printed_as": json.dumps({k: name for k, (name, _) in self.outputs.items()}),
               "fixed_options": json.dumps(self.fixed, sort_keys=True),
               "fixed_config_numbers": json.dumps(self.sets, sort_keys=True)}
        if self.config is not None:  # what the config says and the files it names (a mesh), not where it is
            out["config"] = self.config.name
            out["config_inputs_sha256"] = _inputs_digest(self.config)
        return out


def _inputs_digest(config: Path) -> str:
    """SHA-256 of a config's content (its TOML as read: comments and layout aside) and of every
    file it names relative to its folder (a mesh, a partner's mesh)."""
    data = tomllib.loads(config.read_text(encoding="utf-8"))
    digest = hashlib.sha256(json.dumps(data, sort_keys=True, default=str).encode())

    def files(value):
        if isinstance(value, dict):
            for v in value.values():
                yield from files(v)
        elif isinstance(value, list):
            for v in value:
                yield from files(v)
        elif isinstance(value, str) and (config.parent / value).is_file():
            yield config.parent / value

    for path in sorted(set(files(data))):
        digest.update(path.name.encode() + hashlib.sha256(path.read_bytes()).digest())
    return digest.hexdigest()


def _key(param) -> str:
    """The name of an option in a sweep config: its flag without dashes, ``_`` for ``-``."""
    opts = getattr(param, "opts", None) or [param.name]
    return opts[0].lstrip("-").replace("-", "_") if opts[0].startswith("-") else param.name


def _leaf(app, words: tuple):
    command = command_tree(app)
    for word in words:
        command = getattr(command, "commands", {}).get(word)
        if command is None:
            return None
    return None if getattr(command, "commands", None) else command


def _commands(app, command=None, prefix=()) -> list[str]:
    command = command or command_tree(app)
    out = []
    for name, sub in sorted(getattr(command, "commands", {}).items()):
        words = (*prefix, name)
        if getattr(sub, "commands", None):
            out += _commands(app, sub, words)
        elif words not in NOT_SWEPT and any(p.name == "json" for p in sub.params):
            out.append(" ".join(words))
    return out


def _values(name: str, spec, problems: list) -> list:
    """An axis' values: a list, ``{start, stop, num[, scale]}`` or ``{count}`` (replicates)."""
    where = f"axes.{name}"
    if isinstance(spec, list):
        if not spec or not all(isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)
                               for v in spec):
            problems.append(f"{where} must be a non-empty list of finite numbers")
            return []
        return [float(v) for v in spec]
    if not isinstance(spec, dict):
        problems.append(f"{where} must be a list of numbers, {{start, stop, num[, scale]}} or {{count}}")
        return []
    if name == REPLICATE:
        count = spec.get("count")
        if set(spec) != {"count"} or not isinstance(count, int) or isinstance(count, bool) or \
                not 1 <= count <= COMMON["seeds"].range.hi:
            problems.append(f"{where} must be {{count = N}} with N an integer in [1, {COMMON['seeds'].range.hi:g}]")
            return []
        return [float(i) for i in range(count)]
    extra = set(spec) - {"start", "stop", "num", "scale"}
    start, stop, num, scale = spec.get("start"), spec.get("stop"), spec.get("num"), spec.get("scale", "linear")
    if extra or not all(isinstance(v, (int, float)) and not isinstance(v, bool) and math.isfinite(v)
                        for v in (start, stop)) or not isinstance(num, int) or isinstance(num, bool) \
            or not 1 <= num <= MAX_POINTS or scale not in ("linear", "log"):
        problems.append(f"{where} must be {{start, stop, num[, scale]}}: finite start and stop, an integer num in "
                        f"[1, {MAX_POINTS:.0e}], scale linear or log" + (f" (unknown: {', '.join(sorted(extra))})"
                                                                          if extra else ""))
        return []
    if scale == "log":
        if start <= 0 or stop <= 0:
            problems.append(f"{where}: a log range needs start > 0 and stop > 0 (got {start:g}, {stop:g})")
            return []
        return np.geomspace(start, stop, num).tolist()  # both ends exactly as written
    return np.linspace(start, stop, num).tolist()


def _store_name(key: str) -> str:
    """A key as a variable of the store (letters, digits and ``_``)."""
    return "_".join(part for part in "".join(c if c.isalnum() else "_" for c in key).split("_") if part)


def read_study(path: Path, app) -> Study:
    """Read and check the sweep config ``path``; every problem in one `ParameterError`."""
    path = regular_input("CONFIG", path, "a readable TOML file")
    try:
        data = tomllib.loads(path.read_text(encoding="utf-8"))
    except OSError as err:
        raise ParameterError("CONFIG", str(path), f"a readable TOML file ({err.strerror})") from None
    except (UnicodeDecodeError, tomllib.TOMLDecodeError) as err:
        raise ParameterError("CONFIG", str(path), f"a valid TOML file in UTF-8 ({err})") from None
    except RecursionError:
        raise ParameterError("CONFIG", str(path), "a TOML file without deeply nested arrays or tables (a sweep "
                             "config nests three levels)") from None
    problems: list[str] = [f"unknown key {k}" for k in sorted(set(data) - _KEYS)]
    text = data.get("command")
    words = tuple(str(text).split()) if isinstance(text, str) else ()
    command = _leaf(app, words) if words and words not in NOT_SWEPT else None
    if command is None or not any(p.name == "json" for p in command.params):
        problems.append(f"command must be one of: {', '.join(_commands(app))} (got {text!r})")
        raise ParameterError("CONFIG", str(path), _summary(problems))
    params = {_key(p): p for p in command.params if p.name not in OWN}
    config = None
    if "config" in params:  # a fem command: its config file, and its numbers as axes
        given = data.get("config")
        config = (path.parent / given) if isinstance(given, str) else None
        if config is None or not config.is_file():
            problems.append(f"config must name the {' '.join(words)} config file, relative to this file "
                            f"(got {given!r})")
    elif "config" in data:
        problems.append(f"config is only for the fem commands ({' '.join(words)} takes none)")
    fixed, sets, axes, keys, unparsed = {}, {}, {}, {}, set()
    key_of = _config_keys(config, problems) if config is not None and config.is_file() else None
    spelled: dict = {}  # what each option or config number was given as: a second spelling of it is refused
    for section in ("fixed", "axes"):
        table = data.get(section, {})
        if not isinstance(table, dict):
            problems.append(f"[{section}] must be a table")
            continue
        for raw, value in _flat(table, section == "axes"):
            name = raw.replace("-", "_")
            if section == "axes" and name == REPLICATE:
                values = _values(name, value, problems)
                if values:
                    axes[REPLICATE], keys[REPLICATE] = values, REPLICATE
                continue
            if name in params and name not in ("config", "json"):
                target = params[name]
            elif key_of is not None and key_of(raw) is not None:
                target = key_of(raw)
            else:
                known = sorted(n for n in params if n not in ("config", "json")) + (key_of.keys if key_of else [])
                problems.append(f"{section}.{raw} is not an option of {' '.join(words)}"
                                + (" nor a number of its config" if key_of is not None else "")
                                + f" ({', '.join(known) or 'none'})")
                continue
            same = target if isinstance(target, str) else name
            if (section, same) in spelled:
                problems.append(f"{section}.{spelled[section, same]} and {section}.{raw} are one "
                                f"{'config number' if isinstance(target, str) else 'option'} ({same}) given twice: "
                                "keep one")
                continue
            spelled[section, same] = raw
            kind = _kind_problem(section, raw, value, target)
            if kind:
                problems.append(kind)
                if not isinstance(target, str) and section == "axes":
                    unparsed.add(target.opts[0])
                continue
            if section == "fixed":
                (sets if isinstance(target, str) else fixed)[target if isinstance(target, str) else name] = value
                continue
            values = _values(raw, value, problems)
            if len(set(values)) < len(values):  # a point computed twice, and a grid whose axis is not a coordinate
                twice = sorted({v for v in values if values.count(v) > 1})
                problems.append(f"axes.{raw} repeats {', '.join(f'{v:g}' for v in twice[:3])}: each value once")
                values = []
            if not values and not isinstance(target, str):
                unparsed.add(params[name].opts[0])
            if values:
                store_key = _store_name(target if isinstance(target, str) else name)
                if store_key in axes:
                    problems.append(f"axes.{raw} is swept twice (as {store_key})")
                axes[store_key] = values
                keys[store_key] = f"{_CONFIG}{target}" if isinstance(target, str) else name
    both = {k.removeprefix(_CONFIG) for k in keys.values()} & (set(fixed) | set(sets))
    problems += [f"{k} is both fixed and swept" for k in sorted(both)]
    if not axes and not data.get("axes"):
        problems.append("[axes] must sweep at least one option or config number")
    elif math.prod(len(v) for v in axes.values()) > MAX_POINTS:
        problems.append(f"the grid has {math.prod(len(v) for v in axes.values()):.3g} points (at most "
                        f"{MAX_POINTS:.0e}: split the study)")
    outputs = {}
    names = data.get("outputs")
    model = model_of(words)
    if not isinstance(names, list) or not names or not all(isinstance(n, str) for n in names):
        problems.append(f"outputs must be a non-empty list of the numbers {' '.join(words)} --json prints "
                        "(e.g. [\"period\"]; a nested one as \"a.b\", an entry of a list as \"a[0].b\")")
    else:
        for name in names:
            units = units_of(name, model)[0]
            if not units:
                problems.append(f"outputs: {name!r} is not a number {' '.join(words)} prints with its units")
            elif _store_name(name) in outputs or _store_name(name) in axes or _store_name(name) in ("done", "checksum"):
                problems.append(f"outputs: {name!r} is given twice or names an axis")
            else:
                outputs[_store_name(name)] = (name, units)
    flags = {k: p.opts[0] for k, p in params.items() if getattr(p, "opts", None)}
    ints = frozenset(k for k, p in params.items() if int in (p.type_descriptor.annotation,
                                                              *getattr(p.type_descriptor.annotation, "__args__", ())))
    study = Study(path, words, config, fixed, sets, axes, keys, outputs,
                  str(data.get("title", f"stickslip {' '.join(words)} over {', '.join(axes)}")), flags, ints)
    if axes and (config is None or config.is_file()):  # the values, also when the config has other problems
        problems += [p for p in _check_values(study, command)  # not "required" for an axis already refused
                     if not any(p.startswith(f"{flag} is required") for flag in unparsed)]
    if problems:
        raise ParameterError("CONFIG", str(path), _summary(problems))
    return study


def _summary(problems: list) -> str:
    return f"a valid sweep config; {len(problems)} problem{'s' if len(problems) > 1 else ''}: " + "; ".join(problems)


def _flat(table: dict, axes: bool, prefix: str = ""):
    """``(key, value)`` of a table, a nested one (``contact.friction = 0.3`` unquoted) as a dotted
    key; on axes a table of ``start, stop, num, scale`` or ``count`` is a value."""
    for key, value in table.items():
        name = f"{prefix}{key}"
        if isinstance(value, dict) and not (axes and set(value) <= {"start", "stop", "num", "scale", "count"}):
            yield from _flat(value, axes, f"{name}.")
        else:
            yield name, value


def _kind_problem(section: str, raw: str, value, target) -> str | None:
    """A value of the wrong kind for its option: a bool for a number or a number for a flag."""
    flag = not isinstance(target, str) and getattr(target, "is_flag", False)
    values = value if isinstance(value, list) else [value]
    if flag and not (section == "fixed" and isinstance(value, bool)):
        return f"{section}.{raw} is a flag: fixed, true or false (not swept)" if section == "axes" else \
            f"fixed.{raw} = {value!r}: true or false"
    if not flag and any(isinstance(v, bool) for v in values):
        return f"{section}.{raw} = {value!r}: a number, not true or false"
    return None


def _config_keys(config: Path, problems: list):
    """``key_of(name)``: the config key a name means (`resolve_key`), or None."""
    from ..fem.config import numeric_keys, read_toml, resolve_key

    try:
        data = read_toml(config)
    except ParameterError as err:
        problems.append(f"config: {err}")
        return None

    def key_of(name):
        try:
            return resolve_key(data, name)
        except ParameterError:
            return None

    key_of.keys = numeric_keys(data)
    return key_of


def _check_values(study: Study, command) -> list[str]:
    """Each fixed value and each value of each axis checked by the command's own option (type,
    range, choices), the required options asked for, and the config's numbers by the config's
    checks (each axis' values with the others at their first)."""
    problems = []
    ctx = command.make_context(" ".join(study.words), [str(study.config)] if study.config else [],
                               resilient_parsing=True)
    params = {_key(p): p for p in command.params}
    options = {study.keys[k]: v for k, v in study.axes.items() if k != REPLICATE and not study.keys[k].startswith(_CONFIG)}
    for key, param in params.items():
        if param.required and param.name not in OWN and param.name != "config" and key not in study.fixed \
                and key not in options:
            problems.append(f"{param.opts[0]} is required by {' '.join(study.words)}: fixed or swept")

    def fails(name, value) -> str | None:
        if isinstance(value, bool):
            return None
        try:
            params[name].process_value(ctx, _option(study, name, value)[1])
        except ParameterError as err:
            return str(err)
        except _CLICK_ERROR as err:
            return " ".join(err.format_message().split())
        return None

    for name, value in study.fixed.items():
        why = fails(name, value)
        if why:
            problems.append(f"fixed.{name}: {why}")
    for name, values in options.items():
        bad = [(v, why) for v in values if (why := fails(name, v))]
        if bad:
            problems.append(f"axes.{name} = {bad[0][0]:g}: {bad[0][1]}" + (f" (and {len(bad) - 1} more of its values)"
                                                                          if len(bad) > 1 else ""))
    problems += _combinations(study, options, params)
    if study.config is not None:
        from ..fem.config import load_config

        problems += _config_combinations(study)

        first = {k: v[0] for k, v in study.axes.items()}
        seen = set()
        for axis, values in [(None, [None]), *((k, v) for k, v in study.axes.items() if study.keys[k].startswith(_CONFIG))]:
            for value in values:
                try:
                    load_config(study.config, _sets(study, dict(first) if axis is None else {**first, axis: value}))
                except ParameterError as err:
                    message = err.allowed if err.name == "config" else str(err)
                    if message not in seen:
                        seen.add(message)
                        problems.append(f"config {study.config}: {message}" if axis is None else
                                        f"axes.{_shown(study, axis)} = {value:g}: {message}")
    return problems


#: Rules between two options of one command, ``(larger, smaller)``: the grid holds every
#: combination of the axes' values, so the rule holds at every point iff it holds between the
#: smallest value of the one and the largest of the other (checked before any point runs).
AT_LEAST = [("fs", "fd")]
#: The same between two swept numbers of a fem command's config (their full keys).
CONFIG_AT_LEAST = [("contact.static_friction", "contact.friction")]


def _combinations(study: Study, options: dict, params: dict) -> list[str]:
    """The points of the grid that break a rule of `AT_LEAST` (the first one, and how many)."""
    problems = []
    for big, small in AT_LEAST:
        if big not in params or small not in params:
            continue
        bigs, smalls = options.get(big, [study.fixed.get(big)]), options.get(small, [study.fixed.get(small)])
        if any(not isinstance(v, (int, float)) or isinstance(v, bool) for v in [*bigs, *smalls]):
            continue  # left out (the option's default) or refused above
        broken = [(b, s) for b in bigs for s in smalls if b < s]
        if broken:
            b, s = broken[0]
            where = lambda n: f"axes.{n}" if n in options else f"fixed.{n}"  # noqa: E731
            problems.append(f"{where(big)} = {b:g} with {where(small)} = {s:g}: {params[big].opts[0]} must be >= "
                            f"{params[small].opts[0]} at every point of the grid ({len(broken)} of "
                            f"{len(bigs) * len(smalls)} combinations are not)")
    return problems


def _config_combinations(study: Study) -> list[str]:
    """The points of the grid that break a rule of `CONFIG_AT_LEAST` between two swept numbers (the first
    one, and how many): the config's own check varies one axis at a time (the others at their first),
    which sees a number swept against a fixed one, not two axes' values together."""
    axis_of = {k.removeprefix(_CONFIG): a for a, k in study.keys.items() if k.startswith(_CONFIG)}
    problems = []
    for big, small in CONFIG_AT_LEAST:
        if big not in axis_of or small not in axis_of:
            continue
        bigs, smalls = study.axes[axis_of[big]], study.axes[axis_of[small]]
        broken = [(b, v) for b in bigs for v in smalls if b < v]
        if broken:
            b, v = broken[0]
            problems.append(f"axes.{_shown(study, axis_of[big])} = {b:g} with axes.{_shown(study, axis_of[small])} = "
                            f"{v:g}: {big} must be >= {small} at every point of the grid ({len(broken)} of "
                            f"{len(bigs) * len(smalls)} combinations are not)")
    return problems


def _shown(study: Study, axis: str) -> str:
    return study.keys[axis].removeprefix(_CONFIG)


def _sets(study: Study, point: dict) -> dict:
    """The config's numbers of a point: the fixed ones and the swept ones."""
    return {**study.sets, **{study.keys[k].removeprefix(_CONFIG): v for k, v in point.items()
                             if study.keys[k].startswith(_CONFIG)}}


def _option(study: Study, name: str, value) -> list[str]:
    flag = study.flags[name]
    if isinstance(value, bool):
        return [flag] if value else []
    if name in study.ints and isinstance(value, float) and value.is_integer():
        value = int(value)
    return [flag, repr(value) if isinstance(value, float) else str(value)]


def _argv(study: Study, point: dict, checkpoint: Path | None = None) -> list[str]:
    """The command line of one point."""
    argv = list(study.words) + ([str(study.config)] if study.config is not None else [])
    swept = {study.keys[k]: v for k, v in point.items() if k != REPLICATE and not study.keys[k].startswith(_CONFIG)}
    for name, value in {**study.fixed, **swept}.items():
        argv += _option(study, name, value)
    for key, value in _sets(study, point).items():
        argv += ["--set", f"{key}={value!r}"]
    if checkpoint is not None:
        argv += ["--out", str(checkpoint)]
    return argv


def run_point(study: Study, checkpoints: str | None, runner, **point) -> dict:
    """One point: the command run in this process by ``runner`` with ``--json``; its
    ``outputs``. A point whose command fails raises its one-line message."""
    checkpoint = None
    if checkpoints is not None:
        name = hashlib.sha256(json.dumps(sorted(point.items())).encode()).hexdigest()[:16]
        Path(checkpoints).mkdir(parents=True, exist_ok=True)
        checkpoint = Path(checkpoints) / f"{name}.nc"
    out, err = io.StringIO(), io.StringIO()
    with contextlib.redirect_stdout(out), contextlib.redirect_stderr(err):
        code = runner([*_argv(study, point, checkpoint), "--json"])
    if code != 0:
        last = [line for line in err.getvalue().splitlines() if line.strip()]
        message = last[-1] if last else f"exit code {code}"
        for prefix in ("no solution: ", "error: "):
            message = message.removeprefix(prefix)
        raise (NoSolutionError if code == 1 else ValueError)(message)
    data = json.loads(out.getvalue())
    values = {}
    for store_key, (name, _) in study.outputs.items():
        value = data
        for part in name.split("."):
            key, _, index = part.partition("[")
            value = value.get(key, MISSING) if isinstance(value, dict) else MISSING
            if index:  # an entry of a list: modes[0] (the most unstable mode of a CEA)
                i = int(index.rstrip("]")) if index.rstrip("]").isdigit() else -1
                value = value[i] if isinstance(value, list) and 0 <= i < len(value) else MISSING
        if isinstance(value, bool):
            value = float(value)
        if not isinstance(value, (int, float)):
            raise ValueError(f"{' '.join(study.words)} printed no number {name!r} (it printed: "
                             f"{', '.join(k for k in data if k != 'units')})")
        values[store_key] = float(value)
    return values


def command(app, runner):
    """The ``stickslip sweep`` command of the command line ``app``, whose points run through
    ``runner(argv) -> exit code`` (`stickslip.cli.run`)."""
    def sweep(config: Annotated[Path, typer.Argument(help="The sweep's TOML config: command, outputs, [fixed] and "
                                                           "[axes] (an example: python -m pydoc stickslip.cli.study).")],
              out: Annotated[Path, typer.Option("--out", help="The sweep's Zarr store (.zarr); resumed if it holds "
                                                              "this sweep.")],
              scheduler: Annotated[Optional[str], scheduler_option(
                  "Where the points run: distributed (the default: a local Dask cluster of --workers processes), "
                  "the address tcp://HOST:PORT of a running Dask scheduler and its workers, processes (a local pool "
                  "of --workers processes, in batches), or synchronous (one after another in this process).")] = None,
              workers: Annotated[Optional[int], declared(COMMON["workers"], "--workers", "Local worker processes "
                                                         "(default: all cores).")] = None,
              overwrite: Overwrite = False, json: Json = False):
        """Any command over a grid of its options (and a fem config's numbers), on Dask: each point
        stored as it finishes, a failing point stored with its message, resumable."""
        import functools

        from ..sweep import run_sweep

        out = output_folder("--out", out, ".zarr")
        study = read_study(config, app)
        if scheduler not in (None, "distributed", "processes") and workers is not None:
            raise ParameterError("--workers", workers, f"left out with --scheduler {scheduler} (" + (
                "the cluster has its own workers)" if "://" in str(scheduler) else "it runs in this process)"))
        checkpoints = str(out.with_suffix(".runs")) if study.words in RESUMABLE else None
        if overwrite and checkpoints is not None:
            shutil.rmtree(checkpoints, ignore_errors=True)
        func = functools.partial(run_point, study, checkpoints, runner)
        outputs = {key: units for key, (_, units) in study.outputs.items()}
        stored = []  # the points already in the store when the sweep starts

        def progress(done, total):
            if not stored:
                stored.append(done)
            tick(done, total)

        with progress_bar(" ".join(study.words)) as tick:  # failed points: logged, then one line and exit 1
            ds = run_sweep(func, study.axes, out, outputs=outputs, scheduler=scheduler or "distributed",
                           workers=workers, progress=progress, overwrite=overwrite, attrs=study.attrs(),
                           title=study.title, model=study.model, batch=8, keep_going=True)
        emit({"store": str(out), "command": " ".join(study.words), "grid_points": study.points,
              "computed_now": int(ds["done"].sum()) - stored[0],
              "axes": {k: [v[0], v[-1], len(v)] for k, v in study.axes.items()},
              "outputs": {key: name for key, (name, _) in study.outputs.items()}}, json, "sweep",
             meanings={f"outputs.{key}": units_of(name, study.model)  # each output's meaning in its own model
                       for key, (name, _) in study.outputs.items()})

    return sweep
