"""The `stickslip` command line: thin wrappers that parse, call the library and print.

Errors never show a traceback: bad input prints one line on stderr and exits with
code 2, a well-posed problem without solution exits with code 1.
"""

from __future__ import annotations

import contextlib
import logging
import os
import sys
import warnings

import typer
from rich.console import Console

from ..errors import NoSolutionError, ParameterError
from . import brake, fem, halfspace, oscillator, reproduce, rsf, status, study, system
from .helptext import Typer, command_tree

# typer vendors its own copy of click (older releases re-export click's classes):
# its usage errors are the parent class of typer.BadParameter in both cases
_EXIT, _ABORT, _USAGE = typer.Exit, typer.Abort, typer.BadParameter.__mro__[1]

app = Typer(no_args_is_help=True, add_completion=True, pretty_exceptions_enable=False, rich_markup_mode=None,
                  help="Friction-induced vibration and stick-slip waves (models of the paper, and beyond).")


def _version(value: bool) -> None:
    if value:
        from .. import __version__

        print(f"stickslip {__version__}")
        raise typer.Exit(0)


@app.callback()
def _main(version: bool = typer.Option(False, "--version", callback=_version, is_eager=True,
                                       help="Print the version and exit.")) -> None:
    """Friction-induced vibration and stick-slip waves (models of the paper, and beyond)."""
app.add_typer(oscillator.app, name="oscillator")
app.add_typer(brake.app, name="brake")
app.add_typer(halfspace.app, name="halfspace")
app.add_typer(fem.app, name="fem")
app.add_typer(system.app, name="system")
app.add_typer(rsf.app, name="rsf")
app.command("reproduce")(reproduce.reproduce)


def _one_line(message: str) -> str:
    return " ".join(str(message).split())


def _as_typed(argv: list[str] | None, exc: ParameterError) -> ParameterError:
    """The error with the library's parameter names (its own and those its bound depends on)
    replaced by the options of the command that was run (``transits`` -> ``--transits``),
    when the command has such options."""
    command, path = command_tree(app), []
    for token in (sys.argv[1:] if argv is None else argv):
        sub = getattr(command, "commands", {}).get(token)
        if sub is None:
            break
        command = sub
        path.append(token)
    options = dict(fem.CONFIG_NAMES) if path[:1] == ["fem"] else {}  # what the config file calls them
    options.update({p.name: p.opts[0] for p in getattr(command, "params", []) if getattr(p, "opts", None)})
    if "out" in options:  # the run file a command writes as it goes, the store of a map
        options.setdefault("checkpoint", options["out"])
        options.setdefault("store", options["out"])
    typed = lambda name: name if name.startswith("-") else options.get(name, name)
    also = tuple(typed(n) for n in exc.also if n.startswith("-") or n in options)  # what this command can set
    return ParameterError(typed(exc.name), exc.value, exc.allowed, also)


class _Stderr(logging.StreamHandler):
    """A handler writing to whatever ``sys.stderr`` is when a record comes (a live progress display
    of rich redirects it, so that log lines go above the display instead of through it)."""

    @property
    def stream(self):
        return sys.stderr

    @stream.setter
    def stream(self, value):
        pass


class _OneLine(logging.Formatter):
    def format(self, record):
        text = " ".join(record.getMessage().split())
        return text if record.levelno <= logging.INFO else f"{record.levelname.lower()}: {text}"


@contextlib.contextmanager
def _logs_on_stderr():
    """The library's log records (``stickslip.*``: a sweep's dashboard, its failed or recomputed
    points) on stderr, one line each, for the block."""
    logger = logging.getLogger("stickslip")
    handler = _Stderr()
    handler.setFormatter(_OneLine())
    level = logger.level
    logger.addHandler(handler)
    logger.setLevel(logging.INFO)
    try:
        yield
    finally:
        logger.removeHandler(handler)
        logger.setLevel(level)


def run(argv: list[str] | None = None) -> int:
    """Run the CLI and return its exit code."""
    def fail(prefix: str, exc, code: int) -> int:
        print(f"{prefix}: {_one_line(exc)}", file=sys.stderr)
        return code

    try:
        # numeric warnings are not for the user: a result that went NaN or infinite is refused
        # by `common.emit` (one line, exit 1), a finite one is printed
        words = [w for w in (sys.argv[1:] if argv is None else argv)[:2] if not w.startswith("-")]
        with warnings.catch_warnings(), _logs_on_stderr(), \
                status.heartbeat(" ".join(["stickslip", *words]), Console(stderr=True).is_terminal):
            warnings.simplefilter("ignore", RuntimeWarning)
            result = command_tree(app).main(args=argv, prog_name="stickslip", standalone_mode=False)
        return result if isinstance(result, int) else 0
    except _EXIT as exc:
        return exc.exit_code
    except _ABORT:
        print("aborted", file=sys.stderr)
        return 1
    except _USAGE as exc:  # parsing errors: missing or malformed options
        if type(exc).__name__ == "NoArgsIsHelpError":  # bare: the help, and 2 where a group needs a command
            top = exc.ctx.parent is None  # as click: on stderr where a command is missing
            print(exc.ctx.get_help(), file=sys.stdout if top else sys.stderr)
            return 0 if top else 2
        return fail("error", exc.format_message().replace("Value error, ", ""), 2)  # typer's enum wording
    except ParameterError as exc:
        return fail("error", _as_typed(argv, exc), 2)
    except NoSolutionError as exc:
        return fail("no solution", exc, 1)
    except ValueError as exc:
        return fail("error", exc, 2)
    except KeyboardInterrupt:
        print("interrupted", file=sys.stderr)
        return 130
    except Exception as exc:  # a bug: say so in one line, keep the traceback for debugging
        if os.environ.get("STICKSLIP_DEBUG"):
            raise
        return fail("internal error", f"{type(exc).__name__}: {exc} (set STICKSLIP_DEBUG=1 for a traceback)", 3)


app.command("sweep")(study.command(app, run))  # its points run commands of this app


def main() -> None:
    sys.exit(run())
