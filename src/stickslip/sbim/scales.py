"""The lengths of a slip-weakening interface and what a run's grid and period say about them.

Linear slip-weakening, the strength falling by ``tau_s - tau_d`` over ``D_c``, with the effective modulus
``mu*`` (``mu`` in mode III, antiplane; ``mu / (1 - nu)`` in mode II, in-plane): a slipping patch grows
on its own once longer than twice Uenishi and Rice's (2003) half-length ``1.158 mu* D_c / (tau_s -
tau_d)``, and a rupture's front carries a cohesive zone of Palmer and Rice's (1973) static length
``(9 pi / 32) mu* D_c / (tau_s - tau_d)``. A run whose cell is longer than that zone does not resolve its
fronts; a period shorter than the nucleation length cannot nucleate a rupture by itself. Runs say so.
"""

from __future__ import annotations

import math

__all__ = ["NUCLEATION", "COHESIVE", "weakening_lengths", "resolution_notes"]

#: Uenishi and Rice's nucleation half-length, in ``mu* D_c / (tau_s - tau_d)``.
NUCLEATION = 1.158
#: Palmer and Rice's static cohesive zone, in ``mu* D_c / (tau_s - tau_d)``: 9 pi / 32.
COHESIVE = 9.0 * math.pi / 32.0


def weakening_lengths(modulus: float, weakening_slip: float, drop: float) -> tuple[float, float]:
    """``(nucleation half-length, cohesive zone)`` [m] for the effective ``modulus`` ``mu*`` [Pa], ``D_c`` and
    the strength ``drop`` [Pa]; infinite without a drop."""
    if not drop > 0.0:
        return math.inf, math.inf
    scale = modulus * weakening_slip / drop
    return NUCLEATION * scale, COHESIVE * scale


def resolution_notes(half: float, zone: float, dx: float, length: float, modulus: str) -> list[str]:
    """What a run of cells ``dx`` over the period ``length`` [m] cannot show of those lengths; ``modulus``
    names ``mu*`` in the messages."""
    notes = []
    if zone < dx:
        notes.append(f"unresolved: the cohesive zone ({zone:.3g} m, 9 pi/32 {modulus} D_c / (tau_s - tau_d)) is "
                     f"shorter than a cell ({dx:.3g} m): a rupture front is not resolved (more elements, or a "
                     "longer weakening_slip)")
    if length < 2.0 * half:
        notes.append(f"too short: the interface ({length:.3g} m) is shorter than the nucleation length "
                     f"({2.0 * half:.3g} m, 2 x 1.158 {modulus} D_c / (tau_s - tau_d)): a slip-weakening "
                     "rupture cannot nucleate on its own in it")
    return notes
