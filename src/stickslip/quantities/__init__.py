"""Every quantity stickslip takes or gives, declared once.

A `Quantity` holds a name, symbol, units (UDUNITS-2), the range of values a model accepts
(with open or closed ends, and why it ends there), its meaning and CF ``standard_name``.
Everything else reads these declarations:

* the validators of every public function and of the command line (``Quantity.check``
  raises a `ParameterError` naming the parameter as typed, its value and its range);
* the command line's option help (``Quantity.help``);
* the ``units`` of every ``--json`` result and the rows of the printed tables (`lookup`);
* the attributes of every netCDF and Zarr file (`stickslip.cf`);
* the parameter tables of the documentation (``python -m stickslip.quantities``);
* the fuzzing strategies of the tests, which reach each range's edges and beyond.

The CF standard-name table (earth sciences) names none of these quantities but time, and CF's
``time`` needs units since an epoch (compliance-checker: ``s since <epoch>`` and a calendar),
which a simulated time has not (and xarray would decode it into dates): an elapsed time is a
plain coordinate ``t`` in s (or in the model's scaled unit). ``standard_name`` is there for the
quantities that have one.

The quantities of a model are in its `Domain` (`OSCILLATOR`, `BRAKE`, `HALFSPACE`, `FEM`);
`COMMON` serves every model (counters, labels, the shared scheme's settings), and a model's
own declaration of a name takes precedence.
"""

from __future__ import annotations

from .brake import BRAKE
from .common import COMMON, MAX_MESH_NODES, MAX_POINTS, MAX_WORKERS
from .core import Domain, Quantity, Range, number
from .fem import FEM
from .halfspace import HALFSPACE
from .oscillator import OSCILLATOR
from .rsf import RSF
from .sbim import SBIM
from .system import MAX_CONTACTS, MAX_SYSTEM_DOFS, SYSTEM

__all__ = ["Quantity", "Range", "Domain", "DOMAINS", "COMMON", "OSCILLATOR", "BRAKE", "HALFSPACE", "FEM",
           "SYSTEM", "RSF", "SBIM",
           "declared", "lookup", "number", "MAX_MESH_NODES", "MAX_POINTS", "MAX_WORKERS", "MAX_SYSTEM_DOFS",
           "MAX_CONTACTS"]

#: Model -> its declarations; ``common`` serves every model.
DOMAINS = {"common": COMMON, "oscillator": OSCILLATOR, "brake": BRAKE, "halfspace": HALFSPACE, "fem": FEM,
           "system": SYSTEM, "rsf": RSF, "sbim": SBIM}
for _domain in (OSCILLATOR, BRAKE, HALFSPACE, FEM, SYSTEM, RSF, SBIM):
    _domain.fallback = COMMON

# derived names: a branch's or a run's copy of a quantity, its real or imaginary part
_PREFIXES = {"ss_": "stick-slip branch: ", "dc_": "damped Coulomb branch: ", "c0_": "undamped Coulomb branch: ",
             "slip_": "pure-slip branch: ", "sweep_": "sweep: ", "ring_": "ring run: ", "noise_": "run from noise: ",
             "wave_": "travelling wave: ", "far_field_": "far field: ", "fraction_": "fraction in state ",
             "length_": "total length of the zones: "}
_SUFFIXES = {"_re": "real part of the ", "_im": "imaginary part of the "}


def declared(name: str, domain: str = "common") -> Quantity | None:
    """The declaration of ``name`` in ``domain`` (or in `COMMON`), derived names included:
    a prefix names a branch or a run (``ss_period``), a suffix a part (``eigen_re``)."""
    found = DOMAINS.get(domain, COMMON).get(name)
    if found is not None:
        return found
    for prefix, note in _PREFIXES.items():
        if name.startswith(prefix) and len(name) > len(prefix):
            rest = name[len(prefix):]
            if prefix == "fraction_":
                return Quantity(name, "1", f"fraction of contact nodes in {rest.replace('_', ' ')}")
            if prefix == "length_":
                return Quantity(name, "rad", f"total angular length of the {rest.replace('_', ' ')} zones")
            found = declared(rest, domain)
            if found is not None:
                return Quantity(name, found.units, note + found.meaning, scale=found.scale)
    for suffix, note in _SUFFIXES.items():
        if name.endswith(suffix):
            found = declared(name[: -len(suffix)], domain)
            if found is not None:
                return Quantity(name, found.units, note + found.meaning, scale=found.scale)
    return None


def lookup(name: str, domain: str = "common") -> tuple[str, str] | None:
    """``(units, long_name)`` of ``name`` in ``domain``, or None if it is not declared."""
    q = declared(name, domain)
    return None if q is None else (q.units, q.meaning)
