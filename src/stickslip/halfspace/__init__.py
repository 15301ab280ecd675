"""Model 3: stick-slip waves between an elastic half-space and a rigid body (paper §4-5).

Radok potentials, periodic stick (``[0, a = 1]``) and slip (``[1, b]``) segments moving
at ``c = cbar c2`` (``-1 < cbar < 0``).

- `radok`, `Material`, `rayleigh_speed_ratio`, `wave_speed_ratio`: wave quantities.
- `inverse_problem`: ``(v, T)`` from ``(b, cbar, v*)`` ([54]-[58]), vectorised; `b_for_loading`,
  the period that gives a traction ``T``.
- `direct_problem`, `direct_map`: ``(cbar, b)`` from the loading ``(T, v, v*)``.
- `loading_from_wave`, `stresses_from_T`, ...: the physical loading ([25], [26], [40]).
- `StickSlipWave`: the interface fields ([43]-[48]) from the periodic canonical function.
"""

from .direct import DirectSolution, direct_map, direct_problem
from .fields import (InterfaceFields, StickSlipWave, decaying_velocity, decaying_wave, periodic_X,
                     wave_from_inverse)
from .inverse import (SYSTEMS, InverseSolution, b_for_loading, closed_form, determinant, inverse_map,
                      inverse_problem, printed_closed_form, system_matrix)
from .loading import (Loading, driving_traction, loading_from_wave, remote_strain, stress_from_v_star,
                      stresses_from_T, v_star_from_stress)
from .waves import Material, Radok, radok, rayleigh_speed_ratio, wave_speed_ratio

__all__ = [
    "Material", "Radok", "radok", "rayleigh_speed_ratio", "wave_speed_ratio",
    "SYSTEMS", "InverseSolution", "inverse_problem", "inverse_map", "system_matrix", "determinant",
    "closed_form", "printed_closed_form", "b_for_loading",
    "DirectSolution", "direct_problem", "direct_map",
    "Loading", "loading_from_wave", "remote_strain", "v_star_from_stress", "stress_from_v_star",
    "driving_traction", "stresses_from_T",
    "StickSlipWave", "InterfaceFields", "wave_from_inverse", "decaying_wave", "decaying_velocity", "periodic_X",
]
