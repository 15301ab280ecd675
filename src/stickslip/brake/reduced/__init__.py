"""The reduced model of the brake-like system (paper section 3, eqs. [10]-[16]).

Parameters (`BrakeParams`, `PhysicalParams`), the Lamé steady state ([11] corrected,
[16]), the Galerkin coefficients [13] of the reduced equations [12], and the flutter of
steady sliding (growth rate per Fourier mode). The travelling waves (`brake.waves`),
the ring integration (`brake.ring`) and the finite elements (`brake.fem`) build on it.
"""

from .coefficients import (ReducedCoefficients, coefficients, coupling, elastic_moduli, neutral_radius_ratio,
                           shape_integrals)
from .flutter import (GrowthRates, ModeGrowth, grid_growth_rates, growth_rate_limit, growth_rates, mode_numbers,
                      most_unstable_mode, separation_number, unstable_root)
from .params import STEEL, BrakeParams, PhysicalParams
from .steady import SteadySliding, steady_sliding

__all__ = ["BrakeParams", "PhysicalParams", "STEEL", "ReducedCoefficients", "coefficients", "coupling",
           "elastic_moduli", "neutral_radius_ratio", "shape_integrals", "SteadySliding", "steady_sliding",
           "GrowthRates", "ModeGrowth", "growth_rates", "growth_rate_limit", "most_unstable_mode", "mode_numbers",
           "unstable_root", "grid_growth_rates", "separation_number"]
