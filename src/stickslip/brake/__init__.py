"""Model 2: the brake-like system (paper section 3).

An elastic annulus clamped on its outer radius, pressed on a rotating rigid shaft with
Coulomb friction. This package holds the parameters, the steady sliding state
([11], [16]), the reduced-model coefficients ([13]) and the linear stability of steady
sliding (flutter); `figures` turns the stability analysis into a figure and its checks.
"""

from .coefficients import ReducedCoefficients, coefficients, coupling, neutral_radius_ratio, shape_integrals
from .params import STEEL, BrakeParams, PhysicalParams
from .stability import GrowthRates, ModeGrowth, growth_rate_limit, growth_rates, most_unstable_mode
from .steady import SteadySliding, steady_sliding

__all__ = ["BrakeParams", "PhysicalParams", "STEEL", "ReducedCoefficients", "coefficients", "coupling",
           "neutral_radius_ratio", "shape_integrals", "SteadySliding", "steady_sliding", "GrowthRates",
           "ModeGrowth", "growth_rates", "growth_rate_limit", "most_unstable_mode"]
