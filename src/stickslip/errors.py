"""Exceptions raised by stickslip.

`ParameterError` is a `ValueError` whose message names the parameter, its value and
the allowed range; the command line turns it into one line on stderr and exit code 2.
`NoSolutionError` means a well-posed request has no answer (no limit cycle, no wave);
the command line turns it into one line and exit code 1.
"""


class _Missing:
    """The value of a parameter that was not given (`ParameterError` then says "missing")."""

    def __repr__(self):
        return "MISSING"

    def __reduce__(self):
        return "MISSING"


#: The value of a `ParameterError` for a required parameter left out.
MISSING = _Missing()


class ParameterError(ValueError):
    """A public parameter is outside its allowed range.

    ``also`` names the other parameters the allowed range depends on (a bound on a
    combination such as ``rho R^2 Omega^2 / E``), so that a message can name each of them.
    """

    def __init__(self, name: str, value, allowed: str, also: tuple[str, ...] = ()):
        self.name, self.value, self.allowed, self.also = name, value, allowed, tuple(also)
        text = f"missing {name}: it must be {allowed}" if value is MISSING else \
            f"invalid {name} = {value!r}: must be {allowed}"
        if self.also:
            text += f" (the bound depends on {', '.join(self.also)})"
        super().__init__(text)

    def __reduce__(self):  # raised in a worker process, it must cross back intact
        return type(self), (self.name, self.value, self.allowed, self.also)


class NoSolutionError(RuntimeError):
    """The problem is well posed but has no solution of the requested kind."""
