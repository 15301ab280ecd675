"""Exceptions raised by stickslip.

`ParameterError` is a `ValueError` whose message names the parameter, its value and
the allowed range; the command line turns it into one line on stderr and exit code 2.
`NoSolutionError` means a well-posed request has no answer (no limit cycle, no wave);
the command line turns it into one line and exit code 1.
"""


class ParameterError(ValueError):
    """A public parameter is outside its allowed range."""

    def __init__(self, name: str, value, allowed: str):
        self.name, self.value, self.allowed = name, value, allowed
        super().__init__(f"invalid {name} = {value!r}: must be {allowed}")

    def __reduce__(self):  # raised in a worker process, it must cross back intact
        return type(self), (self.name, self.value, self.allowed)


class NoSolutionError(RuntimeError):
    """The problem is well posed but has no solution of the requested kind."""
