"""A `System` from a TOML file.

```toml
mass = [[1.0, 0.0], [0.0, 1.5]]          # kg; symmetric positive definite
stiffness = [[3.0, -1.0], [-1.0, 2.0]]   # N/m
damping = [[0.06, -0.02], [-0.02, 0.04]] # N s/m (optional)
force = [0.0, 0.0]                       # N (optional)

[[contact]]                              # one table per contact
direction = [1.0, 0.0]                   # its slip velocity is surface_speed - direction . x'
normal_force = 2.0                       # N
surface_speed = 0.3                      # m/s
law = "coulomb"                          # coulomb | linear-weakening (with tau) | stribeck (with vs)
fs = 0.6
fd = 0.4
# normal_direction = [0.0, 1.0]          # optional: a unilateral contact, N = normal_force - k_n n . x,
# normal_stiffness = 0.5                 # N/m; it opens where N would pull (Coulomb only)
# rigid = true                           # instead: the constraint n . x >= 0, its normal force a reaction
#                                        # (no normal_force, no normal_stiffness); plastic landings

[[harmonic]]                             # optional, any number: a force cos cos(W t) + sin sin(W t)
frequency = 1.1                          # rad/s
cos = [0.5, 0.0]                         # N, one per degree of freedom (cos, sin or both)

[history]                                # optional: a force given in time, linear between the points
times = [0.0, 10.0, 20.0]                # s, increasing
forces = [[0.0, 0.0], [1.0, 0.0], [1.0, 0.0]]   # N, one list per time, one number per degree of freedom
```

A Stribeck contact (``vs`` its Stribeck speed, m/s) or a rate-and-state one makes the system move by
`stickslip.system.rate_state_simulate` (integrated between its switches: no exact flow; every contact
then has a constant normal force). A rate-and-state contact gives, instead of
``fs``, ``fd`` and ``tau``, the fields of `stickslip.rsf.RateState`:

```toml
law = "rate-state"
a = 0.01                                 # direct effect
b = 0.015                                # evolution effect (b2, dc2: a second state variable)
dc = 1e-5                                # m, the state's slip distance
f0 = 0.6                                 # friction at the reference rate v_ref (m/s, default 1e-6)
evolution = "aging"                      # aging | slip | prz
regularized = false                      # true: the asinh form, which holds through zero slip rate
```

Every problem is a `ParameterError` naming the key as the file writes it (``contact[1].fs``).
"""

from __future__ import annotations

import os
import tomllib
from pathlib import Path

from ..errors import MISSING, ParameterError
from ..validation import regular_input
from ..friction import make_law
from ..rsf import RateState
from .model import Contact, ForceHistory, Harmonic, System

__all__ = ["load_system", "read_table", "system_from_dict", "as_file_keys"]

_TOP = ("mass", "stiffness", "damping", "force", "contact", "harmonic", "history")
_HARMONIC = ("frequency", "cos", "sin")
_HISTORY = ("times", "forces")
_CONTACT = ("direction", "normal_force", "surface_speed", "law", "fs", "fd", "tau", "vs", "name", "normal_direction",
            "normal_stiffness", "rigid")
#: The keys of a rate-and-state law (`stickslip.rsf.RateState`'s fields), with ``law = "rate-state"``.
_RATE_STATE = ("a", "b", "dc", "f0", "v_ref", "evolution", "b2", "dc2", "regularized")
_LAWS = ("coulomb", "linear-weakening", "stribeck", "rate-state")


def _renamed(err: ParameterError, prefix: str) -> ParameterError:
    return ParameterError(f"{prefix}{err.name}", err.value, err.allowed,
                          also=tuple(f"{prefix}{a}" for a in err.also))


def _contact(i: int, table) -> Contact:
    where = f"contact[{i}]."
    if not isinstance(table, dict):
        raise ParameterError(f"contact[{i}]", table, "a table of direction, normal_force, law, fs, fd, ...")
    law = table.get("law", "coulomb")
    if law not in _LAWS:
        raise ParameterError(where + "law", law, "one of " + ", ".join(_LAWS))
    rate_state = law == "rate-state"
    keys = _CONTACT + _RATE_STATE if rate_state else _CONTACT
    unknown = sorted(set(table) - set(keys))
    if unknown:
        raise ParameterError(where + unknown[0], table[unknown[0]], f"a key of a contact with law {law!r}: "
                             + ", ".join(k for k in keys if not (rate_state and k in ("fs", "fd", "tau", "vs"))))
    rigid = table.get("rigid", False)
    if not isinstance(rigid, bool):
        raise ParameterError(where + "rigid", rigid, "true or false")
    for key in ("direction",) + (() if rigid is True else ("normal_force",)) + (("a", "b", "dc") if rate_state
                                                                                else ("fs", "fd")):
        if key not in table:
            raise ParameterError(where + key, MISSING, "given")
    try:
        if rate_state:
            if any(k in table for k in ("fs", "fd", "tau", "vs")):
                key = next(k for k in ("fs", "fd", "tau", "vs") if k in table)
                raise ParameterError(key, table[key], "left out with law 'rate-state' (its friction is f0, a, b, ...)")
            friction = RateState(**{k: table[k] for k in _RATE_STATE if k in table})
        else:
            friction = make_law(law, fs=table["fs"], fd=table["fd"], tau=table.get("tau"), vs=table.get("vs"))
        return Contact(table["direction"], table.get("normal_force"), friction, table.get("surface_speed", 0.0),
                       table.get("name", ""), table.get("normal_direction"), table.get("normal_stiffness", 0.0),
                       rigid=rigid)
    except ParameterError as err:
        raise _renamed(err, where) from None


