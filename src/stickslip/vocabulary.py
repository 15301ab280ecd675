"""Deprecated: the units and long names of results are declared in `stickslip.quantities`.

``stickslip.vocabulary.lookup`` and ``VOCABULARY`` keep working for one release (0.2), with a
one-line notice on stderr; use `stickslip.quantities.lookup` and `stickslip.quantities.DOMAINS`.
"""

from __future__ import annotations

import sys

from .quantities import DOMAINS, lookup as _lookup

__all__ = ["lookup", "VOCABULARY"]

print("stickslip: stickslip.vocabulary is deprecated and goes in 0.3; use stickslip.quantities (lookup, DOMAINS)",
      file=sys.stderr)

#: Model -> {name: (units, long name)} (deprecated: `stickslip.quantities.DOMAINS`).
VOCABULARY = {name: {q.name: (q.units, q.meaning) for q in domain} for name, domain in DOMAINS.items()}


def lookup(name: str, domain: str = "common") -> tuple[str, str] | None:
    """Deprecated: `stickslip.quantities.lookup`."""
    return _lookup(name, domain)
