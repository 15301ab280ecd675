"""States of a contact node and the names of the regimes they make up (paper [17]-[20]).

At every step the explicit scheme (`stickslip.contact.kernel`) leaves each contact node in
one of four states, stored as ``int8`` codes:

====  ================  ======================================================
code  name              meaning
====  ================  ======================================================
0     ``stick``         in contact, moving with the rigid surface [17]
1     ``slip``          in contact, slower than the surface (forward slip) [18]
2     ``reverse_slip``  in contact, faster than the surface [19]
3     ``separation``    no contact, zero reactions [20]
====  ================  ======================================================

A regime is named by the states present, joined in the order stick, slip, separation,
reverse slip: ``stick-slip-separation``, say.
"""

from __future__ import annotations
from ..errors import ParameterError

import numpy as np

__all__ = ["STICK", "SLIP_POS", "SLIP_NEG", "SEPARATION", "STATE_NAMES", "STATE_ATTRS", "regime_name",
           "REGIME_CODES", "REGIME_ATTRS", "regime_code", "count_zones", "state_fractions"]

STICK, SLIP_POS, SLIP_NEG, SEPARATION = 0, 1, 2, 3
STATE_NAMES = ("stick", "slip", "reverse_slip", "separation")
#: CF attributes of a variable holding state codes.
STATE_ATTRS = {"flag_values": [STICK, SLIP_POS, SLIP_NEG, SEPARATION], "flag_meanings": " ".join(STATE_NAMES)}

_ORDER = ("stick", "slip", "separation", "reverse_slip")
#: Integer codes of regime names, for maps and sweeps (``other``: a combination without a code).
REGIME_CODES = {"none": 0, "stick-slip": 1, "stick-slip-reverse-slip": 2, "stick-slip-separation": 3,
                "stick-slip-separation-reverse-slip": 4, "stick-separation": 5, "slip": 6, "other": 7}
#: CF attributes of a variable holding regime codes.
REGIME_ATTRS = {"flag_values": list(REGIME_CODES.values()), "flag_meanings": " ".join(REGIME_CODES)}


def regime_name(present) -> str:
    """``stick-slip-separation-reverse-slip`` style name of a set of state names (``none`` if empty)."""
    try:
        present = set(present) if not isinstance(present, (str, bytes)) else None
    except TypeError:
        present = None
    if present is None:
        raise ParameterError("present", present, "a collection of state names (" + ", ".join(_ORDER) + ")")
    names = [k for k in _ORDER if k in set(present)]
    return "-".join(k.replace("_", "-") for k in names) if names else "none"


def regime_code(name: str) -> int:
    """Integer code of a regime name (`REGIME_CODES`; ``other`` for combinations without a code)."""
    if not isinstance(name, str):
        raise ParameterError("name", name, "a regime name (text), e.g. " + ", ".join(list(REGIME_CODES)[:3]))
    return REGIME_CODES.get(name, REGIME_CODES["other"])


def count_zones(mask: np.ndarray, min_run: int = 1, periodic: bool = True) -> int:
    """Number of runs of ``True`` of length >= ``min_run`` in a 1-D mask along a closed contact
    line (``periodic``: a run may wrap around its end) or an open one."""
    try:
        mask = np.asarray(mask, dtype=bool)
    except (TypeError, ValueError):
        mask = None
    if mask is None or mask.ndim != 1:
        raise ParameterError("mask", mask if mask is None else mask.tolist(), "a 1-D array of booleans")
    if mask.all():
        return 1 if periodic or mask.size >= min_run else 0
    if not mask.any():
        return 0
    start = int(np.argmin(mask)) if periodic else 0  # rotate so that the line starts outside a run
    m = np.concatenate([[False], np.roll(mask, -start), [False]]).astype(np.int8)
    d = np.diff(m)
    lengths = np.flatnonzero(d == -1) - np.flatnonzero(d == 1)
    return int(np.sum(lengths >= min_run))


def state_fractions(state: np.ndarray) -> np.ndarray:
    """Fraction of the nodes in each state (columns in the order of `STATE_NAMES`), over the last axis."""
    try:
        state = np.asarray(state)
    except ValueError:  # a ragged list
        state = np.asarray([])
    if state.ndim == 0 or state.size == 0 or state.dtype.kind not in "iubf" or not np.isfinite(state).all():
        raise ParameterError("state", state.tolist() if state.size <= 8 else f"array of shape {state.shape}",
                             "a non-empty array of state codes (integers)")
    if state.ndim == 1:  # one row (every sample of a run): one pass
        return np.bincount(state.astype(np.intp), minlength=len(STATE_NAMES))[: len(STATE_NAMES)] / state.size
    counts = np.stack([np.sum(state == code, axis=-1) for code in range(len(STATE_NAMES))], axis=-1)
    return counts / state.shape[-1]