def _harmonic(i: int, table) -> Harmonic:
    where = f"harmonic[{i}]."
    if not isinstance(table, dict):
        raise ParameterError(f"harmonic[{i}]", table, "a table of frequency, cos, sin")
    unknown = sorted(set(table) - set(_HARMONIC))
    if unknown:
        raise ParameterError(where + unknown[0], table[unknown[0]], "a key of a harmonic: " + ", ".join(_HARMONIC))
    if "frequency" not in table:
        raise ParameterError(where + "frequency", MISSING, "given")
    try:
        return Harmonic(table["frequency"], table.get("cos"), table.get("sin"))
    except ParameterError as err:
        raise _renamed(err, where) from None


def _history(table) -> ForceHistory | None:
    if table is None:
        return None
    if not isinstance(table, dict):
        raise ParameterError("history", table, "a [history] table of times and forces")
    unknown = sorted(set(table) - set(_HISTORY))
    if unknown:
        raise ParameterError("history." + unknown[0], table[unknown[0]], "a key of a history: times, forces")
    for key in _HISTORY:
        if key not in table:
            raise ParameterError("history." + key, MISSING, "given")
    try:
        return ForceHistory(table["times"], table["forces"])
    except ParameterError as err:
        raise _renamed(err, "history.") from None


def system_from_dict(data: dict) -> System:
    """The `System` a parsed TOML file describes (see the module's docstring)."""
    if not isinstance(data, dict):
        raise ParameterError("system", data, "a table of mass, stiffness, contact, ...")
    unknown = sorted(set(data) - set(_TOP))
    if unknown:
        raise ParameterError(unknown[0], data[unknown[0]], "a key of a system: " + ", ".join(_TOP))
    for key in ("mass", "stiffness", "contact"):
        if key not in data:
            raise ParameterError(key, MISSING, "given" + (" (one [[contact]] table per contact)" if key == "contact"
                                                          else ""))
    if not isinstance(data["contact"], list) or not data["contact"]:
        raise ParameterError("contact", data["contact"], "one [[contact]] table per contact, at least one")
    contacts = [_contact(i, t) for i, t in enumerate(data["contact"])]
    tables = data.get("harmonic", [])
    if not isinstance(tables, list):
        raise ParameterError("harmonic", tables, "one [[harmonic]] table per harmonic force")
    harmonics = [_harmonic(i, t) for i, t in enumerate(tables)]
    history = _history(data.get("history"))
    try:
        return System(data["mass"], data["stiffness"], contacts, damping=data.get("damping"),
                      force=data.get("force"), harmonics=harmonics, history=history)
    except ParameterError as err:
        raise as_file_keys(err) from None


def as_file_keys(err: ParameterError) -> ParameterError:
    """``err`` naming a contact as the file does (``contact[1].surface_speed``, not the Python
    ``contacts[1].surface_speed``; ``harmonic[0].cos``, not ``harmonics[0].cos``): for the errors
    of a system read from a file."""
    for python, file in (("contacts[", "contact["), ("harmonics", "harmonic")):
        if err.name.startswith(python):
            return ParameterError(err.name.replace(python, file, 1), err.value, err.allowed, also=err.also)
    return err


def load_system(path) -> System:
    """The `System` of the TOML file at ``path``."""
    return system_from_dict(read_table(path))


def read_table(path) -> dict:
    """The parsed TOML table of the system file at ``path`` (`ParameterError` naming ``system
    file`` if it cannot be read)."""
    if not isinstance(path, (str, os.PathLike)):
        raise ParameterError("system file", path, "a path to a TOML file")
    path = regular_input("system file", path, "a readable UTF-8 TOML file")
    try:
        text = path.read_text(encoding="utf-8")
    except (OSError, UnicodeDecodeError) as err:
        raise ParameterError("system file", str(path), f"a readable UTF-8 TOML file ({err.__class__.__name__})") \
            from None
    try:
        data = tomllib.loads(text)
    except tomllib.TOMLDecodeError as err:
        raise ParameterError("system file", str(path), f"valid TOML ({err})") from None
    except RecursionError:
        raise ParameterError("system file", str(path), "a TOML file without deeply nested arrays or tables (a "
                             "system file nests two levels)") from None
    return data
